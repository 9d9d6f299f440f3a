/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

/** \file The whole public API of mrpt_topoeval in one include, stage by stage
 * (doc/architecture.md). Types are MRPT's and Eigen's; CGAL and OpenCV stay inside.
 *
 * \code
 * #include <mrpt_topoeval/topoeval.h>
 * const auto gt = mrpt_topoeval::loadMap("gt.yaml"), map = mrpt_topoeval::loadMap("map.yaml");
 * const mrpt_topoeval::QualityReport r =
 *     mrpt_topoeval::evaluate(gt.grid, map.grid, mrpt_topoeval::Parameters{});
 * std::cout << r.quality << "\n";
 * \endcode */

// Errors: InputError (bad input), OutputError (cannot write).
#include <mrpt_topoeval/errors.h>
// geometry: the rigid 2D transform (T_gt_map) of matches and reports.
#include <mrpt_topoeval/geometry/Transform2D.h>
// maps: map files -> mrpt::maps::COccupancyGridMap2D.
#include <mrpt_topoeval/maps/load_map.h>
// graph: the Topology Graph of a grid (paper II).
#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/graph/build_graph.h>
// similarity: vertex similarity, attributes or ICP (paper III-A).
#include <mrpt_topoeval/similarity/vertex_similarity.h>
// matching: isomorphism, neighbour growing, consistent groups (paper III-B).
#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/matching/match_graphs.h>
// evaluation: coverage, accuracies, consistency, brokenness, quality (paper IV).
#include <mrpt_topoeval/QualityReport.h>
#include <mrpt_topoeval/evaluation/evaluate_match.h>
// outputs: JSON, pictures, score rows over time, the HTML report, atomic files.
#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/graph_json.h>
#include <mrpt_topoeval/html_report.h>
#include <mrpt_topoeval/json/JsonWriter.h>
#include <mrpt_topoeval/match_json.h>
#include <mrpt_topoeval/output.h>
#include <mrpt_topoeval/report_json.h>
#include <mrpt_topoeval/scores/ranking.h>
#include <mrpt_topoeval/scores/scores.h>
// pipeline: every stage in one call, all parameters in one INI, rawlogs scored over time.
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/pipeline/RawlogScorer.h>
#include <mrpt_topoeval/pipeline/evaluate.h>
