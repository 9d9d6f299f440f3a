/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// MRPT serialized occupancy grids (.gridmap, .gridmap.gz).
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
#include "maps/serialized_layout.h"
#include "maps/serialized_map.h"

namespace mrpt_topoeval::map_formats
{
using internal::oneLine;
using mrpt::maps::COccupancyGridMap2D;
namespace fs = std::filesystem;

/** The number of cells COccupancyGridMap2D::serializeFrom() will allocate and read for the
 * limits stored in a file; refuses what it must not allocate. MRPT ignores the stored cell
 * counts: it calls setSize() on the stored limits, in float, and sizes the grid from them. */
std::uint64_t storedGridCells(const std::string& path, const internal::StoredGridLimits& g,
                              const MapLoadOptions& opts)
{
    const double x_min = g.x_min, x_max = g.x_max, y_min = g.y_min, y_max = g.y_max,
                 res = g.resolution;
    if (!(std::isfinite(x_min) && std::isfinite(x_max) && std::isfinite(y_min) &&
          std::isfinite(y_max) && std::isfinite(res) && res > 0 && x_max > x_min && y_max > y_min))
        fail(path, "stores invalid grid limits (x " + num(x_min) + " .. " + num(x_max) + ", y " +
                       num(y_min) + " .. " + num(y_max) + ", resolution " + num(res) + ")");
    // Far from the origin, float limits are coarser than a cell and MRPT's float arithmetic
    // (and its int cell counts) no longer follow the double estimate below; 2^24 cells keep
    // every rounding within a cell or two (0.84 km at 0.05 m/cell... 16777 km at 1 m/cell).
    constexpr double kMaxCellsFromOrigin = 16777216.0;
    for (const double v : {x_min, x_max, y_min, y_max})
        if (std::abs(v / res) > kMaxCellsFromOrigin)
            fail(path, "stores grid limits (x " + num(x_min) + " .. " + num(x_max) + ", y " +
                           num(y_min) + " .. " + num(y_max) + ") more than 2^24 cells of " +
                           num(res) +
                           " m from the origin: not representable in MRPT's float "
                           "grid coordinates");
    // Same snapping as setSize(), in double so absurd values cannot overflow.
    const double nx = std::round(x_max / res) - std::round(x_min / res);
    const double ny = std::round(y_max / res) - std::round(y_min / res);
    const auto over = [&](double cx, double cy)
    {
        fail(path, "stores a grid of " + num(cx) + " x " + num(cy) +
                       " cells, over max_cells = " + std::to_string(opts.max_cells));
    };
    if (nx * ny > static_cast<double>(opts.max_cells)) over(nx, ny);
    // The exact count, from MRPT's own setSize() (within a cell or two of the estimate, so the
    // probe allocates about what the real load will).
    COccupancyGridMap2D probe;
    probe.setSize(g.x_min, g.x_max, g.y_min, g.y_max, g.resolution, 0.5f);
    const std::uint64_t cells = probe.getRawMap().size();
    if (cells > opts.max_cells) over(probe.getSizeX(), probe.getSizeY());
    return cells;
}

/** The decompressed bytes of a serialized file, streamed to the layout check: the cells of a
 * big grid are skipped, not kept. At most `limit` bytes are read; a plain file also knows
 * where it ends. Gzip errors end the data (error() says so). */
class StreamLayoutSource final : public internal::LayoutSource
{
public:
    StreamLayoutSource(const std::string& path, std::uint64_t limit, std::string limit_text)
        : m_in(path), m_limit(limit), m_limit_text(std::move(limit_text))
    {
        unsigned char magic[2] = {0, 0};
        std::ifstream f(path, std::ios::binary);
        f.read(reinterpret_cast<char*>(magic), 2);
        if (!(f.gcount() == 2 && magic[0] == 0x1f && magic[1] == 0x8b))
            m_file_bytes = fs::file_size(path);
    }
    Result take(void* dst, std::uint64_t n) override
    {
        if (n > m_limit - m_pos) return Result::Limit;
        if (n > m_file_bytes - std::min(m_pos, m_file_bytes)) return Result::End;
        auto* out = static_cast<unsigned char*>(dst);
        unsigned char scratch[1 << 16];
        std::uint64_t done = 0;
        while (done < n)
        {
            const std::size_t want =
                static_cast<std::size_t>(std::min<std::uint64_t>(n - done, sizeof scratch));
            std::size_t got = 0;
            try
            {
                got = m_in.readSome(out ? out + done : scratch, want);
            }
            catch (const std::exception&)
            {
                m_error = m_in.error();
                return Result::End;
            }
            m_pos += got;
            done += got;
            if (got < want) return Result::End;
        }
        return Result::Ok;
    }
    std::uint64_t position() const override { return m_pos; }
    std::uint64_t available() const override
    {
        const std::uint64_t cap = std::min(m_limit, m_file_bytes);
        return cap - std::min(m_pos, cap);
    }
    bool availableIsLimit() const override { return m_limit <= m_file_bytes; }
    std::string limitText() const override { return m_limit_text; }
    const std::string& error() const { return m_error; }

private:
    CheckedGzInput m_in;
    std::uint64_t m_limit;
    std::string m_limit_text;
    std::uint64_t m_file_bytes = std::numeric_limits<std::uint64_t>::max();  // gz: unknown
    std::uint64_t m_pos = 0;
    std::string m_error;
};

/** Walks the whole serialized grid (maps/serialized_layout.h) before MRPT reads it, so
 * that no length field can make MRPT allocate more than the grid's cells (checked against
 * max_cells) and the bytes the file really holds. */
void checkGridLayout(const std::string& path, const MapLoadOptions& opts)
{
    // Cells (8 or 16 bits) of a grid within max_cells, plus 1 MiB for its options.
    const std::uint64_t limit = 2 * opts.max_cells + (std::uint64_t{1} << 20);
    StreamLayoutSource src(path, limit,
                           "the " + std::to_string(limit) + " bytes a grid within max_cells = " +
                               std::to_string(opts.max_cells) + " can take");
    internal::LayoutOptions lo;
    lo.grid_cells = [&](const internal::StoredGridLimits& g)
    { return storedGridCells(path, g, opts); };
    try
    {
        internal::LayoutChecker(src, lo).occupancyGrid();
    }
    catch (const internal::LayoutError& e)
    {
        failLayout(path, e, src.error());
    }
}

LoadedMap loadGridmap(const std::string& path, const MapLoadOptions& opts)
{
    const ObjectHeader h = peekObjectHeader(path);
    expectClass(path, h, "COccupancyGridMap2D", ".gridmap");
    checkGridLayout(path, opts);
    LoadedMap out;
    out.file = path;
    out.format = "gridmap";
    readObject(path, out.grid, "serialized grid");
    checkGridSize(path, out.grid, opts, "the grid");
    return out;
}

}  // namespace mrpt_topoeval::map_formats
