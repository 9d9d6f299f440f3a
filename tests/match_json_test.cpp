/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The match's JSON: the exact text for a tiny hand-made pair of graphs and match, determinism,
// non-finite numbers, the timing object last, and the "matches" object `compare` embeds.

#include <gtest/gtest.h>
#include <mrpt_topoeval/match_json.h>

#include <limits>
#include <map>
#include <string>
#include <vector>

// The writer is internal to the library; `compare` embeds the same "matches" object.
#include "../libmrpt_topoeval/src/json/match_json_internal.h"

using mrpt_topoeval::GraphMatch;
using mrpt_topoeval::MatchStage;
using mrpt_topoeval::matchToJson;
using mrpt_topoeval::TopologyGraph;
using mrpt_topoeval::VertexPair;

namespace
{
/** `n` vertices joined in a path by `n - 1` edges; the vertices listed in `spurious` are
 * spurious. Only what the match's JSON reads is filled in. */
TopologyGraph pathGraph(const std::string& file, int n, std::vector<int> spurious = {})
{
    TopologyGraph g;
    g.map.file = file;
    g.vertices.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) g.vertices[i].id = i;
    for (const int i : spurious) g.vertices[i].spurious = true;
    for (int i = 0; i + 1 < n; ++i)
    {
        mrpt_topoeval::TopoEdge e;
        e.id = i;
        e.from = i;
        e.to = i + 1;
        g.edges.push_back(e);
    }
    return g;
}

/** Ground truth: 4 vertices (3 spurious-free) and 3 edges; map: 3 vertices and 2 edges. */
TopologyGraph tinyGroundTruth() { return pathGraph("gt.yaml", 4, {3}); }
TopologyGraph tinyMap() { return pathGraph("dir/robot \"map\".pgm", 3); }

/** Two pairs by isomorphism, one by neighbour growing, one ground-truth vertex missing. */
GraphMatch tinyMatch()
{
    GraphMatch m;
    m.pairs = {{0, 2, MatchStage::Isomorphism, 0.912345, 0},
               {1, 1, MatchStage::Isomorphism, 1.0, 0},
               {2, 0, MatchStage::NeighbourGrowing, 0.00004, 0}};
    m.isomorphism = 2;
    m.neighbour_growing = 1;
    m.missing = 0;
    m.isomorphism_sizes = {2};
    m.messages = {"a note\nwith a line break"};
    m.timing_ms = {{"isomorphism", 0.5}, {"total", 1.25}};
    return m;
}

const char* const kTinyJson = R"({
  "ground_truth": {
    "file": "gt.yaml",
    "vertices": 4,
    "non_spurious_vertices": 3,
    "half_edges": 6
  },
  "map": {
    "file": "dir/robot \"map\".pgm",
    "vertices": 3,
    "non_spurious_vertices": 3,
    "half_edges": 4
  },
  "matches": {
    "isomorphism": 2,
    "neighbour_growing": 1,
    "missing": 0,
    "isomorphisms": [2],
    "pairs": [
      {"ground_truth": 0, "map": 2, "stage": "isomorphism", "similarity": 0.9123, "isomorphism_index": 0},
      {"ground_truth": 1, "map": 1, "stage": "isomorphism", "similarity": 1, "isomorphism_index": 0},
      {"ground_truth": 2, "map": 0, "stage": "neighbour_growing", "similarity": 0, "isomorphism_index": 0}
    ],
    "messages": [
      "a note\nwith a line break"
    ]
  }
}
)";

}  // namespace

TEST(MatchJson, ExactTextOfATinyMatch)
{
    EXPECT_EQ(matchToJson(tinyGroundTruth(), tinyMap(), tinyMatch()), kTinyJson);
}

TEST(MatchJson, EmptyGraphsAndEmptyMatch)
{
    const std::string json = matchToJson(TopologyGraph(), TopologyGraph(), GraphMatch());
    EXPECT_EQ(json,
              "{\n"
              "  \"ground_truth\": {\n"
              "    \"file\": \"\",\n"
              "    \"vertices\": 0,\n"
              "    \"non_spurious_vertices\": 0,\n"
              "    \"half_edges\": 0\n"
              "  },\n"
              "  \"map\": {\n"
              "    \"file\": \"\",\n"
              "    \"vertices\": 0,\n"
              "    \"non_spurious_vertices\": 0,\n"
              "    \"half_edges\": 0\n"
              "  },\n"
              "  \"matches\": {\n"
              "    \"isomorphism\": 0,\n"
              "    \"neighbour_growing\": 0,\n"
              "    \"missing\": 0,\n"
              "    \"isomorphisms\": [],\n"
              "    \"pairs\": [],\n"
              "    \"messages\": []\n"
              "  }\n"
              "}\n");
}

TEST(MatchJson, NonFiniteNumbersAreNull)
{
    GraphMatch m = tinyMatch();
    m.pairs[0].similarity = std::numeric_limits<double>::quiet_NaN();
    m.pairs[2].similarity = std::numeric_limits<double>::infinity();
    const std::map<std::string, double> timing = {
        {"similarity", -std::numeric_limits<double>::infinity()}};
    const std::string json = matchToJson(tinyGroundTruth(), tinyMap(), m, &timing);
    EXPECT_NE(json.find("{\"ground_truth\": 0, \"map\": 2, \"stage\": \"isomorphism\", "
                        "\"similarity\": null, \"isomorphism_index\": 0},\n"),
              std::string::npos)
        << json;
    EXPECT_NE(json.find("\"stage\": \"neighbour_growing\", \"similarity\": null,"),
              std::string::npos)
        << json;
    EXPECT_NE(json.find("\"timing_ms\": {\n    \"similarity\": null\n  }\n}\n"), std::string::npos)
        << json;
}

TEST(MatchJson, DeterministicAndTimingLast)
{
    const TopologyGraph gt = tinyGroundTruth(), map = tinyMap();
    const GraphMatch m = tinyMatch();
    const std::map<std::string, double> t1 = {{"similarity", 1.23456}, {"total", 5.0}};
    const std::map<std::string, double> t2 = {{"similarity", 9.87}, {"total", 12.5}};

    const std::string a = matchToJson(gt, map, m, &t1), b = matchToJson(gt, map, m, &t2);
    EXPECT_EQ(a, matchToJson(gt, map, m, &t1));
    EXPECT_NE(a, b);

    // "timing_ms" is the last member, milliseconds to 3 decimals, keys sorted: cutting it off
    // leaves the text without timing.
    const std::string tail =
        ",\n  \"timing_ms\": {\n    \"similarity\": 1.235,\n    \"total\": 5\n  }\n}\n";
    ASSERT_GE(a.size(), tail.size());
    EXPECT_EQ(a.substr(a.size() - tail.size()), tail) << a;
    const std::string without = matchToJson(gt, map, m);
    EXPECT_EQ(a.substr(0, a.size() - tail.size()) + "\n}\n", without);
    EXPECT_EQ(a.substr(0, a.find(",\n  \"timing_ms\"")), b.substr(0, b.find(",\n  \"timing_ms\"")));

    // The match's own timing is not written by itself: the caller decides what to report.
    EXPECT_EQ(without.find("timing_ms"), std::string::npos);
}

TEST(MatchJson, MatchesObjectIsTheOneCompareEmbeds)
{
    // Written by itself into another document, the "matches" object is the same text as in
    // matchToJson(), so `compare` writes the same format.
    using mrpt_topoeval::JsonWriter;
    JsonWriter w;
    w.beginObject();
    w.key("matches");
    mrpt_topoeval::internal::writeMatches(w, tinyMatch());
    w.endObject();
    const std::string alone = w.str();

    const std::string full = matchToJson(tinyGroundTruth(), tinyMap(), tinyMatch());
    const std::string from_full = "{\n" + full.substr(full.find("  \"matches\": {"));
    EXPECT_EQ(alone, from_full);
}
