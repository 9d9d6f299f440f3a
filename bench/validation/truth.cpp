/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "truth.h"

#include <cmath>
#include <sstream>

namespace mrpt_topoeval::validation
{
Eigen::Vector2d Rigid2D::apply(const Eigen::Vector2d& p) const
{
    const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
    return {c * p.x() - s * p.y() + t_m.x(), s * p.x() + c * p.y() + t_m.y()};
}

Rigid2D Rigid2D::inverse() const
{
    Rigid2D inv;
    inv.yaw_rad = -yaw_rad;
    const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
    // R^T (-t)
    inv.t_m = {-(c * t_m.x() + s * t_m.y()), -(-s * t_m.x() + c * t_m.y())};
    return inv;
}

std::string fmt(double v, int decimals)
{
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(decimals);
    s << v;
    return s.str();
}

Rigid2D Rigid2D::compose(const Rigid2D& other) const
{
    Rigid2D r;
    r.yaw_rad = std::remainder(yaw_rad + other.yaw_rad, 2.0 * M_PI);
    r.t_m = apply(other.t_m);
    return r;
}
}  // namespace mrpt_topoeval::validation
