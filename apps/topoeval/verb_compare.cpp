/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// `topoeval compare GT MAP`: the quality of a map against a ground truth (paper IV): coverage,
// accuracies, local consistency, brokenness and one quality score, printed as a brief (or,
// with --verbose, full) report; optionally written as JSON and drawn like the paper's Fig. 7.

#include <mrpt_topoeval/QualityEvaluator.h>
#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/map_io.h>
#include <mrpt_topoeval/output.h>
#include <mrpt_topoeval/report_json.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "cli_common.h"

namespace fs = std::filesystem;

namespace mrpt_topoeval::cli
{
namespace
{
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

std::string fmt(const char* format, double v)
{
    char buf[64];
    std::snprintf(buf, sizeof(buf), format, v);
    return buf;
}

bool endsWithPng(const std::string& path)
{
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return ext == ".png";
}

/** The run's steps in pipeline order for the summary; steps not listed follow
 * alphabetically, so a new step still shows up. */
std::vector<std::pair<std::string, double>> orderedTimings(const std::map<std::string, double>& t)
{
    static const std::vector<std::string> kOrder = {"load_ground_truth", "load_map", "graphs",
                                                    "similarity",        "match",    "evaluation",
                                                    "evaluate",          "draw",     "total"};
    std::vector<std::pair<std::string, double>> out;
    for (const auto& name : kOrder)
        if (const auto it = t.find(name); it != t.end()) out.emplace_back(*it);
    for (const auto& kv : t)
        if (std::find(kOrder.begin(), kOrder.end(), kv.first) == kOrder.end()) out.emplace_back(kv);
    return out;
}

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
        "numbered by its brokenness group (the paper's Fig. 7). A map that matches nothing "
        "gives coverage 0 and quality 0 with a warning, and exit code 0. Existing files are "
        "never replaced without --force; outputs are written only after everything succeeded. "
        "Exit codes: 0 ok, 1 internal error, 2 bad input or usage, 3 output error.");
    TCLAP::CmdLine& cmd = cl.cmd();
    // Declared in reverse order of the usage line (TCLAP lists the last added first).
    TCLAP::SwitchArg force_arg("f", "force", "Replace existing output files.", cmd);
    TCLAP::ValueArg<std::string> image_arg(
        "i", "image",
        "Draw both maps, the match lines and the brokenness groups into this PNG file.", false, "",
        "OUT.png", cmd);
    TCLAP::ValueArg<std::string> json_arg("j", "json", "Write the report as JSON to this file.",
                                          false, "", "OUT.json", cmd);
    // No short form: TCLAP keeps -v for --version.
    TCLAP::SwitchArg verbose_arg(
        "", "verbose",
        "Print the full report: every consistency class, every brokenness group, the "
        "alignment, notes and the time per step.",
        cmd);
    TCLAP::ValueArg<int> threads_arg(
        "", "threads",
        "Worker threads for ICP similarity, 0 = all cores; overrides [VertexSimilarity] "
        "threads. Results do not depend on it.",
        false, 0, "N", cmd);
    TCLAP::ValueArg<std::string> similarity_arg(
        "s", "similarity",
        "Vertex similarity: 'attributes' (fast) or 'icp' (obstacles around each vertex aligned "
        "by ICP); overrides [VertexSimilarity] mode (default attributes).",
        false, "", "attributes|icp", cmd);
    TCLAP::ValueArg<double> res_arg(
        "r", "resolution",
        "Cell size for plain images and .simplemap files [m/cell]; overrides [MapLoad] "
        "resolution_m (default 0.05).",
        false, 0.0, "R", cmd);
    TCLAP::ValueArg<std::string> config_arg(
        "c", "config", "Parameters from this INI file (see 'topoeval config').", false, "", "F.ini",
        cmd);
    // One argument for both files: TCLAP allows a single optional unlabeled argument, and
    // checking the count ourselves names what is missing.
    TCLAP::UnlabeledMultiArg<std::string> maps_arg(
        "GT_MAP",
        "Exactly two maps: the ground truth, then the map to evaluate. ROS map_server .yaml, "
        "image (.png .pgm .bmp .jpg), MRPT .gridmap[.gz] or .simplemap[.gz].",
        false, "GT MAP", cmd);
    if (const auto done = cl.parse(argc, argv)) return *done;

    const std::vector<std::string>& maps = maps_arg.getValue();
    if (maps.empty()) throw cl.usageError("missing the GT and MAP arguments");
    if (maps.size() == 1) throw cl.usageError("missing the MAP argument");
    if (maps.size() > 2)
        throw cl.usageError("expected two maps (GT MAP), got " + std::to_string(maps.size()) +
                            "; unexpected '" + maps[2] +
                            "'; to score several maps use "
                            "'topoeval rank'");
    const std::string gt_path = maps[0], map_path = maps[1];
    if (gt_path.empty()) throw cl.usageError("the GT argument is empty");
    if (map_path.empty()) throw cl.usageError("the MAP argument is empty");
    const std::string json_path = json_arg.getValue();
    const std::string image_path = image_arg.getValue();
    const bool force = force_arg.getValue();
    if (json_arg.isSet() && json_path.empty()) throw cl.usageError("--json needs a file name");
    if (image_arg.isSet() && image_path.empty()) throw cl.usageError("--image needs a file name");
    if (!image_path.empty() && !endsWithPng(image_path))
        throw cl.usageError("--image " + image_path + ": pictures are PNG; use a .png file name");
    if (!json_path.empty() && !image_path.empty() &&
        fs::absolute(json_path).lexically_normal() == fs::absolute(image_path).lexically_normal())
        throw cl.usageError("--json and --image name the same file " + json_path);
    // The same bounds as [VertexSimilarity] threads, reported as the option the user typed.
    if (threads_arg.isSet() && (threads_arg.getValue() < 0 || threads_arg.getValue() > 256))
        throw cl.usageError("--threads " + std::to_string(threads_arg.getValue()) +
                            " violates 0 <= N <= 256");
    const std::string similarity_mode = similarity_arg.getValue();
    if (similarity_arg.isSet() && similarity_mode != "attributes" && similarity_mode != "icp")
        throw cl.usageError("--similarity '" + similarity_mode +
                            "' is not one of: attributes, icp");

    Parameters params =
        loadParameters(config_arg.getValue(),
                       res_arg.isSet() ? std::optional<double>(res_arg.getValue()) : std::nullopt);
    if (similarity_arg.isSet()) params.similarity.mode = similarityModeFromString(similarity_mode);
    if (threads_arg.isSet()) params.similarity.threads = threads_arg.getValue();
    params.validate();

    // Refuse unwritable outputs now rather than after the work.
    const std::vector<std::string> inputs = {gt_path, map_path, config_arg.getValue()};
    if (!json_path.empty()) checkOutputPath(json_path, force, inputs);
    if (!image_path.empty()) checkOutputPath(image_path, force, inputs);

    std::map<std::string, double> timing_ms;
    auto t0 = Clock::now();
    const LoadedMap gt = loadMap(gt_path, params.map_load);
    timing_ms["load_ground_truth"] = msSince(t0);
    t0 = Clock::now();
    const LoadedMap map = loadMap(map_path, params.map_load);
    timing_ms["load_map"] = msSince(t0);

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
        t0 = Clock::now();
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

    std::vector<std::string> written;
    if (!json_path.empty())
    {
        writeFileAtomic(json_path, json_text, force);
        written.push_back(json_path);
    }
    if (!image_path.empty())
    {
        writePngAtomic(image_path, picture, force);
        written.push_back(image_path);
    }

    std::ostream& os = std::cout;
    printSide(os, "ground truth  ", gt, gt_graph);
    printSide(os, "map           ", map, map_graph);
    os << "similarity    " << toString(params.similarity.mode) << "\n\n";
    const bool verbose = verbose_arg.getValue();
    os << (verbose ? report.fullReport() : report.briefReport());
    if (verbose)
    {
        os << "time [ms]   ";
        bool first = true;
        for (const auto& [step, ms] : orderedTimings(timing_ms))
        {
            os << (first ? "" : ", ") << step << " " << fmt("%.1f", ms);
            first = false;
        }
        os << "\n";
    }
    for (const auto& w : written) os << "wrote       " << w << "\n";
    flushStdout();
    return kExitOk;
}

}  // namespace mrpt_topoeval::cli
