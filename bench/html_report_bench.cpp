/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Google Benchmark of the HTML report (doc/report.md): what `--html` adds to a compare, and the
// size of a 100-map rank page. Pairs:
//   office: the synthetic office floor against a copy rotated by 37 deg (built in code);
//   intel:  Radish intel-corrected_ref vs the ICP-SLAM map of the Intel lab (../shared/data).
// BM_CompareEvaluate: evaluate() alone (the compare itself, loading aside), for the ratio.
// BM_CompareHtml: the ground truth's picture, the map's entry and the page (what compare adds).
// BM_RankHtml100: a rank page of 100 entries of the pair's map, each with its own picture and
// thumbnail, as `rank --html` makes them. Counter `page_MB`: the page's size [MB = 10^6 bytes].

#include <benchmark/benchmark.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/html_report.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <mrpt_topoeval/pipeline/evaluate.h>

#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "synthetic_maps.h"
#include "test_paths.h"

namespace
{
using mrpt::maps::COccupancyGridMap2D;
using namespace mrpt_topoeval;

/** A compared pair: both grids, their graphs and the report. */
struct Compared
{
    COccupancyGridMap2D gt_grid, map_grid;
    TopologyGraph gt, map;
    QualityReport report;
};

std::unique_ptr<Compared> compare(COccupancyGridMap2D gt, COccupancyGridMap2D map)
{
    auto c = std::make_unique<Compared>();
    c->gt_grid = std::move(gt);
    c->map_grid = std::move(map);
    c->report = evaluate(c->gt_grid, c->map_grid, Parameters{}, &c->gt, &c->map);
    return c;
}

/** The pair, compared once per process; nullptr (benchmark skipped) without its data. */
const Compared* pairOrSkip(benchmark::State& state, const std::string& name)
{
    static std::map<std::string, std::unique_ptr<Compared>> cache;
    auto& slot = cache[name];
    if (!slot && name == "office")
    {
        const COccupancyGridMap2D office = testing::makeOfficeMap();
        slot = compare(office, testing::transformGrid(office, 37.0 * M_PI / 180.0, {2.5, -1.0}));
    }
    else if (!slot && name == "intel")
    {
        const auto gt = testing::sharedDataFile("radish/intel-corrected_ref.yaml");
        const auto map = testing::sharedDataFile("slam_maps/intel_icp-slam_app-final.yaml");
        if (gt && map) slot = compare(loadMap(*gt).grid, loadMap(*map).grid);
    }
    if (!slot)
    {
        state.SkipWithError(("no data for pair " + name + " (../shared/data)").c_str());
        for (auto _ : state)
        {
        }
    }
    return slot.get();
}

HtmlReportContent page(const Compared& c, HtmlReportContent::Kind kind)
{
    HtmlReportContent p;
    p.kind = kind;
    p.title = "benchmark";
    p.parameters_ini = "[QualityEvaluator]\n";
    p.ground_truth = makeHtmlMap("gt.yaml", c.gt_grid, c.gt);
    return p;
}

void BM_CompareEvaluate(benchmark::State& state, const std::string& name)
{
    const Compared* c = pairOrSkip(state, name);
    if (!c) return;
    for (auto _ : state)
    {
        const QualityReport r = evaluate(c->gt_grid, c->map_grid, Parameters{});
        benchmark::DoNotOptimize(r.quality);
    }
}

void BM_CompareHtml(benchmark::State& state, const std::string& name)
{
    const Compared* c = pairOrSkip(state, name);
    if (!c) return;
    std::string html;
    for (auto _ : state)
    {
        HtmlReportContent p = page(*c, HtmlReportContent::Kind::Compare);
        p.entries.push_back(
            makeHtmlEntry("map.yaml", c->gt_grid, c->gt, c->map_grid, c->map, c->report, false));
        html = renderHtmlReport(p);
        benchmark::DoNotOptimize(html.data());
    }
    state.counters["page_MB"] = static_cast<double>(html.size()) / 1e6;
}

void BM_RankHtml100(benchmark::State& state, const std::string& name)
{
    const Compared* c = pairOrSkip(state, name);
    if (!c) return;
    std::string html;
    for (auto _ : state)
    {
        HtmlReportContent p = page(*c, HtmlReportContent::Kind::Rank);
        for (int i = 0; i < 100; ++i)
        {
            p.entries.push_back(makeHtmlEntry("map_" + std::to_string(i) + ".yaml", c->gt_grid,
                                              c->gt, c->map_grid, c->map, c->report, true));
            p.ranks.push_back(std::to_string(i + 1));
        }
        html = renderHtmlReport(p);
        benchmark::DoNotOptimize(html.data());
    }
    state.counters["page_MB"] = static_cast<double>(html.size()) / 1e6;
}

/** Registered before main(): the pairs are runtime names, not BENCHMARK() macros. */
bool registerAll()
{
    for (const std::string name : {"office", "intel"})
    {
        benchmark::RegisterBenchmark(("BM_CompareEvaluate/" + name).c_str(), BM_CompareEvaluate,
                                     name)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("BM_CompareHtml/" + name).c_str(), BM_CompareHtml, name)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("BM_RankHtml100/" + name).c_str(), BM_RankHtml100, name)
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1)
            ->UseRealTime();
    }
    return true;
}
const bool kRegistered = registerAll();
}  // namespace

BENCHMARK_MAIN();
