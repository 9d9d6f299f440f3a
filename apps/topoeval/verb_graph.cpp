/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// `topoeval graph MAP`: builds the Topology Graph of one map, prints a one-screen summary and
// optionally writes it as JSON, as a picture, and as one picture per construction step.

#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/graph_json.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <mrpt_topoeval/output.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "cli_common.h"
#include "cli_options.h"

namespace fs = std::filesystem;

namespace mrpt_topoeval::cli
{
namespace
{
// Pictures stay below ~64 megapixels by default: 2 px per cell, 1 for big maps.
constexpr int kLargeMapCells = 4000;

/** The graph builder's steps in pipeline order for the summary, the builder's total last. */
std::vector<std::pair<std::string, double>> orderedGraphTimings(
    const std::map<std::string, double>& t)
{
    static const std::vector<std::string> kOrder = {
        "load_map",  "classify",          "voronoi", "chains",    "prune",
        "alpha_cut", "largest_component", "join",    "attributes"};
    std::map<std::string, double> steps = t;
    steps.erase("total");
    auto out = cli::orderedTimings(steps, kOrder);
    if (const auto it = t.find("total"); it != t.end()) out.emplace_back("build total", it->second);
    return out;
}

void printSummary(std::ostream& os, const LoadedMap& lm, const TopologyGraph& g,
                  const std::map<std::string, double>& timing_ms, double run_ms,
                  const std::vector<std::string>& written)
{
    const MapInfo& m = g.map;
    os << "map        " << lm.file << " (" << lm.format << ")\n";
    os << "size       " << m.size_x << " x " << m.size_y << " cells, "
       << fmt("%.2f", m.x_max_m - m.x_min_m) << " x " << fmt("%.2f", m.y_max_m - m.y_min_m)
       << " m, " << fmt("%g", m.resolution_m) << " m/cell\n";
    os << "extent     x " << fmt("%.2f", m.x_min_m) << " .. " << fmt("%.2f", m.x_max_m) << " m, y "
       << fmt("%.2f", m.y_min_m) << " .. " << fmt("%.2f", m.y_max_m) << " m\n";
    os << "cells      " << m.occupied_cells << " occupied, " << m.free_cells << " free\n";
    os << "vertices   " << g.vertices.size() << " (" << g.numNonSpuriousVertices()
       << " non-spurious)\n";
    os << "edges      " << g.numHalfEdges() << " half edges (" << g.edges.size()
       << " edges), total length " << fmt("%.2f", g.totalEdgeLength()) << " m\n";
    os << "degrees    ";
    const auto hist = g.degreeHistogram();
    bool any = false;
    for (std::size_t d = 0; d < hist.size(); ++d)
        if (hist[d] > 0)
        {
            os << (any ? ", " : "") << "deg " << d << ": " << hist[d];
            any = true;
        }
    os << (any ? " (non-spurious vertices)" : "none") << "\n";
    os << "time [ms]  ";
    for (const auto& [step, ms] : orderedGraphTimings(timing_ms))
        os << step << " " << fmt("%.1f", ms) << ", ";
    os << "run " << fmt("%.1f", run_ms) << "\n";
    for (const auto& w : written) os << "wrote      " << w << "\n";
}

/** The builder's steps as GraphBuildObserver reports them, in order (GraphBuilder.h); --steps
 * writes step i as "NN_<step>.png", NN = i + 1. */
const std::vector<std::string>& buildSteps()
{
    static const std::vector<std::string> kSteps = {"voronoi", "pruned", "alpha_cut",
                                                    "largest_component", "joined"};
    return kSteps;
}

std::string stepPicturePath(const std::string& dir, std::size_t index)
{
    const std::string number = std::to_string(index + 1);
    const std::string prefix = (number.size() < 2 ? "0" : "") + number + "_";
    return (fs::path(dir) / (prefix + buildSteps()[index] + ".png")).string();
}

}  // namespace

int verbGraph(int argc, char** argv)
{
    const auto t_run = Clock::now();
    VerbCommandLine cl(
        "graph",
        "Builds the Topology Graph of a grid map (Schwertfeger & Birk 2013, section II) and "
        "prints a summary: vertices, half edges, total edge length, degrees, time per step. "
        "--json writes the graph (coordinates in metres in the map's frame), --image draws it "
        "over the map, --steps draws it after each construction step. Existing files are never "
        "replaced without --force; outputs are written only after everything succeeded. Exit "
        "codes: 0 ok, 1 internal error, 2 bad input or usage, 3 output error.");
    TCLAP::CmdLine& cmd = cl.cmd();
    // Declared in reverse order of the usage line (TCLAP lists the last added first).
    StandardOptions opts(cl);
    opts.addForce();
    TCLAP::SwitchArg no_ids_arg("", "no-ids", "Do not write vertex ids in the pictures.", cmd);
    TCLAP::ValueArg<std::string> steps_arg(
        "", "steps",
        "Draw the graph after each construction step into this folder (created if missing): "
        "01_voronoi.png, 02_pruned.png, 03_alpha_cut.png, 04_largest_component.png, "
        "05_joined.png (the final graph).",
        false, "", "DIR", cmd);
    TCLAP::ValueArg<int> scale_arg("", "image-scale",
                                   "Pixels per map cell in the --image and --steps pictures, 1..8 "
                                   "(default: 2; 1 for maps over " +
                                       std::to_string(kLargeMapCells) + " cells wide or high).",
                                   false, 0, "N", cmd);
    opts.addImage("Draw the graph over the map into this PNG file.");
    opts.addJson("Write the graph as JSON to this file.");
    opts.addResolution();
    opts.addConfig();
    TCLAP::UnlabeledValueArg<std::string> map_arg(
        "MAP",
        "The map: ROS map_server .yaml, image (.png .pgm .bmp .jpg), MRPT .gridmap[.gz] or "
        ".simplemap[.gz].",
        false, "", "MAP", cmd);
    if (const auto done = cl.parse(argc, argv)) return *done;

    const std::string map_path = map_arg.getValue();
    if (map_path.empty()) throw cl.usageError("missing the MAP argument");
    const std::string json_path = opts.json();
    const std::string image_path = opts.image();
    const bool force = opts.force();
    opts.checkJsonImage();
    if (scale_arg.isSet() && (scale_arg.getValue() < 1 || scale_arg.getValue() > 8))
        throw cl.usageError("--image-scale " + std::to_string(scale_arg.getValue()) +
                            " violates 1 <= N <= 8");
    const std::string steps_dir = steps_arg.getValue();
    if (steps_arg.isSet() && steps_dir.empty()) throw cl.usageError("--steps needs a folder name");
    std::vector<std::string> step_paths;
    if (!steps_dir.empty())
        for (std::size_t i = 0; i < buildSteps().size(); ++i)
            step_paths.push_back(stepPicturePath(steps_dir, i));

    // No two outputs may name the same file.
    OutputList outputs = opts.outputs();
    for (const auto& p : step_paths) outputs.emplace_back("--steps", p);
    checkDistinctOutputs(cl, outputs);

    const Parameters params = opts.parameters();

    // Refuse unwritable outputs now rather than after the work.
    const std::vector<std::string> inputs = {map_path, opts.config()};
    std::error_code ec;
    if (!steps_dir.empty() && fs::exists(steps_dir, ec) && !fs::is_directory(steps_dir, ec))
        throw OutputError("--steps " + steps_dir + ": is not a folder");
    for (const auto& out : outputs) checkOutputPath(out.second, force, inputs);

    double load_ms = 0.0;
    const LoadedMap lm = loadMapTimed(map_path, params.map_load, load_ms);

    // --steps: keep the graph of each step (smaller than its picture); drawn after the build.
    std::vector<TopologyGraph> step_graphs(step_paths.size());
    GraphBuildObserver observer;
    if (!step_paths.empty())
        observer = [&](const std::string& step, const TopologyGraph& g)
        {
            const auto& names = buildSteps();
            const auto it = std::find(names.begin(), names.end(), step);
            if (it == names.end())
                throw std::logic_error("graph builder reported an unknown step '" + step + "'");
            step_graphs[static_cast<std::size_t>(it - names.begin())] = g;
        };

    GraphBuildStats stats;
    TopologyGraph graph = buildTopologyGraph(lm.grid, params.graph, &stats, observer);
    graph.map.file = lm.file;
    stats.timing_ms["load_map"] = load_ms;

    if (graph.vertices.empty() && graph.warnings.empty())
        graph.warnings.push_back("the Topology Graph is empty");
    for (const auto& w : graph.warnings) printWarning(lm.file + ": " + w);

    // Everything is produced in memory first: a failure leaves no output behind.
    std::string json_text;
    if (!json_path.empty()) json_text = graphToJson(graph, &stats);
    DrawOptions draw;
    const bool large = std::max(graph.map.size_x, graph.map.size_y) > kLargeMapCells;
    draw.scale = scale_arg.isSet() ? scale_arg.getValue() : (large ? 1 : 2);
    draw.draw_ids = !no_ids_arg.getValue();
    mrpt::img::CImage picture;
    if (!image_path.empty())
    {
        const auto t0 = Clock::now();
        picture = drawTopologyGraph(lm.grid, graph, draw);
        stats.timing_ms["draw"] = msSince(t0);
    }
    // A map with no obstacles or no free space stops the builder before its first step: every
    // step's graph is then empty, and is drawn so.
    std::vector<mrpt::img::CImage> step_pictures;
    if (!step_paths.empty())
    {
        const auto t0 = Clock::now();
        for (const TopologyGraph& g : step_graphs)
            step_pictures.push_back(drawTopologyGraph(lm.grid, g, draw));
        stats.timing_ms["draw_steps"] = msSince(t0);
    }

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
    for (std::size_t i = 0; i < step_paths.size(); ++i)
    {
        writePngAtomic(step_paths[i], step_pictures[i], force);
        written.push_back(step_paths[i]);
    }

    printSummary(std::cout, lm, graph, stats.timing_ms, msSince(t_run), written);
    flushStdout();
    return kExitOk;
}

}  // namespace mrpt_topoeval::cli
