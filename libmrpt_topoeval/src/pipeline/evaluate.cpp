/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The one-call pipeline: both graphs, vertex similarity, match, evaluation (paper II-IV).

#include <mrpt/maps/COccupancyGridMap2D.h>  // the clutter pass keeps an edited copy
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/evaluation/evaluate_match.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/matching/match_graphs.h>
#include <mrpt_topoeval/pipeline/evaluate.h>

#include <chrono>
#include <exception>
#include <future>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <utility>

#include "common/clock.h"
#include "common/threads.h"
#include "pipeline/clutter.h"

namespace mrpt_topoeval
{
SimilarityMatrix vertexSimilarity(const TopologyGraph& gt,
                                  const mrpt::maps::COccupancyGridMap2D& gt_grid,
                                  const TopologyGraph& map,
                                  const mrpt::maps::COccupancyGridMap2D& map_grid,
                                  const VertexSimilarityParameters& p,
                                  std::map<std::string, double>* timing_ms)
{
    return p.mode == SimilarityMode::Icp ? icpSimilarity(gt, gt_grid, map, map_grid, p, timing_ms)
                                         : attributeSimilarity(gt, map, p);
}

namespace
{
using internal::Clock;
using internal::msSince;

// Vertex similarity and match of two graphs, timed.
struct Matched
{
    GraphMatch match;
    double similarity_ms = 0.0, match_ms = 0.0;
};

Matched matchStep(const TopologyGraph& gt, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                  const TopologyGraph& map, const mrpt::maps::COccupancyGridMap2D& map_grid,
                  const Parameters& params)
{
    Matched m;
    const auto t1 = Clock::now();
    const SimilarityMatrix s = vertexSimilarity(gt, gt_grid, map, map_grid, params.similarity);
    m.similarity_ms = msSince(t1);
    const auto t2 = Clock::now();
    m.match = matchGraphs(gt, map, s, params.matcher);
    m.match_ms = msSince(t2);
    return m;
}

// The clutter pass (GraphMatcherParameters::clutter_passes; doc/matching.md): the map without
// the free-standing obstacles that the ground truth lacks where the match `m` puts them, built
// and matched again; kept, with its graph in `map`, when it pairs more vertices. A match that
// grew reaches further islands: the pass repeats on the edited map. A match of fewer than 3
// pairs gives nothing to judge by: the first round then judges by the match of the map with
// all its islands freed (clutter_start_without_islands). Returns what it did, for the report's
// messages (empty when it changed nothing).
std::string clutterPasses(const TopologyGraph& gt, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                          TopologyGraph& map, const mrpt::maps::COccupancyGridMap2D& map_grid,
                          const Parameters& params, Matched& m)
{
    const GraphMatcherParameters& p = params.matcher;
    if (p.method != MatchMethod::Consistent || p.clutter_passes <= 0) return {};
    // What the first round judges by: the match itself, or that of the map without islands.
    struct Start
    {
        TopologyGraph graph;
        GraphMatch match;
    };
    std::optional<Start> start;
    std::size_t start_islands = 0;
    if (m.match.pairs.size() < 3 && p.clutter_start_without_islands)
    {
        if (auto bare = internal::withoutIslands(map_grid, params, start_islands))
        {
            TopologyGraph graph = buildTopologyGraph(*bare, params.graph);
            Matched bare_match = matchStep(gt, gt_grid, graph, *bare, params);
            if (bare_match.match.pairs.size() >= 3)
                start = Start{std::move(graph), std::move(bare_match.match)};
        }
    }
    std::optional<mrpt::maps::COccupancyGridMap2D> current;  // the map as edited so far
    const std::size_t first_pairs = m.match.pairs.size();
    std::size_t removed_total = 0;
    int passes = 0;
    for (int pass = 0; pass < p.clutter_passes; ++pass)
    {
        const bool from_start = pass == 0 && start;
        std::size_t removed = 0, judged = 0;
        auto edited = internal::withoutClutter(
            gt, from_start ? start->graph : map, current ? *current : map_grid,
            from_start ? start->match : m.match, params, removed, judged);
        if (!edited) break;
        // Is the map furnished where its ground truth is not? A ground truth drawn from a robot
        // map holds the same furniture; the few islands it lacks are noise and not worth a
        // rebuild.
        if (pass == 0 && double(removed) < p.clutter_min_share * double(judged)) break;
        TopologyGraph graph = buildTopologyGraph(*edited, params.graph);
        Matched next = matchStep(gt, gt_grid, graph, *edited, params);
        if (next.match.pairs.size() <= m.match.pairs.size()) break;
        m.match = std::move(next.match);
        map = std::move(graph);
        current = std::move(edited);
        removed_total += removed;
        ++passes;
    }
    if (passes == 0) return {};
    std::string text = "clutter pass: " + std::to_string(removed_total) +
                       " free-standing obstacle(s) of the map that the ground truth lacks where "
                       "the match puts them made free and the map matched again (" +
                       std::to_string(passes) + " pass(es)";
    if (start)
        text += "; judged first by the " + std::to_string(start->match.pairs.size()) +
                " pairs of the map with all its " + std::to_string(start_islands) +
                " islands freed, as its own match paired fewer than 3";
    return text + "): " + std::to_string(first_pairs) + " -> " +
           std::to_string(m.match.pairs.size()) +
           " pairs; the map's graph reported is without them";
}

// Similarity, match (with the clutter pass, which may replace `map`'s graph) and evaluation of
// two graphs built since `t0` (their time is "graphs").
QualityReport scoreGraphs(const TopologyGraph& gt, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                          TopologyGraph& map, const mrpt::maps::COccupancyGridMap2D& map_grid,
                          const Parameters& params, Clock::time_point t0)
{
    const double t_graphs = msSince(t0);
    Matched m = matchStep(gt, gt_grid, map, map_grid, params);
    const auto tc = Clock::now();
    const std::string clutter = clutterPasses(gt, gt_grid, map, map_grid, params, m);
    const double t_clutter = msSince(tc);
    const auto t3 = Clock::now();
    QualityReport r = evaluateMatch(gt, map, m.match, params.quality,
                                    internal::workerThreads(params.similarity.threads));
    r.timing_ms["graphs"] = t_graphs;
    r.timing_ms["similarity"] = m.similarity_ms;
    r.timing_ms["match"] = m.match_ms;
    if (params.matcher.clutter_passes > 0) r.timing_ms["clutter"] = t_clutter;
    r.timing_ms["evaluation"] = msSince(t3);
    r.timing_ms["total"] = msSince(t0);
    if (!clutter.empty()) r.messages.push_back(clutter);
    for (const auto& w : gt.warnings) r.messages.push_back("ground truth: " + w);
    for (const auto& w : map.warnings) r.messages.push_back("map: " + w);
    return r;
}
}  // namespace

QualityReport evaluate(const TopologyGraph& gt, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                       const mrpt::maps::COccupancyGridMap2D& map_grid, const Parameters& params,
                       TopologyGraph* map_out)
{
    const auto t0 = Clock::now();
    TopologyGraph map = buildTopologyGraph(map_grid, params.graph);
    QualityReport r = scoreGraphs(gt, gt_grid, map, map_grid, params, t0);
    if (map_out) *map_out = std::move(map);
    return r;
}

QualityReport evaluate(const mrpt::maps::COccupancyGridMap2D& gt_grid,
                       const mrpt::maps::COccupancyGridMap2D& map_grid, const Parameters& params,
                       TopologyGraph* gt_out, TopologyGraph* map_out)
{
    const auto t0 = Clock::now();
    // The two graphs do not depend on each other: with more than one worker thread the ground
    // truth's is built on a second thread while this one builds the map's (each build is
    // deterministic and shares nothing, so the result does not depend on it).
    TopologyGraph gt, map;
    std::future<TopologyGraph> gt_future;
    if (internal::workerThreads(params.similarity.threads) > 1)
    {
        try
        {
            gt_future = std::async(std::launch::async,
                                   [&] { return buildTopologyGraph(gt_grid, params.graph); });
        }
        catch (const std::system_error&)
        {
            // No thread to be had (a process or container limit): build both here.
        }
    }
    if (gt_future.valid())
    {
        std::exception_ptr map_error;
        try
        {
            map = buildTopologyGraph(map_grid, params.graph);
        }
        catch (...)
        {
            map_error = std::current_exception();
        }
        gt = gt_future.get();  // the ground truth's error first, as without threads
        if (map_error) std::rethrow_exception(map_error);
    }
    else
    {
        gt = buildTopologyGraph(gt_grid, params.graph);
        map = buildTopologyGraph(map_grid, params.graph);
    }
    QualityReport r = scoreGraphs(gt, gt_grid, map, map_grid, params, t0);
    if (gt_out) *gt_out = std::move(gt);
    if (map_out) *map_out = std::move(map);
    return r;
}

}  // namespace mrpt_topoeval
