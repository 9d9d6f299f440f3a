/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt_topoeval/GraphMatch.h>

#include <algorithm>

namespace mrpt_topoeval
{
std::string toString(MatchStage s)
{
    switch (s)
    {
        case MatchStage::Isomorphism:
            return "isomorphism";
        case MatchStage::NeighbourGrowing:
            return "neighbour_growing";
        case MatchStage::Walls:
            break;
    }
    return "walls";
}

std::size_t GraphMatch::byWalls() const
{
    return std::size_t(std::count_if(pairs.begin(), pairs.end(),
                                     [](const VertexPair& p)
                                     { return p.stage == MatchStage::Walls; }));
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
