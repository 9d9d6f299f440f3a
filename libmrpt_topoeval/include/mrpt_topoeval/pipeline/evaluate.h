/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// The pipeline layer: calls that drive every stage, map grid in, quality report out.
//
// evaluate(gt_grid, map_grid, params) -> QualityReport   both graphs, similarity, match, scores
// evaluate(gt_graph, gt_grid, map_grid, params)         the same with the ground truth's graph
//                                                        built once (rank, series, rawlog)
// vertexSimilarity(...)                                  the similarity [VertexSimilarity] mode
//                                                        chooses (attributes or ICP)
//
// The two evaluate() overloads are declared in <mrpt_topoeval/evaluation/evaluate_match.h> until
// that header is renamed (doc/architecture.md, "Left to do"); their definitions live here
// (src/pipeline/evaluate.cpp).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/evaluation/evaluate_match.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <map>
#include <string>

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

}  // namespace mrpt_topoeval
