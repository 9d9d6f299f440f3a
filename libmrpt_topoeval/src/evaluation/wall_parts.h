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
    int min_pin_lead = 2;          //!< or the best's pinned vertices minus each closer rival's
    bool free_space = true;        //!< or the best's walls x free space against each rival's
    double turn_step_deg = 3.0;    //!< the turns tried before ICP
    double pair_distance_m = 0.5;  //!< a placed ground-truth vertex's map vertex
};

/** One part placed by its walls. */
struct WallPart
{
    Transform2D transform;                //!< T_gt_map of `placed` (the map as brokenness saw it)
    std::vector<Eigen::Vector2d> points;  //!< its region's wall points (placed's frame)
    std::vector<std::pair<int, int>> pairs;  //!< (ground truth, map): free vertices it places
};

/** The rule of parts singled out by their region (QualityParameters map_by_walls_*,
 * wall_part_max_overlap): a map the match grouped nothing of (placeMapByWalls()), and a region of
 * missed walls that no one fit places (findWallParts()). */
struct WallMapRule
{
    WallPartRule part;                   //!< each part's placement, as a missed part's
    double explained_tolerance_m = 0.3;  //!< a point a part's fit explains (and takes away)
    double region_m = 3.0;               //!< a part's region: its points' neighbourhood ...
    double region_share = 0.9;           //!< ... on a ground-truth wall at least this share
    double min_explained = 0.9;          //!< the parts together explain this share of walls
    int max_parts = 4;                   //!< parts sought at most
    double slack_share = 0.1;            //!< a pair's reach: + this share of its clearance
    double max_overlap = 0.5;            //!< a part's points where another part stands, at most
    double whole_min_share = 0.5;        //!< no region: the whole map's best placement, this share
};

/** A map placed part by part by its walls. */
struct WallMap
{
    std::vector<WallPart> parts;   //!< largest first; empty when refused (a whole map: no pair)
    double explained = 0.0;        //!< share of the map's wall points the parts sought explain
    int parts_sought = 0;          //!< parts found before the search stopped (refused or not)
    bool whole = false;            //!< no region singled out: the whole map placed as one part
    double whole_share = 0.0;      //!< ... its points on a ground-truth wall
    double whole_runner_up = 0.0;  //!< ... the next distinct placement's
};

/** A map the match grouped nothing of, placed part by part on the ground truth's walls:
 * the placement (as findWallParts()'s, from every non-spurious vertex pair) of the wall points
 * no part explains yet, its region being the points whose neighbourhood of `region_m` it puts
 * on a ground-truth wall for at least `region_share` of them (coincident straight walls of
 * another building leave none); a region of min_length_m whose placement is clear on it (as a
 * missed part's) is the next part, and takes away the points within `explained_tolerance_m`.
 * The parts are kept when together they explain at least `min_explained` of the map's walls.
 * When no region is singled out, the whole map is one part if its best placement puts at least
 * `whole_min_share` of its points on a wall and the next distinct one at most
 * `part.max_runner_up` of that (a robot map against a plan: clutter leaves no clean region).
 * Of the parts kept, each map vertex then pairs, under a part that explains at least a quarter
 * of the walls around it, with the ground-truth vertex it is put nearest within pair_distance_m
 * + slack_share of the larger clearance (a vertex slides in its room); a pair of the match
 * (`given`: ground truth, map) is kept first when such a part puts it within the ground-truth
 * vertex's clearance. Each vertex once. Deterministic. */
WallMap placeMapByWalls(const TopologyGraph& gt, const TopologyGraph& map,
                        const WallIndex& gt_walls, const WallIndex& map_walls,
                        const std::vector<std::pair<int, int>>& given, const WallMapRule& rule);

/** The regions of `unexplained` (wall points of `placed` that no brokenness group explains, in
 * its frame: explainedWalls()'s), each placed on the ground truth's walls from every free map
 * vertex near it paired with every free ground-truth vertex (`*_free`: 1 for a matchable vertex
 * of no pair), under turns of `rule.part.turn_step_deg`, the best distinct placements refined by
 * MRPT's ICP; a region whose best placement puts at least `min_share` of its points on a wall, and
 * whose next distinct one (5 degrees or 0.5 m away at the region's centre) at most
 * `max_runner_up` of that, is a part. Largest region first; a region an accepted part already
 * places is not placed again. With `split`, a region that no one fit places clearly may hold
 * more than one part (two parts that touch at a cut): parts are singled out within it as
 * placeMapByWalls() singles them out (rule.region_m, rule.region_share, at most rule.max_parts),
 * each of which must also pair a vertex. A part that puts more than `rule.max_overlap` of its
 * points on ground-truth walls where a group puts the map's walls it explains (`stood_on`, in the
 * ground truth's frame: explainedWalls()'s `placed_explained`) or an accepted part puts its own
 * is refused: one place of the building is the image of one part of the map. And one part of
 * the map has one fit: a part whose points another part's fit puts on a wall for at least
 * `rule.part.min_share` of them, while its own fit puts fewer of that part's, goes with its
 * pairs (a piece of a rack block singled out under a half turn). Deterministic. */
std::vector<WallPart> findWallParts(const TopologyGraph& gt, const TopologyGraph& placed,
                                    const WallIndex& gt_walls,
                                    const std::vector<Eigen::Vector2f>& unexplained,
                                    const std::vector<char>& gt_free,
                                    const std::vector<char>& map_free, const WallMapRule& rule,
                                    const std::vector<Eigen::Vector2f>& stood_on, bool split);
}  // namespace mrpt_topoeval::internal
