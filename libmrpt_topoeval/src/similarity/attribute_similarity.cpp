/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Paper III-A, first approach: vertex similarity from the Topology Graph's attributes.

#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "graph/MatchView.h"

namespace mrpt_topoeval
{
namespace
{
using internal::MatchView;
using internal::ViewVertex;

constexpr double kRadToDeg = 180.0 / M_PI;

// 1 when diff is 0, falling linearly to 0 at tol.
double ramp(double diff, double tol) { return std::max(0.0, 1.0 - std::abs(diff) / tol); }

struct Terms
{
    double angles = 0, lengths = 0, edge_clearance = 0;
};

double combine(const Terms& t, double vertex_clearance, const VertexSimilarityParameters& p)
{
    const double w =
        p.weight_angles + p.weight_lengths + p.weight_vertex_clearance + p.weight_edge_clearance;
    return (p.weight_angles * t.angles + p.weight_lengths * t.lengths +
            p.weight_vertex_clearance * vertex_clearance +
            p.weight_edge_clearance * t.edge_clearance) /
           w;
}

double lengthTerm(double la, double lb, const VertexSimilarityParameters& p)
{
    const double m = std::max({la, lb, 1e-9});
    return ramp((la - lb) / m, p.length_tolerance);
}

// Equal degrees: the terms for ring b shifted by k against ring a (edge j of a <-> edge j+k of
// b), the rotation-independent comparison the paper's ring buffer allows.
Terms alignedTerms(const ViewVertex& a, const ViewVertex& b, int k,
                   const VertexSimilarityParameters& p)
{
    const int d = a.degree();
    Terms t;
    double angle_err = 0.0;
    for (int j = 0; j < d; ++j)
    {
        const int jb = (j + k) % d;
        angle_err += std::abs(a.gaps_rad[j] - b.gaps_rad[jb]);
        t.lengths += lengthTerm(a.ring[j].length_m, b.ring[jb].length_m, p);
        t.edge_clearance +=
            ramp(a.ring[j].mean_clearance_m - b.ring[jb].mean_clearance_m, p.clearance_tolerance_m);
    }
    t.angles = ramp(angle_err / d * kRadToDeg, p.angle_tolerance_deg);
    t.lengths /= d;
    t.edge_clearance /= d;
    return t;
}

// Different degrees: smallest and largest ring angles, and the edges compared longest to
// longest; then a factor per unit of degree difference.
Terms unalignedTerms(const ViewVertex& a, const ViewVertex& b, const VertexSimilarityParameters& p)
{
    auto sortedDesc = [](const ViewVertex& v, auto field)
    {
        std::vector<double> x;
        for (const auto& inc : v.ring) x.push_back(field(inc));
        std::sort(x.rbegin(), x.rend());
        return x;
    };
    Terms t;
    const auto [amin, amax] = std::minmax_element(a.gaps_rad.begin(), a.gaps_rad.end());
    const auto [bmin, bmax] = std::minmax_element(b.gaps_rad.begin(), b.gaps_rad.end());
    t.angles = ramp(0.5 * (std::abs(*amin - *bmin) + std::abs(*amax - *bmax)) * kRadToDeg,
                    p.angle_tolerance_deg);
    const auto la = sortedDesc(a, [](const auto& i) { return i.length_m; });
    const auto lb = sortedDesc(b, [](const auto& i) { return i.length_m; });
    const auto ca = sortedDesc(a, [](const auto& i) { return i.mean_clearance_m; });
    const auto cb = sortedDesc(b, [](const auto& i) { return i.mean_clearance_m; });
    const std::size_t n = std::min(la.size(), lb.size());
    for (std::size_t j = 0; j < n; ++j)
    {
        t.lengths += lengthTerm(la[j], lb[j], p) / n;
        t.edge_clearance += ramp(ca[j] - cb[j], p.clearance_tolerance_m) / n;
    }
    return t;
}

// Base similarity and, for equal degrees, the best ring shift (-1 otherwise).
double baseSimilarity(const ViewVertex& a, const ViewVertex& b, const VertexSimilarityParameters& p,
                      int* best_shift)
{
    *best_shift = -1;
    if (!a.active || !b.active) return 0.0;
    const double vclr = ramp(a.clearance_m - b.clearance_m, p.clearance_tolerance_m);
    const int da = a.degree(), db = b.degree();
    if (da != db)
        return combine(unalignedTerms(a, b, p), vclr, p) *
               std::pow(p.degree_mismatch_factor, std::abs(da - db));
    double best = -1.0;
    for (int k = 0; k < da; ++k)
    {
        const double s = combine(alignedTerms(a, b, k, p), vclr, p);
        if (s > best)
        {
            best = s;
            *best_shift = k;
        }
    }
    return best;
}
}  // namespace

SimilarityMatrix attributeSimilarity(const TopologyGraph& a, const TopologyGraph& b,
                                     const VertexSimilarityParameters& p)
{
    p.validate();
    const MatchView va = internal::makeMatchView(a), vb = internal::makeMatchView(b);
    const int na = static_cast<int>(va.v.size()), nb = static_cast<int>(vb.v.size());
    SimilarityMatrix s = SimilarityMatrix::Zero(na, nb);
    Eigen::MatrixXi shift = Eigen::MatrixXi::Constant(na, nb, -1);
    for (int i = 0; i < na; ++i)
        for (int j = 0; j < nb; ++j) s(i, j) = baseSimilarity(va.v[i], vb.v[j], p, &shift(i, j));

    // Paper III-A: "The results ... can be improved by taking the similarities of the
    // neighboring vertices into account": blend in the mean similarity of the neighbours that
    // the best ring alignment pairs up (for different degrees there is no such pairing, and the
    // blend uses the pair's own value).
    for (int it = 0; it < p.neighbour_iterations && p.neighbour_weight > 0.0; ++it)
    {
        SimilarityMatrix next = s;
        for (int i = 0; i < na; ++i)
            for (int j = 0; j < nb; ++j)
            {
                if (s(i, j) <= 0.0 || shift(i, j) < 0) continue;
                const auto& ra = va.v[i].ring;
                const auto& rb = vb.v[j].ring;
                const int d = static_cast<int>(ra.size());
                double nsum = 0.0;
                for (int k = 0; k < d; ++k) nsum += s(ra[k].other, rb[(k + shift(i, j)) % d].other);
                next(i, j) = (1.0 - p.neighbour_weight) * s(i, j) + p.neighbour_weight * nsum / d;
            }
        s = std::move(next);
    }
    return s;
}

}  // namespace mrpt_topoeval
