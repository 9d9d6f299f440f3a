/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The picture of a quality report (paper Fig. 7 and 9): the match, each matched vertex
// coloured and numbered by its brokenness group.

#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/errors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "common/format.h"
#include "drawing/graph_drawing.h"

namespace mrpt_topoeval
{
namespace
{
using Grid = mrpt::maps::COccupancyGridMap2D;
using internal::kGroupColours;
using internal::kNoGroupColour;
using internal::kShift;
using internal::kUnmatchedColour;
using internal::LegendEntry;
using internal::MatchPanel;

const cv::Scalar& groupColour(int group)
{
    return group < 0 ? kNoGroupColour
                     : kGroupColours[static_cast<std::size_t>(group) % kGroupColours.size()];
}

using internal::fmt;

/** A white strip with one line of text, like a legend row without a mark. */
cv::Mat textStrip(int width, const std::string& text)
{
    const int font = cv::FONT_HERSHEY_SIMPLEX;
    const double font_scale = 0.45;
    const int margin = 6, height = 22;
    int base = 0;
    const int text_w = cv::getTextSize(text, font, font_scale, 1, &base).width;
    cv::Mat strip(height, std::max(width, text_w + 2 * margin), CV_8UC3, internal::kWhite);
    cv::putText(strip, text, {margin, height - 7}, font, font_scale, internal::kTextColour, 1,
                cv::LINE_AA);
    return strip;
}

/** Group index of each vertex of a graph with `n` vertices, -1 for none.
 * \throws InputError naming the bad id. */
std::vector<int> groupOfGroundTruthVertex(const QualityReport& r, std::size_t n)
{
    std::vector<int> group(n, -1);
    for (std::size_t gi = 0; gi < r.brokenness.groups.size(); ++gi)
        for (const int v : r.brokenness.groups[gi].gt_vertices)
        {
            if (v < 0 || static_cast<std::size_t>(v) >= n)
                throw InputError("drawQualityReport: brokenness group " + std::to_string(gi) +
                                 " names ground-truth vertex " + std::to_string(v) +
                                 ", but that graph has " + std::to_string(n) + " vertices");
            group[static_cast<std::size_t>(v)] = static_cast<int>(gi);
        }
    return group;
}

/** Fills a vertex with its group's colour; `label` (the group number) goes at the id's place,
 * or below the vertex when ids are drawn. */
void drawGroupVertex(cv::Mat& canvas, const MatchPanel& panel, const TopoVertex& v,
                     const cv::Scalar& fill, const std::string& label, bool ids_drawn)
{
    // One pixel larger than the graph's own mark, so its degree colour does not show.
    const int r = (panel.style.vertex_radius_px + 1) << kShift;
    const cv::Point c = panel.fixedPoint(v.position_m);
    cv::circle(canvas, c, r, fill, cv::FILLED, cv::LINE_AA, kShift);
    cv::circle(canvas, c, r, internal::kOutlineColour, 1, cv::LINE_AA, kShift);
    if (label.empty()) return;

    const double font_scale = panel.style.id_font_scale * 1.25;
    int base = 0;
    const cv::Size text = cv::getTextSize(label, cv::FONT_HERSHEY_SIMPLEX, font_scale, 2, &base);
    const cv::Point p = panel.point(v.position_m);
    const int off = panel.style.vertex_radius_px + 2;
    const cv::Point at =
        ids_drawn ? cv::Point(p.x + off, p.y + off + text.height) : cv::Point(p.x + off, p.y - off);
    // A white halo keeps the number readable over walls and edges; the number itself in a
    // darker shade of its group's colour, which stays readable for the light ones.
    cv::putText(canvas, label, at, cv::FONT_HERSHEY_SIMPLEX, font_scale, internal::kWhite, 4,
                cv::LINE_AA);
    cv::putText(canvas, label, at, cv::FONT_HERSHEY_SIMPLEX, font_scale, fill * 0.65, 2,
                cv::LINE_AA);
}
}  // namespace

mrpt::img::CImage drawQualityReport(const Grid& gt_grid, const TopologyGraph& gt,
                                    const Grid& map_grid, const TopologyGraph& map,
                                    const QualityReport& r, const DrawOptions& opts)
{
    const std::vector<int> gt_group = groupOfGroundTruthVertex(r, gt.vertices.size());
    internal::MatchPicture pic =
        internal::drawMatchPicture(gt_grid, gt, map_grid, map, r.match, opts, "drawQualityReport");

    // The map's walls that no matched part explains (doc/quality.md, "Explained walls"): where
    // the map disagrees with the ground truth. Under the vertices, which stay readable.
    const int wall_radius = std::max(1, pic.map.style.edge_thickness_px);
    for (const Eigen::Vector2f& q : r.explained_walls.unexplained_m)
        cv::circle(pic.canvas, pic.map.point(q.cast<double>()), wall_radius,
                   internal::kUnexplainedWallColour, cv::FILLED);

    // Unmatched non-spurious vertices first (white), then the matched ones; spurious vertices
    // keep their graph colour, as their edges do.
    std::vector<bool> gt_matched(gt.vertices.size(), false),
        map_matched(map.vertices.size(), false);
    for (const VertexPair& p : r.match.pairs)
    {
        gt_matched[static_cast<std::size_t>(p.ground_truth)] = true;
        map_matched[static_cast<std::size_t>(p.map)] = true;
    }
    for (const auto& [graph, matched, panel] :
         {std::make_tuple(&gt, &gt_matched, &pic.ground_truth),
          std::make_tuple(&map, &map_matched, &pic.map)})
        for (const TopoVertex& v : graph->vertices)
            if (!v.spurious && !(*matched)[static_cast<std::size_t>(v.id)])
                drawGroupVertex(pic.canvas, *panel, v, kUnmatchedColour, "", opts.draw_ids);

    // The paper's Fig. 7 numbers both ends of a match with the group of the pair.
    for (const VertexPair& p : r.match.pairs)
    {
        const int group = gt_group[static_cast<std::size_t>(p.ground_truth)];
        const std::string label = group >= 0 ? std::to_string(group) : "";
        drawGroupVertex(pic.canvas, pic.ground_truth,
                        gt.vertices[static_cast<std::size_t>(p.ground_truth)], groupColour(group),
                        label, opts.draw_ids);
        drawGroupVertex(pic.canvas, pic.map, map.vertices[static_cast<std::size_t>(p.map)],
                        groupColour(group), label, opts.draw_ids);
    }

    // Legends: the attributes on one line, one entry per group, then the match and the graph.
    const int w = pic.canvas.cols;
    const std::string summary =
        "quality " + fmt("%.3f", r.quality) + "    coverage " + fmt("%.3f", r.coverage) +
        "    brokenness " + std::to_string(r.brokenness.degree) + " (" +
        std::to_string(r.brokenness.groups.size()) +
        (r.brokenness.groups.size() == 1 ? " group)" : " groups)") +
        (r.explained_walls.measured ? "    explained walls " + fmt("%.3f", r.explained_walls.share)
                                    : std::string()) +
        (r.map_scale != 1.0 ? "    map read at x " + fmt("%.4f", r.map_scale) + " (scale pass)"
                            : std::string());
    using Mark = LegendEntry::Mark;
    std::vector<LegendEntry> groups;
    for (std::size_t gi = 0; gi < r.brokenness.groups.size(); ++gi)
    {
        const BrokennessGroup& g = r.brokenness.groups[gi];
        groups.push_back({"group " + std::to_string(gi) + ": " +
                              std::to_string(g.gt_vertices.size()) + " vertices, yaw " +
                              fmt("%.1f", g.transform.yaw_deg) + " deg" +
                              (gi ? ", off by " + fmt("%.2f", g.offset_m) + " m" : "") +
                              (g.by_walls ? ", placed by its walls" : ""),
                          groupColour(static_cast<int>(gi)), Mark::Dot});
    }
    groups.push_back({"matched, in no group", kNoGroupColour, Mark::Dot});
    groups.push_back({"not matched", kUnmatchedColour, Mark::Dot});
    if (r.explained_walls.measured)
        groups.push_back(
            {"map walls no part explains (" +
                 std::to_string(r.explained_walls.wall_points - r.explained_walls.explained) + ")",
             internal::kUnexplainedWallColour, Mark::Dot});
    // Vertex fills mean groups here, not degrees: only the graph's edge entries stay.
    std::vector<LegendEntry> graph_entries;
    for (const LegendEntry& e : internal::graphLegendEntries(opts.draw_boundary))
        if (e.mark != Mark::Dot) graph_entries.push_back(e);

    const cv::Mat out = internal::stackVertically(
        {pic.canvas, textStrip(w, summary), internal::drawLegend(w, groups),
         internal::drawLegend(w, internal::matchLegendEntries(r.match)),
         internal::drawLegend(w, graph_entries)});
    return mrpt::img::CImage(out, mrpt::img::SHALLOW_COPY);
}

}  // namespace mrpt_topoeval
