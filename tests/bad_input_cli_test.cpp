/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Reliability of the `topoeval` command on bad and degenerate input (issue 6): every run is
// bounded in time (`timeout`), never ends by a signal, exits with the documented code and one
// line naming the file, and leaves no output file behind when it fails. Also: results do not
// depend on the thread count. The file corpus in tests/data/bad_inputs is driven by cli_test;
// the inputs here are made in code (folders, degenerate maps, cut rawlogs, other classes).

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "simulated_rawlog.h"
#include "test_paths.h"

namespace fs = std::filesystem;
using mrpt_topoeval::testing::shareDir;
using mrpt_topoeval::testing::topoevalBin;

using mrpt_topoeval::testing::contains;
using mrpt_topoeval::testing::lineCount;
using mrpt_topoeval::testing::readText;
using mrpt_topoeval::testing::RunResult;
using mrpt_topoeval::testing::ScopedTempDir;
using mrpt_topoeval::testing::topLevelObject;
using mrpt_topoeval::testing::withoutTiming;
using mrpt_topoeval::testing::writeText;
using mrpt_topoeval::testing::writeUniformRosMap;

namespace
{
/** Longest a single run may take, even under the sanitizers [s]; `timeout` kills it after. */
constexpr int kRunTimeLimitS = 60;

/** `s` quoted for /bin/sh. */
std::string q(const std::string& s) { return mrpt_topoeval::testing::shellQuote(s); }

/** `topoeval ARGS` (already quoted) under `timeout`, stdout and stderr captured. */
RunResult run(const std::string& args)
{
    return mrpt_topoeval::testing::runTopoeval(args, kRunTimeLimitS);
}

/** Every file (not folder) under `dir`, recursively, hidden temporary files included.
 * Folders are left out: a test that gives a folder of its own to several runs checks files;
 * the tests of `rawlog` and `series` check that their output folders are not created. */
std::vector<std::string> filesUnder(const std::string& dir)
{
    std::vector<std::string> names;
    if (!fs::exists(dir)) return names;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (!e.is_directory()) names.push_back(e.path().string());
    return names;
}

/** Everything under `dir`, recursively: each file with its bytes, each folder as "<folder>",
 * so that a tree can be compared before and after a run. */
std::map<std::string, std::string> treeOf(const std::string& dir)
{
    std::map<std::string, std::string> tree;
    if (!fs::exists(dir)) return tree;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        tree[e.path().string()] = e.is_directory() ? "<folder>" : readText(e.path().string());
    return tree;
}

/** Exit `code`, one `topoeval: error:` line that contains `must_contain`, no file in `out_dir`. */
void expectCleanFailure(const RunResult& r, int code, const std::string& must_contain,
                        const std::string& out_dir)
{
    EXPECT_NE(r.code, 124) << "timed out after " << kRunTimeLimitS << " s";
    EXPECT_LT(r.code, 128) << "ended by signal " << r.code - 128 << ": " << r.err;
    EXPECT_EQ(r.code, code) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("topoeval: error: ", 0), 0u) << r.err;
    EXPECT_TRUE(contains(r.err, must_contain)) << "'" << must_contain << "' not in: " << r.err;
    EXPECT_TRUE(filesUnder(out_dir).empty()) << "an output was left for a failed run";
}

/** The JSON with the timing (last member) and the thread count (the effective configuration
 * records what was asked) removed: everything else must be byte-identical. */
std::string comparable(const std::string& json)
{
    std::string head = withoutTiming(json);
    const std::string key = "\"threads\": ";
    for (auto k = head.find(key); k != std::string::npos; k = head.find(key, k + 1))
    {
        const auto digits = head.find_first_not_of("0123456789", k + key.size());
        head.replace(k + key.size(), digits - (k + key.size()), "N");
    }
    return head;
}

class BadInputCli : public ::testing::Test
{
protected:
    void SetUp() override
    {
        if (topoevalBin().empty() || !fs::exists(topoevalBin()))
            GTEST_SKIP() << "the topoeval command is not built";
    }
};
}  // namespace

TEST_F(BadInputCli, FoldersGivenAsFilesExit2)
{
    const ScopedTempDir dir("bad_cli");
    const std::string folder_map = dir.path + "/folder.yaml", folder_png = dir.path + "/f.png";
    fs::create_directory(folder_map);
    fs::create_directory(folder_png);
    const std::string gt = writeUniformRosMap(dir.path, "gt", 20, 20, 255);
    const std::string out = dir.path + "/out";
    fs::create_directory(out);
    const std::string outputs = " --json " + q(out + "/o.json") + " --image " + q(out + "/o.png");

    expectCleanFailure(run("graph " + q(folder_map) + outputs), 2, folder_map, out);
    expectCleanFailure(run("graph " + q(folder_png) + outputs), 2, folder_png, out);
    expectCleanFailure(run("graph " + q(dir.path) + outputs), 2, dir.path, out);
    expectCleanFailure(run("compare " + q(gt) + " " + q(folder_map) + outputs), 2, folder_map, out);
    expectCleanFailure(run("match " + q(folder_map) + " " + q(gt) + outputs), 2, folder_map, out);
    expectCleanFailure(run("graph " + q(gt) + " --config " + q(folder_map) + outputs), 2,
                       folder_map, out);
    expectCleanFailure(run("rawlog " + q(folder_map) + " -g " + q(gt) + " -o " + q(out + "/r")), 2,
                       folder_map, out);
}

TEST_F(BadInputCli, GridmapOfAnotherClassAndEmptyFilesExit2)
{
    const ScopedTempDir dir("bad_cli");
    const std::string out = dir.path + "/out";
    fs::create_directory(out);
    const std::string outputs = " --json " + q(out + "/o.json") + " --image " + q(out + "/o.png");

    // A pose serialized where a grid is expected, plain and gz.
    const std::string pose_plain = dir.path + "/pose.gridmap";
    const std::string pose_gz = dir.path + "/pose.gridmap.gz";
    {
        mrpt::io::CFileOutputStream f(pose_plain);
        mrpt::serialization::archiveFrom(f) << mrpt::poses::CPose2D(1, 2, 0.5);
    }
    {
        mrpt::io::CFileGZOutputStream f(pose_gz);
        mrpt::serialization::archiveFrom(f) << mrpt::poses::CPose2D(1, 2, 0.5);
    }
    expectCleanFailure(run("graph " + q(pose_plain) + outputs), 2, pose_plain, out);
    expectCleanFailure(run("graph " + q(pose_gz) + outputs), 2, pose_gz, out);

    for (const char* name : {"empty.pgm", "empty.bmp", "empty.jpg", "empty.gridmap.gz",
                             "empty.simplemap.gz", "empty.yml"})
    {
        const std::string f = dir.path + "/" + name;
        writeText(f, "");
        expectCleanFailure(run("graph " + q(f) + outputs), 2, f, out);
    }
    const std::string empty_ini = dir.path + "/empty.ini";
    writeText(empty_ini, "");
    // An empty INI is a valid configuration (every key keeps its default).
    EXPECT_EQ(run("config --check " + q(empty_ini)).code, 0);
}

TEST_F(BadInputCli, CutRawlogsExit2BeforeTheFirstEntryAnd4After)
{
    const std::string sample = shareDir() + "/rawlog/office_sim.rawlog.gz";
    const std::string gt = shareDir() + "/rawlog/office_gt.yaml";
    if (!fs::exists(sample) || !fs::exists(gt)) GTEST_SKIP() << "no share/ rawlog sample";
    const ScopedTempDir dir("bad_cli_rawlog");
    // The uncompressed sample, so that cuts fall at chosen byte offsets.
    const std::string plain = dir.path + "/full.rawlog";
    ASSERT_EQ(std::system(("zcat " + q(sample) + " > " + q(plain)).c_str()), 0);
    const std::string bytes = readText(plain);
    ASSERT_GT(bytes.size(), 30000u);

    // Cut inside the first entry: nothing was read, so it is not a rawlog (exit 2), no output.
    const std::string cut0 = dir.path + "/cut0.rawlog";
    writeText(cut0, bytes.substr(0, 100));
    const std::string out0 = dir.path + "/out0";
    expectCleanFailure(run("rawlog " + q(cut0) + " -g " + q(gt) + " -o " + q(out0)), 2, cut0, out0);

    // Cut after some entries: stopped early (exit 4), the part done written completely, no
    // temporary file left.
    const std::string cut = dir.path + "/cut.rawlog";
    writeText(cut, bytes.substr(0, 30000));
    const std::string out = dir.path + "/out";
    const RunResult r = run("rawlog " + q(cut) + " -g " + q(gt) + " -o " + q(out));
    EXPECT_EQ(r.code, 4) << r.err;
    EXPECT_TRUE(contains(r.err, cut)) << r.err;
    EXPECT_TRUE(contains(readText(out + "/report.json"), "\"stop\": \"truncated\""));
    for (const std::string& f : filesUnder(out))
        EXPECT_EQ(f.find(".part"), std::string::npos) << "temporary file left: " << f;
}

// A rawlog that fails the checks must leave nothing behind: not even the output folder, nor
// the missing folders above it that `-o` would have created.
// A name the file system refuses (longer than NAME_MAX) is bad input, not an internal error.
TEST_F(BadInputCli, OverlongInputNamesAreBadInput)
{
    const std::string gt = shareDir() + "/rawlog/office_gt.yaml";
    if (!fs::exists(gt)) GTEST_SKIP() << "no share/ rawlog sample";
    const ScopedTempDir dir("bad_cli_long_name");
    const std::string overlong = dir.path + "/" + std::string(300, 'x') + ".rawlog";
    const std::string out = dir.path + "/out";
    expectCleanFailure(run("rawlog " + q(overlong) + " -g " + q(gt) + " -o " + q(out)), 2,
                       "no such file", out);
    expectCleanFailure(run("series " + q(gt) + " " + q(overlong) + " -o " + q(out)), 2,
                       "no such file", out);
}

TEST_F(BadInputCli, RawlogBadInputCreatesNoOutputFolder)
{
    const std::string sample = shareDir() + "/rawlog/office_sim.rawlog.gz";
    const std::string gt = shareDir() + "/rawlog/office_gt.yaml";
    if (!fs::exists(sample) || !fs::exists(gt)) GTEST_SKIP() << "no share/ rawlog sample";
    const ScopedTempDir dir("bad_cli_rawlog_dir");
    const std::string sample_bytes = readText(sample);
    ASSERT_GT(sample_bytes.size(), 1000u);

    struct Case
    {
        std::string name, file, message;
    };
    std::vector<Case> cases;
    const auto add = [&](const std::string& name, const std::string& message)
    {
        cases.push_back({name, dir.path + "/" + name, message});
        return cases.back().file;
    };
    writeText(add("text.rawlog", "not an MRPT rawlog"), "this is not a rawlog\n");
    writeText(add("empty.rawlog", "is empty"), "");
    writeText(add("empty.rawlog.gz", "is empty"), "");
    // The gz sample cut inside its first entry (the gz header and a few compressed bytes), and
    // inside its second entry (the first sensory frame, so before the first scan).
    writeText(add("cut_first.rawlog.gz", "no rawlog entry"), sample_bytes.substr(0, 40));
    writeText(add("cut_second.rawlog.gz", "no 2D laser scan in 1 entries"),
              sample_bytes.substr(0, 300));
    // Well-formed rawlogs without a laser scan: plain, gz, and gz cut in the middle.
    mrpt_topoeval::testing::writeRawlogWithoutScans(add("no_scan.rawlog", "no 2D laser scan"), 30,
                                                    false);
    mrpt_topoeval::testing::writeRawlogWithoutScans(add("no_scan.rawlog.gz", "no 2D laser scan"),
                                                    30, true);
    const std::string cut_no_scan = add("no_scan_cut.rawlog.gz", "no 2D laser scan");
    mrpt_topoeval::testing::writeRawlogWithoutScans(cut_no_scan, 2000, true);
    fs::resize_file(cut_no_scan, fs::file_size(cut_no_scan) / 2);

    for (const Case& c : cases)
    {
        SCOPED_TRACE(c.name);
        const std::string top = dir.path + "/out_" + c.name;
        for (const std::string& extra : {std::string(), std::string(" --snapshots --force")})
        {
            const RunResult r =
                run("rawlog " + q(c.file) + " -g " + q(gt) + " -o " + q(top + "/a/b") + extra);
            expectCleanFailure(r, 2, c.file, top);
            EXPECT_TRUE(contains(r.err, c.message)) << "'" << c.message << "' not in: " << r.err;
            EXPECT_FALSE(fs::exists(top)) << "the run left " << top << " behind" << extra;
        }
    }
}

// A failing run in a folder that holds a user's files changes nothing in it: no file, no
// folder (`snapshots/`) is added, removed or rewritten.
TEST_F(BadInputCli, RawlogAndSeriesFailuresLeaveAnExistingFolderAsItWas)
{
    const std::string gt = shareDir() + "/rawlog/office_gt.yaml";
    const std::string map = shareDir() + "/maps/map_6ccdcaa.yaml";
    if (!fs::exists(gt) || !fs::exists(map)) GTEST_SKIP() << "no share/ samples";
    const ScopedTempDir dir("bad_cli_rawlog_keep");
    const std::string mine = dir.path + "/mine";
    fs::create_directories(mine + "/notes");
    writeText(mine + "/notes/todo.txt", "my notes\n");
    writeText(mine + "/scores.csv", "step,entry\n1,42\n");  // an earlier run's results
    const auto before = treeOf(mine);
    ASSERT_EQ(before.size(), 3u);

    const std::string text = dir.path + "/text.rawlog", no_scan = dir.path + "/no_scan.rawlog";
    writeText(text, "this is not a rawlog\n");
    mrpt_topoeval::testing::writeRawlogWithoutScans(no_scan, 10, false);
    const std::string bad_map = dir.path + "/bad.pgm";
    writeText(bad_map, "P5\n2 2\n255\n");  // no pixels
    for (const std::string& args :
         {"rawlog " + q(text) + " -g " + q(gt) + " -o " + q(mine) + " --force",
          "rawlog " + q(no_scan) + " -g " + q(gt) + " -o " + q(mine) + " --force --snapshots",
          "series " + q(gt) + " " + q(bad_map) + " -o " + q(mine) + " --force",
          "series " + q(gt) + " " + q(map) + " " + q(bad_map) + " -o " + q(mine) + " --force"})
    {
        SCOPED_TRACE(args);
        const RunResult r = run(args);
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_EQ(treeOf(mine), before) << "the failing run changed " << mine;
    }
}

// `series` checks every map before it creates its output folder: a bad map anywhere in the
// list is bad input with nothing written, not a half-filled folder.
TEST_F(BadInputCli, SeriesBadMapCreatesNoOutputFolder)
{
    const std::string gt = shareDir() + "/maps/map_2333d24.yaml";
    const std::string map = shareDir() + "/maps/map_6ccdcaa.yaml";
    if (!fs::exists(gt) || !fs::exists(map)) GTEST_SKIP() << "no share/ maps";
    const ScopedTempDir dir("bad_cli_series");
    const std::string bad_map = dir.path + "/bad.pgm";
    writeText(bad_map, "P5\n2 2\n255\n");
    for (const std::string& maps :
         {q(bad_map), q(map) + " " + q(bad_map), q(map) + " " + q(map) + " " + q(bad_map)})
    {
        SCOPED_TRACE(maps);
        const std::string top = dir.path + "/out";
        const RunResult r = run("series " + q(gt) + " " + maps + " -o " + q(top + "/series"));
        expectCleanFailure(r, 2, bad_map, top);
        EXPECT_FALSE(fs::exists(top)) << "the run left " << top << " behind";
    }
}

// A `scores.csv.part` left by a killed run holds the rows scored before it died: it is an
// output like the others, never replaced without --force.
TEST_F(BadInputCli, RawlogNeverOverwritesTheRowsOfAKilledRun)
{
    const std::string sample = shareDir() + "/rawlog/office_sim.rawlog.gz";
    const std::string gt = shareDir() + "/rawlog/office_gt.yaml";
    if (!fs::exists(sample) || !fs::exists(gt)) GTEST_SKIP() << "no share/ rawlog sample";
    const ScopedTempDir dir("bad_cli_rawlog_part");
    const std::string out = dir.path + "/out";
    fs::create_directory(out);
    const std::string part = out + "/scores.csv.part";
    const std::string rows = "step,entry\n1,199\n2,399\n";
    writeText(part, rows);
    const RunResult r = run("rawlog " + q(sample) + " -g " + q(gt) + " -o " + q(out));
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_TRUE(contains(r.err, part + ": exists; pass --force")) << r.err;
    EXPECT_EQ(readText(part), rows);
    EXPECT_EQ(filesUnder(out), std::vector<std::string>{part});
}

// A run that fails after its first snapshot keeps the part done: scores.csv with every row
// scored, the snapshots written, and report.json saying that an error stopped it and which.
TEST_F(BadInputCli, RawlogErrorAfterTheFirstSnapshotKeepsThePartDone)
{
    const std::string sample = shareDir() + "/rawlog/office_sim.rawlog.gz";
    const std::string gt = shareDir() + "/rawlog/office_gt.yaml";
    if (!fs::exists(sample) || !fs::exists(gt)) GTEST_SKIP() << "no share/ rawlog sample";
    const ScopedTempDir dir("bad_cli_rawlog_error");
    const std::string out = dir.path + "/out";
    // A folder where the second snapshot's map goes: that write fails (exit 3).
    const std::string blocker = out + "/snapshots/step_0002.gridmap.gz";
    fs::create_directories(blocker);
    const RunResult r = run("rawlog " + q(sample) + " -g " + q(gt) + " -o " + q(out) +
                            " --every 20 --snapshots --force");
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_TRUE(contains(r.err, "topoeval: error: " + blocker)) << r.err;
    EXPECT_TRUE(fs::is_directory(blocker));
    EXPECT_TRUE(fs::exists(out + "/snapshots/step_0001.gridmap.gz"));
    EXPECT_TRUE(fs::exists(out + "/snapshots/step_0001_match.png"));
    const std::string csv = readText(out + "/scores.csv");
    EXPECT_EQ(lineCount(csv), 3) << csv;  // the header and both rows scored
    const std::string json = readText(out + "/report.json");
    EXPECT_TRUE(contains(json, "\"stop\": \"error\"")) << json;
    EXPECT_TRUE(contains(json, "step_0002.gridmap.gz")) << json;
    EXPECT_TRUE(contains(json, "\"snapshots\": 2")) << json;
    for (const std::string& f : filesUnder(out))
        EXPECT_EQ(f.find(".part"), std::string::npos) << "temporary file left: " << f;
}

TEST_F(BadInputCli, DegenerateMapsGiveEmptyGraphsWithAWarningAndExit0)
{
    const ScopedTempDir dir("bad_cli");
    struct Case
    {
        const char* name;
        int w, h;
        unsigned char grey;
        const char* warning;
    };
    // 205 is the ROS "unknown" grey: between the thresholds of a trinary map.
    for (const Case& c : {Case{"one_free", 1, 1, 255, "no obstacles"},
                          Case{"one_occupied", 1, 1, 0, "no free space"},
                          Case{"one_unknown", 1, 1, 205, "no obstacles"},
                          Case{"all_unknown", 60, 40, 205, "no obstacles"},
                          Case{"all_occupied", 60, 40, 0, "no free space"}})
    {
        SCOPED_TRACE(c.name);
        const std::string map = writeUniformRosMap(dir.path, c.name, c.w, c.h, c.grey);
        const std::string json = dir.path + "/" + c.name + ".json";
        const std::string png = dir.path + "/" + c.name + ".png";
        const RunResult r = run("graph " + q(map) + " --json " + q(json) + " --image " + q(png));
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_TRUE(contains(r.err, "topoeval: warning: " + map + ": ")) << r.err;
        EXPECT_TRUE(contains(r.err, c.warning)) << r.err;
        EXPECT_TRUE(contains(readText(json), "\"vertices\": [],"));
        EXPECT_EQ(readText(png).substr(0, 4), "\x89PNG");

        // As ground truth and as map of a comparison: nothing matched, coverage 0, exit 0.
        const std::string report = dir.path + "/" + c.name + ".report.json";
        const RunResult cmp = run("compare " + q(map) + " " + q(map) + " --json " + q(report) +
                                  " --image " + q(dir.path + "/" + c.name + ".report.png"));
        EXPECT_EQ(cmp.code, 0) << cmp.err;
        EXPECT_TRUE(contains(readText(report), "\"quality\": 0")) << readText(report);
    }
}

TEST_F(BadInputCli, CompareJsonDoesNotDependOnTheThreadCount)
{
    const std::string maps = shareDir() + "/maps/";
    const std::string gt = maps + "map_2333d24.yaml", map = maps + "map_6ccdcaa.yaml";
    for (const auto& f : {gt, map})
        if (!fs::exists(f)) GTEST_SKIP() << f << " is not there";
    const ScopedTempDir dir("bad_cli_threads");
    const auto compare = [&](const std::string& tag, const std::string& extra)
    {
        const std::string json = dir.path + "/" + tag + ".json";
        const RunResult r = run("compare " + q(gt) + " " + q(map) + " --json " + q(json) + extra);
        EXPECT_EQ(r.code, 0) << tag << ": " << r.err;
        return readText(json);
    };
    // Attributes: one thread against the default (all cores).
    const std::string one = compare("attr1", " --threads 1");
    EXPECT_TRUE(contains(one, "\"timing_ms\": {"));
    EXPECT_EQ(comparable(one), comparable(compare("attr_default", "")));
    // ICP similarity runs vertex pairs in threads: 1 against 2.
    const std::string icp1 = compare("icp1", " --similarity icp --threads 1");
    EXPECT_TRUE(contains(icp1, "\"mode\": \"icp\"")) << icp1.substr(0, 2000);
    EXPECT_EQ(comparable(icp1), comparable(compare("icp2", " --similarity icp --threads 2")));
}
