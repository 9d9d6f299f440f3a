/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// What tests that run the `topoeval` command share: temporary folders, file text, shell
// quoting, and running the command with its output captured.

#include <string>

#include "test_paths.h"  // ScopedTempDir

namespace mrpt_topoeval::testing
{
/** The whole file as bytes ("" if it cannot be read). */
std::string readText(const std::string& path);
/** Writes `text` as the whole file. */
void writeText(const std::string& path, const std::string& text);
/** `s` quoted for /bin/sh. */
std::string shellQuote(const std::string& s);
bool contains(const std::string& s, const std::string& part);
int lineCount(const std::string& s);

/** A ROS map (PGM + YAML, trinary, ROS thresholds, 0.05 m/px) of `w` x `h` pixels of one grey
 * level in `dir`; returns the YAML's path. */
std::string writeUniformRosMap(const std::string& dir, const std::string& name, int w, int h,
                               unsigned char grey);

/** The JSON text without its last member "timing_ms" (the only part allowed to differ). */
std::string withoutTiming(const std::string& json);
/** The text of the top-level member object `key` of a JSON document written by the library
 * (two-space indent), "" if there is none. */
std::string topLevelObject(const std::string& json, const std::string& key);

struct RunResult
{
    /** Exit code; 128 + N when ended by signal N (never one of ours); 124 when `timeout`
     * stopped the run. */
    int code = -1;
    std::string out, err;
};

/** Runs `topoeval ARGS` (ARGS already quoted), capturing exit code, stdout and stderr; under
 * `timeout` when time_limit_s > 0. */
RunResult runTopoeval(const std::string& args, int time_limit_s = 0);

}  // namespace mrpt_topoeval::testing
