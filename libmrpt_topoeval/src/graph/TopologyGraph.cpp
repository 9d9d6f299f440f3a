/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt_topoeval/TopologyGraph.h>

namespace mrpt_topoeval
{
double TopologyGraph::totalEdgeLength() const
{
    double sum = 0.0;
    for (const auto& e : edges) sum += e.length_m;
    return sum;
}

std::size_t TopologyGraph::numNonSpuriousVertices() const
{
    std::size_t n = 0;
    for (const auto& v : vertices) n += v.spurious ? 0 : 1;
    return n;
}

std::vector<std::size_t> TopologyGraph::degreeHistogram(bool include_spurious) const
{
    std::vector<std::size_t> hist;
    for (const auto& v : vertices)
    {
        if (v.spurious && !include_spurious) continue;
        const auto d = static_cast<std::size_t>(v.degree());
        if (hist.size() <= d) hist.resize(d + 1, 0);
        ++hist[d];
    }
    return hist;
}

}  // namespace mrpt_topoeval
