/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Map quality over time: a rawlog is mapped by MRPT's ICP-SLAM and the grid built so far is
// scored against the ground truth every N scans, with the same evaluate() as `compare`
// (doc/rawlog.md). The SLAM types stay in the .cpp: this header speaks MRPT maps and our own
// report types only.

#include <mrpt/img/CImage.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/QualityReport.h>
#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/scores/scores.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace mrpt_topoeval
{
/** What a rawlog held and which real-data quirks were repaired or skipped on the way. */
struct RawlogStats
{
    std::size_t entries = 0;             //!< Objects read (the last one processed is entries-1).
    std::size_t action_collections = 0;  //!< `CActionCollection` entries (action/SF format).
    std::size_t sensory_frames = 0;      //!< `CSensoryFrame` entries (action/SF format).
    std::size_t observations = 0;        //!< Bare `CObservation` entries (observation format).
    std::size_t scans = 0;               //!< 2D laser scans fed to the SLAM.
    std::size_t odometry = 0;            //!< Odometry readings (actions or observations).
    std::size_t odometry_stamped = 0;    //!< Odometry without a timestamp, given its scan's.
    std::size_t odometry_restamped = 0;  //!< Odometry not after the previous one, restamped.
    std::size_t scans_restamped = 0;     //!< Scans without a time or not after the last one.
    std::size_t scans_without_odometry = 0;  //!< Scans with no odometry since the previous scan.
    std::size_t odometry_superseded = 0;     //!< Observation odometry replaced by a later reading
                                             //!< before any scan (absolute readings: nothing lost).
    std::size_t other_observations = 0;      //!< Observations ICP-SLAM does not use (skipped).
    std::size_t unknown_objects = 0;         //!< Objects of other classes (skipped).
    std::size_t skipped_before_offset =
        0;               //!< Entries before `[MappingApplication] rawlog_offset`.
    std::string format;  //!< "action-sensoryframe", "observations", "mixed" or "" (nothing read).
};

/** Why reading stopped. Everything but EndOfFile means the map covers only part of the log. */
enum class RawlogStop
{
    EndOfFile,    //!< The whole rawlog was read.
    Interrupted,  //!< The stop flag was set (Ctrl-C).
    Truncated,    //!< The file ends inside an entry.
    Corrupt,      //!< An entry could not be decoded, or is larger than the size limit.
    MaxEntries,   //!< RawlogScorerOptions::max_entries was reached.
};
/** "end_of_file", "interrupted", "truncated", "corrupt", "max_entries". */
std::string toString(RawlogStop stop);

/** How the rawlog is read and when snapshots are taken. The SLAM itself is configured by an
 * `icp-slam` INI (see RawlogScorer::defaultSlamIniText()). */
struct RawlogScorerOptions
{
    /** A snapshot is scored every this many scans, and always at the end [scans, >= 1]. */
    std::size_t every_scans = 100;
    /** Stop (RawlogStop::MaxEntries) after this many entries; 0 = read everything. */
    std::size_t max_entries = 0;
    /** An entry whose serialized size exceeds this is corrupt: MRPT's serialization has no
     * length prefix to check beforehand, so this bounds what one damaged entry can consume.
     * Real laser entries are a few kB; default 64 MiB [bytes]. */
    std::uint64_t max_entry_bytes = 64ULL << 20;
    /** The `icp-slam` INI file (MRPT's sections `[MappingApplication]`, `[ICP]`); empty = the
     * documented default. A file building no occupancy grid gets the default grid added. */
    std::string slam_config_file;
    /** Keep each snapshot's graphs and report for the snapshot callback (pictures). */
    bool keep_snapshot_graphs = false;
};

/** A snapshot as it is scored, for the caller's outputs. The references live until the
 * callback returns. */
struct Snapshot
{
    const ScoreRow& row;
    const mrpt::maps::COccupancyGridMap2D& grid;
    const QualityReport& report;
    const TopologyGraph& gt_graph;   //!< Filled when keep_snapshot_graphs, else empty.
    const TopologyGraph& map_graph;  //!< Filled when keep_snapshot_graphs, else empty.
};

/** Progress of the reading, reported about every 50 scans and at the end. */
struct RawlogProgress
{
    std::size_t entries = 0, scans = 0;
    std::uint64_t bytes_read = 0;       //!< Uncompressed bytes consumed so far.
    std::uint64_t bytes_total = 0;      //!< File size (compressed size for .gz; 0 unknown).
    double compressed_fraction = -1.0;  //!< Share of the file read, [0, 1], -1 if unknown.
    double elapsed_s = 0.0;
};

/** The result of a run: always filled for the part done, whatever stopped it. */
struct RawlogScoreResult
{
    RawlogStats stats;
    RawlogStop stop = RawlogStop::EndOfFile;
    std::size_t stop_entry = 0;  //!< The entry at which reading stopped (== stats.entries).
    std::string stop_message;    //!< Why, naming the file and the entry; empty at end of file.
    std::vector<ScoreRow> rows;  //!< One per snapshot, the final one last.
    mrpt::maps::COccupancyGridMap2D final_grid;
    QualityReport final_report;
    TopologyGraph final_gt_graph, final_map_graph;
    /** The ICP-SLAM keyframes at the end, as MRPT's `icp-slam` saves them (`.simplemap`): each
     * the robot pose SLAM estimated and the sensory frame inserted there. The final grid was
     * drawn from them; with the true poses of their scans they give a per-point truth of the
     * map (bench/validation: the Radish logs' corrected poses). */
    mrpt::maps::CSimpleMap final_keyframes;
    std::string effective_slam_ini;     //!< The SLAM configuration actually used, as INI text.
    std::vector<std::string> messages;  //!< Notes on the configuration and the data.
    double slam_ms = 0.0;               //!< Time in reading and ICP-SLAM [ms].
    double scoring_ms = 0.0;            //!< Time in snapshots and evaluate() [ms].
    double total_ms = 0.0;
};

/** What RawlogScorer::probe() found: the rawlog starts like one run() accepts. */
struct RawlogProbe
{
    std::size_t entries = 0;            //!< Entries read, up to and including the first scan's.
    std::size_t first_scan_entry = 0;   //!< The entry (from 0) holding the first 2D laser scan.
    std::string effective_slam_ini;     //!< As RawlogScoreResult::effective_slam_ini.
    std::vector<std::string> messages;  //!< Notes on the SLAM configuration, as run() gives.
};

/** Reads a rawlog entry by entry, runs ICP-SLAM, scores snapshots (doc/rawlog.md). */
class RawlogScorer
{
public:
    using ProgressCallback = std::function<void(const RawlogProgress&)>;
    using SnapshotCallback = std::function<void(const Snapshot&)>;

    RawlogScorer(const RawlogScorerOptions& options, const Parameters& params);

    /** Called with each snapshot right after it is scored (write the CSV row there). */
    void onSnapshot(SnapshotCallback cb) { m_on_snapshot = std::move(cb); }
    /** Called about every 50 scans and once at the end. */
    void onProgress(ProgressCallback cb) { m_on_progress = std::move(cb); }

    /** Runs on `rawlog_path` (MRPT rawlog, either format, gz or plain) against the ground
     * truth. `stop` (may be null) is checked between entries: when set, reading stops and the
     * map built so far is scored (RawlogStop::Interrupted).
     * A truncated or corrupt rawlog is not an exception: the result says where it stopped.
     * \throws InputError for a missing or unreadable rawlog, a file that is not a rawlog (its
     * first entry cannot be read), one with no laser scan, a bad SLAM INI. */
    RawlogScoreResult run(const std::string& rawlog_path,
                          const mrpt::maps::COccupancyGridMap2D& ground_truth,
                          const std::atomic<bool>* stop = nullptr);

    /** Checks, before the caller creates any output, what run() would refuse as bad input:
     * the SLAM configuration, and the rawlog read up to its first 2D laser scan (at or after
     * `rawlog_offset`, within `max_entries`). Throws the InputError run() would throw, with
     * the same message. Cheap for a rawlog that starts with a scan; one without any scan is
     * read to its end, as run() would. A rawlog that passes can still stop early in run()
     * (truncated or corrupt after its first scan), which is not an exception there.
     * \throws InputError */
    RawlogProbe probe(const std::string& rawlog_path) const;

    /** The SLAM configuration used without `--slam-config`, as an `icp-slam` INI: ICP-SLAM
     * on a points map, and a 0.05 m occupancy grid that grows as needed. */
    static std::string defaultSlamIniText();

private:
    RawlogScorerOptions m_options;
    Parameters m_params;
    SnapshotCallback m_on_snapshot;
    ProgressCallback m_on_progress;
};

}  // namespace mrpt_topoeval
