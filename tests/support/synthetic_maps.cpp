/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "synthetic_maps.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace mrpt_topoeval::testing
{
using mrpt::maps::COccupancyGridMap2D;

GridSketch::GridSketch(double width_m, double height_m, double resolution_m)
{
    m_grid.setSize(0.0, width_m, 0.0, height_m, resolution_m, 0.0f);
}

void GridSketch::set(double x0, double y0, double x1, double y1, float p_free)
{
    const int cx0 = std::max(0, m_grid.x2idx(std::min(x0, x1) + 1e-9));
    const int cy0 = std::max(0, m_grid.y2idx(std::min(y0, y1) + 1e-9));
    const int cx1 = std::min<int>(m_grid.getSizeX() - 1, m_grid.x2idx(std::max(x0, x1) - 1e-9));
    const int cy1 = std::min<int>(m_grid.getSizeY() - 1, m_grid.y2idx(std::max(y0, y1) - 1e-9));
    for (int cy = cy0; cy <= cy1; ++cy)
        for (int cx = cx0; cx <= cx1; ++cx) m_grid.setCell(cx, cy, p_free);
}

GridSketch& GridSketch::carve(double x0, double y0, double x1, double y1)
{
    set(x0, y0, x1, y1, 1.0f);
    return *this;
}
GridSketch& GridSketch::fill(double x0, double y0, double x1, double y1)
{
    set(x0, y0, x1, y1, 0.0f);
    return *this;
}
GridSketch& GridSketch::unknown(double x0, double y0, double x1, double y1)
{
    set(x0, y0, x1, y1, 0.5f);
    return *this;
}

COccupancyGridMap2D makeTJunctionMap(double res)
{
    GridSketch s(14.0, 9.0, res);
    s.carve(1.0, 6.0, 13.0, 7.5);   // horizontal corridor, centre line y = 6.75
    s.carve(6.25, 1.0, 7.75, 6.0);  // branch down from the middle, centre line x = 7
    return s.grid();
}

COccupancyGridMap2D makePlusMap(double res)
{
    GridSketch s(16.0, 16.0, res);
    s.carve(2.0, 7.25, 14.0, 8.75);
    s.carve(7.25, 2.0, 8.75, 14.0);
    return s.grid();
}

COccupancyGridMap2D makeTwoRoomsMap(double res)
{
    GridSketch s(10.6, 6.0, res);
    s.carve(1.0, 1.0, 5.0, 5.0);  // room A, centre (3, 3)
    s.carve(5.2, 1.0, 9.2, 5.0);  // room B, centre (7.2, 3)
    s.carve(4.9, 2.5, 5.3, 3.5);  // 1 m door through the 0.2 m wall
    return s.grid();
}

GridSketch hallBuildingSketch()
{
    GridSketch s(44.0, 20.0);
    s.carve(1.0, 5.0, 42.0, 7.0);  // corridor
    double x = 2.0;
    for (double w : {5.0, 4.0, 6.0, 5.0, 4.5, 6.5})
    {
        s.carve(x, 1.0, x + w, 4.0).carve(x + 1.0, 4.0, x + 2.0, 5.0);
        x += w + 1.0;
    }
    s.carve(1.0, 8.0, 21.0, 13.0).carve(9.0, 7.0, 11.0, 8.0);   // hall and its door
    s.carve(3.0, 14.0, 8.0, 18.0).carve(5.0, 13.0, 6.0, 14.0);  // rooms off the hall
    s.carve(10.0, 14.0, 14.0, 18.0).carve(11.0, 13.0, 12.0, 14.0);
    s.carve(16.0, 14.0, 21.0, 17.0).carve(18.0, 13.0, 19.0, 14.0);
    s.carve(23.0, 9.0, 30.0, 15.0).carve(25.0, 7.0, 26.0, 9.0);  // offices east
    s.carve(32.0, 9.0, 41.0, 13.0).carve(35.0, 7.0, 36.0, 9.0);
    return s;
}

COccupancyGridMap2D makePinwheelMap(double res)
{
    constexpr double c = 22.0;
    GridSketch s(2.0 * c, 2.0 * c, res);
    // A rectangle in a wing's frame (u along the wing from the centre, v across it), turned by
    // k quarter turns about the centre.
    auto carve = [&](int k, double u0, double v0, double u1, double v1)
    {
        auto at = [&](double u, double v) -> Eigen::Vector2d
        {
            const std::array<Eigen::Vector2d, 4> turned = {
                Eigen::Vector2d(u, v), {-v, u}, {-u, -v}, {v, -u}};
            return Eigen::Vector2d(c, c) + turned[std::size_t(k)];
        };
        const Eigen::Vector2d a = at(u0, v0), b = at(u1, v1);
        s.carve(a.x(), a.y(), b.x(), b.y());
    };
    carve(0, -3.0, -3.0, 3.0, 3.0);  // the hall
    for (int k = 0; k < 4; ++k)
    {
        carve(k, 3.0, -1.0, 17.0, 1.0);  // the corridor
        for (double u : {4.0, 8.0, 12.0})
        {
            carve(k, u, 1.2, u + 3.8, 5.0);        // a room on the left
            carve(k, u + 1.5, 1.0, u + 2.5, 1.2);  // its door
        }
        for (double u : {5.0, 9.0})
        {
            carve(k, u, -5.0, u + 3.8, -1.2);        // a room on the right
            carve(k, u + 1.4, -1.2, u + 2.4, -1.0);  // its door
        }
    }
    carve(0, 17.2, -1.0, 20.5, 3.5);  // the marker room, east wing only
    carve(0, 17.0, -0.5, 17.2, 0.5);  // its door
    return s.grid();
}

COccupancyGridMap2D makeCorridorLoopMap(double res)
{
    GridSketch s(12.0, 12.0, res);
    s.carve(1.5, 1.5, 10.5, 10.5);
    s.fill(3.0, 3.0, 9.0, 9.0);  // the 6 m solid block inside
    return s.grid();
}

COccupancyGridMap2D makeLoopWithSpurMap(double res)
{
    GridSketch s(16.0, 12.0, res);
    s.carve(1.5, 1.5, 10.5, 10.5);
    s.fill(3.0, 3.0, 9.0, 9.0);
    s.carve(10.5, 5.25, 14.5, 6.75);  // 4 m dead-end corridor from the right side
    return s.grid();
}

COccupancyGridMap2D makeOfficeMap(double res)
{
    // An asymmetric floor: a corridor loop around a core, rooms of different sizes on doors,
    // and two dead-end corridors, so that vertices differ in degree, angles and edge lengths.
    GridSketch s(32.0, 22.0, res);
    s.carve(2.0, 8.0, 28.0, 10.0);    // main corridor (south side of the loop)
    s.carve(2.0, 14.0, 22.0, 16.0);   // north corridor
    s.carve(2.0, 8.0, 4.0, 16.0);     // west link
    s.carve(20.0, 10.0, 22.0, 14.0);  // east link
    s.carve(26.0, 10.0, 28.0, 20.0);  // dead-end corridor going north
    s.carve(9.0, 2.0, 10.8, 8.0);     // dead-end corridor going south
    // Rooms north of the north corridor, doors 1 m wide.
    s.carve(2.5, 17.0, 7.0, 21.0).carve(4.0, 16.0, 5.0, 17.0);
    s.carve(8.0, 17.0, 15.0, 21.0).carve(10.0, 16.0, 11.0, 17.0);
    s.carve(16.0, 17.0, 21.5, 20.0).carve(19.0, 16.0, 20.0, 17.0);
    // Rooms south of the main corridor.
    s.carve(2.0, 2.0, 8.0, 7.0).carve(5.0, 7.0, 6.0, 8.0);
    s.carve(12.0, 2.5, 18.0, 7.0).carve(13.0, 7.0, 14.0, 8.0);
    s.carve(19.0, 1.0, 30.0, 7.0).carve(24.0, 7.0, 25.0, 8.0);
    // A room inside the loop with two doors.
    s.carve(6.0, 11.0, 18.0, 13.0).carve(7.0, 10.0, 8.0, 11.0).carve(16.0, 13.0, 17.0, 14.0);
    // A room east of the dead-end corridor.
    s.carve(29.0, 12.0, 31.5, 18.0).carve(28.0, 14.5, 29.0, 15.5);
    return s.grid();
}

namespace
{
Eigen::Vector2d mapCentre(const COccupancyGridMap2D& g)
{
    return {0.5 * (g.getXMin() + g.getXMax()), 0.5 * (g.getYMin() + g.getYMax())};
}
}  // namespace

Eigen::Vector2d transformPoint(const COccupancyGridMap2D& src, double yaw,
                               const Eigen::Vector2d& shift, const Eigen::Vector2d& p)
{
    const Eigen::Vector2d c = mapCentre(src);
    const Eigen::Rotation2Dd R(yaw);
    return c + R * (p - c) + shift;
}

COccupancyGridMap2D transformGrid(const COccupancyGridMap2D& src, double yaw,
                                  const Eigen::Vector2d& shift, double res)
{
    if (res <= 0.0) res = src.getResolution();
    // Bounding box of the moved source.
    double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
    for (double x : {src.getXMin(), src.getXMax()})
        for (double y : {src.getYMin(), src.getYMax()})
        {
            const Eigen::Vector2d q = transformPoint(src, yaw, shift, {x, y});
            x0 = std::min(x0, q.x()), x1 = std::max(x1, q.x());
            y0 = std::min(y0, q.y()), y1 = std::max(y1, q.y());
        }
    COccupancyGridMap2D dst;
    dst.setSize(x0, x1, y0, y1, res, 0.5f);
    const Eigen::Vector2d c = mapCentre(src);
    const Eigen::Rotation2Dd Rinv(-yaw);
    // At the same resolution a target cell takes the source cell under its centre. When
    // coarsening, it looks at k x k points of its footprint: an obstacle seen anywhere wins
    // (a wall hit anywhere in a cell marks it in a coarser map, and a thin wall is never lost
    // the way sampling the centre alone loses it); otherwise the cell gets the footprint's mean
    // P(free), so a cell mostly unseen stays unknown.
    const double ratio = res / src.getResolution();
    const int k = ratio > 1.0 + 1e-9 ? static_cast<int>(std::ceil(2.0 * ratio)) : 1;
    const auto occ_l = COccupancyGridMap2D::p2l(0.35f);
    const auto l_occ = COccupancyGridMap2D::p2l(0.0f);
    for (unsigned cy = 0; cy < dst.getSizeY(); ++cy)
        for (unsigned cx = 0; cx < dst.getSizeX(); ++cx)
        {
            bool any_occ = false;
            double sum_p = 0.0;
            int n = 0;
            for (int i = 0; i < k; ++i)
                for (int j = 0; j < k; ++j)
                {
                    const Eigen::Vector2d q(dst.idx2x(cx) + res * ((i + 0.5) / k - 0.5),
                                            dst.idx2y(cy) + res * ((j + 0.5) / k - 0.5));
                    const Eigen::Vector2d p = c + Rinv * (q - shift - c);
                    const int sx = src.x2idx(p.x()), sy = src.y2idx(p.y());
                    ++n;
                    if (sx < 0 || sy < 0 || sx >= static_cast<int>(src.getSizeX()) ||
                        sy >= static_cast<int>(src.getSizeY()))
                    {
                        sum_p += 0.5;
                        continue;
                    }
                    const auto l = src.getRow(sy)[sx];
                    any_occ = any_occ || l <= occ_l;
                    sum_p += COccupancyGridMap2D::l2p(l);
                }
            if (any_occ)
                dst.getRow(cy)[cx] = l_occ;
            else
                dst.getRow(cy)[cx] = COccupancyGridMap2D::p2l(static_cast<float>(sum_p / n));
        }
    return dst;
}

Eigen::Vector2d breakPoint(const Eigen::Vector2d& pivot, double yaw,
                           const std::function<bool(double, double)>& in_part,
                           const Eigen::Vector2d& p)
{
    if (!in_part(p.x(), p.y())) return p;
    return pivot + Eigen::Rotation2Dd(yaw) * (p - pivot);
}

COccupancyGridMap2D breakMap(const COccupancyGridMap2D& src, const Eigen::Vector2d& pivot,
                             double yaw, const std::function<bool(double, double)>& in_part)
{
    // The moved part may leave the source's extent: grow the grid to hold it.
    double x0 = src.getXMin(), y0 = src.getYMin(), x1 = src.getXMax(), y1 = src.getYMax();
    for (double x : {src.getXMin(), src.getXMax()})
        for (double y : {src.getYMin(), src.getYMax()})
        {
            const Eigen::Vector2d q =
                pivot + Eigen::Rotation2Dd(yaw) * (Eigen::Vector2d(x, y) - pivot);
            x0 = std::min(x0, q.x()), x1 = std::max(x1, q.x());
            y0 = std::min(y0, q.y()), y1 = std::max(y1, q.y());
        }
    COccupancyGridMap2D dst;
    dst.setSize(x0, x1, y0, y1, src.getResolution(), 0.5f);
    const Eigen::Rotation2Dd Rinv(-yaw);
    const auto occ_l = COccupancyGridMap2D::p2l(0.35f);
    auto sample = [&](const Eigen::Vector2d& p, COccupancyGridMap2D::cellType* out)
    {
        const int sx = src.x2idx(p.x()), sy = src.y2idx(p.y());
        if (sx < 0 || sy < 0 || sx >= static_cast<int>(src.getSizeX()) ||
            sy >= static_cast<int>(src.getSizeY()))
            return false;
        *out = src.getRow(sy)[sx];
        return true;
    };
    for (unsigned cy = 0; cy < dst.getSizeY(); ++cy)
        for (unsigned cx = 0; cx < dst.getSizeX(); ++cx)
        {
            const Eigen::Vector2d q(dst.idx2x(cx), dst.idx2y(cy));
            const Eigen::Vector2d back = pivot + Rinv * (q - pivot);
            COccupancyGridMap2D::cellType moved = 0, still = 0;
            const bool has_moved = in_part(back.x(), back.y()) && sample(back, &moved);
            const bool has_still = !in_part(q.x(), q.y()) && sample(q, &still);
            auto& cell = dst.getRow(cy)[cx];
            if (has_moved && has_still)
                cell = (moved <= occ_l || still <= occ_l) ? std::min(moved, still)
                                                          : std::max(moved, still);
            else if (has_moved)
                cell = moved;
            else if (has_still)
                cell = still;
        }
    return dst;
}

COccupancyGridMap2D addSpeckleNoise(const COccupancyGridMap2D& src, double fraction,
                                    std::uint32_t seed)
{
    COccupancyGridMap2D dst = src;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int sx = static_cast<int>(src.getSizeX()), sy = static_cast<int>(src.getSizeY());
    auto occ = [&](int x, int y) { return src.getCell(x, y) < 0.35f; };
    auto fre = [&](int x, int y) { return src.getCell(x, y) > 0.65f; };
    for (int y = 1; y < sy - 1; ++y)
        for (int x = 1; x < sx - 1; ++x)
        {
            const bool near_occ = occ(x - 1, y) || occ(x + 1, y) || occ(x, y - 1) || occ(x, y + 1);
            const bool near_free = fre(x - 1, y) || fre(x + 1, y) || fre(x, y - 1) || fre(x, y + 1);
            if (fre(x, y) && near_occ && u(rng) < fraction)
                dst.setCell(x, y, 0.0f);
            else if (occ(x, y) && near_free && u(rng) < fraction)
                dst.setCell(x, y, 1.0f);
        }
    return dst;
}

COccupancyGridMap2D makeCampusMap(std::uint32_t seed, double res)
{
    std::mt19937 rng(seed);
    auto uni = [&](double a, double b)
    { return std::uniform_real_distribution<double>(a, b)(rng); };
    // Corridor west and south edges: a fixed layout for seed 1, a layout of its own for others.
    std::vector<double> xs = {1.0, 12.5, 21.0, 34.5, 47.0, 59.0};
    std::vector<double> ys = {1.0, 10.0, 22.5, 33.0};
    if (seed != 1)
    {
        for (std::size_t i = 1; i + 1 < xs.size(); ++i) xs[i] = xs[i - 1] + uni(7.5, 14.0);
        xs.back() = std::min(59.0, xs[xs.size() - 2] + uni(7.5, 14.0));
        for (std::size_t j = 1; j + 1 < ys.size(); ++j) ys[j] = ys[j - 1] + uni(7.5, 13.0);
        ys.back() = std::min(33.0, ys[ys.size() - 2] + uni(7.5, 13.0));
    }
    const double w = 1.8, wall = 0.2;
    GridSketch s(62.0, 37.0, res);
    for (double x : xs) s.carve(x, ys.front(), x + w, ys.back() + w);
    for (double y : ys) s.carve(xs.front(), y, xs.back() + w, y + w);
    // Rooms: split each block into a random number of rooms along its longer side, with a door
    // of 0.9 m at a random position onto the south or north corridor.
    for (std::size_t i = 0; i + 1 < xs.size(); ++i)
        for (std::size_t j = 0; j + 1 < ys.size(); ++j)
        {
            const double bx0 = xs[i] + w + wall, bx1 = xs[i + 1] - wall;
            const double by0 = ys[j] + w + wall, by1 = ys[j + 1] - wall;
            double x = bx0;
            while (bx1 - x > 2.5)
            {
                const double rw = std::min(bx1 - x, uni(2.5, 6.5));
                const double x1 = (bx1 - (x + rw) < 2.5) ? bx1 : x + rw;
                // Some rooms are split in two along y.
                const bool split = (by1 - by0) > 7.0 && uni(0.0, 1.0) < 0.5;
                const double ym = split ? uni(by0 + 3.0, by1 - 3.0) : by1;
                s.carve(x, by0, x1, split ? ym - wall / 2 : by1);
                const double d0 = uni(x + 0.3, x1 - 1.2);
                s.carve(d0, by0 - wall, d0 + 0.9, by0);  // door south
                if (split)
                {
                    s.carve(x, ym + wall / 2, x1, by1);
                    const double d1 = uni(x + 0.3, x1 - 1.2);
                    s.carve(d1, by1, d1 + 0.9, by1 + wall);  // door north
                }
                x = x1 + wall;
            }
        }
    return s.grid();
}

COccupancyGridMap2D makeLargeBuilding(int cells, double res)
{
    // Blocks of 2 x 2 rooms (5.8 m, 0.2 m walls) with a 2 m corridor along the south and west
    // of each block; the corridors form a lattice of loops. Every room has one 1 m door: the
    // south rooms to the south corridor, the north-west room to the west corridor, the
    // north-east room to its western neighbour. A 0.5 m solid margin closes the building.
    const double size = cells * res, margin = 0.5, corridor = 2.0, wall = 0.2, room = 5.8;
    const double pitch = corridor + 2.0 * (wall + room) + wall;
    GridSketch s(size, size, res);
    const int blocks = static_cast<int>((size - 2.0 * margin - corridor) / pitch);
    const double end = margin + blocks * pitch + corridor;
    for (int j = 0; j < blocks; ++j)
        for (int i = 0; i < blocks; ++i)
        {
            const double bx = margin + i * pitch, by = margin + j * pitch;
            s.carve(bx, by, bx + pitch + corridor, by + corridor);  // south corridor
            s.carve(bx, by, bx + corridor, by + pitch + corridor);  // west corridor
            for (int ry = 0; ry < 2; ++ry)
                for (int rx = 0; rx < 2; ++rx)
                {
                    const double x0 = bx + corridor + wall + rx * (room + wall);
                    const double y0 = by + corridor + wall + ry * (room + wall);
                    s.carve(x0, y0, x0 + room, y0 + room);
                    const double mid = 0.5 * room - 0.5;
                    if (ry == 0)
                        s.carve(x0 + mid, y0 - wall, x0 + mid + 1.0, y0);
                    else
                        s.carve(x0 - wall, y0 + mid, x0, y0 + mid + 1.0);
                }
        }
    s.carve(margin, end - corridor, end, end);  // north corridor closes the lattice
    s.carve(end - corridor, margin, end, end);  // east corridor
    return s.grid();
}

}  // namespace mrpt_topoeval::testing
