/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The `topoeval` command end to end: help, exit codes, one-line errors naming the file,
// outputs never overwritten without --force, deterministic JSON, pictures of the construction
// steps, the bad-input corpus.

#include <gtest/gtest.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt_topoeval/Parameters.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "test_paths.h"

namespace fs = std::filesystem;
using mrpt_topoeval::testing::shareDir;
using mrpt_topoeval::testing::testsDir;
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
/** `s` quoted for /bin/sh. */
std::string q(const std::string& s) { return mrpt_topoeval::testing::shellQuote(s); }

/** Runs `topoeval ARGS` (ARGS already quoted), capturing exit code, stdout and stderr. */
RunResult run(const std::string& args) { return mrpt_topoeval::testing::runTopoeval(args); }

/** Everything in `dir`, recursively (hidden temp files included). */
std::vector<std::string> listing(const std::string& dir)
{
    std::vector<std::string> names;
    if (!fs::exists(dir)) return names;
    for (const auto& e : fs::recursive_directory_iterator(dir)) names.push_back(e.path().string());
    return names;
}

class Cli : public ::testing::Test
{
protected:
    void SetUp() override
    {
        if (topoevalBin().empty() || !fs::exists(topoevalBin()))
            GTEST_SKIP() << "the topoeval command is not built";
    }
};

void expectOneLineError(const RunResult& r, int code, const std::string& must_contain)
{
    EXPECT_EQ(r.code, code) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("topoeval: error: ", 0), 0u) << r.err;
    EXPECT_TRUE(contains(r.err, must_contain)) << "'" << must_contain << "' not in: " << r.err;
}
}  // namespace

TEST_F(Cli, TopLevelHelpListsTheVerbs)
{
    for (const char* flag : {"--help", "-h", "help"})
    {
        const RunResult r = run(flag);
        EXPECT_EQ(r.code, 0) << flag;
        EXPECT_TRUE(contains(r.out, "\n  graph ")) << r.out;
        EXPECT_TRUE(contains(r.out, "\n  config ")) << r.out;
        EXPECT_TRUE(r.err.empty()) << r.err;
    }
    const RunResult v = run("--version");
    EXPECT_EQ(v.code, 0);
    EXPECT_EQ(v.out.rfind("topoeval ", 0), 0u) << v.out;
    // No verb: the list on stderr and a usage exit code.
    const RunResult none = run("");
    EXPECT_EQ(none.code, 2);
    EXPECT_TRUE(contains(none.err, "graph"));
}

TEST_F(Cli, HelpOnEveryVerb)
{
    for (const std::string verb : {"graph", "config"})
    {
        for (const std::string& args : {verb + " --help", verb + " -h", "help " + verb})
        {
            const RunResult r = run(args);
            EXPECT_EQ(r.code, 0) << args << ": " << r.err;
            EXPECT_TRUE(contains(r.out, "topoeval " + verb)) << r.out;
            EXPECT_TRUE(contains(r.out, "--help")) << r.out;
            EXPECT_TRUE(r.err.empty()) << r.err;
        }
    }
}

TEST_F(Cli, UsageErrorsExit2WithOneLine)
{
    expectOneLineError(run("frobnicate"), 2, "unknown verb 'frobnicate'");
    expectOneLineError(run("--frobnicate"), 2, "unknown option '--frobnicate'");
    expectOneLineError(run("graph"), 2, "missing the MAP argument");
    expectOneLineError(run("graph map.yaml --frobnicate"), 2, "--frobnicate");
    expectOneLineError(run("graph map.yaml --resolution abc"), 2, "resolution");
    expectOneLineError(run("graph map.yaml --image out.jpg"), 2, "out.jpg");
    expectOneLineError(run("graph map.yaml --image-scale 9"), 2, "--image-scale 9");
    expectOneLineError(run("graph map.yaml --steps ''"), 2, "--steps needs a folder");
    expectOneLineError(run("graph map.yaml --steps out --image out/05_joined.png"), 2, "same file");
    expectOneLineError(run("config --write a.ini --check b.ini"), 2, "cannot be combined");
}

TEST_F(Cli, MissingMapFileNamesTheFile)
{
    const ScopedTempDir dir_tmp("cli");
    const std::string& dir = dir_tmp.path;
    const std::string map = dir + "/no_such_map.yaml";
    const RunResult r = run("graph " + q(map) + " --json " + q(dir + "/out.json"));
    expectOneLineError(r, 2, map);
    EXPECT_TRUE(listing(dir).empty());
}

TEST_F(Cli, ConfigPrintsWritesAndNeverOverwritesWithoutForce)
{
    const std::string text = mrpt_topoeval::Parameters::defaultIniText();
    const RunResult printed = run("config");
    EXPECT_EQ(printed.code, 0);
    EXPECT_EQ(printed.out, text);

    const ScopedTempDir dir_tmp("cli");
    const std::string& dir = dir_tmp.path;
    const std::string ini = dir + "/my.ini";
    EXPECT_EQ(run("config --write " + q(ini)).code, 0);
    EXPECT_EQ(readText(ini), text);

    writeText(ini, "[GraphBuilder]\nmin_clearance_m = 0.4\n");  // the user's edits
    expectOneLineError(run("config --write " + q(ini)), 3, ini + ": exists; pass --force");
    EXPECT_EQ(readText(ini), "[GraphBuilder]\nmin_clearance_m = 0.4\n");

    const RunResult check = run("config --check " + q(ini));
    EXPECT_EQ(check.code, 0) << check.err;
    EXPECT_TRUE(contains(check.out, "min_clearance_m")) << check.out;
    EXPECT_TRUE(contains(check.out, "0.400000")) << check.out;

    EXPECT_EQ(run("config --write " + q(ini) + " --force").code, 0);
    EXPECT_EQ(readText(ini), text);
    // Only the one file: no temporary files left next to it.
    EXPECT_EQ(listing(dir).size(), 1u);
}

TEST_F(Cli, BadConfigFileIsBadInput)
{
    const ScopedTempDir dir_tmp("cli");
    const std::string& dir = dir_tmp.path;
    const std::string ini = dir + "/typo.ini";
    writeText(ini, "[GraphBuilder]\nmin_clearence_m = 0.3\n");
    expectOneLineError(run("config --check " + q(ini)), 2,
                       ini + ": [GraphBuilder] unknown key 'min_clearence_m'");
    const std::string map = writeUniformRosMap(dir, "free", 40, 30, 255);
    expectOneLineError(run("graph " + q(map) + " --config " + q(ini)), 2, ini);
    expectOneLineError(run("graph " + q(map) + " --config " + q(dir + "/none.ini")), 2,
                       dir + "/none.ini: no such file");
    expectOneLineError(run("graph " + q(map) + " --resolution -1"), 2, "resolution");
}

TEST_F(Cli, MapsWithoutObstaclesOrFreeSpaceGiveAnEmptyGraphAndAWarning)
{
    const ScopedTempDir dir_tmp("cli");
    const std::string& dir = dir_tmp.path;
    for (const auto& [name, grey] : {std::pair<const char*, unsigned char>{"all_free", 255},
                                     std::pair<const char*, unsigned char>{"all_occupied", 0}})
    {
        const std::string map = writeUniformRosMap(dir, name, 40, 30, grey);
        const std::string json = dir + "/" + name + ".json";
        const std::string png = dir + "/" + name + ".png";
        const std::string steps = dir + "/" + name + "_steps";
        const RunResult r = run("graph " + q(map) + " --json " + q(json) + " --image " + q(png) +
                                " --steps " + q(steps));
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_TRUE(contains(r.err, "topoeval: warning: ")) << name << ": " << r.err;
        EXPECT_FALSE(contains(r.err, "error")) << r.err;
        const std::string text = readText(json);
        EXPECT_TRUE(contains(text, "\"vertices\": [],")) << text;
        EXPECT_TRUE(contains(text, "\"edges\": [],")) << text;
        EXPECT_TRUE(fs::exists(png));
        // The builder stops before its first step; every step's (empty) graph is still drawn.
        EXPECT_EQ(listing(steps).size(), 5u);
        EXPECT_TRUE(fs::exists(steps + "/05_joined.png"));
        EXPECT_TRUE(contains(r.out, "vertices   0")) << r.out;
    }
}

TEST_F(Cli, OutputsAreNeverInputs)
{
    const ScopedTempDir dir_tmp("cli");
    const std::string& dir = dir_tmp.path;
    const std::string map = writeUniformRosMap(dir, "free", 40, 30, 255);
    const std::string before = readText(map);
    expectOneLineError(run("graph " + q(map) + " --json " + q(map) + " --force"), 2,
                       "is an input of this run");
    EXPECT_EQ(readText(map), before);
    expectOneLineError(
        run("graph " + q(map) + " --json " + q(dir + "/x.png") + " --image " + q(dir + "/x.png")),
        2, "same file");
}

TEST_F(Cli, HouseMapJsonAndPngAreDeterministic)
{
    const std::string map = shareDir() + "/maps/house_gt_trinary_res0.05.yaml";
    if (!fs::exists(map)) GTEST_SKIP() << map << " is not there";
    const ScopedTempDir dir_tmp("cli");
    const std::string& dir = dir_tmp.path;
    const RunResult a =
        run("graph " + q(map) + " --json " + q(dir + "/a.json") + " --image " + q(dir + "/a.png"));
    ASSERT_EQ(a.code, 0) << a.err;
    const RunResult b =
        run("graph " + q(map) + " --json " + q(dir + "/b.json") + " --image " + q(dir + "/b.png"));
    ASSERT_EQ(b.code, 0) << b.err;

    const std::string ja = readText(dir + "/a.json"), jb = readText(dir + "/b.json");
    EXPECT_TRUE(contains(ja, "\"timing_ms\": {")) << ja.substr(0, 200);
    EXPECT_EQ(withoutTiming(ja), withoutTiming(jb));
    EXPECT_TRUE(contains(ja, "\"file\": \"" + map + "\""));
    EXPECT_FALSE(contains(ja, "\"vertices\": [],")) << "the house map has a graph";
    EXPECT_EQ(readText(dir + "/a.png").substr(0, 4), "\x89PNG");
    EXPECT_EQ(readText(dir + "/a.png"), readText(dir + "/b.png"));

    for (const char* key : {"map  ", "size ", "vertices ", "edges ", "degrees ", "time [ms] "})
        EXPECT_TRUE(contains(a.out, key)) << key << " missing in the summary:\n" << a.out;

    // A second run onto existing outputs is refused unless --force, and changes nothing.
    const RunResult again = run("graph " + q(map) + " --json " + q(dir + "/a.json"));
    expectOneLineError(again, 3, dir + "/a.json: exists; pass --force");
    EXPECT_EQ(readText(dir + "/a.json"), ja);
    EXPECT_EQ(run("graph " + q(map) + " --json " + q(dir + "/a.json") + " --force").code, 0);
    EXPECT_EQ(withoutTiming(readText(dir + "/a.json")), withoutTiming(ja));
    EXPECT_EQ(listing(dir).size(), 4u);  // a.json a.png b.json b.png, no temporary files
}

TEST_F(Cli, GraphStepsDrawsEachConstructionStepAndNeverOverwrites)
{
    const std::string map = shareDir() + "/maps/house_gt_trinary_res0.05.yaml";
    if (!fs::exists(map)) GTEST_SKIP() << map << " is not there";
    const ScopedTempDir dir_tmp("cli");
    const std::string steps = dir_tmp.path + "/steps";  // created by the run
    const std::string final_png = dir_tmp.path + "/final.png";
    const std::vector<std::string> names = {"01_voronoi.png", "02_pruned.png", "03_alpha_cut.png",
                                            "04_largest_component.png", "05_joined.png"};

    const RunResult r =
        run("graph " + q(map) + " --steps " + q(steps) + " --image " + q(final_png));
    ASSERT_EQ(r.code, 0) << r.err;
    std::vector<std::string> before;
    for (const auto& name : names)
    {
        const std::string file = steps + "/" + name;
        before.push_back(readText(file));
        EXPECT_EQ(before.back().substr(0, 4), "\x89PNG") << file;
        EXPECT_TRUE(contains(r.out, "wrote      " + file)) << r.out;
    }
    EXPECT_EQ(listing(steps).size(), names.size());  // the five pictures, nothing else
    // The last step is the final graph: the same picture as --image.
    EXPECT_EQ(before.back(), readText(final_png));
    // Pruning removes branches: the Voronoi step's picture differs from the pruned one.
    EXPECT_NE(before[0], before[1]);

    // Again without --force: refused before any work, every picture left as it was.
    const RunResult again = run("graph " + q(map) + " --steps " + q(steps));
    expectOneLineError(again, 3, steps + "/01_voronoi.png: exists; pass --force");
    for (std::size_t i = 0; i < names.size(); ++i)
        EXPECT_EQ(readText(steps + "/" + names[i]), before[i]) << names[i];
    EXPECT_EQ(listing(steps).size(), names.size());  // no temporary files left

    const RunResult forced = run("graph " + q(map) + " --steps " + q(steps) + " --force");
    EXPECT_EQ(forced.code, 0) << forced.err;
    for (std::size_t i = 0; i < names.size(); ++i)
        EXPECT_EQ(readText(steps + "/" + names[i]), before[i]) << names[i];  // deterministic
    EXPECT_EQ(listing(steps).size(), names.size());
}

TEST_F(Cli, EveryBadInputIsRejectedCleanly)
{
    const fs::path corpus = fs::path(testsDir()) / "data" / "bad_inputs";
    if (!fs::is_directory(corpus)) GTEST_SKIP() << corpus << " is not there";
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(corpus))
    {
        // Files the bad maps refer to live in sub-folders; a README would document the corpus.
        const std::string name = e.path().filename().string();
        if (e.is_regular_file() && name.rfind("README", 0) != 0) files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    if (files.empty()) GTEST_SKIP() << corpus << " is empty";

    for (const fs::path& f : files)
    {
        SCOPED_TRACE(f.string());
        const ScopedTempDir out_dir_tmp("cli_bad");
        const std::string& out_dir = out_dir_tmp.path;
        const RunResult r = run("graph " + q(f.string()) + " --json " + q(out_dir + "/g.json") +
                                " --image " + q(out_dir + "/g.png"));
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_EQ(r.err.rfind("topoeval: error: ", 0), 0u) << r.err;
        EXPECT_TRUE(contains(r.err, f.filename().string())) << r.err;
        EXPECT_TRUE(listing(out_dir).empty()) << "output written for a bad input";
    }
}

// ---------------------------------------------------------------- topoeval match

namespace
{
/** The integer after the first occurrence of `key` (e.g. "\"missing\": ") at or after `from`,
 * or -1. */
long numberAfter(const std::string& text, const std::string& key, std::size_t from = 0)
{
    const auto at = text.find(key, from);
    if (at == std::string::npos) return -1;
    return std::strtol(text.c_str() + at + key.size(), nullptr, 10);
}

/** The vertex ids of `topoeval graph --json` output (the edges' ids are not vertex ids). */
std::vector<long> graphVertexIds(const std::string& graph_json)
{
    std::vector<long> ids;
    const auto begin = graph_json.find("\n  \"vertices\": [");
    const auto end = graph_json.find("\n  \"edges\": [");
    if (begin == std::string::npos || end == std::string::npos) return ids;
    for (auto at = graph_json.find("\"id\": ", begin); at < end;
         at = graph_json.find("\"id\": ", at + 1))
        ids.push_back(numberAfter(graph_json, "\"id\": ", at));
    return ids;
}

/** (ground truth, map) ids of the pairs of `topoeval match --json` output. */
std::vector<std::pair<long, long>> matchPairs(const std::string& match_json)
{
    std::vector<std::pair<long, long>> pairs;
    const std::string key = "{\"ground_truth\": ";
    for (auto at = match_json.find(key); at != std::string::npos; at = match_json.find(key, at + 1))
        pairs.emplace_back(numberAfter(match_json, key, at),
                           numberAfter(match_json, "\"map\": ", at));
    return pairs;
}

bool hasId(const std::vector<long>& ids, long id)
{
    return std::find(ids.begin(), ids.end(), id) != ids.end();
}
}  // namespace

TEST_F(Cli, MatchHelpAndUsageErrors)
{
    for (const std::string args : {"match --help", "match -h", "help match"})
    {
        const RunResult r = run(args);
        EXPECT_EQ(r.code, 0) << args << ": " << r.err;
        EXPECT_TRUE(contains(r.out, "topoeval match")) << r.out;
        EXPECT_TRUE(contains(r.out, "--similarity")) << r.out;
        EXPECT_TRUE(r.err.empty()) << r.err;
    }
    EXPECT_TRUE(contains(run("--help").out, "\n  match ")) << "match is not in the verb list";

    expectOneLineError(run("match"), 2, "missing the GT and MAP arguments");
    expectOneLineError(run("match gt.yaml"), 2, "missing the MAP argument");
    expectOneLineError(run("match a.yaml b.yaml c.yaml"), 2, "unexpected 'c.yaml'");
    expectOneLineError(run("match a.yaml b.yaml --similarity fast"), 2, "--similarity 'fast'");
    expectOneLineError(run("match a.yaml b.yaml --threads -2"), 2, "--threads -2");
    expectOneLineError(run("match a.yaml b.yaml --image out.jpg"), 2, "out.jpg");
}

TEST_F(Cli, MatchIdsAreTheGraphVerbsIdsAndOutputsAreDeterministic)
{
    const std::string maps = shareDir() + "/maps/";
    const std::string gt = maps + "house_gt_trinary_res0.05.yaml";
    const std::string robot = maps + "map_6ccdcaa.yaml";
    const std::string other = maps + "map_2333d24.yaml";
    for (const auto& f : {gt, robot, other})
        if (!fs::exists(f)) GTEST_SKIP() << f << " is not there";
    const ScopedTempDir dir_tmp("cli_match");
    const std::string& dir = dir_tmp.path;

    // The graphs as `topoeval graph --json` prints them.
    std::vector<std::vector<long>> ids;
    for (const auto& [name, map] :
         {std::pair<std::string, std::string>{"gt", gt}, {"robot", robot}, {"other", other}})
    {
        const std::string json = dir + "/graph_" + name + ".json";
        const RunResult r = run("graph " + q(map) + " --json " + q(json));
        ASSERT_EQ(r.code, 0) << r.err;
        ids.push_back(graphVertexIds(readText(json)));
        EXPECT_FALSE(ids.back().empty()) << map;
    }

    // The pair (house ground truth against a robot map), and two robot maps of one
    // environment, which share structure: their match is not empty.
    struct Case
    {
        std::string gt, map;
        std::size_t gt_ids, map_ids;
        bool expect_pairs;
    };
    for (const Case& c : {Case{gt, robot, 0, 1, false}, Case{other, robot, 2, 1, true}})
    {
        SCOPED_TRACE(c.gt + " vs " + c.map);
        const std::string json = dir + "/match.json", png = dir + "/match.png";
        const std::string args = "match " + q(c.gt) + " " + q(c.map) + " --json " + q(json) +
                                 " --image " + q(png) + " --force";
        const RunResult a = run(args);
        ASSERT_EQ(a.code, 0) << a.err;
        const std::string ja = readText(json), pa = readText(png);
        const RunResult b = run(args);
        ASSERT_EQ(b.code, 0) << b.err;
        EXPECT_EQ(withoutTiming(readText(json)), withoutTiming(ja));
        EXPECT_EQ(readText(png), pa);
        EXPECT_EQ(pa.substr(0, 4), "\x89PNG");

        EXPECT_TRUE(contains(ja, "\"ground_truth\": {\n    \"file\": \"" + c.gt + "\"")) << ja;
        EXPECT_TRUE(contains(ja, "\"map\": {\n    \"file\": \"" + c.map + "\"")) << ja;
        EXPECT_TRUE(contains(ja, "\"timing_ms\": {")) << ja;
        const auto pairs = matchPairs(ja);
        if (c.expect_pairs)
        {
            EXPECT_FALSE(pairs.empty()) << ja;
        }
        for (const auto& [g, m] : pairs)
        {
            EXPECT_TRUE(hasId(ids[c.gt_ids], g)) << "ground-truth id " << g;
            EXPECT_TRUE(hasId(ids[c.map_ids], m)) << "map id " << m;
        }

        // The counts add up to the pairs and appear in the summary as in the JSON.
        const auto matches = ja.find("\"matches\": {");
        const long iso = numberAfter(ja, "\"isomorphism\": ", matches);
        const long grow = numberAfter(ja, "\"neighbour_growing\": ", matches);
        const long missing = numberAfter(ja, "\"missing\": ", matches);
        EXPECT_EQ(static_cast<std::size_t>(iso + grow), pairs.size());
        EXPECT_TRUE(contains(a.out, "isomorphism " + std::to_string(iso) + ", neighbour growing " +
                                        std::to_string(grow) + ", missing " +
                                        std::to_string(missing)))
            << a.out;
        for (const char* key : {"ground truth  ", "map           ", "matches       ",
                                "isomorphisms  ", "time [ms]     "})
            EXPECT_TRUE(contains(a.out, key)) << key << " missing in the summary:\n" << a.out;
    }
}

TEST_F(Cli, MatchOfAMapWithItselfIsComplete)
{
    const std::string map = shareDir() + "/maps/map_6ccdcaa.yaml";
    if (!fs::exists(map)) GTEST_SKIP() << map << " is not there";
    const ScopedTempDir dir_tmp("cli_match");
    const std::string json = dir_tmp.path + "/self.json";
    const RunResult r = run("match " + q(map) + " " + q(map) + " --json " + q(json));
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string text = readText(json);
    EXPECT_TRUE(contains(text, "\"missing\": 0,")) << text;
    const auto pairs = matchPairs(text);
    EXPECT_FALSE(pairs.empty());
    for (const auto& [g, m] : pairs) EXPECT_EQ(g, m) << "identical graphs match identically";
}

TEST_F(Cli, MatchWithAnEmptyGraphIsAnEmptyMatchAndAWarning)
{
    const std::string house = shareDir() + "/maps/house_gt_trinary_res0.05.yaml";
    if (!fs::exists(house)) GTEST_SKIP() << house << " is not there";
    const ScopedTempDir dir_tmp("cli_match");
    const std::string& dir = dir_tmp.path;
    const std::string empty = writeUniformRosMap(dir, "all_free", 40, 30, 255);
    for (const auto& [gt, map] :
         {std::pair<std::string, std::string>{empty, house}, {house, empty}, {empty, empty}})
    {
        SCOPED_TRACE(gt + " vs " + map);
        const std::string json = dir + "/m.json", png = dir + "/m.png";
        const RunResult r = run("match " + q(gt) + " " + q(map) + " --json " + q(json) +
                                " --image " + q(png) + " --force");
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_TRUE(contains(r.err, "topoeval: warning: " + empty)) << r.err;
        EXPECT_FALSE(contains(r.err, "error")) << r.err;
        EXPECT_TRUE(contains(readText(json), "\"pairs\": [],")) << readText(json);
        EXPECT_EQ(readText(png).substr(0, 4), "\x89PNG");
    }
}

TEST_F(Cli, MatchBadInputAndExistingOutputs)
{
    const std::string map = shareDir() + "/maps/map_6ccdcaa.yaml";
    if (!fs::exists(map)) GTEST_SKIP() << map << " is not there";
    const ScopedTempDir dir_tmp("cli_match");
    const std::string& dir = dir_tmp.path;
    const std::string json = dir + "/m.json", png = dir + "/m.png";
    const std::string outputs = " --json " + q(json) + " --image " + q(png);

    // A missing map, as ground truth or as map: exit 2 naming it, nothing written.
    const std::string none = dir + "/no_such_map.yaml";
    expectOneLineError(run("match " + q(none) + " " + q(map) + outputs), 2, none);
    expectOneLineError(run("match " + q(map) + " " + q(none) + outputs), 2, none);
    EXPECT_TRUE(listing(dir).empty());

    // Existing outputs are refused before any work, and left as they were.
    writeText(json, "mine");
    writeText(png, "mine too");
    expectOneLineError(run("match " + q(map) + " " + q(map) + outputs), 3,
                       json + ": exists; pass --force");
    expectOneLineError(run("match " + q(map) + " " + q(map) + " --image " + q(png)), 3,
                       png + ": exists; pass --force");
    EXPECT_EQ(readText(json), "mine");
    EXPECT_EQ(readText(png), "mine too");
    expectOneLineError(run("match " + q(map) + " " + q(map) + " --json " + q(map) + " --force"), 2,
                       "is an input of this run");

    const RunResult forced = run("match " + q(map) + " " + q(map) + outputs + " --force");
    EXPECT_EQ(forced.code, 0) << forced.err;
    EXPECT_TRUE(contains(readText(json), "\"matches\": {"));
    EXPECT_EQ(listing(dir).size(), 2u);  // no temporary files left
}

// ---------------------------------------------------------------- topoeval compare and rank

namespace
{
/** A ROS map (PGM + YAML) of `w` x `h` pixels: free inside a one-pixel wall, plus the
 * occupied rectangles `blocks` ({x, y, width, height} in pixels). */
std::string writeBoxRosMap(const std::string& dir, const std::string& name, int w, int h,
                           const std::vector<std::vector<int>>& blocks)
{
    std::vector<unsigned char> px(static_cast<std::size_t>(w) * h, 255);
    const auto set = [&](int x, int y) { px[static_cast<std::size_t>(y) * w + x] = 0; };
    for (int x = 0; x < w; ++x)
    {
        set(x, 0);
        set(x, h - 1);
    }
    for (int y = 0; y < h; ++y)
    {
        set(0, y);
        set(w - 1, y);
    }
    for (const auto& b : blocks)
        for (int y = b[1]; y < b[1] + b[3]; ++y)
            for (int x = b[0]; x < b[0] + b[2]; ++x) set(x, y);
    std::string pgm = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
    pgm.append(px.begin(), px.end());
    writeText(dir + "/" + name + ".pgm", pgm);
    const std::string yaml = dir + "/" + name + ".yaml";
    writeText(yaml, "image: " + name +
                        ".pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                        "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
    return yaml;
}

std::vector<std::string> splitOn(const std::string& s, char sep)
{
    std::vector<std::string> out;
    std::string cur;
    for (const char ch : s)
        if (ch == sep)
        {
            out.push_back(cur);
            cur.clear();
        }
        else
            cur.push_back(ch);
    if (!cur.empty()) out.push_back(cur);
    return out;
}

/** True if `ranks` (e.g. {"2", "1", "3"} or {"1-2", "1-2", "3"}) ranks them all: each
 * distinct "a-b" ("a" meaning "a-a") appears exactly b - a + 1 times, and together the
 * ranges cover the positions 1..n once each. */
bool isRankingWithTies(const std::vector<std::string>& ranks)
{
    const int n = static_cast<int>(ranks.size());
    std::vector<int> covered(ranks.size() + 1, 0);
    std::vector<std::string> distinct = ranks;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    for (const auto& r : distinct)
    {
        const auto dash = r.find('-');
        const int a = std::atoi(r.c_str());
        const int b = dash == std::string::npos ? a : std::atoi(r.c_str() + dash + 1);
        if (a < 1 || b < a || b > n) return false;
        if (std::count(ranks.begin(), ranks.end(), r) != b - a + 1) return false;
        for (int k = a; k <= b; ++k) ++covered[static_cast<std::size_t>(k)];
    }
    return std::all_of(covered.begin() + 1, covered.end(), [](int c) { return c == 1; });
}

const char* const kRankCsvHeader =
    "file,rank,quality,coverage,relative_accuracy_rmse_m,relative_accuracy_score,"
    "consistency_short,consistency_medium,consistency_long,brokenness,rank_coverage,"
    "rank_relative_accuracy,rank_consistency,rank_brokenness,map_scale,explained_walls";
}  // namespace

TEST_F(Cli, CompareAndRankHelpAndUsageErrors)
{
    for (const std::string verb : {"compare", "rank"})
        for (const std::string& args : {verb + " --help", verb + " -h", "help " + verb})
        {
            const RunResult r = run(args);
            EXPECT_EQ(r.code, 0) << args << ": " << r.err;
            EXPECT_TRUE(contains(r.out, "topoeval " + verb)) << r.out;
            EXPECT_TRUE(contains(r.out, "--similarity")) << r.out;
            EXPECT_TRUE(contains(r.out, "--threads")) << r.out;
            EXPECT_TRUE(r.err.empty()) << r.err;
        }
    EXPECT_TRUE(contains(run("compare --help").out, "--verbose"));
    EXPECT_TRUE(contains(run("rank --help").out, "--csv"));
    const RunResult list = run("--help");
    EXPECT_TRUE(contains(list.out, "\n  compare ")) << list.out;
    EXPECT_TRUE(contains(list.out, "\n  rank ")) << list.out;

    expectOneLineError(run("compare"), 2, "missing the GT and MAP arguments");
    expectOneLineError(run("compare gt.yaml"), 2, "missing the MAP argument");
    expectOneLineError(run("compare a.yaml b.yaml c.yaml"), 2, "unexpected 'c.yaml'");
    expectOneLineError(run("compare a.yaml b.yaml --similarity fast"), 2, "--similarity 'fast'");
    expectOneLineError(run("compare a.yaml b.yaml --threads -2"), 2, "--threads -2");
    expectOneLineError(run("compare a.yaml b.yaml --image out.jpg"), 2, "out.jpg");
    expectOneLineError(run("compare a.yaml b.yaml --json o.png --image o.png"), 2, "same file");
    expectOneLineError(run("compare a.yaml b.yaml --bogus"), 2, "--bogus");
    expectOneLineError(run("rank"), 2, "missing the GT and MAP arguments");
    expectOneLineError(run("rank gt.yaml"), 2, "missing the MAP arguments");
    expectOneLineError(run("rank a.yaml b.yaml --threads 300"), 2, "--threads 300");
    expectOneLineError(run("rank a.yaml b.yaml --similarity fast"), 2, "--similarity 'fast'");
    expectOneLineError(run("rank a.yaml b.yaml --csv ''"), 2, "--csv needs a file name");
}

TEST_F(Cli, CompareWritesJsonAndPngDeterministicallyWithMatchsMatches)
{
    const std::string maps = shareDir() + "/maps/";
    const std::string gt = maps + "map_2333d24.yaml", map = maps + "map_6ccdcaa.yaml";
    for (const auto& f : {gt, map})
        if (!fs::exists(f)) GTEST_SKIP() << f << " is not there";
    const ScopedTempDir dir_tmp("cli_compare");
    const std::string& dir = dir_tmp.path;

    const auto compare = [&](const std::string& tag, const std::string& extra)
    {
        return run("compare " + q(gt) + " " + q(map) + " --json " + q(dir + "/" + tag + ".json") +
                   " --image " + q(dir + "/" + tag + ".png") + extra);
    };
    const RunResult a = compare("a", "");
    ASSERT_EQ(a.code, 0) << a.err;
    const RunResult b = compare("b", " --verbose");
    ASSERT_EQ(b.code, 0) << b.err;
    const std::string ja = readText(dir + "/a.json"), jb = readText(dir + "/b.json");

    // Every member the issue lists, at the top level and inside.
    for (const char* key :
         {"ground_truth", "map", "matches", "coverage", "global_accuracy", "relative_accuracy",
          "local_consistency", "brokenness", "quality", "messages", "parameters", "timing_ms"})
        EXPECT_TRUE(contains(ja, "\n  \"" + std::string(key) + "\": ")) << key << " missing";
    for (const char* key : {"file",
                            "vertices",
                            "half_edges",
                            "edge_length_m",
                            "rmse_m",
                            "score",
                            "transform",
                            "x",
                            "y",
                            "yaw_deg",
                            "class",
                            "pairs",
                            "mean_error_m",
                            "min_graph_distance_m",
                            "max_graph_distance_m",
                            "degree",
                            "groups",
                            "isomorphism",
                            "neighbour_growing",
                            "missing",
                            "VertexSimilarity",
                            "QualityEvaluator"})
        EXPECT_TRUE(contains(ja, "\"" + std::string(key) + "\": ")) << key << " missing";
    EXPECT_TRUE(contains(ja, "\"ground_truth\": {\n    \"file\": \"" + gt + "\"")) << ja;
    EXPECT_TRUE(contains(ja, "\"map\": {\n    \"file\": \"" + map + "\"")) << ja;
    for (const char* bad : {"nan", "NaN", "inf", "Inf"})
        EXPECT_FALSE(contains(ja, bad)) << bad << " in the JSON";
    // The timing is last, and the only difference between two runs (--verbose changes only
    // what is printed).
    EXPECT_EQ(ja.rfind("\n  \"timing_ms\": {"), ja.find("\n  \"timing_ms\": {"));
    EXPECT_EQ(ja.substr(ja.size() - 4), "}\n}\n");
    EXPECT_EQ(withoutTiming(ja), withoutTiming(jb));
    const std::string png = readText(dir + "/a.png");
    EXPECT_EQ(png.substr(0, 4), "\x89PNG");
    EXPECT_EQ(png, readText(dir + "/b.png"));

    // "matches" is the object `topoeval match --json` writes for the same pair, byte for byte.
    const RunResult m = run("match " + q(gt) + " " + q(map) + " --json " + q(dir + "/m.json"));
    ASSERT_EQ(m.code, 0) << m.err;
    const std::string matches = topLevelObject(ja, "matches");
    EXPECT_FALSE(matches.empty());
    EXPECT_EQ(matches, topLevelObject(readText(dir + "/m.json"), "matches"));

    // The report names both files; --verbose adds the time per step.
    for (const std::string& part :
         {"ground truth  " + gt + " (ros_yaml)", "map           " + map + " (ros_yaml)",
          std::string("similarity    attributes"), "wrote       " + dir + "/a.json",
          "wrote       " + dir + "/a.png"})
        EXPECT_TRUE(contains(a.out, part)) << part << " missing in:\n" << a.out;
    EXPECT_FALSE(contains(a.out, "time [ms]")) << a.out;
    EXPECT_TRUE(contains(b.out, "time [ms]")) << b.out;
    EXPECT_GT(b.out.size(), a.out.size());
    EXPECT_EQ(listing(dir).size(), 5u);  // a.json a.png b.json b.png m.json, no temporary files
}

TEST_F(Cli, CompareOfAMapWithItselfCoversEverythingUnbroken)
{
    const std::string map = shareDir() + "/maps/map_6ccdcaa.yaml";
    if (!fs::exists(map)) GTEST_SKIP() << map << " is not there";
    const ScopedTempDir dir_tmp("cli_compare");
    const std::string json = dir_tmp.path + "/self.json";
    const RunResult r = run("compare " + q(map) + " " + q(map) + " --json " + q(json) +
                            " --image " + q(dir_tmp.path + "/self.png"));
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string text = readText(json);
    EXPECT_TRUE(contains(text, "\n  \"coverage\": 1,\n")) << text;
    const std::string brokenness = topLevelObject(text, "brokenness");
    EXPECT_TRUE(contains(brokenness, "\"degree\": 0,")) << brokenness;
    // One group of every vertex, aligned by the identity.
    EXPECT_TRUE(contains(brokenness, "\"ground_truth_ids\": [")) << brokenness;
    EXPECT_TRUE(contains(brokenness, "\"squared_error_m2\": 0,")) << brokenness;
    EXPECT_TRUE(contains(brokenness, "\"yaw_deg\": 0,")) << brokenness;
    EXPECT_TRUE(contains(topLevelObject(text, "matches"), "\"missing\": 0,"));
}

TEST_F(Cli, CompareOfMapsThatMatchNothingIsCoverageZeroAndExit0)
{
    const ScopedTempDir dir_tmp("cli_compare");
    const std::string& dir = dir_tmp.path;
    // Two small unrelated rooms, each with too few vertices for an isomorphism (at least 8,
    // pinned here), and a room without obstacles, whose graph is empty.
    const std::string pillar = writeBoxRosMap(dir, "pillar", 80, 60, {{35, 25, 10, 10}});
    const std::string two = writeBoxRosMap(dir, "two", 100, 50, {{20, 20, 8, 8}, {70, 15, 6, 20}});
    const std::string empty = writeUniformRosMap(dir, "all_free", 40, 30, 255);
    const std::string ini = dir + "/pin.ini";
    writeText(ini, "[GraphMatcher]\nmin_isomorphism_vertices = 8\n");
    for (const auto& [gt, map] :
         {std::pair<std::string, std::string>{pillar, two}, {pillar, empty}, {empty, two}})
    {
        SCOPED_TRACE(gt + " vs " + map);
        const std::string json = dir + "/c.json", png = dir + "/c.png";
        const RunResult r = run("compare " + q(gt) + " " + q(map) + " -c " + q(ini) + " --json " +
                                q(json) + " --image " + q(png) + " --force");
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_TRUE(contains(r.err, "topoeval: warning: ")) << r.err;
        EXPECT_FALSE(contains(r.err, "error")) << r.err;
        const std::string text = readText(json);
        EXPECT_TRUE(contains(text, "\n  \"coverage\": 0,\n")) << text;
        EXPECT_TRUE(contains(text, "\n  \"quality\": 0,\n")) << text;
        EXPECT_TRUE(contains(text, "\"pairs\": [],")) << text;
        EXPECT_FALSE(contains(text, "nan")) << text;
        EXPECT_EQ(readText(png).substr(0, 4), "\x89PNG");
    }
}

TEST_F(Cli, CompareBadInputAndExistingOutputs)
{
    const std::string map = shareDir() + "/maps/map_6ccdcaa.yaml";
    if (!fs::exists(map)) GTEST_SKIP() << map << " is not there";
    const ScopedTempDir dir_tmp("cli_compare");
    const std::string& dir = dir_tmp.path;
    const std::string json = dir + "/c.json", png = dir + "/c.png";
    const std::string outputs = " --json " + q(json) + " --image " + q(png);

    const std::string none = dir + "/no_such_map.yaml";
    expectOneLineError(run("compare " + q(none) + " " + q(map) + outputs), 2, none);
    expectOneLineError(run("compare " + q(map) + " " + q(none) + outputs), 2, none);
    const std::string ini = dir + "/typo.ini";
    writeText(ini, "[QualityEvaluator]\nbrokenness_min_vertice = 5\n");
    expectOneLineError(run("compare " + q(map) + " " + q(map) + " -c " + q(ini) + outputs), 2,
                       "brokenness_min_vertice");
    std::filesystem::remove(ini);
    EXPECT_TRUE(listing(dir).empty());

    writeText(json, "mine");
    writeText(png, "mine too");
    expectOneLineError(run("compare " + q(map) + " " + q(map) + outputs), 3,
                       json + ": exists; pass --force");
    expectOneLineError(run("compare " + q(map) + " " + q(map) + " --image " + q(png)), 3,
                       png + ": exists; pass --force");
    EXPECT_EQ(readText(json), "mine");
    EXPECT_EQ(readText(png), "mine too");
    expectOneLineError(run("compare " + q(map) + " " + q(map) + " --json " + q(map) + " --force"),
                       2, "is an input of this run");

    const RunResult forced = run("compare " + q(map) + " " + q(map) + outputs + " --force");
    EXPECT_EQ(forced.code, 0) << forced.err;
    EXPECT_TRUE(contains(readText(json), "\"quality\": "));
    EXPECT_EQ(listing(dir).size(), 2u);  // no temporary files left
}

TEST_F(Cli, RankWritesCsvWithRanksIndependentOfThreads)
{
    const std::string maps = shareDir() + "/maps/";
    const std::string gt = maps + "map_2333d24.yaml";
    const std::vector<std::string> scored = {maps + "map_6ccdcaa.yaml", maps + "map_2333d24.yaml",
                                             maps + "house_gt_trinary_res0.05.yaml"};
    for (const auto& f : scored)
        if (!fs::exists(f)) GTEST_SKIP() << f << " is not there";
    const ScopedTempDir dir_tmp("cli_rank");
    const std::string& dir = dir_tmp.path;
    std::string args = "rank " + q(gt);
    for (const auto& f : scored) args += " " + q(f);

    const RunResult one = run(args + " --threads 1 --csv " + q(dir + "/one.csv"));
    ASSERT_EQ(one.code, 0) << one.err;
    const RunResult three = run(args + " --threads 3 --csv " + q(dir + "/three.csv"));
    ASSERT_EQ(three.code, 0) << three.err;
    const std::string csv = readText(dir + "/one.csv");
    EXPECT_EQ(csv, readText(dir + "/three.csv"));

    const std::vector<std::string> lines = splitOn(csv, '\n');
    ASSERT_EQ(lines.size(), 4u) << csv;
    EXPECT_EQ(lines[0], kRankCsvHeader);
    std::vector<std::vector<std::string>> rows;
    for (std::size_t i = 1; i < lines.size(); ++i)
    {
        std::vector<std::string> f = splitOn(lines[i] + ",", ',');
        f.resize(16);
        EXPECT_EQ(f[0], scored[i - 1]) << "rows in the order given";
        EXPECT_EQ(f[14], "1") << "every map read at its own scale:\n" << csv;
        EXPECT_EQ(f[15].empty(), f[9].empty())
            << "explained walls, empty exactly when nothing matched:\n"
            << csv;
        rows.push_back(f);
    }
    // Each rank column (overall, coverage, relative accuracy, consistency, brokenness) ranks
    // all three maps, ties sharing positions.
    for (const std::size_t col : {1u, 10u, 11u, 12u, 13u})
    {
        std::vector<std::string> ranks;
        for (const auto& r : rows) ranks.push_back(r[col]);
        EXPECT_TRUE(isRankingWithTies(ranks)) << "column " << col << ":\n" << csv;
    }
    // The ground truth scored against itself is the best map.
    EXPECT_EQ(rows[1][1].substr(0, 1), "1") << csv;
    EXPECT_EQ(rows[1][3], "1") << "coverage of the map against itself:\n" << csv;

    // The table lists the maps in the order given, with a header.
    const auto h = one.out.find("\nmap ");
    ASSERT_NE(h, std::string::npos) << one.out;
    const auto p1 = one.out.find("map_6ccdcaa.yaml", h), p2 = one.out.find("map_2333d24.yaml", h),
               p3 = one.out.find("house_gt_trinary_res0.05.yaml", h);
    EXPECT_TRUE(p1 < p2 && p2 < p3 && p3 != std::string::npos) << one.out;
    EXPECT_TRUE(contains(one.out, "wrote         " + dir + "/one.csv")) << one.out;

    // The CSV is an output like any other.
    expectOneLineError(run(args + " --csv " + q(dir + "/one.csv")), 3,
                       dir + "/one.csv: exists; pass --force");
    EXPECT_EQ(readText(dir + "/one.csv"), csv);
    expectOneLineError(run(args + " --csv " + q(scored[0]) + " --force"), 2,
                       "is an input of this run");
}

TEST_F(Cli, RankListsAMapThatFailsAndRanksTheOthers)
{
    const std::string maps = shareDir() + "/maps/";
    const std::string gt = maps + "map_2333d24.yaml", good = maps + "map_6ccdcaa.yaml";
    for (const auto& f : {gt, good})
        if (!fs::exists(f)) GTEST_SKIP() << f << " is not there";
    const ScopedTempDir dir_tmp("cli_rank");
    const std::string& dir = dir_tmp.path;
    const std::string none = dir + "/no_such_map.yaml", csv = dir + "/r.csv";

    const RunResult r =
        run("rank " + q(gt) + " " + q(good) + " " + q(none) + " " + q(gt) + " --csv " + q(csv));
    EXPECT_EQ(r.code, 2) << r.err;
    // One error line, naming the map (warnings about the other maps may come before it).
    std::vector<std::string> errors;
    for (const auto& line : splitOn(r.err, '\n'))
        if (line.rfind("topoeval: error: ", 0) == 0) errors.push_back(line);
    ASSERT_EQ(errors.size(), 1u) << r.err;
    EXPECT_EQ(errors[0].rfind("topoeval: error: " + none, 0), 0u) << r.err;
    EXPECT_TRUE(contains(r.out, "no_such_map.yaml  error: " + none)) << r.out;

    const std::vector<std::string> lines = splitOn(readText(csv), '\n');
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[2], none + ",,,,,,,,,,,,,,,");
    std::vector<std::string> ranks;
    for (const std::size_t i : {1u, 3u}) ranks.push_back(splitOn(lines[i], ',').at(1));
    EXPECT_TRUE(isRankingWithTies(ranks)) << readText(csv);

    // Without a readable ground truth there is nothing to rank: nothing written.
    const std::string csv2 = dir + "/r2.csv";
    expectOneLineError(run("rank " + q(none) + " " + q(good) + " --csv " + q(csv2)), 2, none);
    EXPECT_FALSE(fs::exists(csv2));
}

// ---------------------------------------------------------------- rawlog and series

namespace
{
/** The demo's simulated sample (share/mrpt_topoeval/rawlog/, made by rawlog_test). */
struct RawlogSample
{
    std::string rawlog = shareDir() + "/rawlog/office_sim.rawlog.gz";
    std::string gt = shareDir() + "/rawlog/office_gt.yaml";
    bool present() const { return fs::exists(rawlog) && fs::exists(gt); }
};

const char* const kScoresHeader =
    "step,entry,time_s,scans,vertices,coverage,relative_accuracy,consistency_short,"
    "consistency_medium,consistency_long,brokenness,quality,scoring_ms,explained_walls";
}  // namespace

TEST_F(Cli, RawlogHelpAndUsageErrors)
{
    const RunResult help = run("rawlog --help");
    EXPECT_EQ(help.code, 0) << help.err;
    EXPECT_TRUE(contains(help.out, "--ground-truth")) << help.out;
    EXPECT_TRUE(contains(help.out, "4 stopped early")) << help.out;
    const RunResult ini = run("rawlog --print-slam-config");
    EXPECT_EQ(ini.code, 0);
    EXPECT_TRUE(contains(ini.out, "[MappingApplication]")) << ini.out;
    EXPECT_TRUE(contains(ini.out, "occupancyGrid_count=1")) << ini.out;
    expectOneLineError(run("rawlog"), 2, "missing the RAWLOG argument");
    const RawlogSample s;
    if (!s.present()) GTEST_SKIP() << "the share/ rawlog sample is not there";
    expectOneLineError(run("rawlog " + q(s.rawlog)), 2, "--ground-truth");
}

TEST_F(Cli, RawlogBadInputsExit2)
{
    const RawlogSample s;
    if (!s.present()) GTEST_SKIP() << "the share/ rawlog sample is not there";
    const ScopedTempDir dir_tmp("cli_rawlog_bad");
    const std::string& dir = dir_tmp.path;
    const std::string missing_gt = dir + "/no_gt.yaml";
    expectOneLineError(
        run("rawlog " + q(s.rawlog) + " -g " + q(missing_gt) + " -o " + q(dir + "/o1")), 2,
        missing_gt);
    const std::string empty = dir + "/empty.rawlog", text = dir + "/text.rawlog";
    writeText(empty, "");
    writeText(text, "not a rawlog at all\n");
    expectOneLineError(run("rawlog " + q(empty) + " -g " + q(s.gt) + " -o " + q(dir + "/o2")), 2,
                       empty);
    expectOneLineError(run("rawlog " + q(text) + " -g " + q(s.gt) + " -o " + q(dir + "/o3")), 2,
                       "not an MRPT rawlog");
    // The inputs are checked before the output folder is created: bad input leaves none.
    for (const char* o : {"/o1", "/o2", "/o3"})
        EXPECT_FALSE(fs::exists(dir + o)) << o << " was created by a run that failed";
}

TEST_F(Cli, RawlogEndToEndWritesEveryOutputAndNeverOverwrites)
{
    const RawlogSample s;
    if (!s.present()) GTEST_SKIP() << "the share/ rawlog sample is not there";
    const ScopedTempDir dir_tmp("cli_rawlog");
    const std::string out = dir_tmp.path + "/out";
    const RunResult r = run("rawlog " + q(s.rawlog) + " --ground-truth " + q(s.gt) +
                            " --every 100 --out " + q(out));
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* f : {"scores.csv", "report.json", "scores.png", "final.gridmap.gz",
                          "final.simplemap", "final.png"})
        EXPECT_TRUE(fs::exists(out + "/" + f)) << f;
    const std::vector<std::string> lines = splitOn(readText(out + "/scores.csv"), '\n');
    ASSERT_GE(lines.size(), 4u);
    EXPECT_EQ(lines[0], kScoresHeader);
    // 349 scans, every 100: snapshots at 100, 200, 300 and the end.
    EXPECT_EQ(lines.size(), 5u) << readText(out + "/scores.csv");
    EXPECT_EQ(splitOn(lines.back(), ',').size(), 14u);
    const std::string json = readText(out + "/report.json");
    EXPECT_TRUE(contains(json, "\"stop\": \"end_of_file\"")) << json;
    EXPECT_TRUE(contains(json, "\"final_scores\": {")) << json;
    EXPECT_TRUE(contains(json, "\"slam_ini\": ")) << json;
    // The final map reads back as a map.
    const RunResult g = run("graph " + q(out + "/final.gridmap.gz"));
    EXPECT_EQ(g.code, 0) << g.err;
    // The keyframes read back as MRPT's simplemap (rendered into a grid by every verb).
    mrpt::maps::CSimpleMap keyframes;
    ASSERT_TRUE(keyframes.loadFromFile(out + "/final.simplemap"));
    EXPECT_GE(keyframes.size(), 10u);
    EXPECT_LT(keyframes.size(), 349u);
    const RunResult k = run("graph " + q(out + "/final.simplemap"));
    EXPECT_EQ(k.code, 0) << k.err;

    // Outputs are never replaced without --force.
    const RunResult again = run("rawlog " + q(s.rawlog) + " -g " + q(s.gt) + " -o " + q(out));
    expectOneLineError(again, 3, "--force");
    const RunResult forced =
        run("rawlog " + q(s.rawlog) + " -g " + q(s.gt) + " -o " + q(out) + " --force");
    EXPECT_EQ(forced.code, 0) << forced.err;
}

TEST_F(Cli, RawlogTruncatedStopsWithExit4AndWritesThePartDone)
{
    const RawlogSample s;
    if (!s.present()) GTEST_SKIP() << "the share/ rawlog sample is not there";
    const ScopedTempDir dir_tmp("cli_rawlog_cut");
    const std::string& dir = dir_tmp.path;
    // A plain copy cut in the middle (the sample is gz: decompress by reading it through MRPT
    // would need more code; a cut .gz is a truncation too).
    const std::string cut = dir + "/cut.rawlog.gz";
    fs::copy_file(s.rawlog, cut);
    fs::resize_file(cut, fs::file_size(cut) / 2);
    const RunResult r = run("rawlog " + q(cut) + " -g " + q(s.gt) + " -o " + q(dir + "/out"));
    EXPECT_EQ(r.code, 4) << r.err;
    EXPECT_TRUE(contains(r.err, "stopped at entry")) << r.err;
    for (const char* f : {"scores.csv", "report.json", "scores.png", "final.gridmap.gz",
                          "final.simplemap", "final.png"})
        EXPECT_TRUE(fs::exists(dir + "/out/" + f)) << f;
    EXPECT_TRUE(contains(readText(dir + "/out/report.json"), "\"stop\": \"truncated\""));
}

TEST_F(Cli, SeriesOverSavedMaps)
{
    const auto snaps = mrpt_topoeval::testing::sharedDataFile(
        "slam_maps/intel_rbpf-slam_broken_snapshots/mapbuilt_00000.yaml");
    const auto gt = mrpt_topoeval::testing::sharedDataFile("radish/intel-corrected_ref.yaml");
    if (!snaps || !gt) GTEST_SKIP() << "../shared/data is not there";
    const ScopedTempDir dir_tmp("cli_series");
    const std::string out = dir_tmp.path + "/out";
    // The folder's first three snapshots (the third already broken): all 14 take a minute, ten
    // under the sanitizers (doc/performance.md).
    const std::string folder = dir_tmp.path + "/snapshots";
    fs::create_directories(folder);
    for (const char* n : {"mapbuilt_00000", "mapbuilt_00200", "mapbuilt_00400"})
        for (const char* ext : {".yaml", ".png"})
            fs::copy_file(fs::path(*snaps).parent_path() / (std::string(n) + ext),
                          fs::path(folder) / (std::string(n) + ext));
    const RunResult r = run("series " + q(*gt) + " " + q(folder) + " -o " + q(out));
    ASSERT_EQ(r.code, 0) << r.err;
    const std::vector<std::string> lines = splitOn(readText(out + "/scores.csv"), '\n');
    std::size_t maps = 0;
    for (const auto& e : fs::directory_iterator(folder)) maps += e.path().extension() == ".yaml";
    ASSERT_EQ(lines.size(), maps + 1);
    EXPECT_EQ(lines[0], kScoresHeader);
    EXPECT_EQ(lines[2].rfind("2,200,,0,", 0), 0u) << lines[2];
    EXPECT_TRUE(fs::exists(out + "/scores.png"));
    expectOneLineError(run("series " + q(*gt) + " " + q(folder) + " -o " + q(out)), 3, "--force");
}

TEST_F(Cli, HtmlReportsAreWrittenAtomicallyAndNeverOverwrittenWithoutForce)
{
    const std::string maps = shareDir() + "/maps/";
    const std::string gt = maps + "map_2333d24.yaml", map = maps + "map_6ccdcaa.yaml";
    if (!fs::exists(gt) || !fs::exists(map)) GTEST_SKIP() << "the share/ samples are not there";
    const ScopedTempDir dir_tmp("cli_html");
    const std::string& dir = dir_tmp.path;
    const std::string html = dir + "/report.html";

    const RunResult c = run("compare " + q(gt) + " " + q(map) + " --html " + q(html));
    ASSERT_EQ(c.code, 0) << c.err;
    EXPECT_TRUE(contains(c.out, "wrote       " + html));
    const std::string page = readText(html);
    EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_TRUE(contains(page, "<body data-kind=\"compare\">"));
    EXPECT_EQ(listing(dir).size(), 1u);  // no temporary file left

    // Never replaced without --force, by any verb; the file stays as it was.
    writeText(html, "mine");
    expectOneLineError(run("compare " + q(gt) + " " + q(map) + " --html " + q(html)), 3,
                       html + ": exists; pass --force");
    expectOneLineError(run("rank " + q(gt) + " " + q(map) + " --html " + q(html)), 3,
                       html + ": exists; pass --force");
    expectOneLineError(
        run("series " + q(gt) + " " + q(map) + " -o " + q(dir + "/s") + " --html " + q(html)), 3,
        html + ": exists; pass --force");
    EXPECT_EQ(readText(html), "mine");
    EXPECT_FALSE(fs::exists(dir + "/s"));

    // A page is a .html file, and no output names another's file.
    expectOneLineError(run("compare " + q(gt) + " " + q(map) + " --html " + q(dir + "/r.txt")), 2,
                       "use a .html file name");
    expectOneLineError(run("rank " + q(gt) + " " + q(map) + " --csv " + q(dir + "/r.html") +
                           " --html " + q(dir + "/r.html")),
                       2, "name the same file");

    const RunResult r =
        run("rank " + q(gt) + " " + q(map) + " " + q(gt) + " --html " + q(html) + " --force");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(contains(readText(html), "<body data-kind=\"rank\">"));
    const RunResult s = run("series " + q(gt) + " " + q(map) + " " + q(gt) + " -o " +
                            q(dir + "/s") + " --html " + q(html) + " --force");
    ASSERT_EQ(s.code, 0) << s.err;
    EXPECT_TRUE(contains(readText(html), "<body data-kind=\"series\">"));
}
