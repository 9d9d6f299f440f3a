/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "variants.h"

#include <mrpt/core/bits_math.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>
#include <string>

#include "pipeline/map_scale.h"

namespace mrpt_topoeval::validation
{
using mrpt::maps::COccupancyGridMap2D;

namespace
{
bool occupied(float p_free) { return p_free < 0.35f; }
bool freeCell(float p_free) { return p_free > 0.65f; }

/** Cell geometry of a grid, copied so truth functions outlive nothing. */
struct CellIndexer
{
    double x_min = 0.0, y_min = 0.0, res = 1.0;
    int size_x = 0, size_y = 0;
    explicit CellIndexer(const COccupancyGridMap2D& g)
        : x_min(g.getXMin()),
          y_min(g.getYMin()),
          res(g.getResolution()),
          size_x(static_cast<int>(g.getSizeX())),
          size_y(static_cast<int>(g.getSizeY()))
    {
    }
    /** Index of the cell holding p, or -1 outside. */
    long index(const Eigen::Vector2d& p) const
    {
        const int cx = static_cast<int>(std::floor((p.x() - x_min) / res));
        const int cy = static_cast<int>(std::floor((p.y() - y_min) / res));
        if (cx < 0 || cy < 0 || cx >= size_x || cy >= size_y) return -1;
        return static_cast<long>(cy) * size_x + cx;
    }
    /** Calls f(cell index) for every cell of the grid whose centre lies within `reach` of q;
     * stops early, returning false, when f does. */
    template <typename F>
    bool forEachCellWithin(const Eigen::Vector2d& q, double reach, F f) const
    {
        const int r = static_cast<int>(std::ceil(reach / res));
        const int qx = static_cast<int>(std::floor((q.x() - x_min) / res));
        const int qy = static_cast<int>(std::floor((q.y() - y_min) / res));
        for (int y = std::max(0, qy - r); y <= std::min(size_y - 1, qy + r); ++y)
            for (int x = std::max(0, qx - r); x <= std::min(size_x - 1, qx + r); ++x)
            {
                const Eigen::Vector2d centre(x_min + (x + 0.5) * res, y_min + (y + 0.5) * res);
                if ((centre - q).norm() <= reach &&
                    !f(static_cast<std::size_t>(y) * static_cast<std::size_t>(size_x) + x))
                    return false;
            }
        return true;
    }
};

/** A clutter predicate over the cells marked in `mask` (one byte per cell of `g`). */
std::function<bool(const Eigen::Vector2d&)> clutterOf(const COccupancyGridMap2D& g,
                                                      std::vector<std::uint8_t> mask)
{
    auto m = std::make_shared<const std::vector<std::uint8_t>>(std::move(mask));
    const CellIndexer idx(g);
    return [m, idx](const Eigen::Vector2d& p)
    {
        const long i = idx.index(p);
        return i >= 0 && (*m)[static_cast<std::size_t>(i)] != 0;
    };
}

std::vector<float> cellsOf(const COccupancyGridMap2D& g)
{
    const int sx = static_cast<int>(g.getSizeX()), sy = static_cast<int>(g.getSizeY());
    std::vector<float> c(static_cast<std::size_t>(sx) * sy);
    for (int y = 0; y < sy; ++y)
        for (int x = 0; x < sx; ++x) c[static_cast<std::size_t>(y) * sx + x] = g.getCell(x, y);
    return c;
}

/** Distance [cells] of every cell to the nearest cell for which `is_target` holds. */
cv::Mat distanceTo(const std::vector<float>& cells, int sx, int sy, bool (*is_target)(float))
{
    cv::Mat src(sy, sx, CV_8UC1);
    for (int y = 0; y < sy; ++y)
        for (int x = 0; x < sx; ++x)
            src.at<std::uint8_t>(y, x) =
                is_target(cells[static_cast<std::size_t>(y) * sx + x]) ? 0 : 255;
    cv::Mat dist;
    cv::distanceTransform(src, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    return dist;
}

bool notFree(float p) { return !freeCell(p); }

Truth identityTruth(double tolerance_m)
{
    Truth t;
    t.mapping = [](const Eigen::Vector2d& p) { return std::optional<Eigen::Vector2d>(p); };
    t.forward = t.mapping;
    t.keeps_free_space = true;
    t.source = "by construction";
    t.wall_tolerance_m = tolerance_m;
    return t;
}

double defaultTolerance(double res_a, double res_b)
{
    return std::max(0.10, 1.5 * std::max(res_a, res_b));
}

/** A grid with `src`'s geometry, cells from `cells`. */
COccupancyGridMap2D withCells(const COccupancyGridMap2D& src, const std::vector<float>& cells)
{
    COccupancyGridMap2D g = src;
    const int sx = static_cast<int>(g.getSizeX()), sy = static_cast<int>(g.getSizeY());
    for (int y = 0; y < sy; ++y)
        for (int x = 0; x < sx; ++x) g.setCell(x, y, cells[static_cast<std::size_t>(y) * sx + x]);
    return g;
}

double uniform(std::mt19937& rng, double a, double b)
{
    return std::uniform_real_distribution<double>(a, b)(rng);
}
}  // namespace

Rigid2D randomRigid(std::uint32_t seed, double max_shift_m)
{
    std::mt19937 rng(seed * 2654435761u + 17u);
    double yaw_deg = 0.0;
    do
    {
        yaw_deg = uniform(rng, 0.0, 360.0);
    } while (std::abs(std::remainder(yaw_deg, 90.0)) < 8.0);
    Rigid2D r;
    r.yaw_rad = std::remainder(mrpt::DEG2RAD(yaw_deg), 2.0 * M_PI);
    r.t_m = {uniform(rng, -max_shift_m, max_shift_m), uniform(rng, -max_shift_m, max_shift_m)};
    return r;
}

Variant warpGrid(const COccupancyGridMap2D& src, const std::vector<WarpPart>& parts,
                 double resolution_m)
{
    const double src_res = src.getResolution();
    const double res = resolution_m > 0.0 ? resolution_m : src_res;
    double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
    for (const auto& part : parts)
        for (double x : {src.getXMin(), src.getXMax()})
            for (double y : {src.getYMin(), src.getYMax()})
            {
                const Eigen::Vector2d q = part.gt_to_map.apply({x, y});
                x0 = std::min(x0, q.x()), x1 = std::max(x1, q.x());
                y0 = std::min(y0, q.y()), y1 = std::max(y1, q.y());
            }
    Variant v;
    v.map.setSize(x0 - res, x1 + res, y0 - res, y1 + res, res, 0.5f);
    std::vector<Rigid2D> inv;
    for (const auto& part : parts) inv.push_back(part.gt_to_map.inverse());

    // k x k samples per target cell when coarsening, one otherwise.
    const int k = res > 1.01 * src_res ? static_cast<int>(std::ceil(res / src_res)) : 1;
    const int ssx = static_cast<int>(src.getSizeX()), ssy = static_cast<int>(src.getSizeY());
    const auto src_cells = cellsOf(src);
    const int dsx = static_cast<int>(v.map.getSizeX()), dsy = static_cast<int>(v.map.getSizeY());
    // The part each target cell took its value from (an obstacle's part wins, as the cell
    // does): in overlaps the truth of a cell is the part that put its wall there.
    std::vector<std::int8_t> cell_part(static_cast<std::size_t>(dsx) * dsy, -1);
    // Every part that put a wall in a cell, one bit each: a topology vertex's walls name its
    // part (the lowest bit, the part whose wall the cell shows), and where parts overlap the
    // others' walls change a part's vertices. Only a warp of several parts asks (vertex_places
    // and kept_part below); a broken map has at most 4 parts.
    if (parts.size() > 8)
        throw std::invalid_argument("warpGrid: " + std::to_string(parts.size()) +
                                    " parts, at most 8 (one bit each)");
    std::vector<std::uint8_t> wall_parts(parts.size() > 1 ? cell_part.size() : 0, 0);
    for (int cy = 0; cy < dsy; ++cy)
        for (int cx = 0; cx < dsx; ++cx)
        {
            const Eigen::Vector2d q(v.map.idx2x(cx), v.map.idx2y(cy));
            // Each part's own verdict first (its samples' majority when coarsening), then the
            // parts fused as a robot's grid fuses them: a wall seen from any part stays a wall,
            // free seen from any part stays free, and a part that saw nothing there (the
            // unknown around its building) says nothing. Voting unknown against another
            // part's free space greyed out a broken map's turned rooms where they overlapped
            // the other part's surroundings, and their graph with them (session 9).
            int occ_part = -1, free_part = -1, seen_part = -1;
            for (std::size_t i = 0; i < parts.size(); ++i)
            {
                int n_occ = 0, n_free = 0, n_seen = 0;
                for (int a = 0; a < k; ++a)
                    for (int b = 0; b < k; ++b)
                    {
                        const Eigen::Vector2d s((a + 0.5) / k - 0.5, (b + 0.5) / k - 0.5);
                        const Eigen::Vector2d p = inv[i].apply(q + res * s);
                        if (!parts[i].contains(p)) continue;
                        const int sx =
                            static_cast<int>(std::floor((p.x() - src.getXMin()) / src_res));
                        const int sy =
                            static_cast<int>(std::floor((p.y() - src.getYMin()) / src_res));
                        if (sx < 0 || sy < 0 || sx >= ssx || sy >= ssy) continue;
                        const float c = src_cells[static_cast<std::size_t>(sy) * ssx + sx];
                        ++n_seen;
                        if (occupied(c))
                            ++n_occ;
                        else if (freeCell(c))
                            ++n_free;
                    }
                if (n_seen == 0) continue;
                if (seen_part < 0) seen_part = static_cast<int>(i);
                if (n_occ > 0 && occ_part < 0) occ_part = static_cast<int>(i);
                if (n_occ > 0 && !wall_parts.empty())
                    wall_parts[static_cast<std::size_t>(cy) * dsx + cx] |=
                        static_cast<std::uint8_t>(1u << i);
                if (n_occ == 0 && 2 * n_free > n_seen && free_part < 0)
                    free_part = static_cast<int>(i);
            }
            cell_part[static_cast<std::size_t>(cy) * dsx + cx] =
                static_cast<std::int8_t>(occ_part >= 0    ? occ_part
                                         : free_part >= 0 ? free_part
                                                          : seen_part);
            if (occ_part >= 0)
                v.map.setCell(cx, cy, 0.0f);
            else if (free_part >= 0)
                v.map.setCell(cx, cy, 1.0f);
        }

    auto shared_parts = std::make_shared<const std::vector<WarpPart>>(parts);
    auto shared_inv = std::make_shared<const std::vector<Rigid2D>>(inv);
    auto shared_cells = std::make_shared<const std::vector<std::int8_t>>(std::move(cell_part));
    const CellIndexer idx(v.map);
    // The part of a map point: the one its cell came from, else the first whose preimage
    // contains it (points outside the grid).
    auto part_of = [shared_parts, shared_inv, shared_cells, idx](const Eigen::Vector2d& q)
    {
        const long c = idx.index(q);
        if (c >= 0 && (*shared_cells)[static_cast<std::size_t>(c)] >= 0)
            return static_cast<int>((*shared_cells)[static_cast<std::size_t>(c)]);
        for (std::size_t i = 0; i < shared_parts->size(); ++i)
            if ((*shared_parts)[i].contains((*shared_inv)[i].apply(q))) return static_cast<int>(i);
        return -1;
    };
    v.truth.mapping = [part_of, shared_inv](const Eigen::Vector2d& q)
    {
        const int i = part_of(q);
        if (i < 0) return std::optional<Eigen::Vector2d>();
        return std::optional<Eigen::Vector2d>((*shared_inv)[static_cast<std::size_t>(i)].apply(q));
    };
    v.truth.part_of = part_of;
    // A topology vertex stands for the walls nearest to it (its Voronoi sites): the parts that
    // put those walls there, by the occupied cells within its clearance plus 1.5 cells. Where
    // two parts overlap, the free space at a vertex may come from one part and its walls from
    // the other; part_of() alone names the first part with free space there, which put a
    // vertex drawn by part 1's walls 5.5 m from its true place on the Gazebo office (session
    // 17). So a vertex belongs to each part with a quarter of those walls and to part_of().
    // One part (a rigid or resampled copy): `mapping` alone.
    if (parts.size() > 1)
    {
        auto shared_wall_parts =
            std::make_shared<const std::vector<std::uint8_t>>(std::move(wall_parts));
        v.truth.kept_part =
            [shared_parts, shared_wall_parts, idx](const Eigen::Vector2d& p_gt, double clearance_m)
        {
            const double r = std::max(0.0, clearance_m);
            for (std::size_t j = 0; j < shared_parts->size(); ++j)
            {
                const WarpPart& part = (*shared_parts)[j];
                // The disc in the part: its centre and 16 points of its circle (the parts are
                // convex boxes, so this misses at most 2 % of r where a corner cuts the circle
                // between two points). The parts are disjoint: no other part holds the disc.
                bool inside = part.contains(p_gt);
                for (int s = 0; s < 16 && inside; ++s)
                {
                    const double a = s * M_PI / 8.0;
                    inside = part.contains(p_gt + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
                }
                if (!inside) continue;
                // No other part's wall within the disc where this part drew it.
                const std::uint8_t others = static_cast<std::uint8_t>(~(1u << j));
                const bool alone = idx.forEachCellWithin(
                    part.gt_to_map.apply(p_gt), r,
                    [&](std::size_t c) { return ((*shared_wall_parts)[c] & others) == 0; });
                return alone ? static_cast<int>(j) : -1;
            }
            return -1;
        };
        v.truth.vertex_places = [part_of, shared_inv, shared_wall_parts, idx](
                                    const Eigen::Vector2d& q, double clearance_m)
        {
            const double reach = std::max(0.0, clearance_m) + 1.5 * idx.res;
            std::vector<int> votes(shared_inv->size(), 0);
            int total = 0;
            idx.forEachCellWithin(q, reach,
                                  [&](std::size_t c)
                                  {
                                      const std::uint8_t walls = (*shared_wall_parts)[c];
                                      if (walls != 0)
                                      {
                                          // The part whose wall the cell shows: the first.
                                          int part = 0;
                                          while (!(walls & (1u << part))) ++part;
                                          ++votes[static_cast<std::size_t>(part)];
                                          ++total;
                                      }
                                      return true;
                                  });
            std::vector<int> order;
            for (std::size_t i = 0; i < votes.size(); ++i)
                if (total > 0 && 4 * votes[i] >= total) order.push_back(static_cast<int>(i));
            std::stable_sort(order.begin(), order.end(),
                             [&](int a, int b) { return votes[a] > votes[b]; });
            // The part whose free space holds the vertex too: walls of a part that ends at unknown
            // space there are not occupied cells.
            const int holder = part_of(q);
            if (holder >= 0 && std::find(order.begin(), order.end(), holder) == order.end())
                order.push_back(holder);
            std::vector<std::pair<int, Eigen::Vector2d>> places;
            for (int i : order)
                places.emplace_back(i, (*shared_inv)[static_cast<std::size_t>(i)].apply(q));
            return places;
        };
    }
    v.truth.keeps_free_space = true;
    v.truth.forward = [shared_parts](const Eigen::Vector2d& p)
    {
        for (const auto& part : *shared_parts)
            if (part.contains(p)) return std::optional<Eigen::Vector2d>(part.gt_to_map.apply(p));
        return std::optional<Eigen::Vector2d>();
    };
    for (const auto& part : parts)
        v.truth.part_yaw_deg.push_back(
            mrpt::RAD2DEG(std::remainder(-part.gt_to_map.yaw_rad, 2 * M_PI)));
    v.truth.source = "by construction";
    v.truth.wall_tolerance_m = defaultTolerance(src_res, res);
    return v;
}

namespace
{
WarpPart wholeMap(const Rigid2D& t)
{
    return {t, [](const Eigen::Vector2d&) { return true; }};
}
}  // namespace

Variant makeIdentical(const COccupancyGridMap2D& gt)
{
    Variant v;
    v.map = gt;
    v.truth = identityTruth(defaultTolerance(gt.getResolution(), gt.getResolution()));
    return v;
}

Variant makeRigid(const COccupancyGridMap2D& gt, double yaw_rad, const Eigen::Vector2d& shift_m)
{
    Rigid2D t;
    t.yaw_rad = yaw_rad;
    t.t_m = shift_m;
    Variant v = warpGrid(gt, {wholeMap(t)});
    v.truth.part_of = nullptr;  // one part: not a broken map
    v.truth.part_yaw_deg.clear();
    return v;
}

Variant makeResampled(const COccupancyGridMap2D& gt, double resolution_m)
{
    Variant v = warpGrid(gt, {wholeMap(Rigid2D{})}, resolution_m);
    v.truth.part_of = nullptr;
    v.truth.part_yaw_deg.clear();
    return v;
}

Variant makeScaled(const COccupancyGridMap2D& gt, double scale, double yaw_rad,
                   const Eigen::Vector2d& shift_m)
{
    const Variant moved = makeRigid(gt, yaw_rad, shift_m);
    Variant v;
    // The same cells, each `scale` times as wide (as the library's scale pass reads a map).
    v.map = internal::scaledGrid(moved.map, scale);
    v.truth = moved.truth;
    const double inv = 1.0 / scale;
    if (moved.truth.mapping)
        v.truth.mapping = [f = moved.truth.mapping, inv](const Eigen::Vector2d& p)
        { return f(p * inv); };
    if (moved.truth.forward)
        v.truth.forward = [f = moved.truth.forward, scale](const Eigen::Vector2d& p)
        {
            auto q = f(p);
            if (q) *q *= scale;
            return q;
        };
    if (moved.truth.vertex_places)
        v.truth.vertex_places =
            [f = moved.truth.vertex_places, inv](const Eigen::Vector2d& p, double clearance_m)
        { return f(p * inv, clearance_m * inv); };
    if (moved.truth.is_clutter)
        v.truth.is_clutter = [f = moved.truth.is_clutter, inv](const Eigen::Vector2d& p)
        { return f(p * inv); };
    v.truth.source = moved.truth.source + ", scaled by " + fmt(scale, 3);
    return v;
}

Variant makeSpeckled(const COccupancyGridMap2D& gt, double wall_fraction, double specks_per_m2,
                     std::uint32_t seed)
{
    std::mt19937 rng(seed);
    const int sx = static_cast<int>(gt.getSizeX()), sy = static_cast<int>(gt.getSizeY());
    const auto src = cellsOf(gt);
    auto cells = src;
    auto at = [&](int x, int y) { return src[static_cast<std::size_t>(y) * sx + x]; };
    std::size_t free_cells = 0;
    for (int y = 1; y < sy - 1; ++y)
        for (int x = 1; x < sx - 1; ++x)
        {
            const float c = at(x, y);
            free_cells += freeCell(c) ? 1 : 0;
            const bool near_occ = occupied(at(x - 1, y)) || occupied(at(x + 1, y)) ||
                                  occupied(at(x, y - 1)) || occupied(at(x, y + 1));
            const bool near_free = freeCell(at(x - 1, y)) || freeCell(at(x + 1, y)) ||
                                   freeCell(at(x, y - 1)) || freeCell(at(x, y + 1));
            if (freeCell(c) && near_occ && uniform(rng, 0, 1) < wall_fraction)
                cells[static_cast<std::size_t>(y) * sx + x] = 0.0f;
            else if (occupied(c) && near_free && uniform(rng, 0, 1) < wall_fraction)
                cells[static_cast<std::size_t>(y) * sx + x] = 1.0f;
        }
    // Specks in open space, at least 0.4 m from anything that is not free.
    const cv::Mat clear = distanceTo(src, sx, sy, notFree);
    const double res = gt.getResolution();
    std::vector<std::uint8_t> mask(cells.size(), 0);
    const auto n_specks = static_cast<long>(std::lround(specks_per_m2 * free_cells * res * res));
    std::uniform_int_distribution<int> ux(1, std::max(1, sx - 3)), uy(1, std::max(1, sy - 3));
    for (long n = 0, tries = 0; n < n_specks && tries < 100 * (n_specks + 1); ++tries)
    {
        const int x = ux(rng), y = uy(rng);
        if (clear.at<float>(y, x) * res < 0.4) continue;
        const int w = uniform(rng, 0, 1) < 0.5 ? 1 : 2;
        for (int dx = 0; dx < w; ++dx)
        {
            const std::size_t i = static_cast<std::size_t>(y) * sx + x + dx;
            cells[i] = 0.0f;
            mask[i] = 1;
        }
        ++n;
    }
    Variant v;
    v.map = withCells(gt, cells);
    v.truth = identityTruth(defaultTolerance(res, res));
    v.truth.is_clutter = clutterOf(v.map, std::move(mask));
    return v;
}

Variant makeWallGaps(const COccupancyGridMap2D& gt, double gaps_per_m, std::uint32_t seed)
{
    std::mt19937 rng(seed);
    const int sx = static_cast<int>(gt.getSizeX()), sy = static_cast<int>(gt.getSizeY());
    const auto src = cellsOf(gt);
    auto cells = src;
    const double res = gt.getResolution();
    struct Border
    {
        int x, y, dx, dy;  // wall cell and the direction into the wall
    };
    std::vector<Border> border;
    const int dirs[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (int y = 1; y < sy - 1; ++y)
        for (int x = 1; x < sx - 1; ++x)
        {
            if (!occupied(src[static_cast<std::size_t>(y) * sx + x])) continue;
            for (const auto& d : dirs)
                if (freeCell(src[static_cast<std::size_t>(y - d[1]) * sx + x - d[0]]))
                {
                    border.push_back({x, y, d[0], d[1]});
                    break;
                }
        }
    const auto n_gaps = static_cast<long>(std::lround(gaps_per_m * border.size() * res));
    if (!border.empty())
    {
        std::uniform_int_distribution<std::size_t> pick(0, border.size() - 1);
        for (long n = 0; n < n_gaps; ++n)
        {
            const Border b = border[pick(rng)];
            // Walk through the wall (at most 0.4 m); cut only if it comes out on the other side.
            std::vector<std::size_t> cut;
            int x = b.x, y = b.y;
            bool through = false;
            for (int step = 0; step < static_cast<int>(std::ceil(0.4 / res)); ++step)
            {
                if (x < 0 || y < 0 || x >= sx || y >= sy) break;
                const std::size_t i = static_cast<std::size_t>(y) * sx + x;
                if (!occupied(src[i]))
                {
                    through = true;
                    break;
                }
                cut.push_back(i);
                x += b.dx, y += b.dy;
            }
            if (through)
                for (std::size_t i : cut) cells[i] = 1.0f;
        }
    }
    Variant v;
    v.map = withCells(gt, cells);
    v.truth = identityTruth(defaultTolerance(res, res));
    return v;
}

Variant makeRagged(const COccupancyGridMap2D& gt, int amplitude_cells, std::uint32_t seed)
{
    std::mt19937 rng(seed);
    const int sx = static_cast<int>(gt.getSizeX()), sy = static_cast<int>(gt.getSizeY());
    const double res = gt.getResolution();
    // A smooth field in [-1, 1]: six plane waves of wavelength 0.6-2 m.
    struct Wave
    {
        double kx, ky, phase;
    };
    std::vector<Wave> waves;
    for (int i = 0; i < 6; ++i)
    {
        const double wl = uniform(rng, 0.6, 2.0), dir = uniform(rng, 0, 2 * M_PI);
        waves.push_back({2 * M_PI / wl * std::cos(dir), 2 * M_PI / wl * std::sin(dir),
                         uniform(rng, 0, 2 * M_PI)});
    }
    auto field = [&](int x, int y)
    {
        double s = 0;
        for (const auto& w : waves) s += std::sin(w.kx * x * res + w.ky * y * res + w.phase);
        return s / std::sqrt(3.0);  // ~[-1.4, 1.4] before clamping
    };
    const auto src = cellsOf(gt);
    const cv::Mat d_occ = distanceTo(src, sx, sy, occupied);
    auto cells = src;
    // Bulges: free cells within the field's amplitude of a wall become wall.
    for (int y = 0; y < sy; ++y)
        for (int x = 0; x < sx; ++x)
        {
            const std::size_t i = static_cast<std::size_t>(y) * sx + x;
            if (!freeCell(src[i])) continue;
            const double f = std::clamp(field(x, y), -1.0, 1.0);
            if (f > 0 && d_occ.at<float>(y, x) <= f * amplitude_cells + 0.01) cells[i] = 0.0f;
        }
    // Dents: wall border cells become free where the field is negative, one cell per pass, only
    // where the wall stays at least two cells thick behind them.
    const int dirs[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (int pass = 0; pass < amplitude_cells; ++pass)
    {
        const auto before = cells;
        for (int y = 1; y < sy - 1; ++y)
            for (int x = 1; x < sx - 1; ++x)
            {
                const std::size_t i = static_cast<std::size_t>(y) * sx + x;
                if (!occupied(before[i])) continue;
                const double f = std::clamp(field(x, y), -1.0, 1.0);
                if (f >= 0 || -f * amplitude_cells < pass + 0.5) continue;
                for (const auto& d : dirs)
                {
                    if (!freeCell(before[static_cast<std::size_t>(y - d[1]) * sx + x - d[0]]))
                        continue;
                    int thick = 0;
                    for (int s = 1; s <= 3; ++s)
                    {
                        const int xx = x + s * d[0], yy = y + s * d[1];
                        if (xx < 0 || yy < 0 || xx >= sx || yy >= sy) break;
                        if (!occupied(before[static_cast<std::size_t>(yy) * sx + xx])) break;
                        ++thick;
                    }
                    if (thick >= 2) cells[i] = 1.0f;
                    break;
                }
            }
    }
    Variant v;
    v.map = withCells(gt, cells);
    v.truth = identityTruth(std::max(0.10, (amplitude_cells + 1.5) * res));
    return v;
}

Variant makeCrop(const COccupancyGridMap2D& gt, double keep_share, std::uint32_t seed)
{
    std::mt19937 rng(seed);
    const int side = std::uniform_int_distribution<int>(0, 3)(rng);  // 0 W, 1 E, 2 S, 3 N
    const int sx = static_cast<int>(gt.getSizeX()), sy = static_cast<int>(gt.getSizeY());
    const auto src = cellsOf(gt);
    std::vector<int> coord;  // of known cells along the cut axis
    for (int y = 0; y < sy; ++y)
        for (int x = 0; x < sx; ++x)
            if (!(std::abs(src[static_cast<std::size_t>(y) * sx + x] - 0.5f) < 0.1f))
                coord.push_back(side < 2 ? x : y);
    Variant v;
    if (coord.empty()) return makeIdentical(gt);
    std::sort(coord.begin(), coord.end());
    const bool keep_low = side == 0 || side == 2;
    const std::size_t n = coord.size();
    const std::size_t k = std::min(n - 1, static_cast<std::size_t>(keep_share * n));
    const int cut = keep_low ? coord[k] : coord[n - 1 - k];
    int x0 = 0, x1 = sx - 1, y0 = 0, y1 = sy - 1;
    if (side == 0) x1 = cut;
    if (side == 1) x0 = cut;
    if (side == 2) y1 = cut;
    if (side == 3) y0 = cut;
    const double res = gt.getResolution();
    v.map.setSize(gt.idx2x(x0) - 0.5 * res, gt.idx2x(x1) + 0.5 * res, gt.idx2y(y0) - 0.5 * res,
                  gt.idx2y(y1) + 0.5 * res, res, 0.5f);
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
        {
            const int tx = v.map.x2idx(gt.idx2x(x)), ty = v.map.y2idx(gt.idx2y(y));
            if (tx >= 0 && ty >= 0 && tx < static_cast<int>(v.map.getSizeX()) &&
                ty < static_cast<int>(v.map.getSizeY()))
                v.map.setCell(tx, ty, src[static_cast<std::size_t>(y) * sx + x]);
        }
    v.truth = identityTruth(defaultTolerance(res, res));
    v.truth.keeps_free_space = false;  // the part cut away is unknown
    const Eigen::Vector2d lo(gt.idx2x(x0) - 0.5 * res, gt.idx2y(y0) - 0.5 * res),
        hi(gt.idx2x(x1) + 0.5 * res, gt.idx2y(y1) + 0.5 * res);
    v.truth.kept = [lo, hi](const Eigen::Vector2d& p, double r)
    {
        auto inside = [&](double m)
        {
            return p.x() - m >= lo.x() && p.y() - m >= lo.y() && p.x() + m <= hi.x() &&
                   p.y() + m <= hi.y();
        };
        return inside(r) ? 2 : inside(0.0) ? 1 : 0;
    };
    return v;
}

Variant makeBroken(const COccupancyGridMap2D& gt, int breaks, std::uint32_t seed, bool chained)
{
    std::mt19937 rng(seed);
    const double dir = uniform(rng, 0, M_PI);
    const Eigen::Vector2d u(std::cos(dir), std::sin(dir)), w(-u.y(), u.x());
    const int sx = static_cast<int>(gt.getSizeX()), sy = static_cast<int>(gt.getSizeY());
    const double res = gt.getResolution();
    const auto src = cellsOf(gt);
    auto known = [&](std::size_t i) { return !(std::abs(src[i] - 0.5f) < 0.1f); };
    auto centre = [&](int x, int y) { return Eigen::Vector2d(gt.idx2x(x), gt.idx2y(y)); };
    std::vector<double> along;
    for (int y = 0; y < sy; ++y)
        for (int x = 0; x < sx; ++x)
            if (known(static_cast<std::size_t>(y) * sx + x)) along.push_back(u.dot(centre(x, y)));
    if (along.empty() || breaks < 1 || breaks > 3) return makeIdentical(gt);
    auto quantile = [](std::vector<double> v, double q)
    {
        std::sort(v.begin(), v.end());
        return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
    };
    // Compact parts of equal known area: halves across u (1 break); a third, then the rest
    // halved across w (2 breaks); halves, each halved across w (3 breaks: quadrants).
    const double big = std::numeric_limits<double>::max();
    struct Box
    {
        double s0, s1, t0, t1;  // along u and along w
    };
    std::vector<Box> boxes;
    auto medianAcross = [&](double s0, double s1)
    {
        std::vector<double> t;
        for (int y = 0; y < sy; ++y)
            for (int x = 0; x < sx; ++x)
            {
                if (!known(static_cast<std::size_t>(y) * sx + x)) continue;
                const double si = u.dot(centre(x, y));
                if (si >= s0 && si < s1) t.push_back(w.dot(centre(x, y)));
            }
        return t.empty() ? 0.0 : quantile(t, 0.5);
    };
    if (breaks == 1)
    {
        const double c = quantile(along, 0.5);
        boxes = std::vector<Box>{{-big, c, -big, big}, {c, big, -big, big}};
    }
    else if (breaks == 2)
    {
        const double c = quantile(along, 1.0 / 3.0), m = medianAcross(c, big);
        boxes = std::vector<Box>{{-big, c, -big, big}, {c, big, -big, m}, {c, big, m, big}};
    }
    else
    {
        const double c = quantile(along, 0.5), m0 = medianAcross(-big, c),
                     m1 = medianAcross(c, big);
        boxes = std::vector<Box>{
            {-big, c, -big, m0}, {-big, c, m0, big}, {c, big, -big, m1}, {c, big, m1, big}};
    }
    auto partOf = [&](const Eigen::Vector2d& p)
    {
        const double s = u.dot(p), t = w.dot(p);
        for (std::size_t j = 0; j < boxes.size(); ++j)
            if (s >= boxes[j].s0 && s < boxes[j].s1 && t >= boxes[j].t0 && t < boxes[j].t1)
                return static_cast<int>(j);
        return -1;
    };
    // Pivots: for each turned part, a free cell of open space (a point on the robot's way) on
    // its border with another part (chained: with the previous part of the chain).
    const std::size_t n_parts = boxes.size();
    std::vector<std::size_t> chain(n_parts);
    std::iota(chain.begin(), chain.end(), std::size_t{0});
    if (n_parts == 4) chain = {0, 1, 3, 2};  // quadrants: around, each next to the previous
    std::vector<int> previous(n_parts, -1);  // chained: the part each is turned against
    if (chained)
        for (std::size_t k = 1; k < n_parts; ++k) previous[chain[k]] = int(chain[k - 1]);
    const cv::Mat clear = distanceTo(src, sx, sy, notFree);
    const int reach = std::max(1, static_cast<int>(std::lround(0.1 / res)));
    std::vector<std::vector<Eigen::Vector2d>> open(n_parts), any(n_parts);
    for (int y = reach; y < sy - reach; ++y)
        for (int x = reach; x < sx - reach; ++x)
        {
            if (!freeCell(src[static_cast<std::size_t>(y) * sx + x])) continue;
            const int j = partOf(centre(x, y));
            if (j < 0) continue;
            bool border = false;
            for (int d = 0; d < 4 && !border; ++d)
            {
                const int xx = x + (d == 0 ? reach : d == 1 ? -reach : 0);
                const int yy = y + (d == 2 ? reach : d == 3 ? -reach : 0);
                const int k = partOf(centre(xx, yy));
                border = k != j && (!chained || k == previous[static_cast<std::size_t>(j)]);
            }
            if (!border) continue;
            any[static_cast<std::size_t>(j)].push_back(centre(x, y));
            if (clear.at<float>(y, x) * res >= 0.4)
                open[static_cast<std::size_t>(j)].push_back(centre(x, y));
        }
    // Yaws: part 0 stays; the others turn 10-30 degrees either way, at least 10 degrees apart
    // from every other part, so each part is a separate brokenness group (chained: each turn
    // is against the previous part, and the sums along the chain are kept apart).
    std::vector<double> yaw(n_parts, 0.0), turn(n_parts, 0.0);
    for (int attempt = 0; attempt < 200; ++attempt)
    {
        for (std::size_t j = 1; j < n_parts; ++j)
            turn[j] = (uniform(rng, 0, 1) < 0.5 ? -1.0 : 1.0) * uniform(rng, 10.0, 30.0);
        for (std::size_t k = 1; k < n_parts; ++k)
            yaw[chain[k]] = turn[chain[k]] + (chained ? yaw[chain[k - 1]] : 0.0);
        bool apart = true;
        for (std::size_t i = 0; i < n_parts; ++i)
            for (std::size_t j = i + 1; j < n_parts; ++j)
                apart = apart && std::abs(yaw[i] - yaw[j]) >= 10.0;
        if (apart) break;
    }
    const Rigid2D global = randomRigid(seed ^ 0x9e3779b9u, 10.0);
    // Each part's turn in the ground truth's frame (chained, in the chain's order: the previous
    // part's, then its own about a point of their common border; else in the parts' order, as
    // the standard corpus has always drawn them).
    std::vector<Rigid2D> placed(n_parts);
    for (std::size_t k = 1; k < n_parts; ++k)
    {
        const std::size_t j = chained ? chain[k] : k;
        const auto& from = open[j].empty() ? any[j] : open[j];
        Eigen::Vector2d c = Eigen::Vector2d::Zero();
        if (!from.empty())
            c = from[std::uniform_int_distribution<std::size_t>(0, from.size() - 1)(rng)];
        Rigid2D r;
        r.yaw_rad = mrpt::DEG2RAD(turn[j]);
        r.t_m = c - Eigen::Rotation2Dd(r.yaw_rad) * c;
        placed[j] = chained ? placed[chain[k - 1]].compose(r) : r;
    }
    std::vector<WarpPart> parts;
    for (std::size_t j = 0; j < n_parts; ++j)
    {
        const Box box = boxes[j];
        parts.push_back({global.compose(placed[j]), [u, w, box](const Eigen::Vector2d& p)
                         {
                             const double s = u.dot(p), t = w.dot(p);
                             return s >= box.s0 && s < box.s1 && t >= box.t0 && t < box.t1;
                         }});
    }
    Variant v = warpGrid(gt, parts);
    v.truth.injected_breaks = breaks;
    return v;
}

Variant makeFurnished(const COccupancyGridMap2D& gt, double items_per_m2, std::uint32_t seed)
{
    std::mt19937 rng(seed);
    const int sx = static_cast<int>(gt.getSizeX()), sy = static_cast<int>(gt.getSizeY());
    const double res = gt.getResolution();
    const auto src = cellsOf(gt);
    auto cells = src;
    const cv::Mat clear = distanceTo(src, sx, sy, notFree);
    std::vector<std::pair<int, int>> centres;
    std::size_t free_cells = 0;
    for (int y = 0; y < sy; ++y)
        for (int x = 0; x < sx; ++x)
        {
            const double c = clear.at<float>(y, x) * res;
            free_cells += freeCell(src[static_cast<std::size_t>(y) * sx + x]) ? 1 : 0;
            if (c >= 0.9) centres.emplace_back(x, y);
        }
    std::vector<std::uint8_t> mask(cells.size(), 0);
    const auto n_items = static_cast<long>(std::lround(items_per_m2 * free_cells * res * res));
    auto fillRect = [&](const Eigen::Vector2d& c, double half_w, double half_h, double yaw)
    {
        const Eigen::Rotation2Dd rinv(-yaw);
        const double r = std::hypot(half_w, half_h);
        for (int y = gt.y2idx(c.y() - r); y <= gt.y2idx(c.y() + r); ++y)
            for (int x = gt.x2idx(c.x() - r); x <= gt.x2idx(c.x() + r); ++x)
            {
                if (x < 0 || y < 0 || x >= sx || y >= sy) continue;
                const Eigen::Vector2d l = rinv * (Eigen::Vector2d(gt.idx2x(x), gt.idx2y(y)) - c);
                if (std::abs(l.x()) > half_w || std::abs(l.y()) > half_h) continue;
                if (clear.at<float>(y, x) * res < 0.5) continue;  // keep passages open
                const std::size_t i = static_cast<std::size_t>(y) * sx + x;
                cells[i] = 0.0f;
                mask[i] = 1;
            }
    };
    if (!centres.empty())
    {
        std::uniform_int_distribution<std::size_t> pick(0, centres.size() - 1);
        for (long n = 0; n < n_items; ++n)
        {
            const auto [x, y] = centres[pick(rng)];
            const Eigen::Vector2d c(gt.idx2x(x), gt.idx2y(y));
            const double yaw = uniform(rng, 0, 1) < 0.6
                                   ? 0.5 * M_PI * std::floor(uniform(rng, 0, 4))
                                   : uniform(rng, 0, M_PI);
            const double kind = uniform(rng, 0, 1);
            if (kind < 0.35)  // desk or table top seen by the laser (solid)
                fillRect(c, uniform(rng, 0.3, 0.8), uniform(rng, 0.25, 0.4), yaw);
            else if (kind < 0.55)  // shelf
                fillRect(c, uniform(rng, 0.5, 1.0), 0.15, yaw);
            else  // legs of a table or chair: four small posts
            {
                const double hw = uniform(rng, 0.2, 0.6), hh = uniform(rng, 0.2, 0.45);
                const double post = std::max(res, uniform(rng, 0.04, 0.08));
                const Eigen::Rotation2Dd rot(yaw);
                for (int sxn : {-1, 1})
                    for (int syn : {-1, 1})
                        fillRect(c + rot * Eigen::Vector2d(sxn * hw, syn * hh), post / 2, post / 2,
                                 yaw);
            }
        }
    }
    Variant v;
    v.map = withCells(gt, cells);
    v.truth = identityTruth(defaultTolerance(res, res));
    v.truth.is_clutter = clutterOf(v.map, std::move(mask));
    return v;
}
}  // namespace mrpt_topoeval::validation
