/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// `topoeval compare GT MAP`: the quality of a map against a ground truth (paper IV): coverage,
// accuracies, local consistency, brokenness and one quality score, printed as a brief (or,
// with --verbose, full) report; optionally written as JSON and drawn like the paper's Fig. 7.

#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/html_report.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <mrpt_topoeval/output.h>
#include <mrpt_topoeval/pipeline/evaluate.h>
#include <mrpt_topoeval/report_json.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "cli_common.h"
#include "cli_options.h"

namespace mrpt_topoeval::cli
{
namespace
{
void printSide(std::ostream& os, const char* label, const LoadedMap& m, const TopologyGraph& g)
{
    os << label << m.file << " (" << m.format << "): " << g.vertices.size() << " vertices ("
       << g.numNonSpuriousVertices() << " non-spurious), " << g.numHalfEdges() << " half edges, "
       << fmt("%.2f", g.totalEdgeLength()) << " m of edges\n";
}
}  // namespace

int verbCompare(int argc, char** argv)
{
    const auto t_run = Clock::now();
    VerbCommandLine cl(
        "compare",
        "Evaluates a map against a ground-truth map with the Topology Graph method "
        "(Schwertfeger & Birk 2013, section IV): both maps' graphs are built and matched as by "
        "'topoeval match', then coverage, global and relative accuracy, local consistency "
        "(short, medium, long graph distances), brokenness and one quality score in [0, 1] are "
        "computed. Prints a brief report (--verbose: the full one, with each consistency class, "
        "each brokenness group and the time per step). --json writes everything, including the "
        "match (the same object as 'topoeval match --json') and the effective parameters; "
        "--image draws both maps with the match lines and each matched vertex coloured and "
        "numbered by its brokenness group (the paper's Fig. 7); --html writes one "
        "self-contained web page with the scores, both maps with their graphs and the match "
        "(zoom, pan, hover), the messages and the parameters (doc/report.md). A map that matches "
        "nothing "
        "gives coverage 0 and quality 0 with a warning, and exit code 0. Existing files are "
        "never replaced without --force; outputs are written only after everything succeeded. "
        "Exit codes: 0 ok, 1 internal error, 2 bad input or usage, 3 output error.");
    TCLAP::CmdLine& cmd = cl.cmd();
    StandardOptions opts(cl);
    // Declared in reverse order of the usage line (TCLAP lists the last added first).
    opts.addForce();
    opts.addHtml("Write the report as one self-contained web page to this file.");
    opts.addImage("Draw both maps, the match lines and the brokenness groups into this PNG file.");
    opts.addJson("Write the report as JSON to this file.");
    // No short form: TCLAP keeps -v for --version.
    TCLAP::SwitchArg verbose_arg(
        "", "verbose",
        "Print the full report: every consistency class, every brokenness group, the "
        "alignment, notes and the time per step.",
        cmd);
    opts.addThreads(
        "Worker threads, 0 = all cores: the two graphs are built side by side, and ICP "
        "similarity runs in them; overrides [VertexSimilarity] threads. Results do not depend "
        "on it.");
    opts.addSimilarity();
    opts.addResolution();
    opts.addConfig();
    opts.addGtAndMap();
    if (const auto done = cl.parse(argc, argv)) return *done;

    const auto [gt_path, map_path, params] =
        opts.gtAndMapRun("; to score several maps use 'topoeval rank'");
    const std::string json_path = opts.json();
    const std::string image_path = opts.image();

    std::map<std::string, double> timing_ms;
    const LoadedMap gt = loadMapTimed(gt_path, params.map_load, timing_ms["load_ground_truth"]);
    const LoadedMap map = loadMapTimed(map_path, params.map_load, timing_ms["load_map"]);

    TopologyGraph gt_graph, map_graph;
    QualityReport report = evaluate(gt.grid, map.grid, params, &gt_graph, &map_graph);
    gt_graph.map.file = gt.file;
    map_graph.map.file = map.file;
    // An empty graph is the likeliest reason for an empty match: say so (the builder's own
    // warnings, when it has some, are among the report's messages already).
    for (const auto& [graph, role] :
         {std::pair<const TopologyGraph*, const char*>{&gt_graph, "ground truth"},
          {&map_graph, "map"}})
        if (graph->vertices.empty() && graph->warnings.empty())
            report.messages.push_back(std::string(role) + ": the Topology Graph of " +
                                      graph->map.file + " is empty");
    for (const auto& msg : report.messages) printWarning(msg);

    // Everything is produced in memory first: a failure leaves no output behind.
    mrpt::img::CImage picture;
    if (!image_path.empty())
    {
        const auto t0 = Clock::now();
        DrawOptions draw;
        // The outer boundary is green like the isomorphism's match lines, and the group
        // numbers take the ids' place (the paper's Fig. 7): both left out.
        draw.draw_boundary = false;
        draw.draw_ids = false;
        picture = drawQualityReport(gt.grid, gt_graph, map.grid, map_graph, report, draw);
        timing_ms["draw"] = msSince(t0);
    }
    // The library's "total" is the evaluation; the run's total includes loading and drawing.
    for (const auto& [step, ms] : report.timing_ms)
        timing_ms[step == "total" ? "evaluate" : step] = ms;
    timing_ms["total"] = msSince(t_run);
    report.timing_ms = timing_ms;
    std::string json_text;
    if (!json_path.empty()) json_text = reportToJson(gt_graph, map_graph, report, params, true);
    std::string html_text;
    if (!opts.html().empty())
    {
        HtmlReportContent page;
        page.kind = HtmlReportContent::Kind::Compare;
        page.title = "compare " + map.file + " against " + gt.file;
        page.generator = versionLine();
        page.parameters_ini = iniText(params);
        page.ground_truth = makeHtmlMap(gt.file, gt.grid, gt_graph);
        page.entries.push_back(
            makeHtmlEntry(map.file, gt.grid, gt_graph, map.grid, map_graph, report, false));
        html_text = renderHtmlReport(page);
    }

    const std::vector<std::string> written = opts.writeOutputs(json_text, picture, html_text);

    std::ostream& os = std::cout;
    printSide(os, "ground truth  ", gt, gt_graph);
    printSide(os, "map           ", map, map_graph);
    os << "similarity    " << toString(params.similarity.mode) << "\n\n";
    const bool verbose = verbose_arg.getValue();
    os << (verbose ? report.fullReport() : report.briefReport());
    if (verbose)
    {
        // The run's steps in pipeline order.
        os << "time [ms]   "
           << timingList(orderedTimings(
                  timing_ms, {"load_ground_truth", "load_map", "graphs", "similarity", "match",
                              "evaluation", "evaluate", "draw", "total"}))
           << "\n";
    }
    for (const auto& w : written) os << "wrote       " << w << "\n";
    flushStdout();
    return kExitOk;
}

}  // namespace mrpt_topoeval::cli
