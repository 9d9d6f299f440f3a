/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The only translation unit that includes CGAL. Built with CGAL_NDEBUG: CGAL's debug checks make
// the dual() calls linear each (quadratic extraction; see the notes in doc/).

#include "skeleton/voronoi_cgal.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace mrpt_topoeval::internal
{
namespace
{
// Per face: the merged Voronoi node of its circumcentre (-1: dropped) and whether it belongs to
// the alpha shape's interior.
struct FaceInfo
{
    int node = -1;
    bool interior = false;
};
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
using Vb = CGAL::Triangulation_vertex_base_2<Kernel>;
using Fb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;

// Circumcentres of co-circular cell centres coincide up to rounding: merge them by a key on a
// fine lattice (1/1024 cell), so zero-length Voronoi segments disappear.
std::uint64_t nodeKey(double x, double y)
{
    const auto qx = static_cast<std::int64_t>(std::llround(x * 1024.0));
    const auto qy = static_cast<std::int64_t>(std::llround(y * 1024.0));
    return (static_cast<std::uint64_t>(qx) << 32) ^ static_cast<std::uint64_t>(qy & 0xffffffff);
}

// Smallest distance from site p to the segment a-b: along a Voronoi edge the distance to its two
// sites is equal, and it is smallest at the foot of the perpendicular from p (if on the segment).
double segmentClearance(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                        const Eigen::Vector2d& p)
{
    const Eigen::Vector2d ab = b - a;
    const double len2 = ab.squaredNorm();
    double t = len2 > 0.0 ? (p - a).dot(ab) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return (a + t * ab - p).norm();
}

}  // namespace

VoronoiSkeleton computeVoronoiSkeleton(const VoronoiInput& in)
{
    VoronoiSkeleton out;
    if (in.sites.size() < 3) return out;

    std::vector<Point> pts;
    pts.reserve(in.sites.size());
    for (const auto& s : in.sites) pts.emplace_back(s.x(), s.y());

    // Range insertion spatially sorts first: 100x faster than inserting one by one.
    Delaunay dt;
    dt.insert(pts.begin(), pts.end());
    if (dt.dimension() < 2) return out;

    // Paper II-B: the Voronoi vertices are the circumcentres of the Delaunay faces.
    std::unordered_map<std::uint64_t, int> key_node;
    key_node.reserve(dt.number_of_faces());
    const double alpha2 = in.alpha_radius_cells * in.alpha_radius_cells;

    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    {
        const Point c = dt.circumcenter(f);
        const Eigen::Vector2d cc(c.x(), c.y());
        const Point& v0 = f->vertex(0)->point();
        const double r = std::hypot(c.x() - v0.x(), c.y() - v0.y());
        f->info().interior = r * r <= alpha2;

        const long cx = std::lround(cc.x()), cy = std::lround(cc.y());
        bool keep = cx >= 0 && cy >= 0 && cx < in.size_x && cy < in.size_y;
        if (keep && !in.keep_mask.empty())
            keep = in.keep_mask[static_cast<std::size_t>(cx) +
                                static_cast<std::size_t>(cy) * in.size_x] != 0;
        if (!keep) continue;

        const std::uint64_t key = nodeKey(cc.x(), cc.y());
        auto [it, inserted] = key_node.emplace(key, static_cast<int>(out.node_pos.size()));
        if (inserted)
        {
            out.node_pos.push_back(cc);
            out.node_clearance.push_back(r);
        }
        f->info().node = it->second;
    }

    // Voronoi edges: the duals of Delaunay edges between two finite faces (hull edges give rays,
    // which lie outside the map). Paper II-B step 1: drop those too close to an obstacle.
    for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
    {
        const Delaunay::Face_handle f = e->first;
        const int i = e->second;
        const Delaunay::Face_handle g = f->neighbor(i);

        if (alpha2 > 0.0)
        {
            const bool fin = !dt.is_infinite(f) && f->info().interior;
            const bool gin = !dt.is_infinite(g) && g->info().interior;
            if (fin != gin)
            {
                // Orient with the interior face on the left: ccw(i) -> cw(i) is ccw around f.
                const Point& p = f->vertex(f->ccw(i))->point();
                const Point& q = f->vertex(f->cw(i))->point();
                Eigen::Vector2d a(p.x(), p.y()), b(q.x(), q.y());
                if (!fin) std::swap(a, b);
                out.alpha_boundary.emplace_back(a, b);
            }
        }

        if (dt.is_infinite(f) || dt.is_infinite(g)) continue;
        const int na = f->info().node, nb = g->info().node;
        if (na < 0 || nb < 0) continue;
        if (na == nb) continue;  // degenerate (co-circular) zero-length edge

        ++out.edges_total;
        const Point& s = f->vertex(f->cw(i))->point();
        const double clearance =
            segmentClearance(out.node_pos[na], out.node_pos[nb], Eigen::Vector2d(s.x(), s.y()));
        if (clearance < in.min_clearance_cells) continue;
        out.edges.push_back({na, nb, clearance});
    }
    return out;
}

}  // namespace mrpt_topoeval::internal
