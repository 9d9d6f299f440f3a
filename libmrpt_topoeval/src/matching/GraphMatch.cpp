/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt_topoeval/GraphMatch.h>

namespace mrpt_topoeval
{
std::string toString(MatchStage s)
{
    return s == MatchStage::Isomorphism ? "isomorphism" : "neighbour_growing";
}

int GraphMatch::mapVertexOf(int gt) const
{
    for (const auto& p : pairs)
        if (p.ground_truth == gt) return p.map;
    return -1;
}

int GraphMatch::groundTruthVertexOf(int m) const
{
    for (const auto& p : pairs)
        if (p.map == m) return p.ground_truth;
    return -1;
}

}  // namespace mrpt_topoeval
