/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <Eigen/Core>

namespace mrpt_topoeval
{
/** A rigid 2D transform taking map coordinates into the ground truth's frame (T_gt_map). */
struct Transform2D
{
    double x_m = 0.0, y_m = 0.0, yaw_deg = 0.0;
    Eigen::Vector2d apply(const Eigen::Vector2d& p) const;
};

}  // namespace mrpt_topoeval
