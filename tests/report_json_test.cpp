/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The quality report's JSON (`topoeval compare --json`): the exact text for a tiny hand-made
// report, non-finite and undefined numbers as null, the effective parameters, determinism,
// the timing object last, and the "matches" object identical to `topoeval match`'s.

#include <gtest/gtest.h>
#include <mrpt_topoeval/match_json.h>
#include <mrpt_topoeval/report_json.h>

#include <limits>
#include <string>
#include <vector>

#include "cli_runner.h"

using mrpt_topoeval::GraphMatch;
using mrpt_topoeval::MatchStage;
using mrpt_topoeval::Parameters;
using mrpt_topoeval::QualityReport;
using mrpt_topoeval::reportToJson;
using mrpt_topoeval::TopologyGraph;

namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/** `n` vertices on the x axis, 1 m apart, joined in a path of 1 m edges. Only what the
 * report's JSON reads is filled in. */
TopologyGraph pathGraph(const std::string& file, int n)
{
    TopologyGraph g;
    g.map.file = file;
    g.vertices.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
    {
        g.vertices[i].id = i;
        g.vertices[i].position_m = {double(i), 0.0};
    }
    for (int i = 0; i + 1 < n; ++i)
    {
        mrpt_topoeval::TopoEdge e;
        e.id = i;
        e.from = i;
        e.to = i + 1;
        e.length_m = 1.0;
        g.edges.push_back(e);
    }
    return g;
}

/** Three of four ground-truth vertices matched; two brokenness groups; a long consistency
 * class without an upper bound; every number chosen to show its rounding. */
QualityReport tinyReport()
{
    QualityReport r;
    r.gt_vertices = 4;
    r.map_vertices = 3;
    r.match.pairs = {{0, 2, MatchStage::Isomorphism, 0.912345, 0},
                     {1, 1, MatchStage::Isomorphism, 1.0, 0},
                     {2, 0, MatchStage::NeighbourGrowing, 0.5, 0}};
    r.match.isomorphism = 2;
    r.match.neighbour_growing = 1;
    r.match.missing = 1;
    r.match.isomorphism_sizes = {2};
    r.coverage = 0.75;
    r.global_accuracy.pairs = 3;
    r.global_accuracy.rmse_m = 0.123456;
    r.global_accuracy.score = 0.8019;
    r.relative_accuracy.pairs = 3;
    r.relative_accuracy.rmse_m = 0.05;
    r.relative_accuracy.score = 0.909091;
    r.relative_accuracy.transform = {1.5, -2.25, 12.34567};
    r.local_consistency = {{"short", 0.0, 3.0, 2, 0.1, 0.714286},
                           {"medium", 3.0, 9.0, 0, 0.0, 0.0},
                           {"long", 9.0, kInf, 1, 0.25, 0.5}};
    r.brokenness.degree = 1;
    r.brokenness.score = 0.5;
    r.brokenness.groups = {{{2, 0, 1}, 0.0123456789, {0.1, -0.2, -69.5}, 0.0, false, {}},
                           {{3}, 0.2, {0.0, 0.0, 21.8}, 1.23456789, true, {2}}};
    r.explained_walls.measured = true;
    r.explained_walls.wall_points = 3;
    r.explained_walls.explained = 2;
    r.explained_walls.share = 2.0 / 3.0;
    r.explained_walls.tolerance_m = 0.3;
    r.explained_walls.unexplained_m = {{1.0f, 2.0f}};  // not written: the picture draws them
    r.quality = 0.6543219;
    r.messages = {"a \"quoted\" note"};
    r.timing_ms = {{"similarity", 0.5}, {"total", 1.25}};
    return r;
}

const TopologyGraph kGroundTruth = pathGraph("gt.yaml", 4);
const TopologyGraph kMap = pathGraph("robot.pgm", 3);

// Everything before the effective parameters (checked on their own below).
const char* const kTinyJsonHead = R"({
  "ground_truth": {
    "file": "gt.yaml",
    "vertices": 4,
    "non_spurious_vertices": 4,
    "matchable_vertices": 4,
    "half_edges": 6,
    "edge_length_m": 3
  },
  "map": {
    "file": "robot.pgm",
    "vertices": 3,
    "non_spurious_vertices": 3,
    "matchable_vertices": 3,
    "half_edges": 4,
    "edge_length_m": 2
  },
  "matches": {
    "isomorphism": 2,
    "neighbour_growing": 1,
    "missing": 1,
    "isomorphisms": [2],
    "pairs": [
      {"ground_truth": 0, "map": 2, "stage": "isomorphism", "similarity": 0.9123, "isomorphism_index": 0},
      {"ground_truth": 1, "map": 1, "stage": "isomorphism", "similarity": 1, "isomorphism_index": 0},
      {"ground_truth": 2, "map": 0, "stage": "neighbour_growing", "similarity": 0.5, "isomorphism_index": 0}
    ],
    "messages": []
  },
  "coverage": 0.75,
  "global_accuracy": {
    "pairs": 3,
    "rmse_m": 0.1235,
    "score": 0.8019
  },
  "relative_accuracy": {
    "pairs": 3,
    "rmse_m": 0.05,
    "score": 0.9091,
    "pairs_by_walls": 0,
    "transform": {
      "x": 1.5,
      "y": -2.25,
      "yaw_deg": 12.346
    }
  },
  "local_consistency": [
    {
      "class": "short",
      "min_graph_distance_m": 0,
      "max_graph_distance_m": 3,
      "pairs": 2,
      "mean_error_m": 0.1,
      "score": 0.7143
    },
    {
      "class": "medium",
      "min_graph_distance_m": 3,
      "max_graph_distance_m": 9,
      "pairs": 0,
      "mean_error_m": null,
      "score": 0
    },
    {
      "class": "long",
      "min_graph_distance_m": 9,
      "max_graph_distance_m": null,
      "pairs": 1,
      "mean_error_m": 0.25,
      "score": 0.5
    }
  ],
  "brokenness": {
    "degree": 1,
    "score": 0.5,
    "groups": [
      {
        "vertices": 3,
        "ground_truth_ids": [2, 0, 1],
        "squared_error_m2": 0.012346,
        "yaw_deg": -69.5,
        "x": 0.1,
        "y": -0.2,
        "offset_m": 0,
        "by_walls": false
      },
      {
        "vertices": 1,
        "ground_truth_ids": [3],
        "squared_error_m2": 0.2,
        "yaw_deg": 21.8,
        "x": 0,
        "y": 0,
        "offset_m": 1.2346,
        "by_walls": true,
        "map_ids": [2]
      }
    ]
  },
  "explained_walls": {
    "measured": true,
    "share": 0.6667,
    "wall_points": 3,
    "explained": 2,
    "tolerance_m": 0.3
  },
  "quality": 0.6543,
  "map_scale": 1,
  "messages": [
    "a \"quoted\" note"
  ],
  "parameters": {
)";

std::string head(const std::string& json)
{
    const std::string key = "  \"parameters\": {\n";
    const auto at = json.find(key);
    return at == std::string::npos ? json : json.substr(0, at + key.size());
}

using mrpt_topoeval::testing::contains;
using mrpt_topoeval::testing::topLevelObject;
}  // namespace

TEST(ReportJson, ExactTextOfATinyReport)
{
    const std::string json = reportToJson(kGroundTruth, kMap, tinyReport(), Parameters(), false);
    EXPECT_EQ(head(json), kTinyJsonHead);
    // Without timing the document ends with the parameters.
    const std::string tail = "\n    }\n  }\n}\n";
    ASSERT_GE(json.size(), tail.size());
    EXPECT_EQ(json.substr(json.size() - tail.size()), tail) << json;
    EXPECT_FALSE(contains(json, "timing_ms"));
}

TEST(ReportJson, NonFiniteNumbersAreNull)
{
    QualityReport r = tinyReport();
    r.coverage = kNaN;
    r.quality = kInf;
    r.relative_accuracy.rmse_m = kNaN;
    r.relative_accuracy.transform.yaw_deg = -kInf;
    r.local_consistency[0].mean_error_m = kNaN;
    r.brokenness.groups[0].squared_error_m2 = kNaN;
    r.timing_ms["draw"] = kNaN;
    const std::string json = reportToJson(kGroundTruth, kMap, r, Parameters(), true);
    EXPECT_TRUE(contains(json, "\"coverage\": null,")) << json;
    EXPECT_TRUE(contains(json, "\"quality\": null,")) << json;
    EXPECT_TRUE(contains(json, "\"rmse_m\": null,\n    \"score\": 0.9091,")) << json;
    EXPECT_TRUE(contains(json, "\"yaw_deg\": null\n")) << json;
    EXPECT_TRUE(contains(json, "\"squared_error_m2\": null,")) << json;
    EXPECT_TRUE(contains(json, "\"draw\": null,")) << json;
    for (const char* bad : {"nan", "NaN", "inf", "Inf"})
        EXPECT_FALSE(contains(json, bad)) << bad << " in:\n" << json;
}

TEST(ReportJson, NothingMatchedHasNullErrorsAndZeroScores)
{
    // What evaluateMatch() returns for an empty match: zeros, which the JSON must not present
    // as perfect accuracy.
    QualityReport r;
    r.gt_vertices = 4;
    r.local_consistency = {{"short", 0.0, 3.0, 0, 0.0, 0.0},
                           {"medium", 3.0, 9.0, 0, 0.0, 0.0},
                           {"long", 9.0, kInf, 0, 0.0, 0.0}};
    r.messages = {"nothing was matched: coverage and quality are 0"};
    const std::string json = reportToJson(kGroundTruth, kMap, r, Parameters(), false);
    EXPECT_TRUE(contains(json, "\"coverage\": 0,")) << json;
    EXPECT_TRUE(contains(json, "\"quality\": 0,")) << json;
    EXPECT_TRUE(contains(json, "\"global_accuracy\": {\n    \"pairs\": 0,\n    \"rmse_m\": null,"))
        << json;
    EXPECT_TRUE(contains(json,
                         "\"transform\": {\n      \"x\": null,\n      \"y\": null,\n      "
                         "\"yaw_deg\": null\n    }"))
        << json;
    EXPECT_TRUE(contains(json,
                         "\"brokenness\": {\n    \"degree\": 0,\n    \"score\": 0,\n    "
                         "\"groups\": []\n  },"))
        << json;
    EXPECT_TRUE(contains(json, "\"pairs\": [],")) << json;
    EXPECT_TRUE(contains(json, "\"nothing was matched: coverage and quality are 0\"")) << json;
}

TEST(ReportJson, EffectiveParametersInIniOrderWithTypes)
{
    Parameters p;
    p.graph.min_clearance_m = 1e-7;  // MRPT writes this as 1.000000e-07
    p.similarity.mode = mrpt_topoeval::SimilarityMode::Icp;
    p.quality.brokenness_min_vertices = 7;
    const std::string json = reportToJson(kGroundTruth, kMap, tinyReport(), p, false);
    const std::string params = topLevelObject(json, "parameters");
    ASSERT_FALSE(params.empty()) << json;

    // Sections in the INI file's (pipeline) order, each key with its JSON type.
    std::size_t last = 0;
    for (const char* section :
         {"MapLoad", "GraphBuilder", "VertexSimilarity", "GraphMatcher", "QualityEvaluator"})
    {
        const auto at = params.find("\n    \"" + std::string(section) + "\": {\n");
        ASSERT_NE(at, std::string::npos) << section << " missing in:\n" << params;
        EXPECT_GT(at, last) << section << " out of order";
        last = at;
    }
    EXPECT_TRUE(contains(params, "\"resolution_m\": 0.05,")) << params;
    EXPECT_TRUE(contains(params, "\"free_thresh\": 0.196,")) << params;
    EXPECT_TRUE(contains(params, "\"max_cells\": 100000000\n")) << params;
    EXPECT_TRUE(contains(params, "\"unknown_is_obstacle\": true,")) << params;
    EXPECT_TRUE(contains(params, "\"min_clearance_m\": 0.0000001,")) << params;
    EXPECT_TRUE(contains(params, "\"mode\": \"icp\",")) << params;
    EXPECT_TRUE(contains(params, "\"brokenness_min_vertices\": 7,")) << params;
    // Keys within a section in the INI file's order too: MapLoad's six as written.
    EXPECT_TRUE(
        contains(params,
                 "\"MapLoad\": {\n      \"resolution_m\": 0.05,\n      \"occupied_thresh\": "
                 "0.65,\n      \"free_thresh\": 0.196,\n      \"grey_between_thresholds\": "
                 "\"auto\",\n      \"trinary_unknown_grey\": 205,\n      \"max_cells\": "
                 "100000000\n    }"))
        << params;

    // Every key of the default INI text is there.
    const std::string ini = Parameters::defaultIniText();
    std::size_t keys = 0;
    for (std::size_t pos = 0; (pos = ini.find('\n', pos)) != std::string::npos; ++pos)
    {
        const std::string line = ini.substr(pos + 1, ini.find('\n', pos + 1) - pos - 1);
        if (line.empty() || line[0] == '#' || line[0] == ';' || line[0] == '[') continue;
        const std::string key = line.substr(0, line.find_first_of(" =\t"));
        if (key.empty()) continue;
        ++keys;
        EXPECT_TRUE(contains(params, "\"" + key + "\": ")) << key << " missing";
    }
    EXPECT_GT(keys, 40u);
}

TEST(ReportJson, DeterministicAndTimingLast)
{
    const QualityReport r = tinyReport();
    QualityReport slower = r;
    slower.timing_ms = {{"similarity", 9.87654}, {"total", 20.0}};
    const std::string a = reportToJson(kGroundTruth, kMap, r, Parameters(), true);
    EXPECT_EQ(a, reportToJson(kGroundTruth, kMap, r, Parameters(), true));
    const std::string b = reportToJson(kGroundTruth, kMap, slower, Parameters(), true);
    EXPECT_NE(a, b);

    const std::string tail =
        ",\n  \"timing_ms\": {\n    \"similarity\": 0.5,\n    \"total\": 1.25\n  }\n}\n";
    ASSERT_GE(a.size(), tail.size());
    EXPECT_EQ(a.substr(a.size() - tail.size()), tail) << a;
    const std::string without = reportToJson(kGroundTruth, kMap, r, Parameters(), false);
    EXPECT_EQ(a.substr(0, a.size() - tail.size()) + "\n}\n", without);
    EXPECT_EQ(a.substr(0, a.find(",\n  \"timing_ms\"")), b.substr(0, b.find(",\n  \"timing_ms\"")));
}

TEST(ReportJson, MatchesObjectIsByteIdenticalToMatchJson)
{
    QualityReport r = tinyReport();
    r.match.messages = {"a note\nwith a line break"};
    const std::string report = reportToJson(kGroundTruth, kMap, r, Parameters(), true);
    const std::string match = mrpt_topoeval::matchToJson(kGroundTruth, kMap, r.match);
    const std::string from_report = topLevelObject(report, "matches");
    ASSERT_FALSE(from_report.empty()) << report;
    EXPECT_EQ(from_report, topLevelObject(match, "matches"));
}
