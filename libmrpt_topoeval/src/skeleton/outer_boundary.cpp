/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "skeleton/outer_boundary.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>

#include "geometry/polygon.h"

namespace mrpt_topoeval::internal
{
namespace
{
using Key = std::pair<std::int64_t, std::int64_t>;
Key keyOf(const Eigen::Vector2d& p) { return {std::llround(p.x()), std::llround(p.y())}; }

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    return a.x() * b.y() - a.y() * b.x();
}
}  // namespace

std::vector<Eigen::Vector2d> longestBoundaryPolygon(
    const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& segments,
    std::size_t* num_polygons)
{
    // Sort for an order that does not depend on the triangulation's storage.
    std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> segs = segments;
    auto lessSeg = [](const auto& s, const auto& t)
    {
        return std::make_tuple(s.first.x(), s.first.y(), s.second.x(), s.second.y()) <
               std::make_tuple(t.first.x(), t.first.y(), t.second.x(), t.second.y());
    };
    std::sort(segs.begin(), segs.end(), lessSeg);

    std::map<Key, std::vector<int>> outgoing;
    for (int i = 0; i < static_cast<int>(segs.size()); ++i)
        outgoing[keyOf(segs[i].first)].push_back(i);

    std::vector<char> used(segs.size(), 0);
    std::vector<Eigen::Vector2d> best;
    double best_len = -1.0;
    std::size_t count = 0;
    for (int s0 = 0; s0 < static_cast<int>(segs.size()); ++s0)
    {
        if (used[s0]) continue;
        std::vector<Eigen::Vector2d> poly{segs[s0].first};
        double len = 0.0;
        const Key start = keyOf(segs[s0].first);
        int s = s0;
        bool closed = false;
        while (s >= 0)
        {
            used[s] = 1;
            const Eigen::Vector2d dir = segs[s].second - segs[s].first;
            len += dir.norm();
            const Key end = keyOf(segs[s].second);
            if (end == start)
            {
                closed = true;
                break;
            }
            poly.push_back(segs[s].second);
            // At a pinch point several segments leave one vertex: take the sharpest right turn,
            // which keeps each traced loop simple.
            int next = -1;
            double best_turn = 0.0;
            const auto it = outgoing.find(end);
            if (it != outgoing.end())
                for (int cand : it->second)
                {
                    if (used[cand]) continue;
                    const Eigen::Vector2d d = segs[cand].second - segs[cand].first;
                    const double turn = std::atan2(cross(dir, d), dir.dot(d));
                    if (next < 0 || turn < best_turn)
                    {
                        next = cand;
                        best_turn = turn;
                    }
                }
            s = next;
        }
        if (!closed) continue;
        ++count;
        // The segments run with the shape's interior on their left, so an outer loop runs
        // counter-clockwise (positive area) and a hole's boundary clockwise. A hole's can be the
        // longer: a floor plan drawn on a black page and then rotated has an obstacle band along
        // the page's edge, and the black between page and building is one hole whose boundary
        // runs along both. The outer shape is never a hole.
        if (signedArea(poly) > 0.0 && len > best_len)
        {
            best_len = len;
            best = std::move(poly);
        }
    }
    if (num_polygons) *num_polygons = count;
    return best;
}

bool pointInPolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p)
{
    bool inside = false;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++)
    {
        const Eigen::Vector2d &a = polygon[i], &b = polygon[j];
        if ((a.y() > p.y()) != (b.y() > p.y()) &&
            p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
            inside = !inside;
    }
    return inside;
}

}  // namespace mrpt_topoeval::internal
