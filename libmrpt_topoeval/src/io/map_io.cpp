/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
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
#include <mrpt_topoeval/map_io.h>
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

#include "internal/error_text.h"
#include "internal/image_header.h"
#include "internal/serialized_layout.h"

namespace fs = std::filesystem;
using mrpt_topoeval::internal::oneLine;

namespace mrpt_topoeval
{
namespace
{
using mrpt::maps::COccupancyGridMap2D;
using CellType = COccupancyGridMap2D::cellType;

[[noreturn]] void fail(const std::string& prefix, const std::string& what)
{
    throw InputError(prefix + ": " + what);
}

/** A number for messages: `digits` significant digits, no trailing zeros. */
std::string num(double v, int digits = 10)
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

// ---------------------------------------------------------------------------------------
// Pixels -> cells
// ---------------------------------------------------------------------------------------

/** ROS map_server interpretation modes. */
enum class PixelMode
{
    Trinary,  //!< occupied / free / unknown only
    Scale,    //!< between the thresholds, keep the probability
    Raw       //!< P(free) = 1 - grey, no thresholds
};

/** How grey levels become cell probabilities (ROS map_server semantics). */
struct PixelRule
{
    double occupied_thresh = 0.65;
    double free_thresh = 0.196;
    bool negate = false;
    PixelMode mode = PixelMode::Trinary;
    /** Trinary without an explicit mode: switch to Scale when the image has many grey levels
     * between the thresholds (a probabilistic rendering). */
    bool detect_probabilistic = false;
};

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
 * lower-left pixel corner at (x0, y0). `prefix` starts every message. */
void imageToGrid(const std::string& image_path, const internal::ImageHeader& hdr,
                 const PixelRule& rule_in, double res, double x0, double y0,
                 COccupancyGridMap2D& grid, const std::string& prefix)
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
    if (rule.detect_probabilistic && rule.mode == PixelMode::Trinary)
    {
        // Distinct channel sums whose probability lies between the thresholds.
        std::vector<char> seen(n_sums, 0);
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
        std::size_t between = 0;
        PixelRule scale = rule;
        scale.mode = PixelMode::Scale;
        for (std::size_t s = 0; s < n_sums; ++s)
        {
            const double p = pixelToPFree(static_cast<double>(s) / denom, scale);
            between += seen[s] && p != 0.0 && p != 1.0;
        }
        if (between > kProbabilisticGreyLevels) rule.mode = PixelMode::Scale;
    }
    for (std::size_t s = 0; s < n_sums; ++s)
        lut[s] = COccupancyGridMap2D::p2l(
            static_cast<float>(pixelToPFree(static_cast<double>(s) / denom, rule)));

    allocateGrid(grid, hdr.width, hdr.height, res, x0, y0, prefix);
    if (img.depth() == CV_8U)
        copyPixels<std::uint8_t>(img, used, lut, grid);
    else
        copyPixels<std::uint16_t>(img, used, lut, grid);
    markAsLoaded(grid);
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

void checkResolutionOption(const std::string& path, const MapLoadOptions& opts)
{
    if (!std::isfinite(opts.resolution_m) || opts.resolution_m <= 0)
        fail(path, "option resolution_m = " + num(opts.resolution_m) +
                       " must be a positive number of metres per cell");
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

// ---------------------------------------------------------------------------------------
// ROS map_server YAML
// ---------------------------------------------------------------------------------------

/** One top-level value of a ROS map YAML: a scalar, or a sequence of scalars. */
struct YamlValue
{
    std::string scalar;
    std::vector<std::string> items;
    bool is_sequence = false;

    /** The value as written, for messages. */
    std::string text() const
    {
        if (!is_sequence) return scalar;
        std::string s = "[";
        for (std::size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + items[i];
        return s + "]";
    }
};

/** A strict reader for the flat YAML subset ROS map files use: `key: scalar`,
 * `key: [a, b, c]` and block sequences (`key:` then `- a` lines), with comments, quotes and
 * an optional `---`. Anything else (nesting, anchors, duplicate keys) is refused with its line
 * number: lenient YAML readers accept a broken file and silently drop or overwrite keys. */
class RosYamlReader
{
public:
    RosYamlReader(std::string file, std::string_view text) : m_file(std::move(file))
    {
        // UTF-8 byte order mark, as some editors on Windows write.
        if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
        m_text = text;
    }

    std::map<std::string, YamlValue> read()
    {
        std::map<std::string, YamlValue> out;
        YamlValue* open_block = nullptr;  // a `key:` with no value may take `- item` lines
        std::size_t pos = 0;
        int line_no = 0;
        while (pos <= m_text.size())
        {
            std::size_t eol = m_text.find_first_of("\r\n", pos);
            if (eol == std::string_view::npos) eol = m_text.size();
            const std::string_view raw = m_text.substr(pos, eol - pos);
            ++line_no;
            // "\r\n" counts as one line end.
            pos = eol + ((eol + 1 < m_text.size() && m_text[eol] == '\r' && m_text[eol + 1] == '\n')
                             ? 2
                             : 1);

            const std::size_t indent = raw.find_first_not_of(" \t");
            if (indent == std::string_view::npos) continue;
            const std::string_view body = raw.substr(indent);
            if (body[0] == '#') continue;
            if (indent == 0 && (body == "---" || body.substr(0, 4) == "--- "))
            {
                if (!out.empty())
                    failAt(line_no, "a second YAML document ('---') is not supported");
                continue;
            }
            if (indent == 0 && body == "...") break;

            if (body[0] == '-' && (body.size() == 1 || body[1] == ' ' || body[1] == '\t'))
            {
                if (!open_block)
                    failAt(line_no, "unexpected list item (only a key may open a list)");
                open_block->is_sequence = true;
                open_block->items.push_back(scalar(body.substr(1), line_no));
                continue;
            }
            if (indent > 0)
                failAt(line_no, "unexpected indented line (ROS map files have no nested mappings)");

            open_block = nullptr;
            auto [key, rest] = splitKey(body, line_no);
            if (out.count(key)) failAt(line_no, "key '" + key + "' appears twice");
            YamlValue& v = out[key];
            rest = trim(rest);
            if (rest.empty() || rest[0] == '#')
            {
                open_block = &v;
            }
            else if (rest[0] == '[')
            {
                v.is_sequence = true;
                v.items = flowSequence(rest, line_no);
            }
            else
            {
                v.scalar = scalar(rest, line_no);
            }
        }
        return out;
    }

private:
    [[noreturn]] void failAt(int line, const std::string& what) const
    {
        fail(m_file, "line " + std::to_string(line) + ": " + what);
    }

    static std::string_view trim(std::string_view s)
    {
        const auto b = s.find_first_not_of(" \t");
        if (b == std::string_view::npos) return {};
        const auto e = s.find_last_not_of(" \t");
        return s.substr(b, e - b + 1);
    }

    /** `key: rest` -> (key, rest); plain or quoted keys. */
    std::pair<std::string, std::string_view> splitKey(std::string_view body, int line) const
    {
        std::string key;
        std::size_t after = 0;
        if (body[0] == '"' || body[0] == '\'')
        {
            std::size_t used = 0;
            key = quoted(body, line, used);
            after = used;
        }
        else
        {
            // The key ends at the first ": " (or a ':' ending the line).
            std::size_t k = 0;
            for (; k < body.size(); ++k)
                if (body[k] == ':' &&
                    (k + 1 == body.size() || body[k + 1] == ' ' || body[k + 1] == '\t'))
                    break;
            if (k == body.size()) failAt(line, "expected 'key: value'");
            key = std::string(trim(body.substr(0, k)));
            after = k;
        }
        const std::string_view rest = trim(body.substr(after));
        if (rest.empty() || rest[0] != ':') failAt(line, "expected ':' after key '" + key + "'");
        if (key.empty()) failAt(line, "empty key");
        return {key, rest.substr(1)};
    }

    /** A quoted scalar starting at s[0]; `used` gets the characters consumed. */
    std::string quoted(std::string_view s, int line, std::size_t& used) const
    {
        const char q = s[0];
        std::string out;
        for (std::size_t i = 1; i < s.size(); ++i)
        {
            const char c = s[i];
            if (q == '\'' && c == '\'')
            {
                if (i + 1 < s.size() && s[i + 1] == '\'')
                {
                    out += '\'';
                    ++i;
                    continue;
                }
                used = i + 1;
                return out;
            }
            if (q == '"' && c == '"')
            {
                used = i + 1;
                return out;
            }
            if (q == '"' && c == '\\' && i + 1 < s.size())
            {
                const char e = s[++i];
                out += e == 'n' ? '\n' : e == 't' ? '\t' : e;
                continue;
            }
            out += c;
        }
        failAt(line, "unterminated quoted string");
    }

    /** A scalar value: quoted, or plain up to a " #" comment. */
    std::string scalar(std::string_view s, int line) const
    {
        s = trim(s);
        if (s.empty()) return {};
        if (s[0] == '"' || s[0] == '\'')
        {
            std::size_t used = 0;
            std::string v = quoted(s, line, used);
            const std::string_view tail = trim(s.substr(used));
            if (!tail.empty() && tail[0] != '#')
                failAt(line, "unexpected text after a quoted value");
            return v;
        }
        for (const char c : {'[', ']', '{', '}', '&', '*', '!', '|', '>', '@', '`'})
            if (s[0] == c)
                failAt(line, std::string("unsupported YAML construct starting with '") + c + "'");
        for (std::size_t i = 1; i < s.size(); ++i)
            if (s[i] == '#' && (s[i - 1] == ' ' || s[i - 1] == '\t'))
            {
                s = trim(s.substr(0, i));
                break;
            }
        if (s.find(": ") != std::string_view::npos || s.back() == ':')
            failAt(line, "unexpected ':' in value '" + std::string(s) + "'");
        return std::string(s);
    }

    /** `[a, b, c]` on one line (a trailing comma is allowed, as in YAML). */
    std::vector<std::string> flowSequence(std::string_view s, int line) const
    {
        std::vector<std::string> items;
        std::string cur;
        bool cur_has_item = false;  // a quoted string or a non-blank character since the last ','
        bool closed = false;
        std::size_t i = 1;
        while (i < s.size())
        {
            const char c = s[i];
            if (c == '"' || c == '\'')
            {
                std::size_t used = 0;
                cur += quoted(s.substr(i), line, used);
                cur_has_item = true;
                i += used;
                continue;
            }
            ++i;
            if (c == '[' || c == '{') failAt(line, "nested collections are not supported");
            if (c == ',' || c == ']')
            {
                if (c == ',' && !cur_has_item) failAt(line, "empty list item");
                if (cur_has_item) items.emplace_back(trim(cur));
                cur.clear();
                cur_has_item = false;
                if (c == ']')
                {
                    closed = true;
                    break;
                }
                continue;
            }
            cur += c;
            if (c != ' ' && c != '\t') cur_has_item = true;
        }
        if (!closed) failAt(line, "list without a closing ']'");
        const std::string_view tail = trim(s.substr(i));
        if (!tail.empty() && tail[0] != '#') failAt(line, "unexpected text after ']'");
        return items;
    }

    std::string m_file;
    std::string_view m_text;
};

/** Strict decimal number (YAML's .nan / .inf are parsed so the message can say "finite"). */
std::optional<double> parseNumber(const std::string& s)
{
    const std::string l = toLower(s);
    if (l == ".nan") return std::numeric_limits<double>::quiet_NaN();
    if (l == ".inf" || l == "+.inf") return std::numeric_limits<double>::infinity();
    if (l == "-.inf") return -std::numeric_limits<double>::infinity();
    // [+-] digits [. digits] [e [+-] digits], at least one digit in the mantissa.
    std::size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t digits = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++digits;
    if (i < s.size() && s[i] == '.')
    {
        ++i;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++digits;
    }
    if (digits == 0) return std::nullopt;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E'))
    {
        ++i;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        std::size_t exp_digits = 0;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++exp_digits;
        if (exp_digits == 0) return std::nullopt;
    }
    if (i != s.size()) return std::nullopt;
    // istringstream with the classic locale: a decimal point whatever the user's locale.
    std::istringstream in(s);
    in.imbue(std::locale::classic());
    double v = 0;
    in >> v;
    // Overflow sets failbit and gives +-max: report it as not finite.
    if (in.fail()) return std::numeric_limits<double>::infinity();
    return v;
}

/** Typed access to the keys of one ROS map YAML, with messages naming file, key and value. */
class RosYamlKeys
{
public:
    RosYamlKeys(std::string file, std::map<std::string, YamlValue> values)
        : m_file(std::move(file)), m_values(std::move(values))
    {
    }

    const YamlValue& require(const std::string& key) const
    {
        const auto it = m_values.find(key);
        if (it == m_values.end())
            fail(m_file, "missing key '" + key +
                             "' (a ROS map YAML needs image, resolution, origin, negate, "
                             "occupied_thresh and free_thresh)");
        return it->second;
    }
    bool has(const std::string& key) const { return m_values.count(key) != 0; }

    std::string scalar(const std::string& key) const
    {
        const YamlValue& v = require(key);
        if (v.is_sequence) bad(key, v, "must be a single value, not a list");
        if (v.scalar.empty()) fail(m_file, "key '" + key + "' has no value");
        return v.scalar;
    }

    /** A finite number within [lo, hi] (and > lo when `lo_open`). */
    double number(const std::string& key, double lo, double hi, bool lo_open,
                  const std::string& requirement) const
    {
        const std::string s = scalar(key);
        const std::optional<double> v = parseNumber(s);
        if (!v || !std::isfinite(*v) || *v < lo || (lo_open && *v == lo) || *v > hi)
            bad(key, require(key), requirement);
        return *v;
    }

    [[noreturn]] void bad(const std::string& key, const YamlValue& v,
                          const std::string& requirement) const
    {
        fail(m_file, "key '" + key + "' = " + v.text() + " " + requirement);
    }

private:
    std::string m_file;
    std::map<std::string, YamlValue> m_values;
};

LoadedMap loadRosYaml(const std::string& path, const MapLoadOptions& opts)
{
    // A map description is a few hundred bytes; refuse to slurp a huge file given by mistake.
    constexpr std::uintmax_t kMaxYamlBytes = 1 << 20;
    const std::uintmax_t size = fs::file_size(path);
    if (size > kMaxYamlBytes)
        fail(path, "is too large for a ROS map YAML (" + std::to_string(size) + " bytes)");
    std::ifstream f(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    if (f.bad()) fail(path, "cannot be read");
    if (text.find('\0') != std::string::npos)
        fail(path, "is not a text file (a ROS map YAML was expected)");

    const RosYamlKeys keys(path, RosYamlReader(path, text).read());

    const std::string image = keys.scalar("image");
    const double res = keys.number("resolution", 0.0, std::numeric_limits<double>::max(), true,
                                   "must be a positive number of metres per cell");

    const YamlValue& origin_v = keys.require("origin");
    double origin[3] = {0, 0, 0};
    {
        bool ok = origin_v.is_sequence && origin_v.items.size() == 3;
        for (std::size_t i = 0; ok && i < 3; ++i)
        {
            const std::optional<double> v = parseNumber(origin_v.items[i]);
            ok = v && std::isfinite(*v);
            if (ok) origin[i] = *v;
        }
        if (!ok) keys.bad("origin", origin_v, "must be [x, y, yaw] with 3 finite numbers");
    }
    // MRPT grids are axis-aligned: silently dropping the yaw (as MRPT's own loader does) would
    // turn the whole map about its origin.
    if (std::abs(origin[2]) > 1e-9)
        keys.bad("origin", origin_v,
                 "has a yaw of " + num(origin[2]) +
                     " rad: rotated maps are not supported (MRPT grids are axis-aligned)");

    PixelRule rule;
    {
        const std::string n = toLower(keys.scalar("negate"));
        if (n == "0" || n == "false")
            rule.negate = false;
        else if (n == "1" || n == "true")
            rule.negate = true;
        else
            keys.bad("negate", keys.require("negate"), "must be 0 or 1 (or false / true)");
    }
    rule.occupied_thresh =
        keys.number("occupied_thresh", 0.0, 1.0, false, "must be a number in [0, 1]");
    rule.free_thresh = keys.number("free_thresh", 0.0, 1.0, false, "must be a number in [0, 1]");
    if (!(rule.free_thresh < rule.occupied_thresh))
        fail(path,
             "key 'free_thresh' = " + keys.require("free_thresh").text() +
                 " must be below occupied_thresh = " + keys.require("occupied_thresh").text());
    if (!keys.has("mode")) applyGreyOption(rule, opts, path);
    if (keys.has("mode"))
    {
        const std::string m = toLower(keys.scalar("mode"));
        if (m == "trinary")
            rule.mode = PixelMode::Trinary;
        else if (m == "scale")
            rule.mode = PixelMode::Scale;
        else if (m == "raw")
            rule.mode = PixelMode::Raw;
        else
            keys.bad("mode", keys.require("mode"), "must be trinary, scale or raw");
    }

    // The image path is relative to the YAML's folder (ROS map_server convention).
    fs::path image_path(image);
    if (image_path.is_relative()) image_path = fs::path(path).parent_path() / image_path;
    const std::string image_file = image_path.string();
    std::string prefix = path + ": image '" + image + "'";
    if (image_file != image) prefix += " (" + image_file + ")";
    checkReadableFile(image_file, prefix);
    const internal::ImageHeader hdr = checkedImageHeader(image_file, prefix, opts);

    LoadedMap out;
    out.file = path;
    out.format = "ros_yaml";
    imageToGrid(image_file, hdr, rule, res, origin[0], origin[1], out.grid, prefix);
    return out;
}

// ---------------------------------------------------------------------------------------
// MRPT serialized files
// ---------------------------------------------------------------------------------------

/** Reads through CFileGZInputStream (gzip or plain) but checks what it ignores:
 * - its Read() returns zlib's -1 on corrupt or truncated data as a huge byte count, which
 *   MRPT's deserializers take for success and then parse stale buffer contents: here such a
 *   read throws, and the reason is kept, because MRPT replaces any error inside an object by
 *   a generic "Cannot read object due to EOF";
 * - MRPT accepts a short read as long as it is not empty, so a file cut inside a field leaves
 *   part of that field uninitialised (a garbage scan size then crashes MRPT): here Read()
 *   delivers all the bytes asked for or none. */
class CheckedGzInput : public mrpt::io::CStream
{
public:
    explicit CheckedGzInput(const std::string& path) : m_in(path)
    {
        if (!m_in.fileOpenCorrectly()) fail(path, "cannot be opened");
    }

    /** Up to `count` bytes; fewer only at the end of the file. */
    size_t readSome(void* buffer, size_t count)
    {
        auto* p = static_cast<unsigned char*>(buffer);
        size_t done = 0;
        while (done < count)
        {
            const size_t got = m_in.Read(p + done, count - done);
            if (got == 0)
            {
                m_hit_end = true;
                break;
            }
            if (got > count - done)
            {
                m_error = "corrupt or truncated gzip data";
                throw std::runtime_error(m_error);
            }
            done += got;
        }
        m_position += done;
        return done;
    }

    size_t Read(void* buffer, size_t count) override
    {
        return readSome(buffer, count) == count ? count : 0;
    }
    size_t Write(const void*, size_t) override
    {
        throw std::logic_error("CheckedGzInput is read-only");
    }
    uint64_t Seek(int64_t, TSeekOrigin) override
    {
        throw std::logic_error("CheckedGzInput cannot seek");
    }
    uint64_t getTotalBytesCount() const override { return m_in.getTotalBytesCount(); }
    uint64_t getPosition() const override { return m_position; }

    /** Why the last read failed, if it was the stream (not the data) that failed. */
    const std::string& error() const { return m_error; }
    /** Whether a read asked for bytes past the end of the (decompressed) file. */
    bool hitEnd() const { return m_hit_end; }

private:
    mrpt::io::CFileGZInputStream m_in;
    uint64_t m_position = 0;
    std::string m_error;
    bool m_hit_end = false;
};

/** The start of an MRPT serialized object (CArchive::WriteObject). */
struct ObjectHeader
{
    std::string class_name;  //!< As stored, e.g. "mrpt::maps::COccupancyGridMap2D".
    int version = 0;
};

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

/** Walks the whole serialized grid (internal/serialized_layout.h) before MRPT reads it, so
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

/** Deserializes one object, turning MRPT's errors into a one-line message. */
template <typename T>
void readObject(const std::string& path, T& obj, const std::string& what)
{
    CheckedGzInput in(path);
    try
    {
        mrpt::serialization::archiveFrom(in) >> obj;
    }
    catch (const std::bad_alloc&)
    {
        throw;
    }
    catch (const std::exception& e)
    {
        if (!in.error().empty()) fail(path, in.error());
        if (in.hitEnd()) fail(path, "truncated: the file ends inside its " + what);
        fail(path, "corrupt " + what + " (MRPT: " + oneLine(e) + ")");
    }
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

/** Walks the whole serialized simple map (internal/serialized_layout.h) before MRPT reads
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

// ---------------------------------------------------------------------------------------

enum class MapKind
{
    RosYaml,
    Image,
    Gridmap,
    Simplemap
};

MapKind kindFromName(const std::string& path)
{
    const std::string name = toLower(fs::path(path).filename().string());
    for (const char* s : {".gridmap", ".gridmap.gz"})
        if (endsWith(name, s)) return MapKind::Gridmap;
    for (const char* s : {".simplemap", ".simplemap.gz"})
        if (endsWith(name, s)) return MapKind::Simplemap;
    for (const char* s : {".yaml", ".yml"})
        if (endsWith(name, s)) return MapKind::RosYaml;
    for (const char* s : {".png", ".pgm", ".bmp", ".jpg", ".jpeg"})
        if (endsWith(name, s)) return MapKind::Image;
    fail(path,
         "unknown map format (supported: .yaml, .yml, .png, .pgm, .bmp, .jpg, .jpeg, .gridmap, "
         ".gridmap.gz, .simplemap, .simplemap.gz)");
}

}  // namespace

LoadedMap loadMap(const std::string& path, const MapLoadOptions& opts)
{
    if (path.empty()) throw InputError("(empty file name): no such file");
    try
    {
        checkReadableFile(path, path);
        if (opts.max_cells == 0) fail(path, "option max_cells = 0 must be positive");
        switch (kindFromName(path))
        {
            case MapKind::RosYaml:
                return loadRosYaml(path, opts);
            case MapKind::Image:
                return loadPlainImage(path, opts);
            case MapKind::Gridmap:
                return loadGridmap(path, opts);
            case MapKind::Simplemap:
                return loadSimplemap(path, opts);
        }
        fail(path, "unknown map format");
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
