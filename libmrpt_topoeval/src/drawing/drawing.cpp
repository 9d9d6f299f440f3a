/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/graph/build_graph.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "drawing/graph_drawing.h"

namespace mrpt_topoeval
{
namespace internal
{
namespace
{
constexpr std::uint8_t kGreyOccupied = 0;
constexpr std::uint8_t kGreyFree = 255;
constexpr std::uint8_t kGreyUnknown = 150;

const cv::Scalar& vertexColour(const TopoVertex& v)
{
    if (v.spurious) return kSpuriousColour;
    switch (v.degree())
    {
        case 0:
            return kVertexDeg0Colour;
        case 1:
            return kVertexDeg1Colour;
        case 2:
            return kVertexDeg2Colour;
        case 3:
            return kVertexDeg3Colour;
        default:
            return kVertexDeg4PlusColour;
    }
}

void drawPolyline(cv::Mat& img, const PixelMapper& px, const std::vector<Eigen::Vector2d>& pts,
                  bool closed, const cv::Scalar& colour, int thickness)
{
    if (pts.size() < 2) return;
    std::vector<cv::Point> line;
    line.reserve(pts.size());
    for (const auto& p : pts) line.push_back(px.fixedPoint(p));
    cv::polylines(img, line, closed, colour, thickness, cv::LINE_AA, kShift);
}
}  // namespace

cv::Mat renderGrid(const mrpt::maps::COccupancyGridMap2D& grid)
{
    using Grid = mrpt::maps::COccupancyGridMap2D;
    const GraphBuilderParameters thresholds;
    std::array<std::uint8_t, 256> lut{};
    for (int l = -128; l <= 127; ++l)
    {
        const double p_occ = 1.0 - Grid::l2p(static_cast<Grid::cellType>(l));
        lut[static_cast<std::uint8_t>(l)] = p_occ >= thresholds.occupied_min_prob ? kGreyOccupied
                                            : p_occ <= thresholds.free_max_prob   ? kGreyFree
                                                                                  : kGreyUnknown;
    }
    const int w = static_cast<int>(grid.getSizeX());
    const int h = static_cast<int>(grid.getSizeY());
    const auto& raw = grid.getRawMap();
    cv::Mat img(h, w, CV_8UC1);
    for (int cy = 0; cy < h; ++cy)
    {
        std::uint8_t* row = img.ptr<std::uint8_t>(h - 1 - cy);
        const auto* cells = raw.data() + static_cast<std::size_t>(cy) * w;
        for (int cx = 0; cx < w; ++cx) row[cx] = lut[static_cast<std::uint8_t>(cells[cx])];
    }
    return img;
}

PixelMapper::PixelMapper(const mrpt::maps::COccupancyGridMap2D& grid, double px_per_cell)
    : m_x_min(grid.getXMin()),
      m_y_max(grid.getYMax()),
      m_px_per_m(px_per_cell / static_cast<double>(grid.getResolution()))
{
}

cv::Point2d PixelMapper::toPixel(const Eigen::Vector2d& p) const
{
    return {(p.x() - m_x_min) * m_px_per_m - 0.5, (m_y_max - p.y()) * m_px_per_m - 0.5};
}

cv::Point PixelMapper::fixedPoint(const Eigen::Vector2d& p) const
{
    const cv::Point2d q = toPixel(p);
    return {static_cast<int>(std::lround(q.x * kSubPixel)),
            static_cast<int>(std::lround(q.y * kSubPixel))};
}

GraphStyle GraphStyle::forScale(double px_per_cell)
{
    GraphStyle s;
    // Marks grow with the scale but stay legible when a big map is drawn small.
    s.vertex_radius_px = std::max(3, static_cast<int>(std::lround(2.0 * px_per_cell)));
    s.edge_thickness_px = px_per_cell >= 3.0 ? 2 : 1;
    s.id_font_scale = 0.3 + 0.05 * std::clamp(px_per_cell, 1.0, 8.0);
    return s;
}

cv::Size pictureSize(const mrpt::maps::COccupancyGridMap2D& grid, double px_per_cell)
{
    const auto side = [&](std::size_t cells)
    { return std::max(1L, std::lround(static_cast<double>(cells) * px_per_cell)); };
    return {static_cast<int>(side(grid.getSizeX())), static_cast<int>(side(grid.getSizeY()))};
}

cv::Mat drawGraphOverGrid(const mrpt::maps::COccupancyGridMap2D& grid, const TopologyGraph& graph,
                          double px_per_cell, bool draw_ids, bool draw_boundary)
{
    const double w_px = std::round(static_cast<double>(grid.getSizeX()) * px_per_cell);
    const double h_px = std::round(static_cast<double>(grid.getSizeY()) * px_per_cell);
    if (w_px * h_px > kMaxPixels)
        throw InputError("a picture of " + std::to_string(static_cast<long long>(w_px)) + " x " +
                         std::to_string(static_cast<long long>(h_px)) +
                         " pixels is too large; use a smaller drawing scale");

    cv::Mat img;
    if (grid.getSizeX() > 0 && grid.getSizeY() > 0)
    {
        // Nearest neighbour keeps cells crisp when enlarging; area averaging keeps one-cell
        // walls visible (grey) when shrinking a big map.
        const int interpolation = px_per_cell >= 1.0 ? cv::INTER_NEAREST : cv::INTER_AREA;
        cv::Mat grey;
        cv::resize(renderGrid(grid), grey, pictureSize(grid, px_per_cell), 0, 0, interpolation);
        cv::cvtColor(grey, img, cv::COLOR_GRAY2BGR);
    }
    else
        img = cv::Mat(1, 1, CV_8UC3, kWhite);

    const PixelMapper px(grid, px_per_cell);
    const GraphStyle style = GraphStyle::forScale(px_per_cell);

    if (draw_boundary) drawPolyline(img, px, graph.outer_boundary_m, true, kBoundaryColour, 1);

    // Normal edges first, then dead ends, then spurious ones, so the rarer classes stay
    // visible where edges overlap.
    for (int pass = 0; pass < 3; ++pass)
        for (const TopoEdge& e : graph.edges)
        {
            const int cls = e.spurious ? 2 : e.dead_end ? 1 : 0;
            if (cls != pass) continue;
            const cv::Scalar& colour = cls == 2   ? kSpuriousColour
                                       : cls == 1 ? kDeadEndEdgeColour
                                                  : kEdgeColour;
            drawPolyline(img, px, e.path_m, false, colour, style.edge_thickness_px);
        }

    for (const TopoVertex& v : graph.vertices)
    {
        const cv::Point c = px.fixedPoint(v.position_m);
        const int r = style.vertex_radius_px << kShift;
        cv::circle(img, c, r, vertexColour(v), cv::FILLED, cv::LINE_AA, kShift);
        cv::circle(img, c, r, kOutlineColour, 1, cv::LINE_AA, kShift);
    }

    if (draw_ids)
        for (const TopoVertex& v : graph.vertices)
        {
            const cv::Point2d c = px.toPixel(v.position_m);
            const cv::Point at(static_cast<int>(std::lround(c.x)) + style.vertex_radius_px + 1,
                               static_cast<int>(std::lround(c.y)) - style.vertex_radius_px - 1);
            cv::putText(img, std::to_string(v.id), at, cv::FONT_HERSHEY_SIMPLEX,
                        style.id_font_scale, kIdTextColour, 1, cv::LINE_AA);
        }
    return img;
}

std::vector<LegendEntry> graphLegendEntries(bool with_boundary)
{
    using Mark = LegendEntry::Mark;
    std::vector<LegendEntry> entries = {{"edge", kEdgeColour, Mark::Line},
                                        {"dead-end edge", kDeadEndEdgeColour, Mark::Line},
                                        {"spurious", kSpuriousColour, Mark::Line},
                                        {"degree 1", kVertexDeg1Colour, Mark::Dot},
                                        {"degree 2", kVertexDeg2Colour, Mark::Dot},
                                        {"degree 3", kVertexDeg3Colour, Mark::Dot},
                                        {"degree 4+", kVertexDeg4PlusColour, Mark::Dot}};
    if (with_boundary) entries.push_back({"outer boundary", kBoundaryColour, Mark::Line});
    return entries;
}

cv::Mat drawLegend(int width, const std::vector<LegendEntry>& entries)
{
    const int font = cv::FONT_HERSHEY_SIMPLEX;
    const double font_scale = 0.4;
    const int row_h = 16, sample_w = 18, gap = 12, margin = 6;
    // Lay out entries left to right, wrapping to a new row when the picture is narrow.
    std::vector<cv::Point> at;
    int x = margin, y = 0, widest = 0;
    for (const auto& e : entries)
    {
        int base = 0;
        const int w = sample_w + 4 + cv::getTextSize(e.label, font, font_scale, 1, &base).width;
        if (x > margin && x + w > width - margin)
        {
            x = margin;
            ++y;
        }
        at.emplace_back(x, y);
        x += w + gap;
        widest = std::max(widest, x);
    }
    cv::Mat legend(margin + (y + 1) * row_h, std::max(width, widest), CV_8UC3, kWhite);
    for (std::size_t i = 0; i < entries.size(); ++i)
    {
        const LegendEntry& e = entries[i];
        const int cx = at[i].x, cy = margin / 2 + at[i].y * row_h + row_h / 2;
        switch (e.mark)
        {
            case LegendEntry::Mark::Line:
                cv::line(legend, {cx, cy}, {cx + sample_w, cy}, e.colour, 2, cv::LINE_AA);
                break;
            case LegendEntry::Mark::Dot:
                cv::circle(legend, {cx + sample_w / 2, cy}, 5, e.colour, cv::FILLED, cv::LINE_AA);
                cv::circle(legend, {cx + sample_w / 2, cy}, 5, kOutlineColour, 1, cv::LINE_AA);
                break;
            case LegendEntry::Mark::Ring:
                cv::circle(legend, {cx + sample_w / 2, cy}, 6, e.colour, 2, cv::LINE_AA);
                break;
        }
        cv::putText(legend, e.label, {cx + sample_w + 4, cy + 4}, font, font_scale, kTextColour, 1,
                    cv::LINE_AA);
    }
    return legend;
}

cv::Mat stackVertically(const std::vector<cv::Mat>& parts)
{
    int rows = 0, cols = 0;
    for (const cv::Mat& p : parts)
    {
        rows += p.rows;
        cols = std::max(cols, p.cols);
    }
    cv::Mat out(std::max(rows, 1), std::max(cols, 1), CV_8UC3, kWhite);
    int y = 0;
    for (const cv::Mat& p : parts)
    {
        if (p.empty()) continue;
        p.copyTo(out(cv::Rect(0, y, p.cols, p.rows)));
        y += p.rows;
    }
    return out;
}
}  // namespace internal

mrpt::img::CImage drawTopologyGraph(const mrpt::maps::COccupancyGridMap2D& grid,
                                    const TopologyGraph& graph, const DrawOptions& opts)
{
    if (opts.scale < 1 || opts.scale > 8)
        throw InputError("DrawOptions::scale = " + std::to_string(opts.scale) +
                         " violates 1 <= scale <= 8");
    const cv::Mat img =
        internal::drawGraphOverGrid(grid, graph, opts.scale, opts.draw_ids, opts.draw_boundary);
    // The legend sits below the map: it never hides part of the graph.
    const cv::Mat out = internal::stackVertically(
        {img, internal::drawLegend(img.cols, internal::graphLegendEntries(opts.draw_boundary))});
    return mrpt::img::CImage(out, mrpt::img::SHALLOW_COPY);
}

}  // namespace mrpt_topoeval
