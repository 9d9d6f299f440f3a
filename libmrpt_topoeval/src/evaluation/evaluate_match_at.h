/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// evaluateMatch() with brokenness measured on the map's graph read at another scale (the scale
// pass of the pipeline, doc/matching.md, "A map at another scale"): a map whose distances are
// all off by one factor is not broken, it is inaccurate. Accuracy and consistency measure the
// map as given; its parts are judged where the factor is undone.

#include <mrpt_topoeval/evaluation/evaluate_match.h>

namespace mrpt_topoeval::internal
{
/** As evaluateMatch(ground_truth, map, match, p, threads), but brokenness is measured on
 * `map_for_brokenness`: the same graph (vertex for vertex) read at another scale. */
QualityReport evaluateMatchAt(const TopologyGraph& ground_truth, const TopologyGraph& map,
                              const TopologyGraph& map_for_brokenness, const GraphMatch& match,
                              const QualityParameters& p, unsigned threads);
}  // namespace mrpt_topoeval::internal
