/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/TopologyGraph.h>

#include <map>
#include <string>

namespace mrpt_topoeval
{
/** A match of two Topology Graphs as JSON (the format of `topoeval match --json`, documented in
 * doc/cli.md):
 *
 * ```
 * {
 *   "ground_truth": {"file", "vertices", "non_spurious_vertices", "half_edges"},
 *   "map": {... the same for the map's graph ...},
 *   "matches": {
 *     "isomorphism": n, "neighbour_growing": n, "missing": n,   (the paper's Table II)
 *     "isomorphisms": [size, ...],                               (in the order found)
 *     "pairs": [{"ground_truth": id, "map": id, "stage": "isomorphism" | "neighbour_growing"
 *                | "walls", "similarity": s, "isomorphism_index": k}, ...],
 *     "messages": ["...", ...]
 *   },
 *   "timing_ms": {...}
 * }
 * ```
 *
 * Vertex ids are the `id`s of `graphToJson()` for the same graphs. `isomorphism_index` is the
 * position in "isomorphisms" of the isomorphism that found the pair (for neighbour growing: the
 * one it grew from; -1 if none). Pairs are written in the match's order. Byte-identical for
 * equal inputs apart from `timing_ms`, the last member (omitted when `timing_ms` is null). NaN
 * and infinities are written as null. */
std::string matchToJson(const TopologyGraph& ground_truth, const TopologyGraph& map,
                        const GraphMatch& match,
                        const std::map<std::string, double>* timing_ms = nullptr);

}  // namespace mrpt_topoeval
