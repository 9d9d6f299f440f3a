/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <utility>
#include <vector>

namespace mrpt_topoeval::internal
{
/** Chains oriented boundary segments (interior on the left, endpoints on integer cell
 * coordinates) into closed polygons and returns the outer one (counter-clockwise: a hole's
 * boundary runs clockwise) with the longest perimeter: the map's outer boundary (paper II-B).
 * `num_polygons` receives how many closed polygons there were, holes included. */
std::vector<Eigen::Vector2d> longestBoundaryPolygon(
    const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& segments,
    std::size_t* num_polygons = nullptr);

/** Even-odd point-in-polygon test. */
bool pointInPolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

}  // namespace mrpt_topoeval::internal
