/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The scale pass (ours, issue 11): the factor a match shows between the map's distances and the
// ground truth's, and a graph or grid read at another scale (doc/matching.md, "A map at another
// scale").

#include "pipeline/map_scale.h"

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace mrpt_topoeval::internal
{
MapScale mapScaleOf(const TopologyGraph& gt, const TopologyGraph& map, const GraphMatch& match)
{
    // Each isomorphism's core pairs: a group the matcher fitted as one rigid part.
    std::map<int, std::vector<const VertexPair*>> cores;
    for (const VertexPair& p : match.pairs)
        if (p.stage == MatchStage::Isomorphism && p.isomorphism >= 0 && p.ground_truth >= 0 &&
            p.map >= 0 && p.ground_truth < int(gt.vertices.size()) &&
            p.map < int(map.vertices.size()))
            cores[p.isomorphism].push_back(&p);
    MapScale out;
    double weighted = 0.0, weights = 0.0, rss = 0.0, dof = 0.0;
    for (const auto& [k, pairs] : cores)
    {
        const std::size_t n = pairs.size();
        if (n < 3) continue;
        Eigen::Vector2d cg = Eigen::Vector2d::Zero(), cm = Eigen::Vector2d::Zero();
        for (const VertexPair* p : pairs)
        {
            cg += gt.vertices[p->ground_truth].position_m;
            cm += map.vertices[p->map].position_m;
        }
        cg /= double(n);
        cm /= double(n);
        // Umeyama in 2D on centred points: the rotation is Horn's, the factor
        // |(sum m.g, sum m x g)| / sum |m|^2, and the residual sum |g|^2 - that^2 sum |m|^2.
        double sc = 0.0, ss = 0.0, mm = 0.0, gg = 0.0;
        for (const VertexPair* p : pairs)
        {
            const Eigen::Vector2d g = gt.vertices[p->ground_truth].position_m - cg;
            const Eigen::Vector2d m = map.vertices[p->map].position_m - cm;
            sc += m.dot(g);
            ss += m.x() * g.y() - m.y() * g.x();
            mm += m.squaredNorm();
            gg += g.squaredNorm();
        }
        if (!(mm > 0.0)) continue;
        const double s = std::hypot(sc, ss) / mm;
        weighted += s * mm;
        weights += mm;
        rss += std::max(0.0, gg - s * s * mm);
        dof += 2.0 * double(n) - 4.0;
        out.pairs += n;
        ++out.groups;
    }
    if (out.groups == 0) return {};
    out.scale = weighted / weights;
    out.std_error = dof > 0.0 ? std::sqrt(rss / dof / weights) : 0.0;
    return out;
}

TopologyGraph scaledGraph(const TopologyGraph& g, double s)
{
    TopologyGraph out = g;
    for (TopoVertex& v : out.vertices)
    {
        v.position_m *= s;
        v.clearance_m *= s;
    }
    for (TopoEdge& e : out.edges)
    {
        for (Eigen::Vector2d& p : e.path_m) p *= s;
        for (double& c : e.clearance_m) c *= s;
        e.length_m *= s;
        e.min_clearance_m *= s;
        e.mean_clearance_m *= s;
    }
    for (Eigen::Vector2d& p : out.outer_boundary_m) p *= s;
    for (Eigen::Vector2f& p : out.wall_points_m) p *= static_cast<float>(s);
    out.map.resolution_m *= s;
    out.map.x_min_m *= s;
    out.map.y_min_m *= s;
    out.map.x_max_m *= s;
    out.map.y_max_m *= s;
    return out;
}

mrpt::maps::COccupancyGridMap2D scaledGrid(const mrpt::maps::COccupancyGridMap2D& grid, double s)
{
    mrpt::maps::COccupancyGridMap2D out;
    // The limits are multiples of the cell, so of the scaled cell too: setSize's snapping keeps
    // them and the cell counts.
    out.setSize(grid.getXMin() * s, grid.getXMax() * s, grid.getYMin() * s, grid.getYMax() * s,
                grid.getResolution() * s);
    const unsigned sx = std::min(out.getSizeX(), grid.getSizeX()),
                   sy = std::min(out.getSizeY(), grid.getSizeY());
    // Cell values as stored (log-odds), not through probabilities and back.
    for (unsigned y = 0; y < sy; ++y)
        std::copy_n(grid.getRow(static_cast<int>(y)), sx, out.getRow(static_cast<int>(y)));
    return out;
}

}  // namespace mrpt_topoeval::internal
