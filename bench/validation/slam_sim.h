/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// Simulated SLAM for the validation corpus (doc/validation.md): a robot drives a tour through a
// ground-truth grid, a laser is simulated, odometry gets seeded noise, and MRPT's ICP-SLAM
// (CMetricMapBuilderICP, in-process) builds the map. The truth is per keyframe.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "truth.h"

namespace mrpt_topoeval::validation
{
struct SlamRun
{
    mrpt::maps::COccupancyGridMap2D map;  //!< ICP-SLAM's grid, in its own (start pose) frame.
    std::vector<mrpt::poses::CPose2D> true_keyframes;       //!< Ground-truth frame.
    std::vector<mrpt::poses::CPose2D> estimated_keyframes;  //!< SLAM map frame.
    /** A map point maps through its nearest estimated keyframe k:
     * p_gt = true_k (+) (estimated_k (-) p). */
    TruthMapping truth;
    std::size_t scans = 0;
    double odometry_drift_m = 0.0;  //!< Final position error of dead reckoning alone [m].
    /** Where the drive was restarted after the tour's own start lost track (0: not restarted),
     * and how many keyframes that first run kept. */
    std::size_t restarted_at_waypoint = 0, first_start_keyframes = 0;
};

/** Drives `tour` through `world`, simulating a 360-degree laser and odometry with noise level
 * `noise_level` (1 low, 2 medium, 3 high; see slam_sim.cpp for the standard deviations), and
 * runs ICP-SLAM. A run that loses track from the tour's start (a keyframe on fewer than a tenth
 * of its scans) is driven again from the first waypoint where half the laser's rays return;
 * std::runtime_error if that loses track too. Deterministic for (world, tour, noise_level,
 * seed); thread-safe (no global random generator). */
SlamRun simulateIcpSlam(const mrpt::maps::COccupancyGridMap2D& world,
                        const std::vector<Eigen::Vector2d>& tour, int noise_level,
                        std::uint32_t seed);
}  // namespace mrpt_topoeval::validation
