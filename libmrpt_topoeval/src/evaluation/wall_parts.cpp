/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "evaluation/wall_parts.h"

#include <mrpt/maps/CSimplePointsMap.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "common/union_find.h"

namespace mrpt_topoeval::internal
{
namespace
{
// A region's points scored per placement: evenly thinned to this many (the coarse search
// scores turns x pivots x ground-truth vertices placements).
constexpr std::size_t kScoredPoints = 300;
// The best coarse placements refined by ICP, and two placements this far apart are distinct.
constexpr std::size_t kRefined = 20;
constexpr double kDistinctDeg = 5.0;
constexpr double kDistinctM = 0.5;
// A map vertex is near a region when a region point lies within its clearance + this [m].
constexpr double kPivotMargin = 1.0;
// ICP's first matching distance [m] (at least 3 cells).
constexpr double kIcpReach = 0.5;

struct Placement
{
    double share = 0.0;
    Transform2D t;
};

double shareOn(const WallIndex& gt_walls, const std::vector<Eigen::Vector2d>& pts,
               const Transform2D& t, double tolerance_m)
{
    std::size_t on = 0;
    for (const auto& q : pts) on += gt_walls.near(t.apply(q), tolerance_m) ? 1 : 0;
    return pts.empty() ? 0.0 : double(on) / double(pts.size());
}

/** Two placements of a region are one when they turn it alike and put its centre `c` alike
 * (the region's place, not the frame's origin, which lies anywhere). */
bool distinctFrom(const Transform2D& a, const std::vector<Placement>& kept,
                  const Eigen::Vector2d& c)
{
    for (const Placement& k : kept)
        if (std::abs(std::remainder(a.yaw_deg - k.t.yaw_deg, 360.0)) <= kDistinctDeg &&
            (a.apply(c) - k.t.apply(c)).norm() <= kDistinctM)
            return false;
    return true;
}

/** The first `n` placements of `sorted` (best first) distinct from each other. */
std::vector<Placement> distinct(const std::vector<Placement>& sorted, std::size_t n,
                                const Eigen::Vector2d& c)
{
    std::vector<Placement> out;
    for (const Placement& p : sorted)
    {
        if (out.size() == n) break;
        if (distinctFrom(p.t, out, c)) out.push_back(p);
    }
    return out;
}

/** Regions: wall points within `link` of each other, by union-find over square cells `link`
 * wide (a point's neighbours lie in its cell or the 8 around it). Largest first; ties by the
 * first point. */
std::vector<std::vector<Eigen::Vector2d>> regionsOf(const std::vector<Eigen::Vector2d>& pts,
                                                    double link)
{
    UnionFind sets(pts.size());
    std::map<std::pair<long, long>, std::vector<std::size_t>> cells;
    auto cellOf = [&](const Eigen::Vector2d& p)
    { return std::make_pair(long(std::floor(p.x() / link)), long(std::floor(p.y() / link))); };
    for (std::size_t i = 0; i < pts.size(); ++i) cells[cellOf(pts[i])].push_back(i);
    const double link2 = link * link;
    for (std::size_t i = 0; i < pts.size(); ++i)
    {
        const auto [cx, cy] = cellOf(pts[i]);
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy)
            {
                const auto it = cells.find({cx + dx, cy + dy});
                if (it == cells.end()) continue;
                for (std::size_t j : it->second)
                    if (j > i && (pts[i] - pts[j]).squaredNorm() <= link2)
                        sets.unite(int(i), int(j));
            }
    }
    // Regions numbered by their first point, then ordered by size (largest first).
    std::map<std::size_t, std::size_t> label_of_root;
    std::vector<std::vector<Eigen::Vector2d>> out;
    for (std::size_t i = 0; i < pts.size(); ++i)
    {
        const auto [it, fresh] = label_of_root.emplace(std::size_t(sets.find(int(i))), out.size());
        if (fresh) out.emplace_back();
        out[it->second].push_back(pts[i]);
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const auto& a, const auto& b) { return a.size() > b.size(); });
    return out;
}
}  // namespace

std::vector<WallPart> findWallParts(const TopologyGraph& gt, const TopologyGraph& placed,
                                    const WallIndex& gt_walls,
                                    const std::vector<Eigen::Vector2f>& unexplained,
                                    const std::vector<char>& gt_free,
                                    const std::vector<char>& map_free, const WallPartRule& rule)
{
    std::vector<WallPart> parts;
    if (gt_walls.empty() || unexplained.empty()) return parts;
    std::vector<Eigen::Vector2d> rest;
    for (const auto& w : unexplained) rest.push_back(w.cast<double>());
    const double cell = std::max(placed.map.resolution_m, 1e-6);
    if (double(rest.size()) * cell < rule.min_length_m) return parts;

    // Vertices free for a part's pairs (each goes to one part).
    std::vector<char> gt_left(gt.vertices.size(), 0), map_left(placed.vertices.size(), 0);
    for (std::size_t g = 0; g < gt_left.size() && g < gt_free.size(); ++g) gt_left[g] = gt_free[g];
    for (std::size_t m = 0; m < map_left.size() && m < map_free.size(); ++m)
        map_left[m] = map_free[m];
    std::vector<int> gt_pivots;
    for (std::size_t g = 0; g < gt.vertices.size(); ++g)
        if (g < gt_free.size() && gt_free[g]) gt_pivots.push_back(int(g));
    if (gt_pivots.empty()) return parts;

    // ICP's reference: every ground-truth wall point, indexed once (MRPT keeps its KD-tree).
    mrpt::maps::CSimplePointsMap reference;
    for (const auto& w : gt.wall_points_m) reference.insertPoint(w.x(), w.y(), 0.0f);
    const double res = std::max(gt.map.resolution_m, placed.map.resolution_m);

    for (const auto& region : regionsOf(rest, rule.link_m))
    {
        if (double(region.size()) * cell < rule.min_length_m) break;
        const std::vector<Eigen::Vector2d> scored = evenlyThinned(region, kScoredPoints);
        Eigen::Vector2d centre = Eigen::Vector2d::Zero();
        for (const auto& q : region) centre += q;
        centre /= double(region.size());
        // A region an accepted part already places is that part's.
        bool placed_already = false;
        for (const WallPart& p : parts)
            if (shareOn(gt_walls, scored, p.transform, rule.tolerance_m) >= rule.min_share)
                placed_already = true;
        if (placed_already) continue;
        // Its pivots: free map vertices whose clearance (+ a margin) reaches the region.
        std::vector<int> map_pivots;
        for (std::size_t m = 0; m < placed.vertices.size(); ++m)
        {
            if (m >= map_free.size() || !map_free[m]) continue;
            const auto& v = placed.vertices[m];
            const double reach = v.clearance_m + kPivotMargin;
            for (const auto& q : scored)
                if ((q - v.position_m).squaredNorm() <= reach * reach)
                {
                    map_pivots.push_back(int(m));
                    break;
                }
        }
        if (map_pivots.empty()) continue;
        // Coarse: every turn, every pivot pair.
        std::vector<Placement> coarse;
        const int turns = std::max(1, int(std::lround(360.0 / rule.turn_step_deg)));
        for (int k = 0; k < turns; ++k)
        {
            const double yaw = k * 360.0 / turns;
            const Transform2D turn{0.0, 0.0, yaw};
            for (int m : map_pivots)
            {
                const Eigen::Vector2d mq = turn.apply(placed.vertices[size_t(m)].position_m);
                for (int g : gt_pivots)
                {
                    const Eigen::Vector2d d = gt.vertices[size_t(g)].position_m - mq;
                    const Transform2D t{d.x(), d.y(), yaw};
                    coarse.push_back({shareOn(gt_walls, scored, t, rule.tolerance_m), t});
                }
            }
        }
        std::stable_sort(coarse.begin(), coarse.end(),
                         [](const Placement& a, const Placement& b) { return a.share > b.share; });
        // Refined by ICP of the region's points onto the ground truth's walls.
        mrpt::maps::CSimplePointsMap cloud;
        for (const auto& q : region) cloud.insertPoint(float(q.x()), float(q.y()), 0.0f);
        std::vector<Placement> refined;
        for (const Placement& c : distinct(coarse, kRefined, centre))
        {
            const Transform2D t = icpOfWalls(reference, cloud, c.t, res, kIcpReach);
            refined.push_back({shareOn(gt_walls, scored, t, rule.tolerance_m), t});
        }
        std::stable_sort(refined.begin(), refined.end(),
                         [](const Placement& a, const Placement& b) { return a.share > b.share; });
        const std::vector<Placement> best = distinct(refined, 2, centre);
        if (best.empty()) continue;
        const double runner = best.size() > 1 ? best[1].share : 0.0;
        if (best[0].share < rule.min_share || runner > rule.max_runner_up * best[0].share) continue;
        WallPart part;
        part.transform = best[0].t;
        part.share = best[0].share;
        part.runner_up = runner;
        part.points = scored;
        // Its pairs: each free ground-truth vertex the fit puts within pair_distance_m of a free
        // map vertex (the nearest; each vertex in one part's pairs only, ground-truth vertices
        // in id order).
        for (int g : gt_pivots)
        {
            if (!gt_left[size_t(g)]) continue;
            const Eigen::Vector2d& p = gt.vertices[size_t(g)].position_m;
            int nearest = -1;
            double d_best = rule.pair_distance_m;
            for (std::size_t m = 0; m < placed.vertices.size(); ++m)
            {
                if (!map_left[m]) continue;
                const double d = (part.transform.apply(placed.vertices[m].position_m) - p).norm();
                if (d <= d_best) d_best = d, nearest = int(m);
            }
            if (nearest >= 0)
            {
                map_left[size_t(nearest)] = 0;
                gt_left[size_t(g)] = 0;
                part.pairs.emplace_back(g, nearest);
            }
        }
        parts.push_back(std::move(part));
    }
    return parts;
}
}  // namespace mrpt_topoeval::internal
