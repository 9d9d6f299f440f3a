/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "evaluation/wall_places.h"

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>

namespace mrpt_topoeval::internal
{
std::optional<Transform2D> alignWalls(const TopologyGraph& gt, const TopologyGraph& map,
                                      const WallIndex& gt_walls, const WallIndex& map_walls,
                                      const std::vector<std::pair<int, int>>& pairs,
                                      double margin_m, const Transform2D& start,
                                      const QualityParameters& p, double reach_m)
{
    return alignWallsByIcp(gt, map, gt_walls, map_walls, pairs, margin_m, start,
                           std::max(std::sqrt(p.brokenness_max_squared_error_m2), reach_m));
}

double pairWallTolerance(const TopologyGraph& gt, const TopologyGraph& map,
                         const QualityParameters& p)
{
    return wallTolerance(p.pair_wall_tolerance_m, gt, map);
}

void placeByWalls(const TopologyGraph& gt, const TopologyGraph& map, const GraphMatch& m,
                  const Transform2D& t, const QualityParameters& p, Walls& walls,
                  std::vector<Eigen::Vector2d>& places, std::vector<double>& slack,
                  std::size_t& by_walls)
{
    by_walls = 0;
    if (!(p.pair_wall_margin_m > 0.0) || !walls.ok()) return;
    const WallIndex &gt_walls = walls.gt(), &map_walls = walls.map();
    const double tolerance = pairWallTolerance(gt, map, p);
    for (std::size_t i = 0; i < m.pairs.size(); ++i)
    {
        const auto& a = gt.vertices[static_cast<std::size_t>(m.pairs[i].ground_truth)];
        const auto& b = map.vertices[static_cast<std::size_t>(m.pairs[i].map)];
        const std::vector<std::pair<int, int>> pair{{m.pairs[i].ground_truth, m.pairs[i].map}};
        // ICP reaches at least as far as the pair's own error (within the outlier distance):
        // a room off by more than the default matching distance is found, not missed.
        const double own_error = (a.position_m - t.apply(b.position_m)).norm();
        const auto walls_fit = alignWalls(
            gt, map, gt_walls, map_walls, pair, p.pair_wall_margin_m, t, p,
            p.outlier_distance_m > 0.0 ? std::min(own_error, p.outlier_distance_m) : own_error);
        if (!walls_fit) continue;
        // The map point this alignment puts on the ground-truth vertex: walls_fit^-1 (p_a).
        const double yaw = mrpt::DEG2RAD(walls_fit->yaw_deg);
        const Eigen::Vector2d d = a.position_m - Eigen::Vector2d(walls_fit->x_m, walls_fit->y_m);
        const Eigen::Vector2d q(std::cos(yaw) * d.x() + std::sin(yaw) * d.y(),
                                -std::sin(yaw) * d.x() + std::cos(yaw) * d.y());
        if ((q - b.position_m).norm() > std::max(a.clearance_m, b.clearance_m)) continue;
        const WallAgreement agreement =
            wallAgreement(gt, map, gt_walls, map_walls, pair, *walls_fit, p.pair_wall_margin_m,
                          tolerance, p.pair_wall_min_agreement);
        if (!agreement.vouches(p.pair_wall_min_agreement, p.pair_wall_max_pinning)) continue;
        places[i] = q;
        slack[i] = 0.0;
        ++by_walls;
    }
}

}  // namespace mrpt_topoeval::internal
