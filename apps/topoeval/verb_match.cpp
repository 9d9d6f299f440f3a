/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// `topoeval match GT MAP`: builds both maps' Topology Graphs, matches them (paper III) and
// prints the counts of the paper's Table II; optionally writes the match as JSON and as a
// picture like the paper's Fig. 5 and 7.

#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <mrpt_topoeval/match_json.h>
#include <mrpt_topoeval/matching/match_graphs.h>
#include <mrpt_topoeval/output.h>
#include <mrpt_topoeval/pipeline/evaluate.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

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
    Side s{loadMapTimed(path, params.map_load, timing_ms["load_" + role]), {}};
    const auto t0 = Clock::now();
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
    // The run's steps in pipeline order.
    os << "time [ms]     "
       << timingList(orderedTimings(
              timing_ms, {"load_ground_truth", "load_map", "graph_ground_truth", "graph_map",
                          "similarity", "similarity_clouds", "similarity_icp", "isomorphism",
                          "neighbour_growing", "match", "draw", "total"}))
       << "\n";
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
    StandardOptions opts(cl);
    // Declared in reverse order of the usage line (TCLAP lists the last added first).
    opts.addForce();
    opts.addImage("Draw both maps and the match lines into this PNG file.");
    opts.addJson("Write the match as JSON to this file.");
    opts.addThreads();
    opts.addSimilarity();
    opts.addResolution();
    opts.addConfig();
    opts.addGtAndMap();
    if (const auto done = cl.parse(argc, argv)) return *done;

    const auto [gt_path, map_path, params] = opts.gtAndMapRun();
    const std::string json_path = opts.json();
    const std::string image_path = opts.image();

    std::map<std::string, double> timing_ms;
    const Side gt = loadSide(gt_path, "ground_truth", params, timing_ms);
    const Side map = loadSide(map_path, "map", params, timing_ms);

    auto t0 = Clock::now();
    std::map<std::string, double> icp_timing_ms;
    const SimilarityMatrix similarity = vertexSimilarity(
        gt.graph, gt.map.grid, map.graph, map.map.grid, params.similarity, &icp_timing_ms);
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

    const std::vector<std::string> written = opts.writeOutputs(json_text, picture);

    printSummary(std::cout, gt, map, params.similarity.mode, match, timing_ms, written);
    flushStdout();
    return kExitOk;
}

}  // namespace mrpt_topoeval::cli
