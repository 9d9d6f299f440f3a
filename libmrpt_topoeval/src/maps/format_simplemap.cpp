/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// MRPT simple maps (.simplemap, .simplemap.gz): keyframes rendered into a grid.
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

/** Refuses a simple map whose rendering would crash MRPT or exceed max_cells, before
 * rendering it. COccupancyGridMap2D grows while scans are inserted, inside a noexcept
 * resizeGrid() (a failed allocation there terminates the program), reaches every scan
 * endpoint (ranges clipped to insertionOptions.maxDistanceInsertion from above only: a
 * negative or infinite range reaches anywhere) and puts each scan's rays in two alloca()
 * buffers on the stack. So: finite poses and ranges, a bounded number of rays per scan, and a
 * bounding box of sensor positions +- reach that fits max_cells. */
void checkRenderExtent(const std::string& path, const mrpt::maps::CSimpleMap& sm,
                       const COccupancyGridMap2D::TInsertionOptions& insertion,
                       const MapLoadOptions& opts)
{
    // 100k rays -> 800 kB of stack, well within the usual 8 MB; real scanners give < 10k.
    constexpr std::size_t kMaxRaysPerScan = 100'000;
    const double max_d = insertion.maxDistanceInsertion;
    // loadFromSimpleMap() starts from a 20 m x 20 m grid about the origin.
    double x0 = -10, x1 = 10, y0 = -10, y1 = 10;
    const auto finitePose = [](const mrpt::poses::CPose3D& p)
    {
        return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()) &&
               std::isfinite(p.yaw()) && std::isfinite(p.pitch()) && std::isfinite(p.roll());
    };
    const auto extend = [&](double x, double y, double reach)
    {
        x0 = std::min(x0, x - reach);
        x1 = std::max(x1, x + reach);
        y0 = std::min(y0, y - reach);
        y1 = std::max(y1, y + reach);
    };
    for (std::size_t i = 0; i < sm.size(); ++i)
    {
        const auto [pose_pdf, sf] = sm.get(i);
        const std::string kf = "keyframe " + std::to_string(i);
        if (!pose_pdf || !sf) fail(path, kf + " has no pose or no observations (corrupt file?)");
        const mrpt::poses::CPose3D robot = pose_pdf->getMeanVal();
        if (!finitePose(robot)) fail(path, kf + " has a non-finite pose");
        for (const auto& obs : *sf)
        {
            if (!obs) continue;
            if (const auto* scan =
                    dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(obs.get()))
            {
                if (scan->getScanSize() > kMaxRaysPerScan)
                    fail(path, kf + " has a scan of " + std::to_string(scan->getScanSize()) +
                                   " rays (more than " + std::to_string(kMaxRaysPerScan) + ")");
                if (!std::isfinite(scan->aperture))
                    fail(path, kf + " has a scan with a non-finite aperture");
                const mrpt::poses::CPose3D sensor = robot + scan->sensorPose;
                if (!finitePose(sensor)) fail(path, kf + " has a non-finite sensor pose");
                double reach = max_d;
                for (std::size_t k = 0; k < scan->getScanSize(); ++k)
                {
                    if (!scan->getScanRangeValidity(k)) continue;
                    // std::min as MRPT does: a NaN range becomes max_d, -inf stays.
                    const double r =
                        std::min<float>(static_cast<float>(max_d), scan->getScanRange(k));
                    if (!std::isfinite(r)) fail(path, kf + " has a scan with a non-finite range");
                    reach = std::max(reach, std::abs(r));
                }
                extend(sensor.x(), sensor.y(), reach);
            }
            else if (const auto* ranges =
                         dynamic_cast<const mrpt::obs::CObservationRange*>(obs.get()))
            {
                for (const auto& m : ranges->sensedData)
                {
                    const mrpt::poses::CPose3D sensor = robot + mrpt::poses::CPose3D(m.sensorPose);
                    if (!finitePose(sensor)) fail(path, kf + " has a non-finite sensor pose");
                    double reach = max_d;
                    if (m.sensedDistance < max_d)
                    {
                        if (!std::isfinite(m.sensedDistance))
                            fail(path, kf + " has a non-finite range");
                        reach = std::max(reach, std::abs(double(m.sensedDistance)));
                    }
                    extend(sensor.x(), sensor.y(), reach);
                }
            }
        }
    }
    // Each insertion grows the grid 2 m (low side) or 30 cells (high side) past the scan, then
    // resizeGrid() adds 4 m and rounds out to whole metres.
    const double res = opts.resolution_m;
    const double margin = 8.0 + 30.0 * res;
    const double w_m = (x1 - x0) + 2 * margin;
    const double h_m = (y1 - y0) + 2 * margin;
    const double cells = std::ceil(w_m / res) * std::ceil(h_m / res);
    if (cells > static_cast<double>(opts.max_cells))
        fail(path, "rendering it at " + num(res) + " m/cell would need about " + num(cells, 2) +
                       " cells (" + num(std::round(w_m)) + " m x " + num(std::round(h_m)) +
                       " m), over max_cells = " + std::to_string(opts.max_cells));
}

/** The whole file after decompression (gzip or plain); also proves the gzip stream intact
 * before MRPT parses it. */
std::vector<unsigned char> decompressAll(const std::string& path)
{
    // Simple maps of real runs are a few MB; a bigger one is corrupt or a decompression bomb.
    constexpr std::uint64_t kMaxBytes = std::uint64_t{2} << 30;
    CheckedGzInput in(path);
    std::vector<unsigned char> data;
    std::vector<unsigned char> buf(1 << 20);
    for (std::size_t got; (got = in.readSome(buf.data(), buf.size())) > 0;)
    {
        if (data.size() + got > kMaxBytes)
            fail(path, "is larger than 2 GiB after decompression: not supported");
        data.insert(data.end(), buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(got));
    }
    return data;
}

/** Walks the whole serialized simple map (maps/serialized_layout.h) before MRPT reads
 * it: MRPT sizes its keyframe list, observation lists, scans and strings from counts stored in
 * the file before it reads the data they announce, so every count is checked against the
 * bytes that really follow it. The decompressed file is in memory: the check knows its end. */
void checkSimplemapLayout(const std::string& path, const std::vector<unsigned char>& data)
{
    internal::MemoryLayoutSource src(data.data(), data.size());
    try
    {
        internal::LayoutChecker(src).simpleMap();
    }
    catch (const internal::LayoutError& e)
    {
        // A keyframe that holds another sensor (a camera...): what comes before it was
        // checked; MRPT reads the rest as it is, as for rawlogs (doc/reliability.md).
        if (e.kind() == internal::LayoutError::Kind::Unchecked) return;
        failLayout(path, e, "");
    }
}

LoadedMap loadSimplemap(const std::string& path, const MapLoadOptions& opts)
{
    checkResolutionOption(path, opts);
    const ObjectHeader h = peekObjectHeader(path);
    expectClass(path, h, "CSimpleMap", ".simplemap");
    checkSimplemapLayout(path, decompressAll(path));
    mrpt::maps::CSimpleMap sm;
    readObject(path, sm, "simple map");
    if (sm.empty()) fail(path, "holds no keyframes (nothing to render)");

    LoadedMap out;
    out.file = path;
    out.format = "simplemap";
    checkRenderExtent(path, sm, out.grid.insertionOptions, opts);
    // loadFromSimpleMap() clears the grid to 20 m x 20 m at the grid's current resolution,
    // then grows it as scans are inserted (MRPT's default insertion options).
    out.grid.setSize(-10.0f, 10.0f, -10.0f, 10.0f, static_cast<float>(opts.resolution_m), 0.5f);
    try
    {
        out.grid.loadFromSimpleMap(sm);
    }
    catch (const std::bad_alloc&)
    {
        throw;
    }
    catch (const std::exception& e)
    {
        fail(path, "cannot render its scans into a grid (MRPT: " + oneLine(e) + ")");
    }
    checkGridSize(path, out.grid, opts, "the rendered grid");
    return out;
}

}  // namespace mrpt_topoeval::map_formats
