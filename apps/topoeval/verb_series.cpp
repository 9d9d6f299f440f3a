/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// `topoeval series GT MAP...`: the scoring of `rawlog` over maps saved by another SLAM system
// (a map every N steps): the same scores.csv and scores.png (doc/rawlog.md).

#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/html_report.h>
#include <mrpt_topoeval/json/JsonWriter.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <mrpt_topoeval/output.h>
#include <mrpt_topoeval/pipeline/evaluate.h>
#include <mrpt_topoeval/scores/scores.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>

#include "cli_common.h"
#include "cli_options.h"
#include "scores_output.h"

namespace fs = std::filesystem;

namespace mrpt_topoeval::cli
{
namespace
{
/** A folder's maps sorted by name; an image with a YAML beside it is the YAML's. */
std::vector<std::string> mapsInFolder(const std::string& dir)
{
    // The non-throwing overloads: an unreadable folder is bad input (exit 2), not an
    // internal error.
    std::error_code ec, entry_ec;  // listing errors; an entry that cannot be checked is skipped
    fs::directory_iterator it(dir, ec);
    if (ec) throw InputError(dir + ": cannot list the folder: " + ec.message());
    std::vector<std::string> out;
    for (; it != fs::directory_iterator(); it.increment(ec))
    {
        if (ec) throw InputError(dir + ": cannot list the folder: " + ec.message());
        if (!it->is_regular_file(entry_ec) || !isMapFile(it->path().string())) continue;
        if (mapFormatFromName(it->path().string()) == MapFormat::Image)
        {
            fs::path y = it->path();
            if (fs::exists(y.replace_extension(".yaml"), entry_ec) ||
                fs::exists(y.replace_extension(".yml"), entry_ec))
                continue;
        }
        out.push_back(it->path().string());
    }
    if (ec) throw InputError(dir + ": cannot list the folder: " + ec.message());
    std::sort(out.begin(), out.end());
    return out;
}

/** report.json: the ground truth, each map scored so far (`maps[i]` with `rows[i]`), and how
 * the run ended: "done", or "error" and the error's text. */
std::string reportJson(const std::string& gt_path, const std::vector<std::string>& maps,
                       const std::vector<ScoreRow>& rows, const std::string& error)
{
    JsonWriter w;
    w.beginObject();
    w.key("ground_truth").value(gt_path);
    w.key("stop").value(error.empty() ? "done" : "error");
    w.key("stop_message").value(error);
    w.key("maps").beginArray(true);
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        w.beginObject().key("file").value(maps[i]).key("scores");
        writeScoreRow(w, rows[i]);
        w.endObject();
    }
    w.endArray();
    w.endObject();
    return w.str();
}

/** The last number in a file name (mapbuilt_00200.yaml -> 200), or `fallback`. */
std::size_t numberInName(const std::string& path, std::size_t fallback)
{
    const std::string name = fs::path(path).filename().string();
    std::size_t end = std::string::npos;
    for (std::size_t i = name.size(); i-- > 0;)
        if (std::isdigit(static_cast<unsigned char>(name[i])))
        {
            end = i;
            break;
        }
    if (end == std::string::npos) return fallback;
    std::size_t begin = end;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(name[begin - 1]))) --begin;
    if (end - begin > 15) return fallback;
    return static_cast<std::size_t>(std::stoull(name.substr(begin, end - begin + 1)));
}
}  // namespace

int verbSeries(int argc, char** argv)
{
    VerbCommandLine cl(
        "series",
        "Scores a sequence of saved maps against one ground truth, as 'rawlog' scores its "
        "snapshots, for SLAM systems other than MRPT's ICP-SLAM (e.g. an RBPF run's map every "
        "200 steps). MAP may be a folder: its maps sorted by name (an image with a YAML beside "
        "it counts once). The 'entry' column is the last number in each map's file name "
        "(mapbuilt_00200 -> 200), or its position; time_s and scans are empty/0. Outputs in "
        "DIR: scores.csv (row by row), scores.png, report.json; --html one self-contained web "
        "page with the scores over time and each map's match (doc/report.md). Existing outputs are "
        "never "
        "replaced without --force. Every map is read before DIR is created: a bad one leaves "
        "nothing behind. Exit codes: 0 ok, 1 internal error, 2 bad input or usage, 3 "
        "output error.");
    TCLAP::CmdLine& cmd = cl.cmd();
    StandardOptions opts(cl);
    opts.addForce();
    opts.addHtml(
        "Write one self-contained web page to this file: the scores over time and each map "
        "with its match (a slider over the maps).");
    TCLAP::ValueArg<std::string> out_arg("o", "out", "Output folder (default: series-scores).",
                                         false, "series-scores", "DIR", cmd);
    opts.addResolution();
    opts.addConfig();
    TCLAP::UnlabeledMultiArg<std::string> maps_arg(
        "GT_MAPS", "The ground truth, then the maps in time order (files or folders).", false,
        "GT MAP...", cmd);
    if (const auto done = cl.parse(argc, argv)) return *done;

    const std::vector<std::string>& args = maps_arg.getValue();
    if (args.empty()) throw cl.usageError("missing the GT and MAP arguments");
    if (args.size() == 1) throw cl.usageError("missing the MAP arguments");
    const std::string gt_path = args[0];
    std::vector<std::string> maps;
    for (std::size_t i = 1; i < args.size(); ++i)
    {
        std::error_code ec;
        if (!fs::exists(args[i], ec)) throw InputError(args[i] + ": no such file");
        if (fs::is_directory(args[i], ec))
        {
            const auto in = mapsInFolder(args[i]);
            if (in.empty()) throw InputError(args[i] + ": a folder with no map file");
            maps.insert(maps.end(), in.begin(), in.end());
        }
        else
            maps.push_back(args[i]);
    }
    const std::string dir = out_arg.getValue();
    if (dir.empty()) throw cl.usageError("--out needs a folder name");
    const bool force = opts.force();
    const Parameters params = opts.parameters();
    std::vector<std::string> inputs = maps;
    inputs.push_back(gt_path);
    inputs.push_back(opts.config());
    checkOutputFolder(dir, {"scores.csv", "scores.csv.part", "scores.png", "report.json"}, force,
                      inputs);
    opts.checkJsonImage();
    const std::string html_path = opts.html();
    if (!html_path.empty()) checkOutputPath(html_path, force, inputs);
    const LoadedMap gt = loadMapWarning(gt_path, params.map_load);
    // Every map is read once before the output folder is created, so that a bad one anywhere
    // in the list is bad input with nothing written. Reading is a small part of a map's
    // scoring (the graphs are most of it); the maps are not kept, to hold one at a time.
    for (const auto& m : maps) loadMapWarning(m, params.map_load);
    const TopologyGraph gt_graph = buildTopologyGraph(gt.grid, params.graph);

    // From here on: if the run fails before its first row, `folder` and `csv` remove what they
    // created (and only that).
    OutputFolder folder(dir);
    const auto out = [&](const std::string& name) { return folder.file(name); };
    ScoresCsv csv(out("scores.csv"));
    std::vector<ScoreRow> rows;
    std::vector<HtmlEntry> html_entries;
    try
    {
        for (std::size_t i = 0; i < maps.size(); ++i)
        {
            const LoadedMap m = loadMap(maps[i], params.map_load);
            const auto t0 = Clock::now();
            TopologyGraph graph;
            const QualityReport report = evaluate(gt_graph, gt.grid, m.grid, params, &graph);
            ScoreRow row = scoreRowFromReport(report);
            row.step = static_cast<int>(i) + 1;
            row.entry = numberInName(maps[i], i);
            row.time_s = std::numeric_limits<double>::quiet_NaN();
            row.scoring_ms = msSince(t0);
            csv.append(row);
            rows.push_back(row);
            if (!html_path.empty())
                html_entries.push_back(
                    makeHtmlEntry(maps[i], gt.grid, gt_graph, m.grid, graph, report, false, &row));
            std::cerr << "topoeval: series: " << (i + 1) << "/" << maps.size() << " " << maps[i]
                      << ": quality " << report.quality << ", coverage " << report.coverage << "\n";
        }
    }
    catch (...)
    {
        if (rows.empty()) throw;  // nothing scored: the folder is left as the run found it
        keepPartialRun(
            folder, csv, "maps",
            [&](const std::string& error) { return reportJson(gt_path, maps, rows, error); },
            force);
        throw;
    }
    folder.keep();
    csv.commit();
    writePngAtomic(out("scores.png"),
                   drawScorePlot(rows, "maps vs " + fs::path(gt_path).filename().string()), force);
    writeFileAtomic(out("report.json"), reportJson(gt_path, maps, rows, ""), force);
    if (!html_path.empty())
    {
        HtmlReportContent page;
        page.kind = HtmlReportContent::Kind::Series;
        page.title = "series of " + std::to_string(maps.size()) + " maps against " + gt_path;
        page.generator = versionLine();
        page.parameters_ini = iniText(params);
        page.ground_truth = makeHtmlMap(gt_path, gt.grid, gt_graph);
        page.entries = std::move(html_entries);
        writeFileAtomic(html_path, renderHtmlReport(page), force);
    }

    std::cout << "ground truth  " << gt_path << " (" << gt.format << ")\n";
    std::cout << "maps          " << maps.size() << "\n";
    char buf[160];
    std::snprintf(buf, sizeof(buf), "last          quality %.3f, coverage %.3f, brokenness %d\n",
                  rows.back().quality, rows.back().coverage, rows.back().brokenness);
    std::cout << buf;
    for (const char* name : {"scores.csv", "scores.png", "report.json"})
        std::cout << "wrote         " << out(name) << "\n";
    if (!html_path.empty()) std::cout << "wrote         " << html_path << "\n";
    flushStdout();
    return kExitOk;
}

}  // namespace mrpt_topoeval::cli
