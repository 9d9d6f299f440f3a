/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// Ours (issue 11, brokenness): a part the match missed, found by its walls. The map's walls that
// no brokenness group explains are where a missed part lies (doc/quality.md, "Explained
// walls"); a region of them that one rigid fit clearly puts on the ground truth's walls is a
// part of its own (doc/quality.md, brokenness step 9, "A part placed by its walls").

#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/geometry/Transform2D.h>

#include <utility>
#include <vector>

#include "matching/wall_agreement.h"

namespace mrpt_topoeval::internal
{
/** The rule's values, from QualityParameters (wall_part_*), tolerances already at least 1.5
 * cells. */
struct WallPartRule
{
    double tolerance_m = 0.15;     //!< a region's point placed on a ground-truth wall
    double link_m = 2.0;           //!< wall points this near are one region
    double min_length_m = 20.0;    //!< the least wall of a region (points x cell size)
    double min_share = 0.95;       //!< the placement's share of points on a wall
    double max_runner_up = 0.8;    //!< the next distinct placement's share / the best's
    double turn_step_deg = 3.0;    //!< the turns tried before ICP
    double pair_distance_m = 0.5;  //!< a placed ground-truth vertex's map vertex
};

/** One part placed by its walls. */
struct WallPart
{
    Transform2D transform;   //!< T_gt_map of `placed` (the map as brokenness saw it)
    double share = 0.0;      //!< its region's points within tolerance of a ground-truth wall
    double runner_up = 0.0;  //!< the next distinct placement's share
    std::vector<Eigen::Vector2d> points;     //!< its region's wall points (placed's frame)
    std::vector<std::pair<int, int>> pairs;  //!< (ground truth, map): free vertices it places
};

/** The regions of `unexplained` (wall points of `placed` that no brokenness group explains, in
 * its frame: explainedWalls()'s), each placed on the ground truth's walls from every free map
 * vertex near it paired with every free ground-truth vertex (`*_free`: 1 for a matchable vertex
 * of no pair), under turns of `turn_step_deg`, the best distinct placements refined by MRPT's
 * ICP; a region whose best placement puts at least `min_share` of its points on a wall, and
 * whose next distinct one (5 degrees or 0.5 m away at the region's centre) at most
 * `max_runner_up` of that, is a part. Largest region first; a region an accepted part already
 * places is not placed again. Deterministic. */
std::vector<WallPart> findWallParts(const TopologyGraph& gt, const TopologyGraph& placed,
                                    const WallIndex& gt_walls,
                                    const std::vector<Eigen::Vector2f>& unexplained,
                                    const std::vector<char>& gt_free,
                                    const std::vector<char>& map_free, const WallPartRule& rule);
}  // namespace mrpt_topoeval::internal
