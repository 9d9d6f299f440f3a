/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/graph/build_graph.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <unordered_map>

#include "graph/GraphEditor.h"
#include "graph/attributes.h"
#include "graph/islands.h"
#include "skeleton/outer_boundary.h"
#include "skeleton/voronoi_cgal.h"

namespace mrpt_topoeval
{
// ---------------------------------------------------------------- construction
namespace
{
using Clock = std::chrono::steady_clock;

class StepTimer
{
public:
    explicit StepTimer(GraphBuildStats& stats) : m_stats(stats) {}
    // Adds the time since the last lap to `step` (a step timed twice, like "observer", sums).
    void lap(const char* step)
    {
        const auto now = Clock::now();
        m_stats.timing_ms[step] += std::chrono::duration<double, std::milli>(now - m_last).count();
        m_last = now;
    }
    void total()
    {
        m_stats.timing_ms["total"] =
            std::chrono::duration<double, std::milli>(Clock::now() - m_start).count();
    }

private:
    GraphBuildStats& m_stats;
    Clock::time_point m_start = Clock::now(), m_last = m_start;
};

enum CellClass : std::uint8_t
{
    kUnknown = 0,
    kFree = 1,
    kOccupied = 2
};
// Morphological closing of `mask` with a disc of radius r cells. Outside the grid counts as
// not in the mask, so the closing adds nothing along the grid's border.
cv::Mat closedWithDisc(const cv::Mat& mask, int r)
{
    cv::Mat closed;
    const cv::Mat disc =
        cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * r + 1, 2 * r + 1));
    cv::morphologyEx(mask, closed, cv::MORPH_CLOSE, disc, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT,
                     cv::Scalar(0));
    return closed;
}

// The cleaning closings run tile by tile, with the same result as on the whole grid: a cell's
// closing depends only on the mask within 2r of it (dilation reads r cells, erosion r more), so a
// tile closed with a margin of 2r cells is exact, and where the margin meets the grid's edge it
// is the grid's own border. Only a tile that holds a cell the closing may change, and sees a
// cell of the mask within the margin, is closed at all: most tiles of a large map are all free,
// all wall or all outside, and each tile's masks stay in cache (the 10^8-cell benchmark's
// first build: cleaning 2.5-2.7 s -> 1.6-1.7 s; doc/performance.md, session 19).
constexpr int kTile = 256;

/** Which cell classes each tile of kTile x kTile cells holds: bit (1 << class). */
struct TileClasses
{
    int tx = 0, ty = 0;
    std::vector<std::uint8_t> bits;
};

TileClasses tileClasses(const std::vector<std::uint8_t>& cls, int sx, int sy)
{
    TileClasses t;
    t.tx = (sx + kTile - 1) / kTile;
    t.ty = (sy + kTile - 1) / kTile;
    t.bits.assign(static_cast<std::size_t>(t.tx) * t.ty, 0);
    for (int y = 0; y < sy; ++y)
    {
        const std::uint8_t* row = &cls[static_cast<std::size_t>(y) * sx];
        std::uint8_t* bits = &t.bits[static_cast<std::size_t>(y / kTile) * t.tx];
        for (int i = 0; i < t.tx; ++i)
        {
            const std::uint8_t* seg = row + static_cast<std::size_t>(i) * kTile;
            const std::size_t n = static_cast<std::size_t>(std::min(kTile, sx - i * kTile));
            // memchr is a vectorised scan; most segments are decided by their first bytes.
            for (const std::uint8_t c : {kUnknown, kFree, kOccupied})
                if (!(bits[i] & (1u << c)) && std::memchr(seg, c, n))
                    bits[i] |= static_cast<std::uint8_t>(1u << c);
        }
    }
    return t;
}

/** The closing of `mask` (the grid `cls`'s, taken before any tile changes) with a disc of r
 * cells, handed to `apply(tile, closed)` for each tile that holds a class of `changeable` and
 * sees a class of `source` within the margin (bit masks as in TileClasses). */
template <class Apply>
void closeByTiles(const std::vector<std::uint8_t>& cls, const cv::Mat& mask, int r,
                  unsigned changeable, unsigned source, Apply apply)
{
    const int margin = 2 * r;
    const cv::Rect grid(0, 0, mask.cols, mask.rows);
    if (margin > kTile / 16)
    {
        // Windows of (256 + 4r)^2 cells for 256^2 useful ones: beyond r = 8 the whole grid at
        // once is cheaper (a 3000^2 grid: equal at r = 8, 2.4 times faster at r = 32).
        apply(grid, closedWithDisc(mask, r));
        return;
    }
    const TileClasses t = tileClasses(cls, mask.cols, mask.rows);
    for (int j = 0; j < t.ty; ++j)
        for (int i = 0; i < t.tx; ++i)
        {
            if (!(t.bits[static_cast<std::size_t>(j) * t.tx + i] & changeable)) continue;
            // The margin (at most kTile / 16 cells) reaches the eight neighbouring tiles.
            bool seen = false;
            for (int jj = std::max(0, j - 1); jj <= std::min(t.ty - 1, j + 1); ++jj)
                for (int ii = std::max(0, i - 1); ii <= std::min(t.tx - 1, i + 1); ++ii)
                    seen |= (t.bits[static_cast<std::size_t>(jj) * t.tx + ii] & source) != 0;
            if (!seen) continue;
            const cv::Rect tile(i * kTile, j * kTile, std::min(kTile, mask.cols - i * kTile),
                                std::min(kTile, mask.rows - j * kTile));
            const cv::Rect window = cv::Rect(tile.x - margin, tile.y - margin,
                                             tile.width + 2 * margin, tile.height + 2 * margin) &
                                    grid;
            const cv::Mat closed = closedWithDisc(mask(window), r);
            apply(tile,
                  closed(cv::Rect(tile.x - window.x, tile.y - window.y, tile.width, tile.height)));
        }
}

// Closing of the free cells with a disc: unknown cells enclosed by free space within the radius
// become free, occupied cells never change.
void fillUnknownSpecks(std::vector<std::uint8_t>& cls, int sx, int sy, double radius_cells)
{
    const int r = static_cast<int>(std::lround(radius_cells));
    if (r < 1 || cls.empty()) return;
    cv::Mat c(sy, sx, CV_8UC1, cls.data());
    closeByTiles(cls, c == kFree, r, 1u << kUnknown, 1u << kFree,
                 [&](const cv::Rect& tile, const cv::Mat& closed)
                 {
                     cv::Mat out = c(tile);
                     out.setTo(kFree, closed & (out == kUnknown));
                 });
}

// Closing of the obstacle cells with a disc: gaps and notches in walls up to about twice the
// radius wide become obstacle. Free space is only lost where no disc of the radius fits, so
// every point with at least that clearance keeps its clearance.
void closeObstacleGaps(std::vector<std::uint8_t>& cls, int sx, int sy, double radius_cells)
{
    const int r = static_cast<int>(std::lround(radius_cells));
    if (r < 1 || cls.empty()) return;
    cv::Mat c(sy, sx, CV_8UC1, cls.data());
    closeByTiles(cls, c == kOccupied, r, (1u << kUnknown) | (1u << kFree), 1u << kOccupied,
                 [&](const cv::Rect& tile, const cv::Mat& closed)
                 { c(tile).setTo(kOccupied, closed); });
}

// Every region of `from` cells that touches the grid's edge becomes `to`: OpenCV's scan-line
// flood fill from each such edge cell, 4- or 8-connected.
void floodFromEdge(std::vector<std::uint8_t>& cls, int sx, int sy, std::uint8_t from,
                   std::uint8_t to, int connectivity)
{
    cv::Mat grid(sy, sx, CV_8UC1, cls.data());
    auto reach = [&](int x, int y)
    {
        if (grid.at<std::uint8_t>(y, x) == from)
            cv::floodFill(grid, cv::Point(x, y), cv::Scalar(to), nullptr, cv::Scalar(0),
                          cv::Scalar(0), connectivity);
    };
    for (int x = 0; x < sx; ++x) reach(x, 0), reach(x, sy - 1);
    for (int y = 0; y < sy; ++y) reach(0, y), reach(sx - 1, y);
}

// Enclosed unknown regions: 8-connected components of unknown cells that do not reach the
// grid's edge through unknown cells, and whose outer neighbours (4-neighbours outside the
// component) are at least `min_free_share` free cells, become free. Such a region is free space
// the laser crossed too sparsely to mark (the middle of a large hall, the wedge behind a
// column); an unexplored room seen through a door is bounded mostly by its walls and stays,
// and so does the unknown inside a thick wall. Returns how many regions were filled.
std::size_t fillEnclosedUnknown(std::vector<std::uint8_t>& cls, int sx, int sy,
                                double min_free_share)
{
    if (min_free_share <= 0.0 || cls.empty()) return 0;
    constexpr std::uint8_t kOutside = 3, kSeen = 4;
    const std::size_t n = cls.size();
    std::vector<std::size_t> stack;  // depth first: the order does not matter, only the set
    // Visits the unknown component of `start`, marking it `mark`, appends its cells and counts
    // its border: the free and occupied 4-neighbours of its cells.
    std::size_t free_border = 0, occupied_border = 0;
    auto flood = [&](std::size_t start, std::uint8_t mark, std::vector<std::size_t>& cells)
    {
        free_border = occupied_border = 0;
        stack.assign(1, start);
        cls[start] = mark;
        while (!stack.empty())
        {
            const std::size_t i = stack.back();
            stack.pop_back();
            cells.push_back(i);
            const int x = static_cast<int>(i % sx), y = static_cast<int>(i / sx);
            for (const std::size_t j : {x > 0 ? i - 1 : i, x + 1 < sx ? i + 1 : i,
                                        y > 0 ? i - sx : i, y + 1 < sy ? i + sx : i})
            {
                free_border += cls[j] == kFree;
                occupied_border += cls[j] == kOccupied;
            }
            const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, sx - 1);
            const int y0 = std::max(y - 1, 0), y1 = std::min(y + 1, sy - 1);
            for (int yy = y0; yy <= y1; ++yy)
            {
                std::uint8_t* row = &cls[static_cast<std::size_t>(yy) * sx];
                for (int xx = x0; xx <= x1; ++xx)
                    if (row[xx] == kUnknown)
                    {
                        row[xx] = mark;
                        stack.push_back(static_cast<std::size_t>(yy) * sx + xx);
                    }
            }
        }
    };
    // The outside (often most of the grid), 8-connected.
    floodFromEdge(cls, sx, sy, kUnknown, kOutside, 8);
    std::size_t filled = 0;
    std::vector<std::size_t> cells;
    for (std::size_t start = 0; start < n; ++start)
    {
        if (cls[start] != kUnknown) continue;
        cells.clear();
        flood(start, kSeen, cells);
        const std::size_t border = free_border + occupied_border;
        if (border == 0 || static_cast<double>(free_border) < min_free_share * border) continue;
        for (const std::size_t i : cells) cls[i] = kFree;
        ++filled;
    }
    for (auto& v : cls)
        if (v == kOutside || v == kSeen) v = kUnknown;
    return filled;
}

// Ours (alpha_keep_enclosed): the free cells that reach the edge of the grid region through
// free cells (4-connected): the page around a floor plan. Free space enclosed by walls or
// unknown is the map's inside, whatever the alpha polygon says. 1 where a cell reaches the
// edge; empty when nothing is outside, and then no copy of the grid is made: no free cell lies
// on the map's edge (a robot map, unknown all around), or more than `max_edge_unknown` of the
// map's edge cells are unknown (alpha_page_max_edge_unknown: a map that says its outside is
// unknown, whose free space at the edge is its inside cut by the map's border, as a crop
// through a hall). The share is of the whole grid's edge, so it does not depend on the region
// worked on: `cls` is the region (w x h cells at ox, oy) of a grid of sx x sy cells, whose
// cells outside the region are unknown, and a free cell of the region's edge lies on the
// grid's edge (the region's margin is unknown).
std::vector<std::uint8_t> freeReachingEdge(const std::vector<std::uint8_t>& cls, int w, int h,
                                           int ox, int oy, int sx, int sy, double max_edge_unknown)
{
    std::size_t free_cells = 0, known_cells = 0;  // on the grid's edge
    auto count = [&](int x, int y)
    {
        const int gx = ox + x, gy = oy + y;
        if (gx != 0 && gy != 0 && gx != sx - 1 && gy != sy - 1) return;
        const std::uint8_t c = cls[static_cast<std::size_t>(y) * w + x];
        free_cells += c == kFree;
        known_cells += c != kUnknown;
    };
    for (int x = 0; x < w; ++x)
    {
        count(x, 0);
        if (h > 1) count(x, h - 1);
    }
    for (int y = 1; y + 1 < h; ++y)
    {
        count(0, y);
        if (w > 1) count(w - 1, y);
    }
    const std::size_t edge_cells = sx == 1 || sy == 1
                                       ? static_cast<std::size_t>(sx) * static_cast<std::size_t>(sy)
                                       : 2 * static_cast<std::size_t>(sx + sy) - 4;
    const std::size_t unknown_cells = edge_cells - known_cells;
    if (free_cells == 0 ||
        static_cast<double>(unknown_cells) > max_edge_unknown * static_cast<double>(edge_cells))
        return {};
    constexpr std::uint8_t kReached = 3;
    std::vector<std::uint8_t> mark(cls);
    floodFromEdge(mark, w, h, kFree, kReached, 4);
    for (auto& m : mark) m = m == kReached;
    return mark;
}

// The share of the obstacle cells nearest a piece's skeleton (`edges`, in grid cells) that are
// walls, not unknown (graph step 5: a room sealed off, or a laser fan's piece). They lie at each
// path point's clearance: sampled in kRoomRays directions one cell beyond it; a ray that lands
// on a free cell passes no obstacle that near. `cls` is the region (w x h cells at ox, oy);
// outside it is unknown.
double wallShareAround(const std::vector<std::uint8_t>& cls, int w, int h, int ox, int oy,
                       const std::vector<const internal::GraphEditor::Edge*>& edges)
{
    constexpr int kRoomRays = 16;
    std::size_t walls = 0, unknown = 0;
    for (const internal::GraphEditor::Edge* e : edges)
        for (std::size_t i = 0; i < e->path.size(); ++i)
        {
            const double r = e->clearance[i] + 1.0;
            for (int k = 0; k < kRoomRays; ++k)
            {
                const double a = 2.0 * M_PI * k / kRoomRays;
                const long x = std::lround(e->path[i].x() + r * std::cos(a)) - ox;
                const long y = std::lround(e->path[i].y() + r * std::sin(a)) - oy;
                const std::uint8_t c = x < 0 || y < 0 || x >= w || y >= h
                                           ? std::uint8_t(kUnknown)
                                           : cls[static_cast<std::size_t>(y) * w + x];
                walls += c == kOccupied;
                unknown += c == kUnknown;
            }
        }
    return walls + unknown == 0 ? 1.0 : double(walls) / double(walls + unknown);
}

// Islands: 8-connected components of non-free cells (occupied or unknown) surrounded by free
// space, not touching the grid's edge, whose smallest enclosing circle (of the cells'
// squares) is narrower than `min_size_cells`, become free. Returns how many were removed.
std::size_t removeSmallIslands(std::vector<std::uint8_t>& cls, int sx, int sy,
                               double min_size_cells)
{
    if (min_size_cells <= 0.0 || cls.empty()) return 0;
    cv::Mat c(sy, sx, CV_8UC1, cls.data());
    // Labelled in overlapping strips of rows, not the whole grid at once: a 10^8-cell label
    // image (400 MB) cost more than the labelling. A component that touches neither edge row of
    // its strip is a whole component of the grid; an island (narrower than min_size_cells)
    // lies whole in the strip whose core rows hold its top row, and is judged there only.
    const int overlap = static_cast<int>(std::ceil(min_size_cells)) + 2;
    const int core = std::max(256, 4 * overlap);
    std::size_t removed = 0;
    for (int y0 = 0; y0 < sy; y0 += core)
    {
        const int top = std::max(0, y0 - overlap), bottom = std::min(sy, y0 + core + overlap);
        cv::Mat strip = c.rowRange(top, bottom);
        const cv::Mat solid = (strip != kFree);
        cv::Mat labels, boxes, centroids;
        const int n = cv::connectedComponentsWithStats(solid, labels, boxes, centroids, 8, CV_32S);
        std::vector<cv::Point2f> cells;
        for (int k = 1; k < n; ++k)
        {
            const int x0 = boxes.at<int>(k, cv::CC_STAT_LEFT);
            const int ys = boxes.at<int>(k, cv::CC_STAT_TOP);  // strip rows
            const int w = boxes.at<int>(k, cv::CC_STAT_WIDTH);
            const int h = boxes.at<int>(k, cv::CC_STAT_HEIGHT);
            const int gy = top + ys;  // grid row of its top
            // The enclosing circle is at least as wide as the box's longer side.
            if (std::max(w, h) >= min_size_cells) continue;
            if (gy < y0 || gy >= y0 + core) continue;       // judged in another strip
            if (ys == 0 || ys + h == strip.rows) continue;  // strip or grid edge row
            if (x0 == 0 || x0 + w == sx) continue;          // grid edge column
            cells.clear();
            for (int y = ys; y < ys + h; ++y)
            {
                const int* row = labels.ptr<int>(y);
                for (int x = x0; x < x0 + w; ++x)
                    if (row[x] == k)
                        cells.emplace_back(static_cast<float>(x), static_cast<float>(y));
            }
            if (!(internal::islandWidthCells(cells) < min_size_cells)) continue;
            ++removed;
            for (int y = ys; y < ys + h; ++y)
            {
                const int* row = labels.ptr<int>(y);
                std::uint8_t* out = strip.ptr<std::uint8_t>(y);
                for (int x = x0; x < x0 + w; ++x)
                    if (row[x] == k) out[x] = kFree;
            }
        }
    }
    return removed;
}
}  // namespace

TopologyGraph buildTopologyGraph(const mrpt::maps::COccupancyGridMap2D& grid,
                                 const GraphBuilderParameters& params, GraphBuildStats* stats_out,
                                 const GraphBuildObserver& observer)
{
    params.validate();
    GraphBuildStats stats;
    StepTimer timer(stats);

    TopologyGraph graph;
    const int sx = static_cast<int>(grid.getSizeX()), sy = static_cast<int>(grid.getSizeY());
    const double res = grid.getResolution();
    graph.map.resolution_m = res;
    graph.map.size_x = sx;
    graph.map.size_y = sy;
    graph.map.x_min_m = grid.getXMin();
    graph.map.y_min_m = grid.getYMin();
    graph.map.x_max_m = grid.getXMax();
    graph.map.y_max_m = grid.getYMax();

    // Classify cells once, comparing quantised log-odds against thresholds converted once.
    using Cell = mrpt::maps::COccupancyGridMap2D::cellType;
    const Cell occ_l =
        mrpt::maps::COccupancyGridMap2D::p2l(static_cast<float>(1.0 - params.occupied_min_prob));
    const Cell free_l =
        mrpt::maps::COccupancyGridMap2D::p2l(static_cast<float>(1.0 - params.free_max_prob));
    std::vector<std::uint8_t> cls(static_cast<std::size_t>(sx) * sy, kUnknown);
    int known_x0 = sx, known_x1 = -1, known_y0 = sy, known_y1 = -1;  // bounding box of known
    for (int cy = 0; cy < sy; ++cy)
    {
        const Cell* row = grid.getRow(cy);
        std::uint8_t* out = &cls[static_cast<std::size_t>(cy) * sx];
        int first = sx, last = -1;
        for (int cx = 0; cx < sx; ++cx)
        {
            // Log-odds of P(free): low = occupied.
            if (row[cx] <= occ_l)
                out[cx] = kOccupied;
            else if (row[cx] >= free_l)
                out[cx] = kFree;
            else
                continue;
            first = std::min(first, cx);
            last = cx;
        }
        if (last < 0) continue;
        known_x0 = std::min(known_x0, first);
        known_x1 = std::max(known_x1, last);
        known_y0 = std::min(known_y0, cy);
        known_y1 = cy;
    }
    timer.lap("classify");

    // The steps below work on the known cells' bounding box with a margin of unknown cells (the
    // whole grid when that saves little): the grid's unknown surroundings, often a third of it,
    // cost time in every step and change nothing. With a margin wider than any closing radius,
    // every step gives what it gives on the whole grid (the closings add nothing outside the
    // box; unknown cells beyond the box reach the grid's edge through unknown cells, as the
    // margin's do), so the graph does not depend on it.
    const int margin =
        2 + static_cast<int>(std::ceil(std::max(
                {0.0, params.wall_gap_close_radius_m / res, params.unknown_fill_radius_m / res})));
    int ox = 0, oy = 0, w = sx, h = sy;  // the region worked on, in grid cells
    if (known_x1 >= 0)
    {
        ox = std::max(0, known_x0 - margin);
        oy = std::max(0, known_y0 - margin);
        w = std::min(sx, known_x1 + margin + 1) - ox;
        h = std::min(sy, known_y1 + margin + 1) - oy;
        if (static_cast<double>(w) * h < 0.9 * static_cast<double>(sx) * sy)
        {
            std::vector<std::uint8_t> crop(static_cast<std::size_t>(w) * h);
            for (int y = 0; y < h; ++y)
                std::copy_n(&cls[static_cast<std::size_t>(oy + y) * sx + ox], w,
                            &crop[static_cast<std::size_t>(y) * w]);
            cls.swap(crop);
        }
        else
            ox = oy = 0, w = sx, h = sy;
    }
    stats.work_cells = static_cast<std::size_t>(w) * h;
    // Order matters: gaps are closed first, so that a wall cut into short pieces by one-cell
    // gaps is whole again before small free-standing pieces are judged as islands.
    closeObstacleGaps(cls, w, h, params.wall_gap_close_radius_m / res);
    timer.lap("close_gaps");
    stats.unknown_regions_filled =
        fillEnclosedUnknown(cls, w, h, params.enclosed_unknown_min_free_share);
    timer.lap("enclosed_unknown");
    stats.islands_removed = removeSmallIslands(cls, w, h, params.min_island_size_m / res);
    timer.lap("islands");
    fillUnknownSpecks(cls, w, h, params.unknown_fill_radius_m / res);
    timer.lap("unknown_specks");
    for (auto c : cls)
    {
        graph.map.occupied_cells += c == kOccupied;
        graph.map.free_cells += c == kFree;
    }

    // Paper II-B: the sites are the occupied cells. Only those with a non-occupied 4-neighbour
    // (or on the grid's edge) can be the nearest obstacle of a free point; the rest only make
    // the triangulation bigger. With unknown_is_obstacle, unknown cells bordering free space
    // are sites too. Cells outside the region are unknown with no free neighbour: no sites.
    internal::VoronoiInput vin;
    vin.size_x = sx;
    vin.size_y = sy;
    auto at = [&](int x, int y) { return cls[static_cast<std::size_t>(y) * w + x]; };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
        {
            const std::uint8_t c = at(x, y);
            if (c == kFree || (c == kUnknown && !params.unknown_is_obstacle)) continue;
            const int cx = ox + x, cy = oy + y;
            const bool border = cx == 0 || cy == 0 || cx == sx - 1 || cy == sy - 1;
            // On the region's edge but not the grid's: an unknown cell of the margin.
            const bool region_edge = x == 0 || y == 0 || x == w - 1 || y == h - 1;
            bool site;
            if (c == kOccupied)
                site = border || region_edge || at(x - 1, y) != kOccupied ||
                       at(x + 1, y) != kOccupied || at(x, y - 1) != kOccupied ||
                       at(x, y + 1) != kOccupied;
            else
                site = !border && !region_edge &&
                       (at(x - 1, y) == kFree || at(x + 1, y) == kFree || at(x, y - 1) == kFree ||
                        at(x, y + 1) == kFree);
            if (site) vin.sites.emplace_back(cx, cy);
        }
    stats.sites = vin.sites.size();
    // The occupied sites are the walls the matcher checks a small part against (doc/
    // matching.md); counted first, so that a large map's copy takes no spare capacity.
    auto occupiedSite = [&](const Eigen::Vector2i& c)
    { return at(c.x() - ox, c.y() - oy) == kOccupied; };
    graph.wall_points_m.reserve(
        std::size_t(std::count_if(vin.sites.begin(), vin.sites.end(), occupiedSite)));
    for (const Eigen::Vector2i& c : vin.sites)
        if (occupiedSite(c))
            graph.wall_points_m.emplace_back(float(grid.idx2x(c.x())), float(grid.idx2y(c.y())));
    timer.lap("sites");

    if (graph.map.occupied_cells == 0 || graph.map.free_cells == 0)
    {
        graph.warnings.push_back(graph.map.occupied_cells == 0
                                     ? "the map has no obstacles: the Topology Graph is empty"
                                     : "the map has no free space: the Topology Graph is empty");
        timer.total();
        if (stats_out) *stats_out = stats;
        return graph;
    }

    if (params.skeleton_on_free_cells_only)
    {
        vin.keep_mask.assign(static_cast<std::size_t>(sx) * sy, 0);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                vin.keep_mask[static_cast<std::size_t>(oy + y) * sx + ox + x] = at(x, y) == kFree;
    }
    // For the alpha cut (step 4): which free cells reach the region's edge, i.e. the map's.
    // None on most robot maps (unknown all around) and on maps whose edge is mostly unknown:
    // then nothing is outside.
    const bool keep_enclosed = params.alpha_radius_m > 0.0 && params.alpha_keep_enclosed;
    const std::vector<std::uint8_t> open_free =
        keep_enclosed
            ? freeReachingEdge(cls, w, h, ox, oy, sx, sy, params.alpha_page_max_edge_unknown)
            : std::vector<std::uint8_t>();
    // The cells stay for the components step (a room's walls); the sites go once the diagram
    // is built.
    vin.min_clearance_cells = params.min_clearance_m / res;
    vin.alpha_radius_cells = params.alpha_radius_m / res;
    internal::VoronoiSkeleton vd = internal::computeVoronoiSkeleton(vin);
    std::vector<Eigen::Vector2i>().swap(vin.sites);
    std::vector<std::uint8_t>().swap(vin.keep_mask);
    stats.voronoi_vertices = vd.node_pos.size();
    stats.voronoi_edges = vd.edges_total;
    stats.voronoi_edges_kept = vd.edges.size();
    timer.lap("voronoi");

    // Paper II-B: vertices of degree 1 or > 2 become graph vertices, degree-2 chains merge into
    // edges that keep their polyline path.
    internal::GraphEditor g = internal::GraphEditor::fromSkeleton(vd);
    stats.vertices_initial = g.numAliveVertices();
    timer.lap("chains");
    const internal::CellToWorld to_world{grid.idx2x(0), grid.idx2y(0), res};
    // Snapshots for the observer cost an attribute pass each; none without an observer.
    auto snapshot = [&](const char* step)
    {
        if (!observer) return;
        TopologyGraph snap;
        snap.map = graph.map;
        snap.outer_boundary_m = graph.outer_boundary_m;
        internal::attributeGraph(g, to_world, params, snap);
        observer(step, snap);
        timer.lap("observer");
    };
    snapshot("voronoi");

    g.pruneDeadEnds(params.prune_dead_end_length_m / res, params.corner_spur_ratio,
                    params.junction_disc_ratio, params.junction_disc_max_length_m / res);
    stats.vertices_after_prune = g.numAliveVertices();
    timer.lap("prune");
    snapshot("pruned");

    // Paper II-B: cut everything outside the longest polygon of the map's alpha shape.
    if (params.alpha_radius_m > 0.0)
    {
        std::size_t polygons = 0;
        std::vector<Eigen::Vector2d> outer =
            internal::longestBoundaryPolygon(vd.alpha_boundary, &polygons);
        stats.alpha_polygon_segments = outer.size();
        if (outer.size() >= 3)
        {
            // Ours (alpha_keep_enclosed): outside the polygon, only free space that reaches
            // the map's edge is the outside; a room the polygon misses (wider than the alpha
            // radius, or walled by a line of collinear cells, which makes no faces) stays.
            auto inside = [&](const Eigen::Vector2d& p)
            {
                if (internal::pointInPolygon(outer, p)) return true;
                if (!keep_enclosed) return false;
                if (open_free.empty()) return true;  // nothing is outside (freeReachingEdge)
                const long x = std::lround(p.x()) - ox, y = std::lround(p.y()) - oy;
                if (x < 0 || y < 0 || x >= w || y >= h) return false;
                return open_free[static_cast<std::size_t>(y) * w + x] == 0;
            };
            g.cutOutside(inside);
            g.dissolveDegreeTwo();
            // The cut leaves stubs where corridors crossed the boundary: prune them as above.
            g.pruneDeadEnds(params.prune_dead_end_length_m / res, params.corner_spur_ratio,
                            params.junction_disc_ratio, params.junction_disc_max_length_m / res);
            for (const auto& p : outer) graph.outer_boundary_m.push_back(to_world(p));
        }
    }
    stats.vertices_after_alpha = g.numAliveVertices();
    timer.lap("alpha_cut");
    snapshot("alpha_cut");

    // Ours (issue 11): a dead end ends where its room or corridor ends, not in a corner.
    g.retractDeadEndTails(params.dead_end_tail_share, params.dead_end_tail_ratio);
    timer.lap("tails");

    // Ours (session 48): a short part whose skeleton runs between walls is a room sealed off
    // (a closed door, a crop, a break's cut), kept; one facing the unknown is a laser fan's or
    // the outside's fragment.
    auto isRoom = [&](const std::vector<const internal::GraphEditor::Edge*>& edges)
    { return wallShareAround(cls, w, h, ox, oy, edges) >= params.room_piece_min_wall_share; };
    g.keepComponents(params.min_component_length_m / res, params.room_piece_min_length_m / res,
                     isRoom);
    std::vector<std::uint8_t>().swap(cls);
    stats.vertices_after_component = g.numAliveVertices();
    timer.lap("largest_component");
    snapshot("largest_component");

    g.joinClose(params.join_distance_m / res);
    timer.lap("join");

    internal::attributeGraph(g, to_world, params, graph);
    stats.vertices_final = graph.vertices.size();
    timer.lap("attributes");
    if (observer) observer("joined", graph);

    if (graph.vertices.empty())
        graph.warnings.push_back(
            "no passage wider than 2 x min_clearance_m was found: the Topology Graph is empty");
    else if (graph.vertices.size() == 1 && graph.vertices[0].degree() == 2)
        graph.warnings.push_back(
            "the map's graph is a single cycle with no junction or dead end: it is returned as "
            "one degree-2 vertex (largest clearance) on a loop edge");

    timer.total();
    if (stats_out) *stats_out = stats;
    return graph;
}

}  // namespace mrpt_topoeval
