/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt_topoeval/json/JsonWriter.h>
#include <mrpt_topoeval/match_json.h>

#include <cstdint>

#include "json/match_json_internal.h"

namespace mrpt_topoeval
{
namespace internal
{
namespace
{
std::uint64_t u64(std::size_t n) { return static_cast<std::uint64_t>(n); }
}  // namespace

void writeMatchedGraph(JsonWriter& w, const TopologyGraph& g, const std::size_t* matchable)
{
    w.beginObject();
    w.key("file").value(g.map.file);
    w.key("vertices").value(u64(g.vertices.size()));
    // "missing" counts non-spurious ground-truth vertices only: the total it is out of.
    w.key("non_spurious_vertices").value(u64(g.numNonSpuriousVertices()));
    // Coverage is out of these (QualityReport::gt_vertices / map_vertices).
    if (matchable) w.key("matchable_vertices").value(u64(*matchable));
    w.key("half_edges").value(u64(g.numHalfEdges()));
    if (matchable) w.key("edge_length_m").value(g.totalEdgeLength(), kMetreDecimals);
    w.endObject();
}

void writeMatches(JsonWriter& w, const GraphMatch& match)
{
    w.beginObject();
    // The columns of the paper's Table II.
    w.key("isomorphism").value(u64(match.isomorphism));
    w.key("neighbour_growing").value(u64(match.neighbour_growing));
    w.key("missing").value(u64(match.missing));
    w.key("isomorphisms").beginArray(true);
    for (const std::size_t n : match.isomorphism_sizes) w.value(u64(n));
    w.endArray();
    // One pair per line: a few hundred lines stay readable and diff well.
    w.key("pairs").beginArray();
    for (const VertexPair& p : match.pairs)
    {
        w.beginObject(true);
        w.key("ground_truth").value(p.ground_truth);
        w.key("map").value(p.map);
        w.key("stage").value(toString(p.stage));
        w.key("similarity").value(p.similarity, kSimilarityDecimals);
        w.key("isomorphism_index").value(p.isomorphism);
        w.endObject();
    }
    w.endArray();
    w.key("messages").beginArray();
    for (const std::string& m : match.messages) w.value(m);
    w.endArray();
    w.endObject();
}
}  // namespace internal

std::string matchToJson(const TopologyGraph& ground_truth, const TopologyGraph& map,
                        const GraphMatch& match, const std::map<std::string, double>* timing_ms)
{
    JsonWriter w;
    w.beginObject();
    w.key("ground_truth");
    internal::writeMatchedGraph(w, ground_truth);
    w.key("map");
    internal::writeMatchedGraph(w, map);
    w.key("matches");
    internal::writeMatches(w, match);
    if (timing_ms) writeTiming(w, *timing_ms);
    w.endObject();
    return w.str();
}

}  // namespace mrpt_topoeval
