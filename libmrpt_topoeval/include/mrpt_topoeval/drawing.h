/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt/img/CImage.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/QualityReport.h>
#include <mrpt_topoeval/TopologyGraph.h>

namespace mrpt_topoeval
{
/** How pictures are drawn. */
struct DrawOptions
{
    int scale = 2;              //!< Output pixels per map cell (1..8).
    bool draw_ids = true;       //!< Write vertex ids next to vertices.
    bool draw_boundary = true;  //!< Draw the alpha-shape outer boundary.
};

/** The grid map with its Topology Graph drawn over it, like the paper's Fig. 1 and 4: edges
 * along their paths (dead ends and spurious parts in their own colours), vertices, ids. Top of
 * the picture is +y. */
mrpt::img::CImage drawTopologyGraph(const mrpt::maps::COccupancyGridMap2D& grid,
                                    const TopologyGraph& graph, const DrawOptions& opts = {});

/** A match of two Topology Graphs, like the paper's Fig. 5 and 7: the ground-truth map (left)
 * and the robot map (right) side by side, each with its graph drawn as by drawTopologyGraph(),
 * scaled to a common height; a line from each matched ground-truth vertex to its map vertex,
 * green for isomorphism and red for neighbour growing; a ring around each ground-truth vertex
 * that GraphMatch::missing counts (non-spurious, unmatched); the file names above and a legend
 * with the counts below.
 *
 * The common height is `opts.scale` pixels per cell of the taller map; both maps are shrunk
 * together so that the picture stays at most 4000 pixels wide and the maps at most 4000 high.
 * Deterministic.
 * \throws InputError if `opts.scale` is outside 1..8 or a pair names a vertex that is not in
 * its graph. */
mrpt::img::CImage drawMatch(const mrpt::maps::COccupancyGridMap2D& gt_grid, const TopologyGraph& gt,
                            const mrpt::maps::COccupancyGridMap2D& map_grid,
                            const TopologyGraph& map, const GraphMatch& match,
                            const DrawOptions& opts = {});

/** A quality report's match with its brokenness groups, like the paper's Fig. 7 and 9: the
 * picture of drawMatch() (same layout, match lines, rings and limits), where each matched
 * vertex, on both maps, is filled with the colour of its brokenness group and labelled with
 * the group's number (0 = the largest group, as in BrokennessGroup order). Matched vertices in
 * no accepted group are grey, unmatched non-spurious ones white; spurious ones keep their graph
 * colour. Group numbers sit where the ids would; with `opts.draw_ids` the ids stay and the
 * numbers go below the vertices. Below the maps: a line with quality, coverage and brokenness
 * degree, one legend entry per group (number, vertices, yaw of its alignment), then the match
 * and edge legends. Colours repeat after 10 groups; the numbers do not. Deterministic.
 * \throws InputError if `opts.scale` is outside 1..8 or the report names a vertex that is not
 * in its graph. */
mrpt::img::CImage drawQualityReport(const mrpt::maps::COccupancyGridMap2D& gt_grid,
                                    const TopologyGraph& gt,
                                    const mrpt::maps::COccupancyGridMap2D& map_grid,
                                    const TopologyGraph& map, const QualityReport& report,
                                    const DrawOptions& opts = {});

}  // namespace mrpt_topoeval
