/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// A rawlog simulated from a ground-truth grid: a robot drives a path of waypoints, a 360 degree
// laser is simulated with COccupancyGridMap2D::laserScanSimulator() at each step, odometry is
// perfect. Header-only so that every test executable can use it without a library change.

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/datetime.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace mrpt_topoeval::testing
{
struct SimulatedRawlogOptions
{
    bool observation_format = false;  //!< Observation-only instead of action/sensory-frame pairs.
    bool untimed_odometry = false;    //!< Odometry without timestamps (as intel.rawlog).
    bool unknown_objects = false;     //!< A CPose2D object every 10 scans (not a rawlog class).
    /** An IMU reading every 10 scans (in the scan's sensory frame, or an entry of its own):
     * another sensor, of a class whose layout topoeval does not check. */
    bool other_sensors = false;
    bool gzip = false;            //!< Compressed output.
    double step_m = 0.25;         //!< Distance between scans [m].
    double turn_step_deg = 15.0;  //!< Rotation between scans when turning in place [deg].
    double scan_period_s = 0.1;   //!< Time between scans [s].
    float max_range_m = 12.0f;
};

/** A path through the corridors and into every room of makeOfficeMap(). */
inline std::vector<mrpt::poses::CPose2D> officeWaypoints()
{
    const std::vector<std::pair<double, double>> xy = {
        {3.0, 9.0},   {5.5, 9.0},   {5.5, 7.5},   {5.0, 4.5},   {5.5, 7.5},   {5.5, 9.0},
        {9.9, 9.0},   {9.9, 3.0},   {9.9, 9.0},   {13.5, 9.0},  {13.5, 7.5},  {15.0, 4.5},
        {13.5, 7.5},  {13.5, 9.0},  {24.5, 9.0},  {24.5, 7.5},  {24.5, 4.0},  {24.5, 7.5},
        {24.5, 9.0},  {27.0, 9.0},  {27.0, 15.0}, {30.2, 15.0}, {27.0, 15.0}, {27.0, 19.0},
        {27.0, 9.0},  {21.0, 9.0},  {21.0, 15.0}, {19.5, 15.0}, {19.5, 16.5}, {19.0, 18.5},
        {19.5, 16.5}, {19.5, 15.0}, {10.5, 15.0}, {10.5, 17.0}, {11.5, 19.0}, {10.5, 17.0},
        {10.5, 15.0}, {4.5, 15.0},  {4.5, 17.0},  {4.75, 19.0}, {4.5, 17.0},  {4.5, 15.0},
        {3.0, 15.0},  {3.0, 9.0},   {7.5, 9.0},   {7.5, 12.0},  {16.5, 12.0}, {16.5, 15.0}};
    std::vector<mrpt::poses::CPose2D> out;
    for (const auto& [x, y] : xy) out.emplace_back(x, y, 0.0);
    return out;
}

/** The robot's poses: straight moves of `step_m` between waypoints, turning in place first. */
inline std::vector<mrpt::poses::CPose2D> drivePath(const std::vector<mrpt::poses::CPose2D>& wps,
                                                   double step_m, double turn_step_deg)
{
    std::vector<mrpt::poses::CPose2D> poses;
    if (wps.empty()) return poses;
    double x = wps[0].x(), y = wps[0].y(), phi = 0.0;
    poses.emplace_back(x, y, phi);
    const double turn = turn_step_deg * M_PI / 180.0;
    for (std::size_t i = 1; i < wps.size(); ++i)
    {
        const double dx = wps[i].x() - x, dy = wps[i].y() - y;
        const double dist = std::hypot(dx, dy);
        if (dist < 1e-9) continue;
        const double target = std::atan2(dy, dx);
        double d = std::remainder(target - phi, 2 * M_PI);
        while (std::abs(d) > 1e-9)
        {
            const double s = std::abs(d) > turn ? std::copysign(turn, d) : d;
            phi += s;
            d -= s;
            poses.emplace_back(x, y, phi);
        }
        const int n = static_cast<int>(std::ceil(dist / step_m));
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

/** Writes the rawlog; returns the number of scans. \throws std::runtime_error */
inline std::size_t writeSimulatedRawlog(const std::string& path,
                                        const mrpt::maps::COccupancyGridMap2D& grid,
                                        const std::vector<mrpt::poses::CPose2D>& poses,
                                        const SimulatedRawlogOptions& opts = {})
{
    mrpt::io::CFileGZOutputStream f;
    if (!f.open(path, opts.gzip ? 1 : 0)) throw std::runtime_error(path + ": cannot write");
    auto ar = mrpt::serialization::archiveFrom(f);
    const auto t0 = mrpt::Clock::fromDouble(1.6e9);
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motion;
    for (std::size_t i = 0; i < poses.size(); ++i)
    {
        const auto t = mrpt::system::timestampAdd(t0, opts.scan_period_s * static_cast<double>(i));
        auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
        scan->sensorLabel = "LASER";
        scan->aperture = static_cast<float>(2 * M_PI);
        scan->maxRange = opts.max_range_m;
        scan->rightToLeft = true;
        grid.laserScanSimulator(*scan, poses[i], 0.5f, 361);
        scan->timestamp = t;
        mrpt::obs::CObservationIMU::Ptr imu;
        if (opts.other_sensors && i % 10 == 3)
        {
            imu = std::make_shared<mrpt::obs::CObservationIMU>();
            imu->sensorLabel = "IMU";
            imu->timestamp = t;
            imu->set(mrpt::obs::IMU_WZ, 0.1);
        }
        if (opts.observation_format)
        {
            auto odo = std::make_shared<mrpt::obs::CObservationOdometry>();
            odo->odometry = poses[i];
            odo->timestamp = opts.untimed_odometry ? INVALID_TIMESTAMP : t;
            ar << *odo << *scan;
            if (imu) ar << *imu;
        }
        else
        {
            mrpt::obs::CActionCollection acts;
            mrpt::obs::CActionRobotMovement2D mov;
            const mrpt::poses::CPose2D inc =
                i == 0 ? mrpt::poses::CPose2D() : poses[i] - poses[i - 1];
            mov.computeFromOdometry(inc, motion);
            mov.timestamp = opts.untimed_odometry ? INVALID_TIMESTAMP : t;
            acts.insert(mov);
            mrpt::obs::CSensoryFrame sf;
            sf.insert(scan);
            if (imu) sf.insert(imu);
            ar << acts << sf;
        }
        if (opts.unknown_objects && i % 10 == 5) ar << mrpt::poses::CPose2D(1, 2, 3);
    }
    return poses.size();
}

/** Writes a rawlog of `n` odometry observations and no laser scan: a well-formed rawlog that
 * `topoeval rawlog` must refuse as bad input. \throws std::runtime_error */
inline void writeRawlogWithoutScans(const std::string& path, std::size_t n, bool gzip)
{
    mrpt::io::CFileGZOutputStream f;
    if (!f.open(path, gzip ? 1 : 0)) throw std::runtime_error(path + ": cannot write");
    auto ar = mrpt::serialization::archiveFrom(f);
    const auto t0 = mrpt::Clock::fromDouble(1.6e9);
    for (std::size_t i = 0; i < n; ++i)
    {
        mrpt::obs::CObservationOdometry odo;
        odo.odometry = mrpt::poses::CPose2D(0.1 * static_cast<double>(i), 0.0, 0.0);
        odo.timestamp = mrpt::system::timestampAdd(t0, 0.1 * static_cast<double>(i));
        ar << odo;
    }
}

}  // namespace mrpt_topoeval::testing
