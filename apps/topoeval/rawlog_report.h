/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// report.json of `topoeval rawlog` (doc/rawlog.md): what was read, how the run ended, the
// configuration used, the final scores and the final quality report.

#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/pipeline/RawlogScorer.h>

#include <string>
#include <vector>

namespace mrpt_topoeval::cli
{
/** What a run was given: its inputs and configuration, as the report records them. */
struct RawlogRun
{
    std::string rawlog;                //!< The rawlog's path, as given.
    std::string ground_truth;          //!< The ground truth's path, as given.
    RawlogScorerOptions options;       //!< every_scans, max_entries, max_entry_bytes, SLAM file.
    std::string topoeval_config_file;  //!< --config, or empty.
    std::string topoeval_ini;          //!< The effective topoeval parameters as INI text.
};

/** report.json of a run that finished or stopped (RawlogScoreResult::stop). */
std::string rawlogReportJson(const RawlogRun& run, const RawlogScoreResult& result,
                             const Parameters& params);

/** report.json of a run that an error ended after `snapshots` snapshots: what the scorer had
 * not returned (its counters, the final report, the times) is null; `probe` gives the
 * messages and the SLAM configuration, `last_row` the final scores. */
std::string rawlogErrorReportJson(const RawlogRun& run, const std::string& error,
                                  std::size_t snapshots, const RawlogProbe& probe,
                                  const ScoreRow& last_row);

}  // namespace mrpt_topoeval::cli
