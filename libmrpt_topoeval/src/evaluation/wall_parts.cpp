/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "evaluation/wall_parts.h"

#include <mrpt/maps/CSimplePointsMap.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <optional>

#include "common/union_find.h"

namespace mrpt_topoeval::internal
{
namespace
{
// A region's points scored per placement: evenly thinned to this many (the coarse search
// scores turns x pivots x ground-truth vertices placements).
constexpr std::size_t kScoredPoints = 300;
// Coarse placements are scored first on a kFirstRound-th of their points (at least
// kFirstRoundMin), then the best of them on all, until kRescoredDistinct distinct ones are among
// those (1500-2000 placements of 10^5-10^6 on the Intel RBPF snapshots, where the 20 refined
// are those scoring every placement on every point gives but for ties at the twentieth's share;
// every corpus's outputs the same but two groups' turns by 0.01-0.07 degrees).
constexpr std::size_t kFirstRound = 5;
constexpr std::size_t kFirstRoundMin = 12;
constexpr std::size_t kRescoredDistinct = 1000;
// The best coarse placements refined by ICP, and two placements this far apart are distinct.
constexpr std::size_t kRefined = 20;
constexpr double kDistinctDeg = 5.0;
constexpr double kDistinctM = 0.5;
// A map vertex is near a region when a region point lies within its clearance + this [m].
constexpr double kPivotMargin = 1.0;
// ICP's first matching distance [m] (at least 3 cells).
constexpr double kIcpReach = 0.5;
// A part's region (placeMapByWalls) is judged on at most this many of the points left.
constexpr std::size_t kRegionSample = 3000;
// A whole map's placement (placeMapByWalls) tries at most this many map vertices as pivots
// (each with every ground-truth vertex) ...
constexpr std::size_t kMapPivots = 32;
// ... scores the map's first placement on this many points (it only singles out a region, whose
// own placement is scored on kScoredPoints), and refines by ICP on at most this many.
constexpr std::size_t kFirstScoredPoints = 60;
constexpr std::size_t kIcpPoints = 2000;
// A map vertex's walls a part must explain for the part to place it (the validator's truth
// asks a quarter of them too).
constexpr double kOwnWalls = 0.25;

struct Placement
{
    double share = 0.0;
    Transform2D t;
    int pivot = -1;  //!< The map vertex the coarse search put on a ground-truth vertex.
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

/** `pts` in square cells `radius` wide, for the points within `radius` of a place: they lie in
 * its cell or the 8 around it. */
class Neighbours
{
public:
    Neighbours(const std::vector<Eigen::Vector2d>& pts, double radius) : m_pts(pts), m_r(radius)
    {
        for (std::size_t i = 0; i < pts.size(); ++i) m_cells[cellOf(pts[i])].push_back(i);
    }
    /** `f(j)` for each point j within the radius of `q` (in no particular order). */
    template <class F>
    void within(const Eigen::Vector2d& q, F f) const
    {
        const auto [cx, cy] = cellOf(q);
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy)
            {
                const auto it = m_cells.find({cx + dx, cy + dy});
                if (it == m_cells.end()) continue;
                for (std::size_t j : it->second)
                    if ((m_pts[j] - q).squaredNorm() <= m_r * m_r) f(j);
            }
    }

private:
    std::pair<long, long> cellOf(const Eigen::Vector2d& p) const
    {
        return {long(std::floor(p.x() / m_r)), long(std::floor(p.y() / m_r))};
    }
    const std::vector<Eigen::Vector2d>& m_pts;
    double m_r;
    std::map<std::pair<long, long>, std::vector<std::size_t>> m_cells;
};

/** Regions: wall points within `link` of each other, by union-find over square cells `link`
 * wide (a point's neighbours lie in its cell or the 8 around it). Largest first; ties by the
 * first point. */
std::vector<std::vector<Eigen::Vector2d>> regionsOf(const std::vector<Eigen::Vector2d>& pts,
                                                    double link)
{
    UnionFind sets(pts.size());
    const Neighbours near(pts, link);
    for (std::size_t i = 0; i < pts.size(); ++i)
        near.within(pts[i],
                    [&](std::size_t j)
                    {
                        if (j > i) sets.unite(int(i), int(j));
                    });
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

/** The vertices of `g` free for pivots (`free`) whose clearance + kPivotMargin reaches a point
 * of `pts`. */
std::vector<int> pivotsNear(const TopologyGraph& g, const std::vector<Eigen::Vector2d>& pts,
                            const std::vector<char>& free)
{
    std::vector<int> out;
    for (std::size_t m = 0; m < g.vertices.size(); ++m)
    {
        if (m >= free.size() || !free[m]) continue;
        const auto& v = g.vertices[m];
        const double reach = v.clearance_m + kPivotMargin;
        for (const auto& q : pts)
            if ((q - v.position_m).squaredNorm() <= reach * reach)
            {
                out.push_back(int(m));
                break;
            }
    }
    return out;
}

/** The two best distinct placements of `region` (`scored`: its thinned points, `centre` its
 * centre) on the ground truth's walls, best first: every turn of turn_step_deg with each pivot
 * pair's map vertex put on its ground-truth vertex, scored by the share of `coarse_pts` on a
 * wall; the best kRefined distinct refined by MRPT's ICP of `region` onto `reference` and scored
 * again on `scored`. */
std::vector<Placement> bestPlacements(
    const TopologyGraph& gt, const TopologyGraph& placed, const WallIndex& gt_walls,
    const mrpt::maps::CSimplePointsMap& reference, const std::vector<Eigen::Vector2d>& region,
    const std::vector<Eigen::Vector2d>& scored, const std::vector<Eigen::Vector2d>& coarse_pts,
    const Eigen::Vector2d& centre, const std::vector<std::pair<int, int>>& pivot_pairs, double res,
    const WallPartRule& rule)
{
    // Coarse: every turn, every pivot pair (map vertex, ground-truth vertex), in two rounds:
    // each placement scored on a kFirstRound-th of coarse_pts, the best of those on all of
    // coarse_pts (a large region has thousands of pivot pairs: 10^5-10^6 placements, each
    // scored on 300 points took 16 s of a broken Intel snapshot's compare).
    const std::vector<Eigen::Vector2d> first_pts =
        evenlyThinned(coarse_pts, std::max(kFirstRoundMin, coarse_pts.size() / kFirstRound));
    std::vector<Placement> coarse;
    const int turns = std::max(1, int(std::lround(360.0 / rule.turn_step_deg)));
    for (int k = 0; k < turns; ++k)
    {
        const double yaw = k * 360.0 / turns;
        const Transform2D turn{0.0, 0.0, yaw};
        for (const auto& [m, g] : pivot_pairs)
        {
            const Eigen::Vector2d d = gt.vertices[size_t(g)].position_m -
                                      turn.apply(placed.vertices[size_t(m)].position_m);
            const Transform2D t{d.x(), d.y(), yaw};
            coarse.push_back({shareOn(gt_walls, first_pts, t, rule.tolerance_m), t, m});
        }
    }
    if (first_pts.size() < coarse_pts.size())
    {
        // Rescored: the first round's best (ties: in the order tried), until kRescoredDistinct
        // distinct placements are among them; then in the order tried, so that equal shares
        // sort as a single round sorts them.
        std::vector<std::size_t> order(coarse.size());
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) {
                      return coarse[a].share > coarse[b].share ||
                             (coarse[a].share == coarse[b].share && a < b);
                  });
        std::vector<Placement> seen;
        std::size_t prefix = 0;
        while (prefix < order.size() && seen.size() < kRescoredDistinct)
        {
            const Placement& c = coarse[order[prefix++]];
            if (distinctFrom(c.t, seen, centre)) seen.push_back(c);
        }
        // Each map pivot's best goes on too (see the refined, below); the rest of the order is
        // walked only until every pivot has one (it holds up to 10^6 placements).
        std::vector<std::size_t> kept(order.begin(), order.begin() + std::ptrdiff_t(prefix));
        std::vector<char> is_pivot(placed.vertices.size(), 0), pivot_in(is_pivot);
        for (const auto& pair : pivot_pairs) is_pivot[size_t(pair.first)] = 1;
        const auto pivots = std::size_t(std::count(is_pivot.begin(), is_pivot.end(), 1));
        std::size_t pivots_in = 0;
        auto firstOfPivot = [&](std::size_t i)
        {
            char& in = pivot_in[size_t(coarse[i].pivot)];
            if (in) return false;
            in = 1;
            return true;
        };
        for (std::size_t i : kept) pivots_in += firstOfPivot(i) ? 1 : 0;
        for (std::size_t k = prefix; k < order.size() && pivots_in < pivots; ++k)
            if (firstOfPivot(order[k]))
            {
                kept.push_back(order[k]);
                ++pivots_in;
            }
        order = std::move(kept);
        std::sort(order.begin(), order.end());
        std::vector<Placement> rescored;
        for (std::size_t i : order)
            rescored.push_back({shareOn(gt_walls, coarse_pts, coarse[i].t, rule.tolerance_m),
                                coarse[i].t, coarse[i].pivot});
        coarse = std::move(rescored);
    }
    std::stable_sort(coarse.begin(), coarse.end(),
                     [](const Placement& a, const Placement& b) { return a.share > b.share; });
    // Refined by ICP of the region's points onto the ground truth's walls.
    mrpt::maps::CSimplePointsMap cloud;
    for (const auto& q : region) cloud.insertPoint(float(q.x()), float(q.y()), 0.0f);
    // The best kRefined distinct, and each map pivot's best: more pivots (a region near more
    // free vertices) must not crowd a pivot's only good placement out of the few refined
    // (held-out house_9002/broken_1: a sealed room's two vertices, session 48).
    std::vector<Placement> candidates = distinct(coarse, kRefined, centre);
    std::vector<char> pivot_done(placed.vertices.size(), 0);
    for (const Placement& c : coarse)  // best first
        if (!pivot_done[size_t(c.pivot)] && distinctFrom(c.t, candidates, centre))
        {
            pivot_done[size_t(c.pivot)] = 1;
            candidates.push_back(c);
        }
    std::vector<Placement> refined;
    for (const Placement& c : candidates)
    {
        const Transform2D t = icpOfWalls(reference, cloud, c.t, res, kIcpReach);
        refined.push_back({shareOn(gt_walls, scored, t, rule.tolerance_m), t, c.pivot});
    }
    std::stable_sort(refined.begin(), refined.end(),
                     [](const Placement& a, const Placement& b) { return a.share > b.share; });
    return distinct(refined, kRefined, centre);
}

/** How many of `map_vertices` (a region's) `t` puts within `reach` of a vertex of `gt_vertices`
 * (the nearest not taken, map vertices in order). */
int pinned(const TopologyGraph& gt, const TopologyGraph& map, const std::vector<int>& map_vertices,
           const std::vector<int>& gt_vertices, const Transform2D& t, double reach)
{
    std::vector<char> taken(gt.vertices.size(), 0);
    int n = 0;
    for (int m : map_vertices)
    {
        const Eigen::Vector2d at = t.apply(map.vertices[size_t(m)].position_m);
        int nearest = -1;
        double d_best = reach;
        for (int g : gt_vertices)
        {
            if (taken[size_t(g)]) continue;
            const double d = (gt.vertices[size_t(g)].position_m - at).norm();
            if (d <= d_best) d_best = d, nearest = g;
        }
        if (nearest >= 0) taken[size_t(nearest)] = 1, ++n;
    }
    return n;
}

/** The map's free space around a region, as its Topology Graph sees it: the clearance discs
 * along its edges (the medial axis and its clearance are the free space, as a medial axis
 * transform), sampled a cell apart, those whose disc reaches the region (its clearance + 2
 * cells), at most kScoredPoints evenly thinned. A placement of the region that puts a
 * ground-truth wall inside such a disc (deeper than `slack`) puts the map's free space on a wall:
 * a room turned half round has its doorway where the truth has a wall, a room slid onto a like
 * room elsewhere a wall through its middle. */
class FreeSpace
{
public:
    FreeSpace(const TopologyGraph& map, const std::vector<Eigen::Vector2d>& region, double slack)
        : m_slack(slack)
    {
        if (region.empty()) return;
        const double cell = std::max(map.map.resolution_m, 1e-6);
        Eigen::Vector2d lo = region.front(), hi = region.front();
        for (const auto& q : region) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
        std::vector<Disc> discs;
        auto sample = [&](const Eigen::Vector2d& p, double c)
        {
            const double reach = c + 2.0 * cell;
            if (c <= slack || (p.array() < lo.array() - reach).any() ||
                (p.array() > hi.array() + reach).any())
                return;
            for (const auto& q : region)
                if ((q - p).squaredNorm() <= reach * reach)
                {
                    discs.push_back({p, c});
                    return;
                }
        };
        for (const auto& e : map.edges)
        {
            if (e.path_m.empty() || e.clearance_m.size() != e.path_m.size()) continue;
            sample(e.path_m.front(), e.clearance_m.front());
            for (std::size_t i = 1; i < e.path_m.size(); ++i)
            {
                // A simplified path's points are metres apart; the clearance between two of
                // them is taken as linear.
                const Eigen::Vector2d a = e.path_m[i - 1], b = e.path_m[i];
                const int steps = std::max(1, int(std::ceil((b - a).norm() / cell)));
                for (int k = 1; k <= steps; ++k)
                {
                    const double f = double(k) / double(steps);
                    sample(a + f * (b - a),
                           (1.0 - f) * e.clearance_m[i - 1] + f * e.clearance_m[i]);
                }
            }
        }
        m_discs = evenlyThinned(discs, kScoredPoints);
    }
    /** The share of the discs that `t` puts clear of every ground-truth wall (but `slack`);
     * 0 when the graph has no disc at the region. */
    double share(const WallIndex& gt_walls, const Transform2D& t) const
    {
        std::size_t clear = 0;
        for (const Disc& d : m_discs)
            clear += gt_walls.near(t.apply(d.centre), d.radius - m_slack) ? 0 : 1;
        return m_discs.empty() ? 0.0 : double(clear) / double(m_discs.size());
    }

private:
    struct Disc
    {
        Eigen::Vector2d centre;
        double radius;
    };
    double m_slack;
    std::vector<Disc> m_discs;
};

/** What singles a region's placement out besides its walls: the region's free map vertices
 * (`near`, pinned()'s), the free ground-truth vertices (`gt_pivots`) and the ground truth's
 * walls, in `gt` and `map` (the map as brokenness placed it). */
struct Evidence
{
    const TopologyGraph& gt;
    const TopologyGraph& map;
    const std::vector<int>& near;
    const std::vector<int>& gt_pivots;
    const WallIndex& gt_walls;
};

/** The part the best of `best` (distinct placements, best first) is, when it puts at least
 * min_share of the region on a wall and the runner-up at most max_runner_up of that: the walls
 * single it out. When a rival's walls come closer, the vertices may: the best is clear when it
 * pins (pinned()) at least min_pin_lead more of the region's vertices than every rival within
 * the walls' doubt (a corridor slid by a door's spacing keeps its walls and pins fewer). Or the
 * free space may: the best is clear when its share times its free share (FreeSpace, gathered
 * only then) exceeds every rival's by the same ratio as the walls ask. `scored` its region's
 * points. */
std::optional<WallPart> clearPart(const std::vector<Placement>& best,
                                  const std::vector<Eigen::Vector2d>& scored,
                                  const WallPartRule& rule, const Evidence& ev)
{
    if (best.empty() || best[0].share < rule.min_share) return std::nullopt;
    const double doubt = rule.max_runner_up * best[0].share;
    auto byPins = [&]
    {
        if (rule.min_pin_lead <= 0) return false;
        auto pins = [&](const Transform2D& t)
        { return pinned(ev.gt, ev.map, ev.near, ev.gt_pivots, t, rule.pair_distance_m); };
        const int own = pins(best[0].t);
        for (std::size_t k = 1; k < best.size() && best[k].share > doubt; ++k)
            if (own - pins(best[k].t) < rule.min_pin_lead) return false;
        return true;
    };
    auto byFreeSpace = [&]
    {
        if (!rule.free_space) return false;
        const FreeSpace free_space(ev.map, scored, rule.tolerance_m);
        const double own = best[0].share * free_space.share(ev.gt_walls, best[0].t);
        if (own <= 0.0) return false;
        const double free_doubt = rule.max_runner_up * own;
        // The list is by share: a rival at most the doubt by its walls alone is below it.
        for (std::size_t k = 1; k < best.size() && best[k].share > free_doubt; ++k)
            if (best[k].share * free_space.share(ev.gt_walls, best[k].t) > free_doubt) return false;
        return true;
    };
    if (best.size() > 1 && best[1].share > doubt && !byPins() && !byFreeSpace())
        return std::nullopt;
    WallPart part;
    part.transform = best[0].t;
    part.points = scored;
    return part;
}

/** The wall length of `pts`, wall points of cells `cell` wide (points x cell size) [m]. */
double wallLength(const std::vector<Eigen::Vector2d>& pts, double cell)
{
    return double(pts.size()) * cell;
}

Eigen::Vector2d centreOf(const std::vector<Eigen::Vector2d>& pts)
{
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (const auto& q : pts) c += q;
    return pts.empty() ? c : Eigen::Vector2d(c / double(pts.size()));
}

/** The points of `pts` that `t` puts on a ground-truth wall and whose neighbourhood (radius
 * `radius`, counted on at most kRegionSample evenly thinned points) it puts there for at least
 * `share` of it: a part's own walls, not a straight wall that happens to lie along another. */
std::vector<Eigen::Vector2d> regionOf(const WallIndex& gt_walls,
                                      const std::vector<Eigen::Vector2d>& pts, const Transform2D& t,
                                      double tolerance, double radius, double share)
{
    const std::vector<Eigen::Vector2d> sample = evenlyThinned(pts, kRegionSample);
    std::vector<char> on(sample.size());
    for (std::size_t i = 0; i < sample.size(); ++i)
        on[i] = gt_walls.near(t.apply(sample[i]), tolerance) ? 1 : 0;
    const Neighbours around(sample, radius);
    std::vector<Eigen::Vector2d> out;
    for (const auto& q : pts)
    {
        if (!gt_walls.near(t.apply(q), tolerance)) continue;
        std::size_t near = 0, placed = 0;
        around.within(q, [&](std::size_t j) { ++near, placed += std::size_t(on[j]); });
        if (near > 0 && double(placed) >= share * double(near)) out.push_back(q);
    }
    return out;
}

/** Pivot pairs: at most `max_map` of `near` (map vertices, evenly by id), each with every
 * vertex of `gt_pivots`. */
std::vector<std::pair<int, int>> pivotPairs(std::vector<int> near,
                                            const std::vector<int>& gt_pivots, std::size_t max_map)
{
    if (near.size() > max_map)
    {
        std::vector<int> thin;
        for (std::size_t k = 0; k < max_map; ++k) thin.push_back(near[k * near.size() / max_map]);
        near = std::move(thin);
    }
    std::vector<std::pair<int, int>> pairs;
    for (int m : near)
        for (int g : gt_pivots) pairs.emplace_back(m, g);
    return pairs;
}

/** The points of `pts` that `t` does not put within `tolerance` of a ground-truth wall. */
std::vector<Eigen::Vector2d> notExplained(const WallIndex& gt_walls,
                                          const std::vector<Eigen::Vector2d>& pts,
                                          const Transform2D& t, double tolerance)
{
    std::vector<Eigen::Vector2d> left;
    for (const auto& q : pts)
        if (!gt_walls.near(t.apply(q), tolerance)) left.push_back(q);
    return left;
}

/** The next part of `rest` (wall points no part explains yet): the best placement of all of
 * `rest` (the coarse search on fewer points: it only singles out a region) puts a region on
 * the ground truth's walls, its points whose neighbourhood it places too (regionOf()); that
 * region, of min_length_m at least, placed clearly on its own (clearPart()), is the part.
 * Pivots: the vertices `map_free` marks near the points (at most `max_map_pivots`), each with
 * every vertex of `gt_pivots`. `placements`: the best distinct placements of all of `rest`. */
std::optional<WallPart> singledOut(const TopologyGraph& gt, const TopologyGraph& map,
                                   const WallIndex& gt_walls,
                                   const mrpt::maps::CSimplePointsMap& reference,
                                   const std::vector<Eigen::Vector2d>& rest,
                                   const std::vector<char>& map_free,
                                   const std::vector<int>& gt_pivots, std::size_t max_map_pivots,
                                   double res, const WallMapRule& rule,
                                   std::vector<Placement>* placements = nullptr)
{
    const WallPartRule& pr = rule.part;
    const double cell = std::max(map.map.resolution_m, 1e-6);
    std::vector<Eigen::Vector2d> scored = evenlyThinned(rest, kScoredPoints);
    std::vector<int> near = pivotsNear(map, scored, map_free);
    std::vector<std::pair<int, int>> pivots = pivotPairs(near, gt_pivots, max_map_pivots);
    if (pivots.empty()) return std::nullopt;
    const std::vector<Placement> first =
        bestPlacements(gt, map, gt_walls, reference, evenlyThinned(rest, kIcpPoints), scored,
                       evenlyThinned(rest, kFirstScoredPoints), centreOf(rest), pivots, res, pr);
    if (first.empty()) return std::nullopt;
    if (placements) *placements = first;
    const Transform2D& t = first[0].t;
    const std::vector<Eigen::Vector2d> region =
        regionOf(gt_walls, rest, t, pr.tolerance_m, rule.region_m, rule.region_share);
    if (wallLength(region, cell) < pr.min_length_m) return std::nullopt;
    scored = evenlyThinned(region, kScoredPoints);
    const Eigen::Vector2d centre = centreOf(region);
    // Its own pivots (else the rest's: with none its rivals would go untried, and any
    // placement look clear).
    if (std::vector<int> own = pivotsNear(map, scored, map_free); !own.empty())
    {
        near = std::move(own);
        pivots = pivotPairs(near, gt_pivots, max_map_pivots);
    }
    std::vector<Placement> found =
        bestPlacements(gt, map, gt_walls, reference, evenlyThinned(region, kIcpPoints), scored,
                       scored, centre, pivots, res, pr);
    // The placement that singled it out is one of its candidates.
    found.push_back({shareOn(gt_walls, scored, t, pr.tolerance_m), t});
    std::stable_sort(found.begin(), found.end(),
                     [](const Placement& a, const Placement& b) { return a.share > b.share; });
    return clearPart(distinct(found, kRefined, centre), scored, pr,
                     {gt, map, near, gt_pivots, gt_walls});
}

/** The places on the ground truth's walls that parts of the map stand on: one place of the
 * building is the image of one part of the map. */
class StoodOn
{
public:
    /** Places (the ground truth's frame). */
    void add(const std::vector<Eigen::Vector2f>& places)
    {
        if (!places.empty()) m_places.push_back(std::make_unique<WallIndex>(places));
    }
    /** Where `part`'s fit puts its points. */
    void add(const WallPart& part)
    {
        std::vector<Eigen::Vector2f> places;
        for (const auto& q : part.points) places.push_back(part.transform.apply(q).cast<float>());
        add(places);
    }
    /** The share of `part`'s points its fit puts within `tolerance` of a place stood on. */
    double share(const WallPart& part, double tolerance) const
    {
        std::size_t n = 0;
        for (const auto& q : part.points)
        {
            const Eigen::Vector2d at = part.transform.apply(q);
            n += std::any_of(m_places.begin(), m_places.end(),
                             [&](const auto& w) { return w->near(at, tolerance); })
                     ? 1
                     : 0;
        }
        return part.points.empty() ? 0.0 : double(n) / double(part.points.size());
    }

private:
    std::vector<std::unique_ptr<WallIndex>> m_places;  // WallIndex is not copied
};
}  // namespace

std::vector<WallPart> findWallParts(const TopologyGraph& gt, const TopologyGraph& placed,
                                    const WallIndex& gt_walls,
                                    const std::vector<Eigen::Vector2f>& unexplained,
                                    const std::vector<char>& gt_free,
                                    const std::vector<char>& map_free, const WallMapRule& map_rule,
                                    const std::vector<Eigen::Vector2f>& stood_on, bool split)
{
    const WallPartRule& rule = map_rule.part;
    std::vector<WallPart> parts;
    if (gt_walls.empty() || unexplained.empty()) return parts;
    std::vector<Eigen::Vector2d> rest;
    for (const auto& w : unexplained) rest.push_back(w.cast<double>());
    const double cell = std::max(placed.map.resolution_m, 1e-6);
    auto lengthOf = [cell](const std::vector<Eigen::Vector2d>& pts)
    { return wallLength(pts, cell); };
    if (lengthOf(rest) < rule.min_length_m) return parts;

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

    // The ground-truth walls a part of the map already stands on: where the groups' fits put the
    // map's walls they explain (`stood_on`), then each accepted part's. One place of the building
    // is the image of one part of the map; a region that no group explains and that lands where
    // a group stands is map the ground truth lacks (the whole campus against its west half: its
    // east rooms fit the west's), not a part.
    StoodOn stood;
    stood.add(stood_on);

    // A part's pairs: each free ground-truth vertex its fit puts within pair_distance_m of a
    // free map vertex (the nearest; each vertex in one part's pairs only, ground-truth vertices
    // in id order). A part with none is refused when `need_pair`.
    auto keep = [&](WallPart part, bool need_pair)
    {
        std::vector<char> gt_next = gt_left, map_next = map_left;
        for (int g : gt_pivots)
        {
            if (!gt_next[size_t(g)]) continue;
            const Eigen::Vector2d& p = gt.vertices[size_t(g)].position_m;
            int nearest = -1;
            double d_best = rule.pair_distance_m;
            for (std::size_t m = 0; m < placed.vertices.size(); ++m)
            {
                if (!map_next[m]) continue;
                const double d = (part.transform.apply(placed.vertices[m].position_m) - p).norm();
                if (d <= d_best) d_best = d, nearest = int(m);
            }
            if (nearest >= 0)
            {
                map_next[size_t(nearest)] = 0;
                gt_next[size_t(g)] = 0;
                part.pairs.emplace_back(g, nearest);
            }
        }
        if (need_pair && part.pairs.empty()) return false;
        if (stood.share(part, rule.tolerance_m) > map_rule.max_overlap) return false;
        gt_left = std::move(gt_next);
        map_left = std::move(map_next);
        stood.add(part);
        parts.push_back(std::move(part));
        return true;
    };

    for (const auto& region : regionsOf(rest, rule.link_m))
    {
        if (lengthOf(region) < rule.min_length_m) break;
        const std::vector<Eigen::Vector2d> scored = evenlyThinned(region, kScoredPoints);
        const Eigen::Vector2d centre = centreOf(region);
        // A region an accepted part already places is that part's.
        bool placed_already = false;
        for (const WallPart& p : parts)
            if (shareOn(gt_walls, scored, p.transform, rule.tolerance_m) >= rule.min_share)
                placed_already = true;
        if (placed_already) continue;
        // Its pivots: free map vertices whose clearance (+ a margin) reaches the region.
        // (All of them: a region's few, unlike a whole map's.)
        const std::vector<int> near = pivotsNear(placed, scored, map_free);
        const std::vector<std::pair<int, int>> pairs =
            pivotPairs(near, gt_pivots, std::numeric_limits<std::size_t>::max());
        if (pairs.empty()) continue;
        const std::vector<Placement> best = bestPlacements(
            gt, placed, gt_walls, reference, region, scored, scored, centre, pairs, res, rule);
        if (std::optional<WallPart> clear =
                clearPart(best, scored, rule, {gt, placed, near, gt_pivots, gt_walls}))
        {
            keep(std::move(*clear), false);
            continue;
        }
        if (!split) continue;
        // No one fit places the region: it may hold more than one part (two parts that touch
        // at a cut; a part with the walls of a fused neighbour). Parts singled out within it,
        // as a whole map's are (placeMapByWalls()).
        std::vector<Eigen::Vector2d> left = region;
        for (int k = 0; k < map_rule.max_parts && lengthOf(left) >= rule.min_length_m; ++k)
        {
            std::optional<WallPart> part =
                singledOut(gt, placed, gt_walls, reference, left, map_free, gt_pivots, kMapPivots,
                           res, map_rule);
            if (!part) break;
            // A part singled out within a region must place a vertex of its own as well: its
            // walls alone may be one room's or a corner's, which a building holds more than once
            // (held-out corridor_office_28001/slam_1: 15 m of outer wall put 13.9 m away).
            const Transform2D t = part->transform;
            if (!keep(std::move(*part), true)) break;
            const std::size_t before = left.size();
            left = notExplained(gt_walls, left, t, map_rule.explained_tolerance_m);
            if (left.size() == before) break;
        }
    }
    // One part of the map, one fit: a part whose walls another part's fit puts on the ground
    // truth's walls as a part's must be (min_share), while its own fit puts fewer of that
    // part's, is that part placed wrongly (a rack block of a held-out warehouse singled out
    // under a half turn, whose correct fit, found next, explains both; session 49).
    const std::size_t n = parts.size();
    std::vector<std::vector<double>> by(n, std::vector<double>(n));  // [a][b]: a's points, b's fit
    for (std::size_t a = 0; a < n; ++a)
    {
        const std::vector<Eigen::Vector2d> scored = evenlyThinned(parts[a].points, kScoredPoints);
        for (std::size_t b = 0; b < n; ++b)
            if (a != b) by[a][b] = shareOn(gt_walls, scored, parts[b].transform, rule.tolerance_m);
    }
    std::vector<char> wrong(n, 0);
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = 0; b < n && !wrong[a]; ++b)
            if (a != b && !wrong[b] && by[a][b] >= rule.min_share && by[b][a] < by[a][b])
                wrong[a] = 1;
    std::vector<WallPart> kept;
    for (std::size_t k = 0; k < parts.size(); ++k)
        if (!wrong[k]) kept.push_back(std::move(parts[k]));
    return kept;
}

WallMap placeMapByWalls(const TopologyGraph& gt, const TopologyGraph& map,
                        const WallIndex& gt_walls, const WallIndex& map_walls,
                        const std::vector<std::pair<int, int>>& given, const WallMapRule& rule)
{
    WallMap out;
    if (gt_walls.empty() || map.wall_points_m.empty()) return out;
    const WallPartRule& pr = rule.part;
    const double cell = std::max(map.map.resolution_m, 1e-6);
    std::vector<Eigen::Vector2d> rest;
    for (const auto& w : map.wall_points_m) rest.push_back(w.cast<double>());
    const std::size_t all = rest.size();
    std::vector<char> gt_free(gt.vertices.size()), map_free(map.vertices.size());
    for (const auto& v : gt.vertices) gt_free[size_t(v.id)] = !v.spurious;
    for (const auto& v : map.vertices) map_free[size_t(v.id)] = !v.spurious;
    std::vector<int> gt_pivots;
    for (std::size_t g = 0; g < gt.vertices.size(); ++g)
        if (gt_free[g]) gt_pivots.push_back(int(g));
    if (gt_pivots.empty()) return out;
    mrpt::maps::CSimplePointsMap reference;
    for (const auto& w : gt.wall_points_m) reference.insertPoint(w.x(), w.y(), 0.0f);
    const double res = std::max(gt.map.resolution_m, map.map.resolution_m);
    auto lengthOf = [cell](const std::vector<Eigen::Vector2d>& pts)
    { return wallLength(pts, cell); };
    // The whole map's pivots are many: at most kMapPivots map vertices, each with every
    // ground-truth vertex. (Only those of a like clearance, as a rigid motion keeps it, lost
    // floorplan_lab_ipa/broken_3: at a cut a vertex's clearance changes.)
    std::vector<WallPart> parts;
    StoodOn stood;
    std::vector<Placement> whole;  // the whole map's best distinct placements
    while (int(parts.size()) < rule.max_parts && lengthOf(rest) >= pr.min_length_m)
    {
        std::optional<WallPart> part =
            singledOut(gt, map, gt_walls, reference, rest, map_free, gt_pivots, kMapPivots, res,
                       rule, parts.empty() ? &whole : nullptr);
        // One place, one part: a part found where an earlier one stands is the same walls
        // again (the whole house against its west half: its east rooms on the west's).
        if (!part || stood.share(*part, pr.tolerance_m) > rule.max_overlap) break;
        stood.add(*part);
        parts.push_back(std::move(*part));
        // Its walls leave: the next part is sought on the rest.
        const std::size_t before = rest.size();
        rest = notExplained(gt_walls, rest, parts.back().transform, rule.explained_tolerance_m);
        if (rest.size() == before) break;
    }
    out.parts_sought = int(parts.size());
    out.explained = all ? 1.0 - double(rest.size()) / double(all) : 0.0;
    // No region singled out: a robot map against its plan (furniture along the walls, clutter)
    // has no 3 m neighbourhood on the plan's walls for 0.9 of it, yet one placement of the whole
    // map may put most of its walls on them, far ahead of every other (doc/quality.md, step 10).
    // (`whole` is filled only when the search ran: the map holds min_length_m of wall.)
    if (parts.empty() && rule.whole_min_share > 0.0 && !whole.empty() &&
        whole[0].share >= rule.whole_min_share &&
        (whole.size() < 2 || whole[1].share <= pr.max_runner_up * whole[0].share))
    {
        WallPart part;
        part.transform = whole[0].t;
        part.points = rest;
        parts.push_back(std::move(part));
        out.whole = true;
        out.whole_share = whole[0].share;
        out.whole_runner_up = whole.size() < 2 ? 0.0 : whole[1].share;
        rest = notExplained(gt_walls, rest, parts.back().transform, rule.explained_tolerance_m);
        out.explained = all ? 1.0 - double(rest.size()) / double(all) : 0.0;
    }
    if (parts.empty() || (!out.whole && out.explained < rule.min_explained)) return out;

    // A map vertex is placed by each part that explains at least kOwnWalls of the walls around
    // it (its clearance + 2 cells: its Voronoi sites; a vertex at a break has both parts'),
    // and paired with the ground-truth vertex one of them puts it nearest, within
    // pair_distance_m + slack_share of the larger clearance, or (a pair of the match, `given`)
    // within the ground-truth vertex's clearance (a vertex slides in its room); the match's first,
    // then nearest first, each vertex once.
    struct Candidate
    {
        double d;
        int g, m, part;
    };
    std::vector<Candidate> candidates;
    std::vector<int> given_of(gt.vertices.size(), -1);
    for (const auto& [g, m] : given)
        if (g >= 0 && std::size_t(g) < given_of.size()) given_of[size_t(g)] = m;
    for (const auto& v : map.vertices)
    {
        if (v.spurious) continue;
        const auto& around = map_walls.around(v.position_m, v.clearance_m + 2.0 * cell);
        for (std::size_t k = 0; k < parts.size(); ++k)
        {
            std::size_t n = 0;
            for (const auto& q : around)
                n += gt_walls.near(parts[k].transform.apply(q), rule.explained_tolerance_m) ? 1 : 0;
            if (n == 0 || double(n) < kOwnWalls * double(around.size())) continue;
            const Eigen::Vector2d at = parts[k].transform.apply(v.position_m);
            for (int g : gt_pivots)
            {
                const auto& w = gt.vertices[size_t(g)];
                const double d = (w.position_m - at).norm();
                const bool given_pair = given_of[size_t(g)] == v.id && d <= w.clearance_m;
                // A vertex slides in its room (vertex_slack_share of its clearance).
                const double reach =
                    pr.pair_distance_m + rule.slack_share * std::max(w.clearance_m, v.clearance_m);
                if (d > reach && !given_pair) continue;
                // The match's pairs first.
                candidates.push_back({given_pair ? -1.0 : d, g, v.id, int(k)});
            }
        }
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.d < b.d; });
    std::vector<char> gt_left = gt_free, map_left = map_free;
    for (const Candidate& c : candidates)
    {
        if (!gt_left[size_t(c.g)] || !map_left[size_t(c.m)]) continue;
        gt_left[size_t(c.g)] = map_left[size_t(c.m)] = 0;
        parts[size_t(c.part)].pairs.emplace_back(c.g, c.m);
    }
    for (WallPart& p : parts) std::sort(p.pairs.begin(), p.pairs.end());
    // The whole map placed but no vertex of it near a ground-truth vertex (the house plan's
    // rooms against a robot map's): nothing to measure it by.
    if (out.whole && parts[0].pairs.empty()) return out;
    out.parts = std::move(parts);
    return out;
}
}  // namespace mrpt_topoeval::internal
