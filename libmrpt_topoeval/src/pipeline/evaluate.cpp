/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The one-call pipeline: both graphs, vertex similarity, match, evaluation (paper II-IV).

#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/evaluation/evaluate_match.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/matching/match_graphs.h>
#include <mrpt_topoeval/pipeline/evaluate.h>

#include <chrono>
#include <utility>

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
using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}
}  // namespace

QualityReport evaluate(const TopologyGraph& gt, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                       const mrpt::maps::COccupancyGridMap2D& map_grid, const Parameters& params,
                       TopologyGraph* map_out)
{
    const auto t0 = Clock::now();
    TopologyGraph map = buildTopologyGraph(map_grid, params.graph);
    const double t_graphs = msSince(t0);
    const auto t1 = Clock::now();
    const SimilarityMatrix s = vertexSimilarity(gt, gt_grid, map, map_grid, params.similarity);
    const double t_sim = msSince(t1);
    const auto t2 = Clock::now();
    const GraphMatch match = matchGraphs(gt, map, s, params.matcher);
    const double t_match = msSince(t2);
    const auto t3 = Clock::now();
    QualityReport r = evaluateMatch(gt, map, match, params.quality);
    r.timing_ms["graphs"] = t_graphs;
    r.timing_ms["similarity"] = t_sim;
    r.timing_ms["match"] = t_match;
    r.timing_ms["evaluation"] = msSince(t3);
    r.timing_ms["total"] = msSince(t0);
    for (const auto& w : gt.warnings) r.messages.push_back("ground truth: " + w);
    for (const auto& w : map.warnings) r.messages.push_back("map: " + w);
    if (map_out) *map_out = std::move(map);
    return r;
}

QualityReport evaluate(const mrpt::maps::COccupancyGridMap2D& gt_grid,
                       const mrpt::maps::COccupancyGridMap2D& map_grid, const Parameters& params,
                       TopologyGraph* gt_out, TopologyGraph* map_out)
{
    const auto t0 = Clock::now();
    TopologyGraph gt = buildTopologyGraph(gt_grid, params.graph);
    const double t_gt = msSince(t0);
    QualityReport r = evaluate(gt, gt_grid, map_grid, params, map_out);
    r.timing_ms["graphs"] += t_gt;
    r.timing_ms["total"] += t_gt;
    if (gt_out) *gt_out = std::move(gt);
    return r;
}

}  // namespace mrpt_topoeval
