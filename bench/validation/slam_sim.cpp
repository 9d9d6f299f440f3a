/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Simulated ICP-SLAM (doc/validation.md): a robot drives a tour through a ground-truth grid, a
// 360-degree laser and the wheel odometry are simulated with seeded noise, MRPT's ICP-SLAM
// builds the map in-process, and every keyframe it inserts is paired with the true pose of the
// scan it came from.
//
// Thread safety: nothing here touches MRPT's global random generator. The laser uses
// COccupancyGridMap2D::laserScanSimulator() with noiseStd = angleNoiseStd = 0, the only case in
// which MRPT 2.5.8's simulateScanRay() does not draw from getRandomGenerator(); the range noise
// is added here from a std::mt19937. Odometry actions use the Gaussian motion model (the Thrun
// model draws particles from the global generator). ICP runs with doRANSAC = false (RANSAC
// draws from it too).

#include "slam_sim.h"

#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDF.h>
#include <mrpt/slam/CMetricMapBuilderICP.h>
#include <mrpt/system/datetime.h>

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>

namespace mrpt_topoeval::validation
{
namespace
{
using mrpt::poses::CPose2D;

// ---- The drive and the laser.
constexpr double kStep_m = 0.25;         //!< Straight move between scans [m].
constexpr double kTurnStep_deg = 10.0;   //!< Rotation between scans when turning in place.
constexpr double kScanPeriod_s = 0.1;    //!< Time between scans (timestamps only) [s].
constexpr std::size_t kRays = 361;       //!< Rays over 360 degrees (1 degree apart).
constexpr float kMaxRange_m = 10.0f;     //!< Laser range; longer rays read "no return".
constexpr double kRangeSigma_m = 0.015;  //!< Gaussian range noise [m].

/** Odometry error model. Per step, with d the true distance and a the true turn:
 *   forward  = d (1 + scale_bias) + N(0, (sigma_fwd * d)^2)        [+ N(0, slip_fwd^2)]
 *   lateral  = N(0, (sigma_lat * d)^2)
 *   turn     = a (1 + turn_bias) + drift_per_m * d + N(0, (sigma_rot * |a| + sigma_rot_m * d)^2)
 *                                                                   [+ N(0, slip_rot^2)]
 * The biases are systematic (the same sign on every step, as a wrong wheel radius or wheel
 * base gives): they bend a dead-reckoned corridor. The bracketed terms are wheel slips, drawn
 * on a step with probability slip_prob.
 *
 * Why slips: ICP-SLAM here localises on every step (0.25 m, 10 deg apart) with a 360-degree
 * 10 m laser, and corrects any small per-step error. Measured on the office tour (3 seeds):
 * with the Gaussian terms alone, even 15 %, 5 deg/m and biases of 8-10 % (30 m of dead-
 * reckoning drift) gave maps as good as level 1. Only errors that leave ICP's basin (a slip
 * of several degrees or decimetres) change the map, as they do on a real robot. */
struct OdometryNoise
{
    double sigma_fwd = 0.0;    //!< Forward error per metre driven [m/m].
    double sigma_lat = 0.0;    //!< Sideways error per metre driven [m/m].
    double sigma_rot = 0.0;    //!< Heading error per radian turned [rad/rad].
    double sigma_rot_m = 0.0;  //!< Heading error per metre driven [rad/m].
    double scale_bias = 0.0;   //!< Systematic distance scale error [-].
    double turn_bias = 0.0;    //!< Systematic turn scale error [-].
    double drift_per_m = 0.0;  //!< Systematic heading drift while driving straight [rad/m].
    double slip_prob = 0.0;    //!< Chance of a wheel slip per step [-].
    double slip_rot = 0.0;     //!< Heading error of a slip: sigma [rad].
    double slip_fwd = 0.0;     //!< Distance error of a slip: sigma [m].
};

constexpr double deg(double d) { return d * M_PI / 180.0; }

/** The three levels (per-step sigmas, proportional to the motion of the step):
 *  1 (good wheel odometry): fwd 1 %, lat 0.5 %, rot 1 % of the turn + 0.25 deg/m; no bias, no
 *     slips.
 *  2 (medium): fwd 3 %, lat 1.5 %, rot 3 % + 1 deg/m; bias: scale +1 %, turns +1.5 %,
 *     drift 0.5 deg/m; slips on 2 % of the steps, sigma 6 deg and 0.15 m.
 *  3 (poor): fwd 6 %, lat 3 %, rot 6 % + 2 deg/m; bias: scale +2.5 %, turns +4 %,
 *     drift 1.5 deg/m; slips on 5 % of the steps, sigma 10 deg and 0.3 m. */
OdometryNoise noiseForLevel(int level)
{
    switch (level)
    {
        case 1:
            return {0.01, 0.005, 0.01, deg(0.25), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        case 2:
            return {0.03, 0.015, 0.03, deg(1.0), 0.01, 0.015, deg(0.5), 0.02, deg(6.0), 0.15};
        case 3:
            return {0.06, 0.03, 0.06, deg(2.0), 0.025, 0.04, deg(1.5), 0.05, deg(10.0), 0.3};
        default:
            throw std::invalid_argument("noise_level = " + std::to_string(level) +
                                        " violates noise_level in {1, 2, 3}");
    }
}

/** The true poses: from the first waypoint facing the second, turn in place, then straight
 * moves of at most kStep_m to the next waypoint (as testing::drivePath()). */
std::vector<CPose2D> drive(const std::vector<Eigen::Vector2d>& tour)
{
    std::vector<CPose2D> poses;
    if (tour.empty()) return poses;
    double x = tour[0].x(), y = tour[0].y(), phi = 0.0;
    for (std::size_t i = 1; i < tour.size(); ++i)
        if ((tour[i] - tour[0]).norm() > 1e-9)
        {
            phi = std::atan2(tour[i].y() - y, tour[i].x() - x);
            break;
        }
    poses.emplace_back(x, y, phi);
    const double turn = deg(kTurnStep_deg);
    for (std::size_t i = 1; i < tour.size(); ++i)
    {
        const double dx = tour[i].x() - x, dy = tour[i].y() - y;
        const double dist = std::hypot(dx, dy);
        if (dist < 1e-9) continue;
        double d = std::remainder(std::atan2(dy, dx) - phi, 2 * M_PI);
        const int n_turn = static_cast<int>(std::ceil(std::abs(d) / turn - 1e-9));
        for (int k = 1; k <= n_turn; ++k) poses.emplace_back(x, y, phi + d * k / n_turn);
        phi = std::remainder(phi + d, 2 * M_PI);
        const int n = static_cast<int>(std::ceil(dist / kStep_m));
        const double x0 = x, y0 = y;
        for (int k = 1; k <= n; ++k)
        {
            x = x0 + dx * k / n;
            y = y0 + dy * k / n;
            poses.emplace_back(x, y, phi);
        }
    }
    return poses;
}

/** The true increment `inc` (robot frame) as the odometry reports it. */
CPose2D noisyIncrement(const CPose2D& inc, const OdometryNoise& nm, std::mt19937& rng)
{
    std::normal_distribution<double> gauss(0.0, 1.0);
    const double d = std::hypot(inc.x(), inc.y());
    const double a = inc.phi();
    // Draw all three every step so that the random sequence does not depend on the motion.
    const double g_fwd = gauss(rng), g_lat = gauss(rng), g_rot = gauss(rng);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    const double u_slip = uni(rng), g_slip_rot = gauss(rng), g_slip_fwd = gauss(rng);
    const bool slip = u_slip < nm.slip_prob;
    const double fwd = d * (1.0 + nm.scale_bias) + nm.sigma_fwd * d * g_fwd +
                       (slip ? nm.slip_fwd * g_slip_fwd : 0.0);
    const double lat = nm.sigma_lat * d * g_lat;
    const double rot = a * (1.0 + nm.turn_bias) + nm.drift_per_m * d +
                       (nm.sigma_rot * std::abs(a) + nm.sigma_rot_m * d) * g_rot +
                       (slip ? nm.slip_rot * g_slip_rot : 0.0);
    // The translation keeps its direction in the robot frame (forward for this robot).
    const double dir = d > 1e-12 ? std::atan2(inc.y(), inc.x()) : 0.0;
    const double c = std::cos(dir), s = std::sin(dir);
    return CPose2D(c * fwd - s * lat, s * fwd + c * lat, rot);
}

/** A 360-degree scan at `pose` on `world`, without noise. */
mrpt::obs::CObservation2DRangeScan::Ptr noiselessScan(const mrpt::maps::COccupancyGridMap2D& world,
                                                      const CPose2D& pose)
{
    auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
    scan->sensorLabel = "LASER";
    scan->aperture = static_cast<float>(2 * M_PI);
    scan->maxRange = kMaxRange_m;
    scan->rightToLeft = true;
    // noiseStd = 0 and angleNoiseStd = 0: MRPT's global random generator is not used.
    world.laserScanSimulator(*scan, pose, 0.5f, kRays, 0.0f, 1, 0.0f);
    return scan;
}

/** A 360-degree scan at `pose` on `world`, with seeded Gaussian range noise. */
mrpt::obs::CObservation2DRangeScan::Ptr simulateScan(const mrpt::maps::COccupancyGridMap2D& world,
                                                     const CPose2D& pose, std::mt19937& rng)
{
    auto scan = noiselessScan(world, pose);
    std::normal_distribution<double> gauss(0.0, kRangeSigma_m);
    for (std::size_t i = 0; i < kRays; ++i)
    {
        const double g = gauss(rng);  // drawn for every ray: the sequence is fixed per scan
        if (!scan->getScanRangeValidity(i)) continue;
        const float r = scan->getScanRange(i) + static_cast<float>(g);
        scan->setScanRange(i, std::max(0.01f, r));
    }
    return scan;
}

/** RawlogScorer's default ICP-SLAM set-up (insertion every 0.5 m / 10 deg, localisation every
 * 0.1 m / 5 deg, a points map for ICP and a 0.05 m grid), with ICP capped for speed. */
void configure(mrpt::slam::CMetricMapBuilderICP& builder)
{
    auto& o = builder.ICP_options;
    o.matchAgainstTheGrid = false;
    o.insertionLinDistance = 0.5;
    o.insertionAngDistance = deg(10.0);
    o.localizationLinDistance = 0.1;
    o.localizationAngDistance = deg(5.0);
    o.minICPgoodnessToAccept = 0.40;

    mrpt::maps::CSimplePointsMap::TMapDefinition pts;
    pts.insertionOpts.minDistBetweenLaserPoints = 0.05f;
    // Fusing keeps the points map at about one point per 5 cm of wall: without it every
    // keyframe adds its scan, and rebuilding the k-d tree of the growing cloud after each
    // insertion took 80 % of the run (6-9 s on the office tour instead of ~1.5 s).
    pts.insertionOpts.fuseWithExisting = true;
    pts.insertionOpts.isPlanarMap = true;
    pts.insertionOpts.disableDeletion = true;
    o.mapInitializers.push_back(pts);

    mrpt::maps::COccupancyGridMap2D::TMapDefinition grid;
    grid.resolution = 0.05f;
    grid.min_x = grid.min_y = -10.0f;
    grid.max_x = grid.max_y = 10.0f;
    grid.insertionOpts.maxDistanceInsertion = 30.0f;
    grid.insertionOpts.maxOccupancyUpdateCertainty = 0.55f;
    grid.insertionOpts.considerInvalidRangesAsFreeSpace = false;
    grid.insertionOpts.wideningBeamsWithDistance = false;
    o.mapInitializers.push_back(grid);

    auto& icp = builder.ICP_params;
    icp.ICP_algorithm = mrpt::slam::icpClassic;
    icp.maxIterations = 40;
    icp.minAbsStep_trans = 1e-6;
    icp.minAbsStep_rot = 1e-6;
    icp.thresholdDist = 0.75;
    icp.thresholdAng = deg(0.15);
    icp.ALFA = 0.5;
    icp.smallestThresholdDist = 0.05;
    icp.doRANSAC = false;
    icp.corresponding_points_decimation = 3;
    icp.skip_cov_calculation = true;  // the builder's pose covariance is not used here

    builder.setVerbosityLevel(mrpt::system::LVL_ERROR);
    builder.initialize();
}

/** Which keyframe's scan put an obstacle into each cell of `grid` (the last one that hit it;
 * -1 for none): a cell's truth is the pose of the scan that drew it. Where a poor odometry slip
 * made SLAM draw one wall twice, each copy then maps through its own keyframes. */
struct CellOwners
{
    double x_min = 0, y_min = 0, res = 1;
    int size_x = 0, size_y = 0;
    std::vector<int> owner;
    int at(const Eigen::Vector2d& p) const
    {
        const int cx = static_cast<int>(std::floor((p.x() - x_min) / res));
        const int cy = static_cast<int>(std::floor((p.y() - y_min) / res));
        if (cx < 0 || cy < 0 || cx >= size_x || cy >= size_y) return -1;
        return owner[static_cast<std::size_t>(cy) * size_x + cx];
    }
};

/** p_gt = true_k (+) (p in the frame of estimated_k), k the keyframe whose scan drew p's cell,
 * else the nearest estimated keyframe. */
TruthMapping keyframeTruth(const std::vector<CPose2D>& true_kf, const std::vector<CPose2D>& est_kf,
                           std::shared_ptr<const CellOwners> owners)
{
    struct Frame
    {
        double ex, ey, ec, es;  // estimated keyframe: position, cos and sin of its heading
        double tx, ty, tc, ts;  // true keyframe
    };
    auto frames = std::make_shared<std::vector<Frame>>();
    for (std::size_t k = 0; k < est_kf.size(); ++k)
        frames->push_back({est_kf[k].x(), est_kf[k].y(), std::cos(est_kf[k].phi()),
                           std::sin(est_kf[k].phi()), true_kf[k].x(), true_kf[k].y(),
                           std::cos(true_kf[k].phi()), std::sin(true_kf[k].phi())});
    return [frames, owners](const Eigen::Vector2d& p) -> std::optional<Eigen::Vector2d>
    {
        const Frame* best = nullptr;
        double best_d2 = std::numeric_limits<double>::infinity();
        const int k = owners ? owners->at(p) : -1;
        if (k >= 0 && static_cast<std::size_t>(k) < frames->size())
            best = &(*frames)[static_cast<std::size_t>(k)];
        for (const Frame& f : *frames)
        {
            if (best && k >= 0) break;
            {
                const double d2 = (p.x() - f.ex) * (p.x() - f.ex) + (p.y() - f.ey) * (p.y() - f.ey);
                if (d2 < best_d2)  // strict: ties go to the earliest keyframe
                {
                    best_d2 = d2;
                    best = &f;
                }
            }
        }
        if (!best) return std::nullopt;
        const double dx = p.x() - best->ex, dy = p.y() - best->ey;
        const double lx = best->ec * dx + best->es * dy, ly = -best->es * dx + best->ec * dy;
        return Eigen::Vector2d(best->tx + best->tc * lx - best->ts * ly,
                               best->ty + best->ts * lx + best->tc * ly);
    };
}
/** One drive of `tour` and its ICP-SLAM run (simulateIcpSlam() without the restart). */
SlamRun runOnce(const mrpt::maps::COccupancyGridMap2D& world,
                const std::vector<Eigen::Vector2d>& tour, int noise_level, std::uint32_t seed)
{
    const OdometryNoise nm = noiseForLevel(noise_level);
    const std::vector<CPose2D> poses = drive(tour);
    if (poses.size() < 2)
        throw std::invalid_argument("simulateIcpSlam: the tour has " + std::to_string(tour.size()) +
                                    " waypoints and no motion; it needs two distinct ones");

    // Two streams, so that the laser noise does not change with the odometry level.
    std::seed_seq odo_seq{seed, 0x0d0u, static_cast<std::uint32_t>(noise_level)};
    std::seed_seq scan_seq{seed, 0x5ca7u};
    std::mt19937 odo_rng(odo_seq), scan_rng(scan_seq);

    mrpt::slam::CMetricMapBuilderICP builder;
    configure(builder);

    SlamRun run;
    const auto t0 = mrpt::Clock::fromDouble(1.0e9);
    std::map<mrpt::Clock::time_point, std::size_t> step_of_time;
    CPose2D dead_reckoning = poses.front();
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motion;
    motion.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
    const auto points =
        builder.getCurrentlyBuiltMetricMap()->mapByClass<mrpt::maps::CSimplePointsMap>();
    if (!points) throw std::logic_error("simulateIcpSlam: the ICP-SLAM map has no points map");
    unsigned int n_keyframes = 0;
    for (std::size_t i = 0; i < poses.size(); ++i)
    {
        const auto t = mrpt::system::timestampAdd(t0, kScanPeriod_s * static_cast<double>(i));
        step_of_time[t] = i;
        const CPose2D inc =
            i == 0 ? CPose2D() : noisyIncrement(poses[i] - poses[i - 1], nm, odo_rng);
        dead_reckoning = dead_reckoning + inc;

        mrpt::obs::CActionCollection acts;
        mrpt::obs::CActionRobotMovement2D mov;
        mov.computeFromOdometry(inc, motion);
        mov.timestamp = t;
        acts.insert(mov);
        auto scan = simulateScan(world, poses[i], scan_rng);
        scan->timestamp = t;
        mrpt::obs::CSensoryFrame sf;
        sf.insert(scan);
        builder.processActionObservation(acts, sf);
        // MRPT 2.5.8 bug: CPointsMap::fuseWith() marks the map modified, builds the k-d tree
        // to find the fused pairs, then appends the new points with insertPointFast(), which
        // does not mark it again. ICP then searches a tree without the last keyframe's points:
        // entering a room, its new walls match nothing, ICP goodness stays below the
        // acceptance threshold, no keyframe is inserted, and the pose slides (0.9 m jumps in
        // the office's big room). Marking the map after each insertion fixes that.
        if (builder.getCurrentlyBuiltMapSize() != n_keyframes)
        {
            n_keyframes = builder.getCurrentlyBuiltMapSize();
            points->mark_as_modified();
        }
    }
    run.scans = poses.size();
    run.odometry_drift_m =
        std::hypot(dead_reckoning.x() - poses.back().x(), dead_reckoning.y() - poses.back().y());

    // Keyframes: the simple map holds the inserted scans themselves, so their timestamps name
    // the step (and so the true pose) of each.
    mrpt::maps::CSimpleMap sm;
    builder.getCurrentlyBuiltMap(sm);
    std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> kf_scans;
    for (std::size_t k = 0; k < sm.size(); ++k)
    {
        mrpt::poses::CPose3DPDF::Ptr pose_pdf;
        mrpt::obs::CSensoryFrame::Ptr kf_sf;
        sm.get(k, pose_pdf, kf_sf);
        if (!pose_pdf || !kf_sf || kf_sf->size() == 0) continue;
        const auto it = step_of_time.find((*kf_sf->begin())->timestamp);
        if (it == step_of_time.end()) continue;
        run.estimated_keyframes.emplace_back(pose_pdf->getMeanVal());
        run.true_keyframes.push_back(poses[it->second]);
        kf_scans.push_back(
            std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(*kf_sf->begin()));
    }

    const auto grid =
        builder.getCurrentlyBuiltMetricMap()->mapByClass<mrpt::maps::COccupancyGridMap2D>();
    if (!grid) throw std::logic_error("simulateIcpSlam: the ICP-SLAM map has no occupancy grid");
    run.map = *grid;
    auto owners = std::make_shared<CellOwners>();
    owners->x_min = run.map.getXMin();
    owners->y_min = run.map.getYMin();
    owners->res = run.map.getResolution();
    owners->size_x = static_cast<int>(run.map.getSizeX());
    owners->size_y = static_cast<int>(run.map.getSizeY());
    owners->owner.assign(static_cast<std::size_t>(owners->size_x) * owners->size_y, -1);
    for (std::size_t k = 0; k < kf_scans.size(); ++k)
    {
        const auto& scan = kf_scans[k];
        if (!scan) continue;
        const CPose2D sensor = run.estimated_keyframes[k] + CPose2D(scan->sensorPose);
        const std::size_t n = scan->getScanSize();
        for (std::size_t r = 0; r < n; ++r)
        {
            if (!scan->getScanRangeValidity(r)) continue;
            const double a = -0.5 * scan->aperture +
                             scan->aperture * static_cast<double>(r) / static_cast<double>(n - 1);
            const double range = scan->getScanRange(r);
            const CPose2D hit = sensor + CPose2D(range * std::cos(a), range * std::sin(a), 0.0);
            const int cx = static_cast<int>(std::floor((hit.x() - owners->x_min) / owners->res));
            const int cy = static_cast<int>(std::floor((hit.y() - owners->y_min) / owners->res));
            if (cx < 0 || cy < 0 || cx >= owners->size_x || cy >= owners->size_y) continue;
            owners->owner[static_cast<std::size_t>(cy) * owners->size_x + cx] = static_cast<int>(k);
        }
    }
    run.truth = keyframeTruth(run.true_keyframes, run.estimated_keyframes, owners);
    return run;
}

/** A run lost track when ICP-SLAM inserted a keyframe on fewer than this share of its scans. A
 * run that keeps track inserts one every 0.5 m or 10 degrees, about every second scan (corpus
 * seeds 1-5: 350 keyframes and more). A run that starts where its 10 m laser reaches few walls
 * (the middle of a column hall: 15-26 returns of 361) builds its first map from them; later
 * scans, with hundreds of returns, match too little of it (ICP goodness under
 * minICPgoodnessToAccept), nothing more is inserted, and the map stays a few rays (3-16
 * keyframes in 600 scans and more on seeds 2, 4 and 5; none on seed 1). */
constexpr double kMinKeyframeShare = 0.1;
/** A restart's first waypoint: the first of the tour where this share of a scan's rays return. */
constexpr double kMinStartReturns = 0.5;

bool lostTrack(const SlamRun& run)
{
    return static_cast<double>(run.true_keyframes.size()) <
           kMinKeyframeShare * static_cast<double>(run.scans);
}

/** The first waypoint of `tour` where at least kMinStartReturns of a scan's rays return (0 if
 * none does). */
std::size_t firstWaypointNearWalls(const mrpt::maps::COccupancyGridMap2D& world,
                                   const std::vector<Eigen::Vector2d>& tour)
{
    for (std::size_t k = 0; k < tour.size(); ++k)
    {
        const auto scan = noiselessScan(world, CPose2D(tour[k].x(), tour[k].y(), 0.0));
        std::size_t returns = 0;
        for (std::size_t r = 0; r < scan->getScanSize(); ++r)
            returns += scan->getScanRangeValidity(r);
        if (static_cast<double>(returns) >= kMinStartReturns * static_cast<double>(kRays)) return k;
    }
    return 0;
}
}  // namespace

SlamRun simulateIcpSlam(const mrpt::maps::COccupancyGridMap2D& world,
                        const std::vector<Eigen::Vector2d>& tour, int noise_level,
                        std::uint32_t seed)
{
    SlamRun run = runOnce(world, tour, noise_level, seed);
    if (!lostTrack(run)) return run;
    // As an operator would: start again where the laser sees walls, drive back along the tour
    // to its start, then the whole tour (the stretch before the new start is driven twice).
    const std::size_t k = firstWaypointNearWalls(world, tour);
    const std::size_t lost_keyframes = run.true_keyframes.size(), lost_scans = run.scans;
    if (k > 0)
    {
        std::vector<Eigen::Vector2d> restarted(
            tour.rbegin() + static_cast<std::ptrdiff_t>(tour.size() - 1 - k), tour.rend());
        restarted.insert(restarted.end(), tour.begin() + 1, tour.end());
        run = runOnce(world, restarted, noise_level, seed);
        run.restarted_at_waypoint = k;
    }
    if (lostTrack(run))
        throw std::runtime_error(
            "simulated ICP-SLAM lost track: " + std::to_string(lost_keyframes) + " keyframes in " +
            std::to_string(lost_scans) + " scans" +
            (k > 0 ? ", and " + std::to_string(run.true_keyframes.size()) + " in " +
                         std::to_string(run.scans) + " restarted at waypoint " + std::to_string(k)
                   : std::string(", and no waypoint where half the laser's rays return")));
    run.first_start_keyframes = lost_keyframes;
    return run;
}
}  // namespace mrpt_topoeval::validation
