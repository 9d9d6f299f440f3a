/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt_topoeval/geometry/Transform2D.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace mrpt_topoeval::internal
{
/** Point pairs split into two sets, each with its own rigid fit (map to ground truth). */
struct RigidSplit
{
    std::vector<int> side;         //!< 0 or 1 per pair; pair 0 is always on side 0
    Transform2D fit[2];            //!< Horn's fit of each side
    double squared_error_m2[2]{};  //!< each side's mean squared error
};

/** The split of pairs (gt_k, map_k) into two sets, each connected by `links` (indices of pairs)
 * and of at least `min_size` pairs, whose two rigid fits leave the smallest total squared
 * error: two parts of a broken map that one fit holds as a compromise. Candidate splits come
 * from pairs of local fits (each pair with its `local_size` nearest pairs, by ground-truth
 * distance) that place those pairs' map points differently, by a mean squared distance above
 * `min_gap_m2`; each is refined by assigning every pair to the fit that places it better and
 * refitting, until it holds. None when no such split exists (a rigid part: its local fits
 * agree). Deterministic; O(n^2) candidate splits at most, each O(n) per round. */
std::optional<RigidSplit> bestRigidSplit(const std::vector<Eigen::Vector2d>& gt,
                                         const std::vector<Eigen::Vector2d>& map,
                                         const std::vector<std::vector<int>>& links, int min_size,
                                         int local_size, double min_gap_m2);

}  // namespace mrpt_topoeval::internal
