/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Paper III-B, last paragraph: neighbour growing, "a wavefront approach which has relaxed
// constraints and is heavily guided by the vertex similarity".

#include <cmath>
#include <queue>
#include <tuple>

#include "matching/matching.h"

namespace mrpt_topoeval::internal
{
namespace
{
using internal::MatchView;

struct GrowthCandidate
{
    double score;
    int gt, map, from_gt;
    bool operator<(const GrowthCandidate& o) const
    {
        // priority_queue pops the largest: highest similarity, then lowest ids.
        return std::tie(score, o.gt, o.map) < std::tie(o.score, gt, map);
    }
};

// Directions of the first edges from v that reach an assigned vertex, directly or through one
// unassigned vertex: (assigned vertex, angle).
std::vector<std::pair<int, double>> assignedLinks(const MatchView& view,
                                                  const std::vector<int>& assigned, int v)
{
    std::vector<std::pair<int, double>> out;
    for (const auto& inc : view.v[v].ring)
    {
        const int n = inc.other;
        if (n == v) continue;
        if (assigned[n] >= 0)
        {
            out.emplace_back(n, inc.angle_rad);
            continue;
        }
        for (const auto& inc2 : view.v[n].ring)
            if (inc2.other != v && inc2.other != n && assigned[inc2.other] >= 0)
                out.emplace_back(inc2.other, inc.angle_rad);
    }
    return out;
}

// The rotation between the two maps' frames at an assigned pair (circular mean over the edges
// that lead to pairs assigned to each other); false if there is none.
bool localRotation(const MatchContext& ctx, int a, int b, double* theta)
{
    double sx = 0.0, sy = 0.0;
    int n = 0;
    const auto la = assignedLinks(ctx.gt, ctx.gt_to_map, a);
    const auto lb = assignedLinks(ctx.map, ctx.map_to_gt, b);
    for (const auto& [ta, alpha] : la)
        for (const auto& [tb, beta] : lb)
            if (ctx.gt_to_map[ta] == tb)
            {
                sx += std::cos(alpha - beta);
                sy += std::sin(alpha - beta);
                ++n;
                break;
            }
    if (n == 0) return false;
    *theta = std::atan2(sy, sx);
    return true;
}

// A vertex reachable from an assigned vertex along its ring: directly (one hop) or through
// one unassigned vertex (two hops). Two hops is the relaxation that bridges a vertex that
// exists in only one of the graphs (a junction one map shows and the other does not).
struct Reach
{
    int vertex;
    double angle_rad;  // direction of the first edge
    double length_m;   // path length
    int hops;
};

std::vector<Reach> reachable(const MatchView& view, const std::vector<int>& assigned, int v)
{
    std::vector<Reach> out;
    for (const auto& inc : view.v[v].ring)
    {
        const int n = inc.other;
        if (n == v || !view.v[n].active || assigned[n] >= 0) continue;
        out.push_back({n, inc.angle_rad, inc.length_m, 1});
        for (const auto& inc2 : view.v[n].ring)
        {
            const int m = inc2.other;
            if (m == v || m == n || inc2.edge == inc.edge || !view.v[m].active || assigned[m] >= 0)
                continue;
            out.push_back({m, inc.angle_rad, inc.length_m + inc2.length_m, 2});
        }
    }
    return out;
}

}  // namespace

std::vector<GrownPair> growNeighbours(MatchContext& ctx, std::vector<int>& iso_of_gt)
{
    const auto& p = ctx.params;
    const double max_angle = p.max_angle_difference_deg * M_PI / 180.0;
    // Each hop skipped lowers a candidate's priority, so direct neighbours are paired first.
    constexpr double kSkipPenalty = 0.8;
    std::priority_queue<GrowthCandidate> queue;

    // Unassigned pairs reachable from an assigned pair along edges that leave in matching
    // directions (after the local rotation) with roughly the same path length.
    auto offer = [&](int a, int b)
    {
        double theta = 0.0;
        if (!localRotation(ctx, a, b, &theta)) return;
        const std::vector<Reach> ra = reachable(ctx.gt, ctx.gt_to_map, a);
        const std::vector<Reach> rb = reachable(ctx.map, ctx.map_to_gt, b);
        for (const Reach& x : ra)
            for (const Reach& y : rb)
            {
                if (angleDistance(x.angle_rad - y.angle_rad, theta) > max_angle) continue;
                const double tol = p.growing_edge_length_factor * std::max(x.length_m, y.length_m) +
                                   p.growing_edge_length_allowance_m;
                if (std::abs(x.length_m - y.length_m) > tol) continue;
                const double s = ctx.similarity(x.vertex, y.vertex);
                if (s < p.min_growing_similarity) continue;
                const int skipped = x.hops + y.hops - 2;
                queue.push({s * std::pow(kSkipPenalty, skipped), x.vertex, y.vertex, a});
            }
    };
    for (int a = 0; a < static_cast<int>(ctx.gt_to_map.size()); ++a)
        if (ctx.gt_to_map[a] >= 0) offer(a, ctx.gt_to_map[a]);

    std::vector<GrownPair> grown;
    while (!queue.empty())
    {
        const GrowthCandidate c = queue.top();
        queue.pop();
        if (ctx.gt_to_map[c.gt] >= 0 || ctx.map_to_gt[c.map] >= 0) continue;
        ctx.gt_to_map[c.gt] = c.map;
        ctx.map_to_gt[c.map] = c.gt;
        iso_of_gt[c.gt] = iso_of_gt[c.from_gt];
        grown.push_back({c.gt, c.map, iso_of_gt[c.gt]});
        offer(c.gt, c.map);
    }
    return grown;
}

}  // namespace mrpt_topoeval::internal
