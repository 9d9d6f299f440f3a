/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

namespace mrpt_topoeval
{
/** One end of an edge as seen from a vertex (paper II-C: the ring buffer of incident edges). */
struct Incidence
{
    int edge = -1;           //!< Index into TopologyGraph::edges.
    int other_vertex = -1;   //!< The vertex at the edge's other end (itself for a loop).
    bool at_from = true;     //!< True if this vertex is the edge's `from` end.
    double angle_rad = 0.0;  //!< Direction the edge leaves the vertex, world frame, (-pi, pi].
};

/** A junction (degree > 2) or dead end (degree 1) of the Topology Graph. */
struct TopoVertex
{
    int id = -1;                           //!< Equals the index in TopologyGraph::vertices.
    Eigen::Vector2d position_m{0.0, 0.0};  //!< World frame of the map [m].
    double clearance_m = 0.0;              //!< Distance to the nearest obstacle [m].
    bool spurious = false;                 //!< End of a short dead end (paper II-C).
    /** Incident edges ordered counter-clockwise by angle; a loop edge appears twice. */
    std::vector<Incidence> ring;
    /** Angle from each ring entry to the next, counter-clockwise, summing to 2 pi: the
     * rotation-independent ring buffer of the paper [rad]. */
    std::vector<double> angle_diffs_rad;
    double min_angle_rad = 0.0;  //!< Smallest entry of angle_diffs_rad [rad].
    double max_angle_rad = 0.0;  //!< Largest entry of angle_diffs_rad [rad].

    int degree() const { return static_cast<int>(ring.size()); }
};

/** A corridor between two vertices, following the Voronoi skeleton. */
struct TopoEdge
{
    int id = -1;  //!< Equals the index in TopologyGraph::edges.
    int from = -1;
    int to = -1;
    /** Polyline from `from`'s position to `to`'s position, world frame [m]. */
    std::vector<Eigen::Vector2d> path_m;
    /** Obstacle distance at each path point [m]. */
    std::vector<double> clearance_m;
    double length_m = 0.0;          //!< Length of the path [m].
    double min_clearance_m = 0.0;   //!< Smallest clearance along the path [m].
    double mean_clearance_m = 0.0;  //!< Length-weighted mean clearance along the path [m].
    bool dead_end = false;          //!< One end has degree 1.
    bool spurious = false;          //!< Dead end shorter than the spurious length.
};

/** Facts about the grid a graph was built from, for reports and drawing. */
struct MapInfo
{
    std::string file;            //!< Source file, if any.
    double resolution_m = 0.0;   //!< Cell size [m].
    int size_x = 0, size_y = 0;  //!< Cells.
    double x_min_m = 0.0, y_min_m = 0.0, x_max_m = 0.0, y_max_m = 0.0;
    std::size_t occupied_cells = 0;
    std::size_t free_cells = 0;
};

/** The Topology Graph of a grid map (paper section II). Plain data. */
struct TopologyGraph
{
    MapInfo map;
    std::vector<TopoVertex> vertices;
    std::vector<TopoEdge> edges;
    /** The outer boundary of the map used to cut the graph (alpha shape polygon) [m]. */
    std::vector<Eigen::Vector2d> outer_boundary_m;
    /** Centres of the occupied cells that border non-occupied space (the obstacle surfaces
     * the skeleton was built from), world frame [m]. The matcher checks a small group's rigid
     * fit against them (doc/matching.md). */
    std::vector<Eigen::Vector2f> wall_points_m;
    /** Notes on how the graph came out (no obstacles, pure ring, ...) for the user. */
    std::vector<std::string> warnings;

    std::size_t numHalfEdges() const { return 2 * edges.size(); }
    /** Sum of the edges' path lengths, each undirected edge once [m]. */
    double totalEdgeLength() const;
    std::size_t numNonSpuriousVertices() const;
    /** Number of non-spurious vertices of each degree: result[d] for degree d. */
    std::vector<std::size_t> degreeHistogram(bool include_spurious = false) const;
};

}  // namespace mrpt_topoeval
