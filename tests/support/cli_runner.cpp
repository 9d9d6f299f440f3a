/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "cli_runner.h"

#include <sys/wait.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "test_paths.h"

namespace fs = std::filesystem;

namespace mrpt_topoeval::testing
{
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

std::string shellQuote(const std::string& s)
{
    std::string out = "'";
    for (const char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return out + "'";
}

bool contains(const std::string& s, const std::string& part)
{
    return s.find(part) != std::string::npos;
}

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

std::string withoutTiming(const std::string& json)
{
    const auto at = json.find(",\n  \"timing_ms\": {");
    return at == std::string::npos ? json : json.substr(0, at);
}

std::string topLevelObject(const std::string& json, const std::string& key)
{
    const auto at = json.find("\n  \"" + key + "\": {");
    if (at == std::string::npos) return {};
    const auto open = json.find('{', at);
    const auto close = json.find("\n  }", open);
    return close == std::string::npos ? std::string() : json.substr(open, close + 4 - open);
}

int lineCount(const std::string& s)
{
    int n = 0;
    for (const char ch : s) n += ch == '\n';
    return n;
}

RunResult runTopoeval(const std::string& args, int time_limit_s)
{
    static std::atomic<int> counter{0};
    const ScopedTempDir io("cli_io");
    const int k = counter++;
    const std::string out = io.path + "/out" + std::to_string(k) + ".txt";
    const std::string err = io.path + "/err" + std::to_string(k) + ".txt";
    // --kill-after: a run that ignores SIGTERM still ends; without --preserve-status a hang
    // reads as 124, never as one of our codes.
    const std::string prefix = time_limit_s > 0
                                   ? "timeout --kill-after=5 " + std::to_string(time_limit_s) + " "
                                   : std::string();
    const std::string cmd = prefix + shellQuote(topoevalBin()) + " " + args + " >" +
                            shellQuote(out) + " 2>" + shellQuote(err);
    const int status = std::system(cmd.c_str());
    RunResult r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = readText(out);
    r.err = readText(err);
    return r;
}

}  // namespace mrpt_topoeval::testing
