/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// A mutable multigraph for the post-processing steps of paper II-B. Positions and lengths are in
// cell units here; GraphBuilder converts to metres at the end.

#include <Eigen/Core>

#include <cstddef>
#include <vector>

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

    int degree(int v) const { return static_cast<int>(m_v[v].edges.size()); }
    const std::vector<Vertex>& vertices() const { return m_v; }
    const std::vector<Edge>& edges() const { return m_e; }
    std::size_t numAliveVertices() const;
    std::size_t numAliveEdges() const;

    /** Replaces every chain through degree-2 vertices by one edge with the joined path (paper
     * II-B: only vertices of degree 1 or > 2 become graph vertices). A cycle with no other
     * vertex keeps one degree-2 vertex, the one of largest clearance, on a loop edge. Vertices
     * of degree 0 are removed. Linear in the graph size; compacts the storage. */
    void dissolveDegreeTwo();

    /** Removes dead-end edges shorter than `max_length`, or shorter than `corner_ratio` times
     * the clearance they lose from junction to end, with their dead-end vertex; dissolves
     * degree-2 vertices after each round, until none is left. Returns edges removed. */
    std::size_t pruneDeadEnds(double max_length, double corner_ratio);

    /** Removes the vertices for which `inside(pos)` is false, with their edges. */
    template <class Pred>
    std::size_t removeVerticesIf(Pred outside)
    {
        std::size_t n = 0;
        for (int v = 0; v < static_cast<int>(m_v.size()); ++v)
            if (m_v[v].alive && outside(m_v[v].pos))
            {
                removeVertex(v);
                ++n;
            }
        return n;
    }

    /** Keeps the connected part with the largest total edge length (ties: more vertices, then
     * the smallest position), removing the rest. */
    void keepLargestComponent();

    /** Merges the two ends of every non-loop edge shorter than `max_length` (transitively) into
     * one vertex at their mean position; the short edges disappear, longer edges inside a group
     * become loops (paper II-B, last step). Returns vertices removed by merging. */
    std::size_t joinClose(double max_length);

private:
    void removeEdge(int e);
    void removeVertex(int v);
    void compact();
    static double pathLength(const std::vector<Eigen::Vector2d>& path);

    std::vector<Vertex> m_v;
    std::vector<Edge> m_e;
};

}  // namespace mrpt_topoeval::internal
