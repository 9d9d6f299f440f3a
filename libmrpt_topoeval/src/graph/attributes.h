/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/graph/build_graph.h>

#include "graph/GraphEditor.h"

namespace mrpt_topoeval::internal
{
/** Cell coordinates (cell centre of (cx, cy) = (cx, cy)) to metres in the map's world frame. */
struct CellToWorld
{
    double x0_m = 0.0, y0_m = 0.0;  //!< World position of the centre of cell (0, 0).
    double resolution_m = 1.0;
    Eigen::Vector2d operator()(const Eigen::Vector2d& c) const
    {
        return {x0_m + c.x() * resolution_m, y0_m + c.y() * resolution_m};
    }
};

/** Paper II-C: turns the post-processed graph into a TopologyGraph in metres with edge
 * attributes (length, clearances, dead end, spurious) and vertex attributes (clearance, the
 * ring of incident edges by angle and its angle differences). Numbering is canonical: vertices
 * by position, edges by their ends, so it does not depend on CGAL's storage order. */
void attributeGraph(const GraphEditor& g, const CellToWorld& to_world,
                    const GraphBuilderParameters& params, TopologyGraph& out);

}  // namespace mrpt_topoeval::internal
