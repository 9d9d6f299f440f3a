/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The clutter pass (ours, issue 11): which of the map's free-standing obstacles the ground truth
// lacks where the first match puts them (doc/matching.md, "The clutter pass").

#include "pipeline/clutter.h"

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "geometry/horn.h"
#include "graph/islands.h"
#include "matching/wall_agreement.h"

namespace mrpt_topoeval::internal
{
std::optional<mrpt::maps::COccupancyGridMap2D> withoutClutter(
    const TopologyGraph& gt, const TopologyGraph& map,
    const mrpt::maps::COccupancyGridMap2D& map_grid, const GraphMatch& match,
    const Parameters& params, std::size_t& removed, std::size_t& judged)
{
    removed = judged = 0;
    const GraphMatcherParameters& p = params.matcher;
    if (match.pairs.size() < 3 || gt.wall_points_m.empty()) return std::nullopt;
    const double res = map_grid.getResolution();
    const int sx = static_cast<int>(map_grid.getSizeX()),
              sy = static_cast<int>(map_grid.getSizeY());
    if (sx < 3 || sy < 3 || !(res > 0.0)) return std::nullopt;

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
    // island; an island touching its edge may go on beyond it and is not judged.
    Eigen::Vector2d lo = matched.front(), hi = matched.front();
    for (const auto& q : matched) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    const double pad = p.clutter_reach_m + p.clutter_max_size_m;
    const int x0 = std::max(0, map_grid.x2idx(lo.x() - pad)),
              y0 = std::max(0, map_grid.y2idx(lo.y() - pad));
    const int x1 = std::min(sx - 1, map_grid.x2idx(hi.x() + pad)),
              y1 = std::min(sy - 1, map_grid.y2idx(hi.y() + pad));
    const int w = x1 - x0 + 1, h = y1 - y0 + 1;
    if (w < 3 || h < 3) return std::nullopt;

    // Non-free cells, as the graph builder reads free space (P(occupied) <= free_max_prob).
    using Cell = mrpt::maps::COccupancyGridMap2D::cellType;
    const Cell free_l =
        mrpt::maps::COccupancyGridMap2D::p2l(static_cast<float>(1.0 - params.graph.free_max_prob));
    cv::Mat solid(h, w, CV_8UC1);
    for (int y = 0; y < h; ++y)
    {
        const Cell* row = map_grid.getRow(y0 + y);
        auto* out = solid.ptr<std::uint8_t>(y);
        for (int x = 0; x < w; ++x) out[x] = row[x0 + x] >= free_l ? 0 : 1;
    }
    cv::Mat labels, boxes, centroids;
    const int n = cv::connectedComponentsWithStats(solid, labels, boxes, centroids, 8, CV_32S);

    WallIndex gt_walls(gt.wall_points_m);
    const double min_cells = params.graph.min_island_size_m / res;
    const double max_cells = p.clutter_max_size_m / res;
    const double reach2 = p.clutter_reach_m * p.clutter_reach_m;
    std::vector<std::vector<cv::Point2f>> clutter;  // each island's cells in the region
    std::vector<cv::Point2f> cells;
    std::vector<Eigen::Vector2d> border;  // its border cells' centres in the map's frame [m]
    for (int k = 1; k < n; ++k)
    {
        const int bx = boxes.at<int>(k, cv::CC_STAT_LEFT), by = boxes.at<int>(k, cv::CC_STAT_TOP);
        const int bw = boxes.at<int>(k, cv::CC_STAT_WIDTH),
                  bh = boxes.at<int>(k, cv::CC_STAT_HEIGHT);
        if (bx == 0 || by == 0 || bx + bw == w || by + bh == h) continue;  // not surrounded
        if (std::max(bw, bh) > max_cells + 1.0) continue;  // wider than its enclosing circle
        cells.clear();
        border.clear();
        for (int y = by; y < by + bh; ++y)
        {
            const int* row = labels.ptr<int>(y);
            for (int x = bx; x < bx + bw; ++x)
            {
                if (row[x] != k) continue;
                cells.emplace_back(static_cast<float>(x), static_cast<float>(y));
                // A border cell has a free 4-neighbour (the island touches no edge).
                if (labels.at<int>(y - 1, x) != k || labels.at<int>(y + 1, x) != k ||
                    labels.at<int>(y, x - 1) != k || labels.at<int>(y, x + 1) != k)
                    border.emplace_back(map_grid.idx2x(x0 + x), map_grid.idx2y(y0 + y));
            }
        }
        cv::Point2f centre;
        const double size = islandWidthCells(cells, &centre);
        // Smaller ones are the graph builder's to remove (min_island_size_m).
        if (size < min_cells || size > max_cells) continue;
        const Eigen::Vector2d c(map_grid.idx2x(x0 + static_cast<int>(std::lround(centre.x))),
                                map_grid.idx2y(y0 + static_cast<int>(std::lround(centre.y))));
        std::vector<Eigen::Vector2d> local_gt, local_map;
        for (std::size_t i = 0; i < matched.size(); ++i)
            if ((matched[i] - c).squaredNorm() <= reach2)
                local_gt.push_back(matched_gt[i]), local_map.push_back(matched[i]);
        if (local_map.empty()) continue;
        // Structure the ground truth has (a column, a free-standing wall) lies on its walls
        // under one of the alignments; a bent map is rigid only locally, so the fit of the
        // pairs within reach is asked too.
        ++judged;
        std::vector<Transform2D> island_alignments = alignments;
        if (local_map.size() >= 3) island_alignments.push_back(hornAlign(local_gt, local_map));
        bool in_gt = false;
        for (const auto& t : island_alignments)
        {
            std::size_t on = 0;
            for (const auto& b : border)
                on += gt_walls.near(t.apply(b), p.clutter_wall_tolerance_m);
            if (double(on) >= p.clutter_min_wall_share * double(border.size()))
            {
                in_gt = true;
                break;
            }
        }
        if (!in_gt) clutter.push_back(cells);
    }
    if (clutter.empty()) return std::nullopt;
    mrpt::maps::COccupancyGridMap2D out = map_grid;
    for (const auto& island : clutter)
        for (const auto& q : island)  // P(free) = 1
            out.setCell(x0 + static_cast<int>(q.x), y0 + static_cast<int>(q.y), 1.0f);
    removed = clutter.size();
    return out;
}

}  // namespace mrpt_topoeval::internal
