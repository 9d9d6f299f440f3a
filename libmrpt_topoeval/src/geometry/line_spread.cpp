/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "line_spread.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace mrpt_topoeval::internal
{
double lineSpread(const std::vector<Eigen::Vector2d>& points)
{
    if (points.size() < 2) return 0.0;
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const auto& q : points) mean += q;
    mean /= double(points.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (const auto& q : points) cov += (q - mean) * (q - mean).transpose();
    cov /= double(points.size());
    return std::sqrt(
        std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cov).eigenvalues()(0)));
}
}  // namespace mrpt_topoeval::internal
