/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt_topoeval/graph_json.h>
#include <mrpt_topoeval/json/JsonWriter.h>

#include <cmath>
#include <cstdint>

#include "json/decimals.h"

namespace mrpt_topoeval
{
namespace
{

// 0.1 mm for positions and lengths, 0.001 deg for angles (json/decimals.h).
using internal::kDegreeDecimals;
using internal::kMetreDecimals;

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

void writePoint(JsonWriter& w, const Eigen::Vector2d& p) { w.pair(p.x(), p.y(), kMetreDecimals); }

void writeMap(JsonWriter& w, const MapInfo& m)
{
    w.key("map").beginObject();
    w.key("file").value(m.file);
    // The resolution keeps full precision: it is an input, not a measurement.
    w.key("resolution_m").value(m.resolution_m);
    w.key("size_x").value(m.size_x);
    w.key("size_y").value(m.size_y);
    w.key("x_min_m").value(m.x_min_m, kMetreDecimals);
    w.key("y_min_m").value(m.y_min_m, kMetreDecimals);
    w.key("x_max_m").value(m.x_max_m, kMetreDecimals);
    w.key("y_max_m").value(m.y_max_m, kMetreDecimals);
    w.key("occupied_cells").value(static_cast<std::uint64_t>(m.occupied_cells));
    w.key("free_cells").value(static_cast<std::uint64_t>(m.free_cells));
    w.endObject();
}

void writeSummary(JsonWriter& w, const TopologyGraph& g)
{
    w.key("summary").beginObject();
    w.key("vertices").value(static_cast<std::uint64_t>(g.vertices.size()));
    w.key("non_spurious_vertices").value(static_cast<std::uint64_t>(g.numNonSpuriousVertices()));
    w.key("half_edges").value(static_cast<std::uint64_t>(g.numHalfEdges()));
    w.key("edges").value(static_cast<std::uint64_t>(g.edges.size()));
    w.key("total_edge_length_m").value(g.totalEdgeLength(), kMetreDecimals);
    // Index = degree, value = number of non-spurious vertices with that degree.
    w.key("degree_histogram").beginArray(true);
    for (const std::size_t n : g.degreeHistogram()) w.value(static_cast<std::uint64_t>(n));
    w.endArray();
    w.endObject();
}

void writeVertex(JsonWriter& w, const TopoVertex& v)
{
    w.beginObject();
    w.key("id").value(v.id);
    w.key("x").value(v.position_m.x(), kMetreDecimals);
    w.key("y").value(v.position_m.y(), kMetreDecimals);
    w.key("degree").value(v.degree());
    w.key("spurious").value(v.spurious);
    w.key("clearance_m").value(v.clearance_m, kMetreDecimals);
    w.key("dead_end").value(v.degree() == 1);
    // The ring buffer of paper II-C: incident edges counter-clockwise, their directions and
    // the angles between neighbours.
    w.key("edges").beginArray(true);
    for (const Incidence& inc : v.ring) w.value(inc.edge);
    w.endArray();
    w.key("edge_angles_deg").beginArray(true);
    for (const Incidence& inc : v.ring) w.value(inc.angle_rad * kRadToDeg, kDegreeDecimals);
    w.endArray();
    w.key("angle_diffs_deg").beginArray(true);
    for (const double a : v.angle_diffs_rad) w.value(a * kRadToDeg, kDegreeDecimals);
    w.endArray();
    w.key("min_angle_deg").value(v.min_angle_rad * kRadToDeg, kDegreeDecimals);
    w.key("max_angle_deg").value(v.max_angle_rad * kRadToDeg, kDegreeDecimals);
    w.endObject();
}

void writeEdge(JsonWriter& w, const TopoEdge& e)
{
    w.beginObject();
    w.key("id").value(e.id);
    w.key("from").value(e.from);
    w.key("to").value(e.to);
    w.key("length_m").value(e.length_m, kMetreDecimals);
    w.key("min_clearance_m").value(e.min_clearance_m, kMetreDecimals);
    w.key("mean_clearance_m").value(e.mean_clearance_m, kMetreDecimals);
    w.key("dead_end").value(e.dead_end);
    w.key("spurious").value(e.spurious);
    w.key("path").beginArray();
    for (const Eigen::Vector2d& p : e.path_m) writePoint(w, p);
    w.endArray();
    w.endObject();
}

void writeStats(JsonWriter& w, const GraphBuildStats& s)
{
    const auto u = [](std::size_t n) { return static_cast<std::uint64_t>(n); };
    w.key("build").beginObject();
    w.key("sites").value(u(s.sites));
    w.key("voronoi_vertices").value(u(s.voronoi_vertices));
    w.key("voronoi_edges").value(u(s.voronoi_edges));
    w.key("voronoi_edges_kept").value(u(s.voronoi_edges_kept));
    w.key("vertices_initial").value(u(s.vertices_initial));
    w.key("vertices_after_prune").value(u(s.vertices_after_prune));
    w.key("vertices_after_alpha").value(u(s.vertices_after_alpha));
    w.key("vertices_after_component").value(u(s.vertices_after_component));
    w.key("vertices_final").value(u(s.vertices_final));
    w.key("alpha_polygon_segments").value(u(s.alpha_polygon_segments));
    w.endObject();
    writeTiming(w, s.timing_ms);
}
}  // namespace

std::string graphToJson(const TopologyGraph& graph, const GraphBuildStats* stats)
{
    JsonWriter w;
    w.beginObject();
    writeMap(w, graph.map);
    writeSummary(w, graph);

    w.key("vertices").beginArray();
    for (const TopoVertex& v : graph.vertices) writeVertex(w, v);
    w.endArray();

    w.key("edges").beginArray();
    for (const TopoEdge& e : graph.edges) writeEdge(w, e);
    w.endArray();

    w.key("outer_boundary").beginArray();
    for (const Eigen::Vector2d& p : graph.outer_boundary_m) writePoint(w, p);
    w.endArray();

    w.key("warnings").beginArray();
    for (const std::string& msg : graph.warnings) w.value(msg);
    w.endArray();

    if (stats) writeStats(w, *stats);
    w.endObject();
    return w.str();
}

}  // namespace mrpt_topoeval
