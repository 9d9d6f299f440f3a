/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// loadMap(): the one entry for map files; chooses the reader (format_*.cpp) by file name.
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/maps/load_map.h>

#include <filesystem>
#include <new>
#include <optional>
#include <string>

#include "common/error_text.h"
#include "maps/map_formats.h"

namespace mrpt_topoeval
{
namespace
{
using internal::oneLine;

/** File name endings and their formats, longest first where one ends another. */
struct FormatSuffix
{
    const char* suffix;
    MapFormat format;
};
constexpr FormatSuffix kSuffixes[] = {
    {".gridmap", MapFormat::Gridmap},     {".gridmap.gz", MapFormat::Gridmap},
    {".simplemap", MapFormat::Simplemap}, {".simplemap.gz", MapFormat::Simplemap},
    {".yaml", MapFormat::RosYaml},        {".yml", MapFormat::RosYaml},
    {".png", MapFormat::Image},           {".pgm", MapFormat::Image},
    {".bmp", MapFormat::Image},           {".jpg", MapFormat::Image},
    {".jpeg", MapFormat::Image},
};
const char* const kUnknownFormat =
    "unknown map format (supported: .yaml, .yml, .png, .pgm, .bmp, .jpg, .jpeg, .gridmap, "
    ".gridmap.gz, .simplemap, .simplemap.gz)";

/** The file name, lower case, and the suffix it ends with (nullptr if none). */
const FormatSuffix* matchSuffix(const std::string& path, std::string* name_out = nullptr)
{
    const std::string name = map_formats::toLower(std::filesystem::path(path).filename().string());
    if (name_out) *name_out = name;
    for (const FormatSuffix& s : kSuffixes)
        if (map_formats::endsWith(name, s.suffix)) return &s;
    return nullptr;
}
}  // namespace

std::optional<MapFormat> mapFormatFromName(const std::string& path)
{
    const FormatSuffix* s = matchSuffix(path);
    if (!s) return std::nullopt;
    return s->format;
}

bool isMapFile(const std::string& path)
{
    std::string name;
    const FormatSuffix* s = matchSuffix(path, &name);
    return s && name.size() > std::string(s->suffix).size();
}

LoadedMap loadMap(const std::string& path, const MapLoadOptions& opts)
{
    if (path.empty()) throw InputError("(empty file name): no such file");
    try
    {
        map_formats::checkReadableFile(path, path);
        if (opts.max_cells == 0) map_formats::fail(path, "option max_cells = 0 must be positive");
        const std::optional<MapFormat> format = mapFormatFromName(path);
        if (!format) map_formats::fail(path, kUnknownFormat);
        switch (*format)
        {
            case MapFormat::RosYaml:
                return map_formats::loadRosYaml(path, opts);
            case MapFormat::Image:
                return map_formats::loadPlainImage(path, opts);
            case MapFormat::Gridmap:
                return map_formats::loadGridmap(path, opts);
            case MapFormat::Simplemap:
                return map_formats::loadSimplemap(path, opts);
        }
        map_formats::fail(path, "unknown map format");
    }
    catch (const InputError&)
    {
        throw;
    }
    catch (const std::bad_alloc&)
    {
        throw InputError(path +
                         ": out of memory while loading (corrupt file, or a map too large for "
                         "this machine)");
    }
    catch (const std::exception& e)
    {
        throw InputError(path + ": " + oneLine(e));
    }
}
}  // namespace mrpt_topoeval
