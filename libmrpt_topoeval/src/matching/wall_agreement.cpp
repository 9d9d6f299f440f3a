/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "matching/wall_agreement.h"

#include <mrpt/core/bits_math.h>
#include <mrpt/poses/CPosePDF.h>
#include <mrpt/slam/CICP.h>

#include <algorithm>
#include <cmath>

namespace mrpt_topoeval::internal
{
namespace
{
/** Cells of near()'s shortcut, and buckets, at most: beyond, the KD-tree answers (a few MB
 * each; a bucket's offset takes 4 bytes, a cell 1). */
constexpr long kMaxNearCells = 1 << 24;
constexpr long kMaxBuckets = 1 << 21;
/** How much farther than r the buckets are looked in: far more than the floats' rounding
 * (about 10^-7 of r), so that no point the KD-tree's floats put within r is missed. */
constexpr double kBucketMargin = 1e-3;
/** near()'s cells are r / (2 sqrt 2) wide: a wall point within r of p (r / size = 2.83 cells,
 * and the floats' margin) lies at most 3 cells from p's cell along each axis, so within 4. */
constexpr long kReachCells = 4;
/** A cell's flags: it holds a wall point; a wall point lies within kReachCells of it. */
constexpr std::uint8_t kHeld = 1, kReach = 2;
/** The kReach flags are marked once a radius's searches outnumber this share of its cells:
 * marking costs a few operations per cell, a search tens of ns (brokenness step 9's placement
 * search asks 10^7-10^8 points at one radius; the Intel compare never enters it, and marked
 * for every radius asked the flags cost it 3 ms of its 85). */
constexpr std::size_t kReachAfter = 8;
/** around()'s buckets [m]: a vertex's clearance + margin (1-3 m) spans a few of them. */
constexpr double kAroundBucket_m = 0.5;
/** The walls compared for the share: a few hundred points give a mean to a few percent. */
constexpr std::size_t kMaxWallPoints = 400;

/** Where v falls along one axis of a grid, in cells; one expression for the walls and for a
 * query, so that both round alike (the extreme wall point falls in the last cell, not past). */
double along(double v, double origin, double size) { return (v - origin) / size; }

/** The squared distance of nanoflann's L2_Simple_Adaptor::evalMetric, term by term in floats,
 * as MRPT's KD-tree of the points measures it. */
float squaredDistance(float qx, float qy, float x, float y)
{
    const float dx = qx - x, dy = qy - y;
    float d2 = dx * dx;
    d2 += dy * dy;
    return d2;
}

/** out(i) for each i in [0, n) with in(j) true for some j within kReachCells of i: one line of
 * a square window's growth, one pass. */
template <class In, class Out>
void growLine(long n, In in, Out out)
{
    long last = -kReachCells - 1;  // the last j at i + k or before with in(j)
    for (long i = -kReachCells; i < n; ++i)
    {
        if (i + kReachCells < n && in(i + kReachCells)) last = i + kReachCells;
        if (i >= 0 && last >= i - kReachCells) out(i);
    }
}
}  // namespace

WallIndex::WallIndex(const std::vector<Eigen::Vector2f>& points)
{
    // No KD-tree here: MRPT builds it on the first search, which the buckets rarely leave.
    m_points.reserve(points.size());
    for (const Eigen::Vector2f& q : points)
    {
        m_points.insertPointFast(q.x(), q.y());
        m_lo = m_lo.cwiseMin(q.cast<double>());
        m_hi = m_hi.cwiseMax(q.cast<double>());
    }
}

bool WallIndex::beyondWalls(const Eigen::Vector2d& p, double r) const
{
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || m_lo.x() > m_hi.x()) return true;
    const Eigen::Vector2d outside = (m_lo - p).cwiseMax(p - m_hi).cwiseMax(0.0);
    return outside.norm() > r * (1.0 + kBucketMargin) + 1e-6;
}

void WallIndex::fill(Buckets& b, double size) const
{
    const auto& xs = m_points.getPointsBufferRef_x();
    const auto& ys = m_points.getPointsBufferRef_y();
    if (xs.empty() || !(size > 0.0)) return;
    // Counted in doubles first: a tiny size must not overflow the count.
    const double cols = std::floor(along(m_hi.x(), m_lo.x(), size)) + 1.0;
    const double rows = std::floor(along(m_hi.y(), m_lo.y(), size)) + 1.0;
    if (!(cols * rows <= double(kMaxBuckets))) return;
    b.size = size;
    b.origin = m_lo;
    b.nx = long(cols), b.ny = long(rows);
    std::vector<std::uint32_t> of(xs.size());
    b.first.assign(std::size_t(b.nx * b.ny) + 1, 0);
    for (std::size_t i = 0; i < xs.size(); ++i)
    {
        const long ix = std::min(b.nx - 1, long(along(xs[i], b.origin.x(), size)));
        const long iy = std::min(b.ny - 1, long(along(ys[i], b.origin.y(), size)));
        of[i] = std::uint32_t(iy * b.nx + ix);
        ++b.first[of[i] + 1];
    }
    for (std::size_t k = 1; k < b.first.size(); ++k) b.first[k] += b.first[k - 1];
    std::vector<std::uint32_t> next(b.first.begin(), b.first.end() - 1);
    b.xs.resize(xs.size());
    b.ys.resize(xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i)
    {
        const std::uint32_t k = next[of[i]]++;
        b.xs[k] = xs[i], b.ys[k] = ys[i];
    }
}

void WallIndex::markReach(Cells& c)
{
    // The held cells grown by kReachCells along x, then along y (a square window): one byte
    // per cell, read once per query.
    const long nx = c.nx, ny = c.ny;
    auto at = [nx](long x, long y) { return std::size_t(y * nx + x); };
    std::vector<std::uint8_t> along_x(c.held.size(), 0);
    for (long y = 0; y < ny; ++y)
        growLine(
            nx, [&](long x) { return (c.held[at(x, y)] & kHeld) != 0; },
            [&](long x) { along_x[at(x, y)] = 1; });
    for (long x = 0; x < nx; ++x)
        growLine(
            ny, [&](long y) { return along_x[at(x, y)] != 0; },
            [&](long y) { c.held[at(x, y)] |= kReach; });
    c.reach_marked = true;
}

WallIndex::Cells& WallIndex::cellsFor(double r) const
{
    if (m_last_cells && r == m_last_r) return *m_last_cells;
    const auto [at, fresh] = m_cells.try_emplace(r);
    Cells& c = at->second;
    m_last_r = r, m_last_cells = &c;
    if (!fresh || empty() || !(r > 0.0)) return c;
    const auto& xs = m_points.getPointsBufferRef_x();
    const auto& ys = m_points.getPointsBufferRef_y();
    const double size = r / (2.0 * std::sqrt(2.0));
    // Counted in doubles first: a tiny radius must not overflow the cell count.
    const double cols = std::floor(along(m_hi.x(), m_lo.x(), size)) + 1.0;
    const double rows = std::floor(along(m_hi.y(), m_lo.y(), size)) + 1.0;
    if (cols * rows <= double(kMaxNearCells))
    {
        const long nx = long(cols), ny = long(rows);
        c.size = size;
        c.origin = m_lo;
        c.nx = nx, c.ny = ny;
        c.held.assign(std::size_t(nx * ny), 0);
        for (std::size_t i = 0; i < xs.size(); ++i)
        {
            const long ix = std::min(nx - 1, long((xs[i] - c.origin.x()) / size));
            const long iy = std::min(ny - 1, long((ys[i] - c.origin.y()) / size));
            c.held[std::size_t(iy * nx + ix)] = kHeld;
        }
    }
    // A point within r (in the KD-tree's floats, which may stretch r by a few parts in 10^7)
    // is less than a bucket away along each axis.
    fill(c.buckets, r * (1.0 + kBucketMargin));
    return c;
}

bool WallIndex::near(const Eigen::Vector2d& p, double r) const
{
    if (empty()) return false;
    Cells& c = cellsFor(r);
    if (!c.held.empty())
    {
        const double fx = (p.x() - c.origin.x()) / c.size, fy = (p.y() - c.origin.y()) / c.size;
        if (fx >= 0.0 && fy >= 0.0 && fx < double(c.nx) && fy < double(c.ny))
        {
            const std::uint8_t cell = c.held[std::size_t(long(fy) * c.nx + long(fx))];
            if (cell & kHeld) return true;
            if (c.reach_marked)
            {
                if (!(cell & kReach)) return false;
            }
            else if (++c.searched > c.held.size() / kReachAfter)
                markReach(c);  // this query still searches
        }
    }
    // The query as the KD-tree takes it.
    const float qx = float(p.x()), qy = float(p.y());
    const float r2 = float(r * r);
    const Buckets& b = c.buckets;
    if (!b.first.empty())
    {
        const double fx = along(qx, b.origin.x(), b.size), fy = along(qy, b.origin.y(), b.size);
        // More than a bucket outside them all, or not a number: no wall point within r.
        if (!(fx >= -1.0 && fy >= -1.0 && fx < double(b.nx + 1) && fy < double(b.ny + 1)))
            return false;
        const long ix = long(std::floor(fx)), iy = long(std::floor(fy));
        for (long y = std::max(0L, iy - 1); y <= std::min(b.ny - 1, iy + 1); ++y)
            for (long x = std::max(0L, ix - 1); x <= std::min(b.nx - 1, ix + 1); ++x)
            {
                const std::size_t k = std::size_t(y * b.nx + x);
                for (std::uint32_t i = b.first[k]; i < b.first[k + 1]; ++i)
                    if (squaredDistance(qx, qy, b.xs[i], b.ys[i]) <= r2) return true;
            }
        return false;
    }
    if (beyondWalls(p, r)) return false;
    return m_points.kdTreeClosestPoint2DsqrError(qx, qy) <= r2;
}

const std::vector<Eigen::Vector2d>& WallIndex::around(const Eigen::Vector2d& p, double r) const
{
    const auto [at, fresh] = m_around.try_emplace({p.x(), p.y(), r});
    std::vector<Eigen::Vector2d>& out = at->second;
    if (!fresh || empty()) return out;
    if (!m_around_buckets)
    {
        // Buckets{} rather than emplace(): clang decides a nested struct with default member
        // initialisers is not default-constructible while its enclosing class is incomplete
        // (std::optional<Buckets> is declared there) and remembers that answer.
        m_around_buckets.emplace(Buckets{});
        fill(*m_around_buckets, kAroundBucket_m);
    }
    // The query, and nanoflann's radius search's test (strictly within r^2), as the KD-tree.
    const float qx = float(p.x()), qy = float(p.y());
    const float r2 = float(r * r);
    const Buckets& b = *m_around_buckets;
    if (!b.first.empty() && r > 0.0 && std::isfinite(qx) && std::isfinite(qy))
    {
        // The buckets that may hold a point within r, a little farther, clamped to the grid
        // in doubles (a huge r must not overflow).
        const double reach = r * (1.0 + kBucketMargin);
        auto range = [&](float q, double origin, long n)
        {
            const double lo = std::floor(along(double(q) - reach, origin, b.size));
            const double hi = std::floor(along(double(q) + reach, origin, b.size));
            return std::make_pair(long(std::min(std::max(lo, 0.0), double(n))),
                                  long(std::max(std::min(hi, double(n - 1)), -1.0)));
        };
        const auto [x_lo, x_hi] = range(qx, b.origin.x(), b.nx);
        const auto [y_lo, y_hi] = range(qy, b.origin.y(), b.ny);
        for (long y = y_lo; y <= y_hi; ++y)
            for (long x = x_lo; x <= x_hi; ++x)
            {
                const std::size_t k = std::size_t(y * b.nx + x);
                for (std::uint32_t i = b.first[k]; i < b.first[k + 1]; ++i)
                    if (squaredDistance(qx, qy, b.xs[i], b.ys[i]) < r2)
                        out.emplace_back(b.xs[i], b.ys[i]);
            }
        return out;
    }
    std::vector<nanoflann::ResultItem<std::size_t, float>> found;
    m_points.kdTreeRadiusSearch2D(qx, qy, r2, found);
    const auto& xs = m_points.getPointsBufferRef_x();
    const auto& ys = m_points.getPointsBufferRef_y();
    for (const auto& f : found) out.emplace_back(xs[f.first], ys[f.first]);
    return out;
}

const std::vector<Eigen::Vector2d>& WallIndex::aroundVertices(const TopologyGraph& g,
                                                              const std::vector<int>& vertices,
                                                              double margin_m,
                                                              std::size_t max_points) const
{
    std::vector<int> sorted = vertices;
    std::sort(sorted.begin(), sorted.end());
    const auto [at, fresh] =
        m_around_vertices.try_emplace({&g, std::move(sorted), margin_m, max_points});
    std::vector<Eigen::Vector2d>& pts = at->second;
    if (!fresh) return pts;
    for (int v : vertices)
    {
        const auto& near = around(g.vertices[v].position_m, g.vertices[v].clearance_m + margin_m);
        pts.insert(pts.end(), near.begin(), near.end());
    }
    auto less = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b)
    { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); };
    std::sort(pts.begin(), pts.end(), less);
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (max_points > 0) pts = evenlyThinned(pts, max_points);
    return pts;
}

WallAgreement wallAgreement(const TopologyGraph& gt, const TopologyGraph& map,
                            const WallIndex& gt_walls, const WallIndex& map_walls,
                            const std::vector<std::pair<int, int>>& pairs,
                            const Transform2D& gt_T_map, double margin_m, double tolerance_m,
                            double pinning_from_share, double pinning_limit)
{
    WallAgreement out;
    std::vector<int> gv, mv;
    for (const auto& [a, b] : pairs) gv.push_back(a), mv.push_back(b);
    const std::vector<Eigen::Vector2d>& from_gt =
        gt_walls.aroundVertices(gt, gv, margin_m, kMaxWallPoints);
    const std::vector<Eigen::Vector2d>& from_map =
        map_walls.aroundVertices(map, mv, margin_m, kMaxWallPoints);
    if (from_gt.empty() || from_map.empty()) return out;
    out.walls_on_both = true;
    // The share under the fit moved by `shift` (in the ground truth's frame).
    const double yaw = mrpt::DEG2RAD(gt_T_map.yaw_deg);
    const double c = std::cos(yaw), s = std::sin(yaw);
    auto shareAt = [&](const Eigen::Vector2d& shift)
    {
        const Eigen::Vector2d t(gt_T_map.x_m + shift.x(), gt_T_map.y_m + shift.y());
        std::size_t hit_gt = 0, hit_map = 0;
        for (const Eigen::Vector2d& p : from_gt)
        {
            const Eigen::Vector2d d = p - t;  // R^T (p - t): into the map's frame
            hit_gt += map_walls.near({c * d.x() + s * d.y(), -s * d.x() + c * d.y()}, tolerance_m);
        }
        for (const Eigen::Vector2d& q : from_map)
            hit_map += gt_walls.near({c * q.x() - s * q.y() + t.x(), s * q.x() + c * q.y() + t.y()},
                                     tolerance_m);
        return std::min(double(hit_gt) / double(from_gt.size()),
                        double(hit_map) / double(from_map.size()));
    };
    out.share = shareAt(Eigen::Vector2d::Zero());
    if (!(out.share > 0.0) || out.share < pinning_from_share) return out;
    // The shifts stop at the first that takes the pinning over its limit.
    double moved = 0.0;
    for (int k = 0; k < 8; ++k)
    {
        const double a = k * M_PI / 4.0;
        moved =
            std::max(moved, shareAt(2.0 * tolerance_m * Eigen::Vector2d(std::cos(a), std::sin(a))));
        out.pinning = moved / out.share;
        if (out.pinning > pinning_limit) break;
    }
    return out;
}

std::optional<Transform2D> alignWallsByIcp(const TopologyGraph& gt, const TopologyGraph& map,
                                           const WallIndex& gt_walls, const WallIndex& map_walls,
                                           const std::vector<std::pair<int, int>>& pairs,
                                           double margin_m, const Transform2D& start,
                                           double reach_m)
{
    constexpr std::size_t kMinWallPoints = 20;
    auto cloud = [&](const TopologyGraph& g, const WallIndex& index, bool ground_truth)
    {
        std::vector<int> vertices;
        for (const auto& [a, b] : pairs) vertices.push_back(ground_truth ? a : b);
        mrpt::maps::CSimplePointsMap c;
        for (const auto& q : index.aroundVertices(g, vertices, margin_m, 0))
            c.insertPoint(float(q.x()), float(q.y()), 0.0f);
        return c;
    };
    const mrpt::maps::CSimplePointsMap walls_gt = cloud(gt, gt_walls, true),
                                       walls_map = cloud(map, map_walls, false);
    if (walls_gt.size() < kMinWallPoints || walls_map.size() < kMinWallPoints) return std::nullopt;
    return icpOfWalls(walls_gt, walls_map, start,
                      std::max(gt.map.resolution_m, map.map.resolution_m), reach_m);
}

Transform2D icpOfWalls(const mrpt::maps::CSimplePointsMap& reference,
                       const mrpt::maps::CSimplePointsMap& cloud, const Transform2D& start,
                       double res, double reach_m)
{
    constexpr int kWallIcpIterations = 60;
    mrpt::slam::CICP::TConfigParams o;
    o.ICP_algorithm = mrpt::slam::icpClassic;
    o.maxIterations = kWallIcpIterations;
    o.thresholdDist = std::max(3.0 * res, reach_m);
    o.thresholdAng = 0.0;
    o.ALFA = 0.5;
    o.smallestThresholdDist = 2.0 * res;
    o.skip_cov_calculation = true;
    o.skip_quality_calculation = true;
    mrpt::slam::CICP icp(o);
    mrpt::slam::CICP::TReturnInfo info;
    // The ground truth's walls are the reference; the map's walls' pose in its frame is the
    // map -> ground truth transform.
    const auto pose =
        icp.Align(&reference, &cloud,
                  mrpt::poses::CPose2D(start.x_m, start.y_m, mrpt::DEG2RAD(start.yaw_deg)), info)
            ->getMeanVal();
    return Transform2D{pose.x(), pose.y(), mrpt::RAD2DEG(pose.phi())};
}

}  // namespace mrpt_topoeval::internal
