/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "test_paths.h"

#include <mrpt_topoeval/map_io.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;

namespace mrpt_topoeval::testing
{
std::optional<std::string> sharedDataFile(const std::string& relative)
{
    const fs::path p = fs::path(TOPOEVAL_SHARED_DATA_DIR) / relative;
    std::error_code ec;
    if (fs::exists(p, ec)) return p.string();
    return std::nullopt;
}

std::string shareDir() { return TOPOEVAL_SHARE_DIR; }
std::string testsDir() { return TOPOEVAL_TESTS_DIR; }
std::string topoevalBin() { return TOPOEVAL_BIN; }

std::pair<mrpt::maps::COccupancyGridMap2D, mrpt::maps::COccupancyGridMap2D> corpusCase(
    const std::string& folder, const std::string& name)
{
    const std::string base = testsDir() + "/data/" + folder + "/" + name;
    return {loadMap(base + ".gt.gridmap").grid, loadMap(base + ".map.gridmap").grid};
}

namespace
{
std::string makeTempDir(const std::string& tag)
{
    static std::atomic<int> counter{0};
    const fs::path p =
        fs::temp_directory_path() / ("topoeval_test_" + tag + "_" + std::to_string(::getpid()) +
                                     "_" + std::to_string(counter++));
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}
}  // namespace

ScopedTempDir::ScopedTempDir(const std::string& tag) : path(makeTempDir(tag)) {}

ScopedTempDir::~ScopedTempDir()
{
    std::error_code ec;
    fs::remove_all(path, ec);
}

}  // namespace mrpt_topoeval::testing
