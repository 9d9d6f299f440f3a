/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt/img/CImage.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
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
mrpt::img::CImage drawTopologyGraph(
    const mrpt::maps::COccupancyGridMap2D& grid, const TopologyGraph& graph,
    const DrawOptions& opts = {});

}  // namespace mrpt_topoeval
