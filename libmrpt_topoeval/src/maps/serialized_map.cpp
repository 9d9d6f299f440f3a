/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Reading MRPT serialized map files safely (serialized_map.h).
#include "maps/serialized_map.h"

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
#include "maps/map_formats.h"

namespace mrpt_topoeval::map_formats
{
using internal::oneLine;
using mrpt::maps::COccupancyGridMap2D;
namespace fs = std::filesystem;

/** Reads the class name and version of the object at the start of a serialized file without
 * deserializing it, so that a file of another class gets its own message.
 * Format: (0x80 | name length), name, uint8 version; or, before MRPT 0.5.5, name length, three
 * zero bytes, name, int32 version. */
ObjectHeader peekObjectHeader(const std::string& path)
{
    CheckedGzInput in(path);
    std::vector<unsigned char> b(256);
    b.resize(in.readSome(b.data(), b.size()));
    const auto notMrpt = [&]()
    { fail(path, "is not an MRPT serialized file (unrecognised content)"); };
    if (b.empty()) fail(path, "is empty after decompression");
    const bool old_format = (b[0] & 0x80) == 0;
    const std::size_t name_len = b[0] & 0x7F;
    std::size_t pos = old_format ? 4 : 1;
    // MRPT itself refuses class names over 120 characters as corrupt.
    if (name_len == 0 || name_len > 120 || b.size() < pos + name_len + (old_format ? 4 : 1))
        notMrpt();
    if (old_format && (b[1] || b[2] || b[3])) notMrpt();
    ObjectHeader h;
    h.class_name.assign(reinterpret_cast<const char*>(&b[pos]), name_len);
    for (const char c : h.class_name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':')) notMrpt();
    pos += name_len;
    if (old_format)
        h.version = static_cast<int>(b[pos] | (b[pos + 1] << 8) | (b[pos + 2] << 16) |
                                     (static_cast<unsigned>(b[pos + 3]) << 24));
    else
        h.version = static_cast<std::int8_t>(b[pos]);
    return h;
}

/** "mrpt::maps::COccupancyGridMap2D" -> "COccupancyGridMap2D" (old files omit namespaces). */
std::string bareClassName(const std::string& name)
{
    const auto k = name.rfind("::");
    return k == std::string::npos ? name : name.substr(k + 2);
}

void expectClass(const std::string& path, const ObjectHeader& h, const std::string& expected,
                 const std::string& format_name)
{
    if (bareClassName(h.class_name) != expected)
        fail(path, "holds a serialized '" + h.class_name + "', not the " + expected + " a " +
                       format_name + " file must hold");
}

/** Turns a refused layout into the one-line message of a map file. */
[[noreturn]] void failLayout(const std::string& path, const internal::LayoutError& e,
                             const std::string& gzip_error)
{
    if (!gzip_error.empty()) fail(path, gzip_error);
    switch (e.kind())
    {
        case internal::LayoutError::Kind::Truncated:
            fail(path, std::string("truncated or corrupt: ") + e.what());
        case internal::LayoutError::Kind::TooLarge:
            fail(path, std::string("is too large: ") + e.what());
        case internal::LayoutError::Kind::Corrupt:
        case internal::LayoutError::Kind::Unchecked:
            break;
    }
    fail(path, std::string("is corrupt: ") + e.what());
}

}  // namespace mrpt_topoeval::map_formats
