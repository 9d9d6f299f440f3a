/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "evaluation/wall_places.h"

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPosePDF.h>

#include <algorithm>
#include <cmath>

namespace mrpt_topoeval::internal
{
mrpt::slam::CICP::TConfigParams wallIcpOptions(const TopologyGraph& gt, const TopologyGraph& map,
                                               const QualityParameters& p)
{
    const double res = std::max(gt.map.resolution_m, map.map.resolution_m);
    mrpt::slam::CICP::TConfigParams o;
    o.ICP_algorithm = mrpt::slam::icpClassic;
    o.maxIterations = kWallIcpIterations;
    o.thresholdDist = std::max(std::sqrt(p.brokenness_max_squared_error_m2), 3.0 * res);
    o.thresholdAng = 0.0;
    o.ALFA = 0.5;
    o.smallestThresholdDist = 2.0 * res;
    o.skip_cov_calculation = true;
    o.skip_quality_calculation = true;
    return o;
}

void placeByWalls(const TopologyGraph& gt, const TopologyGraph& map, const GraphMatch& m,
                  const Transform2D& t, const QualityParameters& p, Walls& walls,
                  std::vector<Eigen::Vector2d>& places, std::vector<double>& slack,
                  std::size_t& by_walls)
{
    by_walls = 0;
    if (!(p.pair_wall_margin_m > 0.0) || !walls.ok()) return;
    const WallIndex &gt_walls = walls.gt(), &map_walls = walls.map();
    const double res = std::max(gt.map.resolution_m, map.map.resolution_m);
    const double tolerance = std::max(p.pair_wall_tolerance_m, 1.5 * res);
    auto cloud = [&](const TopologyGraph& g, const WallIndex& index, int v)
    {
        mrpt::maps::CSimplePointsMap c;
        for (const auto& q : wallsAround(g, index, {v}, p.pair_wall_margin_m, 0))
            c.insertPoint(float(q.x()), float(q.y()), 0.0f);
        return c;
    };
    for (std::size_t i = 0; i < m.pairs.size(); ++i)
    {
        const auto& a = gt.vertices[static_cast<std::size_t>(m.pairs[i].ground_truth)];
        const auto& b = map.vertices[static_cast<std::size_t>(m.pairs[i].map)];
        const mrpt::maps::CSimplePointsMap walls_gt = cloud(gt, gt_walls, m.pairs[i].ground_truth),
                                           walls_map = cloud(map, map_walls, m.pairs[i].map);
        if (walls_gt.size() < kMinWallPoints || walls_map.size() < kMinWallPoints) continue;
        // ICP reaches at least as far as the pair's own error (within the outlier distance):
        // a room off by more than the default matching distance is found, not missed.
        mrpt::slam::CICP::TConfigParams o = wallIcpOptions(gt, map, p);
        const double own_error = (a.position_m - t.apply(b.position_m)).norm();
        o.thresholdDist = std::max(o.thresholdDist, p.outlier_distance_m > 0.0
                                                        ? std::min(own_error, p.outlier_distance_m)
                                                        : own_error);
        mrpt::slam::CICP icp(o);
        mrpt::slam::CICP::TReturnInfo info;
        const auto pose =
            icp.Align(&walls_gt, &walls_map,
                      mrpt::poses::CPose2D(t.x_m, t.y_m, t.yaw_deg * M_PI / 180.0), info)
                ->getMeanVal();
        // The map point this alignment puts on the ground-truth vertex: pose^-1 (p_a).
        const Eigen::Vector2d d = a.position_m - Eigen::Vector2d(pose.x(), pose.y());
        const double c = std::cos(pose.phi()), sn = std::sin(pose.phi());
        const Eigen::Vector2d q(c * d.x() + sn * d.y(), -sn * d.x() + c * d.y());
        if ((q - b.position_m).norm() > std::max(a.clearance_m, b.clearance_m)) continue;
        const Transform2D walls_fit{pose.x(), pose.y(), pose.phi() * 180.0 / M_PI};
        const WallAgreement agreement =
            wallAgreement(gt, map, gt_walls, map_walls, {{m.pairs[i].ground_truth, m.pairs[i].map}},
                          walls_fit, p.pair_wall_margin_m, tolerance, p.pair_wall_min_agreement);
        if (agreement.share < p.pair_wall_min_agreement ||
            agreement.pinning > p.pair_wall_max_pinning)
            continue;
        places[i] = q;
        slack[i] = 0.0;
        ++by_walls;
    }
}

}  // namespace mrpt_topoeval::internal
