/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Ours (issue 11, "obstacle specks and furniture"): the clutter pass. A robot map holds the
// furniture a floor plan lacks, and every free-standing desk or shelf in a hall or room puts a
// loop around itself into the map's Topology Graph: its junctions gain degrees and their edges
// change, so the plan's vertices there have no similar partner. After a first match, the map's
// free-standing obstacles that the ground truth does not have where the match puts them are
// freed and the map's graph is built again (doc/matching.md, "The clutter pass").

#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/TopologyGraph.h>

#include <cstddef>
#include <optional>

namespace mrpt::maps
{
class COccupancyGridMap2D;
}  // namespace mrpt::maps

namespace mrpt_topoeval::internal
{
/** The map's free-standing obstacles judged by the match `match` of `gt` and `map` (the graph
 * of `map_grid`). An island (8-connected non-free cells surrounded by free space) at least
 * min_island_size_m and at most clutter_max_size_m across, within clutter_reach_m of a matched
 * map vertex, is clutter when under none of the match's alignments (Horn's fit of all its pairs, of
 * each of its groups, and of the pairs within reach of the island) clutter_min_wall_share of its
 * border cells lie within clutter_wall_tolerance_m of a ground-truth wall point. Returns a copy of
 * `map_grid` with the clutter made free, their number in `removed` and the number of islands judged
 * in `judged`; none when nothing is clutter. */
std::optional<mrpt::maps::COccupancyGridMap2D> withoutClutter(
    const TopologyGraph& gt, const TopologyGraph& map,
    const mrpt::maps::COccupancyGridMap2D& map_grid, const GraphMatch& match,
    const Parameters& params, std::size_t& removed, std::size_t& judged);

/** A copy of `map_grid` with every island from min_island_size_m to clutter_max_size_m across
 * made free, unjudged, and their number in `removed`; none when there is none. The clutter pass
 * starts from a match of it when the map's own match pairs too few vertices to judge by
 * (GraphMatcherParameters::clutter_start_without_islands). */
std::optional<mrpt::maps::COccupancyGridMap2D> withoutIslands(
    const mrpt::maps::COccupancyGridMap2D& map_grid, const Parameters& params,
    std::size_t& removed);

}  // namespace mrpt_topoeval::internal
