/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Google Benchmark of vertex similarity (paper III-A) and graph matching (III-B) on map pairs:
//   office: the synthetic office floor against a copy rotated by 37 deg and shifted (built in
//           code, always available);
//   intel:  Radish intel-corrected_ref vs the icp-slam map of the Intel lab (../shared/data);
//   house:  house_gt_trinary_res0.05 vs map_6ccdcaa (../shared/data).
// Pairs whose files are absent are reported as skipped.
//
// Benchmarks per pair: attributeSimilarity, icpSimilarity (1 and 2 threads), matchGraphs on a
// precomputed attribute similarity, and the whole pipeline (build both graphs, similarity,
// match) with either similarity. Counters: `v_gt`, `v_map` (vertices of each graph),
// `matched` (pairs of the resulting match; for the similarity benchmarks, the match
// matchGraphs() makes from that similarity, computed once outside the timed loop), and for
// ICP `clouds_ms`, the part of the time spent cutting the point clouds.

#include <benchmark/benchmark.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <mrpt_topoeval/matching/match_graphs.h>
#include <mrpt_topoeval/pipeline/evaluate.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "synthetic_maps.h"
#include "test_paths.h"

namespace
{
using mrpt::maps::COccupancyGridMap2D;
using namespace mrpt_topoeval;

/** A ground-truth map and a map to evaluate, with their graphs built with default parameters. */
struct MapPair
{
    COccupancyGridMap2D grid_gt, grid_map;
    TopologyGraph gt, map;
};

MapPair makePair(COccupancyGridMap2D gt, COccupancyGridMap2D map)
{
    MapPair p;
    p.grid_gt = std::move(gt);
    p.grid_map = std::move(map);
    p.gt = buildTopologyGraph(p.grid_gt);
    p.map = buildTopologyGraph(p.grid_map);
    return p;
}

MapPair loadPair(const std::string& gt_rel, const std::string& map_rel)
{
    const auto gt = testing::sharedDataFile(gt_rel);
    const auto map = testing::sharedDataFile(map_rel);
    if (!gt || !map)
        throw std::runtime_error("../shared/data/" + (gt ? map_rel : gt_rel) +
                                 " not found: pair not benchmarked");
    return makePair(loadMap(*gt).grid, loadMap(*map).grid);
}

MapPair makeOfficePair()
{
    const COccupancyGridMap2D office = testing::makeOfficeMap();
    return makePair(office, testing::transformGrid(office, 37.0 * M_PI / 180.0, {2.5, -1.0}));
}

/** Pairs are loaded and their graphs built once per process, on first use (a
 * --benchmark_filter run pays only for what it runs). Throws if the data is absent. */
const MapPair& cachedPair(const std::string& name)
{
    static std::map<std::string, std::unique_ptr<MapPair>> cache;
    auto& slot = cache[name];
    if (!slot)
    {
        if (name == "office")
            slot = std::make_unique<MapPair>(makeOfficePair());
        else if (name == "intel")
            slot = std::make_unique<MapPair>(loadPair("radish/intel-corrected_ref.yaml",
                                                      "slam_maps/intel_icp-slam_app-final.yaml"));
        else if (name == "intel_self_rotated")
        {
            const auto f = testing::sharedDataFile("radish/intel-corrected_ref.yaml");
            if (!f)
                throw std::runtime_error("../shared/data/radish not found: pair not benchmarked");
            const COccupancyGridMap2D g = loadMap(*f).grid;
            slot = std::make_unique<MapPair>(
                makePair(g, testing::transformGrid(g, 117.0 * M_PI / 180.0, {3.0, -8.0})));
        }
        else if (name == "campus_broken")
        {
            // 1240 x 740 cells each, every stage of compare doing real work (101 vertices,
            // three brokenness groups).
            const COccupancyGridMap2D campus = testing::makeCampusMap();
            COccupancyGridMap2D broken =
                testing::breakMap(campus, {16.5, 12.0}, 14.0 * M_PI / 180.0,
                                  [](double x, double) { return x > 16.5; });
            broken = testing::breakMap(broken, {31.0, 28.0}, -22.0 * M_PI / 180.0,
                                       [](double x, double) { return x > 31.0; });
            slot = std::make_unique<MapPair>(makePair(campus, broken));
        }
        else if (name == "house")
            slot = std::make_unique<MapPair>(
                loadPair("house/house_gt_trinary_res0.05.yaml", "house/map_6ccdcaa.yaml"));
        else
            throw std::logic_error("unknown pair " + name);
    }
    return *slot;
}

/** The pair, or nullptr after marking the benchmark skipped. */
const MapPair* pairOrSkip(benchmark::State& state, const std::string& name)
{
    try
    {
        return &cachedPair(name);
    }
    catch (const std::exception& e)
    {
        state.SkipWithError(e.what());
        for (auto _ : state)
        {
        }
        return nullptr;
    }
}

void setCounters(benchmark::State& state, const MapPair& p, const GraphMatch& m)
{
    state.counters["v_gt"] = static_cast<double>(p.gt.vertices.size());
    state.counters["v_map"] = static_cast<double>(p.map.vertices.size());
    state.counters["matched"] = static_cast<double>(m.pairs.size());
}

VertexSimilarityParameters icpParams(int threads)
{
    VertexSimilarityParameters sp;
    sp.mode = SimilarityMode::Icp;
    sp.threads = threads;
    return sp;
}

void BM_AttributeSimilarity(benchmark::State& state, const std::string& name)
{
    const MapPair* p = pairOrSkip(state, name);
    if (!p) return;
    const VertexSimilarityParameters sp;
    SimilarityMatrix s;
    for (auto _ : state)
    {
        s = attributeSimilarity(p->gt, p->map, sp);
        benchmark::DoNotOptimize(s.data());
    }
    setCounters(state, *p, matchGraphs(p->gt, p->map, s));
}

void BM_IcpSimilarity(benchmark::State& state, const std::string& name)
{
    const MapPair* p = pairOrSkip(state, name);
    if (!p) return;
    const VertexSimilarityParameters sp = icpParams(static_cast<int>(state.range(0)));
    SimilarityMatrix s;
    std::map<std::string, double> timing;
    double clouds_ms = 0.0;
    for (auto _ : state)
    {
        s = icpSimilarity(p->gt, p->grid_gt, p->map, p->grid_map, sp, &timing);
        clouds_ms += timing["clouds"];
        benchmark::DoNotOptimize(s.data());
    }
    setCounters(state, *p, matchGraphs(p->gt, p->map, s));
    state.counters["clouds_ms"] = benchmark::Counter(clouds_ms, benchmark::Counter::kAvgIterations);
}

void BM_MatchGraphs(benchmark::State& state, const std::string& name)
{
    const MapPair* p = pairOrSkip(state, name);
    if (!p) return;
    const SimilarityMatrix s = attributeSimilarity(p->gt, p->map, {});
    GraphMatch m;
    for (auto _ : state)
    {
        m = matchGraphs(p->gt, p->map, s);
        benchmark::DoNotOptimize(m.pairs.data());
    }
    setCounters(state, *p, m);
}

/** Build both graphs, similarity (range(0): 0 attributes, 1 ICP on 2 threads), match. */
void BM_Pipeline(benchmark::State& state, const std::string& name)
{
    const MapPair* p = pairOrSkip(state, name);
    if (!p) return;
    const bool icp = state.range(0) == 1;
    const VertexSimilarityParameters sp = icp ? icpParams(2) : VertexSimilarityParameters{};
    GraphMatch m;
    for (auto _ : state)
    {
        const TopologyGraph gt = buildTopologyGraph(p->grid_gt);
        const TopologyGraph map = buildTopologyGraph(p->grid_map);
        const SimilarityMatrix s = icp ? icpSimilarity(gt, p->grid_gt, map, p->grid_map, sp)
                                       : attributeSimilarity(gt, map, sp);
        m = matchGraphs(gt, map, s);
        benchmark::DoNotOptimize(m.pairs.data());
    }
    setCounters(state, *p, m);
}

// The whole of `topoeval compare` after loading: both graphs, similarity, match, evaluation.
void BM_Compare(benchmark::State& state, const std::string& name)
{
    const MapPair* p = pairOrSkip(state, name);
    if (!p) return;
    Parameters params;
    if (state.range(0) == 1) params.similarity = icpParams(2);
    QualityReport r;
    for (auto _ : state)
    {
        r = evaluate(p->grid_gt, p->grid_map, params);
        benchmark::DoNotOptimize(r.quality);
    }
    setCounters(state, *p, r.match);
    state.counters["brokenness"] = r.brokenness.degree;
}

void registerAll()
{
    for (const std::string name : {"intel", "intel_self_rotated", "campus_broken"})
        benchmark::RegisterBenchmark(("BM_Compare/" + name).c_str(), BM_Compare, name)
            ->ArgName("icp")
            ->Arg(0)
            ->Arg(1)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    for (const std::string name : {"office", "intel", "house"})
    {
        benchmark::RegisterBenchmark(("BM_AttributeSimilarity/" + name).c_str(),
                                     BM_AttributeSimilarity, name)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("BM_IcpSimilarity/" + name).c_str(), BM_IcpSimilarity, name)
            ->ArgName("threads")
            ->Arg(1)
            ->Arg(2)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("BM_MatchGraphs/" + name).c_str(), BM_MatchGraphs, name)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("BM_Pipeline/" + name).c_str(), BM_Pipeline, name)
            ->ArgName("icp")
            ->Arg(0)
            ->Arg(1)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
}

}  // namespace

int main(int argc, char** argv)
{
    registerAll();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
