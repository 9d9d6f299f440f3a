/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// What every picture shares (drawTopologyGraph(), drawMatch(), drawQualityReport()): colours,
// the world-to-pixel mapping, a grid with its Topology Graph drawn over it, legend strips, and
// the side-by-side layout of a match. OpenCV stays here, out of the public headers.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/drawing.h>

#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace mrpt_topoeval::internal
{
// Colours in OpenCV's BGR order. Edges and dead ends follow the paper's Fig. 1 and 3
// (turquoise marks the spurious parts).
inline const cv::Scalar kEdgeColour(200, 90, 20);             // blue
inline const cv::Scalar kDeadEndEdgeColour(0, 140, 255);      // orange
inline const cv::Scalar kSpuriousColour(208, 224, 64);        // turquoise
inline const cv::Scalar kBoundaryColour(0, 170, 0);           // green
inline const cv::Scalar kVertexDeg1Colour(0, 110, 230);       // dark orange
inline const cv::Scalar kVertexDeg2Colour(60, 160, 60);       // green
inline const cv::Scalar kVertexDeg3Colour(40, 40, 220);       // red
inline const cv::Scalar kVertexDeg4PlusColour(170, 40, 150);  // purple
inline const cv::Scalar kVertexDeg0Colour(128, 128, 128);
inline const cv::Scalar kOutlineColour(0, 0, 0);
inline const cv::Scalar kIdTextColour(110, 30, 0);  // dark blue
inline const cv::Scalar kTextColour(0, 0, 0);
inline const cv::Scalar kWhite(255, 255, 255);

// Sub-pixel precision of OpenCV's drawing calls (coordinates in 1/16 pixel).
constexpr int kShift = 4;
constexpr double kSubPixel = 1 << kShift;

// Pictures beyond this are refused: 2^28 pixels are already ~800 MB of BGR.
constexpr double kMaxPixels = 268435456.0;

/** World [m] -> pixel of the grid drawn `px_per_cell` pixels per cell; row 0 is the map's max
 * y. Pixel centres sit at integer coordinates, hence the half-pixel offset. */
class PixelMapper
{
public:
    PixelMapper(const mrpt::maps::COccupancyGridMap2D& grid, double px_per_cell);
    cv::Point2d toPixel(const Eigen::Vector2d& p) const;
    /** toPixel() in OpenCV's fixed point (kShift fractional bits). */
    cv::Point fixedPoint(const Eigen::Vector2d& p) const;

private:
    double m_x_min, m_y_max, m_px_per_m;
};

/** Sizes of the graph's marks for a drawing scale, so pictures of any scale read alike. */
struct GraphStyle
{
    int vertex_radius_px = 3;
    int edge_thickness_px = 1;
    double id_font_scale = 0.4;

    static GraphStyle forScale(double px_per_cell);
};

/** A grid's picture size at `px_per_cell`: round(cells x scale), at least 1 x 1. */
cv::Size pictureSize(const mrpt::maps::COccupancyGridMap2D& grid, double px_per_cell);

/** The grid (occupied black, free white, unknown grey, by the graph builder's default
 * thresholds) at `px_per_cell` pixels per cell, and the graph over it as in the paper's Fig. 1
 * and 4. Scales below 1 average cells, so thin walls stay visible as grey.
 * \throws InputError if the picture would exceed kMaxPixels. */
cv::Mat drawGraphOverGrid(const mrpt::maps::COccupancyGridMap2D& grid, const TopologyGraph& graph,
                          double px_per_cell, bool draw_ids, bool draw_boundary);

/** The grid as grey classes, one pixel per cell, top row = max y (8-bit grey: occupied 0,
 * free 255, unknown 150). Occupied and free use the graph builder's default probability
 * thresholds, so the picture shows what it works on. */
cv::Mat renderGrid(const mrpt::maps::COccupancyGridMap2D& grid);

/** One entry of a legend strip: a sample mark and its label. */
struct LegendEntry
{
    enum class Mark
    {
        Line,  //!< a short thick line (edges, match lines)
        Dot,   //!< a filled, outlined circle (vertices)
        Ring   //!< an open circle (unmatched vertices)
    };
    std::string label;
    cv::Scalar colour;
    Mark mark = Mark::Line;
};

/** The entries explaining drawGraphOverGrid()'s colours. */
std::vector<LegendEntry> graphLegendEntries(bool with_boundary);

/** A white strip with the entries laid out left to right, wrapping into rows to fit `width`
 * (wider only if a single entry does not fit). */
cv::Mat drawLegend(int width, const std::vector<LegendEntry>& entries);

/** `parts` one below the other, left-aligned on white, as wide as the widest. */
cv::Mat stackVertically(const std::vector<cv::Mat>& parts);

// ---- Match pictures (drawMatch(), drawQualityReport(); draw_match.cpp)

// As in the paper's Fig. 7: green for the isomorphism's matches, red for neighbour growing.
inline const cv::Scalar kIsomorphismLine(0, 190, 0);
inline const cv::Scalar kGrowingLine(0, 0, 235);
// Ours: the pairs of a map placed by its walls (QualityParameters::map_by_walls), teal.
inline const cv::Scalar kWallsLine(128, 128, 0);
inline const cv::Scalar kMissingRing(200, 0, 200);  // magenta: no graph colour uses it

// Brokenness groups (drawQualityReport() and the HTML report): distinct from the match lines
// (green, red), the missing ring (magenta), grey (no group) and white (unmatched); group 0, the
// largest, is blue. Colours repeat after 10 groups.
inline const std::array<cv::Scalar, 10> kGroupColours = {
    cv::Scalar(180, 119, 31),   // blue
    cv::Scalar(14, 127, 255),   // orange
    cv::Scalar(189, 103, 148),  // purple
    cv::Scalar(207, 190, 23),   // cyan
    cv::Scalar(75, 86, 140),    // brown
    cv::Scalar(0, 200, 230),    // yellow
    cv::Scalar(191, 129, 247),  // pink
    cv::Scalar(140, 30, 20),    // navy
    cv::Scalar(128, 128, 0),    // teal
    cv::Scalar(0, 128, 128),    // olive
};
inline const cv::Scalar kNoGroupColour(160, 160, 160);
// The map's walls that no matched part explains (drawQualityReport()): bright red dots on the
// walls, apart from the thin red lines of neighbour growing.
inline const cv::Scalar kUnexplainedWallColour(0, 0, 255);
inline const cv::Scalar kUnmatchedColour(255, 255, 255);

/** One of the two maps of a match picture: where it sits and how to find its vertices. */
struct MatchPanel
{
    cv::Point origin;  //!< Top-left corner in the whole picture.
    cv::Size size;     //!< Of the map's picture.
    PixelMapper px;
    GraphStyle style;

    /** toPixel() in the whole picture, in OpenCV's fixed point (kShift fractional bits). */
    cv::Point fixedPoint(const Eigen::Vector2d& p) const;
    /** toPixel() in the whole picture, rounded to whole pixels. */
    cv::Point point(const Eigen::Vector2d& p) const;
};

/** The ground-truth map (left) and the robot map (right) side by side with their graphs and
 * titles, rings around the ground-truth vertices GraphMatch::missing counts, and a line per
 * matched pair: what drawMatch() and drawQualityReport() share. */
struct MatchPicture
{
    cv::Mat canvas;
    MatchPanel ground_truth, map;
};

/** Draws the MatchPicture (layout and limits as documented at drawMatch()).
 * \throws InputError if `opts.scale` is outside 1..8 or a pair names a vertex that is not in
 * its graph; `caller` starts the message. */
MatchPicture drawMatchPicture(const mrpt::maps::COccupancyGridMap2D& gt_grid,
                              const TopologyGraph& gt,
                              const mrpt::maps::COccupancyGridMap2D& map_grid,
                              const TopologyGraph& map, const GraphMatch& match,
                              const DrawOptions& opts, const char* caller);

/** The legend entries of the match lines and rings, with the counts of the paper's Table II. */
std::vector<LegendEntry> matchLegendEntries(const GraphMatch& match);

}  // namespace mrpt_topoeval::internal
