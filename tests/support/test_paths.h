/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <optional>
#include <string>
#include <utility>

namespace mrpt_topoeval::testing
{
/** `../shared/data/<relative>` if that file exists (tests on real data skip otherwise). */
std::optional<std::string> sharedDataFile(const std::string& relative);
/** The project's `share/mrpt_topoeval` folder (samples, default INI). */
std::string shareDir();
/** The project's `tests` folder (bad-input corpus under tests/data). */
std::string testsDir();
/** The ground truth and the map that the validator wrote for a corpus case (`--pictures`),
 * kept in tests/data/<folder>/<name>.{gt,map}.gridmap. */
std::pair<mrpt::maps::COccupancyGridMap2D, mrpt::maps::COccupancyGridMap2D> corpusCase(
    const std::string& folder, const std::string& name);
/** The built `topoeval` executable, empty if apps are not built. */
std::string topoevalBin();
/** A fresh empty temporary folder for one test (topoeval_test_TAG_PID_N in the system's temp
 * folder), removed with everything in it at scope exit. */
struct ScopedTempDir
{
    explicit ScopedTempDir(const std::string& tag);
    ~ScopedTempDir();
    ScopedTempDir(const ScopedTempDir&) = delete;
    ScopedTempDir& operator=(const ScopedTempDir&) = delete;
    const std::string path;
};

}  // namespace mrpt_topoeval::testing
