/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Ours (issue 11): the scale pass. A floor plan drawn with a wrong resolution in its YAML, or a
// map whose odometry misjudged distances, has every distance off by one factor. The matcher's
// pairwise test forgives distance_tolerance_ratio (3 %) of a distance; beyond it only groups a
// few metres wide stay consistent, and a map 5 % too large falls into "broken" parts or
// matches nothing. After a first match, the factor is estimated from its rigid groups and, when
// the match shows it clearly, the map's graph is read at the ground truth's scale and matched
// again (doc/matching.md, "A map at another scale").

#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/TopologyGraph.h>

#include <cstddef>

namespace mrpt::maps
{
class COccupancyGridMap2D;
}  // namespace mrpt::maps

namespace mrpt_topoeval::internal
{
/** The factor by which a map's distances are the ground truth's, as a match shows it. */
struct MapScale
{
    double scale = 1.0;      //!< Ground-truth distance / map distance [ratio].
    double std_error = 0.0;  //!< Its standard error [ratio]; 0 without evidence.
    std::size_t pairs = 0;   //!< Pairs it was estimated from ...
    std::size_t groups = 0;  //!< ... in this many of the match's groups.
};

/** The scale of `map` against `gt` from `match`: each isomorphism (a group the matcher verified
 * as one rigid part) of at least 3 pairs gives Umeyama's least-squares factor s_k = sum a.(R b)
 * / sum |b|^2 over its centred pairs (a ground truth, b map, R Horn's rotation); they are pooled
 * weighted by sum |b|^2 (the parts' rotations against each other do not enter, so a broken map
 * shows its scale, not its breaks), with the standard error sigma / sqrt(sum of the weights),
 * sigma^2 the pooled residual over 2n - 4 degrees of freedom per group. Scale 1, no pairs, when
 * no group has 3 pairs. */
MapScale mapScaleOf(const TopologyGraph& gt, const TopologyGraph& map, const GraphMatch& match);

/** `g` with every length multiplied by `s` about the world origin: positions, paths,
 * clearances, edge lengths, the outer boundary, the wall points and the map's extent; angles,
 * degrees, ids and flags as they are. */
TopologyGraph scaledGraph(const TopologyGraph& g, double s);

/** `grid` read with cells `s` times as wide: the same cells, its resolution and limits
 * multiplied by `s` (a point of it lies at `s` times its world point). */
mrpt::maps::COccupancyGridMap2D scaledGrid(const mrpt::maps::COccupancyGridMap2D& grid, double s);

}  // namespace mrpt_topoeval::internal
