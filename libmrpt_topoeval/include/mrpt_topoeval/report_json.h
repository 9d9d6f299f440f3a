/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/QualityReport.h>
#include <mrpt_topoeval/TopologyGraph.h>

#include <string>

namespace mrpt_topoeval
{
/** A quality report as JSON (the format of `topoeval compare --json`, documented in
 * doc/cli.md):
 *
 * ```
 * {
 *   "ground_truth": {"file", "vertices", "non_spurious_vertices", "matchable_vertices",
 *                    "half_edges", "edge_length_m"},
 *   "map": {... the same for the map's graph ...},
 *   "matches": {...},          (the object of `topoeval match --json`, byte for byte)
 *   "coverage": c,
 *   "global_accuracy": {"pairs", "rmse_m", "score"},
 *   "relative_accuracy": {"pairs", "rmse_m", "score", "pairs_by_walls",
 *                         "transform": {"x", "y", "yaw_deg"}},
 *   "local_consistency": [{"class", "min_graph_distance_m", "max_graph_distance_m", "pairs",
 *                          "mean_error_m", "score"}, ...],
 *   "brokenness": {"degree", "score",
 *                  "groups": [{"vertices", "ground_truth_ids", "squared_error_m2", "yaw_deg",
 *                              "x", "y"}, ...]},
 *   "quality": q,
 *   "messages": ["...", ...],
 *   "parameters": {"MapLoad": {"resolution_m": 0.05, ...}, "GraphBuilder": {...}, ...},
 *   "timing_ms": {...}
 * }
 * ```
 *
 * `parameters` holds every section and key that `effective.saveToConfigFile()` writes, in the
 * order of the INI file, values as JSON numbers, booleans or strings: the run can be repeated
 * from it. Quantities that do not exist are null: NaN and infinities (the long consistency
 * class has no upper bound), and the errors and transform of an accuracy or consistency class
 * with no pair (their scores are 0). Byte-identical for equal inputs apart from `timing_ms`,
 * the last member, which is left out unless `with_timing`. */
std::string reportToJson(const TopologyGraph& ground_truth, const TopologyGraph& map,
                         const QualityReport& report, const Parameters& effective,
                         bool with_timing);

}  // namespace mrpt_topoeval
