/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "rawlog_report.h"

#include <mrpt_topoeval/json/JsonWriter.h>
#include <mrpt_topoeval/report_json.h>
#include <mrpt_topoeval/scores/scores.h>

#include <cstdint>

namespace mrpt_topoeval::cli
{
namespace
{
using u64 = std::uint64_t;

void writeStats(JsonWriter& w, const RawlogStats& s)
{
    w.beginObject(true);
    w.key("format").value(s.format);
    w.key("entries").value(u64{s.entries});
    w.key("action_collections").value(u64{s.action_collections});
    w.key("sensory_frames").value(u64{s.sensory_frames});
    w.key("observations").value(u64{s.observations});
    w.key("scans").value(u64{s.scans});
    w.key("odometry").value(u64{s.odometry});
    w.key("odometry_stamped").value(u64{s.odometry_stamped});
    w.key("odometry_restamped").value(u64{s.odometry_restamped});
    w.key("scans_restamped").value(u64{s.scans_restamped});
    w.key("scans_without_odometry").value(u64{s.scans_without_odometry});
    w.key("odometry_superseded").value(u64{s.odometry_superseded});
    w.key("other_observations").value(u64{s.other_observations});
    w.key("unknown_objects").value(u64{s.unknown_objects});
    w.key("skipped_before_offset").value(u64{s.skipped_before_offset});
    w.endObject();
}

void writeMessages(JsonWriter& w, const std::vector<std::string>& messages)
{
    w.beginArray(true);
    for (const auto& m : messages) w.value(m);
    w.endArray();
}

void writeConfiguration(JsonWriter& w, const RawlogRun& run, const std::string& slam_ini)
{
    w.beginObject(true);
    w.key("every_scans").value(u64{run.options.every_scans});
    w.key("max_entries").value(u64{run.options.max_entries});
    w.key("max_entry_bytes").value(u64{run.options.max_entry_bytes});
    w.key("slam_config_file").value(run.options.slam_config_file);
    w.key("slam_ini").value(slam_ini);
    w.key("topoeval_config_file").value(run.topoeval_config_file);
    w.key("topoeval_ini").value(run.topoeval_ini);
    w.endObject();
}

/** The members every report starts with. */
void writeHead(JsonWriter& w, const RawlogRun& run)
{
    w.beginObject();
    w.key("rawlog").value(run.rawlog);
    w.key("ground_truth").value(run.ground_truth);
}
}  // namespace

std::string rawlogReportJson(const RawlogRun& run, const RawlogScoreResult& res,
                             const Parameters& params)
{
    constexpr int kDigits = 10;  // significant digits of the times
    JsonWriter w;
    writeHead(w, run);
    w.key("stop").value(toString(res.stop));
    w.key("stop_entry").value(u64{res.stop_entry});
    w.key("stop_message").value(res.stop_message);
    w.key("stats");
    writeStats(w, res.stats);
    w.key("snapshots").value(u64{res.rows.size()});
    w.key("messages");
    writeMessages(w, res.messages);
    w.key("configuration");
    writeConfiguration(w, run, res.effective_slam_ini);
    w.key("final_scores");
    if (res.rows.empty())
        w.null();
    else
        writeScoreRow(w, res.rows.back());
    w.key("final_report")
        .embed(
            reportToJson(res.final_gt_graph, res.final_map_graph, res.final_report, params, false));
    w.key("timing_ms").beginObject(true);
    w.key("slam").valueSignificant(res.slam_ms, kDigits);
    w.key("scoring").valueSignificant(res.scoring_ms, kDigits);
    w.key("total").valueSignificant(res.total_ms, kDigits);
    w.endObject();
    w.endObject();
    return w.str();
}

std::string rawlogErrorReportJson(const RawlogRun& run, const std::string& error,
                                  std::size_t snapshots, const RawlogProbe& probe,
                                  const ScoreRow& last_row)
{
    JsonWriter w;
    writeHead(w, run);
    w.key("stop").value("error");
    w.key("stop_entry").null();
    w.key("stop_message").value(error);
    w.key("stats").null();
    w.key("snapshots").value(u64{snapshots});
    w.key("messages");
    writeMessages(w, probe.messages);
    w.key("configuration");
    writeConfiguration(w, run, probe.effective_slam_ini);
    w.key("final_scores");
    writeScoreRow(w, last_row);
    w.key("final_report").null();
    w.key("timing_ms").null();
    w.endObject();
    return w.str();
}

}  // namespace mrpt_topoeval::cli
