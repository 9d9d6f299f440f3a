/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// `topoeval rawlog RAWLOG --ground-truth GT`: MRPT's ICP-SLAM on a rawlog, the grid scored
// against the ground truth every N scans (doc/rawlog.md). Rows are written as they come; a
// Ctrl-C or a damaged rawlog ends the reading but never the outputs.

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/html_report.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <mrpt_topoeval/output.h>
#include <mrpt_topoeval/pipeline/RawlogScorer.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli_common.h"
#include "cli_options.h"
#include "rawlog_report.h"
#include "scores_output.h"

namespace fs = std::filesystem;

namespace mrpt_topoeval::cli
{
namespace
{
// Set by SIGINT; the scorer checks it between entries. The handler does nothing else but
// restore the default action, so that a second Ctrl-C ends the program at once.
std::atomic<bool> g_stop{false};
extern "C" void onSigint(int)
{
    g_stop.store(true);
    std::signal(SIGINT, SIG_DFL);
}

/** Installs the handler for the run's duration. */
struct SigintScope
{
    using Handler = void (*)(int);
    Handler previous;
    SigintScope() : previous(std::signal(SIGINT, onSigint)) { g_stop = false; }
    ~SigintScope() { std::signal(SIGINT, previous == SIG_ERR ? SIG_DFL : previous); }
};

/** A bar on a terminal, a plain line every few seconds otherwise (logs, CI). */
class Progress
{
public:
    Progress() : m_tty(isatty(STDERR_FILENO) == 1), m_last(std::chrono::steady_clock::now()) {}

    void update(const RawlogProgress& p, bool final)
    {
        const auto now = std::chrono::steady_clock::now();
        const double since = std::chrono::duration<double>(now - m_last).count();
        if (!final && since < (m_tty ? 0.2 : 5.0)) return;
        m_last = now;
        const double rate = p.elapsed_s > 0 ? static_cast<double>(p.scans) / p.elapsed_s : 0.0;
        std::string eta;
        if (p.compressed_fraction > 0.0 && p.compressed_fraction < 1.0)
            eta = ", ETA " + fmt("%.0f s", p.elapsed_s * (1.0 - p.compressed_fraction) /
                                               p.compressed_fraction);
        const std::string stats = std::to_string(p.scans) + " scans, " + std::to_string(p.entries) +
                                  " entries, " + fmt("%.0f scans/s", rate) + eta;
        if (m_tty)
        {
            std::string bar;
            if (p.compressed_fraction >= 0.0)
            {
                const int filled = static_cast<int>(p.compressed_fraction * 30.0 + 0.5);
                bar = "[" + std::string(filled, '#') + std::string(30 - filled, '.') + "] " +
                      fmt("%3.0f%% ", 100.0 * p.compressed_fraction);
            }
            std::cerr << "\r" << bar << stats << "   " << (final ? "\n" : "") << std::flush;
        }
        else
            std::cerr << "topoeval: rawlog: " << stats << "\n" << std::flush;
    }

    /** Ends the bar's line on a terminal, so that a message does not land on it. */
    void endLine()
    {
        if (m_tty) std::cerr << "\n" << std::flush;
    }

private:
    bool m_tty;
    std::chrono::steady_clock::time_point m_last;
};

/** The files of DIR, checked before the run; `scores.csv.part` holds the rows of a run that
 * was killed, which are results too. */
const std::vector<std::string> kOutputNames = {"scores.csv", "scores.csv.part",  "report.json",
                                               "scores.png", "final.gridmap.gz", "final.simplemap",
                                               "final.png",  "snapshots/"};

}  // namespace

int verbRawlog(int argc, char** argv)
{
    VerbCommandLine cl(
        "rawlog",
        "Runs MRPT's ICP-SLAM (CMetricMapBuilderICP) on a rawlog (action/sensory-frame or "
        "observation-only format, gz or plain) and scores the occupancy grid built so far "
        "against the ground truth every N scans and at the end, with the same code as "
        "'compare'. Real-data quirks are repaired and counted: odometry without timestamps "
        "gets its scan's time, equal or decreasing timestamps are made increasing, scans "
        "without odometry and objects ICP-SLAM does not use are counted. Outputs in DIR: "
        "scores.csv (one row per snapshot, written as they come), report.json, scores.png, "
        "final.gridmap.gz, final.simplemap (ICP-SLAM's keyframes: poses and scans, as "
        "icp-slam saves them), final.png; with --snapshots each snapshot's map and match picture "
        "in DIR/snapshots/; --html one self-contained web page with the scores over time, each "
        "snapshot's map and match and the final map (doc/report.md). Existing outputs are never "
        "replaced without --force. The rawlog is "
        "read up to its first scan before DIR is created: bad input leaves nothing behind. "
        "Ctrl-C or a truncated/corrupt rawlog stops reading; the map built so far is scored "
        "and every output written. Exit codes: 0 ok, 1 internal error, 2 bad input or usage, 3 "
        "output error, 4 stopped early (Ctrl-C, or truncated/corrupt rawlog): outputs for the "
        "part done were written.");
    TCLAP::CmdLine& cmd = cl.cmd();
    // Declared in reverse order of the usage line (TCLAP lists the last added first).
    TCLAP::SwitchArg print_slam_arg(
        "", "print-slam-config",
        "Print the default ICP-SLAM configuration (an icp-slam INI) and exit.", cmd);
    StandardOptions std_opts(cl);
    std_opts.addForce();
    std_opts.addHtml(
        "Write one self-contained web page to this file: the scores over time, each snapshot's "
        "map and match (a slider), the final map.");
    TCLAP::ValueArg<std::size_t> max_entries_arg(
        "", "max-entries", "Read at most this many rawlog entries (0 = all).", false, 0, "N", cmd);
    TCLAP::SwitchArg snapshots_arg(
        "", "snapshots", "Also write each snapshot's map and match picture in DIR/snapshots/.",
        cmd);
    TCLAP::ValueArg<std::string> out_arg("o", "out", "Output folder (default: rawlog-scores).",
                                         false, "rawlog-scores", "DIR", cmd);
    TCLAP::ValueArg<std::size_t> every_arg(
        "e", "every", "Score a snapshot every N scans, and at the end (default 100).", false, 100,
        "N", cmd);
    std_opts.addConfig("topoeval parameters from this INI file (see 'topoeval config').");
    TCLAP::ValueArg<std::string> slam_arg(
        "s", "slam-config",
        "ICP-SLAM configuration: an icp-slam INI ([MappingApplication], [ICP]); default: "
        "--print-slam-config.",
        false, "", "F.ini", cmd);
    TCLAP::ValueArg<std::string> gt_arg("g", "ground-truth",
                                        "The ground-truth map (any format 'compare' reads).", false,
                                        "", "GT", cmd);
    TCLAP::UnlabeledValueArg<std::string> rawlog_arg(
        "RAWLOG", "The MRPT rawlog (.rawlog or .rawlog.gz).", false, "", "RAWLOG", cmd);
    if (const auto done = cl.parse(argc, argv)) return *done;

    if (print_slam_arg.getValue())
    {
        std::cout << RawlogScorer::defaultSlamIniText();
        flushStdout();
        return kExitOk;
    }
    const std::string rawlog_path = rawlog_arg.getValue();
    const std::string gt_path = gt_arg.getValue();
    if (rawlog_path.empty()) throw cl.usageError("missing the RAWLOG argument");
    if (gt_path.empty()) throw cl.usageError("missing --ground-truth GT");
    if (every_arg.getValue() < 1) throw cl.usageError("--every 0 violates N >= 1");
    const std::string dir = out_arg.getValue();
    if (dir.empty()) throw cl.usageError("--out needs a folder name");
    const bool force = std_opts.force();

    const Parameters params = std_opts.parameters();
    // Outputs are checked first, as by every verb, but nothing is created until the inputs
    // have passed their checks: bad input must not leave an empty DIR behind.
    const std::vector<std::string> inputs = {rawlog_path, gt_path, slam_arg.getValue(),
                                             std_opts.config()};
    checkOutputFolder(dir, kOutputNames, force, inputs);
    std_opts.checkJsonImage();
    const std::string html_path = std_opts.html();
    if (!html_path.empty()) checkOutputPath(html_path, force, inputs);
    std::error_code ec;  // the non-throwing overload: a bad name is bad input, not a crash
    if (!fs::exists(rawlog_path, ec)) throw InputError(rawlog_path + ": no such file");
    const LoadedMap gt = loadMapWarning(gt_path, params.map_load);

    RawlogScorerOptions opts;
    opts.every_scans = every_arg.getValue();
    opts.max_entries = max_entries_arg.getValue();
    opts.slam_config_file = slam_arg.getValue();
    opts.keep_snapshot_graphs = snapshots_arg.getValue() || !html_path.empty();
    RawlogScorer scorer(opts, params);
    // The SLAM configuration, and the rawlog up to its first scan: what the run would refuse
    // as bad input (not a rawlog, empty, cut in its first entry, no scan) is refused now.
    const RawlogProbe probe = scorer.probe(rawlog_path);

    // From here on the folder and what is in it are this run's: if it fails before its first
    // snapshot, `folder` and `csv` remove what they created (and only that).
    OutputFolder folder(dir);
    const std::string snap_dir =
        snapshots_arg.getValue() ? folder.createSubfolder("snapshots") : std::string();
    const auto out = [&](const std::string& name) { return folder.file(name); };

    ScoresCsv csv(out("scores.csv"));
    std::vector<std::string> written;
    ScoreRow last_row;
    std::vector<HtmlEntry> html_entries;
    // Snapshots are pictured smaller than the final map: a long run has many.
    HtmlReportOptions snapshot_html;
    snapshot_html.max_map_px = 1024;
    const auto snapshotName = [](const ScoreRow& row) {
        return "snapshot " + std::to_string(row.step) + " (entry " + std::to_string(row.entry) +
               ")";
    };
    scorer.onSnapshot(
        [&](const Snapshot& s)
        {
            csv.append(s.row);
            last_row = s.row;
            if (!html_path.empty())
                html_entries.push_back(makeHtmlEntry(snapshotName(s.row), gt.grid, s.gt_graph,
                                                     s.grid, s.map_graph, s.report, false, &s.row,
                                                     snapshot_html));
            if (!snapshots_arg.getValue()) return;
            char stem[32];
            std::snprintf(stem, sizeof(stem), "step_%04d", s.row.step);
            writeGridMapGz((fs::path(snap_dir) / (std::string(stem) + ".gridmap.gz")).string(),
                           s.grid, force);
            DrawOptions draw;
            draw.draw_boundary = false;
            writePngAtomic(
                (fs::path(snap_dir) / (std::string(stem) + "_match.png")).string(),
                drawQualityReport(gt.grid, s.gt_graph, s.grid, s.map_graph, s.report, draw), force);
        });
    Progress progress;
    scorer.onProgress([&](const RawlogProgress& p) { progress.update(p, false); });

    RawlogRun run;
    run.rawlog = rawlog_path;
    run.ground_truth = gt_path;
    run.options = opts;
    run.topoeval_config_file = std_opts.config();
    run.topoeval_ini = iniText(params);

    RawlogScoreResult res;
    try
    {
        const SigintScope sigint;
        res = scorer.run(rawlog_path, gt.grid, &g_stop);
    }
    catch (...)
    {
        progress.endLine();
        // Nothing scored yet: rethrown, the folder is left as the run found it.
        if (csv.rows() == 0) throw;
        // Snapshots were scored: they are results. What the scorer had not returned yet (its
        // counters, the final report) is null in report.json.
        keepPartialRun(
            folder, csv, "snapshots",
            [&](const std::string& error)
            { return rawlogErrorReportJson(run, error, csv.rows(), probe, last_row); },
            force);
        throw;
    }
    folder.keep();
    {
        RawlogProgress last;
        last.entries = res.stats.entries;
        last.scans = res.stats.scans;
        last.compressed_fraction = -1.0;
        last.elapsed_s = res.total_ms / 1000.0;
        progress.update(last, true);
    }
    for (const auto& m : res.messages) printWarning(m);

    csv.commit();
    written.push_back(out("scores.csv"));
    writeGridMapGz(out("final.gridmap.gz"), res.final_grid, force);
    written.push_back(out("final.gridmap.gz"));
    writeSerializedGz(out("final.simplemap"), res.final_keyframes, force);
    written.push_back(out("final.simplemap"));
    writeGridPng(out("final.png"), res.final_grid, force);
    written.push_back(out("final.png"));
    writePngAtomic(out("scores.png"),
                   drawScorePlot(res.rows, fs::path(rawlog_path).filename().string() + " vs " +
                                               fs::path(gt_path).filename().string()),
                   force);
    written.push_back(out("scores.png"));

    // report.json: run summary, effective configuration, final scores.
    writeFileAtomic(out("report.json"), rawlogReportJson(run, res, params), force);
    written.push_back(out("report.json"));
    if (!html_path.empty())
    {
        HtmlReportContent page;
        page.kind = HtmlReportContent::Kind::Rawlog;
        page.title = "rawlog " + rawlog_path + " against " + gt_path;
        page.generator = versionLine();
        page.parameters_ini = run.topoeval_ini;
        page.extra_ini = res.effective_slam_ini;
        page.messages = res.messages;
        if (res.stop != RawlogStop::EndOfFile)
            page.messages.push_back("stopped at entry " + std::to_string(res.stop_entry) + " (" +
                                    toString(res.stop) + "): " + res.stop_message);
        page.ground_truth = makeHtmlMap(gt_path, gt.grid, res.final_gt_graph);
        // The final map at full size (the last snapshot is the final map).
        if (!html_entries.empty() && !res.rows.empty())
            html_entries.back() = makeHtmlEntry(
                snapshotName(res.rows.back()), gt.grid, res.final_gt_graph, res.final_grid,
                res.final_map_graph, res.final_report, false, &res.rows.back());
        page.entries = std::move(html_entries);
        writeFileAtomic(html_path, renderHtmlReport(page), force);
        written.push_back(html_path);
    }

    // Summary.
    const RawlogStats& s = res.stats;
    std::cout << "rawlog        " << rawlog_path << " (" << s.format << "): " << s.entries
              << " entries, " << s.scans << " scans, " << s.odometry << " odometry\n";
    std::cout << "ground truth  " << gt_path << " (" << gt.format << ")\n";
    std::cout << "repaired      " << s.odometry_stamped << " untimed odometry stamped, "
              << s.odometry_restamped << " odometry and " << s.scans_restamped
              << " scans restamped, " << s.scans_without_odometry << " scans without odometry\n";
    std::cout << "skipped       " << s.unknown_objects << " unknown objects, "
              << s.other_observations << " other observations, " << s.skipped_before_offset
              << " before rawlog_offset\n";
    if (!res.rows.empty())
    {
        const ScoreRow& f = res.rows.back();
        std::cout << "final         quality " << fmt("%.3f", f.quality) << ", coverage "
                  << fmt("%.3f", f.coverage) << ", relative accuracy "
                  << fmt("%.3f", f.relative_accuracy) << ", brokenness " << f.brokenness << " ("
                  << res.rows.size() << " snapshots)\n";
    }
    std::cout << "time [ms]     slam " << fmt("%.0f", res.slam_ms) << ", scoring "
              << fmt("%.0f", res.scoring_ms) << ", total " << fmt("%.0f", res.total_ms) << "\n";
    for (const auto& w : written) std::cout << "wrote         " << w << "\n";
    if (res.stop != RawlogStop::EndOfFile)
        std::cout << "stopped       at entry " << res.stop_entry << ": " << res.stop_message
                  << "\n";
    flushStdout();
    if (res.stop == RawlogStop::EndOfFile || res.stop == RawlogStop::MaxEntries) return kExitOk;
    printWarning("stopped at entry " + std::to_string(res.stop_entry) + " (" + toString(res.stop) +
                 "): " + res.stop_message + "; outputs for the part done were written");
    return kExitStoppedEarly;
}

}  // namespace mrpt_topoeval::cli
