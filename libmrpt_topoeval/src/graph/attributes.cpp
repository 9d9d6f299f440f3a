/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "graph/attributes.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "geometry/polygon.h"
#include "graph/ring.h"

namespace mrpt_topoeval::internal
{
namespace
{

// Point at arc length `dist` along a path, from its start or from its end.
Eigen::Vector2d pointAlong(const std::vector<Eigen::Vector2d>& path, double dist, bool from_start)
{
    const std::size_t n = path.size();
    auto at = [&](std::size_t k) -> const Eigen::Vector2d&
    { return from_start ? path[k] : path[n - 1 - k]; };
    double run = 0.0;
    for (std::size_t k = 1; k < n; ++k)
    {
        const double seg = (at(k) - at(k - 1)).norm();
        if (run + seg >= dist && seg > 0.0)
            return at(k - 1) + (at(k) - at(k - 1)) * ((dist - run) / seg);
        run += seg;
    }
    return at(n - 1);
}

// Direction in which an edge leaves a vertex (paper II-C, incidence angles). Measured between
// two points along the path, at a quarter of `dist` and at `dist`: a junction sits off the
// corridors' centre lines (where three walls are equidistant) and the first Voronoi segments
// wiggle on a grid, while the corridor's own direction is what is stable across maps.
double leavingAngle(const std::vector<Eigen::Vector2d>& path, double length, double dist,
                    bool from_start)
{
    const double s1 = std::min(dist, 0.5 * length);
    const double s0 = std::min(0.25 * dist, 0.25 * length);
    Eigen::Vector2d d = pointAlong(path, s1, from_start) - pointAlong(path, s0, from_start);
    if (d.squaredNorm() < 1e-18)
        d = pointAlong(path, s1, from_start) - pointAlong(path, 0.0, from_start);
    return std::atan2(d.y(), d.x());
}
}  // namespace

void attributeGraph(const GraphEditor& g, const CellToWorld& to_world,
                    const GraphBuilderParameters& params, TopologyGraph& out)
{
    const auto& gv = g.vertices();
    const auto& ge = g.edges();
    const double res = to_world.resolution_m;

    // Canonical vertex numbering: by world position.
    std::vector<int> alive_v;
    for (int v = 0; v < static_cast<int>(gv.size()); ++v)
        if (gv[v].alive) alive_v.push_back(v);
    std::sort(alive_v.begin(), alive_v.end(),
              [&](int a, int b) {
                  return std::tie(gv[a].pos.x(), gv[a].pos.y()) <
                         std::tie(gv[b].pos.x(), gv[b].pos.y());
              });
    std::vector<int> vid(gv.size(), -1);
    out.vertices.clear();
    for (int v : alive_v)
    {
        vid[v] = static_cast<int>(out.vertices.size());
        TopoVertex tv;
        tv.id = vid[v];
        tv.position_m = to_world(gv[v].pos);
        tv.clearance_m = gv[v].clearance * res;
        out.vertices.push_back(std::move(tv));
    }

    // Edges in metres, oriented from the lower vertex id; loops counter-clockwise.
    out.edges.clear();
    for (const auto& E : ge)
    {
        if (!E.alive) continue;
        TopoEdge te;
        te.from = vid[E.a];
        te.to = vid[E.b];
        te.path_m.reserve(E.path.size());
        for (const auto& p : E.path) te.path_m.push_back(to_world(p));
        for (double c : E.clearance) te.clearance_m.push_back(c * res);
        bool reverse = te.from > te.to;
        if (te.from == te.to && te.path_m.size() > 2) reverse = signedArea(te.path_m) < 0.0;
        if (reverse)
        {
            std::swap(te.from, te.to);
            std::reverse(te.path_m.begin(), te.path_m.end());
            std::reverse(te.clearance_m.begin(), te.clearance_m.end());
        }
        // Length-weighted mean clearance (trapezoids) and the smallest clearance, including
        // the minimum inside segments found by the Voronoi step.
        double len = 0.0, area = 0.0;
        for (std::size_t k = 1; k < te.path_m.size(); ++k)
        {
            const double seg = (te.path_m[k] - te.path_m[k - 1]).norm();
            len += seg;
            area += seg * 0.5 * (te.clearance_m[k] + te.clearance_m[k - 1]);
        }
        te.length_m = len;
        te.mean_clearance_m = len > 0.0 ? area / len : te.clearance_m.front();
        te.min_clearance_m = std::min(
            E.min_clearance * res, *std::min_element(te.clearance_m.begin(), te.clearance_m.end()));
        out.edges.push_back(std::move(te));
    }
    std::sort(out.edges.begin(), out.edges.end(),
              [](const TopoEdge& a, const TopoEdge& b)
              {
                  const auto& pa = a.path_m[std::min<std::size_t>(1, a.path_m.size() - 1)];
                  const auto& pb = b.path_m[std::min<std::size_t>(1, b.path_m.size() - 1)];
                  return std::make_tuple(a.from, a.to, a.length_m, pa.x(), pa.y()) <
                         std::make_tuple(b.from, b.to, b.length_m, pb.x(), pb.y());
              });

    // Paper II-C: the ring of incident edges ordered by angle, kept as angle differences.
    for (int e = 0; e < static_cast<int>(out.edges.size()); ++e)
    {
        TopoEdge& te = out.edges[e];
        te.id = e;
        const double dist = params.edge_direction_distance_m;
        out.vertices[te.from].ring.push_back(
            {e, te.to, true, leavingAngle(te.path_m, te.length_m, dist, true)});
        out.vertices[te.to].ring.push_back(
            {e, te.from, false, leavingAngle(te.path_m, te.length_m, dist, false)});
    }
    for (TopoVertex& v : out.vertices)
    {
        std::sort(v.ring.begin(), v.ring.end(),
                  [](const Incidence& a, const Incidence& b)
                  {
                      return std::make_tuple(a.angle_rad, a.edge, !a.at_from) <
                             std::make_tuple(b.angle_rad, b.edge, !b.at_from);
                  });
        v.angle_diffs_rad = ringGaps(v.ring);
        if (!v.ring.empty())
        {
            v.min_angle_rad = *std::min_element(v.angle_diffs_rad.begin(), v.angle_diffs_rad.end());
            v.max_angle_rad = *std::max_element(v.angle_diffs_rad.begin(), v.angle_diffs_rad.end());
        }
    }

    // Dead ends, and short dead ends as spurious (paper II-C).
    for (TopoEdge& te : out.edges)
    {
        const bool from_end = out.vertices[te.from].degree() == 1;
        const bool to_end = out.vertices[te.to].degree() == 1;
        te.dead_end = from_end || to_end;
        te.spurious = te.dead_end && te.length_m < params.spurious_dead_end_length_m;
        if (te.spurious)
        {
            if (from_end) out.vertices[te.from].spurious = true;
            if (to_end) out.vertices[te.to].spurious = true;
        }
    }
}

}  // namespace mrpt_topoeval::internal
