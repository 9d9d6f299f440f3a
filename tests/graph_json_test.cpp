/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The graph's JSON: the exact text for a tiny hand-made graph, numbers, escaping,
// determinism, and the timing object last.

#include <gtest/gtest.h>
#include <mrpt_topoeval/graph_json.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

// The writer is internal to the library; its tests live with its main user.
#include <mrpt_topoeval/json/JsonWriter.h>

using mrpt_topoeval::GraphBuildStats;
using mrpt_topoeval::graphToJson;
using mrpt_topoeval::JsonWriter;
using mrpt_topoeval::TopologyGraph;

namespace
{
constexpr double kPi = 3.14159265358979323846;

/** Two dead ends joined by one bent edge; vertex 1 is spurious. */
TopologyGraph tinyGraph()
{
    TopologyGraph g;
    g.map.file = "tiny.yaml";
    g.map.resolution_m = 0.05;
    g.map.size_x = 40;
    g.map.size_y = 20;
    g.map.x_min_m = -1.0;
    g.map.y_min_m = -0.5;
    g.map.x_max_m = 1.0;
    g.map.y_max_m = 0.5;
    g.map.occupied_cells = 100;
    g.map.free_cells = 600;

    g.vertices.resize(2);
    auto& v0 = g.vertices[0];
    v0.id = 0;
    v0.position_m = {-0.5, -0.00001};  // rounds to -0, written as 0
    v0.clearance_m = 0.25;
    v0.ring = {{0, 1, true, 0.0}};
    v0.angle_diffs_rad = {2 * kPi};
    v0.min_angle_rad = v0.max_angle_rad = 2 * kPi;
    auto& v1 = g.vertices[1];
    v1.id = 1;
    v1.position_m = {0.5, 0.0};
    v1.clearance_m = 0.2;
    v1.spurious = true;
    v1.ring = {{0, 0, false, kPi}};
    v1.angle_diffs_rad = {2 * kPi};
    v1.min_angle_rad = v1.max_angle_rad = 2 * kPi;

    g.edges.resize(1);
    auto& e = g.edges[0];
    e.id = 0;
    e.from = 0;
    e.to = 1;
    e.path_m = {{-0.5, 0.0}, {0.0, 0.1}, {0.5, 0.0}};
    e.clearance_m = {0.25, 0.3, 0.2};
    e.length_m = 2.0 * std::sqrt(0.26);
    e.min_clearance_m = 0.2;
    e.mean_clearance_m = 0.26;
    e.dead_end = true;
    e.spurious = true;

    g.outer_boundary_m = {{-1.0, -0.5}, {1.0, -0.5}, {1.0, 0.5}};
    g.warnings = {"a note"};
    return g;
}

const char* const kTinyJson = R"({
  "map": {
    "file": "tiny.yaml",
    "resolution_m": 0.05,
    "size_x": 40,
    "size_y": 20,
    "x_min_m": -1,
    "y_min_m": -0.5,
    "x_max_m": 1,
    "y_max_m": 0.5,
    "occupied_cells": 100,
    "free_cells": 600
  },
  "summary": {
    "vertices": 2,
    "non_spurious_vertices": 1,
    "half_edges": 2,
    "edges": 1,
    "total_edge_length_m": 1.0198,
    "degree_histogram": [0, 1]
  },
  "vertices": [
    {
      "id": 0,
      "x": -0.5,
      "y": 0,
      "degree": 1,
      "spurious": false,
      "clearance_m": 0.25,
      "dead_end": true,
      "edges": [0],
      "edge_angles_deg": [0],
      "angle_diffs_deg": [360],
      "min_angle_deg": 360,
      "max_angle_deg": 360
    },
    {
      "id": 1,
      "x": 0.5,
      "y": 0,
      "degree": 1,
      "spurious": true,
      "clearance_m": 0.2,
      "dead_end": true,
      "edges": [0],
      "edge_angles_deg": [180],
      "angle_diffs_deg": [360],
      "min_angle_deg": 360,
      "max_angle_deg": 360
    }
  ],
  "edges": [
    {
      "id": 0,
      "from": 0,
      "to": 1,
      "length_m": 1.0198,
      "min_clearance_m": 0.2,
      "mean_clearance_m": 0.26,
      "dead_end": true,
      "spurious": true,
      "path": [
        [-0.5, 0],
        [0, 0.1],
        [0.5, 0]
      ]
    }
  ],
  "outer_boundary": [
    [-1, -0.5],
    [1, -0.5],
    [1, 0.5]
  ],
  "warnings": [
    "a note"
  ]
}
)";

std::string fieldLine(const std::string& json, const std::string& key)
{
    const auto at = json.find("\"" + key + "\": ");
    if (at == std::string::npos) return "";
    return json.substr(at, json.find('\n', at) - at);
}
}  // namespace

TEST(GraphJson, ExactTextOfATinyGraph) { EXPECT_EQ(graphToJson(tinyGraph()), kTinyJson); }

TEST(GraphJson, EmptyGraph)
{
    const std::string json = graphToJson(TopologyGraph());
    EXPECT_NE(json.find("\"vertices\": [],\n"), std::string::npos) << json;
    EXPECT_NE(json.find("\"edges\": [],\n"), std::string::npos) << json;
    EXPECT_NE(json.find("\"degree_histogram\": []\n"), std::string::npos) << json;
    EXPECT_NE(json.find("\"warnings\": []\n}\n"), std::string::npos) << json;
}

TEST(GraphJson, NonFiniteNumbersAreNull)
{
    TopologyGraph g = tinyGraph();
    g.edges[0].min_clearance_m = std::numeric_limits<double>::quiet_NaN();
    g.edges[0].mean_clearance_m = std::numeric_limits<double>::infinity();
    g.vertices[0].clearance_m = -std::numeric_limits<double>::infinity();
    const std::string json = graphToJson(g);
    EXPECT_EQ(fieldLine(json, "min_clearance_m"), "\"min_clearance_m\": null,");
    EXPECT_EQ(fieldLine(json, "mean_clearance_m"), "\"mean_clearance_m\": null,");
    EXPECT_EQ(fieldLine(json, "clearance_m"), "\"clearance_m\": null,");
}

TEST(GraphJson, NumbersAreFixedAndTrimmed)
{
    TopologyGraph g = tinyGraph();
    g.vertices[0].position_m = {123456.78904, -0.00005};  // rounds away from zero at 4 decimals
    g.map.resolution_m = 1.0 / 3.0;                       // inputs keep 6 decimals
    const std::string json = graphToJson(g);
    EXPECT_EQ(fieldLine(json, "x"), "\"x\": 123456.789,");
    EXPECT_EQ(fieldLine(json, "y"), "\"y\": -0.0001,");
    EXPECT_EQ(fieldLine(json, "resolution_m"), "\"resolution_m\": 0.333333,");
    g.vertices[1].clearance_m = 1e-9;  // fixed notation: no exponent, rounds to 0
    EXPECT_NE(graphToJson(g).find("\"clearance_m\": 0,\n"), std::string::npos);
}

TEST(GraphJson, StringsAreEscaped)
{
    TopologyGraph g = tinyGraph();
    g.map.file = std::string("a\"b\\c/d\n\t\r\b\f\x01\x1f") + "\xC3\xA9\xE2\x82\xAC" +  // é €
                 "\xF0\x9F\x98\x80" + "\xFF" + "\xC3" + "z";  // emoji, stray and cut bytes
    const std::string json = graphToJson(g);
    EXPECT_EQ(fieldLine(json, "file"),
              "\"file\": \"a\\\"b\\\\c/d\\n\\t\\r\\b\\f\\u0001\\u001f\xC3\xA9\xE2\x82\xAC"
              "\xF0\x9F\x98\x80\xEF\xBF\xBD\xEF\xBF\xBDz\",");
}

TEST(GraphJson, DeterministicAndTimingLast)
{
    const TopologyGraph g = tinyGraph();
    GraphBuildStats s1;
    s1.sites = 42;
    s1.vertices_final = 2;
    s1.timing_ms = {{"voronoi", 1.23456}, {"total", 5.0}};
    GraphBuildStats s2 = s1;
    s2.timing_ms = {{"voronoi", 9.87}, {"total", 12.5}};

    const std::string a = graphToJson(g, &s1), b = graphToJson(g, &s2);
    EXPECT_EQ(a, graphToJson(g, &s1));
    EXPECT_NE(a, b);

    // "build" precedes "timing_ms", the last member: cutting from its key leaves equal text.
    const auto build = a.find("\n  \"build\": {\n    \"sites\": 42,");
    const auto timing =
        a.find(",\n  \"timing_ms\": {\n    \"total\": 5,\n    \"voronoi\": 1.235\n  }\n}\n");
    ASSERT_NE(build, std::string::npos) << a;
    ASSERT_NE(timing, std::string::npos) << a;
    EXPECT_LT(build, timing);
    EXPECT_EQ(a.substr(0, timing), b.substr(0, b.find(",\n  \"timing_ms\"")));

    // Without stats there is neither "build" nor "timing_ms".
    const std::string none = graphToJson(g);
    EXPECT_EQ(none.find("\"build\""), std::string::npos);
    EXPECT_EQ(none.find("\"timing_ms\""), std::string::npos);
}

TEST(JsonWriter, LayoutOfNestedContainers)
{
    JsonWriter w;
    w.beginObject();
    w.key("empty_object").beginObject().endObject();
    w.key("empty_array").beginArray().endArray();
    w.key("rows").beginArray();
    w.beginObject(true).key("a").value(1).key("b").beginArray().value("x").endArray().endObject();
    w.pair(0.5, -2.25);
    w.endArray();
    w.key("flag").value(false);
    w.key("nothing").null();
    w.endObject();
    EXPECT_EQ(w.str(),
              "{\n"
              "  \"empty_object\": {},\n"
              "  \"empty_array\": [],\n"
              "  \"rows\": [\n"
              "    {\"a\": 1, \"b\": [\"x\"]},\n"
              "    [0.5, -2.25]\n"
              "  ],\n"
              "  \"flag\": false,\n"
              "  \"nothing\": null\n"
              "}\n");

    JsonWriter scalar;
    scalar.value(std::uint64_t{18446744073709551615ULL});
    EXPECT_EQ(scalar.str(), "18446744073709551615\n");
}

TEST(JsonWriter, NumberFormat)
{
    EXPECT_EQ(JsonWriter::formatDouble(0.1 + 0.2), "0.3");
    EXPECT_EQ(JsonWriter::formatDouble(-0.0), "0");
    EXPECT_EQ(JsonWriter::formatDouble(-1e-9), "0");
    EXPECT_EQ(JsonWriter::formatDouble(2.75, 0), "3");
    EXPECT_EQ(JsonWriter::formatDouble(1e21), "1000000000000000000000");
    EXPECT_EQ(JsonWriter::formatDouble(-12.5, 3), "-12.5");
    EXPECT_EQ(JsonWriter::formatDouble(std::numeric_limits<double>::quiet_NaN()), "null");
    EXPECT_EQ(JsonWriter::formatDouble(std::numeric_limits<double>::max()).size(), 309u);
}

TEST(JsonWriter, MisuseIsALogicError)
{
    {
        JsonWriter w;
        w.beginObject();
        EXPECT_THROW(w.value(1), std::logic_error);  // no key
        EXPECT_THROW(w.endArray(), std::logic_error);
        EXPECT_THROW(w.str(), std::logic_error);  // still open
        w.key("k");
        EXPECT_THROW(w.key("k2"), std::logic_error);
        EXPECT_THROW(w.endObject(), std::logic_error);  // key without value
    }
    {
        JsonWriter w;
        EXPECT_THROW(w.str(), std::logic_error);  // nothing written
        EXPECT_THROW(w.key("k"), std::logic_error);
        w.value(1);
        EXPECT_THROW(w.value(2), std::logic_error);  // a second document
    }
}
