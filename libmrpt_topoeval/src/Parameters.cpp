/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/errors.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;

namespace mrpt_topoeval
{
namespace
{
const char* const kMapLoadSection = "MapLoad";
const char* const kGraphBuilderSection = "GraphBuilder";
const char* const kSimilaritySection = "VertexSimilarity";
const char* const kMatcherSection = "GraphMatcher";
const char* const kQualitySection = "QualityEvaluator";

// A configuration file is a few kilobytes; anything much larger is the wrong file.
constexpr std::uintmax_t kMaxIniBytes = 1 << 20;

const char* const kIniHeader =
    "# mrpt_topoeval configuration (the defaults, as written by `topoeval config --write`).\n"
    "#\n"
    "# Use it with `topoeval graph MAP --config FILE.ini`. One section per stage of the Topology\n"
    "# Graph method (Schwertfeger & Birk 2013); defaults are the paper's where it gives one.\n"
    "# A key left out keeps its default; an unknown section or key is an error, so typos are\n"
    "# caught. Units are in the key names and comments ([m] metres, [cells], [probability]\n"
    "# in 0..1). Text after // on a line is a comment; lines starting with # or ; too.\n";

// One comment line above each section header of the default INI.
const std::map<std::string, std::string> kSectionComments = {
    {kMapLoadSection,
     "# How map files are read (the command line's --resolution overrides resolution_m)."},
    {kGraphBuilderSection,
     "# Building the Topology Graph from the grid (paper section II-B and II-C)."},
    {kSimilaritySection,
     "# Similarity of two vertices, from attributes or by ICP (paper section III-A)."},
    {kMatcherSection,
     "# Matching two graphs: consistent groups (default) or the paper's isomorphisms (III-B)."},
    {kQualitySection,
     "# Map attributes and scores from the match (paper section IV; doc/quality.md)."},
};

std::string trim(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return s;
}

/** Shortest text that reads back as `v` ("-1", "0.05"), for messages. */
std::string num(double v)
{
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof(buf), v);
    return std::string(buf, r.ptr);
}

/** Strict number: the whole text, finite (MRPT's reader would take "0.3x" as 0.3 and "" as 0). */
bool parseReal(const std::string& text, double& out)
{
    const std::string t = trim(text);
    if (t.empty()) return false;
    char* end = nullptr;
    out = std::strtod(t.c_str(), &end);
    return end == t.c_str() + t.size() && std::isfinite(out);
}

bool isInteger(const std::string& text)
{
    std::string t = trim(text);
    if (!t.empty() && (t[0] == '-' || t[0] == '+')) t.erase(0, 1);
    return !t.empty() &&
           std::all_of(t.begin(), t.end(), [](unsigned char ch) { return std::isdigit(ch) != 0; });
}

/** The spellings MRPT's read_bool() understands the way a user means them. */
bool isBool(const std::string& text)
{
    const std::string t = lower(trim(text));
    return t == "true" || t == "false" || t == "yes" || t == "no" || t == "1" || t == "0";
}

std::size_t editDistance(const std::string& a, const std::string& b)
{
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
            diag = up;
        }
    }
    return row[b.size()];
}

/** " (did you mean 'x'?)" when a known name is close to `given`, else "". */
std::string suggestion(const std::string& given, const std::vector<std::string>& known)
{
    std::size_t best = std::string::npos;
    std::string best_name;
    for (const auto& k : known)
    {
        const std::size_t d = editDistance(lower(given), lower(k));
        if (d < best)
        {
            best = d;
            best_name = k;
        }
    }
    if (best_name.empty() || best > std::max<std::size_t>(2, given.size() / 3)) return {};
    return " (did you mean '" + best_name + "'?)";
}

// ---- [MapLoad] values, read strictly: this section is ours and the reader must not turn
// "0.05m" into 0.05 or "" into 0.

double readRealStrict(const mrpt::config::CConfigFileBase& c, const std::string& s,
                      const std::string& key, double def)
{
    if (!c.keyExists(s, key)) return def;
    const std::string text = trim(c.read_string(s, key, ""));
    double v = 0.0;
    if (!parseReal(text, v))
        throw InputError("[" + s + "] " + key + " = '" + text + "' is not a finite number");
    return v;
}

std::uint64_t readCountStrict(const mrpt::config::CConfigFileBase& c, const std::string& s,
                              const std::string& key, std::uint64_t def)
{
    if (!c.keyExists(s, key)) return def;
    const std::string text = trim(c.read_string(s, key, ""));
    if (!text.empty() && text[0] == '-' && isInteger(text))
        throw InputError("[" + s + "] " + key + " = " + text + " violates " + key + " > 0");
    std::uint64_t v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size())
        throw InputError("[" + s + "] " + key + " = '" + text +
                         "' is not a whole number (up to 2^64-1)");
    return v;
}

// ---- Structure of an INI file, checked before MRPT reads it: MRPT's reader ignores lines
// it does not understand, unknown keys and repeated keys (the last wins), so a typo would
// silently leave a default in place.

enum class ValueKind
{
    Real,
    Integer,
    Bool,
    Text
};

/** Section name -> key -> kind, as the default configuration writes them: the set of keys
 * a file may use is exactly what saveToConfigFile() writes, so it never drifts from the
 * loaders. */
using Schema = std::map<std::string, std::map<std::string, ValueKind>>;

Schema schemaOf(const Parameters& defaults, const std::string& prefix)
{
    mrpt::config::CConfigFileMemory written;
    defaults.saveToConfigFile(written, prefix);
    // Read back from the text: in memory, MRPT keeps the padding of padded writes as part of
    // the key name ("min_clearance_m    "); a parsed file does not.
    const mrpt::config::CConfigFileMemory mem(written.getContent());
    std::vector<std::string> sections;
    mem.getAllSections(sections);
    Schema schema;
    for (const auto& sec : sections)
    {
        std::vector<std::string> keys;
        mem.getAllKeys(sec, keys);
        auto& kinds = schema[sec];
        for (const auto& key : keys)
        {
            const std::string k = trim(key);
            const std::string def = trim(mem.read_string(sec, k, ""));
            double unused = 0.0;
            if (def == "true" || def == "false")
                kinds[k] = ValueKind::Bool;
            else if (isInteger(def))
                kinds[k] = ValueKind::Integer;
            else if (parseReal(def, unused))
                kinds[k] = ValueKind::Real;
            else
                kinds[k] = ValueKind::Text;
        }
    }
    return schema;
}

/** Finds `name` in `m` ignoring case (MRPT matches sections and keys that way). */
template <typename Map>
auto findNoCase(Map& m, const std::string& name)
{
    const std::string l = lower(name);
    for (auto it = m.begin(); it != m.end(); ++it)
        if (lower(it->first) == l) return it;
    return m.end();
}

template <typename Map>
std::vector<std::string> namesOf(const Map& m)
{
    std::vector<std::string> out;
    for (const auto& kv : m) out.push_back(kv.first);
    return out;
}

/** Line-by-line check of sections and keys. \throws InputError "FILE: ..." */
void checkStructure(const std::string& file, const std::string& text, const Schema& schema)
{
    std::istringstream in(text);
    std::string raw;
    int line_no = 0;
    const std::string* section = nullptr;
    // (section, lower-case key) -> first line, to report repeated keys.
    std::map<std::pair<std::string, std::string>, int> seen;
    std::string known_sections;
    for (const auto& kv : schema)
        known_sections += (known_sections.empty() ? "[" : ", [") + kv.first + "]";

    while (std::getline(in, raw))
    {
        ++line_no;
        const std::string line = trim(raw);
        const std::string where = " (line " + std::to_string(line_no) + ")";
        if (line.empty() || line[0] == '#' || line[0] == ';' || line.rfind("//", 0) == 0) continue;
        if (line[0] == '[')
        {
            if (line.back() != ']')
                throw InputError(file + ": malformed section header '" + line + "'" + where);
            const std::string name = trim(line.substr(1, line.size() - 2));
            const auto it = findNoCase(schema, name);
            if (it == schema.end())
                throw InputError(file + ": unknown section [" + name + "]" + where +
                                 suggestion(name, namesOf(schema)) +
                                 "; known sections: " + known_sections);
            section = &it->first;
            continue;
        }
        const auto eq = line.find('=');
        if (eq == std::string::npos)
            throw InputError(file + ": expected '[Section]' or 'key = value', got '" + line + "'" +
                             where);
        const std::string key = trim(line.substr(0, eq));
        if (key.empty()) throw InputError(file + ": missing key name in '" + line + "'" + where);
        if (!section)
            throw InputError(file + ": key '" + key + "' outside any section" + where +
                             "; known sections: " + known_sections);
        const auto& keys = schema.at(*section);
        if (findNoCase(keys, key) == keys.end())
            throw InputError(file + ": [" + *section + "] unknown key '" + key + "'" + where +
                             suggestion(key, namesOf(keys)));
        const auto [it, inserted] = seen.emplace(std::make_pair(*section, lower(key)), line_no);
        if (!inserted)
            throw InputError(file + ": [" + *section + "] key '" + key + "' given twice (lines " +
                             std::to_string(it->second) + " and " + std::to_string(line_no) + ")");
    }
}

/** Every value present has the type its default has. \throws InputError "FILE: ..." */
void checkValues(const std::string& file, const mrpt::config::CConfigFileBase& cfg,
                 const Schema& schema)
{
    for (const auto& [sec, keys] : schema)
        for (const auto& [key, kind] : keys)
        {
            if (!cfg.keyExists(sec, key)) continue;
            const std::string v = trim(cfg.read_string(sec, key, ""));
            const std::string what = file + ": [" + sec + "] " + key + " = '" + v + "' ";
            double unused = 0.0;
            switch (kind)
            {
                case ValueKind::Real:
                    if (!parseReal(v, unused)) throw InputError(what + "is not a finite number");
                    break;
                case ValueKind::Integer:
                    if (!isInteger(v)) throw InputError(what + "is not a whole number");
                    break;
                case ValueKind::Bool:
                    if (!isBool(v)) throw InputError(what + "is not true or false");
                    break;
                case ValueKind::Text:
                    break;
            }
        }
}

/** Prefixes "[Section] " to a stage's own validation message unless it names one already. */
std::string inSection(const std::string& section, const std::string& msg)
{
    if (!msg.empty() && msg[0] == '[') return msg;
    return "[" + section + "] " + msg;
}

std::string firstLine(const std::string& s) { return s.substr(0, s.find('\n')); }
}  // namespace

// `s` prefixes every section name (empty: [MapLoad], [GraphBuilder]), so several complete
// configurations can share one file.
void Parameters::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
    const std::string ml = s + kMapLoadSection;
    map_load.resolution_m = readRealStrict(c, ml, "resolution_m", map_load.resolution_m);
    map_load.occupied_thresh = readRealStrict(c, ml, "occupied_thresh", map_load.occupied_thresh);
    map_load.free_thresh = readRealStrict(c, ml, "free_thresh", map_load.free_thresh);
    map_load.max_cells = readCountStrict(c, ml, "max_cells", map_load.max_cells);
    if (c.keyExists(ml, "grey_between_thresholds"))
        map_load.grey_between_thresholds = trim(c.read_string(ml, "grey_between_thresholds", ""));

    graph.loadFromConfigFile(c, s + kGraphBuilderSection);
    similarity.loadFromConfigFile(c, s + kSimilaritySection);
    matcher.loadFromConfigFile(c, s + kMatcherSection);
    quality.loadFromConfigFile(c, s + kQualitySection);
}

void Parameters::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
    // MRPT_SAVE_CONFIG_VAR_COMMENT would name the keys "map_load.resolution_m": write them
    // with the same padding under their plain names.
    const std::string ml = s + kMapLoadSection;
    const int np = mrpt::config::MRPT_SAVE_NAME_PADDING();
    const int vp = mrpt::config::MRPT_SAVE_VALUE_PADDING();
    c.write(ml, "resolution_m", map_load.resolution_m, np, vp,
            "[m/cell] cell size of plain images and of rendered .simplemap files");
    c.write(ml, "occupied_thresh", map_load.occupied_thresh, np, vp,
            "[probability] plain images: a pixel is occupied if (255-grey)/255 > this");
    c.write(ml, "free_thresh", map_load.free_thresh, np, vp,
            "[probability] plain images: a pixel is free if (255-grey)/255 < this");
    c.write(ml, "grey_between_thresholds", map_load.grey_between_thresholds, np, vp,
            "[auto|unknown|probability] images without a ROS mode: pixels between the "
            "thresholds are unknown, or keep their probability (auto: when >4 such greys)");
    c.write(ml, "max_cells", map_load.max_cells, np, vp,
            "[cells] largest map accepted (width x height), checked before decoding");

    graph.saveToConfigFile(c, s + kGraphBuilderSection);
    similarity.saveToConfigFile(c, s + kSimilaritySection);
    matcher.saveToConfigFile(c, s + kMatcherSection);
    quality.saveToConfigFile(c, s + kQualitySection);
}

void Parameters::validate() const
{
    const std::string sec = std::string("[") + kMapLoadSection + "] ";
    const MapLoadOptions& m = map_load;
    if (!(std::isfinite(m.resolution_m) && m.resolution_m > 0.0))
        throw InputError(sec + "resolution_m = " + num(m.resolution_m) +
                         " violates resolution_m > 0");
    if (!(m.occupied_thresh >= 0.0 && m.occupied_thresh <= 1.0))
        throw InputError(sec + "occupied_thresh = " + num(m.occupied_thresh) +
                         " violates 0 <= occupied_thresh <= 1");
    if (!(m.free_thresh >= 0.0 && m.free_thresh <= 1.0))
        throw InputError(sec + "free_thresh = " + num(m.free_thresh) +
                         " violates 0 <= free_thresh <= 1");
    // Equal thresholds would leave no unknown band, larger free would make cells both.
    if (!(m.free_thresh < m.occupied_thresh))
        throw InputError(sec + "free_thresh = " + num(m.free_thresh) +
                         " violates free_thresh < occupied_thresh (" + num(m.occupied_thresh) +
                         ")");
    if (m.max_cells == 0) throw InputError(sec + "max_cells = 0 violates max_cells > 0");
    if (m.grey_between_thresholds != "auto" && m.grey_between_thresholds != "unknown" &&
        m.grey_between_thresholds != "probability")
        throw InputError(sec + "grey_between_thresholds = '" + m.grey_between_thresholds +
                         "' violates grey_between_thresholds in {auto, unknown, probability}");

    auto validateSection = [](const char* section, auto& part)
    {
        try
        {
            part.validate();
        }
        catch (const InputError& e)
        {
            throw InputError(inSection(section, e.what()));
        }
    };
    validateSection(kGraphBuilderSection, graph);
    validateSection(kSimilaritySection, similarity);
    validateSection(kMatcherSection, matcher);
    validateSection(kQualitySection, quality);
}

Parameters Parameters::fromIniFile(const std::string& path)
{
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (!fs::exists(st)) throw InputError(path + ": no such file");
    if (fs::is_directory(st)) throw InputError(path + ": is a folder, not an INI file");
    if (!fs::is_regular_file(st)) throw InputError(path + ": not a regular file");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (!ec && size > kMaxIniBytes)
        throw InputError(path + ": " + std::to_string(size) +
                         " bytes is too large for a configuration file");

    // Read the text ourselves and parse it from memory: CConfigFile would silently start
    // empty on an unreadable file, and writes the file back if it is ever modified.
    std::ifstream f(path, std::ios::binary);
    if (!f) throw InputError(path + ": cannot open for reading");
    std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    if (f.bad()) throw InputError(path + ": read error");
    return fromIniText(text, path);
}

Parameters Parameters::fromIniText(std::string text, const std::string& source)
{
    if (text.find('\0') != std::string::npos)
        throw InputError(source + ": not a text file (contains NUL bytes)");
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // BOM left by some editors

    Parameters p;
    const Schema schema = schemaOf(p, "");
    checkStructure(source, text, schema);

    const mrpt::config::CConfigFileMemory cfg(text);
    checkValues(source, cfg, schema);
    try
    {
        p.loadFromConfigFile(cfg, "");
        p.validate();
    }
    catch (const InputError& e)
    {
        throw InputError(source + ": " + e.what());
    }
    catch (const std::exception& e)
    {
        throw InputError(source + ": " + firstLine(e.what()));
    }
    return p;
}

std::string Parameters::defaultIniText()
{
    mrpt::config::CConfigFileMemory mem;
    Parameters().saveToConfigFile(mem, "");

    // MRPT's text, with trailing blanks removed, single blank lines between sections and a
    // comment above each section.
    std::ostringstream out;
    out << kIniHeader;
    std::istringstream in(mem.getContent());
    std::string line;
    while (std::getline(in, line))
    {
        line.erase(line.find_last_not_of(" \t\r") + 1);
        if (line.empty()) continue;
        if (line.front() == '[' && line.back() == ']')
        {
            out << "\n";
            const auto it = kSectionComments.find(line.substr(1, line.size() - 2));
            if (it != kSectionComments.end()) out << it->second << "\n";
        }
        out << line << "\n";
    }
    return out.str();
}

}  // namespace mrpt_topoeval
