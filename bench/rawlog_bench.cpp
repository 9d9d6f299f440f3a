/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Rawlog scoring on driving_in_office.rawlog: ICP-SLAM alone (one snapshot at the end, the
// least scoring possible) against SLAM + scoring every 100 scans. README, "Performance".

#include <benchmark/benchmark.h>
#include <mrpt_topoeval/RawlogScorer.h>
#include <mrpt_topoeval/maps/load_map.h>

#include "test_paths.h"

using namespace mrpt_topoeval;

namespace
{
void runRawlog(benchmark::State& state, std::size_t every)
{
    const auto log = testing::sharedDataFile("rawlogs/driving_in_office.rawlog");
    const auto gt = testing::sharedDataFile("rawlogs/gh25_gt_trinary_res0.05.yaml");
    if (!log || !gt)
    {
        state.SkipWithError("../shared/data/rawlogs/driving_in_office.rawlog is not there");
        return;
    }
    const auto gt_map = loadMap(*gt);
    RawlogScorerOptions opts;
    opts.every_scans = every;
    double slam_ms = 0, scoring_ms = 0;
    std::size_t snapshots = 0;
    for (auto _ : state)
    {
        RawlogScorer scorer(opts, Parameters());
        const auto res = scorer.run(*log, gt_map.grid);
        slam_ms = res.slam_ms;
        scoring_ms = res.scoring_ms;
        snapshots = res.rows.size();
    }
    state.counters["slam_ms"] = slam_ms;
    state.counters["scoring_ms"] = scoring_ms;
    state.counters["snapshots"] = static_cast<double>(snapshots);
}

/** SLAM alone: the final snapshot only (every > number of scans). */
void BM_SlamAlone(benchmark::State& state) { runRawlog(state, 1000000); }
/** SLAM with a scored snapshot every 100 scans. */
void BM_SlamScoredEvery100(benchmark::State& state) { runRawlog(state, 100); }
}  // namespace

BENCHMARK(BM_SlamAlone)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_SlamScoredEvery100)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_MAIN();
