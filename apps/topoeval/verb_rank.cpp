/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// `topoeval rank GT MAP...`: scores several maps against one ground truth, in parallel, and
// prints them ranked per attribute and overall, like the paper's Table I; optionally as CSV.
// The scoring and ranking are in rank_maps.h; this file is the command line and the outputs.

#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/html_report.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <mrpt_topoeval/output.h>

#include <iostream>
#include <string>
#include <vector>

#include "cli_common.h"
#include "cli_options.h"
#include "rank_maps.h"

namespace mrpt_topoeval::cli
{
int verbRank(int argc, char** argv)
{
    const auto t_run = Clock::now();
    VerbCommandLine cl(
        "rank",
        "Scores several maps against one ground truth as 'topoeval compare' does (Schwertfeger "
        "& Birk 2013, section IV) and prints them as a table like the paper's Table I: per map "
        "its overall rank (by quality), quality, coverage, relative accuracy score, local "
        "consistency scores (short, medium, long), brokenness degree, and its rank by each "
        "attribute; equal values share a rank ('1-2'). Maps are evaluated in parallel, the "
        "results do not depend on the number of threads and are listed in the order given. "
        "--csv writes the table with a header row; --html one self-contained web page with the "
        "table (sortable), a thumbnail of each map's match and each map's compare view "
        "(doc/report.md). A map that cannot be read is listed with "
        "its error, the others are still ranked, and the exit code is 2 (1 for an internal "
        "error). Existing files are never replaced without --force. Exit codes: 0 ok, 1 "
        "internal error, 2 bad input or usage, 3 output error.");
    TCLAP::CmdLine& cmd = cl.cmd();
    // Declared in reverse order of the usage line (TCLAP lists the last added first).
    StandardOptions opts(cl);
    opts.addForce("Replace existing output files.");
    opts.addHtml(
        "Write the ranking as one self-contained web page to this file: the table, a thumbnail "
        "and the compare view of each map.");
    TCLAP::ValueArg<std::string> csv_arg("", "csv",
                                         "Write the table as CSV (header row first) to this file.",
                                         false, "", "OUT.csv", cmd);
    opts.addThreads(
        "Threads in all, 0 = all cores; overrides [VertexSimilarity] threads. Up to this many "
        "maps are evaluated at once, and ICP similarity shares what is left. Results do not "
        "depend on it.");
    opts.addSimilarity();
    opts.addResolution();
    opts.addConfig();
    TCLAP::UnlabeledMultiArg<std::string> maps_arg(
        "GT_MAPS",
        "The ground truth, then one or more maps to score. ROS map_server .yaml, image (.png "
        ".pgm .bmp .jpg), MRPT .gridmap[.gz] or .simplemap[.gz].",
        false, "GT MAP...", cmd);
    if (const auto done = cl.parse(argc, argv)) return *done;

    const std::vector<std::string>& args = maps_arg.getValue();
    if (args.empty()) throw cl.usageError("missing the GT and MAP arguments");
    if (args.size() == 1) throw cl.usageError("missing the MAP arguments (one or more)");
    for (std::size_t i = 0; i < args.size(); ++i)
        if (args[i].empty())
            throw cl.usageError(i == 0 ? std::string("the GT argument is empty")
                                       : "MAP argument " + std::to_string(i) + " is empty");
    const std::string gt_path = args[0];
    const std::string csv_path = csv_arg.getValue();
    const bool force = opts.force();
    if (csv_arg.isSet() && csv_path.empty()) throw cl.usageError("--csv needs a file name");
    opts.checkJsonImage();
    const std::string html_path = opts.html();
    OutputList outputs = opts.outputs();
    if (!csv_path.empty()) outputs.emplace_back("--csv", csv_path);
    checkDistinctOutputs(cl, outputs);
    const Parameters params = opts.parameters();

    std::vector<std::string> inputs = args;
    inputs.push_back(opts.config());
    for (const auto& out : outputs) checkOutputPath(out.second, force, inputs);

    // The ground truth and its graph once, shared read-only by every evaluation: nothing to
    // rank without it.
    const LoadedMap gt = loadMapWarning(gt_path, params.map_load);
    const TopologyGraph gt_graph = buildTopologyGraph(gt.grid, params.graph);

    std::size_t workers = 0;
    std::vector<MapResult> results =
        scoreMaps(gt_graph, gt.grid, std::vector<std::string>(args.begin() + 1, args.end()), params,
                  !html_path.empty(), &workers);

    // Warnings in the order the maps were given, whatever order they finished in.
    for (const MapResult& m : results)
        for (const auto& msg : m.report.messages) printWarning(m.file + ": " + msg);

    const Ranking rk = rankMaps(results);
    if (!csv_path.empty()) writeFileAtomic(csv_path, rankCsv(results, rk), force);
    if (!html_path.empty())
    {
        HtmlReportContent page;
        page.kind = HtmlReportContent::Kind::Rank;
        page.title = "rank " + std::to_string(results.size()) + " maps against " + gt.file;
        page.generator = versionLine();
        page.parameters_ini = iniText(params);
        page.ground_truth = makeHtmlMap(gt.file, gt.grid, gt_graph);
        page.ranks = rk.overall;
        for (MapResult& m : results)
        {
            page.entries.push_back(m.ok ? std::move(m.html) : makeHtmlErrorEntry(m.name, m.error));
            for (const auto& msg : m.report.messages) page.messages.push_back(m.name + ": " + msg);
        }
        writeFileAtomic(html_path, renderHtmlReport(page), force);
    }

    std::ostream& os = std::cout;
    os << "ground truth  " << gt.file << " (" << gt.format << ")\n";
    os << "similarity    " << toString(params.similarity.mode) << "\n";
    os << "maps          " << results.size() << " (" << workers << " at a time), "
       << fixed(msSince(t_run) / 1000.0, 2) << " s\n\n";
    printRankTable(os, results, rk);
    if (!csv_path.empty()) os << "wrote         " << csv_path << "\n";
    if (!html_path.empty()) os << "wrote         " << html_path << "\n";
    flushStdout();

    int code = kExitOk;
    for (const MapResult& m : results)
        if (!m.ok)
        {
            printError(m.error);
            code = m.internal_error ? kExitInternalError : (code == kExitOk ? kExitBadInput : code);
        }
    return code;
}

}  // namespace mrpt_topoeval::cli
