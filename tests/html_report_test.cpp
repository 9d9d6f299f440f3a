/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The HTML report (doc/report.md), in-process: user text reaches the page as text only (a map
// named `<script>alert(1)</script>.yaml`, messages, INI values), the embedded JSON cannot close
// its <script> element, nothing is fetched from the network, and each kind of page holds what
// its script needs. The page in a browser: tests/browser/check_reports.py (html_report_browser).

#include <gtest/gtest.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/html_report.h>
#include <mrpt_topoeval/pipeline/evaluate.h>

#include <cmath>
#include <string>
#include <vector>

#include "synthetic_maps.h"

using namespace mrpt_topoeval;

namespace
{
std::size_t count(const std::string& s, const std::string& part)
{
    std::size_t n = 0;
    for (std::size_t at = s.find(part); at != std::string::npos; at = s.find(part, at + 1)) ++n;
    return n;
}

/** The office floor against a copy rotated by 37 deg and shifted: a real match. */
struct OfficePair
{
    mrpt::maps::COccupancyGridMap2D gt_grid = mrpt_topoeval::testing::makeOfficeMap();
    mrpt::maps::COccupancyGridMap2D map_grid =
        mrpt_topoeval::testing::transformGrid(gt_grid, 37.0 * M_PI / 180.0, {2.5, -1.0});
    TopologyGraph gt, map;
    QualityReport report;
    OfficePair() { report = evaluate(gt_grid, map_grid, Parameters{}, &gt, &map); }
};

const OfficePair& office()
{
    static const OfficePair p;
    return p;
}

const char* const kEvilName = "<script>alert(1)</script>.yaml";

std::string evilComparePage()
{
    const OfficePair& p = office();
    QualityReport report = p.report;
    report.messages.push_back("map: </script><script>alert(2)</script> & <!-- \u2028");
    HtmlReportContent page;
    page.kind = HtmlReportContent::Kind::Compare;
    page.title = std::string("compare ") + kEvilName;
    page.generator = "topoeval <test>";
    page.parameters_ini = "[MapLoad]\nresolution_m = 0.05 // <img src=x onerror=alert(3)>\n";
    page.messages = {"</SCRIPT><script>alert(4)</script>"};
    page.ground_truth = makeHtmlMap(kEvilName, p.gt_grid, p.gt);
    page.entries.push_back(
        makeHtmlEntry(kEvilName, p.gt_grid, p.gt, p.map_grid, p.map, report, false));
    return renderHtmlReport(page);
}
}  // namespace

TEST(HtmlReport, HtmlEscapeReplacesTheFiveSpecialCharacters)
{
    EXPECT_EQ(htmlEscape("<a href=\"x\">Tom & Jerry's</a>"),
              "&lt;a href=&quot;x&quot;&gt;Tom &amp; Jerry&#39;s&lt;/a&gt;");
    EXPECT_EQ(htmlEscape("plain text, \xC3\xA9t\xC3\xA9"), "plain text, \xC3\xA9t\xC3\xA9");
}

TEST(HtmlReport, JsonForScriptElementCannotCloseTheElement)
{
    EXPECT_EQ(jsonForScriptElement("{\"a\": \"</script><!--&\"}"),
              "{\"a\": \"\\u003c/script\\u003e\\u003c!--\\u0026\"}");
    // U+2028 and U+2029 (E2 80 A8/A9) as escapes; other three-byte characters unchanged.
    EXPECT_EQ(jsonForScriptElement("\"\xE2\x80\xA8\xE2\x80\xA9\xE2\x82\xAC\""),
              "\"\\u2028\\u2029\xE2\x82\xAC\"");
}

TEST(HtmlReport, AMapNamedLikeAScriptShowsAsTextAndRunsNothing)
{
    const std::string html = evilComparePage();
    // Exactly the page's own three script elements: the error recorder, the data, the code.
    EXPECT_EQ(count(html, "<script"), 3u);
    EXPECT_EQ(count(html, "</script>"), 3u);
    EXPECT_EQ(count(html, "<script>alert"), 0u);
    EXPECT_EQ(count(html, "<img"), 0u);
    EXPECT_EQ(count(html, "<!--"), 0u);
    EXPECT_EQ(count(html, "\xE2\x80\xA8"), 0u);
    // The title as text in the head and the heading, the name as JSON escapes.
    EXPECT_NE(html.find("<title>compare &lt;script&gt;alert(1)&lt;/script&gt;.yaml</title>"),
              std::string::npos);
    EXPECT_NE(html.find("<h1 id=\"title\">compare &lt;script&gt;alert(1)"), std::string::npos);
    EXPECT_NE(html.find("\"\\u003cscript\\u003ealert(1)\\u003c/script\\u003e.yaml\""),
              std::string::npos);
    EXPECT_NE(html.find("topoeval &lt;test&gt;"), std::string::npos);
}

TEST(HtmlReport, NothingIsFetchedFromTheNetwork)
{
    const std::string html = evilComparePage();
    EXPECT_NE(html.find("Content-Security-Policy\" content=\"default-src 'none'"),
              std::string::npos);
    for (const char* remote : {"src=\"http", "href=\"http", "url(", "@import", "src=\"//"})
        EXPECT_EQ(html.find(remote), std::string::npos) << remote;
    // The only URL is the SVG namespace, an identifier the browser never fetches.
    EXPECT_EQ(count(html, "http://") + count(html, "https://"),
              count(html, "http://www.w3.org/2000/svg"));
    EXPECT_GE(count(html, "data:image/png;base64,"), 2u);
}

TEST(HtmlReport, ComparePageHoldsTheReport)
{
    const OfficePair& p = office();
    ASSERT_GT(p.report.match.pairs.size(), 10u);
    HtmlReportContent page;
    page.kind = HtmlReportContent::Kind::Compare;
    page.title = "office";
    page.ground_truth = makeHtmlMap("office.yaml", p.gt_grid, p.gt);
    page.entries.push_back(
        makeHtmlEntry("rotated.yaml", p.gt_grid, p.gt, p.map_grid, p.map, p.report, false));
    const std::string html = renderHtmlReport(page);
    EXPECT_NE(html.find("<body data-kind=\"compare\">"), std::string::npos);
    EXPECT_NE(html.find("\"kind\": \"compare\""), std::string::npos);
    EXPECT_NE(html.find("\"brokenness\""), std::string::npos);
    EXPECT_EQ(count(html, "\"thumbnail\": \"data:"), 0u);
    EXPECT_EQ(html, renderHtmlReport(page)) << "deterministic";
    // Both maps' pictures, the group colours of the PNG drawing (group 0 blue).
    EXPECT_EQ(count(html, "data:image/png;base64,"), 2u);
    EXPECT_NE(html.find("\"#1f77b4\""), std::string::npos);
}

// A part placed by its walls (brokenness steps 9 and 10) is said so in the page's groups, and a
// pair of a map placed by its walls is stage 2 with its own line colour.
TEST(HtmlReport, APartPlacedByItsWallsIsMarked)
{
    const OfficePair& p = office();
    QualityReport report = p.report;
    ASSERT_FALSE(report.brokenness.groups.empty());
    ASSERT_FALSE(report.match.pairs.empty());
    auto page = [&]
    {
        HtmlReportContent c;
        c.kind = HtmlReportContent::Kind::Compare;
        c.ground_truth = makeHtmlMap("office.yaml", p.gt_grid, p.gt);
        c.entries.push_back(
            makeHtmlEntry("rotated.yaml", p.gt_grid, p.gt, p.map_grid, p.map, report, false));
        return renderHtmlReport(c);
    };
    EXPECT_EQ(count(page(), "\"by_walls\""), 0u);
    report.brokenness.groups.front().by_walls = true;
    report.match.pairs.front().stage = MatchStage::Walls;
    const std::string html = page();
    EXPECT_EQ(count(html, "\"by_walls\": true"), 1u);
    EXPECT_NE(html.find("\"walls\": \"#008080\""), std::string::npos);  // teal
    EXPECT_NE(html.find("placed by its walls"), std::string::npos);     // the page's words
}

TEST(HtmlReport, RankEntriesCarryThumbnailsAndErrors)
{
    const OfficePair& p = office();
    HtmlReportContent page;
    page.kind = HtmlReportContent::Kind::Rank;
    page.ground_truth = makeHtmlMap("office.yaml", p.gt_grid, p.gt);
    page.entries.push_back(
        makeHtmlEntry("rotated.yaml", p.gt_grid, p.gt, p.map_grid, p.map, p.report, true));
    page.entries.push_back(makeHtmlErrorEntry("bad<1>.yaml", "bad<1>.yaml: no such file"));
    page.ranks = {"1", ""};
    const std::string html = renderHtmlReport(page);
    EXPECT_EQ(count(html, "data:image/png;base64,"), 3u);  // ground truth, map, thumbnail
    EXPECT_NE(html.find("\"error\": \"bad\\u003c1\\u003e.yaml: no such file\""), std::string::npos);
}

TEST(HtmlReport, SnapshotEntriesCarryTheirStepAndTime)
{
    const OfficePair& p = office();
    ScoreRow row = scoreRowFromReport(p.report);
    row.step = 3;
    row.entry = 250;
    row.time_s = std::nan("");
    HtmlReportContent page;
    page.kind = HtmlReportContent::Kind::Series;
    page.ground_truth = makeHtmlMap("office.yaml", p.gt_grid, p.gt);
    page.entries.push_back(
        makeHtmlEntry("map_250.yaml", p.gt_grid, p.gt, p.map_grid, p.map, p.report, false, &row));
    const std::string html = renderHtmlReport(page);
    EXPECT_NE(html.find("\"step\": 3"), std::string::npos);
    EXPECT_NE(html.find("\"entry\": 250"), std::string::npos);
    EXPECT_NE(html.find("\"time_s\": null"), std::string::npos);
}

TEST(HtmlReport, LargeMapsAreShrunkButKeepTheirCellFrame)
{
    const OfficePair& p = office();
    HtmlReportOptions small;
    small.max_map_px = 64;
    const std::string full = makeHtmlMap("office", p.gt_grid, p.gt).json;
    const std::string shrunk = makeHtmlMap("office", p.gt_grid, p.gt, small).json;
    EXPECT_LT(shrunk.size(), full.size());
    EXPECT_NE(shrunk.find("\"size_x\": " + std::to_string(p.gt_grid.getSizeX())),
              std::string::npos);
}

TEST(HtmlReport, AReportNamingAVertexOutsideItsGraphIsBadInput)
{
    const OfficePair& p = office();
    QualityReport bad = p.report;
    bad.match.pairs.push_back({0, 100000, MatchStage::Isomorphism, 0.5, 0});
    EXPECT_THROW(makeHtmlEntry("m", p.gt_grid, p.gt, p.map_grid, p.map, bad, false), InputError);
}
