/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// Ours (issue 11): the share of the map's walls that the match explains, the map's side of
// coverage (doc/quality.md, "Explained walls").

#include <mrpt_topoeval/QualityReport.h>
#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/geometry/Transform2D.h>

#include <vector>

#include "matching/wall_agreement.h"

namespace mrpt_topoeval::internal
{
/** The map's wall points that one of `fits` (each a T_gt_map of `placed`, the map's graph as
 * the fits saw it: the same wall points, read at another scale or not) puts within
 * `tolerance_m` of a ground-truth wall point of `gt_walls`. The unexplained ones are given in
 * `map`'s frame; `placed_explained`, when given, receives where the first fit that explains each
 * explained one puts it (the ground truth's frame: the places a part of the map stands on).
 * Not measured (all 0) when `fits` is empty or either graph has no wall points. */
ExplainedWalls explainedWalls(const TopologyGraph& map, const TopologyGraph& placed,
                              const std::vector<Transform2D>& fits, const WallIndex& gt_walls,
                              double tolerance_m,
                              std::vector<Eigen::Vector2f>* placed_explained = nullptr);
}  // namespace mrpt_topoeval::internal
