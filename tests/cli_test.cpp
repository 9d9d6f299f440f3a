/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The `topoeval` command end to end: help, exit codes, one-line errors naming the file,
// outputs never overwritten without --force, deterministic JSON, the bad-input corpus.

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
        const RunResult r = run("graph " + q(map) + " --json " + q(json) + " --image " + q(png));
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_TRUE(contains(r.err, "topoeval: warning: ")) << name << ": " << r.err;
        EXPECT_FALSE(contains(r.err, "error")) << r.err;
        const std::string text = readText(json);
        EXPECT_TRUE(contains(text, "\"vertices\": [],")) << text;
        EXPECT_TRUE(contains(text, "\"edges\": [],")) << text;
        EXPECT_TRUE(fs::exists(png));
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
