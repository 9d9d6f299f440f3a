/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// mrpt_topoeval._core: the pybind11 binding of the public C++ API, as thin as it can be. The
// Python package (python/mrpt_topoeval/__init__.py) builds the documented API on top: reports
// are the library's JSON (reportToJson, the bytes `topoeval compare --json` writes) parsed by
// json.loads, so Python and the command cannot disagree on a field.
//
// Every call that computes releases the GIL; the objects it hands out (Map, Graph, Config) are
// immutable once made, so several threads may share them.

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/graph_json.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <mrpt_topoeval/pipeline/evaluate.h>
#include <mrpt_topoeval/report_json.h>
#include <mrpt_topoeval/scores/ranking.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace py = pybind11;

namespace mrpt_topoeval::python
{
namespace
{
using MapPtr = std::shared_ptr<const LoadedMap>;
using GraphPtr = std::shared_ptr<const TopologyGraph>;

/** An (n, 2) float64 array of points. */
py::array_t<double> points(const std::vector<Eigen::Vector2d>& pts)
{
    py::array_t<double> a({static_cast<py::ssize_t>(pts.size()), py::ssize_t{2}});
    auto v = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < pts.size(); ++i)
    {
        v(i, 0) = pts[i].x();
        v(i, 1) = pts[i].y();
    }
    return a;
}

template <typename T, typename Item, typename F>
py::array_t<T> column(const std::vector<Item>& items, F get)
{
    py::array_t<T> a(static_cast<py::ssize_t>(items.size()));
    auto v = a.template mutable_unchecked<1>();
    for (std::size_t i = 0; i < items.size(); ++i) v(i) = static_cast<T>(get(items[i]));
    return a;
}

/** The library's evaluation as `topoeval compare` runs it, between loading and output. */
struct Comparison
{
    std::string json;  //!< reportToJson(), with timing_ms.
    GraphPtr gt_graph, map_graph;
    py::dict scores;      //!< The figures `rank` ranks by, at full precision (JSON rounds them).
    double cpp_ms = 0.0;  //!< The call's time in C++: evaluation and JSON [ms].
};

py::dict scoresOf(const QualityReport& r)
{
    py::dict d;
    const bool matched = !r.match.pairs.empty();
    d["quality"] = r.quality;
    d["coverage"] = r.coverage;
    d["relative_accuracy_rmse_m"] = matched ? py::cast(r.relative_accuracy.rmse_m) : py::none();
    d["relative_accuracy_score"] = r.relative_accuracy.score;
    const char* names[] = {"consistency_short", "consistency_medium", "consistency_long"};
    for (std::size_t c = 0; c < 3; ++c)
    {
        const bool has = c < r.local_consistency.size() && r.local_consistency[c].pairs > 0;
        d[names[c]] = has ? py::cast(r.local_consistency[c].score) : py::none();
    }
    d["consistency_score"] = r.consistencyScore();
    d["brokenness"] = matched ? py::cast(r.brokenness.degree) : py::none();
    d["brokenness_score"] = r.brokenness.score;
    d["map_scale"] = r.map_scale;
    d["explained_walls"] =
        r.explained_walls.measured ? py::cast(r.explained_walls.share) : py::none();
    d["matched"] = matched;
    return d;
}

/** The run's timing as the command reports it: the library's "total" is "evaluate". */
void addTiming(QualityReport& report, double total_ms)
{
    std::map<std::string, double> t;
    for (const auto& [step, ms] : report.timing_ms) t[step == "total" ? "evaluate" : step] = ms;
    t["total"] = total_ms;
    report.timing_ms = t;
}

double msSince(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

/** `topoeval compare`: both graphs, match, scores; the empty-graph notes verb_compare.cpp adds. */
Comparison compare(const MapPtr& gt, const MapPtr& map, const Parameters& params)
{
    auto gt_graph = std::make_shared<TopologyGraph>();
    auto map_graph = std::make_shared<TopologyGraph>();
    std::string json;
    QualityReport report;
    double cpp_ms = 0.0;
    {
        py::gil_scoped_release release;
        const auto t0 = std::chrono::steady_clock::now();
        report = evaluate(gt->grid, map->grid, params, gt_graph.get(), map_graph.get());
        gt_graph->map.file = gt->file;
        map_graph->map.file = map->file;
        for (const auto& [graph, role] :
             {std::pair<const TopologyGraph*, const char*>{gt_graph.get(), "ground truth"},
              {map_graph.get(), "map"}})
            if (graph->vertices.empty() && graph->warnings.empty())
                report.messages.push_back(std::string(role) + ": the Topology Graph of " +
                                          graph->map.file + " is empty");
        addTiming(report, msSince(t0));
        json = reportToJson(*gt_graph, *map_graph, report, params, true);
        cpp_ms = msSince(t0);
    }
    return {json, gt_graph, map_graph, scoresOf(report), cpp_ms};
}

/** `topoeval rank`'s evaluation of one map against a ground truth whose graph is built. */
Comparison score(const GraphPtr& gt_graph, const MapPtr& gt, const MapPtr& map,
                 const Parameters& params)
{
    auto map_graph = std::make_shared<TopologyGraph>();
    std::string json;
    QualityReport report;
    double cpp_ms = 0.0;
    {
        py::gil_scoped_release release;
        const auto t0 = std::chrono::steady_clock::now();
        report = evaluate(*gt_graph, gt->grid, map->grid, params, map_graph.get());
        map_graph->map.file = map->file;
        if (map_graph->vertices.empty() && map_graph->warnings.empty())
            report.messages.push_back("map: the Topology Graph is empty");
        addTiming(report, msSince(t0));
        json = reportToJson(*gt_graph, *map_graph, report, params, true);
        cpp_ms = msSince(t0);
    }
    return {json, gt_graph, map_graph, scoresOf(report), cpp_ms};
}

std::string iniText(const Parameters& p)
{
    mrpt::config::CConfigFileMemory ini;
    p.saveToConfigFile(ini);
    return ini.getContent();
}
}  // namespace
}  // namespace mrpt_topoeval::python

PYBIND11_MODULE(_core, m)
{
    using namespace mrpt_topoeval;
    using namespace mrpt_topoeval::python;
    m.doc() = "mrpt_topoeval's C++ core; use the mrpt_topoeval package, not this module.";

    // Bad input is a ValueError, an unwritable output an OSError (doc/python.md).
    static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
    static py::exception<OutputError> output_error(m, "OutputError", PyExc_OSError);
    py::register_exception_translator(
        [](std::exception_ptr p)
        {
            try
            {
                if (p) std::rethrow_exception(p);
            }
            catch (const InputError& e)
            {
                input_error(messageOnOneLine(e.what()).c_str());
            }
            catch (const OutputError& e)
            {
                output_error(messageOnOneLine(e.what()).c_str());
            }
        });

    py::class_<Parameters>(m, "Parameters")
        .def(py::init<>())
        .def_static("from_ini_file", &Parameters::fromIniFile, py::arg("path"),
                    py::call_guard<py::gil_scoped_release>())
        .def_static("from_ini_text", &Parameters::fromIniText, py::arg("text"), py::arg("source"),
                    py::call_guard<py::gil_scoped_release>())
        .def_static("default_ini_text", &Parameters::defaultIniText)
        .def("ini_text", &iniText)
        .def("validate", &Parameters::validate);

    py::class_<LoadedMap, std::shared_ptr<LoadedMap>>(m, "LoadedMap")
        .def_readonly("file", &LoadedMap::file)
        .def_readonly("format", &LoadedMap::format)
        .def_readonly("notes", &LoadedMap::notes)
        .def_property_readonly("width", [](const LoadedMap& l) { return l.grid.getSizeX(); })
        .def_property_readonly("height", [](const LoadedMap& l) { return l.grid.getSizeY(); })
        .def_property_readonly("resolution_m",
                               [](const LoadedMap& l) { return l.grid.getResolution(); })
        .def_property_readonly("origin_xy", [](const LoadedMap& l)
                               { return py::make_tuple(l.grid.getXMin(), l.grid.getYMin()); })
        .def("occupancy",
             [](const LoadedMap& l)
             {
                 // P(occupied) per cell, row 0 at the lowest y (OccupancyGrid order).
                 const auto w = l.grid.getSizeX(), h = l.grid.getSizeY();
                 py::array_t<float> a({static_cast<py::ssize_t>(h), static_cast<py::ssize_t>(w)});
                 auto v = a.mutable_unchecked<2>();
                 for (unsigned y = 0; y < h; ++y)
                     for (unsigned x = 0; x < w; ++x) v(y, x) = 1.0f - l.grid.getCell(x, y);
                 return a;
             });

    m.def(
        "load_map",
        [](const std::string& path, const Parameters& p)
        { return std::make_shared<LoadedMap>(loadMap(path, p.map_load)); },
        py::arg("path"), py::arg("params"), py::call_guard<py::gil_scoped_release>());
    m.def(
        "map_from_cells",
        [](py::array_t<double, py::array::c_style | py::array::forcecast> cells,
           double resolution_m, double x0, double y0, bool ros_values, const Parameters& p,
           const std::string& name)
        {
            if (cells.ndim() != 2)
                throw InputError(name + ": a " + std::to_string(cells.ndim()) +
                                 "-dimensional array is not a grid (2 dimensions: rows, columns)");
            const auto h = static_cast<std::size_t>(cells.shape(0));
            const auto w = static_cast<std::size_t>(cells.shape(1));
            std::vector<double> values(cells.data(), cells.data() + cells.size());
            py::gil_scoped_release release;
            return std::make_shared<LoadedMap>(mapFromCells(
                values, w, h, resolution_m, x0, y0,
                ros_values ? CellEncoding::RosOccupancyGrid : CellEncoding::OccupancyProbability,
                p.map_load, name));
        },
        py::arg("cells"), py::arg("resolution_m"), py::arg("x0"), py::arg("y0"),
        py::arg("ros_values"), py::arg("params"), py::arg("name"));
    m.def("is_map_file", &isMapFile, py::arg("path"));

    py::class_<TopoVertex>(m, "Vertex")
        .def_readonly("id", &TopoVertex::id)
        .def_property_readonly("position", [](const TopoVertex& v)
                               { return py::make_tuple(v.position_m.x(), v.position_m.y()); })
        .def_readonly("clearance_m", &TopoVertex::clearance_m)
        .def_readonly("spurious", &TopoVertex::spurious)
        .def_property_readonly("degree", &TopoVertex::degree)
        .def_readonly("angle_diffs_rad", &TopoVertex::angle_diffs_rad)
        .def("__repr__",
             [](const TopoVertex& v) {
                 return "Vertex(id=" + std::to_string(v.id) +
                        ", degree=" + std::to_string(v.degree()) + ")";
             });
    py::class_<TopoEdge>(m, "Edge")
        .def_readonly("id", &TopoEdge::id)
        .def_readonly("source", &TopoEdge::from)
        .def_readonly("target", &TopoEdge::to)
        .def_property_readonly("path", [](const TopoEdge& e) { return points(e.path_m); })
        .def_readonly("clearance_m", &TopoEdge::clearance_m)
        .def_readonly("length_m", &TopoEdge::length_m)
        .def_readonly("min_clearance_m", &TopoEdge::min_clearance_m)
        .def_readonly("mean_clearance_m", &TopoEdge::mean_clearance_m)
        .def_readonly("dead_end", &TopoEdge::dead_end)
        .def_readonly("spurious", &TopoEdge::spurious)
        .def("__repr__",
             [](const TopoEdge& e)
             {
                 return "Edge(id=" + std::to_string(e.id) + ", " + std::to_string(e.from) + " -> " +
                        std::to_string(e.to) + ")";
             });

    py::class_<TopologyGraph, std::shared_ptr<TopologyGraph>>(m, "TopologyGraph")
        .def_property_readonly("file", [](const TopologyGraph& g) { return g.map.file; })
        .def_readonly("vertices", &TopologyGraph::vertices)
        .def_readonly("edges", &TopologyGraph::edges)
        .def_readonly("warnings", &TopologyGraph::warnings)
        .def_property_readonly("vertex_positions",
                               [](const TopologyGraph& g)
                               {
                                   std::vector<Eigen::Vector2d> p;
                                   for (const auto& v : g.vertices) p.push_back(v.position_m);
                                   return points(p);
                               })
        .def_property_readonly(
            "vertex_clearance_m", [](const TopologyGraph& g)
            { return column<double>(g.vertices, [](auto& v) { return v.clearance_m; }); })
        .def_property_readonly(
            "vertex_degree", [](const TopologyGraph& g)
            { return column<int>(g.vertices, [](auto& v) { return v.degree(); }); })
        .def_property_readonly(
            "vertex_spurious", [](const TopologyGraph& g)
            { return column<bool>(g.vertices, [](auto& v) { return v.spurious; }); })
        .def_property_readonly(
            "edge_ends",
            [](const TopologyGraph& g)
            {
                py::array_t<int> a({static_cast<py::ssize_t>(g.edges.size()), py::ssize_t{2}});
                auto v = a.mutable_unchecked<2>();
                for (std::size_t i = 0; i < g.edges.size(); ++i)
                {
                    v(i, 0) = g.edges[i].from;
                    v(i, 1) = g.edges[i].to;
                }
                return a;
            })
        .def_property_readonly(
            "edge_length_m", [](const TopologyGraph& g)
            { return column<double>(g.edges, [](auto& e) { return e.length_m; }); })
        .def_property_readonly(
            "edge_spurious", [](const TopologyGraph& g)
            { return column<bool>(g.edges, [](auto& e) { return e.spurious; }); })
        .def_property_readonly("edge_paths",
                               [](const TopologyGraph& g)
                               {
                                   py::list l;
                                   for (const auto& e : g.edges) l.append(points(e.path_m));
                                   return l;
                               })
        .def_property_readonly("outer_boundary",
                               [](const TopologyGraph& g) { return points(g.outer_boundary_m); })
        .def_property_readonly("num_non_spurious_vertices", &TopologyGraph::numNonSpuriousVertices)
        .def_property_readonly("num_half_edges", &TopologyGraph::numHalfEdges)
        .def_property_readonly("total_edge_length_m", &TopologyGraph::totalEdgeLength)
        .def("to_json", [](const TopologyGraph& g) { return graphToJson(g); });

    m.def(
        "build_graph",
        [](const std::shared_ptr<LoadedMap>& map, const Parameters& p)
        {
            auto g = std::make_shared<TopologyGraph>();
            {
                py::gil_scoped_release release;
                *g = buildTopologyGraph(map->grid, p.graph);
                g->map.file = map->file;
            }
            return g;
        },
        py::arg("map"), py::arg("params"));

    py::class_<Comparison>(m, "Comparison")
        .def_readonly("json", &Comparison::json)
        .def_property_readonly("gt_graph", [](const Comparison& c)
                               { return std::const_pointer_cast<TopologyGraph>(c.gt_graph); })
        .def_property_readonly("map_graph", [](const Comparison& c)
                               { return std::const_pointer_cast<TopologyGraph>(c.map_graph); })
        .def_readonly("scores", &Comparison::scores)
        .def_readonly("cpp_ms", &Comparison::cpp_ms);
    m.def(
        "compare",
        [](const std::shared_ptr<LoadedMap>& gt, const std::shared_ptr<LoadedMap>& map,
           const Parameters& p) { return compare(gt, map, p); },
        py::arg("gt"), py::arg("map"), py::arg("params"));
    m.def(
        "score",
        [](const std::shared_ptr<TopologyGraph>& gt_graph, const std::shared_ptr<LoadedMap>& gt,
           const std::shared_ptr<LoadedMap>& map, const Parameters& p)
        { return score(gt_graph, gt, map, p); },
        py::arg("gt_graph"), py::arg("gt"), py::arg("map"), py::arg("params"));
    m.def("rank_positions", &rankPositions, py::arg("values"), py::arg("valid"),
          py::arg("decimals") = 3);
}
