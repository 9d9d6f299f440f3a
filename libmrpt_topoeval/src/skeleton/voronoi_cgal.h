/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// The only interface to CGAL (paper II-A/II-B): everything in cell units, no CGAL types.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace mrpt_topoeval::internal
{
/** What the Voronoi step needs to know about the grid. Coordinates are cell indices: the
 * centre of cell (cx, cy) is the point (cx, cy). */
struct VoronoiInput
{
    std::vector<Eigen::Vector2i> sites;  //!< Obstacle cells (Voronoi sites), no duplicates.
    int size_x = 0, size_y = 0;          //!< Grid size; Voronoi vertices outside are dropped.
    /** If non-empty (size_x * size_y, row-major cx + cy * size_x), a Voronoi vertex is kept
     * only if the cell under it is non-zero here (free cells). */
    std::vector<std::uint8_t> keep_mask;
    double min_clearance_cells = 0.0;  //!< Voronoi edges nearer than this to a site are dropped.
    double alpha_radius_cells = 0.0;   //!< > 0: also compute the alpha-shape boundary.
};

/** The filtered Voronoi diagram as a plain graph, plus the alpha-shape boundary. */
struct VoronoiSkeleton
{
    std::vector<Eigen::Vector2d> node_pos;  //!< Voronoi vertices [cells].
    std::vector<double> node_clearance;     //!< Distance to the nearest site [cells].
    struct Edge
    {
        int a = -1, b = -1;
        double min_clearance = 0.0;  //!< Smallest site distance along the segment [cells].
    };
    std::vector<Edge> edges;      //!< Voronoi segments kept by the clearance filter.
    std::size_t edges_total = 0;  //!< Voronoi segments between kept nodes before the filter.
    /** Boundary segments of the regularized alpha shape (interior faces: circumradius <=
     * alpha), each oriented with the interior on its left [cells]. */
    std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> alpha_boundary;
};

/** Delaunay triangulation of the sites (CGAL, range insertion), its dual Voronoi diagram with
 * coincident vertices merged, the clearance filter, and the alpha-shape boundary. Fewer than
 * three non-collinear sites give an empty skeleton. */
VoronoiSkeleton computeVoronoiSkeleton(const VoronoiInput& in);

}  // namespace mrpt_topoeval::internal
