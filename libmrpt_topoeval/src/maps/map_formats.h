/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// What the map-file readers (one format_*.cpp per format) share: message helpers, the checks
// every format makes, and the readers themselves, which load_map.cpp dispatches to by file name.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/maps/load_map.h>

#include <string>

namespace mrpt_topoeval::map_formats
{
using CellType = mrpt::maps::COccupancyGridMap2D::cellType;

/** Throws InputError("prefix: what"). */
[[noreturn]] void fail(const std::string& prefix, const std::string& what);
/** A number for messages: `digits` significant digits, no trailing zeros. */
std::string num(double v, int digits = 10);
std::string toLower(std::string s);
bool endsWith(const std::string& s, const std::string& suffix);
/** Missing, directory, special, empty and unreadable files each get their own message before
 * any reader sees them (`prefix` starts the message: the path, or "map.yaml: image ..."). */
void checkReadableFile(const std::string& path, const std::string& prefix);
void checkResolutionOption(const std::string& path, const MapLoadOptions& opts);
/** Refuses a grid without cells or over max_cells (`what` names it in the message). */
void checkGridSize(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid,
                   const MapLoadOptions& opts, const std::string& what);

/** The readers, one per format (format_*.cpp); `path` is known to be a readable file. */
LoadedMap loadRosYaml(const std::string& path, const MapLoadOptions& opts);
LoadedMap loadPlainImage(const std::string& path, const MapLoadOptions& opts);
LoadedMap loadGridmap(const std::string& path, const MapLoadOptions& opts);
LoadedMap loadSimplemap(const std::string& path, const MapLoadOptions& opts);

}  // namespace mrpt_topoeval::map_formats
