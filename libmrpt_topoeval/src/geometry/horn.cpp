/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "geometry/horn.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace mrpt_topoeval
{
Eigen::Vector2d Transform2D::apply(const Eigen::Vector2d& p) const
{
    // Callers apply one transform to many points in a row (the matcher's consensus places
    // every candidate under each pair's proposal: its sine and cosine were 4 % of a compare).
    // The last yaw's are kept per thread, matched by the yaw's bits (-0 and 0 differ in sine):
    // the same numbers as computed afresh.
    thread_local std::uint64_t last_yaw_bits = 0;
    thread_local double c = 1.0, s = 0.0;  // those of yaw 0 (all bits 0)
    std::uint64_t bits;
    std::memcpy(&bits, &yaw_deg, sizeof bits);
    if (bits != last_yaw_bits)
    {
        const double a = yaw_deg * M_PI / 180.0;
        c = std::cos(a), s = std::sin(a);
        last_yaw_bits = bits;
    }
    return {x_m + c * p.x() - s * p.y(), y_m + s * p.x() + c * p.y()};
}

namespace internal
{
Transform2D hornAlign(const std::vector<Eigen::Vector2d>& gt,
                      const std::vector<Eigen::Vector2d>& map, double* mse)
{
    const std::size_t n = gt.size();
    Transform2D t;
    if (n == 0)
    {
        if (mse) *mse = 0.0;
        return t;
    }
    Eigen::Vector2d cg = Eigen::Vector2d::Zero(), cm = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < n; ++i)
    {
        cg += gt[i];
        cm += map[i];
    }
    cg /= double(n);
    cm /= double(n);
    // theta = atan2(sum m' x g', sum m' . g') on centred points.
    double sc = 0.0, ss = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const Eigen::Vector2d g = gt[i] - cg, m = map[i] - cm;
        sc += m.dot(g);
        ss += m.x() * g.y() - m.y() * g.x();
    }
    const double theta = (n >= 2 && (sc != 0.0 || ss != 0.0)) ? std::atan2(ss, sc) : 0.0;
    const double c = std::cos(theta), s = std::sin(theta);
    t.yaw_deg = theta * 180.0 / M_PI;
    t.x_m = cg.x() - (c * cm.x() - s * cm.y());
    t.y_m = cg.y() - (s * cm.x() + c * cm.y());
    if (mse)
    {
        double sum = 0.0;
        for (std::size_t i = 0; i < n; ++i) sum += (gt[i] - t.apply(map[i])).squaredNorm();
        *mse = sum / double(n);
    }
    return t;
}

std::vector<double> leaveOneOutSquaredErrors(const std::vector<Eigen::Vector2d>& gt,
                                             const std::vector<Eigen::Vector2d>& map)
{
    const std::size_t n = gt.size();
    std::vector<double> out(n, 0.0);
    if (n < 3) return out;
    // About the centroids, so the sums stay well conditioned far from the origin.
    Eigen::Vector2d cg = Eigen::Vector2d::Zero(), cm = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < n; ++i) cg += gt[i], cm += map[i];
    cg /= double(n);
    cm /= double(n);
    auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b)
    { return a.x() * b.y() - a.y() * b.x(); };
    double dot_sum = 0.0, cross_sum = 0.0;  // sum of m.g and m x g
    for (std::size_t i = 0; i < n; ++i)
    {
        dot_sum += (map[i] - cm).dot(gt[i] - cg);
        cross_sum += cross(map[i] - cm, gt[i] - cg);
    }
    const double rest = double(n - 1);
    for (std::size_t k = 0; k < n; ++k)
    {
        const Eigen::Vector2d g = gt[k] - cg, m = map[k] - cm;
        // The others' centroids (the sums of all are zero) and centred sums, as hornAlign().
        const Eigen::Vector2d g_bar = -g / rest, m_bar = -m / rest;
        const double sc = dot_sum - m.dot(g) - rest * m_bar.dot(g_bar);
        const double ss = cross_sum - cross(m, g) - rest * cross(m_bar, g_bar);
        const double theta = (sc != 0.0 || ss != 0.0) ? std::atan2(ss, sc) : 0.0;
        const Eigen::Rotation2Dd R(theta);
        out[k] = (g - (R * (m - m_bar) + g_bar)).squaredNorm();
    }
    return out;
}

std::optional<Eigen::Vector2d> agreementPoint(const Transform2D& a, const Transform2D& b)
{
    // a(m) = b(m): (Ra - Rb) m = tb - ta. Ra - Rb is a rotation scaled by 2 sin(turn / 2),
    // invertible unless the yaws are equal (a turn of 1e-6 degrees puts the point ~10^7 times
    // the shift away, farther than any test of its distance).
    const double ya = a.yaw_deg * M_PI / 180.0, yb = b.yaw_deg * M_PI / 180.0;
    const double c = std::cos(ya) - std::cos(yb), s = std::sin(ya) - std::sin(yb);
    const double det = c * c + s * s;
    if (!(det > 1e-16)) return std::nullopt;
    const Eigen::Vector2d rhs(b.x_m - a.x_m, b.y_m - a.y_m);
    const Eigen::Vector2d m((c * rhs.x() + s * rhs.y()) / det, (-s * rhs.x() + c * rhs.y()) / det);
    return a.apply(m);
}
double partOffset(const Transform2D& own, const std::vector<Transform2D>& others,
                  const std::vector<Eigen::Vector2d>& points)
{
    double best = std::numeric_limits<double>::infinity();
    if (points.empty()) return best;
    for (const Transform2D& other : others)
    {
        double sum = 0.0;
        for (const Eigen::Vector2d& q : points)
            sum += (own.apply(q) - other.apply(q)).squaredNorm();
        best = std::min(best, sum);
    }
    return std::sqrt(best / double(points.size()));
}

}  // namespace internal
}  // namespace mrpt_topoeval
