/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Message helpers and the checks every map format makes (map_formats.h).
#include "maps/map_formats.h"

#include <fcntl.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationRange.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <new>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "common/error_text.h"

namespace mrpt_topoeval::map_formats
{
using internal::oneLine;
using mrpt::maps::COccupancyGridMap2D;
namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& prefix, const std::string& what)
{
    throw InputError(prefix + ": " + what);
}

/** A number for messages: `digits` significant digits, no trailing zeros. */
std::string num(double v, int digits)
{
    std::ostringstream s;
    s.precision(digits);
    s << v;
    return s.str();
}

std::string toLower(std::string s)
{
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

bool endsWith(const std::string& s, const std::string& suffix)
{
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/** Missing, directory, special, empty and unreadable files each get their own message before
 * any reader sees them (`prefix` starts the message: the path, or "map.yaml: image ..."). */
void checkReadableFile(const std::string& path, const std::string& prefix)
{
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (st.type() == fs::file_type::not_found || ec == std::errc::not_a_directory)
        fail(prefix, "no such file");
    if (ec) fail(prefix, "cannot be accessed (" + ec.message() + ")");
    if (fs::is_directory(st)) fail(prefix, "is a directory, not a file");
    if (!fs::is_regular_file(st)) fail(prefix, "is not a regular file");
    const auto size = fs::file_size(path, ec);
    if (ec) fail(prefix, "cannot be accessed (" + ec.message() + ")");
    if (size == 0) fail(prefix, "is empty");
    std::ifstream f(path, std::ios::binary);
    if (!f) fail(prefix, std::string("cannot be read (") + std::strerror(errno) + ")");
}

void checkResolutionOption(const std::string& path, const MapLoadOptions& opts)
{
    if (!std::isfinite(opts.resolution_m) || opts.resolution_m <= 0)
        fail(path, "option resolution_m = " + num(opts.resolution_m) +
                       " must be a positive number of metres per cell");
}

void checkGridSize(const std::string& path, const COccupancyGridMap2D& grid,
                   const MapLoadOptions& opts, const std::string& what)
{
    const std::uint64_t cells = std::uint64_t{grid.getSizeX()} * grid.getSizeY();
    if (cells == 0) fail(path, what + " has no cells");
    if (cells > opts.max_cells)
        fail(path, what + " has " + std::to_string(grid.getSizeX()) + " x " +
                       std::to_string(grid.getSizeY()) +
                       " cells, over max_cells = " + std::to_string(opts.max_cells));
}

}  // namespace mrpt_topoeval::map_formats
