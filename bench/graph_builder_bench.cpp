/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Google Benchmark of buildTopologyGraph() on the Radish reference maps (../shared/data/radish,
// skipped when absent) and on synthetic buildings of growing size.
//
// Counters: `vertices` of the graph, `cells` of the grid, `sites` (obstacle cells used as
// Voronoi sites), `ms_cleaning`, `ms_voronoi`, `ms_graph` (the last build's time in the
// cleaning steps and site search, the Voronoi diagram, and the graph steps after it; of the
// cleaning, `ms_close_gaps` and `ms_unknown_specks`, its two closings) and
// `peak_rss_MB`, the process's peak resident memory (getrusage ru_maxrss) after the benchmark.
// The peak only grows during a run (benchmarks run smallest first): for one benchmark's own
// peak, run it alone, e.g. `--benchmark_filter=LargeBuilding/10000`.

#include <benchmark/benchmark.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <sys/resource.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "synthetic_maps.h"
#include "test_paths.h"

namespace
{
namespace fs = std::filesystem;
using mrpt::maps::COccupancyGridMap2D;

/** Peak resident memory of this process so far [MB] (Linux reports ru_maxrss in KiB). */
double peakRssMB()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/** Times buildTopologyGraph() on `grid` (loading is not timed) and sets the counters. */
void runBuild(benchmark::State& state, const COccupancyGridMap2D& grid)
{
    mrpt_topoeval::GraphBuildStats stats;
    std::size_t vertices = 0;
    for (auto _ : state)
    {
        const auto graph = mrpt_topoeval::buildTopologyGraph(grid, {}, &stats);
        vertices = graph.vertices.size();
        benchmark::DoNotOptimize(vertices);
    }
    state.counters["vertices"] = static_cast<double>(vertices);
    state.counters["cells"] = static_cast<double>(grid.getSizeX()) * grid.getSizeY();
    state.counters["sites"] = static_cast<double>(stats.sites);
    // Where the time goes (last iteration): the cleaning steps with the site search, the
    // Voronoi diagram, and the graph steps after it [ms].
    double cleaning = 0.0;
    for (const char* step :
         {"classify", "close_gaps", "enclosed_unknown", "islands", "unknown_specks", "sites"})
        cleaning += stats.timing_ms[step];
    const double voronoi = stats.timing_ms["voronoi"];
    state.counters["ms_cleaning"] = cleaning;
    // The two closings of the cleaning, tile by tile since session 19 (doc/performance.md).
    state.counters["ms_close_gaps"] = stats.timing_ms["close_gaps"];
    state.counters["ms_unknown_specks"] = stats.timing_ms["unknown_specks"];
    state.counters["ms_voronoi"] = voronoi;
    state.counters["ms_graph"] = stats.timing_ms["total"] - cleaning - voronoi;
    state.counters["peak_rss_MB"] = peakRssMB();
}

/** Maps are loaded or built once per process, on first use (not at registration, so a
 * --benchmark_filter run pays only for what it runs). */
template <typename MakeGrid>
const COccupancyGridMap2D& cachedGrid(const std::string& key, MakeGrid make)
{
    static std::map<std::string, std::unique_ptr<COccupancyGridMap2D>> cache;
    auto& slot = cache[key];
    if (!slot) slot = std::make_unique<COccupancyGridMap2D>(make());
    return *slot;
}

void BM_BuildGraph_Radish(benchmark::State& state, const std::string& yaml)
{
    const COccupancyGridMap2D* grid = nullptr;
    try
    {
        grid = &cachedGrid(yaml, [&] { return mrpt_topoeval::loadMap(yaml).grid; });
    }
    catch (const std::exception& e)
    {
        state.SkipWithError(e.what());
        for (auto _ : state)
        {
        }
        return;
    }
    runBuild(state, *grid);
}

void BM_BuildGraph_RadishAbsent(benchmark::State& state)
{
    state.SkipWithError("../shared/data/radish not found: no real maps to benchmark");
    for (auto _ : state)
    {
    }
}

void BM_BuildGraph_LargeBuilding(benchmark::State& state)
{
    const int cells = static_cast<int>(state.range(0));
    const auto& grid = cachedGrid("large_" + std::to_string(cells),
                                  [&] { return mrpt_topoeval::testing::makeLargeBuilding(cells); });
    runBuild(state, grid);
}

void registerRadishBenchmarks()
{
    const auto dir = mrpt_topoeval::testing::sharedDataFile("radish");
    if (!dir)
    {
        benchmark::RegisterBenchmark("BM_BuildGraph_Radish/absent", BM_BuildGraph_RadishAbsent);
        return;
    }
    std::vector<fs::path> yamls;
    for (const auto& entry : fs::directory_iterator(*dir))
        if (entry.path().extension() == ".yaml") yamls.push_back(entry.path());
    std::sort(yamls.begin(), yamls.end());  // a stable order between runs
    for (const auto& yaml : yamls)
    {
        benchmark::RegisterBenchmark(("BM_BuildGraph_Radish/" + yaml.stem().string()).c_str(),
                                     BM_BuildGraph_Radish, yaml.string())
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
}

void registerSyntheticBenchmarks()
{
    benchmark::RegisterBenchmark("BM_BuildGraph_LargeBuilding", BM_BuildGraph_LargeBuilding)
        ->Arg(1000)
        ->Arg(3000)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    // 10^8 cells: one iteration is enough, and it takes seconds.
    benchmark::RegisterBenchmark("BM_BuildGraph_LargeBuilding", BM_BuildGraph_LargeBuilding)
        ->Arg(10000)
        ->Iterations(1)
        ->Unit(benchmark::kSecond)
        ->UseRealTime();
}

}  // namespace

int main(int argc, char** argv)
{
    // Smallest first: the process's peak memory only grows, so each benchmark's peak_rss_MB
    // is then close to its own.
    registerRadishBenchmarks();
    registerSyntheticBenchmarks();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
