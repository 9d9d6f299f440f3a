/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Map quality over time (doc/rawlog.md): every entry of a rawlog goes to MRPT's ICP-SLAM;
// every N scans the grid built so far is copied and scored with evaluate(), the code of
// `compare`. Real logs are repaired on the way (untimed odometry, equal or decreasing
// timestamps) and every repair is counted.

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/slam/CMetricMapBuilderICP.h>
#include <mrpt/system/datetime.h>
#include <mrpt_topoeval/RawlogScorer.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/pipeline/evaluate.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "common/clock.h"
#include "common/error_text.h"
#include "rawlog/RawlogReader.h"

namespace fs = std::filesystem;

namespace mrpt_topoeval
{
namespace
{
using internal::Clock;
using internal::msSince;
bool validTime(const mrpt::Clock::time_point& t) { return t != INVALID_TIMESTAMP; }

/** A restamped reading lands this long after the previous one: small enough not to disturb
 * the pose extrapolation, large enough to be strictly increasing. */
constexpr double kRestampStep_s = 1e-3;

constexpr const char* kSlamSection = "MappingApplication";
constexpr const char* kIcpSection = "ICP";

std::string readTextFile(const std::string& path)
{
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(path + ": no such file (--slam-config)");
    if (fs::is_directory(path, ec)) throw InputError(path + ": is a folder, not an INI file");
    std::ifstream f(path, std::ios::binary);
    if (!f) throw InputError(path + ": cannot open for reading");
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

std::size_t countGrids(const mrpt::maps::TSetOfMetricMapInitializers& inits)
{
    std::size_t n = 0;
    for (const auto& def : inits)
        if (def && def->getMetricMapClassType() == CLASS_ID(mrpt::maps::COccupancyGridMap2D)) ++n;
    return n;
}

/** The SLAM as the `icp-slam` app configures it: `[MappingApplication]` for the map builder
 * and its maps, `[ICP]` for the aligner, `alwaysInsertByClass` and `rawlog_offset` read like
 * the app reads them. */
struct SlamSetup
{
    std::string effective_ini;
    std::size_t rawlog_offset = 0;
    std::vector<std::string> messages;
};

SlamSetup configureSlam(mrpt::slam::CMetricMapBuilderICP& builder, const std::string& ini_text,
                        const std::string& ini_name)
{
    SlamSetup setup;
    mrpt::config::CConfigFileMemory ini(ini_text);
    try
    {
        builder.ICP_options.loadFromConfigFile(ini, kSlamSection);
        builder.ICP_params.loadFromConfigFile(ini, kIcpSection);
    }
    catch (const std::exception& e)
    {
        throw InputError(ini_name + ": invalid ICP-SLAM configuration: " + internal::oneLine(e));
    }
    // Only the grid is scored: a configuration without one (the stock icp-slam demo INI) gets
    // the default grid so that it still works unchanged.
    if (countGrids(builder.ICP_options.mapInitializers) == 0)
    {
        mrpt::maps::COccupancyGridMap2D::TMapDefinition grid_def;
        grid_def.resolution = 0.05f;
        builder.ICP_options.mapInitializers.push_back(grid_def);
        setup.messages.push_back(ini_name +
                                 ": builds no occupancy grid; added a 0.05 m grid to score");
    }
    const auto n_grids = countGrids(builder.ICP_options.mapInitializers);
    if (n_grids > 1)
        setup.messages.push_back(ini_name + ": builds " + std::to_string(n_grids) +
                                 " occupancy grids; the first one is scored");
    const long offset = ini.read_int(kSlamSection, "rawlog_offset", 0);
    if (offset < 0)
        throw InputError(ini_name + ": [MappingApplication] rawlog_offset = " +
                         std::to_string(offset) + " violates rawlog_offset >= 0");
    setup.rawlog_offset = static_cast<std::size_t>(offset);

    builder.setVerbosityLevel(mrpt::system::LVL_ERROR);
    builder.initialize();
    const std::string always = ini.read_string(kSlamSection, "alwaysInsertByClass", "");
    builder.options.alwaysInsertByClass.fromString(always);

    // What was used, as an icp-slam INI: the builder's fields (angles in degrees, as MRPT
    // reads them), its map definitions and the ICP parameters.
    mrpt::config::CConfigFileMemory eff;
    const auto& o = builder.ICP_options;
    eff.write(kSlamSection, "rawlog_offset", static_cast<int>(setup.rawlog_offset));
    eff.write(kSlamSection, "alwaysInsertByClass", always);
    eff.write(kSlamSection, "matchAgainstTheGrid", o.matchAgainstTheGrid);
    eff.write(kSlamSection, "insertionLinDistance", o.insertionLinDistance);
    eff.write(kSlamSection, "insertionAngDistance", mrpt::RAD2DEG(o.insertionAngDistance));
    eff.write(kSlamSection, "localizationLinDistance", o.localizationLinDistance);
    eff.write(kSlamSection, "localizationAngDistance", mrpt::RAD2DEG(o.localizationAngDistance));
    eff.write(kSlamSection, "minICPgoodnessToAccept", o.minICPgoodnessToAccept);
    o.mapInitializers.saveToConfigFile(eff, kSlamSection);
    builder.ICP_params.saveToConfigFile(eff, kIcpSection);
    // MRPT 2.5.8 reads these two from `<name>_DEG` keys in degrees but writes `<name>` in
    // radians: the degree keys are added so that the effective INI reproduces the run.
    eff.write(kIcpSection, "thresholdAng_DEG", mrpt::RAD2DEG(builder.ICP_params.thresholdAng));
    eff.write(kIcpSection, "ransac_fuseMaxDiffPhi_DEG",
              mrpt::RAD2DEG(builder.ICP_params.ransac_fuseMaxDiffPhi));
    setup.effective_ini = eff.getContent();
    return setup;
}

/** Observation-type bookkeeping for RawlogStats::format. */
void noteFormat(RawlogStats& st, bool action_sf)
{
    const char* f = action_sf ? "action-sensoryframe" : "observations";
    if (st.format.empty())
        st.format = f;
    else if (st.format != f)
        st.format = "mixed";
}

/** The streaming run: one object per step, state kept between entries. */
class Run
{
public:
    Run(const RawlogScorerOptions& opts, const Parameters& params,
        const mrpt::maps::COccupancyGridMap2D& gt, RawlogScoreResult& res,
        const RawlogScorer::SnapshotCallback& on_snapshot)
        : m_opts(opts),
          m_params(params),
          m_gt(gt),
          // Built once: every snapshot is scored against the same ground truth.
          m_gt_graph(buildTopologyGraph(gt, params.graph)),
          m_res(res),
          m_on_snapshot(on_snapshot)
    {
    }

    mrpt::slam::CMetricMapBuilderICP builder;

    /** One rawlog entry. */
    void process(const mrpt::serialization::CSerializable::Ptr& obj, std::size_t entry)
    {
        m_entry = entry;
        RawlogStats& st = m_res.stats;
        if (auto acts = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(obj))
        {
            ++st.action_collections;
            noteFormat(st, true);
            handleActions(*acts);
        }
        else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
        {
            ++st.sensory_frames;
            noteFormat(st, true);
            for (const auto& o : *sf) handleObservation(o);
        }
        else if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj))
        {
            ++st.observations;
            noteFormat(st, false);
            handleObservation(o);
        }
        else
            ++st.unknown_objects;
    }

    std::size_t scans() const { return m_res.stats.scans; }
    bool snapshotDue() const { return m_scans_at_snapshot != scans(); }

    /** Copies the grid and scores it (the copy is what makes the snapshot consistent). */
    void snapshot()
    {
        const auto t0 = Clock::now();
        const auto grid_ptr =
            builder.getCurrentlyBuiltMetricMap()->mapByClass<mrpt::maps::COccupancyGridMap2D>();
        if (!grid_ptr) throw std::logic_error("the ICP-SLAM map has no occupancy grid");
        mrpt::maps::COccupancyGridMap2D grid = *grid_ptr;
        TopologyGraph map_graph;
        QualityReport report = evaluate(m_gt_graph, m_gt, grid, m_params, &map_graph);
        ScoreRow row = scoreRowFromReport(report);
        row.step = static_cast<int>(m_res.rows.size()) + 1;
        row.entry = m_entry;
        row.time_s = validTime(m_first_scan_time) && validTime(m_last_scan_time)
                         ? mrpt::system::timeDifference(m_first_scan_time, m_last_scan_time)
                         : std::numeric_limits<double>::quiet_NaN();
        row.scans = scans();
        row.scoring_ms = msSince(t0);
        m_res.scoring_ms += row.scoring_ms;
        m_res.rows.push_back(row);
        m_scans_at_snapshot = scans();

        static const TopologyGraph kEmpty;
        if (m_on_snapshot)
        {
            const bool keep = m_opts.keep_snapshot_graphs;
            m_on_snapshot(
                Snapshot{row, grid, report, keep ? m_gt_graph : kEmpty, keep ? map_graph : kEmpty});
        }
        m_res.final_grid = std::move(grid);
        m_res.final_report = std::move(report);
        if (m_res.rows.size() == 1) m_res.final_gt_graph = m_gt_graph;  // the same for all
        m_res.final_map_graph = std::move(map_graph);
    }

private:
    void handleActions(const mrpt::obs::CActionCollection& acts)
    {
        const auto mov = acts.getBestMovementEstimation();
        if (!mov) return;
        // Like CMetricMapBuilderICP::processActionObservation: increments accumulate into an
        // absolute odometry reading, so a reading that is superseded loses nothing.
        m_accum_odometry = m_accum_odometry + mov->poseChange->getMeanVal();
        auto odo = std::make_shared<mrpt::obs::CObservationOdometry>();
        odo->timestamp = mov->timestamp;
        odo->odometry = m_accum_odometry;
        setPendingOdometry(odo);
    }

    void handleObservation(const mrpt::obs::CObservation::Ptr& o)
    {
        if (!o) return;
        if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o))
            setPendingOdometry(odo);
        else if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o))
            handleScan(scan);
        else
            ++m_res.stats.other_observations;
    }

    void setPendingOdometry(const mrpt::obs::CObservationOdometry::Ptr& odo)
    {
        ++m_res.stats.odometry;
        if (m_pending_odometry) ++m_res.stats.odometry_superseded;
        // Held until the next scan: an untimed reading gets that scan's time.
        m_pending_odometry = odo;
    }

    void handleScan(const mrpt::obs::CObservation2DRangeScan::Ptr& scan)
    {
        RawlogStats& st = m_res.stats;
        // ICP-SLAM needs strictly increasing times: an equal time makes the robot stand still.
        if (!validTime(scan->timestamp) ||
            (validTime(m_last_scan_time) && scan->timestamp <= m_last_scan_time))
        {
            ++st.scans_restamped;
            if (validTime(m_last_scan_time))
                scan->timestamp = mrpt::system::timestampAdd(m_last_scan_time, kRestampStep_s);
            else if (m_pending_odometry && validTime(m_pending_odometry->timestamp))
                scan->timestamp = m_pending_odometry->timestamp;
            else
                scan->timestamp = mrpt::Clock::fromDouble(1.0);
        }
        if (m_pending_odometry)
        {
            auto& t = m_pending_odometry->timestamp;
            if (!validTime(t))
            {
                ++st.odometry_stamped;
                t = scan->timestamp;
            }
            else if (validTime(m_last_odometry_time) && t <= m_last_odometry_time)
            {
                ++st.odometry_restamped;
                t = scan->timestamp > m_last_odometry_time
                        ? scan->timestamp
                        : mrpt::system::timestampAdd(m_last_odometry_time, kRestampStep_s);
            }
            feed(m_pending_odometry);
            m_last_odometry_time = t;
            m_pending_odometry.reset();
        }
        else
            ++st.scans_without_odometry;
        feed(scan);
        ++st.scans;
        if (!validTime(m_first_scan_time)) m_first_scan_time = scan->timestamp;
        m_last_scan_time = scan->timestamp;
    }

    void feed(const mrpt::obs::CObservation::Ptr& o)
    {
        try
        {
            builder.processObservation(o);
        }
        catch (const std::bad_alloc&)
        {
            throw;
        }
        catch (const std::exception& e)
        {
            // One reading MRPT refuses does not end the run; it is counted and named once.
            if (m_slam_rejections++ == 0)
            {
                m_res.messages.push_back("ICP-SLAM rejected a reading at entry " +
                                         std::to_string(m_entry) + " (" + internal::oneLine(e) +
                                         "); such readings are skipped");
            }
        }
    }

public:
    std::size_t slamRejections() const { return m_slam_rejections; }

private:
    const RawlogScorerOptions& m_opts;
    const Parameters& m_params;
    const mrpt::maps::COccupancyGridMap2D& m_gt;
    const TopologyGraph m_gt_graph;
    RawlogScoreResult& m_res;
    const RawlogScorer::SnapshotCallback& m_on_snapshot;

    std::size_t m_entry = 0;
    mrpt::poses::CPose2D m_accum_odometry;
    mrpt::obs::CObservationOdometry::Ptr m_pending_odometry;
    mrpt::Clock::time_point m_first_scan_time = INVALID_TIMESTAMP;
    mrpt::Clock::time_point m_last_scan_time = INVALID_TIMESTAMP;
    mrpt::Clock::time_point m_last_odometry_time = INVALID_TIMESTAMP;
    std::size_t m_scans_at_snapshot = std::numeric_limits<std::size_t>::max();
    std::size_t m_slam_rejections = 0;
};

const char* kDefaultSlamIni =
    R"INI(# ICP-SLAM configuration of `topoeval rawlog` (MRPT's own sections and keys, as the
# `icp-slam` app reads them: an icp-slam INI works unchanged with --slam-config).

[MappingApplication]
# The icp-slam app's keys that also apply here (rawlog_file, logOutput_dir, LOG_FREQUENCY and
# the SAVE_* / SHOW_* keys are the app's own and are ignored).
# Entries before this one are skipped.
rawlog_offset=0
# A new keyframe is inserted after this much motion [m] / [deg].
insertionLinDistance=0.5
insertionAngDistance=10
# ICP localisation runs after this much motion [m] / [deg]; dead reckoning in between.
localizationLinDistance=0.1
localizationAngDistance=5
# An ICP result is accepted above this goodness [0, 1].
minICPgoodnessToAccept=0.40
# Align scans against the points map (more precise than against the grid).
matchAgainstTheGrid=false

# The metric maps built: one points map (for ICP) and the occupancy grid that is scored.
pointsMap_count=1
occupancyGrid_count=1

[MappingApplication_pointsMap_00_insertOpts]
minDistBetweenLaserPoints=0.05
fuseWithExisting=false
isPlanarMap=true

# The scored grid: 0.05 m cells; it grows as the robot explores [m].
[MappingApplication_occupancyGrid_00_creationOpts]
resolution=0.05
min_x=-10
max_x=10
min_y=-10
max_y=10

[MappingApplication_occupancyGrid_00_insertOpts]
mapAltitude=0
useMapAltitude=false
maxDistanceInsertion=30
maxOccupancyUpdateCertainty=0.55
considerInvalidRangesAsFreeSpace=false
wideningBeamsWithDistance=false

[ICP]
# ICP aligner (mrpt::slam::CICP::TConfigParams); angles in degrees.
ICP_algorithm=icpClassic
maxIterations=80
minAbsStep_trans=1e-6
minAbsStep_rot=1e-6
thresholdDist=0.75
# Matching distance grows with the points' range by this angle [deg].
thresholdAng_DEG=0.15
ALFA=0.5
smallestThresholdDist=0.05
doRANSAC=false
corresponding_points_decimation=5
)INI";

// ---- What run() and probe() share, so that both refuse the same files with the same words.

/** The SLAM INI as messages name it, and its text. */
struct SlamIni
{
    std::string name, text;
};

SlamIni slamIni(const RawlogScorerOptions& o)
{
    if (o.slam_config_file.empty()) return {"default SLAM configuration", kDefaultSlamIni};
    return {o.slam_config_file, readTextFile(o.slam_config_file)};
}

void refuseEmpty(const rawlog::RawlogReader& reader, const std::string& path)
{
    if (reader.fileBytes() == 0) throw InputError(path + ": is empty (no rawlog entries)");
}

/** The first entry cannot be read: the file is no rawlog at all. */
InputError notARawlog(const std::string& path, const std::string& why)
{
    return InputError(path + ": not an MRPT rawlog (" + why + ")");
}

std::string maxEntriesMessage(const std::string& path, std::size_t entries)
{
    return path + ": stopped before entry " + std::to_string(entries) + " (max entries reached)";
}

/** Reading ended (`stop_message`: why, if before the end of the file) without a scan. */
InputError noScan(const std::string& path, std::size_t entries, const std::string& stop_message)
{
    // A gz file cut before its first entry decompresses to nothing without an error: "no
    // scan in 0 entries" would not say what is wrong with it.
    if (entries == 0 && stop_message.empty())
        return InputError(path +
                          ": holds no rawlog entry (empty once decompressed, or cut inside its "
                          "first entry)");
    return InputError(
        path + ": no 2D laser scan in " + std::to_string(entries) + " entries" +
        (stop_message.empty() ? std::string() : " before it stopped: " + stop_message));
}

/** Whether an entry gives ICP-SLAM a scan, as Run::process() counts scans. */
bool holdsScan(const mrpt::serialization::CSerializable::Ptr& obj)
{
    if (const auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
    {
        for (const auto& o : *sf)
            if (std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o)) return true;
        return false;
    }
    return std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obj) != nullptr;
}

}  // namespace

std::string toString(RawlogStop stop)
{
    switch (stop)
    {
        case RawlogStop::EndOfFile:
            return "end_of_file";
        case RawlogStop::Interrupted:
            return "interrupted";
        case RawlogStop::Truncated:
            return "truncated";
        case RawlogStop::Corrupt:
            return "corrupt";
        case RawlogStop::MaxEntries:
            return "max_entries";
    }
    return "unknown";
}

RawlogScorer::RawlogScorer(const RawlogScorerOptions& options, const Parameters& params)
    : m_options(options), m_params(params)
{
    if (m_options.every_scans < 1)
        throw InputError("every_scans = 0 violates every_scans >= 1 (scans between snapshots)");
    if (m_options.max_entry_bytes < 1024)
        throw InputError("max_entry_bytes = " + std::to_string(m_options.max_entry_bytes) +
                         " violates max_entry_bytes >= 1024");
    m_params.validate();
}

std::string RawlogScorer::defaultSlamIniText() { return kDefaultSlamIni; }

RawlogProbe RawlogScorer::probe(const std::string& rawlog_path) const
{
    // The checks of run(), in its order, so that a file with two faults gets the same message.
    const SlamIni ini = slamIni(m_options);
    rawlog::RawlogReader reader(rawlog_path, m_options.max_entry_bytes);
    refuseEmpty(reader, rawlog_path);
    RawlogProbe probe;
    std::size_t rawlog_offset = 0;
    {
        mrpt::slam::CMetricMapBuilderICP builder;  // set up and dropped: only its checks count
        const SlamSetup setup = configureSlam(builder, ini.text, ini.name);
        probe.effective_slam_ini = setup.effective_ini;
        probe.messages = setup.messages;
        rawlog_offset = setup.rawlog_offset;
    }

    mrpt::serialization::CSerializable::Ptr obj;
    std::string why, stop_message;
    for (;;)
    {
        if (m_options.max_entries && reader.entries() >= m_options.max_entries)
        {
            stop_message = maxEntriesMessage(rawlog_path, reader.entries());
            break;
        }
        const auto status = reader.next(obj, why);
        if (status == rawlog::RawlogReader::Status::EndOfFile) break;
        if (status != rawlog::RawlogReader::Status::Object)
        {
            if (reader.entries() == 0) throw notARawlog(rawlog_path, why);
            stop_message = rawlog_path + ": " + why;
            break;
        }
        const std::size_t entry = reader.entries() - 1;
        if (entry >= rawlog_offset && holdsScan(obj))
        {
            probe.entries = reader.entries();
            probe.first_scan_entry = entry;
            return probe;
        }
    }
    throw noScan(rawlog_path, reader.entries(), stop_message);
}

RawlogScoreResult RawlogScorer::run(const std::string& rawlog_path,
                                    const mrpt::maps::COccupancyGridMap2D& ground_truth,
                                    const std::atomic<bool>* stop)
{
    const auto t_run = Clock::now();
    RawlogScoreResult res;
    const SlamIni ini = slamIni(m_options);
    rawlog::RawlogReader reader(rawlog_path, m_options.max_entry_bytes);
    refuseEmpty(reader, rawlog_path);

    Run run(m_options, m_params, ground_truth, res, m_on_snapshot);
    SlamSetup setup = configureSlam(run.builder, ini.text, ini.name);
    res.effective_slam_ini = setup.effective_ini;
    res.messages = setup.messages;

    auto report_progress = [&](double elapsed_s)
    {
        if (!m_on_progress) return;
        RawlogProgress p;
        p.entries = reader.entries();
        p.scans = run.scans();
        p.bytes_read = reader.bytesRead();
        p.bytes_total = reader.fileBytes();
        p.compressed_fraction = reader.fractionRead();
        p.elapsed_s = elapsed_s;
        m_on_progress(p);
    };

    mrpt::serialization::CSerializable::Ptr obj;
    std::string why;
    std::size_t last_progress_scans = 0;
    for (;;)
    {
        if (stop && stop->load())
        {
            res.stop = RawlogStop::Interrupted;
            res.stop_message =
                rawlog_path + ": interrupted before entry " + std::to_string(reader.entries());
            break;
        }
        if (m_options.max_entries && reader.entries() >= m_options.max_entries)
        {
            res.stop = RawlogStop::MaxEntries;
            res.stop_message = maxEntriesMessage(rawlog_path, reader.entries());
            break;
        }
        const auto status = reader.next(obj, why);
        if (status == rawlog::RawlogReader::Status::EndOfFile) break;
        if (status != rawlog::RawlogReader::Status::Object)
        {
            // A file whose first entry cannot be read is no rawlog at all: bad input.
            if (reader.entries() == 0) throw notARawlog(rawlog_path, why);
            res.stop = status == rawlog::RawlogReader::Status::Truncated ? RawlogStop::Truncated
                                                                         : RawlogStop::Corrupt;
            res.stop_message = rawlog_path + ": " + why;
            break;
        }
        const std::size_t entry = reader.entries() - 1;
        if (entry < setup.rawlog_offset)
        {
            ++res.stats.skipped_before_offset;
            continue;
        }
        const std::size_t scans_before = run.scans();
        run.process(obj, entry);
        obj.reset();
        if (run.scans() != scans_before && run.scans() % m_options.every_scans == 0) run.snapshot();
        if (run.scans() >= last_progress_scans + 50)
        {
            last_progress_scans = run.scans();
            report_progress(msSince(t_run) / 1000.0);
        }
    }
    res.stats.entries = reader.entries();
    res.stop_entry = reader.entries();
    if (res.stats.scans == 0) throw noScan(rawlog_path, res.stats.entries, res.stop_message);
    if (run.snapshotDue()) run.snapshot();
    run.builder.getCurrentlyBuiltMap(res.final_keyframes);
    if (run.slamRejections() > 1)
        res.messages.push_back(std::to_string(run.slamRejections()) +
                               " readings were rejected by ICP-SLAM in total");
    report_progress(msSince(t_run) / 1000.0);
    res.total_ms = msSince(t_run);
    res.slam_ms = res.total_ms - res.scoring_ms;
    return res;
}

}  // namespace mrpt_topoeval
