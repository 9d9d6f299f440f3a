/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt_topoeval/geometry/Transform2D.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace mrpt_topoeval::internal
{
/** Horn's closed-form rigid 2D alignment (paper IV, [17]) in double precision on centred
 * points: T minimising sum |gt_i - T(map_i)|^2. (mrpt::tfest::se2_l2 works in float on
 * uncentred sums and loses millimetres at 100 m, metres at 1 km.) Returns the mean squared
 * error [m^2] through `mse`. Fewer than 2 points: identity on the centroids. */
Transform2D hornAlign(const std::vector<Eigen::Vector2d>& gt,
                      const std::vector<Eigen::Vector2d>& map, double* mse = nullptr);

/** For each pair k, the squared distance from gt[k] to map[k] placed by Horn's fit of all the
 * other pairs (leave-one-out), in O(n) for all: the fit depends on the points through sums
 * that one pair changes by its own term. Fewer than 3 pairs: zeros. */
std::vector<double> leaveOneOutSquaredErrors(const std::vector<Eigen::Vector2d>& gt,
                                             const std::vector<Eigen::Vector2d>& map);

/** The ground-truth point where two transforms (map to ground truth) place one map point alike:
 * the fixed point of the turn between them, the pivot of a break. None when their yaws are
 * equal (a shift has no such point). */
std::optional<Eigen::Vector2d> agreementPoint(const Transform2D& a, const Transform2D& b);

/** How far a part is off (BrokennessGroup::offset_m): the root mean square, over the part's map
 * points `points`, of |own(q) - other(q)| for the transform of `others` that places them nearest
 * to where `own` does (its neighbour part in a chain of breaks). Infinity when `others` or
 * `points` is empty. */
double partOffset(const Transform2D& own, const std::vector<Transform2D>& others,
                  const std::vector<Eigen::Vector2d>& points);

}  // namespace mrpt_topoeval::internal
