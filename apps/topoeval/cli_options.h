/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Pieces several verbs of the `topoeval` command share beyond cli_common.h: the standard
// options (--config, --resolution, --similarity, --threads, --json, --image, --force) with
// their help texts and checks, timing and number formatting, and timed map loading.

#include <mrpt/img/CImage.h>
#include <mrpt_topoeval/maps/load_map.h>

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli_common.h"

namespace mrpt_topoeval::cli
{
// ---- Timing and formatting

using Clock = std::chrono::steady_clock;

/** Milliseconds since `t0`. */
double msSince(Clock::time_point t0);

/** `v` printed with a printf `format` ("%.2f"). */
std::string fmt(const char* format, double v);

/** Whether `path` ends in ".png", in any case. */
bool endsWithPng(const std::string& path);
/** Whether `path` ends in ".html" or ".htm", in any case. */
bool endsWithHtml(const std::string& path);

/** The parameters as the INI text `topoeval config --write` would give for them. */
std::string iniText(const Parameters& params);

/** Loads a map as every verb does: its notes (LoadedMap::notes: where it was read otherwise
 * than literally) are printed as warnings naming its file. \throws InputError */
LoadedMap loadMapWarning(const std::string& path, const MapLoadOptions& opts);

/** loadMapWarning(), storing the time it took in `ms`. \throws InputError */
LoadedMap loadMapTimed(const std::string& path, const MapLoadOptions& opts, double& ms);

/** The steps of `t` in the order `order` lists them, then the others alphabetically, so a new
 * step still shows up. */
std::vector<std::pair<std::string, double>> orderedTimings(const std::map<std::string, double>& t,
                                                           const std::vector<std::string>& order);

/** "step 1.0, step 2.0" (milliseconds with one decimal). */
std::string timingList(const std::vector<std::pair<std::string, double>>& steps);

// ---- Outputs

/** (option, file) pairs of a run's outputs. */
using OutputList = std::vector<std::pair<std::string, std::string>>;

/** Refuses two outputs naming the same file: "--json and --image name the same file F".
 * \throws UsageError */
void checkDistinctOutputs(const VerbCommandLine& cl, const OutputList& outputs);

// ---- The standard options

/** What `compare` and `match` start from, every check done before any work. */
struct GtAndMapRun
{
    std::string gt_path, map_path;
    Parameters params;
};

/** The options most verbs share, each declared by its add*() call on the verb's command line
 * (TCLAP lists the last added first, so the verb calls them in reverse order of its usage
 * line, between its own options), read after VerbCommandLine::parse(). */
class StandardOptions
{
public:
    explicit StandardOptions(VerbCommandLine& cl) : m_cl(cl) {}

    void addForce(const std::string& help = "Replace existing output files.");
    void addImage(const std::string& help);
    void addJson(const std::string& help);
    /** --html OUT.html: the verb's HTML report (doc/report.md). */
    void addHtml(const std::string& help);
    void addThreads(const std::string& help =
                        "Worker threads for ICP similarity, 0 = all cores; overrides "
                        "[VertexSimilarity] threads. Results do not depend on it.");
    void addSimilarity();
    void addResolution();
    void addConfig(
        const std::string& help = "Parameters from this INI file (see 'topoeval config').");

    /** The unlabeled "GT MAP" argument of `match` and `compare`. */
    void addGtAndMap();

    bool force() const;
    std::string json() const;    //!< "" if not given
    std::string image() const;   //!< "" if not given
    std::string config() const;  //!< "" if not given
    std::string html() const;    //!< "" if not given

    /** The two maps of addGtAndMap(), checked; `too_many_hint` ends the message for more
     * than two. \throws UsageError */
    std::pair<std::string, std::string> gtAndMap(const std::string& too_many_hint = "") const;

    /** --json, --image and --html: a file name each, the picture a .png, the report a .html
     * or .htm. \throws UsageError */
    void checkJsonImage() const;

    /** The --json, --image and --html outputs given, as (option, file). */
    OutputList outputs() const;

    /** --threads and --similarity checked, then the parameters of --config with
     * --resolution, --similarity and --threads applied, validated. \throws InputError,
     * UsageError */
    Parameters parameters() const;

    /** checkOutputPath() on each of outputs() before any work. \throws UsageError,
     * OutputError */
    void checkOutputPaths(const std::vector<std::string>& inputs) const;

    /** The start `compare` and `match` share, in this order: gtAndMap(), checkJsonImage(), the
     * outputs distinct, parameters(), and checkOutputPaths() against both maps and --config.
     * \throws UsageError, InputError, OutputError */
    GtAndMapRun gtAndMapRun(const std::string& too_many_hint = "") const;

    /** Writes `json_text` to --json, `picture` to --image and `html_text` to --html, those
     * given, in that order; returns the files written. \throws OutputError */
    std::vector<std::string> writeOutputs(const std::string& json_text,
                                          const mrpt::img::CImage& picture,
                                          const std::string& html_text = {}) const;

private:
    VerbCommandLine& m_cl;
    std::unique_ptr<TCLAP::UnlabeledMultiArg<std::string>> m_maps;
    std::unique_ptr<TCLAP::SwitchArg> m_force;
    std::unique_ptr<TCLAP::ValueArg<std::string>> m_image, m_json, m_html, m_similarity, m_config;
    std::unique_ptr<TCLAP::ValueArg<int>> m_threads;
    std::unique_ptr<TCLAP::ValueArg<double>> m_resolution;
};

}  // namespace mrpt_topoeval::cli
