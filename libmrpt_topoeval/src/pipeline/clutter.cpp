/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The clutter pass (ours, issue 11): which of the map's free-standing obstacles the ground truth
// lacks where the first match puts them (doc/matching.md, "The clutter pass").

#include "pipeline/clutter.h"

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "geometry/horn.h"
#include "graph/islands.h"
#include "matching/wall_agreement.h"

namespace mrpt_topoeval::internal
{
namespace
{
/** An island of the region: its cells (region coordinates), its border cells' centres and its
 * enclosing circle's centre in the map's frame [m]. */
struct Island
{
    std::vector<cv::Point2f> cells;
    std::vector<Eigen::Vector2d> border;
    Eigen::Vector2d centre;
};

/** Calls `judge` for each island of `map_grid`'s cells [x0, x0 + w) x [y0, y0 + h) from
 * min_island_size_m to clutter_max_size_m across (8-connected non-free cells, as the graph
 * builder reads free space, surrounded by free space; one touching the region's edge may go on
 * beyond it and is skipped), and returns those it says are clutter. Labelled in overlapping
 * strips of rows, as the graph builder's removeSmallIslands() does: a whole 10^8-cell map's
 * label image is 400 MB. An island (at most clutter_max_size_m across) lies whole in the strip
 * whose core rows hold its top row, and is judged there only. */
std::vector<std::vector<cv::Point2f>> clutterIslands(
    const mrpt::maps::COccupancyGridMap2D& map_grid, int x0, int y0, int w, int h,
    const Parameters& params, const std::function<bool(const Island&)>& judge)
{
    const double res = map_grid.getResolution();
    const double min_cells = params.graph.min_island_size_m / res;
    const double max_cells = params.matcher.clutter_max_size_m / res;
    // Non-free cells, as the graph builder reads free space (P(occupied) <= free_max_prob).
    using Cell = mrpt::maps::COccupancyGridMap2D::cellType;
    const Cell free_l =
        mrpt::maps::COccupancyGridMap2D::p2l(static_cast<float>(1.0 - params.graph.free_max_prob));
    const int overlap = static_cast<int>(std::ceil(max_cells)) + 3;
    const int core = std::max(256, 4 * overlap);
    std::vector<std::vector<cv::Point2f>> clutter;
    Island island;
    for (int c0 = 0; c0 < h; c0 += core)
    {
        // Region rows [top, bottom) of this strip; its core is [c0, c0 + core).
        const int top = std::max(0, c0 - overlap), bottom = std::min(h, c0 + core + overlap);
        cv::Mat solid(bottom - top, w, CV_8UC1);
        for (int y = 0; y < solid.rows; ++y)
        {
            const Cell* row = map_grid.getRow(y0 + top + y);
            auto* out = solid.ptr<std::uint8_t>(y);
            for (int x = 0; x < w; ++x) out[x] = row[x0 + x] >= free_l ? 0 : 1;
        }
        cv::Mat labels, boxes, centroids;
        const int n = cv::connectedComponentsWithStats(solid, labels, boxes, centroids, 8, CV_32S);
        for (int k = 1; k < n; ++k)
        {
            const int bx = boxes.at<int>(k, cv::CC_STAT_LEFT),
                      by = boxes.at<int>(k, cv::CC_STAT_TOP);  // strip rows
            const int bw = boxes.at<int>(k, cv::CC_STAT_WIDTH),
                      bh = boxes.at<int>(k, cv::CC_STAT_HEIGHT);
            if (top + by < c0 || top + by >= c0 + core) continue;  // judged in another strip
            // Not surrounded: on the region's edge, or going on beyond the strip.
            if (bx == 0 || by == 0 || bx + bw == w || by + bh == solid.rows) continue;
            if (std::max(bw, bh) > max_cells + 1.0) continue;  // wider than its enclosing circle
            island.cells.clear();
            island.border.clear();
            for (int y = by; y < by + bh; ++y)
            {
                const int* row = labels.ptr<int>(y);
                for (int x = bx; x < bx + bw; ++x)
                {
                    if (row[x] != k) continue;
                    island.cells.emplace_back(static_cast<float>(x), static_cast<float>(top + y));
                    // A border cell has a free 4-neighbour (the island touches no edge).
                    if (labels.at<int>(y - 1, x) != k || labels.at<int>(y + 1, x) != k ||
                        labels.at<int>(y, x - 1) != k || labels.at<int>(y, x + 1) != k)
                        island.border.emplace_back(map_grid.idx2x(x0 + x),
                                                   map_grid.idx2y(y0 + top + y));
                }
            }
            cv::Point2f centre;
            const double size = islandWidthCells(island.cells, &centre);
            // Smaller ones are the graph builder's to remove (min_island_size_m).
            if (size < min_cells || size > max_cells) continue;
            island.centre = {map_grid.idx2x(x0 + static_cast<int>(std::lround(centre.x))),
                             map_grid.idx2y(y0 + static_cast<int>(std::lround(centre.y)))};
            if (judge(island)) clutter.push_back(island.cells);
        }
    }
    return clutter;
}

/** A copy of `map_grid` with `clutter` (cells of the region at x0, y0) made free. */
mrpt::maps::COccupancyGridMap2D freed(const mrpt::maps::COccupancyGridMap2D& map_grid, int x0,
                                      int y0, const std::vector<std::vector<cv::Point2f>>& clutter)
{
    mrpt::maps::COccupancyGridMap2D out = map_grid;
    for (const auto& island : clutter)
        for (const auto& q : island)  // P(free) = 1
            out.setCell(x0 + static_cast<int>(q.x), y0 + static_cast<int>(q.y), 1.0f);
    return out;
}
}  // namespace

std::optional<mrpt::maps::COccupancyGridMap2D> withoutClutter(
    const TopologyGraph& gt, const TopologyGraph& map,
    const mrpt::maps::COccupancyGridMap2D& map_grid, const GraphMatch& match,
    const Parameters& params, std::size_t& removed, std::size_t& judged)
{
    removed = judged = 0;
    const GraphMatcherParameters& p = params.matcher;
    if (match.pairs.size() < 3 || gt.wall_points_m.empty()) return std::nullopt;
    const int sx = static_cast<int>(map_grid.getSizeX()),
              sy = static_cast<int>(map_grid.getSizeY());
    if (sx < 3 || sy < 3 || !(map_grid.getResolution() > 0.0)) return std::nullopt;

    // The alignments the match knows (ground truth <- map): Horn's fit of all its pairs and of
    // each of its groups (a broken map's parts each have their own).
    std::vector<Eigen::Vector2d> matched, matched_gt;
    std::map<int, std::pair<std::vector<Eigen::Vector2d>, std::vector<Eigen::Vector2d>>> groups;
    for (const auto& pr : match.pairs)
    {
        matched.push_back(map.vertices[pr.map].position_m);
        matched_gt.push_back(gt.vertices[pr.ground_truth].position_m);
        if (pr.isomorphism < 0) continue;
        groups[pr.isomorphism].first.push_back(matched_gt.back());
        groups[pr.isomorphism].second.push_back(matched.back());
    }
    std::vector<Transform2D> alignments{hornAlign(matched_gt, matched)};
    for (const auto& [id, g] : groups)
        if (g.first.size() >= 3) alignments.push_back(hornAlign(g.first, g.second));

    // Islands are judged only where the match speaks: within clutter_reach_m of a matched map
    // vertex. The region worked on is their bounding box, widened by the reach and the largest
    // island.
    Eigen::Vector2d lo = matched.front(), hi = matched.front();
    for (const auto& q : matched) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    const double pad = p.clutter_reach_m + p.clutter_max_size_m;
    const int x0 = std::max(0, map_grid.x2idx(lo.x() - pad)),
              y0 = std::max(0, map_grid.y2idx(lo.y() - pad));
    const int x1 = std::min(sx - 1, map_grid.x2idx(hi.x() + pad)),
              y1 = std::min(sy - 1, map_grid.y2idx(hi.y() + pad));
    const int w = x1 - x0 + 1, h = y1 - y0 + 1;
    if (w < 3 || h < 3) return std::nullopt;

    WallIndex gt_walls(gt.wall_points_m);
    const double reach2 = p.clutter_reach_m * p.clutter_reach_m;
    const auto clutter = clutterIslands(
        map_grid, x0, y0, w, h, params,
        [&](const Island& island)
        {
            std::vector<Eigen::Vector2d> local_gt, local_map;
            for (std::size_t i = 0; i < matched.size(); ++i)
                if ((matched[i] - island.centre).squaredNorm() <= reach2)
                    local_gt.push_back(matched_gt[i]), local_map.push_back(matched[i]);
            if (local_map.empty()) return false;
            // Structure the ground truth has (a column, a free-standing wall) lies on its walls
            // under one of the alignments; a bent map is rigid only locally, so the fit of the
            // pairs within reach is asked too.
            ++judged;
            std::vector<Transform2D> island_alignments = alignments;
            if (local_map.size() >= 3) island_alignments.push_back(hornAlign(local_gt, local_map));
            for (const auto& t : island_alignments)
            {
                std::size_t on = 0;
                for (const auto& b : island.border)
                    on += gt_walls.near(t.apply(b), p.clutter_wall_tolerance_m);
                if (double(on) >= p.clutter_min_wall_share * double(island.border.size()))
                    return false;
            }
            return true;
        });
    if (clutter.empty()) return std::nullopt;
    removed = clutter.size();
    return freed(map_grid, x0, y0, clutter);
}

std::optional<mrpt::maps::COccupancyGridMap2D> withoutIslands(
    const mrpt::maps::COccupancyGridMap2D& map_grid, const Parameters& params, std::size_t& removed)
{
    removed = 0;
    const int sx = static_cast<int>(map_grid.getSizeX()),
              sy = static_cast<int>(map_grid.getSizeY());
    if (sx < 3 || sy < 3 || !(map_grid.getResolution() > 0.0)) return std::nullopt;
    const auto islands =
        clutterIslands(map_grid, 0, 0, sx, sy, params, [](const Island&) { return true; });
    if (islands.empty()) return std::nullopt;
    removed = islands.size();
    return freed(map_grid, 0, 0, islands);
}

}  // namespace mrpt_topoeval::internal
