/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The one-call pipeline: both graphs, vertex similarity, match, evaluation (paper II-IV).

#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/evaluation/evaluate_match.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/matching/match_graphs.h>
#include <mrpt_topoeval/pipeline/evaluate.h>

#include <chrono>
#include <exception>
#include <future>
#include <system_error>
#include <thread>
#include <utility>

#include "common/clock.h"
#include "common/threads.h"

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

// Similarity, match and evaluation of two graphs built since `t0` (their time is "graphs").
QualityReport scoreGraphs(const TopologyGraph& gt, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                          const TopologyGraph& map, const mrpt::maps::COccupancyGridMap2D& map_grid,
                          const Parameters& params, Clock::time_point t0)
{
    const double t_graphs = msSince(t0);
    const auto t1 = Clock::now();
    const SimilarityMatrix s = vertexSimilarity(gt, gt_grid, map, map_grid, params.similarity);
    const double t_sim = msSince(t1);
    const auto t2 = Clock::now();
    const GraphMatch match = matchGraphs(gt, map, s, params.matcher);
    const double t_match = msSince(t2);
    const auto t3 = Clock::now();
    QualityReport r = evaluateMatch(gt, map, match, params.quality,
                                    internal::workerThreads(params.similarity.threads));
    r.timing_ms["graphs"] = t_graphs;
    r.timing_ms["similarity"] = t_sim;
    r.timing_ms["match"] = t_match;
    r.timing_ms["evaluation"] = msSince(t3);
    r.timing_ms["total"] = msSince(t0);
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
