/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The HTML report (doc/report.md): the page's data as one JSON object embedded in the page, and
// the page around it. The page's script (page/report.js) draws everything from that data, and
// shows every string it holds as a text node: nothing user-controlled is parsed as HTML.

#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/html_report.h>
#include <mrpt_topoeval/json/JsonWriter.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "drawing/graph_drawing.h"
#include "graph/MatchView.h"

namespace mrpt_topoeval
{
namespace internal
{
// The page's script and style (page/report.js, page/report.css), built in by
// cmake/EmbedText.cmake.
extern const char* const kReportScript;
extern const char* const kReportStyle;
}  // namespace internal

namespace
{
using Grid = mrpt::maps::COccupancyGridMap2D;

constexpr double kRadToDeg = 180.0 / M_PI;

std::string base64(const std::vector<unsigned char>& bytes)
{
    static const char* const kAlphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3)
    {
        const std::uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
        for (const int shift : {18, 12, 6, 0}) out += kAlphabet[(v >> shift) & 63];
    }
    if (i + 1 == bytes.size())
    {
        const std::uint32_t v = bytes[i] << 16;
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += "==";
    }
    else if (i + 2 == bytes.size())
    {
        const std::uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8);
        for (const int shift : {18, 12, 6}) out += kAlphabet[(v >> shift) & 63];
        out += '=';
    }
    return out;
}

/** The picture as a `data:` URL of a PNG. */
std::string pngDataUrl(const cv::Mat& img)
{
    std::vector<unsigned char> png;
    // Level 6: the grey maps compress to nearly what 9 gives, in a third of the time.
    if (!cv::imencode(".png", img, png, {cv::IMWRITE_PNG_COMPRESSION, 6}))
        throw OutputError("HTML report: PNG encoding of a " + std::to_string(img.cols) + " x " +
                          std::to_string(img.rows) + " picture failed");
    return "data:image/png;base64," + base64(png);
}

/** The factor fitInto() shrinks a `cols` x `rows` picture by: 1 if it fits in `max_px`. */
double fitScale(int cols, int rows, int max_px)
{
    const int longer = std::max(cols, rows);
    return longer <= max_px || max_px < 1 ? 1.0 : static_cast<double>(max_px) / longer;
}

/** `img` shrunk (area averaging, so thin walls stay visible) to at most `max_px` on its longer
 * side; unchanged if it fits. */
cv::Mat fitInto(const cv::Mat& img, int max_px)
{
    const double s = fitScale(img.cols, img.rows, max_px);
    if (s == 1.0) return img;
    cv::Mat out;
    cv::resize(img, out,
               cv::Size(std::max(1, static_cast<int>(std::lround(img.cols * s))),
                        std::max(1, static_cast<int>(std::lround(img.rows * s)))),
               0, 0, cv::INTER_AREA);
    return out;
}

/** "#rrggbb" of an OpenCV BGR colour. */
std::string hexColour(const cv::Scalar& bgr)
{
    char buf[8];
    std::snprintf(buf, sizeof(buf), "#%02x%02x%02x", static_cast<int>(bgr[2]),
                  static_cast<int>(bgr[1]), static_cast<int>(bgr[0]));
    return buf;
}

/** Converts world [m] to the grid's cell frame: x right, y down, (0, 0) the top-left corner
 * of the top-left cell, one unit per cell (the frame of the map's picture in the page). */
struct CellFrame
{
    double x_min, y_max, inv_res;
    explicit CellFrame(const Grid& g)
        : x_min(g.getXMin()), y_max(g.getYMax()), inv_res(1.0 / g.getResolution())
    {
    }
    double x(const Eigen::Vector2d& p) const { return (p.x() - x_min) * inv_res; }
    double y(const Eigen::Vector2d& p) const { return (y_max - p.y()) * inv_res; }
};

/** The map's walls that no matched part explains (doc/quality.md, "Explained walls"), for the
 * viewer to draw over the map's picture: {"block": k, "cells": [x0, y0, x1, y1, ...]}, the
 * top-left cells (x from the left, y from the top) of the k x k blocks of cells that hold one,
 * k the cells per pixel of the picture (fitScale(), opts.max_map_px): no more than the picture
 * shows, however large the map. Sorted, so the page is deterministic. */
void writeUnexplainedWalls(JsonWriter& w, const Grid& grid, const QualityReport& r, int max_px)
{
    const double s =
        fitScale(static_cast<int>(grid.getSizeX()), static_cast<int>(grid.getSizeY()), max_px);
    const long k = std::max(1L, static_cast<long>(std::ceil(1.0 / s - 1e-9)));
    const CellFrame f(grid);
    std::vector<std::pair<long, long>> blocks;
    for (const Eigen::Vector2f& q : r.explained_walls.unexplained_m)
    {
        const Eigen::Vector2d p = q.cast<double>();
        blocks.emplace_back(static_cast<long>(std::floor(f.y(p))) / k,
                            static_cast<long>(std::floor(f.x(p))) / k);
    }
    std::sort(blocks.begin(), blocks.end());
    blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
    w.beginObject(true);
    w.key("block").value(static_cast<std::int64_t>(k));
    w.key("cells").beginArray(true);
    for (const auto& [by, bx] : blocks)
        w.value(static_cast<std::int64_t>(bx * k)).value(static_cast<std::int64_t>(by * k));
    w.endArray();
    w.endObject();
}

/** An edge's path as SVG path data in cells, one decimal, points closer than half a cell to
 * the last one kept left out (the path's end is always kept). */
std::string svgPath(const CellFrame& f, const std::vector<Eigen::Vector2d>& path)
{
    std::string d;
    double lx = 0.0, ly = 0.0;
    char buf[48];
    for (std::size_t i = 0; i < path.size(); ++i)
    {
        const double x = f.x(path[i]), y = f.y(path[i]);
        const bool ends = i == 0 || i + 1 == path.size();
        if (!ends && std::hypot(x - lx, y - ly) < 0.5) continue;
        std::snprintf(buf, sizeof(buf), "%s%.1f %.1f", i == 0 ? "M" : " L", x, y);
        d += buf;
        lx = x;
        ly = y;
    }
    return d;
}

void writeTransform(JsonWriter& w, const Transform2D& t)
{
    w.beginObject(true);
    w.key("x").value(t.x_m, 4).key("y").value(t.y_m, 4).key("yaw_deg").value(t.yaw_deg, 3);
    w.endObject();
}

void writeStrings(JsonWriter& w, const std::vector<std::string>& strings)
{
    w.beginArray();
    for (const auto& s : strings) w.value(s);
    w.endArray();
}

/** The page's data for a report: scores, groups, pairs (with their errors after the relative
 * and the group alignment) and messages. */
void writeReport(JsonWriter& w, const TopologyGraph& gt, const TopologyGraph& map,
                 const QualityReport& r)
{
    const auto vertexCheck = [](int id, const TopologyGraph& g, const char* side)
    {
        if (id < 0 || static_cast<std::size_t>(id) >= g.vertices.size())
            throw InputError("HTML report: the report names " + std::string(side) + " vertex " +
                             std::to_string(id) + ", but that graph has " +
                             std::to_string(g.vertices.size()) + " vertices");
    };
    std::vector<int> group(gt.vertices.size(), -1);
    for (std::size_t gi = 0; gi < r.brokenness.groups.size(); ++gi)
        for (const int v : r.brokenness.groups[gi].gt_vertices)
        {
            vertexCheck(v, gt, "ground-truth");
            group[static_cast<std::size_t>(v)] = static_cast<int>(gi);
        }

    w.key("quality").value(r.quality, 4);
    w.key("map_scale").value(r.map_scale, 5);
    w.key("coverage").value(r.coverage, 4);
    w.key("explained_walls").beginObject(true);
    w.key("measured").value(r.explained_walls.measured);
    w.key("share").value(r.explained_walls.share, 4);
    w.key("wall_points").value(static_cast<std::uint64_t>(r.explained_walls.wall_points));
    w.key("explained").value(static_cast<std::uint64_t>(r.explained_walls.explained));
    w.key("tolerance_m").value(r.explained_walls.tolerance_m, 3);
    w.endObject();
    w.key("gt_vertices").value(static_cast<std::uint64_t>(r.gt_vertices));
    w.key("map_vertices").value(static_cast<std::uint64_t>(r.map_vertices));
    for (const auto& [name, acc] : {std::make_pair("global_accuracy", &r.global_accuracy),
                                    std::make_pair("relative_accuracy", &r.relative_accuracy)})
    {
        w.key(name).beginObject(true);
        w.key("pairs").value(static_cast<std::uint64_t>(acc->pairs));
        w.key("rmse_m").value(acc->pairs ? acc->rmse_m : NAN, 4);
        w.key("score").value(acc->score, 4);
        w.endObject();
    }
    w.key("transform");
    writeTransform(w, r.relative_accuracy.transform);
    w.key("consistency").beginArray();
    for (const ConsistencyClass& c : r.local_consistency)
    {
        w.beginObject(true);
        w.key("name").value(c.name);
        w.key("min_m")
            .value(c.min_graph_distance_m, 3)
            .key("max_m")
            .value(c.max_graph_distance_m, 3);
        w.key("pairs").value(static_cast<std::uint64_t>(c.pairs));
        w.key("mean_error_m").value(c.pairs ? c.mean_error_m : NAN, 4);
        w.key("score").value(c.score, 4);
        w.endObject();
    }
    w.endArray();
    w.key("consistency_score").value(r.consistencyScore(), 4);
    w.key("brokenness").beginObject();
    w.key("degree").value(r.brokenness.degree);
    w.key("score").value(r.brokenness.score, 4);
    w.key("groups").beginArray();
    for (const BrokennessGroup& g : r.brokenness.groups)
    {
        w.beginObject(true);
        w.key("squared_error_m2").value(g.squared_error_m2, 5);
        w.key("offset_m").value(g.offset_m, 3);
        // A part placed by its walls (brokenness steps 9 and 10), said only where it is one.
        if (g.by_walls) w.key("by_walls").value(true);
        w.key("transform");
        writeTransform(w, g.transform);
        w.key("vertices").beginArray(true);
        for (const int v : g.gt_vertices) w.value(v);
        w.endArray();
        w.endObject();
    }
    w.endArray();
    w.endObject();

    const GraphMatch& m = r.match;
    w.key("match").beginObject();
    w.key("isomorphism").value(static_cast<std::uint64_t>(m.isomorphism));
    w.key("neighbour_growing").value(static_cast<std::uint64_t>(m.neighbour_growing));
    w.key("missing").value(static_cast<std::uint64_t>(m.missing));
    // [gt, map, stage (0 isomorphism, 1 neighbour growing, 2 placed by walls), similarity,
    //  isomorphism (a map placed by its walls: its part), group,
    //  error after the relative alignment [m], error after its group's alignment [m]]
    w.key("pairs").beginArray();
    for (const VertexPair& p : m.pairs)
    {
        vertexCheck(p.ground_truth, gt, "ground-truth");
        vertexCheck(p.map, map, "map");
        const Eigen::Vector2d& a = gt.vertices[static_cast<std::size_t>(p.ground_truth)].position_m;
        const Eigen::Vector2d& b = map.vertices[static_cast<std::size_t>(p.map)].position_m;
        const int g = group[static_cast<std::size_t>(p.ground_truth)];
        w.beginArray(true);
        w.value(p.ground_truth).value(p.map);
        w.value(p.stage == MatchStage::Isomorphism ? 0 : p.stage == MatchStage::Walls ? 2 : 1);
        w.value(p.similarity, 3).value(p.isomorphism).value(g);
        w.value(
            r.relative_accuracy.pairs ? (a - r.relative_accuracy.transform.apply(b)).norm() : NAN,
            3);
        w.value(
            g >= 0
                ? (a - r.brokenness.groups[static_cast<std::size_t>(g)].transform.apply(b)).norm()
                : NAN,
            3);
        w.endArray();
    }
    w.endArray();
    w.endObject();
    w.key("messages");
    writeStrings(w, r.messages);
    w.key("timing_ms").beginObject(true);
    for (const auto& [step, ms] : r.timing_ms) w.key(step).value(ms, 1);
    w.endObject();
}

/** The thumbnail of a rank entry: both maps side by side at a common height, a line per
 * matched pair (green isomorphism, red neighbour growing), each matched vertex in its
 * brokenness group's colour and the map's walls that no matched part explains in bright red,
 * as in drawQualityReport(), without the graphs: at thumbnail size they would hide the maps. */
std::string thumbnail(const Grid& gt_grid, const TopologyGraph& gt, const Grid& grid,
                      const TopologyGraph& map, const QualityReport& r, int max_px)
{
    const auto rows = [](const Grid& g) { return std::max<double>(1.0, g.getSizeY()); };
    const auto cols = [](const Grid& g) { return std::max<double>(1.0, g.getSizeX()); };
    const double gap = 0.05 * max_px;
    // Common height h so that both maps and the gap fit max_px wide and high.
    const double h =
        std::max(8.0, std::min<double>(max_px, (max_px - gap) / (cols(gt_grid) / rows(gt_grid) +
                                                                 cols(grid) / rows(grid))));
    std::vector<cv::Mat> parts;
    std::vector<internal::PixelMapper> px;
    for (const Grid* g : {&gt_grid, &grid})
    {
        const double s = h / rows(*g);
        cv::Mat grey = g->getSizeX() > 0 && g->getSizeY() > 0
                           ? internal::renderGrid(*g)
                           : cv::Mat(1, 1, CV_8UC1, cv::Scalar(255));
        cv::resize(grey, grey, internal::pictureSize(*g, s), 0, 0, cv::INTER_AREA);
        cv::Mat bgr;
        cv::cvtColor(grey, bgr, cv::COLOR_GRAY2BGR);
        parts.push_back(bgr);
        px.emplace_back(*g, s);
    }
    const int x_map = parts[0].cols + static_cast<int>(gap);
    cv::Mat canvas(std::max(parts[0].rows, parts[1].rows), x_map + parts[1].cols, CV_8UC3,
                   internal::kWhite);
    parts[0].copyTo(canvas(cv::Rect(0, 0, parts[0].cols, parts[0].rows)));
    parts[1].copyTo(canvas(cv::Rect(x_map, 0, parts[1].cols, parts[1].rows)));

    std::vector<int> group(gt.vertices.size(), -1);
    for (std::size_t gi = 0; gi < r.brokenness.groups.size(); ++gi)
        for (const int v : r.brokenness.groups[gi].gt_vertices)
            group[static_cast<std::size_t>(v)] = static_cast<int>(gi);
    const auto at = [&](int side, const Eigen::Vector2d& p)
    {
        const cv::Point2d q = px[static_cast<std::size_t>(side)].toPixel(p);
        return cv::Point(static_cast<int>(std::lround((q.x + (side ? x_map : 0)) * 16)),
                         static_cast<int>(std::lround(q.y * 16)));
    };
    // The map's walls that no matched part explains, as in the report's picture.
    for (const Eigen::Vector2f& q : r.explained_walls.unexplained_m)
        cv::circle(canvas, at(1, q.cast<double>()), 16, internal::kUnexplainedWallColour,
                   cv::FILLED, cv::LINE_8, 4);
    for (const VertexPair& p : r.match.pairs)
        cv::line(canvas, at(0, gt.vertices[static_cast<std::size_t>(p.ground_truth)].position_m),
                 at(1, map.vertices[static_cast<std::size_t>(p.map)].position_m),
                 p.stage == MatchStage::Isomorphism ? internal::kIsomorphismLine
                 : p.stage == MatchStage::Walls     ? internal::kWallsLine
                                                    : internal::kGrowingLine,
                 1, cv::LINE_AA, 4);
    for (const VertexPair& p : r.match.pairs)
    {
        const int g = group[static_cast<std::size_t>(p.ground_truth)];
        const cv::Scalar& colour = g < 0 ? internal::kNoGroupColour
                                         : internal::kGroupColours[static_cast<std::size_t>(g) %
                                                                   internal::kGroupColours.size()];
        for (const auto& [side, pos] :
             {std::make_pair(0, gt.vertices[static_cast<std::size_t>(p.ground_truth)].position_m),
              std::make_pair(1, map.vertices[static_cast<std::size_t>(p.map)].position_m)})
            cv::circle(canvas, at(side, pos), 2 * 16, colour, cv::FILLED, cv::LINE_AA, 4);
    }
    return pngDataUrl(canvas);
}
}  // namespace

std::string htmlEscape(const std::string& s)
{
    std::string out;
    out.reserve(s.size());
    for (const char ch : s) switch (ch)
        {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:
                out += ch;
        }
    return out;
}

std::string jsonForScriptElement(const std::string& json)
{
    std::string out;
    out.reserve(json.size() + json.size() / 64);
    for (std::size_t i = 0; i < json.size(); ++i)
    {
        const char ch = json[i];
        if (ch == '<')
            out += "\\u003c";
        else if (ch == '>')
            out += "\\u003e";
        else if (ch == '&')
            out += "\\u0026";
        else if (ch == '\xE2' && i + 2 < json.size() && json[i + 1] == '\x80' &&
                 (json[i + 2] == '\xA8' || json[i + 2] == '\xA9'))
        {
            // U+2028, U+2029: line terminators in older JavaScript parsers.
            out += json[i + 2] == '\xA8' ? "\\u2028" : "\\u2029";
            i += 2;
        }
        else
            out += ch;
    }
    return out;
}

std::string toString(HtmlReportContent::Kind kind)
{
    switch (kind)
    {
        case HtmlReportContent::Kind::Compare:
            return "compare";
        case HtmlReportContent::Kind::Rank:
            return "rank";
        case HtmlReportContent::Kind::Series:
            return "series";
        case HtmlReportContent::Kind::Rawlog:
            return "rawlog";
    }
    return "compare";
}

HtmlMap makeHtmlMap(const std::string& name, const Grid& grid, const TopologyGraph& graph,
                    const HtmlReportOptions& opts)
{
    const CellFrame f(grid);
    const internal::MatchView view = internal::makeMatchView(graph);
    JsonWriter w;
    w.beginObject();
    w.key("name").value(name);
    w.key("size_x").value(static_cast<std::uint64_t>(grid.getSizeX()));
    w.key("size_y").value(static_cast<std::uint64_t>(grid.getSizeY()));
    w.key("resolution_m").value(grid.getResolution(), 6);
    w.key("x_min_m").value(grid.getXMin(), 4).key("y_max_m").value(grid.getYMax(), 4);
    cv::Mat img = grid.getSizeX() > 0 && grid.getSizeY() > 0
                      ? fitInto(internal::renderGrid(grid), opts.max_map_px)
                      : cv::Mat(1, 1, CV_8UC1, cv::Scalar(255));
    w.key("image").value(pngDataUrl(img));
    // [id, x, y (cells), degree, clearance [m], spurious, matchable, min angle, max angle [deg]]
    w.key("vertices").beginArray();
    for (const TopoVertex& v : graph.vertices)
    {
        w.beginArray(true);
        w.value(v.id).value(f.x(v.position_m), 2).value(f.y(v.position_m), 2);
        w.value(v.degree()).value(v.clearance_m, 3).value(v.spurious ? 1 : 0);
        const bool active = static_cast<std::size_t>(v.id) < view.v.size() &&
                            view.v[static_cast<std::size_t>(v.id)].active;
        w.value(active ? 1 : 0);
        w.value(v.min_angle_rad * kRadToDeg, 1).value(v.max_angle_rad * kRadToDeg, 1);
        w.endArray();
    }
    w.endArray();
    // [from, to, class (0 edge, 1 dead end, 2 spurious), length [m], mean clearance [m], path]
    w.key("edges").beginArray();
    for (const TopoEdge& e : graph.edges)
    {
        w.beginArray(true);
        w.value(e.from).value(e.to).value(e.spurious ? 2 : e.dead_end ? 1 : 0);
        w.value(e.length_m, 2).value(e.mean_clearance_m, 3).value(svgPath(f, e.path_m));
        w.endArray();
    }
    w.endArray();
    w.key("warnings");
    writeStrings(w, graph.warnings);
    w.endObject();
    return {w.str()};
}

HtmlEntry makeHtmlEntry(const std::string& name, const Grid& gt_grid, const TopologyGraph& gt_graph,
                        const Grid& grid, const TopologyGraph& map_graph,
                        const QualityReport& report, bool with_thumbnail, const ScoreRow* row,
                        const HtmlReportOptions& opts)
{
    JsonWriter w;
    w.beginObject();
    w.key("name").value(name);
    if (row)
    {
        w.key("step").value(row->step);
        w.key("entry").value(static_cast<std::uint64_t>(row->entry));
        w.key("time_s").value(row->time_s, 3);
        w.key("scans").value(static_cast<std::uint64_t>(row->scans));
    }
    writeReport(w, gt_graph, map_graph, report);
    w.key("unexplained_walls");
    writeUnexplainedWalls(w, grid, report, opts.max_map_px);
    if (with_thumbnail)
        w.key("thumbnail")
            .value(thumbnail(gt_grid, gt_graph, grid, map_graph, report, opts.thumbnail_px));
    // The map last: its picture is most of the entry.
    std::string map_json = makeHtmlMap(name, grid, map_graph, opts).json;
    w.endObject();
    // Splice the map object in as the last member (JsonWriter has no raw-value call).
    std::string out = w.str();
    const std::size_t close = out.rfind('}');
    out = out.substr(0, close);
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    return {out + ",\n  \"map\": " + map_json + "}\n"};
}

HtmlEntry makeHtmlErrorEntry(const std::string& name, const std::string& error)
{
    JsonWriter w;
    w.beginObject();
    w.key("name").value(name);
    w.key("error").value(error);
    w.endObject();
    return {w.str()};
}

std::string renderHtmlReport(const HtmlReportContent& c)
{
    // The page's data: the small members first, then the pictures.
    JsonWriter w;
    w.beginObject();
    w.key("kind").value(toString(c.kind));
    w.key("title").value(c.title);
    w.key("generator").value(c.generator);
    w.key("messages");
    writeStrings(w, c.messages);
    w.key("parameters_ini").value(c.parameters_ini);
    w.key("extra_ini").value(c.extra_ini);
    w.key("ranks");
    writeStrings(w, c.ranks);
    w.key("colours").beginObject();
    w.key("groups").beginArray(true);
    for (const cv::Scalar& s : internal::kGroupColours) w.value(hexColour(s));
    w.endArray();
    for (const auto& [key, colour] :
         {std::make_pair("no_group", &internal::kNoGroupColour),
          std::make_pair("unmatched", &internal::kUnmatchedColour),
          std::make_pair("isomorphism", &internal::kIsomorphismLine),
          std::make_pair("growing", &internal::kGrowingLine),
          std::make_pair("walls", &internal::kWallsLine),
          std::make_pair("missing", &internal::kMissingRing),
          std::make_pair("unexplained", &internal::kUnexplainedWallColour),
          std::make_pair("edge", &internal::kEdgeColour),
          std::make_pair("dead_end", &internal::kDeadEndEdgeColour),
          std::make_pair("spurious", &internal::kSpuriousColour),
          std::make_pair("degree1", &internal::kVertexDeg1Colour),
          std::make_pair("degree2", &internal::kVertexDeg2Colour),
          std::make_pair("degree3", &internal::kVertexDeg3Colour),
          std::make_pair("degree4", &internal::kVertexDeg4PlusColour)})
        w.key(key).value(hexColour(*colour));
    w.endObject();
    w.endObject();
    std::string data = w.str();
    data = data.substr(0, data.rfind('}'));
    while (!data.empty() && (data.back() == '\n' || data.back() == ' ')) data.pop_back();
    data += ",\n\"ground_truth\": " + (c.ground_truth.json.empty() ? "null" : c.ground_truth.json);
    data += ",\n\"entries\": [";
    for (std::size_t i = 0; i < c.entries.size(); ++i)
        data += (i ? ",\n" : "\n") + c.entries[i].json;
    data += "]}\n";

    const std::string title = htmlEscape(c.title);
    std::string page;
    page.reserve(data.size() + 64 * 1024);
    page +=
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
        // Nothing may be fetched: pictures are data: URLs, script and style are inline.
        "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src "
        "data:; style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n"
        "<meta name=\"generator\" content=\"" +
        htmlEscape(c.generator) + "\">\n<title>" + title +
        "</title>\n"
        // Errors of the page's script, for the reader and for the browser test.
        "<script>window.topoevalErrors=[];window.addEventListener('error',function(e){"
        "window.topoevalErrors.push(String(e.message));var d=document.getElementById("
        "'page-errors');if(d){d.hidden=false;d.textContent='Error in this page: '+"
        "window.topoevalErrors.join('; ');}});</script>\n<style>\n";
    page += internal::kReportStyle;
    page += "</style>\n</head>\n<body data-kind=\"" + toString(c.kind) +
            "\">\n<header><h1 id=\"title\">" + title + "</h1><p class=\"generator\">" +
            htmlEscape(c.generator) +
            "</p></header>\n<div id=\"page-errors\" class=\"page-errors\" hidden></div>\n"
            "<noscript><p>This report draws its maps and tables with JavaScript: enable it "
            "to see them.</p></noscript>\n<main id=\"app\"></main>\n"
            "<script type=\"application/json\" id=\"report-data\">";
    page += jsonForScriptElement(data);
    page += "</script>\n<script>\n";
    page += internal::kReportScript;
    page += "</script>\n</body>\n</html>\n";
    return page;
}

}  // namespace mrpt_topoeval
