/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Plain images (.png .pgm .bmp .jpg .jpeg), and the pixel rules ROS YAML maps use too.
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
#include "maps/image_header.h"
#include "maps/image_map.h"
#include "maps/map_formats.h"

namespace mrpt_topoeval::map_formats
{
using internal::oneLine;
using mrpt::maps::COccupancyGridMap2D;
namespace fs = std::filesystem;

/** More distinct grey levels than this between the thresholds: a probabilistic rendering. A
 * ROS trinary image has one (205), a Tango slice one (127); MRPT quantises log-odds to int8,
 * so its renderings have about 10 (the Radish reference maps: 11). */
constexpr std::size_t kProbabilisticGreyLevels = 4;

/** The rule for an image without an explicit ROS mode, from MapLoadOptions. */
void applyGreyOption(PixelRule& rule, const MapLoadOptions& opts, const std::string& path)
{
    const std::string& g = opts.grey_between_thresholds;
    if (g == "auto")
        rule.detect_probabilistic = true;
    else if (g == "probability")
        rule.mode = PixelMode::Scale;
    else if (g != "unknown")
        fail(path,
             "option grey_between_thresholds = '" + g + "' must be auto, unknown or probability");
}

/** P(free) of a pixel whose channel average is the fraction `white` of the white level
 * (0 = black, 1 = white), following ROS map_server: p_occ = (255 - grey) / 255, or
 * grey / 255 when negated; occupied above occupied_thresh, free below free_thresh. */
double pixelToPFree(double white, const PixelRule& rule)
{
    const double grey = rule.negate ? 1.0 - white : white;
    // ROS "raw" copies the grey level into the occupancy value: dark means free.
    if (rule.mode == PixelMode::Raw) return 1.0 - grey;
    const double p_occ = 1.0 - grey;
    if (p_occ > rule.occupied_thresh) return 0.0;
    if (p_occ < rule.free_thresh) return 1.0;
    return rule.mode == PixelMode::Scale ? 1.0 - p_occ : 0.5;
}

/** Sets the grid to exactly `w` x `h` cells of `res` metres whose lower-left corner is at
 * (x0, y0), to within half a cell.
 *
 * MRPT's setSize() snaps every limit to the nearest multiple of the resolution
 * (x_min = res * round(x_min / res), same for x_max, y_min, y_max) and derives the cell count
 * from the snapped limits. With an origin that is not a multiple of the resolution, the two
 * ends may round in different directions and the grid would get w +- 1 cells. So we snap the
 * origin ourselves and pass max = min + w * res: setSize() then keeps both limits and the count
 * is exactly w. The price, as with MRPT's own loaders, is that the map moves by less than half
 * a cell (|x0 - x_min| <= res / 2): pixel centres land within half a cell of their world
 * position. */
void allocateGrid(COccupancyGridMap2D& grid, std::uint64_t w, std::uint64_t h, double res,
                  double x0, double y0, const std::string& prefix)
{
    const double sx0 = res * std::round(x0 / res);
    const double sy0 = res * std::round(y0 / res);
    const double sx1 = sx0 + static_cast<double>(w) * res;
    const double sy1 = sy0 + static_cast<double>(h) * res;
    const std::string what = std::to_string(w) + " x " + std::to_string(h) + " grid of " +
                             num(res) + " m/cell at origin (" + num(x0) + ", " + num(y0) + ")";
    try
    {
        grid.setSize(static_cast<float>(sx0), static_cast<float>(sx1), static_cast<float>(sy0),
                     static_cast<float>(sy1), static_cast<float>(res), 0.5f);
    }
    catch (const std::bad_alloc&)
    {
        throw;
    }
    catch (const std::exception& e)
    {
        fail(prefix, "cannot build a " + what + " (" + oneLine(e) + ")");
    }
    // MRPT stores limits and resolution as float: far from the origin or at extreme
    // resolutions the count can drift. Refuse rather than shift the map.
    if (grid.getSizeX() != w || grid.getSizeY() != h)
        fail(prefix,
             "cannot build a " + what + ": not representable in MRPT's float grid coordinates");
}

/** Direct writes through getRow() leave MRPT's "nothing inserted yet" flag set, so isEmpty()
 * would report a loaded map as empty; inserting a scan without rays clears the flag and
 * changes no cell (it needs no resize and traces no ray). */
void markAsLoaded(COccupancyGridMap2D& grid)
{
    const mrpt::obs::CObservation2DRangeScan no_rays;
    grid.insertObservation(no_rays);
}

/** Writes image rows into grid rows through a lookup table indexed by the sum of the first
 * `used_channels` channels of a pixel (averaging is folded into the table). Image row 0 is the
 * top of the map, i.e. grid row h-1. */
template <typename T>
void copyPixels(const cv::Mat& img, int used_channels, const std::vector<CellType>& lut,
                COccupancyGridMap2D& grid)
{
    const int w = img.cols;
    const int h = img.rows;
    const int ch = img.channels();
    const std::size_t lut_last = lut.size() - 1;
    for (int r = 0; r < h; ++r)
    {
        const T* src = img.ptr<T>(r);
        CellType* dst = grid.getRow(h - 1 - r);
        for (int c = 0; c < w; ++c, src += ch)
        {
            std::size_t sum = src[0];
            for (int k = 1; k < used_channels; ++k) sum += src[k];
            // Netpbm samples above the declared maxval are malformed: read them as white.
            dst[c] = lut[std::min(sum, lut_last)];
        }
    }
}

/** OpenCV 4.6 and libpng print their own lines on stderr when an image is truncated or corrupt
 * ("libpng error: Read Error", "imread_(...): can't read data: ..."), which would break the
 * promise of one clear line per error. stderr is pointed at /dev/null for the decode only; the
 * redirect is process-wide, so it is serialised, and it lasts milliseconds. */
class StderrSilencer
{
public:
    StderrSilencer() : m_lock(mutex())
    {
        std::fflush(stderr);
        std::cerr.flush();
        m_saved = ::dup(STDERR_FILENO);
        const int null_fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
        if (m_saved >= 0 && null_fd >= 0) ::dup2(null_fd, STDERR_FILENO);
        if (null_fd >= 0) ::close(null_fd);
    }
    ~StderrSilencer()
    {
        std::fflush(stderr);
        std::cerr.flush();
        if (m_saved >= 0)
        {
            ::dup2(m_saved, STDERR_FILENO);
            ::close(m_saved);
        }
    }
    StderrSilencer(const StderrSilencer&) = delete;
    StderrSilencer& operator=(const StderrSilencer&) = delete;

private:
    static std::mutex& mutex()
    {
        static std::mutex m;
        return m;
    }
    std::lock_guard<std::mutex> m_lock;
    int m_saved = -1;
};

/** Decodes an image file whose header has already been checked, and fills `grid` with it,
 * lower-left pixel corner at (x0, y0). `prefix` starts every message. Returns the notes of
 * PixelRule::map_saver_unknown_grey. */
std::vector<std::string> imageToGrid(const std::string& image_path,
                                     const internal::ImageHeader& hdr, const PixelRule& rule_in,
                                     double res, double x0, double y0, COccupancyGridMap2D& grid,
                                     const std::string& prefix)
{
    // IMREAD_UNCHANGED keeps 16-bit samples and does not apply EXIF rotation (a map's pixel
    // layout is its geometry); alpha is dropped below, as ROS map_server ignores it.
    cv::Mat img;
    try
    {
        const StderrSilencer quiet;
        img = cv::imread(image_path, cv::IMREAD_UNCHANGED);
    }
    catch (const cv::Exception& e)
    {
        fail(prefix, "cannot decode image (" + oneLine(e) + ")");
    }
    if (img.empty())
    {
        // OpenCV refuses images over 2^30 pixels unless OPENCV_IO_MAX_IMAGE_PIXELS says more.
        if (hdr.width * hdr.height > (std::uint64_t{1} << 30))
            fail(prefix,
                 "cannot decode image (over OpenCV's limit of 2^30 pixels; see "
                 "OPENCV_IO_MAX_IMAGE_PIXELS)");
        fail(prefix, "cannot decode image (truncated or corrupt?)");
    }
    if (static_cast<std::uint64_t>(img.cols) != hdr.width ||
        static_cast<std::uint64_t>(img.rows) != hdr.height)
        fail(prefix, "decoded image is " + std::to_string(img.cols) + " x " +
                         std::to_string(img.rows) + " pixels but its header declares " +
                         std::to_string(hdr.width) + " x " + std::to_string(hdr.height));
    if (img.depth() != CV_8U && img.depth() != CV_16U)
        fail(prefix, "unsupported pixel depth (only 8- and 16-bit images are maps)");

    const int ch = img.channels();
    // Grey, grey+alpha, BGR, BGRA: average the colour channels, never the alpha.
    const int used = (ch == 2) ? 1 : (ch == 4 ? 3 : ch);
    const std::uint32_t white =
        hdr.max_value != 0 ? hdr.max_value : (img.depth() == CV_16U ? 65535u : 255u);

    // One table entry per possible channel sum: at most 3 x 65535 + 1 entries.
    const std::size_t n_sums = static_cast<std::size_t>(used) * white + 1;
    std::vector<CellType> lut(n_sums);
    const double denom = static_cast<double>(used) * white;
    PixelRule rule = rule_in;
    // Which channel sums the image holds: one pass over the image, on first use only (both
    // rules below ask for it).
    std::vector<char> seen;
    auto sumsPresent = [&]() -> const std::vector<char>&
    {
        if (!seen.empty()) return seen;
        seen.assign(n_sums, 0);
        for (int y = 0; y < img.rows; ++y)
            for (int x = 0; x < img.cols; ++x)
            {
                std::size_t sum = 0;
                for (int c = 0; c < used; ++c)
                    sum += img.depth() == CV_8U
                               ? img.ptr<std::uint8_t>(y)[static_cast<std::size_t>(x) * ch + c]
                               : img.ptr<std::uint16_t>(y)[static_cast<std::size_t>(x) * ch + c];
                // Netpbm samples above the declared maxval are malformed: read as white, as
                // the pixel loop below reads them.
                seen[std::min(sum, n_sums - 1)] = 1;
            }
        return seen;
    };
    if (rule.detect_probabilistic && rule.mode == PixelMode::Trinary)
    {
        // Distinct channel sums whose probability lies between the thresholds.
        const std::vector<char>& present = sumsPresent();
        std::size_t between = 0;
        PixelRule scale = rule;
        scale.mode = PixelMode::Scale;
        for (std::size_t s = 0; s < n_sums; ++s)
        {
            const double p = pixelToPFree(static_cast<double>(s) / denom, scale);
            between += present[s] && p != 0.0 && p != 1.0;
        }
        if (between > kProbabilisticGreyLevels) rule.mode = PixelMode::Scale;
    }
    for (std::size_t s = 0; s < n_sums; ++s)
        lut[s] = COccupancyGridMap2D::p2l(
            static_cast<float>(pixelToPFree(static_cast<double>(s) / denom, rule)));

    // ROS map_saver's unknown grey that the YAML's free_thresh makes free (nav2 Humble wrote
    // free_thresh 0.25): in an 8-bit grey image of map_saver's greys only (0, g, 254, 255) it
    // is unknown, not free. The sums are the greys themselves (one channel).
    std::vector<std::string> notes;
    const int g = rule.map_saver_unknown_grey;
    if (rule.mode == PixelMode::Trinary && g >= 0 && g <= 254 && !rule.negate && used == 1 &&
        img.depth() == CV_8U && white == 255 &&
        pixelToPFree(static_cast<double>(g) / denom, rule) == 1.0 && sumsPresent()[g])
    {
        const std::vector<char>& present = sumsPresent();
        bool saver_greys_only = true;
        for (int s = 0; s < static_cast<int>(n_sums) && saver_greys_only; ++s)
            saver_greys_only = !present[s] || s == 0 || s == g || s == 254 || s == 255;
        const std::string grey =
            "grey " + std::to_string(g) + " (ROS map_saver's unknown) read as ";
        if (saver_greys_only)
        {
            lut[static_cast<std::size_t>(g)] = COccupancyGridMap2D::p2l(0.5f);
            notes.push_back(grey + "unknown, not free as free_thresh " + num(rule.free_thresh) +
                            " says (as nav2 Humble's map_saver wrote it; [MapLoad] "
                            "trinary_unknown_grey = -1 keeps it free)");
        }
        else
            notes.push_back(grey + "free, as free_thresh " + num(rule.free_thresh) +
                            " says: the image holds other greys than map_saver's, so it was not "
                            "written by map_saver");
    }

    allocateGrid(grid, hdr.width, hdr.height, res, x0, y0, prefix);
    if (img.depth() == CV_8U)
        copyPixels<std::uint8_t>(img, used, lut, grid);
    else
        copyPixels<std::uint16_t>(img, used, lut, grid);
    markAsLoaded(grid);
    return notes;
}

/** Reads and size-checks an image header; `prefix` replaces the image path at the start of
 * any message (used when the image is named by a YAML file). */
internal::ImageHeader checkedImageHeader(const std::string& image_path, const std::string& prefix,
                                         const MapLoadOptions& opts)
{
    internal::ImageHeader hdr;
    try
    {
        hdr = internal::readImageHeader(image_path);
    }
    catch (const InputError& e)
    {
        // readImageHeader() names the image path; say it the caller's way.
        std::string msg = e.what();
        if (msg.rfind(image_path + ": ", 0) == 0) msg = msg.substr(image_path.size() + 2);
        fail(prefix, msg);
    }
    // Checked before decoding: a few header bytes must not make OpenCV allocate gigabytes.
    // Both sizes are below 2^32 (PNG / BMP / JPEG) or saturated (Netpbm), so no overflow.
    const double cells = static_cast<double>(hdr.width) * static_cast<double>(hdr.height);
    if (cells > static_cast<double>(opts.max_cells))
        fail(prefix, std::string(internal::imageFormatName(hdr.format)) + " image declares " +
                         std::to_string(hdr.width) + " x " + std::to_string(hdr.height) +
                         " pixels, over max_cells = " + std::to_string(opts.max_cells));
    return hdr;
}

LoadedMap loadPlainImage(const std::string& path, const MapLoadOptions& opts)
{
    checkResolutionOption(path, opts);
    const std::pair<const char*, double> thresholds[] = {{"occupied_thresh", opts.occupied_thresh},
                                                         {"free_thresh", opts.free_thresh}};
    for (const auto& [name, v] : thresholds)
        if (!(v >= 0.0 && v <= 1.0))
            fail(path, std::string("option ") + name + " = " + num(v) + " must be in [0, 1]");
    if (!(opts.free_thresh < opts.occupied_thresh))
        fail(path, "option free_thresh = " + num(opts.free_thresh) +
                       " must be below occupied_thresh = " + num(opts.occupied_thresh));

    const internal::ImageHeader hdr = checkedImageHeader(path, path, opts);
    PixelRule rule;
    rule.occupied_thresh = opts.occupied_thresh;
    rule.free_thresh = opts.free_thresh;
    applyGreyOption(rule, opts, path);
    LoadedMap out;
    out.file = path;
    out.format = "image";
    // A plain image has no georeference: its lower-left corner is the world origin.
    imageToGrid(path, hdr, rule, opts.resolution_m, 0.0, 0.0, out.grid, path);
    return out;
}

}  // namespace mrpt_topoeval::map_formats
