/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The picture of a match (paper Fig. 5 and 7): both maps side by side, match lines between them.

#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/errors.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "drawing/graph_drawing.h"
#include "graph/MatchView.h"

namespace mrpt_topoeval
{
namespace
{
using internal::kGrowingLine;
using internal::kIsomorphismLine;
using internal::kMissingRing;
using internal::kShift;
using internal::kSubPixel;
using internal::MatchPanel;
using Grid = mrpt::maps::COccupancyGridMap2D;

// Limits that keep the picture viewable and its PNG small (the issue asks for ~4000 px).
constexpr double kMaxWidthPx = 4000.0;
constexpr double kMaxMapHeightPx = 4000.0;
constexpr int kMarginPx = 6;
constexpr int kGapPx = 24;  // between the two maps, so lines leaving the left map stay visible
constexpr int kTitleHeightPx = 24;
constexpr double kTitleFontScale = 0.5;

/** Rows and columns of a grid, at least 1 each, so ratios are defined for empty grids. */
double rowsOf(const Grid& g) { return std::max<double>(1.0, static_cast<double>(g.getSizeY())); }
double colsOf(const Grid& g) { return std::max<double>(1.0, static_cast<double>(g.getSizeX())); }

/** `text` shortened from the left ("...tail") until it fits `max_width_px`. */
std::string fitText(const std::string& text, int max_width_px)
{
    const auto width = [](const std::string& t)
    {
        int base = 0;
        return cv::getTextSize(t, cv::FONT_HERSHEY_SIMPLEX, kTitleFontScale, 1, &base).width;
    };
    if (width(text) <= max_width_px) return text;
    for (std::size_t cut = 1; cut < text.size(); ++cut)
    {
        const std::string t = "..." + text.substr(cut);
        if (width(t) <= max_width_px) return t;
    }
    return "";
}

std::string title(const char* role, const std::string& file)
{
    // The file name alone: the folders rarely tell two maps apart and cost the most width.
    const std::string name = std::filesystem::path(file).filename().string();
    return name.empty() ? std::string(role) : std::string(role) + ": " + name;
}

void checkPairs(const TopologyGraph& gt, const TopologyGraph& map, const GraphMatch& match,
                const char* caller)
{
    for (std::size_t i = 0; i < match.pairs.size(); ++i)
    {
        const VertexPair& p = match.pairs[i];
        const auto bad = [&](const char* side, int id, std::size_t n)
        {
            throw InputError(std::string(caller) + ": pair " + std::to_string(i) + " names " +
                             side + " vertex " + std::to_string(id) + ", but that graph has " +
                             std::to_string(n) + " vertices");
        };
        if (p.ground_truth < 0 || static_cast<std::size_t>(p.ground_truth) >= gt.vertices.size())
            bad("ground-truth", p.ground_truth, gt.vertices.size());
        if (p.map < 0 || static_cast<std::size_t>(p.map) >= map.vertices.size())
            bad("map", p.map, map.vertices.size());
    }
}
}  // namespace

namespace internal
{
cv::Point MatchPanel::fixedPoint(const Eigen::Vector2d& p) const
{
    const cv::Point2d q = px.toPixel(p);
    return {static_cast<int>(std::lround((q.x + origin.x) * kSubPixel)),
            static_cast<int>(std::lround((q.y + origin.y) * kSubPixel))};
}

cv::Point MatchPanel::point(const Eigen::Vector2d& p) const
{
    const cv::Point2d q = px.toPixel(p);
    return {static_cast<int>(std::lround(q.x)) + origin.x,
            static_cast<int>(std::lround(q.y)) + origin.y};
}

MatchPicture drawMatchPicture(const Grid& gt_grid, const TopologyGraph& gt, const Grid& map_grid,
                              const TopologyGraph& map, const GraphMatch& match,
                              const DrawOptions& opts, const char* caller)
{
    if (opts.scale < 1 || opts.scale > 8)
        throw InputError("DrawOptions::scale = " + std::to_string(opts.scale) +
                         " violates 1 <= scale <= 8");
    checkPairs(gt, map, match, caller);

    // Common height (paper Fig. 5: both maps equally tall): `scale` pixels per cell of the
    // taller map, reduced until both maps side by side fit the width limit.
    const double widths_per_height =
        colsOf(gt_grid) / rowsOf(gt_grid) + colsOf(map_grid) / rowsOf(map_grid);
    double height = opts.scale * std::max(rowsOf(gt_grid), rowsOf(map_grid));
    height = std::min(height, kMaxMapHeightPx);
    height = std::min(height, (kMaxWidthPx - 2 * kMarginPx - kGapPx) / widths_per_height);
    height = std::max(height, 1.0);  // absurdly wide maps: 1 pixel high rather than nothing

    std::vector<cv::Mat> images;
    std::vector<MatchPanel> panels;
    for (const auto& [grid, graph] :
         {std::pair<const Grid*, const TopologyGraph*>{&gt_grid, &gt},
          std::pair<const Grid*, const TopologyGraph*>{&map_grid, &map}})
    {
        const double px_per_cell = height / rowsOf(*grid);
        images.push_back(
            drawGraphOverGrid(*grid, *graph, px_per_cell, opts.draw_ids, opts.draw_boundary));
        panels.push_back({{},
                          images.back().size(),
                          PixelMapper(*grid, px_per_cell),
                          GraphStyle::forScale(px_per_cell)});
    }
    MatchPanel& left = panels[0];
    MatchPanel& right = panels[1];
    left.origin = {kMarginPx, kTitleHeightPx};
    right.origin = {kMarginPx + left.size.width + kGapPx, kTitleHeightPx};

    const int width = right.origin.x + right.size.width + kMarginPx;
    const int maps_height = std::max(left.size.height, right.size.height);
    cv::Mat canvas(kTitleHeightPx + maps_height, width, CV_8UC3, kWhite);
    for (std::size_t i = 0; i < panels.size(); ++i)
        images[i].copyTo(canvas(cv::Rect(panels[i].origin, panels[i].size)));

    // Titles above each map; the left one may use the gap too.
    const int baseline_y = kTitleHeightPx - 7;
    cv::putText(canvas, fitText(title("ground truth", gt.map.file), left.size.width + kGapPx - 4),
                {left.origin.x, baseline_y}, cv::FONT_HERSHEY_SIMPLEX, kTitleFontScale, kTextColour,
                1, cv::LINE_AA);
    cv::putText(canvas, fitText(title("map", map.map.file), right.size.width),
                {right.origin.x, baseline_y}, cv::FONT_HERSHEY_SIMPLEX, kTitleFontScale,
                kTextColour, 1, cv::LINE_AA);

    // Unmatched ground-truth vertices the matcher tried to match (those "missing" counts:
    // non-spurious, with a non-spurious edge): a ring just outside the vertex mark.
    const MatchView gt_view = makeMatchView(gt);
    std::vector<bool> matched(gt.vertices.size(), false);
    for (const VertexPair& p : match.pairs)
        matched[static_cast<std::size_t>(p.ground_truth)] = true;
    const int ring_radius = (left.style.vertex_radius_px + 3) << kShift;
    for (std::size_t i = 0; i < gt.vertices.size(); ++i)
        if (gt_view.v[i].active && !matched[i])
            cv::circle(canvas, left.fixedPoint(gt.vertices[i].position_m), ring_radius,
                       kMissingRing, 2, cv::LINE_AA, kShift);

    // Match lines, isomorphism first so the rarer neighbour-growing lines stay on top.
    for (const MatchStage stage :
         {MatchStage::Isomorphism, MatchStage::NeighbourGrowing, MatchStage::Walls})
        for (const VertexPair& p : match.pairs)
        {
            if (p.stage != stage) continue;
            const Eigen::Vector2d& a =
                gt.vertices[static_cast<std::size_t>(p.ground_truth)].position_m;
            const Eigen::Vector2d& b = map.vertices[static_cast<std::size_t>(p.map)].position_m;
            cv::line(canvas, left.fixedPoint(a), right.fixedPoint(b),
                     stage == MatchStage::Isomorphism ? kIsomorphismLine
                     : stage == MatchStage::Walls     ? internal::kWallsLine
                                                      : kGrowingLine,
                     2, cv::LINE_AA, kShift);
        }
    return {canvas, left, right};
}

std::vector<LegendEntry> matchLegendEntries(const GraphMatch& match)
{
    using Mark = LegendEntry::Mark;
    std::vector<LegendEntry> out = {
        {"isomorphism: " + std::to_string(match.isomorphism), kIsomorphismLine, Mark::Line},
        {"neighbour growing: " + std::to_string(match.neighbour_growing), kGrowingLine,
         Mark::Line}};
    if (const std::size_t n = match.byWalls(); n > 0)
        out.push_back({"placed by walls: " + std::to_string(n), internal::kWallsLine, Mark::Line});
    out.push_back({"missing: " + std::to_string(match.missing), kMissingRing, Mark::Ring});
    return out;
}
}  // namespace internal

mrpt::img::CImage drawMatch(const Grid& gt_grid, const TopologyGraph& gt, const Grid& map_grid,
                            const TopologyGraph& map, const GraphMatch& match,
                            const DrawOptions& opts)
{
    const internal::MatchPicture pic =
        internal::drawMatchPicture(gt_grid, gt, map_grid, map, match, opts, "drawMatch");
    // The counts of the paper's Table II on their own row, the graphs' colours below.
    const cv::Mat out = internal::stackVertically(
        {pic.canvas, internal::drawLegend(pic.canvas.cols, internal::matchLegendEntries(match)),
         internal::drawLegend(pic.canvas.cols, internal::graphLegendEntries(opts.draw_boundary))});
    return mrpt::img::CImage(out, mrpt::img::SHALLOW_COPY);
}

}  // namespace mrpt_topoeval
