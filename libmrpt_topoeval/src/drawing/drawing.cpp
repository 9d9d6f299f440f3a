/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt_topoeval/GraphBuilder.h>
#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/errors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

namespace mrpt_topoeval
{
namespace
{
// Colours in OpenCV's BGR order. Edges and dead ends follow the paper's Fig. 1 and 3
// (turquoise marks the spurious parts).
const cv::Scalar kEdge(200, 90, 20);             // blue
const cv::Scalar kDeadEndEdge(0, 140, 255);      // orange
const cv::Scalar kSpurious(208, 224, 64);        // turquoise
const cv::Scalar kBoundary(0, 170, 0);           // green
const cv::Scalar kVertexDeg1(0, 110, 230);       // dark orange
const cv::Scalar kVertexDeg2(60, 160, 60);       // green
const cv::Scalar kVertexDeg3(40, 40, 220);       // red
const cv::Scalar kVertexDeg4Plus(170, 40, 150);  // purple
const cv::Scalar kVertexDeg0(128, 128, 128);
const cv::Scalar kOutline(0, 0, 0);
const cv::Scalar kIdText(110, 30, 0);  // dark blue
const cv::Scalar kLegendText(0, 0, 0);

constexpr std::uint8_t kGreyOccupied = 0;
constexpr std::uint8_t kGreyFree = 255;
constexpr std::uint8_t kGreyUnknown = 150;

// Sub-pixel precision of OpenCV's drawing calls (coordinates in 1/16 pixel).
constexpr int kShift = 4;
constexpr double kSubPixel = 1 << kShift;

// Pictures beyond this are refused: 2^28 pixels are already ~800 MB of BGR.
constexpr double kMaxPixels = 268435456.0;

const cv::Scalar& vertexColour(const TopoVertex& v)
{
    if (v.spurious) return kSpurious;
    switch (v.degree())
    {
        case 0:
            return kVertexDeg0;
        case 1:
            return kVertexDeg1;
        case 2:
            return kVertexDeg2;
        case 3:
            return kVertexDeg3;
        default:
            return kVertexDeg4Plus;
    }
}

/** World [m] -> fixed-point pixel of the scaled picture; row 0 is the map's max y. Pixel
 * centres sit at integer coordinates, hence the half-pixel offset. */
class PixelMapper
{
public:
    PixelMapper(const mrpt::maps::COccupancyGridMap2D& grid, int scale)
        : m_x_min(grid.getXMin()),
          m_y_max(grid.getYMax()),
          m_px_per_m(scale / static_cast<double>(grid.getResolution()))
    {
    }
    cv::Point2d toPixel(const Eigen::Vector2d& p) const
    {
        return {(p.x() - m_x_min) * m_px_per_m - 0.5, (m_y_max - p.y()) * m_px_per_m - 0.5};
    }
    cv::Point fixedPoint(const Eigen::Vector2d& p) const
    {
        const cv::Point2d q = toPixel(p);
        return {static_cast<int>(std::lround(q.x * kSubPixel)),
                static_cast<int>(std::lround(q.y * kSubPixel))};
    }

private:
    double m_x_min, m_y_max, m_px_per_m;
};

/** The grid as grey classes, one pixel per cell, top row = max y. Occupied and free use the
 * graph builder's default probability thresholds, so the picture shows what it works on. */
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

void drawPolyline(cv::Mat& img, const PixelMapper& px, const std::vector<Eigen::Vector2d>& pts,
                  bool closed, const cv::Scalar& colour, int thickness)
{
    if (pts.size() < 2) return;
    std::vector<cv::Point> line;
    line.reserve(pts.size());
    for (const auto& p : pts) line.push_back(px.fixedPoint(p));
    cv::polylines(img, line, closed, colour, thickness, cv::LINE_AA, kShift);
}

/** One row of legend entries below the map (it never hides part of the graph). */
cv::Mat drawLegend(int width, bool with_boundary)
{
    struct Entry
    {
        std::string label;
        cv::Scalar colour;
        bool is_line;
    };
    std::vector<Entry> entries = {{"edge", kEdge, true},
                                  {"dead-end edge", kDeadEndEdge, true},
                                  {"spurious", kSpurious, true},
                                  {"degree 1", kVertexDeg1, false},
                                  {"degree 2", kVertexDeg2, false},
                                  {"degree 3", kVertexDeg3, false},
                                  {"degree 4+", kVertexDeg4Plus, false}};
    if (with_boundary) entries.push_back({"outer boundary", kBoundary, true});

    const int font = cv::FONT_HERSHEY_SIMPLEX;
    const double font_scale = 0.4;
    const int row_h = 16, sample_w = 18, gap = 12, margin = 6;
    // Lay out entries left to right, wrapping to a new row when the map is narrow.
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
    cv::Mat legend(margin + (y + 1) * row_h, std::max(width, widest), CV_8UC3,
                   cv::Scalar(255, 255, 255));
    for (std::size_t i = 0; i < entries.size(); ++i)
    {
        const Entry& e = entries[i];
        const int cx = at[i].x, cy = margin / 2 + at[i].y * row_h + row_h / 2;
        if (e.is_line)
            cv::line(legend, {cx, cy}, {cx + sample_w, cy}, e.colour, 2, cv::LINE_AA);
        else
        {
            cv::circle(legend, {cx + sample_w / 2, cy}, 5, e.colour, cv::FILLED, cv::LINE_AA);
            cv::circle(legend, {cx + sample_w / 2, cy}, 5, kOutline, 1, cv::LINE_AA);
        }
        cv::putText(legend, e.label, {cx + sample_w + 4, cy + 4}, font, font_scale, kLegendText, 1,
                    cv::LINE_AA);
    }
    return legend;
}
}  // namespace

mrpt::img::CImage drawTopologyGraph(const mrpt::maps::COccupancyGridMap2D& grid,
                                    const TopologyGraph& graph, const DrawOptions& opts)
{
    if (opts.scale < 1 || opts.scale > 8)
        throw InputError("DrawOptions::scale = " + std::to_string(opts.scale) +
                         " violates 1 <= scale <= 8");
    const int s = opts.scale;
    const int w = static_cast<int>(grid.getSizeX()) * s;
    const int h = static_cast<int>(grid.getSizeY()) * s;
    if (static_cast<double>(w) * h > kMaxPixels)
        throw InputError("a picture of " + std::to_string(w) + " x " + std::to_string(h) +
                         " pixels is too large; use a smaller drawing scale");

    cv::Mat img;
    if (w > 0 && h > 0)
    {
        cv::Mat grey;
        cv::resize(renderGrid(grid), grey, cv::Size(w, h), 0, 0, cv::INTER_NEAREST);
        cv::cvtColor(grey, img, cv::COLOR_GRAY2BGR);
    }
    else
        img = cv::Mat(1, 1, CV_8UC3, cv::Scalar(255, 255, 255));

    const PixelMapper px(grid, s);
    const int edge_thickness = s >= 3 ? 2 : 1;

    if (opts.draw_boundary) drawPolyline(img, px, graph.outer_boundary_m, true, kBoundary, 1);

    // Normal edges first, then dead ends, then spurious ones, so the rarer classes stay
    // visible where edges overlap.
    for (int pass = 0; pass < 3; ++pass)
        for (const TopoEdge& e : graph.edges)
        {
            const int cls = e.spurious ? 2 : e.dead_end ? 1 : 0;
            if (cls != pass) continue;
            const cv::Scalar& colour = cls == 2 ? kSpurious : cls == 1 ? kDeadEndEdge : kEdge;
            drawPolyline(img, px, e.path_m, false, colour, edge_thickness);
        }

    const int radius_px = std::max(3, 2 * s);
    for (const TopoVertex& v : graph.vertices)
    {
        const cv::Point c = px.fixedPoint(v.position_m);
        const int r = radius_px << kShift;
        cv::circle(img, c, r, vertexColour(v), cv::FILLED, cv::LINE_AA, kShift);
        cv::circle(img, c, r, kOutline, 1, cv::LINE_AA, kShift);
    }

    if (opts.draw_ids)
    {
        const double font_scale = 0.3 + 0.05 * s;
        for (const TopoVertex& v : graph.vertices)
        {
            const cv::Point2d c = px.toPixel(v.position_m);
            const cv::Point at(static_cast<int>(std::lround(c.x)) + radius_px + 1,
                               static_cast<int>(std::lround(c.y)) - radius_px - 1);
            cv::putText(img, std::to_string(v.id), at, cv::FONT_HERSHEY_SIMPLEX, font_scale,
                        kIdText, 1, cv::LINE_AA);
        }
    }

    const cv::Mat legend = drawLegend(img.cols, opts.draw_boundary);
    cv::Mat out(img.rows + legend.rows, std::max(img.cols, legend.cols), CV_8UC3,
                cv::Scalar(255, 255, 255));
    img.copyTo(out(cv::Rect(0, 0, img.cols, img.rows)));
    legend.copyTo(out(cv::Rect(0, img.rows, legend.cols, legend.rows)));
    return mrpt::img::CImage(out, mrpt::img::SHALLOW_COPY);
}

}  // namespace mrpt_topoeval
