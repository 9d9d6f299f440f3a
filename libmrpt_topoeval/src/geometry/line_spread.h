/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <Eigen/Core>
#include <vector>

namespace mrpt_topoeval::internal
{
/** How far points spread across their principal line: the RMS distance from it, the square
 * root of the smaller eigenvalue of their covariance [m]. 0 for fewer than 2 points. */
double lineSpread(const std::vector<Eigen::Vector2d>& points);

}  // namespace mrpt_topoeval::internal
