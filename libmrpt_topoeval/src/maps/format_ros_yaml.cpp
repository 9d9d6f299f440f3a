/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// ROS map_server YAML map descriptions (.yaml .yml) and the image they name.
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

    rule.map_saver_unknown_grey = opts.trinary_unknown_grey;

    LoadedMap out;
    out.file = path;
    out.format = "ros_yaml";
    out.notes = imageToGrid(image_file, hdr, rule, res, origin[0], origin[1], out.grid, prefix);
    return out;
}

}  // namespace mrpt_topoeval::map_formats
