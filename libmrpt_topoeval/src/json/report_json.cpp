/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt_topoeval/json/JsonWriter.h>
#include <mrpt_topoeval/report_json.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "json/match_json_internal.h"

namespace mrpt_topoeval
{
namespace
{

// Fixed precisions, so equal reports give equal bytes: 0.1 mm for distances (as the graph's
// JSON), 1e-6 m^2 for squared errors (the threshold is tenths of m^2), 1e-4 for scores in
// [0, 1] (as similarities), 0.001 deg (and 0.001 ms: writeTiming).
using internal::kDegreeDecimals;
using internal::kMetreDecimals;
constexpr int kSquareMetreDecimals = 6;
constexpr int kScoreDecimals = internal::kSimilarityDecimals;
// A map's scale: 1e-5, a tenth of a millimetre over 10 m.
constexpr int kScaleDecimals = 5;

std::uint64_t u64(std::size_t n) { return static_cast<std::uint64_t>(n); }

std::string trim(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

/** A quantity that is only defined when there were pairs to measure it on. */
void valueIfDefined(JsonWriter& w, bool defined, double v, int decimals)
{
    if (defined)
        w.value(v, decimals);
    else
        w.null();
}

void writeAccuracy(JsonWriter& w, const Accuracy& a, bool with_transform)
{
    const bool defined = a.pairs > 0;
    w.beginObject();
    w.key("pairs").value(u64(a.pairs));
    valueIfDefined(w.key("rmse_m"), defined, a.rmse_m, kMetreDecimals);
    w.key("score").value(a.score, kScoreDecimals);
    if (with_transform)
    {
        w.key("pairs_by_walls").value(u64(a.by_walls));
        // T_gt_map: map coordinates into the ground truth's frame.
        w.key("transform").beginObject();
        valueIfDefined(w.key("x"), defined, a.transform.x_m, kMetreDecimals);
        valueIfDefined(w.key("y"), defined, a.transform.y_m, kMetreDecimals);
        valueIfDefined(w.key("yaw_deg"), defined, a.transform.yaw_deg, kDegreeDecimals);
        w.endObject();
    }
    w.endObject();
}

void writeConsistency(JsonWriter& w, const std::vector<ConsistencyClass>& classes)
{
    w.beginArray();
    for (const ConsistencyClass& c : classes)
    {
        w.beginObject();
        w.key("class").value(c.name);
        // [min, max) of the ground-truth graph distance; the long class has no upper bound
        // (infinity, written as null).
        w.key("min_graph_distance_m").value(c.min_graph_distance_m, kMetreDecimals);
        w.key("max_graph_distance_m").value(c.max_graph_distance_m, kMetreDecimals);
        w.key("pairs").value(u64(c.pairs));
        valueIfDefined(w.key("mean_error_m"), c.pairs > 0, c.mean_error_m, kMetreDecimals);
        w.key("score").value(c.score, kScoreDecimals);
        w.endObject();
    }
    w.endArray();
}

void writeBrokenness(JsonWriter& w, const Brokenness& b)
{
    w.beginObject();
    w.key("degree").value(b.degree);
    w.key("score").value(b.score, kScoreDecimals);
    w.key("groups").beginArray();
    for (const BrokennessGroup& g : b.groups)
    {
        w.beginObject();
        w.key("vertices").value(u64(g.gt_vertices.size()));
        w.key("ground_truth_ids").beginArray(true);
        for (const int id : g.gt_vertices) w.value(id);
        w.endArray();
        w.key("squared_error_m2").value(g.squared_error_m2, kSquareMetreDecimals);
        // The group's T_gt_map (paper Table III lists its angle).
        w.key("yaw_deg").value(g.transform.yaw_deg, kDegreeDecimals);
        w.key("x").value(g.transform.x_m, kMetreDecimals);
        w.key("y").value(g.transform.y_m, kMetreDecimals);
        w.key("offset_m").value(g.offset_m, kMetreDecimals);
        // A part placed by its walls (wall_parts): its map vertices, pair by pair.
        w.key("by_walls").value(g.by_walls);
        if (g.by_walls)
        {
            w.key("map_ids").beginArray(true);
            for (const int id : g.map_vertices) w.value(id);
            w.endArray();
        }
        w.endObject();
    }
    w.endArray();
    w.endObject();
}

void writeExplainedWalls(JsonWriter& w, const ExplainedWalls& e)
{
    w.beginObject();
    w.key("measured").value(e.measured);
    w.key("share").value(e.share, kScoreDecimals);
    w.key("wall_points").value(u64(e.wall_points));
    w.key("explained").value(u64(e.explained));
    w.key("tolerance_m").value(e.tolerance_m, kMetreDecimals);
    w.endObject();
}

// ---------------------------------------------------------------- effective parameters

/** One section of the configuration: its keys and their values as the INI text has them. */
struct IniSection
{
    std::string name;
    std::vector<std::pair<std::string, std::string>> keys;  // (key, value text)
};

/** Every section and key `p.saveToConfigFile()` writes, in the order it writes them. Taken
 * from what the parameters write rather than from their fields, so a key added to a stage
 * appears here without a change. */
std::vector<IniSection> configurationOf(const Parameters& p)
{
    mrpt::config::CConfigFileMemory written;
    p.saveToConfigFile(written, "");
    const std::string text = written.getContent();
    // Read back from the text: in memory MRPT keeps the padding of padded writes as part of
    // the key names; a parsed text does not, and its reader drops the "// comment" tails.
    const mrpt::config::CConfigFileMemory mem(text);

    // MRPT lists sections and keys alphabetically; the text has them in the order written
    // (pipeline order, as in `topoeval config`), which reads better: rank by that.
    std::map<std::string, std::size_t> section_pos;
    std::map<std::pair<std::string, std::string>, std::size_t> key_pos;
    {
        std::istringstream lines(text);
        std::string line, section;
        for (std::size_t n = 0; std::getline(lines, line); ++n)
        {
            const std::string t = trim(line);
            if (t.size() >= 2 && t.front() == '[' && t.back() == ']')
            {
                section = t.substr(1, t.size() - 2);
                section_pos.emplace(section, n);
            }
            else if (const auto eq = t.find('='); eq != std::string::npos && !section.empty())
                key_pos.emplace(std::make_pair(section, trim(t.substr(0, eq))), n);
        }
    }
    const auto rank = [](const auto& positions, const auto& k)
    {
        const auto it = positions.find(k);
        return it == positions.end() ? std::numeric_limits<std::size_t>::max() : it->second;
    };

    std::vector<std::string> sections;
    mem.getAllSections(sections);
    std::stable_sort(sections.begin(), sections.end(),
                     [&](const std::string& a, const std::string& b)
                     { return rank(section_pos, a) < rank(section_pos, b); });
    std::vector<IniSection> out;
    for (const std::string& sec : sections)
    {
        std::vector<std::string> keys;
        mem.getAllKeys(sec, keys);
        for (auto& k : keys) k = trim(k);
        std::stable_sort(keys.begin(), keys.end(),
                         [&](const std::string& a, const std::string& b) {
                             return rank(key_pos, std::make_pair(sec, a)) <
                                    rank(key_pos, std::make_pair(sec, b));
                         });
        IniSection s{sec, {}};
        for (const std::string& k : keys) s.keys.emplace_back(k, trim(mem.read_string(sec, k, "")));
        out.push_back(std::move(s));
    }
    return out;
}

bool isInteger(const std::string& t)
{
    const std::size_t start = !t.empty() && (t[0] == '-' || t[0] == '+') ? 1 : 0;
    return t.size() > start && std::all_of(t.begin() + static_cast<std::ptrdiff_t>(start), t.end(),
                                           [](unsigned char ch) { return std::isdigit(ch) != 0; });
}

/** A value of the INI text as the JSON type it stands for: booleans, integers, reals, else a
 * string (enumerations such as `mode = icp`). */
void writeIniValue(JsonWriter& w, const std::string& text)
{
    if (text == "true" || text == "false")
    {
        w.value(text == "true");
        return;
    }
    if (isInteger(text))
    {
        errno = 0;
        if (text[0] == '-')
        {
            const long long v = std::strtoll(text.c_str(), nullptr, 10);
            if (errno == 0)
            {
                w.value(static_cast<std::int64_t>(v));
                return;
            }
        }
        else
        {
            const unsigned long long v = std::strtoull(text.c_str(), nullptr, 10);
            if (errno == 0)
            {
                w.value(static_cast<std::uint64_t>(v));
                return;
            }
        }
    }
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (!text.empty() && end == text.c_str() + text.size() && std::isfinite(v))
    {
        // MRPT writes reals with 6 decimals ("%f"), or 7 significant digits ("%e") when tiny
        // or huge: keep 6 significant decimals below 1 so 1e-07 does not become 0.
        const int decimals =
            v == 0.0 ? 6
                     : std::clamp(6 - static_cast<int>(std::floor(std::log10(std::abs(v)))), 6, 17);
        w.value(v, decimals);
        return;
    }
    w.value(text);
}

void writeParameters(JsonWriter& w, const Parameters& p)
{
    w.beginObject();
    for (const IniSection& s : configurationOf(p))
    {
        w.key(s.name).beginObject();
        for (const auto& [k, text] : s.keys) writeIniValue(w.key(k), text);
        w.endObject();
    }
    w.endObject();
}
}  // namespace

std::string reportToJson(const TopologyGraph& ground_truth, const TopologyGraph& map,
                         const QualityReport& r, const Parameters& effective, bool with_timing)
{
    JsonWriter w;
    w.beginObject();
    w.key("ground_truth");
    internal::writeMatchedGraph(w, ground_truth, &r.gt_vertices);
    w.key("map");
    internal::writeMatchedGraph(w, map, &r.map_vertices);
    // The same writer as `topoeval match --json`: the two formats cannot drift apart.
    w.key("matches");
    internal::writeMatches(w, r.match);
    w.key("coverage").value(r.coverage, kScoreDecimals);
    w.key("global_accuracy");
    writeAccuracy(w, r.global_accuracy, false);
    w.key("relative_accuracy");
    writeAccuracy(w, r.relative_accuracy, true);
    w.key("local_consistency");
    writeConsistency(w, r.local_consistency);
    w.key("brokenness");
    writeBrokenness(w, r.brokenness);
    w.key("explained_walls");
    writeExplainedWalls(w, r.explained_walls);
    w.key("quality").value(r.quality, kScoreDecimals);
    w.key("map_scale").value(r.map_scale, kScaleDecimals);
    w.key("messages").beginArray();
    for (const std::string& m : r.messages) w.value(m);
    w.endArray();
    w.key("parameters");
    writeParameters(w, effective);
    if (with_timing) writeTiming(w, r.timing_ms);
    w.endObject();
    return w.str();
}

}  // namespace mrpt_topoeval
