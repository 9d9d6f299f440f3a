/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// The pipeline layer: calls that drive every stage, map grid in, quality report out.
//
// evaluate(gt_grid, map_grid, params) -> QualityReport   both graphs, similarity, match, scores
// evaluate(gt_graph, gt_grid, map_grid, params)         the same with the ground truth's graph
//                                                        built once (rank, series, rawlog)
// vertexSimilarity(...)                                  the similarity [VertexSimilarity] mode
//                                                        chooses (attributes or ICP)

#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/QualityReport.h>
#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <map>
#include <string>

namespace mrpt::maps
{
// Only references to grids here: the full class (a heavy header) where a grid is made or read.
class COccupancyGridMap2D;
}  // namespace mrpt::maps

namespace mrpt_topoeval
{
/** Vertex similarity as `p.mode` chooses: attributeSimilarity(), or icpSimilarity(), which
 * needs the grids (`timing_ms`, if given, receives its steps). The one place that choice is
 * made: evaluate() and `topoeval match` use it. */
SimilarityMatrix vertexSimilarity(const TopologyGraph& gt,
                                  const mrpt::maps::COccupancyGridMap2D& gt_grid,
                                  const TopologyGraph& map,
                                  const mrpt::maps::COccupancyGridMap2D& map_grid,
                                  const VertexSimilarityParameters& p,
                                  std::map<std::string, double>* timing_ms = nullptr);

/** The one-call pipeline: both graphs, vertex similarity (attributes or ICP as configured),
 * match, evaluation. Graphs are returned through the pointers if given. With
 * `params.similarity.threads` other than 1 the two graphs are built side by side, on this thread
 * and one more, and so are brokenness and accuracy (evaluateMatch()); the result does not
 * depend on it. */
QualityReport evaluate(const mrpt::maps::COccupancyGridMap2D& ground_truth,
                       const mrpt::maps::COccupancyGridMap2D& map, const Parameters& params,
                       TopologyGraph* gt_graph = nullptr, TopologyGraph* map_graph = nullptr);

/** evaluate() with the ground truth's graph already built, `gt_graph` =
 * buildTopologyGraph(ground_truth, params.graph): for scoring many maps against one ground truth
 * (rank, series, rawlog snapshots) without building its graph again for each. The ground
 * truth's grid is still needed by ICP similarity. timing_ms "graphs" is the map's graph only. */
QualityReport evaluate(const TopologyGraph& gt_graph,
                       const mrpt::maps::COccupancyGridMap2D& ground_truth,
                       const mrpt::maps::COccupancyGridMap2D& map, const Parameters& params,
                       TopologyGraph* map_graph = nullptr);

}  // namespace mrpt_topoeval
