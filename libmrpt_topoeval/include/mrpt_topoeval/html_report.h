/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// One self-contained HTML page per run (`--html` of compare, rank, rawlog and series,
// doc/report.md): the maps as embedded PNG, the graphs and the match as SVG drawn by the
// page's own script, the scores, messages and parameters. Nothing is fetched from the network.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/QualityReport.h>
#include <mrpt_topoeval/RawlogScorer.h>
#include <mrpt_topoeval/TopologyGraph.h>

#include <string>
#include <vector>

namespace mrpt_topoeval
{
/** How maps are pictured in a page. */
struct HtmlReportOptions
{
    /** A map's picture is shrunk (area averaging) to at most this many pixels on its longer
     * side; the graph keeps the map's full resolution [px]. */
    int max_map_px = 2048;
    /** Longer side of a rank thumbnail (the match of both maps, side by side) [px]. */
    int thumbnail_px = 360;
};

/** One picture of a map with its graph, ready for a page: the grid as a grey PNG (occupied
 * black, free white, unknown grey, as the PNG pictures draw it) and the graph in the grid's
 * cell frame. Made once per map, so that the grid need not be kept (rank makes them in its
 * worker threads). Thread-safe: no shared state. */
struct HtmlMap
{
    std::string json;  //!< The page's JSON object for this map (internal format).
};

/** A map and its graph for a page; `name` is shown as given (escaped). */
HtmlMap makeHtmlMap(const std::string& name, const mrpt::maps::COccupancyGridMap2D& grid,
                    const TopologyGraph& graph, const HtmlReportOptions& opts = {});

/** One evaluated map of a page: its picture, the report against the page's ground truth and,
 * for rank, a thumbnail of the match. Made by makeHtmlEntry(); thread-safe. */
struct HtmlEntry
{
    std::string json;  //!< The page's JSON object for this entry (internal format).
};

/** An evaluated map: `report` is `map_graph` matched against the page's ground truth, whose
 * grid and graph are needed for the pair's error and, with `thumbnail`, for the thumbnail.
 * `row` (rawlog, series) adds the snapshot's step, entry and time.
 * \throws InputError if the report names a vertex that is not in its graph. */
HtmlEntry makeHtmlEntry(const std::string& name, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                        const TopologyGraph& gt_graph, const mrpt::maps::COccupancyGridMap2D& grid,
                        const TopologyGraph& map_graph, const QualityReport& report, bool thumbnail,
                        const ScoreRow* row = nullptr, const HtmlReportOptions& opts = {});

/** A map that could not be evaluated (rank): listed with its error. */
HtmlEntry makeHtmlErrorEntry(const std::string& name, const std::string& error);

/** What a page shows. */
struct HtmlReportContent
{
    enum class Kind
    {
        Compare,  //!< one map against the ground truth
        Rank,     //!< several maps, a sortable table
        Series,   //!< saved map snapshots scored over time
        Rawlog    //!< ICP-SLAM snapshots of a rawlog scored over time
    };
    Kind kind = Kind::Compare;
    std::string title;               //!< Shown in the title bar and heading.
    HtmlMap ground_truth;            //!< From makeHtmlMap().
    std::vector<HtmlEntry> entries;  //!< One per map or snapshot, in order.
    /** Rank only: each entry's overall rank ("1", "2-3"; "" for errors), as the table prints. */
    std::vector<std::string> ranks;
    std::vector<std::string> messages;  //!< Notes on the run, shown as text.
    std::string parameters_ini;         //!< The parameters in effect, as INI text.
    std::string extra_ini;              //!< Further configuration (rawlog: the SLAM INI).
    std::string generator;              //!< e.g. "topoeval 0.1.0 (MRPT 2.5.8)".
};

/** "compare", "rank", "series", "rawlog". */
std::string toString(HtmlReportContent::Kind kind);

/** The whole page. Every string from `content` (file names, messages, INI text) reaches the
 * page as text only: HTML-escaped, or inside the embedded JSON with `<`, `>`, `&`, U+2028 and
 * U+2029 escaped and shown by the script as text nodes. Deterministic. */
std::string renderHtmlReport(const HtmlReportContent& content);

/** `s` with `&`, `<`, `>`, `"` and `'` as character references, for HTML text and
 * attribute values. */
std::string htmlEscape(const std::string& s);

/** A JSON text made safe to embed in an HTML `<script>` element: `<`, `>` and `&` as
 * `\u003c`, `\u003e`, `\u0026`, U+2028 and U+2029 as `\u2028`, `\u2029` (those characters can
 * only occur inside JSON strings, where the escapes mean the same). */
std::string jsonForScriptElement(const std::string& json);

}  // namespace mrpt_topoeval
