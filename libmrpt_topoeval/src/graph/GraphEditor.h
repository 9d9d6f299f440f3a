/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// A mutable multigraph for the post-processing steps of paper II-B. Positions and lengths are in
// cell units here; GraphBuilder converts to metres at the end.

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <vector>

#include "skeleton/voronoi_cgal.h"

namespace mrpt_topoeval::internal
{
class GraphEditor
{
public:
    struct Vertex
    {
        Eigen::Vector2d pos;
        double clearance = 0.0;
        std::vector<int> edges;  //!< Incident alive edges; a loop is listed twice.
        bool alive = true;
    };
    struct Edge
    {
        int a = -1, b = -1;
        std::vector<Eigen::Vector2d> path;  //!< From a's position to b's position.
        std::vector<double> clearance;      //!< Per path point.
        double min_clearance = 0.0;         //!< Smallest along the segments.
        double length = 0.0;
        bool alive = true;
    };

    int addVertex(const Eigen::Vector2d& pos, double clearance);
    /** A straight edge a-b (one Voronoi segment). */
    int addSegment(int a, int b, double min_clearance);

    /** The graph of the Voronoi segments with every chain through degree-2 nodes joined into
     * one edge: the same graph as addVertex() for each node in order of first use by the
     * segments (a segment's a before its b), addSegment() for each segment, then
     * dissolveDegreeTwo(), without the two vectors per segment that those store (a 10^8-cell
     * map has millions of segments; that step took 1.7 of its 10.6 s, doc/performance.md). */
    static GraphEditor fromSkeleton(const VoronoiSkeleton& vd);

    int degree(int v) const { return static_cast<int>(m_v[v].edges.size()); }
    const std::vector<Vertex>& vertices() const { return m_v; }
    const std::vector<Edge>& edges() const { return m_e; }
    std::size_t numAliveVertices() const;

    /** Replaces every chain through degree-2 vertices by one edge with the joined path (paper
     * II-B: only vertices of degree 1 or > 2 become graph vertices). A cycle with no other
     * vertex keeps one degree-2 vertex, the one of largest clearance, on a loop edge. Vertices
     * of degree 0 are removed. Linear in the graph size; compacts the storage. */
    void dissolveDegreeTwo();

    /** Removes dead-end edges, with their dead-end vertex, that are shorter than `max_length`,
     * or whose chord is shorter than `corner_ratio` times the clearance they lose from junction
     * to end, or (when shorter than `disc_max_chord`) than `disc_ratio` times the junction's
     * clearance; dissolves degree-2 vertices after each round, until none is left. Two phases:
     * the first two rules alone until a round removes nothing, then all three (the junction
     * disc judges a dead end by its junction, which a spur about to go may have made). Returns
     * edges removed. */
    std::size_t pruneDeadEnds(double max_length, double corner_ratio, double disc_ratio,
                              double disc_max_chord);

    /** Moves the tip of every dead end back along its path, out of the corner it may run
     * into: the tail is the points whose clearance exceeds the tip's by at least 1 /
     * `wedge_ratio` of their distance to the tip (outside the junction's disc); the tip goes
     * back to the last point whose clearance is at least `share` times the tail's largest,
     * and the rest is cut off. Returns the dead ends moved. */
    std::size_t retractDeadEndTails(double share, double wedge_ratio);

    /** Cuts the graph to a region (paper II-B, the alpha-shape cut): vertices outside go with
     * their edges, except that an edge from an inside vertex to an outside one is cut where
     * its path leaves the region and ends in a new dead end there, so a corridor that leaves
     * the map through an open door keeps its inside part. Returns vertices removed. */
    template <class Inside>
    std::size_t cutOutside(Inside inside)
    {
        const int nv = static_cast<int>(m_v.size());
        std::vector<char> in(nv, 0);
        for (int v = 0; v < nv; ++v) in[v] = m_v[v].alive && inside(m_v[v].pos);
        for (int e = 0; e < static_cast<int>(m_e.size()); ++e)
        {
            Edge& E = m_e[e];
            if (!E.alive || in[E.a] == in[E.b]) continue;
            if (!in[E.a]) reverseEdge(E);  // now a is inside, b outside
            std::size_t k = 1;
            while (k < E.path.size() && inside(E.path[k])) ++k;
            truncateEdge(e, k);  // keeps path[0..k-1], ends at a new vertex
        }
        std::size_t n = 0;
        for (int v = 0; v < nv; ++v)
            if (m_v[v].alive && !in[v])
            {
                removeVertex(v);
                ++n;
            }
        return n;
    }

    /** Keeps the connected part with the largest total edge length (ties: more vertices, then
     * the smallest position) and every other part whose total edge length is at least
     * `min_length`, or at least `min_room_length` when `is_room` says so of its edges, removing
     * the rest. */
    void keepComponents(double min_length, double min_room_length,
                        const std::function<bool(const std::vector<const Edge*>&)>& is_room);

    /** Merges the two ends of every non-loop edge shorter than `max_length` (transitively) into
     * one vertex at their mean position; the short edges disappear, longer edges inside a group
     * become loops (paper II-B, last step). Returns vertices removed by merging. */
    std::size_t joinClose(double max_length);

private:
    void removeEdge(int e);
    void removeVertex(int v);
    static void reverseEdge(Edge& E);
    /** Keeps the first `keep` path points of edge e (a to the cut) and ends it at a new
     * vertex there, detached from the old end b. */
    void truncateEdge(int e, std::size_t keep);
    static double pathLength(const std::vector<Eigen::Vector2d>& path);

    std::vector<Vertex> m_v;
    std::vector<Edge> m_e;
};

}  // namespace mrpt_topoeval::internal
