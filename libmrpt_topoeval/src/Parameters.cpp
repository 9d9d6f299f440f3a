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

#include "common/parameter_table.h"

namespace fs = std::filesystem;

namespace mrpt_topoeval
{
namespace
{
using internal::isBool;
using internal::isInteger;
using internal::lower;
using internal::parseReal;
using internal::trim;

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
    {MapLoadOptions::kIniSection,
     "# How map files are read (the command line's --resolution overrides resolution_m)."},
    {GraphBuilderParameters::kIniSection,
     "# Building the Topology Graph from the grid (paper section II-B and II-C)."},
    {VertexSimilarityParameters::kIniSection,
     "# Similarity of two vertices, from attributes or by ICP (paper section III-A)."},
    {GraphMatcherParameters::kIniSection,
     "# Matching two graphs: consistent groups (default) or the paper's isomorphisms (III-B)."},
    {QualityParameters::kIniSection,
     "# Map attributes and scores from the match (paper section IV; doc/quality.md)."},
};

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

std::string firstLine(const std::string& s) { return s.substr(0, s.find('\n')); }
}  // namespace

// `s` prefixes every section name (empty: [MapLoad], [GraphBuilder]), so several complete
// configurations can share one file. Each part's keys are listed once, in its table
// (common/parameter_table.h).
void Parameters::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
    map_load.loadFromConfigFile(c, s + map_load.kIniSection);
    graph.loadFromConfigFile(c, s + graph.kIniSection);
    similarity.loadFromConfigFile(c, s + similarity.kIniSection);
    matcher.loadFromConfigFile(c, s + matcher.kIniSection);
    quality.loadFromConfigFile(c, s + quality.kIniSection);
}

void Parameters::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
    map_load.saveToConfigFile(c, s + map_load.kIniSection);
    graph.saveToConfigFile(c, s + graph.kIniSection);
    similarity.saveToConfigFile(c, s + similarity.kIniSection);
    matcher.saveToConfigFile(c, s + matcher.kIniSection);
    quality.saveToConfigFile(c, s + quality.kIniSection);
}

// Every part's message names its section: "[GraphBuilder] min_clearance_m = -1 violates ...".
void Parameters::validate() const
{
    map_load.validate();
    graph.validate();
    similarity.validate();
    matcher.validate();
    quality.validate();
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
