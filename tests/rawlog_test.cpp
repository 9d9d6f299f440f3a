/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Rawlog scoring (doc/rawlog.md): a rawlog simulated from a known office map with perfect
// odometry must end covered and unbroken; real-data quirks (untimed odometry, unknown objects)
// are repaired and counted; truncated, empty and non-rawlog files are handled, and probe()
// refuses them as run() does; real logs from ../shared/data when present.
//
// The demo's sample in share/mrpt_topoeval/rawlog/ is made by the DISABLED_ test at the end:
//   build-*/tests/rawlog_test --gtest_also_run_disabled_tests --gtest_filter='*MakeShareSample*'

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt_topoeval/RawlogScorer.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/maps/load_map.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "simulated_rawlog.h"
#include "synthetic_maps.h"
#include "test_paths.h"

namespace fs = std::filesystem;
using namespace mrpt_topoeval;
using namespace mrpt_topoeval::testing;

namespace
{
/** A temporary folder for one test, removed at scope exit. */
struct TempDir : ScopedTempDir
{
    TempDir() : ScopedTempDir("rawlog") {}
};

/** The office map and a path through all of it; shared by the tests (simulated once). */
const mrpt::maps::COccupancyGridMap2D& office()
{
    static const auto g = makeOfficeMap(0.05);
    return g;
}

std::vector<mrpt::poses::CPose2D> officePath(double step_m = 0.5)
{
    return drivePath(officeWaypoints(), step_m, 20.0);
}

RawlogScorerOptions everyScans(std::size_t n)
{
    RawlogScorerOptions o;
    o.every_scans = n;
    return o;
}

void cutFile(const std::string& path, std::uintmax_t keep) { fs::resize_file(path, keep); }
}  // namespace

TEST(RawlogScorer, CsvHeaderIsTheDocumentedOne)
{
    EXPECT_EQ(scoreCsvHeader(),
              "step,entry,time_s,scans,vertices,coverage,relative_accuracy,consistency_short,"
              "consistency_medium,consistency_long,brokenness,quality,scoring_ms,explained_walls");
    ScoreRow r;
    r.time_s = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(scoreCsvLine(r), "0,0,,0,0,0.0000,0.0000,0.0000,0.0000,0.0000,0,0.0000,0.0,0.0000");
}

TEST(RawlogScorer, PerfectOdometryCoverageRisesAndEndsUnbroken)
{
    const TempDir dir;
    const std::string log = dir.path + "/office.rawlog";
    const auto poses = officePath();
    const std::size_t n = writeSimulatedRawlog(log, office(), poses);
    RawlogScorer scorer(everyScans(60), Parameters());
    std::vector<ScoreRow> seen;
    scorer.onSnapshot([&](const Snapshot& s) { seen.push_back(s.row); });
    const RawlogScoreResult res = scorer.run(log, office());

    EXPECT_EQ(res.stop, RawlogStop::EndOfFile);
    EXPECT_EQ(res.stats.scans, n);
    EXPECT_EQ(res.stats.entries, 2 * n);  // nothing lost
    EXPECT_EQ(res.stats.format, "action-sensoryframe");
    EXPECT_EQ(res.stats.odometry_stamped, 0u);
    EXPECT_EQ(res.stats.scans_restamped, 0u);
    ASSERT_EQ(res.rows.size(), (n + 59) / 60);
    ASSERT_EQ(seen.size(), res.rows.size());
    EXPECT_EQ(res.rows.back().scans, n);
    EXPECT_EQ(res.rows.back().entry, 2 * n - 1);
    EXPECT_NEAR(res.rows.back().time_s, 0.1 * static_cast<double>(n - 1), 1e-3);
    for (std::size_t i = 0; i < res.rows.size(); ++i)
    {
        std::printf("%s\n", scoreCsvLine(res.rows[i]).c_str());
        EXPECT_EQ(res.rows[i].step, static_cast<int>(i) + 1);
        // A growing map of a perfect run never loses much coverage (small skeleton changes).
        if (i > 0)
        {
            EXPECT_GE(res.rows[i].coverage, res.rows[i - 1].coverage - 0.1) << i;
        }
    }
    EXPECT_LT(res.rows.front().coverage, 0.5);
    EXPECT_GE(res.rows.back().coverage, 0.8);
    EXPECT_EQ(res.rows.back().brokenness, 0);
    EXPECT_EQ(res.final_report.brokenness.degree, 0);
    EXPECT_GT(res.final_grid.getSizeX(), 0u);
    EXPECT_NEAR(res.final_grid.getResolution(), 0.05, 1e-6);
    EXPECT_NE(res.effective_slam_ini.find("[MappingApplication]"), std::string::npos);

    // The keyframes: each a scan of the log (found by its time) at a pose that, relative to
    // the first keyframe's, is the true one but for ICP-SLAM's own drift (perfect odometry, a
    // clean simulation: at most 0.107 m and under 2 degrees measured over the whole drive).
    ASSERT_GE(res.final_keyframes.size(), 10u);
    EXPECT_LT(res.final_keyframes.size(), n);
    const auto t0 = mrpt::Clock::fromDouble(1.6e9);
    mrpt::poses::CPose2D first_est, first_true;
    for (std::size_t k = 0; k < res.final_keyframes.size(); ++k)
    {
        const auto& [pdf, sf] = res.final_keyframes.get(k);
        const auto scan = sf->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
        ASSERT_TRUE(scan) << k;
        const double i = mrpt::system::timeDifference(t0, scan->timestamp) / 0.1;
        const auto index = static_cast<std::size_t>(std::lround(i));
        ASSERT_NEAR(i, double(index), 1e-3) << k;
        ASSERT_LT(index, poses.size()) << k;
        const mrpt::poses::CPose2D est(pdf->getMeanVal());
        if (k == 0) first_est = est, first_true = poses[index];
        const mrpt::poses::CPose2D rel_est = est - first_est, rel_true = poses[index] - first_true;
        EXPECT_LT((rel_est - rel_true).norm(), 0.2) << "keyframe " << k << " scan " << index;
        EXPECT_LT(std::abs(mrpt::math::wrapToPi(rel_est.phi() - rel_true.phi())), 0.035)
            << "keyframe " << k;
    }
}

TEST(RawlogScorer, ObservationFormatGzUntimedOdometryAndUnknownObjects)
{
    const TempDir dir;
    const std::string log = dir.path + "/office_obs.rawlog.gz";
    SimulatedRawlogOptions sim;
    sim.observation_format = true;
    sim.untimed_odometry = true;
    sim.unknown_objects = true;
    sim.gzip = true;
    // A short drive: only the bookkeeping is checked here.
    auto poses = officePath();
    poses.resize(120);
    const std::size_t n = writeSimulatedRawlog(log, office(), poses, sim);
    RawlogScorer scorer(everyScans(50), Parameters());
    const RawlogScoreResult res = scorer.run(log, office());
    EXPECT_EQ(res.stop, RawlogStop::EndOfFile);
    EXPECT_EQ(res.stats.format, "observations");
    EXPECT_EQ(res.stats.scans, n);
    EXPECT_EQ(res.stats.odometry, n);
    EXPECT_EQ(res.stats.odometry_stamped, n);  // every one got its scan's time
    EXPECT_EQ(res.stats.unknown_objects, n / 10);
    EXPECT_EQ(res.stats.entries, 2 * n + n / 10);
    EXPECT_EQ(res.stats.scans_without_odometry, 0u);
    EXPECT_EQ(res.rows.size(), 3u);
}

// Real rawlogs hold other sensors (cameras, IMU, GPS): entries and frames of classes whose
// serialized layout topoeval does not check are read by MRPT as they are, and skipped.
TEST(RawlogScorer, OtherSensorsAreReadAndSkippedInBothFormats)
{
    for (const bool obs_format : {false, true})
    {
        SCOPED_TRACE(obs_format ? "observations" : "action/sensory-frame pairs");
        const TempDir dir;
        const std::string log = dir.path + "/imu.rawlog";
        SimulatedRawlogOptions sim;
        sim.observation_format = obs_format;
        sim.other_sensors = true;
        auto poses = officePath();
        poses.resize(60);
        const std::size_t n = writeSimulatedRawlog(log, office(), poses, sim);
        RawlogScorer scorer(everyScans(30), Parameters());
        const RawlogScoreResult res = scorer.run(log, office());
        EXPECT_EQ(res.stop, RawlogStop::EndOfFile) << res.stop_message;
        EXPECT_EQ(res.stats.scans, n);
        EXPECT_EQ(res.stats.other_observations, n / 10);
        EXPECT_EQ(res.stats.entries, obs_format ? 2 * n + n / 10 : 2 * n);
        EXPECT_EQ(res.rows.size(), 2u);
    }
}

TEST(RawlogScorer, UntimedActionsAreStampedAndScansWithoutOdometryCounted)
{
    const TempDir dir;
    const std::string log = dir.path + "/untimed.rawlog";
    SimulatedRawlogOptions sim;
    sim.untimed_odometry = true;
    auto poses = officePath();
    poses.resize(80);
    const std::size_t n = writeSimulatedRawlog(log, office(), poses, sim);
    // Two sensory frames with no action before them, and equal timestamps.
    {
        mrpt::io::CFileGZOutputStream f;
        ASSERT_TRUE(f.open(dir.path + "/extra.rawlog", 0));
        auto ar = mrpt::serialization::archiveFrom(f);
        for (int i = 0; i < 2; ++i)
        {
            auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
            scan->aperture = static_cast<float>(2 * M_PI);
            scan->maxRange = 12.0f;
            office().laserScanSimulator(*scan, poses.back(), 0.5f, 361);
            scan->timestamp = mrpt::Clock::fromDouble(1.0);  // before every other scan
            mrpt::obs::CSensoryFrame sf;
            sf.insert(scan);
            ar << sf;
        }
    }
    {
        std::ofstream out(log, std::ios::binary | std::ios::app);
        std::ifstream in(dir.path + "/extra.rawlog", std::ios::binary);
        out << in.rdbuf();
    }
    RawlogScorer scorer(everyScans(1000), Parameters());
    const RawlogScoreResult res = scorer.run(log, office());
    EXPECT_EQ(res.stop, RawlogStop::EndOfFile);
    EXPECT_EQ(res.stats.scans, n + 2);
    EXPECT_EQ(res.stats.odometry_stamped, n);
    EXPECT_EQ(res.stats.scans_without_odometry, 2u);
    EXPECT_EQ(res.stats.scans_restamped, 2u);
    ASSERT_EQ(res.rows.size(), 1u);  // the final snapshot only
    EXPECT_EQ(res.rows.back().scans, n + 2);
}

TEST(RawlogScorer, TruncatedRawlogStopsAndScoresThePartDone)
{
    const TempDir dir;
    const std::string log = dir.path + "/cut.rawlog";
    auto poses = officePath();
    poses.resize(150);
    writeSimulatedRawlog(log, office(), poses);
    const auto size = fs::file_size(log);
    cutFile(log, size / 2 + 7);  // inside an entry
    RawlogScorer scorer(everyScans(50), Parameters());
    const RawlogScoreResult res = scorer.run(log, office());
    EXPECT_EQ(res.stop, RawlogStop::Truncated) << res.stop_message;
    EXPECT_GT(res.stats.scans, 60u);
    EXPECT_LT(res.stats.scans, 90u);
    EXPECT_EQ(res.stop_entry, res.stats.entries);
    EXPECT_NE(res.stop_message.find(log), std::string::npos);
    EXPECT_NE(res.stop_message.find("entry " + std::to_string(res.stop_entry)), std::string::npos)
        << res.stop_message;
    ASSERT_FALSE(res.rows.empty());
    EXPECT_EQ(res.rows.back().scans, res.stats.scans);  // the part done was scored
}

TEST(RawlogScorer, StopFlagInterruptsAndScoresThePartDone)
{
    const TempDir dir;
    const std::string log = dir.path + "/stop.rawlog";
    auto poses = officePath();
    poses.resize(100);
    writeSimulatedRawlog(log, office(), poses);
    std::atomic<bool> stop{false};
    RawlogScorer scorer(everyScans(30), Parameters());
    // Set from the snapshot callback, as a signal handler would between two entries.
    scorer.onSnapshot([&](const Snapshot&) { stop = true; });
    const RawlogScoreResult res = scorer.run(log, office(), &stop);
    EXPECT_EQ(res.stop, RawlogStop::Interrupted);
    EXPECT_EQ(res.stats.scans, 30u);
    EXPECT_EQ(res.rows.size(), 1u);  // the snapshot at 30 scans is the final one
}

TEST(RawlogScorer, EmptyMissingAndNonRawlogFilesAreBadInput)
{
    const TempDir dir;
    RawlogScorer scorer(everyScans(10), Parameters());
    const std::string empty = dir.path + "/empty.rawlog";
    std::ofstream(empty).close();
    const std::string text = dir.path + "/text.rawlog";
    std::ofstream(text) << "this is not a rawlog\n";
    for (const std::string& path : {empty, text, dir.path + "/missing.rawlog", dir.path})
    {
        try
        {
            scorer.run(path, office());
            ADD_FAILURE() << path << " was accepted";
        }
        catch (const InputError& e)
        {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    }
}

namespace
{
/** The InputError message of `f`, or "(accepted)". */
template <typename F>
std::string inputErrorOf(F&& f)
{
    try
    {
        f();
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "(accepted)";
}
}  // namespace

// probe() runs before the CLI creates its output folder: it must refuse exactly what run()
// refuses as bad input, with the same message.
TEST(RawlogScorer, ProbeRefusesWhatRunRefusesWithTheSameMessage)
{
    const TempDir dir;
    const std::string empty = dir.path + "/empty.rawlog";
    std::ofstream(empty).close();
    const std::string text = dir.path + "/text.rawlog";
    std::ofstream(text) << "this is not a rawlog\n";
    const std::string no_scan = dir.path + "/no_scan.rawlog";
    writeRawlogWithoutScans(no_scan, 12, false);
    const std::string no_scan_gz = dir.path + "/no_scan.rawlog.gz";
    writeRawlogWithoutScans(no_scan_gz, 2000, true);
    const std::string no_scan_cut = dir.path + "/no_scan_cut.rawlog.gz";
    fs::copy_file(no_scan_gz, no_scan_cut);
    cutFile(no_scan_cut, fs::file_size(no_scan_gz) / 2);
    const std::string log = dir.path + "/short.rawlog";
    auto poses = officePath();
    poses.resize(5);
    writeSimulatedRawlog(log, office(), poses);  // 10 entries: action, frame, action, ...
    const std::string cut_first = dir.path + "/cut_first.rawlog";
    fs::copy_file(log, cut_first);
    cutFile(cut_first, 100);

    struct Case
    {
        std::string name, path, must_contain;
        RawlogScorerOptions opts;
    };
    std::vector<Case> cases = {
        {"empty", empty, "is empty", everyScans(10)},
        {"text", text, "not an MRPT rawlog", everyScans(10)},
        {"missing", dir.path + "/missing.rawlog", "no such file", everyScans(10)},
        {"folder", dir.path, "is a folder", everyScans(10)},
        {"no scan", no_scan, "no 2D laser scan in 12 entries", everyScans(10)},
        {"no scan, gz", no_scan_gz, "no 2D laser scan in 2000 entries", everyScans(10)},
        {"no scan, cut", no_scan_cut, "before it stopped", everyScans(10)},
        {"cut in the first entry", cut_first, "not an MRPT rawlog", everyScans(10)},
    };
    Case max_entries{"max entries before a scan", log, "max entries reached", everyScans(10)};
    max_entries.opts.max_entries = 1;  // the first action only
    cases.push_back(max_entries);
    const std::string ini = dir.path + "/offset.ini";
    std::ofstream(ini) << "[MappingApplication]\nrawlog_offset=10\n";
    Case offset{"every scan before rawlog_offset", log, "no 2D laser scan in 10", everyScans(10)};
    offset.opts.slam_config_file = ini;
    cases.push_back(offset);
    Case bad_ini{"missing SLAM INI", log, "--slam-config", everyScans(10)};
    bad_ini.opts.slam_config_file = dir.path + "/missing.ini";
    cases.push_back(bad_ini);
    // MRPT's exception text starts with a banner line: the message names the value instead.
    const std::string bogus_ini = dir.path + "/bogus.ini";
    std::ofstream(bogus_ini) << "[MappingApplication]\n[ICP]\nICP_algorithm=bogus\n";
    Case bogus{"invalid SLAM INI value", log, "Invalid value 'bogus'", everyScans(10)};
    bogus.opts.slam_config_file = bogus_ini;
    cases.push_back(bogus);

    for (const Case& c : cases)
    {
        SCOPED_TRACE(c.name);
        const RawlogScorer scorer(c.opts, Parameters());
        const std::string probed = inputErrorOf([&] { scorer.probe(c.path); });
        RawlogScorer runner(c.opts, Parameters());
        const std::string ran = inputErrorOf([&] { runner.run(c.path, office()); });
        EXPECT_EQ(probed, ran);
        EXPECT_NE(probed.find(c.must_contain), std::string::npos) << probed;
        if (c.name != "missing SLAM INI" && c.name != "invalid SLAM INI value")
        {
            EXPECT_NE(probed.find(c.path), std::string::npos) << probed;
        }
    }
}

TEST(RawlogScorer, ProbeReadsUpToTheFirstScanOnly)
{
    const TempDir dir;
    auto poses = officePath();
    poses.resize(60);
    const std::string log = dir.path + "/office.rawlog";
    writeSimulatedRawlog(log, office(), poses);
    SimulatedRawlogOptions obs;
    obs.observation_format = true;
    obs.gzip = true;
    const std::string log_obs = dir.path + "/office_obs.rawlog.gz";
    writeSimulatedRawlog(log_obs, office(), poses, obs);

    const RawlogScorer scorer(everyScans(100), Parameters());
    for (const std::string& path : {log, log_obs})
    {
        SCOPED_TRACE(path);
        // Action, then the frame with the first scan; odometry, then the first scan.
        const RawlogProbe p = scorer.probe(path);
        EXPECT_EQ(p.first_scan_entry, 1u);
        EXPECT_EQ(p.entries, 2u);
    }
    // The SLAM set-up is the one run() uses.
    RawlogScorer runner(everyScans(100), Parameters());
    EXPECT_EQ(scorer.probe(log).effective_slam_ini, runner.run(log, office()).effective_slam_ini);

    // Entries before rawlog_offset do not count, as in run().
    const std::string ini = dir.path + "/offset.ini";
    std::ofstream(ini) << "[MappingApplication]\nrawlog_offset=4\noccupancyGrid_count=0\n";
    RawlogScorerOptions o = everyScans(100);
    o.slam_config_file = ini;
    const RawlogProbe p = RawlogScorer(o, Parameters()).probe(log);
    EXPECT_EQ(p.first_scan_entry, 5u);
    ASSERT_FALSE(p.messages.empty());  // the grid added to a configuration without one
    EXPECT_NE(p.messages.front().find("no occupancy grid"), std::string::npos);
}

TEST(RawlogScorer, SlamConfigurationIsMrptsOwn)
{
    const TempDir dir;
    // An icp-slam INI as MRPT's demo ships it: no grid, app-only keys: works unchanged.
    const std::string ini = dir.path + "/icp-slam.ini";
    std::ofstream(ini) << "[MappingApplication]\nrawlog_file=x.rawlog\nrawlog_offset=4\n"
                          "logOutput_dir=out\nLOG_FREQUENCY=5\ninsertionLinDistance=0.8\n"
                          "pointsMap_count=1\noccupancyGrid_count=0\n[ICP]\nmaxIterations=50\n";
    const std::string log = dir.path + "/short.rawlog";
    auto poses = officePath();
    poses.resize(40);
    writeSimulatedRawlog(log, office(), poses);
    RawlogScorerOptions o = everyScans(100);
    o.slam_config_file = ini;
    RawlogScorer scorer(o, Parameters());
    const RawlogScoreResult res = scorer.run(log, office());
    EXPECT_EQ(res.stats.skipped_before_offset, 4u);
    EXPECT_EQ(res.stats.scans, 38u);
    EXPECT_NEAR(res.final_grid.getResolution(), 0.05, 1e-6);  // the default grid was added
    // The effective INI reproduces the run when read back by MRPT.
    mrpt::config::CConfigFileMemory eff(res.effective_slam_ini);
    EXPECT_DOUBLE_EQ(eff.read_double("MappingApplication", "insertionLinDistance", 0.0), 0.8);
    EXPECT_EQ(eff.read_int("ICP", "maxIterations", 0), 50);
    EXPECT_NEAR(eff.read_double("ICP", "thresholdAng_DEG", 0.0), 0.15, 1e-6);
    EXPECT_EQ(eff.read_int("MappingApplication", "rawlog_offset", 0), 4);
    ASSERT_FALSE(res.messages.empty());
    EXPECT_NE(res.messages.front().find("no occupancy grid"), std::string::npos);

    o.slam_config_file = dir.path + "/missing.ini";
    RawlogScorer bad(o, Parameters());
    EXPECT_THROW(bad.run(log, office()), InputError);
}

TEST(RawlogScorer, PlotHasItsSize)
{
    std::vector<ScoreRow> rows(3);
    for (int i = 0; i < 3; ++i)
    {
        rows[i].time_s = 10.0 * i;
        rows[i].coverage = 0.3 * i;
    }
    const auto img = drawScorePlot(rows, "test");
    EXPECT_EQ(img.getWidth(), 960u);
    EXPECT_EQ(img.getHeight(), 540u);
    EXPECT_EQ(drawScorePlot({}, "empty").getWidth(), 960u);
}

// ------------------------------------------------------------------ real data (when present)

TEST(RawlogScorerRealData, DrivingInOfficeAgainstGh25)
{
    const auto log = sharedDataFile("rawlogs/driving_in_office.rawlog");
    const auto gt = sharedDataFile("rawlogs/gh25_gt_trinary_res0.05.yaml");
    if (!log || !gt) GTEST_SKIP() << "../shared/data/rawlogs not present";
    const auto gt_map = loadMap(*gt);
    RawlogScorer scorer(everyScans(200), Parameters());
    std::size_t callbacks = 0;
    scorer.onSnapshot([&](const Snapshot&) { ++callbacks; });
    const RawlogScoreResult res = scorer.run(*log, gt_map.grid);
    EXPECT_EQ(res.stop, RawlogStop::EndOfFile);
    EXPECT_GT(res.stats.scans, 1100u);
    EXPECT_EQ(res.rows.size(), (res.stats.scans + 199) / 200);
    EXPECT_EQ(callbacks, res.rows.size());
    std::printf("driving_in_office: %zu scans, final %s\n", res.stats.scans,
                scoreCsvLine(res.rows.back()).c_str());
}

TEST(RawlogScorerRealData, IntelWithUntimedActionsRunsToTheEnd)
{
    const auto log = sharedDataFile("rawlogs/intel.rawlog");
    const auto gt = sharedDataFile("radish/intel-corrected_ref.yaml");
    if (!log || !gt) GTEST_SKIP() << "../shared/data not present";
    const auto gt_map = loadMap(*gt);
    RawlogScorerOptions o = everyScans(100000);  // the final snapshot only
    // The whole log takes ~13 s of SLAM: the test reads its first 1200 entries (the CLI reads
    // everything); the untimed actions are at the very start.
    o.max_entries = 1200;
    RawlogScorer scorer(o, Parameters());
    const RawlogScoreResult res = scorer.run(*log, gt_map.grid);
    EXPECT_EQ(res.stop, RawlogStop::MaxEntries);
    EXPECT_EQ(res.stats.entries, 1200u);
    EXPECT_GT(res.stats.odometry_stamped, 500u);
    EXPECT_EQ(res.rows.size(), 1u);
}

// ------------------------------------------------------------------ the demo's sample

/** Writes share/mrpt_topoeval/rawlog/: the office map as a ROS map (PNG + YAML) and a
 * simulated gz rawlog of about 300 scans with perfect odometry. Run explicitly (see the top
 * of this file); the files are committed. */
TEST(RawlogScorer, DISABLED_MakeShareSample)
{
    const std::string dir = shareDir() + "/rawlog";
    fs::create_directories(dir);
    const auto& g = office();
    ASSERT_TRUE(g.saveAsBitmapFile(dir + "/office_gt.png"));
    std::ofstream(dir + "/office_gt.yaml")
        << "image: office_gt.png\nresolution: 0.05\norigin: [" << g.getXMin() << ", " << g.getYMin()
        << ", 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
    SimulatedRawlogOptions sim;
    sim.gzip = true;
    const auto poses = drivePath(officeWaypoints(), 0.9, 30.0);
    const std::size_t n = writeSimulatedRawlog(dir + "/office_sim.rawlog.gz", g, poses, sim);
    std::printf("wrote %s: %zu scans\n", dir.c_str(), n);
    // The sample must be worth a demo: covered and unbroken.
    RawlogScorer scorer(everyScans(50), Parameters());
    const auto res =
        scorer.run(dir + "/office_sim.rawlog.gz", loadMap(dir + "/office_gt.yaml").grid);
    EXPECT_GE(res.rows.back().coverage, 0.8);
    EXPECT_EQ(res.rows.back().brokenness, 0);
}
