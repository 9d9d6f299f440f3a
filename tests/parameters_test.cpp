/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Parameters: the paper's defaults, INI round trip, typo and bad-value detection, and the
// shipped default INI never going stale.

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/errors.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "test_paths.h"

namespace fs = std::filesystem;
using mrpt_topoeval::InputError;
using mrpt_topoeval::Parameters;

namespace
{
using mrpt_topoeval::testing::contains;
using mrpt_topoeval::testing::readText;
using mrpt_topoeval::testing::ScopedTempDir;

std::string writeText(const std::string& dir, const std::string& name, const std::string& text)
{
    const std::string path = (fs::path(dir) / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

/** The InputError message fromIniFile() gives for `text`, or "" if it loads. */
std::string iniError(const std::string& text)
{
    const ScopedTempDir dir_tmp("params");
    const std::string& dir = dir_tmp.path;
    const std::string path = writeText(dir, "bad.ini", text);
    try
    {
        Parameters::fromIniFile(path);
    }
    catch (const InputError& e)
    {
        const std::string msg = e.what();
        // Every message names the file first and fits on one line.
        EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
        return msg;
    }
    return "";
}
}  // namespace

TEST(Parameters, DefaultsAreThePapers)
{
    const Parameters p;
    EXPECT_DOUBLE_EQ(p.graph.min_clearance_m, 0.30);  // paper Fig. 2: 30 cm
    EXPECT_DOUBLE_EQ(p.graph.alpha_radius_m, 2.50);   // paper Fig. 3: alpha 2.5 m
    EXPECT_DOUBLE_EQ(p.map_load.resolution_m, 0.05);
    EXPECT_DOUBLE_EQ(p.map_load.occupied_thresh, 0.65);  // ROS map_server defaults
    EXPECT_DOUBLE_EQ(p.map_load.free_thresh, 0.196);
    EXPECT_NO_THROW(p.validate());
}

TEST(Parameters, DefaultIniTextLoadsBackToTheDefaults)
{
    const ScopedTempDir dir_tmp("params");
    const std::string& dir = dir_tmp.path;
    const std::string text = Parameters::defaultIniText();
    const Parameters p = Parameters::fromIniFile(writeText(dir, "default.ini", text));
    const Parameters d;
    EXPECT_EQ(p.map_load.resolution_m, d.map_load.resolution_m);
    EXPECT_EQ(p.map_load.max_cells, d.map_load.max_cells);
    EXPECT_EQ(p.graph.min_clearance_m, d.graph.min_clearance_m);
    EXPECT_EQ(p.graph.alpha_radius_m, d.graph.alpha_radius_m);
    EXPECT_EQ(p.graph.skeleton_on_free_cells_only, d.graph.skeleton_on_free_cells_only);

    // Both sections, and every key line documented with a unit and a meaning.
    EXPECT_TRUE(contains(text, "[MapLoad]"));
    EXPECT_TRUE(contains(text, "[GraphBuilder]"));
    std::istringstream in(text);
    std::string line;
    int keys = 0;
    while (std::getline(in, line))
    {
        if (line.empty() || line[0] == '#' || line[0] == '[') continue;
        ++keys;
        const auto comment = line.find("// [");
        ASSERT_NE(comment, std::string::npos) << "no '// [unit] meaning' comment: " << line;
        EXPECT_GT(line.size(), comment + 12) << "comment too short: " << line;
    }
    EXPECT_GE(keys, 13);
}

TEST(Parameters, ShippedIniEqualsDefaultIniText)
{
    const std::string shipped = mrpt_topoeval::testing::shareDir() + "/topoeval.ini";
    ASSERT_TRUE(fs::exists(shipped)) << shipped;
    EXPECT_EQ(readText(shipped), Parameters::defaultIniText())
        << "share/mrpt_topoeval/topoeval.ini is stale: regenerate it with "
           "`topoeval config --write share/mrpt_topoeval/topoeval.ini --force`";
}

TEST(Parameters, IniRoundTrip)
{
    Parameters p;
    p.map_load.resolution_m = 0.1;
    p.map_load.occupied_thresh = 0.7;
    p.map_load.free_thresh = 0.25;
    p.map_load.max_cells = 123456789;
    p.graph.min_clearance_m = 0.45;
    p.graph.alpha_radius_m = 3.25;
    p.graph.join_distance_m = 0.8;
    p.graph.skeleton_on_free_cells_only = false;

    mrpt::config::CConfigFileMemory mem;
    p.saveToConfigFile(mem);
    const ScopedTempDir dir_tmp("params");
    const std::string& dir = dir_tmp.path;
    const Parameters q = Parameters::fromIniFile(writeText(dir, "rt.ini", mem.getContent()));
    EXPECT_DOUBLE_EQ(q.map_load.resolution_m, 0.1);
    EXPECT_DOUBLE_EQ(q.map_load.occupied_thresh, 0.7);
    EXPECT_DOUBLE_EQ(q.map_load.free_thresh, 0.25);
    EXPECT_EQ(q.map_load.max_cells, 123456789u);
    EXPECT_DOUBLE_EQ(q.graph.min_clearance_m, 0.45);
    EXPECT_DOUBLE_EQ(q.graph.alpha_radius_m, 3.25);
    EXPECT_DOUBLE_EQ(q.graph.join_distance_m, 0.8);
    EXPECT_FALSE(q.graph.skeleton_on_free_cells_only);
}

TEST(Parameters, MissingKeysKeepDefaultsAndCommentsAreIgnored)
{
    const ScopedTempDir dir_tmp("params");
    const std::string& dir = dir_tmp.path;
    const std::string path = writeText(dir, "partial.ini",
                                       "# a comment\n"
                                       "; another\n"
                                       "// and another\n"
                                       "\n"
                                       "[GraphBuilder]\r\n"  // Windows line ends are fine
                                       "  min_clearance_m = 0.4   // wider robot\n"
                                       "skeleton_on_free_cells_only = no\n");
    const Parameters p = Parameters::fromIniFile(path);
    EXPECT_DOUBLE_EQ(p.graph.min_clearance_m, 0.4);
    EXPECT_FALSE(p.graph.skeleton_on_free_cells_only);
    EXPECT_DOUBLE_EQ(p.graph.alpha_radius_m, 2.5);
    EXPECT_DOUBLE_EQ(p.map_load.resolution_m, 0.05);
}

TEST(Parameters, SectionAndKeyNamesIgnoreCaseLikeMrpt)
{
    const ScopedTempDir dir_tmp("params");
    const std::string& dir = dir_tmp.path;
    const Parameters p = Parameters::fromIniFile(
        writeText(dir, "case.ini", "[graphbuilder]\nMIN_CLEARANCE_M = 0.35\n"));
    EXPECT_DOUBLE_EQ(p.graph.min_clearance_m, 0.35);
}

TEST(Parameters, UnknownKeyIsAnErrorWithASuggestion)
{
    const std::string msg = iniError("[GraphBuilder]\nmin_clearence_m = 0.3\n");
    EXPECT_TRUE(contains(msg, ": [GraphBuilder] unknown key 'min_clearence_m'")) << msg;
    EXPECT_TRUE(contains(msg, "line 2")) << msg;
    EXPECT_TRUE(contains(msg, "did you mean 'min_clearance_m'")) << msg;
}

TEST(Parameters, UnknownSectionIsAnError)
{
    const std::string msg = iniError("[GraphBulider]\nmin_clearance_m = 0.3\n");
    EXPECT_TRUE(contains(msg, "unknown section [GraphBulider]")) << msg;
    EXPECT_TRUE(contains(msg, "did you mean 'GraphBuilder'")) << msg;
}

TEST(Parameters, StructuralMistakesAreErrors)
{
    EXPECT_TRUE(contains(iniError("min_clearance_m = 0.3\n"), "outside any section"));
    EXPECT_TRUE(contains(iniError("[GraphBuilder]\nmin_clearance_m 0.3\n"),
                         "expected '[Section]' or 'key = value'"));
    EXPECT_TRUE(contains(iniError("[GraphBuilder\n"), "malformed section header"));
    const std::string dup = iniError(
        "[GraphBuilder]\nmin_clearance_m = 0.3\n[MapLoad]\n[GraphBuilder]\n"
        "min_clearance_m = 0.5\n");
    EXPECT_TRUE(contains(dup, "key 'min_clearance_m' given twice (lines 2 and 5)")) << dup;
}

TEST(Parameters, OutOfRangeValuesNameSectionKeyAndValue)
{
    std::string msg = iniError("[GraphBuilder]\nmin_clearance_m = -1\n");
    EXPECT_TRUE(contains(msg, "[GraphBuilder] min_clearance_m = -1 violates min_clearance_m > 0"))
        << msg;
    msg = iniError("[MapLoad]\nresolution_m = -1\n");
    EXPECT_TRUE(contains(msg, "[MapLoad] resolution_m = -1 violates resolution_m > 0")) << msg;
    msg = iniError("[MapLoad]\nfree_thresh = 0.8\n");
    EXPECT_TRUE(contains(msg, "free_thresh = 0.8 violates free_thresh < occupied_thresh")) << msg;
    msg = iniError("[MapLoad]\nmax_cells = 0\n");
    EXPECT_TRUE(contains(msg, "max_cells = 0 violates max_cells > 0")) << msg;
    msg = iniError("[MapLoad]\nmax_cells = -5\n");
    EXPECT_TRUE(contains(msg, "max_cells = -5 violates max_cells > 0")) << msg;
}

TEST(Parameters, MalformedValuesNameKeyAndValue)
{
    // MRPT's own reader would take "0.3x" as 0.3, "" as 0 and "maybe" as false.
    std::string msg = iniError("[GraphBuilder]\nmin_clearance_m = 0.3x\n");
    EXPECT_TRUE(contains(msg, "[GraphBuilder] min_clearance_m = '0.3x' is not a finite number"))
        << msg;
    msg = iniError("[GraphBuilder]\nalpha_radius_m =\n");
    EXPECT_TRUE(contains(msg, "alpha_radius_m = '' is not a finite number")) << msg;
    msg = iniError("[GraphBuilder]\nalpha_radius_m = nan\n");
    EXPECT_TRUE(contains(msg, "alpha_radius_m = 'nan' is not a finite number")) << msg;
    msg = iniError("[GraphBuilder]\nskeleton_on_free_cells_only = maybe\n");
    EXPECT_TRUE(contains(msg, "skeleton_on_free_cells_only = 'maybe' is not true or false")) << msg;
    msg = iniError("[MapLoad]\nresolution_m = 0.05 # metres\n");
    EXPECT_TRUE(contains(msg, "resolution_m = '0.05 # metres' is not a finite number")) << msg;
    msg = iniError("[MapLoad]\nmax_cells = 1e6\n");
    EXPECT_TRUE(contains(msg, "max_cells = '1e6' is not a whole number")) << msg;
}

TEST(Parameters, NonTextFilesAreRejected)
{
    const std::string msg = iniError(std::string("[MapLoad]\0\x01\x02", 12));
    EXPECT_TRUE(contains(msg, "not a text file")) << msg;
}

TEST(Parameters, MissingFileOrFolderNamesThePath)
{
    const ScopedTempDir dir_tmp("params");
    const std::string& dir = dir_tmp.path;
    const std::string missing = dir + "/nope.ini";
    try
    {
        Parameters::fromIniFile(missing);
        FAIL() << "no error for a missing file";
    }
    catch (const InputError& e)
    {
        EXPECT_EQ(std::string(e.what()), missing + ": no such file");
    }
    try
    {
        Parameters::fromIniFile(dir);
        FAIL() << "no error for a folder";
    }
    catch (const InputError& e)
    {
        EXPECT_EQ(std::string(e.what()), dir + ": is a folder, not an INI file");
    }
}

TEST(Parameters, ReadingNeverModifiesTheFile)
{
    const ScopedTempDir dir_tmp("params");
    const std::string& dir = dir_tmp.path;
    const std::string text = "[GraphBuilder]\nmin_clearance_m=0.4\n";
    const std::string path = writeText(dir, "keep.ini", text);
    const auto before = fs::last_write_time(path);
    Parameters::fromIniFile(path);
    EXPECT_EQ(readText(path), text);
    EXPECT_EQ(fs::last_write_time(path), before);
}

TEST(Parameters, ValidateMessages)
{
    Parameters p;
    p.map_load.resolution_m = -1;
    try
    {
        p.validate();
        FAIL() << "no error";
    }
    catch (const InputError& e)
    {
        EXPECT_EQ(std::string(e.what()), "[MapLoad] resolution_m = -1 violates resolution_m > 0");
    }
    p = Parameters();
    p.graph.min_clearance_m = 0.0;
    try
    {
        p.validate();
        FAIL() << "no error";
    }
    catch (const InputError& e)
    {
        EXPECT_EQ(std::string(e.what()),
                  "[GraphBuilder] min_clearance_m = 0 violates min_clearance_m > 0");
    }
}

namespace
{
/** One key of the default INI: its section, name, value text and unit ("[m]" -> "m"). */
struct IniKey
{
    std::string section, key, value, unit;
};

std::string trimmed(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

/** Every key saveToConfigFile() writes, read from its text (so a key added to any table is
 * covered without a change here). */
std::vector<IniKey> keysOf(const Parameters& p)
{
    mrpt::config::CConfigFileMemory mem;
    p.saveToConfigFile(mem);
    std::istringstream in(mem.getContent());
    std::vector<IniKey> out;
    std::string line, section;
    while (std::getline(in, line))
    {
        line = trimmed(line);
        if (line.empty()) continue;
        if (line.front() == '[')
        {
            section = line.substr(1, line.find(']') - 1);
            continue;
        }
        const auto eq = line.find('='), comment = line.find("//");
        IniKey k{section, trimmed(line.substr(0, eq)),
                 trimmed(line.substr(eq + 1, comment - eq - 1)), ""};
        const auto lb = line.find('[', comment), rb = line.find(']', comment);
        if (lb != std::string::npos && rb != std::string::npos)
            k.unit = line.substr(lb + 1, rb - lb - 1);
        out.push_back(k);
    }
    return out;
}

/** Another valid-looking value for `k`: the other boolean, the next whole number, a real
 * 0.125 larger, the next word of a "[a|b|c]" unit. */
std::string changedValue(const IniKey& k)
{
    if (k.value == "true") return "false";
    if (k.value == "false") return "true";
    if (k.unit.find('|') != std::string::npos)
    {
        std::vector<std::string> words;
        std::istringstream in(k.unit);
        for (std::string w; std::getline(in, w, '|');) words.push_back(w);
        for (std::size_t i = 0; i < words.size(); ++i)
            if (words[i] == k.value) return words[(i + 1) % words.size()];
        ADD_FAILURE() << k.key << ": value '" << k.value << "' not among " << k.unit;
        return k.value;
    }
    if (k.value.find_first_of(".eE") == std::string::npos)
        return std::to_string(std::stoll(k.value) + 1);
    std::ostringstream os;
    os << std::stod(k.value) + 0.125;
    return os.str();
}

bool sameValue(const std::string& a, const std::string& b)
{
    if (a == b) return true;
    try
    {
        return std::abs(std::stod(a) - std::stod(b)) < 1e-9;
    }
    catch (const std::exception&)
    {
        return false;
    }
}
}  // namespace

// Each key's load and save touch one member: a changed value read from the INI is written back
// unchanged, and every other key keeps its default.
TEST(Parameters, EveryKeyRoundTripsAlone)
{
    const std::vector<IniKey> defaults = keysOf(Parameters());
    ASSERT_GE(defaults.size(), 80u);
    for (const IniKey& k : defaults)
    {
        const std::string value = changedValue(k);
        Parameters p;
        p.loadFromConfigFile(mrpt::config::CConfigFileMemory("[" + k.section + "]\n" + k.key +
                                                             " = " + value + "\n"));
        const std::vector<IniKey> after = keysOf(p);
        ASSERT_EQ(after.size(), defaults.size());
        for (std::size_t i = 0; i < after.size(); ++i)
        {
            const bool is_k = after[i].section == k.section && after[i].key == k.key;
            EXPECT_TRUE(sameValue(after[i].value, is_k ? value : defaults[i].value))
                << "after loading [" << k.section << "] " << k.key << " = " << value << ": ["
                << after[i].section << "] " << after[i].key << " = " << after[i].value;
        }
    }
}

// Every numeric key has a lower bound, and its message names the section, key and value.
TEST(Parameters, EveryNumericKeyNamesSectionKeyAndValueWhenOutOfRange)
{
    for (const IniKey& k : keysOf(Parameters()))
    {
        if (k.value == "true" || k.value == "false" || k.unit.find('|') != std::string::npos)
            continue;
        const std::string msg = iniError("[" + k.section + "]\n" + k.key + " = -1000\n");
        EXPECT_TRUE(contains(msg, "[" + k.section + "] " + k.key + " = -1000 violates "))
            << k.key << ": " << msg;
    }
}

// A stage's own validate() names its section too (library users call it without Parameters).
TEST(Parameters, StageValidateNamesItsSection)
{
    const auto message = [](const auto& part) -> std::string
    {
        try
        {
            part.validate();
        }
        catch (const InputError& e)
        {
            return e.what();
        }
        return "";
    };
    mrpt_topoeval::GraphMatcherParameters matcher;
    matcher.max_groups = 0;
    EXPECT_EQ(message(matcher), "[GraphMatcher] max_groups = 0 violates max_groups >= 1");
    mrpt_topoeval::VertexSimilarityParameters similarity;
    similarity.threads = -1;
    EXPECT_EQ(message(similarity), "[VertexSimilarity] threads = -1 violates 0 <= threads <= 256");
    mrpt_topoeval::QualityParameters quality;
    quality.brokenness_min_part_vertices = 9;
    EXPECT_EQ(message(quality),
              "[QualityEvaluator] brokenness_min_part_vertices = 9 violates 2 <= "
              "brokenness_min_part_vertices <= brokenness_min_vertices");
    mrpt_topoeval::MapLoadOptions map_load;
    map_load.grey_between_thresholds = "grey";
    EXPECT_EQ(message(map_load),
              "[MapLoad] grey_between_thresholds = 'grey' violates grey_between_thresholds in "
              "{auto, unknown, probability}");
    EXPECT_EQ(message(mrpt_topoeval::GraphBuilderParameters()), "");
}

// fromIniText() (the Python Config.from_dict) gives fromIniFile()'s values and messages, with
// its source's name where the path would be.
TEST(Parameters, FromIniTextMatchesFromIniFile)
{
    const std::string good = "[GraphBuilder]\nmin_clearance_m = 0.4\n";
    EXPECT_DOUBLE_EQ(Parameters::fromIniText(good, "dict").graph.min_clearance_m, 0.4);
    for (const std::string bad :
         {"[GraphBuilder]\nmin_clearance_m = -1\n", "[GraphBuilder]\nmin_clerance_m = 1\n",
          "[NoSuchSection]\nx = 1\n"})
    {
        SCOPED_TRACE(bad);
        const ScopedTempDir dir_tmp("params_text");
        const std::string path = writeText(dir_tmp.path, "bad.ini", bad);
        std::string from_file, from_text;
        try
        {
            Parameters::fromIniFile(path);
        }
        catch (const InputError& e)
        {
            from_file = e.what();
        }
        try
        {
            Parameters::fromIniText(bad, "dict");
        }
        catch (const InputError& e)
        {
            from_text = e.what();
        }
        ASSERT_FALSE(from_file.empty());
        ASSERT_EQ(from_text.rfind("dict: ", 0), 0u) << from_text;
        EXPECT_EQ(from_text.substr(6), from_file.substr(path.size() + 2));
    }
}
