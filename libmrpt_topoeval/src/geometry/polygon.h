/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <Eigen/Core>
#include <vector>

namespace mrpt_topoeval::internal
{
/** Signed area of a closed polygon (shoelace): positive when its points run counter-clockwise.
 * Used for the orientation of a loop edge's path and of the alpha shape's boundary loops. */
inline double signedArea(const std::vector<Eigen::Vector2d>& polygon)
{
    double a = 0.0;
    if (polygon.empty()) return a;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
        a += polygon[j].x() * polygon[i].y() - polygon[i].x() * polygon[j].y();
    return 0.5 * a;
}
}  // namespace mrpt_topoeval::internal
