/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Paper III-B, Algorithm 1: subgraph isomorphisms by wavefront propagation.

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>

#include "matching/matching.h"

namespace mrpt_topoeval::internal
{
double angleDistance(double a, double b)
{
    const double d = std::fmod(std::abs(a - b), 2.0 * M_PI);
    return std::min(d, 2.0 * M_PI - d);
}

namespace
{
// The state one wavefront grows: the assignment (on top of the context's accepted pairs) and
// the edge assignment, so that once one edge of a vertex is matched its ring's rotation is
// fixed ("at most one assignment can be returned").
struct State
{
    std::vector<int> a2b, b2a;      // vertices: this wavefront's and the context's accepted pairs
    std::vector<int> ea2eb, eb2ea;  // view edges
    std::deque<std::pair<int, int>> wavefront;
    std::vector<std::pair<int, int>> pairs;  // this wavefront's pairs, in order
    double similarity_sum = 0.0;
};

class Wavefront
{
public:
    explicit Wavefront(const MatchContext& ctx) : m_ctx(ctx)
    {
        int max_edge = 0;
        for (const auto* view : {&ctx.gt, &ctx.map})
            for (const auto& v : view->v)
                for (const auto& inc : v.ring) max_edge = std::max(max_edge, inc.edge + 1);
        m_num_edges = max_edge;
    }

    // Grows the isomorphism seeded by (a, b); returns the biggest found.
    State grow(int a, int b)
    {
        State s;
        s.a2b = m_ctx.gt_to_map;
        s.b2a = m_ctx.map_to_gt;
        s.ea2eb.assign(m_num_edges, -1);
        s.eb2ea.assign(m_num_edges, -1);
        addPair(s, a, b);
        m_branches = m_ctx.params.max_branches_per_seed;
        propagate(s);
        return s;
    }

private:
    bool sameLength(double la, double lb) const
    {
        const auto& p = m_ctx.params;
        return std::abs(la - lb) <=
               p.edge_length_factor * std::max(la, lb) + p.edge_length_allowance_m;
    }

    // A new pair may join if both vertices are free, active, of the same degree and similar
    // enough (the isomorphism's rule: number of edges must agree).
    bool canPair(const State& s, int a, int b) const
    {
        const ViewVertex &va = m_ctx.gt.v[a], &vb = m_ctx.map.v[b];
        return va.active && vb.active && s.a2b[a] < 0 && s.b2a[b] < 0 &&
               va.degree() == vb.degree() &&
               m_ctx.similarity(a, b) >= m_ctx.params.min_isomorphism_similarity;
    }

    void addPair(State& s, int a, int b)
    {
        s.a2b[a] = b;
        s.b2a[b] = a;
        s.pairs.emplace_back(a, b);
        s.similarity_sum += m_ctx.similarity(a, b);
        s.wavefront.emplace_back(a, b);
    }

    // checkEdgeAssignmentForConsistency for every rotation k of b's ring against a's: edges in
    // the same cyclic (geometric) order, lengths and ring angles that agree, neighbours either
    // already matched to each other or free to be, edges not matched elsewhere.
    std::vector<int> goodAssignments(const State& s, int a, int b) const
    {
        const ViewVertex &va = m_ctx.gt.v[a], &vb = m_ctx.map.v[b];
        const int d = va.degree();
        const double max_gap = m_ctx.params.max_angle_difference_deg * M_PI / 180.0;
        std::vector<int> good;
        for (int k = 0; k < d; ++k)
        {
            bool ok = true;
            // Within one rotation a gt edge seen twice (a loop) must map to one map edge.
            std::vector<std::pair<int, int>> local;
            for (int j = 0; j < d && ok; ++j)
            {
                const ViewIncidence& ia = va.ring[j];
                const ViewIncidence& ib = vb.ring[(j + k) % d];
                if ((ia.other == a) != (ib.other == b)) ok = false;
                if (ok && s.ea2eb[ia.edge] >= 0 && s.ea2eb[ia.edge] != ib.edge) ok = false;
                if (ok && s.eb2ea[ib.edge] >= 0 && s.eb2ea[ib.edge] != ia.edge) ok = false;
                for (const auto& [ea, eb] : local)
                    if ((ea == ia.edge) != (eb == ib.edge)) ok = false;
                local.emplace_back(ia.edge, ib.edge);
                if (!ok) break;
                const int na = ia.other, nb = ib.other;
                if (s.a2b[na] >= 0 || s.b2a[nb] >= 0)
                    ok = s.a2b[na] == nb && s.b2a[nb] == na;
                else
                    ok = canPair(s, na, nb);
                ok = ok && sameLength(ia.length_m, ib.length_m) &&
                     std::abs(va.gaps_rad[j] - vb.gaps_rad[(j + k) % d]) <= max_gap;
            }
            if (ok) good.push_back(k);
        }
        return good;
    }

    // addToVertexAssignmentAndWavefront
    void apply(State& s, int a, int b, int k)
    {
        const ViewVertex &va = m_ctx.gt.v[a], &vb = m_ctx.map.v[b];
        const int d = va.degree();
        for (int j = 0; j < d; ++j)
        {
            const ViewIncidence& ia = va.ring[j];
            const ViewIncidence& ib = vb.ring[(j + k) % d];
            s.ea2eb[ia.edge] = ib.edge;
            s.eb2ea[ib.edge] = ia.edge;
            if (s.a2b[ia.other] < 0) addPair(s, ia.other, ib.other);
        }
    }

    static bool better(const State& x, const State& y)
    {
        if (x.pairs.size() != y.pairs.size()) return x.pairs.size() > y.pairs.size();
        return x.similarity_sum > y.similarity_sum + 1e-12;
    }

    // wavefrontProp: pairs with one good assignment extend the wavefront; several good ones
    // (in practice only at the seed, whose ring rotation nothing fixes yet) branch, each branch
    // on a copy, and the biggest result wins. The branch budget bounds the recursion on
    // repetitive maps: once spent, the first good assignment is taken without exploring.
    void propagate(State& s)
    {
        while (!s.wavefront.empty())
        {
            const auto [a, b] = s.wavefront.front();
            s.wavefront.pop_front();
            const std::vector<int> good = goodAssignments(s, a, b);
            if (good.empty()) continue;
            if (good.size() == 1 || m_branches <= 0)
            {
                apply(s, a, b, good.front());
                continue;
            }
            State best;
            bool have_best = false;
            for (int k : good)
            {
                if (m_branches <= 0) break;
                --m_branches;
                State copy = s;
                apply(copy, a, b, k);
                propagate(copy);
                if (!have_best || better(copy, best))
                {
                    best = std::move(copy);
                    have_best = true;
                }
            }
            s = std::move(best);
            return;
        }
    }

    const MatchContext& m_ctx;
    int m_num_edges = 0;
    int m_branches = 0;
};
}  // namespace

int minIsomorphismSize(const GraphMatcherParameters& params, int n_gt, int n_map)
{
    const int smaller = std::min(n_gt, n_map);
    return std::min(
        params.min_isomorphism_vertices,
        std::max(3, static_cast<int>(std::ceil(params.min_isomorphism_share * smaller))));
}

std::vector<Isomorphism> findIsomorphisms(MatchContext& ctx)
{
    const int na = static_cast<int>(ctx.gt.v.size()), nb = static_cast<int>(ctx.map.v.size());
    // Seeds in order of their best similarity, so distinctive places anchor first.
    std::vector<int> order;
    std::vector<double> best_sim(na, 0.0);
    for (int a = 0; a < na; ++a)
    {
        if (!ctx.gt.v[a].active) continue;
        order.push_back(a);
        if (nb > 0) best_sim[a] = ctx.similarity.row(a).maxCoeff();
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](int x, int y) { return best_sim[x] > best_sim[y]; });

    const int min_size = minIsomorphismSize(ctx.params, ctx.gt.numActive(), ctx.map.numActive());

    Wavefront wf(ctx);
    std::vector<Isomorphism> accepted;
    for (int a : order)
    {
        if (ctx.gt_to_map[a] >= 0) continue;
        State best;
        bool have_best = false;
        for (int b = 0; b < nb; ++b)
        {
            const ViewVertex& vb = ctx.map.v[b];
            if (!vb.active || ctx.map_to_gt[b] >= 0 || vb.degree() != ctx.gt.v[a].degree() ||
                ctx.similarity(a, b) < ctx.params.min_isomorphism_similarity)
                continue;
            State s = wf.grow(a, b);
            if (!have_best || s.pairs.size() > best.pairs.size() ||
                (s.pairs.size() == best.pairs.size() && s.similarity_sum > best.similarity_sum))
            {
                best = std::move(s);
                have_best = true;
            }
        }
        if (!have_best || static_cast<int>(best.pairs.size()) < min_size) continue;
        Isomorphism iso;
        iso.pairs = best.pairs;
        for (const auto& [x, y] : iso.pairs)
        {
            ctx.gt_to_map[x] = y;
            ctx.map_to_gt[y] = x;
        }
        accepted.push_back(std::move(iso));
    }
    return accepted;
}

}  // namespace mrpt_topoeval::internal
