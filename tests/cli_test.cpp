/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The `topoeval` command end to end: help, exit codes, one-line errors naming the file,
// outputs never overwritten without --force, deterministic JSON, pictures of the construction
// steps, the bad-input corpus.

#include <gtest/gtest.h>
#include <mrpt_topoeval/Parameters.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_paths.h"

namespace fs = std::filesystem;
using mrpt_topoeval::testing::shareDir;
using mrpt_topoeval::testing::testsDir;
using mrpt_topoeval::testing::topoevalBin;

namespace
{
/** A fresh temporary folder, removed with everything in it when the test is done. */
struct ScopedTempDir
{
    explicit ScopedTempDir(const std::string& tag) : path(mrpt_topoeval::testing::makeTempDir(tag))
    {
    }
    ~ScopedTempDir()
    {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    ScopedTempDir(const ScopedTempDir&) = delete;
    ScopedTempDir& operator=(const ScopedTempDir&) = delete;
    const std::string path;
};

struct RunResult
{
    int code = -1;
    std::string out, err;
};

std::string readText(const std::string& path)
{
    std::ifstream f(path, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

void writeText(const std::string& path, const std::string& text)
{
    std::ofstream(path, std::ios::binary) << text;
}

/** `s` quoted for /bin/sh. */
std::string q(const std::string& s)
{
    std::string out = "'";
    for (const char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return out + "'";
}

/** Runs `topoeval ARGS` (ARGS already quoted), capturing exit code, stdout and stderr. */
RunResult run(const std::string& args)
{
    static int counter = 0;
    const ScopedTempDir dir_tmp("cli_io");
    const std::string& dir = dir_tmp.path;
    const std::string out = dir + "/out" + std::to_string(counter) + ".txt";
    const std::string err = dir + "/err" + std::to_string(counter++) + ".txt";
    const std::string cmd = q(topoevalBin()) + " " + args + " >" + q(out) + " 2>" + q(err);
    const int status = std::system(cmd.c_str());
    RunResult r;
    // A crash (signal) shows as 128 + signal number, never as one of our codes.
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = readText(out);
    r.err = readText(err);
    return r;
}

int lineCount(const std::string& s)
{
    int n = 0;
    for (const char ch : s) n += ch == '\n';
    return n;
}

bool contains(const std::string& s, const std::string& part)
{
    return s.find(part) != std::string::npos;
}

/** Everything in `dir`, recursively (hidden temp files included). */
std::vector<std::string> listing(const std::string& dir)
{
    std::vector<std::string> names;
    if (!fs::exists(dir)) return names;
    for (const auto& e : fs::recursive_directory_iterator(dir)) names.push_back(e.path().string());
    return names;
}

/** The JSON without its last member "timing_ms" (the only part allowed to differ). */
std::string withoutTiming(const std::string& json)
{
    const auto at = json.find(",\n  \"timing_ms\": {");
    return at == std::string::npos ? json : json.substr(0, at);
}

/** A ROS map (PGM + YAML) of `w` x `h` pixels of one grey level. */
std::string writeUniformRosMap(const std::string& dir, const std::string& name, int w, int h,
                               unsigned char grey)
{
    std::string pgm = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
    pgm.append(static_cast<std::size_t>(w) * h, static_cast<char>(grey));
    writeText(dir + "/" + name + ".pgm", pgm);
    const std::string yaml = dir + "/" + name + ".yaml";
    writeText(yaml, "image: " + name +
                        ".pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                        "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
    return yaml;
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
