/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Does a group's rigid fit put one map's walls on the other's, and do the walls pin that fit?
// The check of a small further group whose attributes changed at a break (doc/matching.md,
// "Walls of a small part"), and of the further groups the bridges and
// min_unconfirmed_group_similarity ask it of.

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/geometry/Transform2D.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace mrpt_topoeval::internal
{
/** A graph's wall points, for "is there a wall point within r of p" and "the wall points within
 * r of p". Both answer as a search of MRPT's KD-tree (`CSimplePointsMap`, nanoflann) does, in
 * its float arithmetic, but from the points of a few square buckets: building the KD-tree and
 * searching it was a fifth of a compare's time (the tree is built only where the buckets would
 * be too many). It keeps what it found (near()'s cells and buckets, around()'s points), so one
 * index is not for concurrent use: each match makes its own. */
class WallIndex
{
public:
    explicit WallIndex(const std::vector<Eigen::Vector2f>& points);
    // Not copied: the last cells asked are kept by address.
    WallIndex(const WallIndex&) = delete;
    WallIndex& operator=(const WallIndex&) = delete;
    /** True if a wall point lies within r of p. */
    bool near(const Eigen::Vector2d& p, double r) const;
    /** The wall points within r of p (in no particular order), searched once per place and
     * radius: the matcher asks for one vertex's walls many times (every group, pair test and
     * ICP that holds it). */
    const std::vector<Eigen::Vector2d>& around(const Eigen::Vector2d& p, double r) const;
    /** The wall points within each of `vertices`' clearance + `margin_m` in `g` (the graph
     * whose walls these are), without repeats, sorted by position; evenly thinned to
     * `max_points` when there are more (0: all). Gathered once per vertex set, margin and
     * thinning: a match asks for the walls of one group under many fits (on the Intel pair 622
     * times, for 299 sets). */
    const std::vector<Eigen::Vector2d>& aroundVertices(const TopologyGraph& g,
                                                       const std::vector<int>& vertices,
                                                       double margin_m,
                                                       std::size_t max_points) const;
    bool empty() const { return m_points.empty(); }

private:
    mrpt::maps::CSimplePointsMap m_points;
    /** The wall points' bounding box, the cells' and buckets' origin at its lower left (no
     * wall point: lo above hi). */
    Eigen::Vector2d m_lo{Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity())};
    Eigen::Vector2d m_hi{Eigen::Vector2d::Constant(-std::numeric_limits<double>::infinity())};
    /** True if no wall point can lie within r of p: p is not finite, or farther than r (and a
     * margin for the floats) from the walls' box. MRPT's nearest-point search is not asked
     * then: it leaves its result unset when no distance is finite (a query at 1e30). */
    bool beyondWalls(const Eigen::Vector2d& p, double r) const;
    mutable std::map<std::tuple<double, double, double>, std::vector<Eigen::Vector2d>> m_around;
    /** aroundVertices()'s answers by graph, vertex set (sorted: the answer does not depend on
     * the order), margin and thinning. */
    mutable std::map<std::tuple<const TopologyGraph*, std::vector<int>, double, std::size_t>,
                     std::vector<Eigen::Vector2d>>
        m_around_vertices;
    /** The wall points by square bucket `size` wide, from the lower left wall point. None:
     * too many buckets (a tiny size), or no size. */
    struct Buckets
    {
        double size = 0.0;
        Eigen::Vector2d origin{0.0, 0.0};
        long nx = 0, ny = 0;
        std::vector<std::uint32_t> first;  //!< bucket k's points: [first[k], first[k + 1])
        std::vector<float> xs, ys;         //!< the wall points, bucket by bucket
    };
    void fill(Buckets& b, double size) const;
    /** For near(p, r): the cells, r / (2 sqrt 2) wide, that hold a wall point. A point in such
     * a cell lies within r / 2 of it, so near() answers without a search. Elsewhere the
     * buckets, a little over r wide, decide: a point within r lies in p's bucket or one of its
     * 8 neighbours. Made once per r (a wall agreement asks it of hundreds of points, each
     * under nine shifts of the fit). Once many points have been searched at r, a cell also
     * knows whether a held cell lies within kReachCells of it (where a wall point within r of
     * p lies); a point in a cell that is not has no wall point within r, also answered without
     * a search. */
    struct Cells  // none held: too many cells for r
    {
        double size = 0.0;
        Eigen::Vector2d origin{0.0, 0.0};
        long nx = 0, ny = 0;
        std::vector<std::uint8_t> held;  //!< kHeld | kReach flags per cell
        bool reach_marked = false;       //!< the kReach flags are set (markReach())
        std::size_t searched = 0;        //!< points searched at r before they were
        Buckets buckets;
    };
    mutable std::map<double, Cells> m_cells;
    /** The last r asked and its cells: one agreement asks near() hundreds of times at one r. */
    mutable double m_last_r = 0.0;
    mutable Cells* m_last_cells = nullptr;
    Cells& cellsFor(double r) const;
    static void markReach(Cells& c);
    /** For around(): buckets of a fixed size (a vertex's radius spans a few of them). */
    mutable std::optional<Buckets> m_around_buckets;
};

/** How well the walls around a group agree under its rigid fit. */
struct WallAgreement
{
    /** Of the wall points around the group's vertices (within each vertex's clearance +
     * margin), the share that the fit puts within the tolerance of the other map's wall points;
     * counted from each map, the smaller share. 0 when either map has no wall points there. */
    double share = 0.0;
    /** The largest share kept when the fit is moved by twice the tolerance in any of 8
     * directions, over `share`: near 1 when the walls do not pin the fit (a straight corridor
     * fits itself anywhere along it), about 0.5-0.9 when they do. */
    double pinning = 1.0;
    /** Whether both maps have wall points around the group (else share is 0 for want of walls,
     * not for walls that disagree). */
    bool walls_on_both = false;
    /** The walls vouch for the fit: they agree on at least `min_share` of their length and pin
     * it (a pinning of at most `max_pinning`). */
    bool vouches(double min_share, double max_pinning) const
    {
        return share >= min_share && pinning <= max_pinning;
    }
};

/** A wall tolerance of at least 1.5 cells of the coarser of the two maps: a wall point's place
 * is only known to its cell. */
inline double wallTolerance(double tolerance_m, const TopologyGraph& a, const TopologyGraph& b)
{
    return std::max(tolerance_m, 1.5 * std::max(a.map.resolution_m, b.map.resolution_m));
}

/** The agreement of the walls around `pairs` (ground-truth vertex, map vertex) under
 * `gt_T_map` (map to ground truth). The pinning is measured only when the share is at least
 * `pinning_from_share` (else left at 1: a caller that refuses such a share need not pay for
 * it), and only as far as `pinning_limit`: the shifts stop at the first whose share over
 * `share` exceeds it, and that ratio is the pinning (the walls do not pin the fit; a caller
 * that refuses a pinning above the limit learns no less). */
WallAgreement wallAgreement(const TopologyGraph& gt, const TopologyGraph& map,
                            const WallIndex& gt_walls, const WallIndex& map_walls,
                            const std::vector<std::pair<int, int>>& pairs,
                            const Transform2D& gt_T_map, double margin_m, double tolerance_m,
                            double pinning_from_share = 0.0,
                            double pinning_limit = std::numeric_limits<double>::infinity());

/** The ICP of the walls around `pairs` (a pair's place, a part's turn, a grown pair the walls
 * vouch for): the wall points within each vertex's clearance + `margin_m` in both maps (not
 * thinned: ICP wants them all), aligned by MRPT's CICP, classic, from `start` (map -> ground
 * truth). Its first matching distance is `reach_m`, at least 3 cells, halved down to two cells.
 * None when either map has fewer than 20 wall points there (a bare plan's few walls). */
std::optional<Transform2D> alignWallsByIcp(const TopologyGraph& gt, const TopologyGraph& map,
                                           const WallIndex& gt_walls, const WallIndex& map_walls,
                                           const std::vector<std::pair<int, int>>& pairs,
                                           double margin_m, const Transform2D& start,
                                           double reach_m);

/** `pts` evenly thinned to `n` points (every pts.size() / n-th, in order); all when no more. */
template <class T>
std::vector<T> evenlyThinned(const std::vector<T>& pts, std::size_t n)
{
    if (pts.size() <= n) return pts;
    std::vector<T> thin;
    for (std::size_t k = 0; k < n; ++k) thin.push_back(pts[k * pts.size() / n]);
    return thin;
}

/** MRPT's CICP (classic, 60 iterations) of `cloud` (map wall points) onto `reference`
 * (ground-truth wall points) from `start` (map -> ground truth): its first matching distance
 * the larger of 3 cells (`res`) and `reach_m`, halved down to two cells. */
Transform2D icpOfWalls(const mrpt::maps::CSimplePointsMap& reference,
                       const mrpt::maps::CSimplePointsMap& cloud, const Transform2D& start,
                       double res, double reach_m);

}  // namespace mrpt_topoeval::internal
