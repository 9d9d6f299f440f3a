/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// `topoeval match GT MAP`: builds both maps' Topology Graphs, matches them (paper III) and
// prints the counts of the paper's Table II; optionally writes the match as JSON and as a
// picture like the paper's Fig. 5 and 7.

#include <mrpt_topoeval/GraphBuilder.h>
#include <mrpt_topoeval/GraphMatcher.h>
#include <mrpt_topoeval/VertexSimilarity.h>
#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/map_io.h>
#include <mrpt_topoeval/match_json.h>
#include <mrpt_topoeval/output.h>

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

/** One side of the match: its map file and Topology Graph. */
struct Side
{
    LoadedMap map;
    TopologyGraph graph;
};

/** Loads a map and builds its graph, timing both under "load_<role>" and "graph_<role>".
 * Warnings name the role too: GT and MAP may be the same file. */
Side loadSide(const std::string& path, const std::string& role, const Parameters& params,
              std::map<std::string, double>& timing_ms)
{
    auto t0 = Clock::now();
    Side s{loadMap(path, params.map_load), {}};
    timing_ms["load_" + role] = msSince(t0);
    t0 = Clock::now();
    s.graph = buildTopologyGraph(s.map.grid, params.graph);
    s.graph.map.file = s.map.file;
    timing_ms["graph_" + role] = msSince(t0);
    if (s.graph.vertices.empty() && s.graph.warnings.empty())
        s.graph.warnings.push_back("the Topology Graph is empty");
    std::string who = role;
    std::replace(who.begin(), who.end(), '_', ' ');
    for (const auto& w : s.graph.warnings) printWarning(s.map.file + " (" + who + "): " + w);
    return s;
}

/** The run's steps in pipeline order for the summary; steps not listed follow
 * alphabetically, so a new step still shows up. */
std::vector<std::pair<std::string, double>> orderedTimings(const std::map<std::string, double>& t)
{
    static const std::vector<std::string> kOrder = {"load_ground_truth",
                                                    "load_map",
                                                    "graph_ground_truth",
                                                    "graph_map",
                                                    "similarity",
                                                    "similarity_clouds",
                                                    "similarity_icp",
                                                    "isomorphism",
                                                    "neighbour_growing",
                                                    "match",
                                                    "draw",
                                                    "total"};
    std::vector<std::pair<std::string, double>> out;
    for (const auto& name : kOrder)
        if (const auto it = t.find(name); it != t.end()) out.emplace_back(*it);
    for (const auto& kv : t)
        if (std::find(kOrder.begin(), kOrder.end(), kv.first) == kOrder.end()) out.emplace_back(kv);
    return out;
}

void printSide(std::ostream& os, const char* label, const Side& s)
{
    os << label << s.map.file << " (" << s.map.format << "): " << s.graph.vertices.size()
       << " vertices (" << s.graph.numNonSpuriousVertices() << " non-spurious), "
       << s.graph.numHalfEdges() << " half edges\n";
}

void printSummary(std::ostream& os, const Side& gt, const Side& map, SimilarityMode mode,
                  const GraphMatch& match, const std::map<std::string, double>& timing_ms,
                  const std::vector<std::string>& written)
{
    printSide(os, "ground truth  ", gt);
    printSide(os, "map           ", map);
    os << "similarity    " << toString(mode) << "\n";
    // The columns of the paper's Table II.
    os << "matches       isomorphism " << match.isomorphism << ", neighbour growing "
       << match.neighbour_growing << ", missing " << match.missing << "\n";
    os << "isomorphisms  ";
    if (match.isomorphism_sizes.empty())
        os << "none";
    else
    {
        os << match.isomorphism_sizes.size() << ", sizes ";
        for (std::size_t i = 0; i < match.isomorphism_sizes.size(); ++i)
            os << (i ? ", " : "") << match.isomorphism_sizes[i];
    }
    os << "\n";
    os << "time [ms]     ";
    bool first = true;
    for (const auto& [step, ms] : orderedTimings(timing_ms))
    {
        os << (first ? "" : ", ") << step << " " << fmt("%.1f", ms);
        first = false;
    }
    os << "\n";
    for (const auto& w : written) os << "wrote         " << w << "\n";
}
}  // namespace

int verbMatch(int argc, char** argv)
{
    const auto t_run = Clock::now();
    VerbCommandLine cl(
        "match",
        "Matches the Topology Graph of a map against that of a ground-truth map (Schwertfeger "
        "& Birk 2013, section III): vertex similarity, subgraph isomorphisms, neighbour "
        "growing. Prints both graphs' sizes and the matches per stage (isomorphism, neighbour "
        "growing, missing: the paper's Table II). --json writes the match (vertex ids as "
        "'topoeval graph --json' prints them for the same maps and configuration), --image "
        "draws both maps side by side with a line per match, green for isomorphism and red "
        "for neighbour growing. GT and MAP may be the same file. Existing files are never "
        "replaced without --force; outputs are written only after everything succeeded. Exit "
        "codes: 0 ok, 1 internal error, 2 bad input or usage, 3 output error.");
    TCLAP::CmdLine& cmd = cl.cmd();
    // Declared in reverse order of the usage line (TCLAP lists the last added first).
    TCLAP::SwitchArg force_arg("f", "force", "Replace existing output files.", cmd);
    TCLAP::ValueArg<std::string> image_arg("i", "image",
                                           "Draw both maps and the match lines into this PNG file.",
                                           false, "", "OUT.png", cmd);
    TCLAP::ValueArg<std::string> json_arg("j", "json", "Write the match as JSON to this file.",
                                          false, "", "OUT.json", cmd);
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
                            "; unexpected '" + maps[2] + "'");
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
    const Side gt = loadSide(gt_path, "ground_truth", params, timing_ms);
    const Side map = loadSide(map_path, "map", params, timing_ms);

    auto t0 = Clock::now();
    std::map<std::string, double> icp_timing_ms;
    const SimilarityMatrix similarity =
        params.similarity.mode == SimilarityMode::Icp
            ? icpSimilarity(gt.graph, gt.map.grid, map.graph, map.map.grid, params.similarity,
                            &icp_timing_ms)
            : attributeSimilarity(gt.graph, map.graph, params.similarity);
    timing_ms["similarity"] = msSince(t0);
    for (const auto& [step, ms] : icp_timing_ms)
        if (step != "total") timing_ms["similarity_" + step] = ms;

    const GraphMatch match = matchGraphs(gt.graph, map.graph, similarity, params.matcher);
    // The matcher's stages as they are; its "total" is the whole matching call.
    for (const auto& [step, ms] : match.timing_ms) timing_ms[step == "total" ? "match" : step] = ms;
    for (const auto& msg : match.messages) printWarning(msg);

    // Everything is produced in memory first: a failure leaves no output behind.
    mrpt::img::CImage picture;
    if (!image_path.empty())
    {
        t0 = Clock::now();
        DrawOptions draw;
        // The outer boundary is green like the isomorphism's match lines: left out here.
        draw.draw_boundary = false;
        picture = drawMatch(gt.map.grid, gt.graph, map.map.grid, map.graph, match, draw);
        timing_ms["draw"] = msSince(t0);
    }
    timing_ms["total"] = msSince(t_run);
    std::string json_text;
    if (!json_path.empty()) json_text = matchToJson(gt.graph, map.graph, match, &timing_ms);

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

    printSummary(std::cout, gt, map, params.similarity.mode, match, timing_ms, written);
    flushStdout();
    return kExitOk;
}

}  // namespace mrpt_topoeval::cli
