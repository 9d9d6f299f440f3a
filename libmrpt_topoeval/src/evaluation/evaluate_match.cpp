/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Paper IV: map attributes from a match of two Topology Graphs, and the scores built on them.

#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/evaluation/evaluate_match.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/matching/match_graphs.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <future>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <queue>
#include <sstream>
#include <system_error>

#include "evaluation/evaluate_match_at.h"
#include "evaluation/explained_walls.h"
#include "evaluation/wall_parts.h"
#include "evaluation/wall_places.h"
#include "geometry/horn.h"
#include "geometry/rigid_split.h"
#include "graph/MatchView.h"
#include "matching/wall_agreement.h"

namespace mrpt_topoeval
{
// ---------------------------------------------------------------- attributes
namespace
{
double invScore(double error, double scale) { return 1.0 / (1.0 + error / scale); }

// Shortest path lengths along the graph's edges from `src` to every vertex (Dijkstra).
std::vector<double> graphDistances(const TopologyGraph& g, int src)
{
    std::vector<double> d(g.vertices.size(), std::numeric_limits<double>::infinity());
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
    d[src] = 0.0;
    q.emplace(0.0, src);
    while (!q.empty())
    {
        const auto [du, u] = q.top();
        q.pop();
        if (du > d[u]) continue;
        for (const Incidence& inc : g.vertices[u].ring)
        {
            const double nd = du + g.edges[inc.edge].length_m;
            if (nd < d[inc.other_vertex])
            {
                d[inc.other_vertex] = nd;
                q.emplace(nd, inc.other_vertex);
            }
        }
    }
    return d;
}

// The jitter a pair's position error may have without being map error (vertex_slack_share).
double pairSlack(const TopologyGraph& gt, const TopologyGraph& map, const VertexPair& pr,
                 const QualityParameters& p)
{
    return p.vertex_slack_share *
           std::max(gt.vertices[pr.ground_truth].clearance_m, map.vertices[pr.map].clearance_m);
}

// An error as the robust scores count it: beyond the slack, at most outlier_distance_m.
double countedError(double error, double slack, const QualityParameters& p)
{
    const double e = std::max(0.0, error - slack);
    return p.outlier_distance_m > 0.0 ? std::min(e, p.outlier_distance_m) : e;
}

// Horn's fit of the pairs (pg[i], pts[i]) that `t` places within outlier_m of each other (all
// of them when outlier_m is 0), and how many those are; `t` itself when fewer than 2.
struct InlierFit
{
    Transform2D transform;
    std::size_t inliers = 0;
};
InlierFit fitOfInliers(const std::vector<Eigen::Vector2d>& pg,
                       const std::vector<Eigen::Vector2d>& pts, const Transform2D& t,
                       double outlier_m)
{
    std::vector<Eigen::Vector2d> ig, im;
    for (std::size_t i = 0; i < pg.size(); ++i)
        if (!(outlier_m > 0.0) || (pg[i] - t.apply(pts[i])).norm() <= outlier_m)
        {
            ig.push_back(pg[i]);
            im.push_back(pts[i]);
        }
    return {ig.size() >= 2 ? internal::hornAlign(ig, im) : t, ig.size()};
}

// Paper IV, local consistency: all pairs of matched ground-truth vertices, grouped by their
// shortest graph distance; in each class the mean difference between the pair's geometric
// distance in the ground truth and in the map (beyond the pairs' slack, clipped at the outlier
// distance: doc/quality.md).
std::vector<ConsistencyClass> localConsistency(const TopologyGraph& gt, const GraphMatch& m,
                                               const std::vector<Eigen::Vector2d>& places,
                                               const std::vector<double>& slack,
                                               const QualityParameters& p)
{
    std::vector<ConsistencyClass> cls = {
        {"short", 0.0, p.consistency_short_max_m, 0, 0.0, 0.0},
        {"medium", p.consistency_short_max_m, p.consistency_medium_max_m, 0, 0.0, 0.0},
        {"long", p.consistency_medium_max_m, std::numeric_limits<double>::infinity(), 0, 0.0, 0.0}};
    for (std::size_t i = 0; i < m.pairs.size(); ++i)
    {
        const std::vector<double> dist = graphDistances(gt, m.pairs[i].ground_truth);
        for (std::size_t j = i + 1; j < m.pairs.size(); ++j)
        {
            const double dg = dist[m.pairs[j].ground_truth];
            if (!std::isfinite(dg)) continue;
            const double d_gt = (gt.vertices[m.pairs[i].ground_truth].position_m -
                                 gt.vertices[m.pairs[j].ground_truth].position_m)
                                    .norm();
            const double d_map = (places[i] - places[j]).norm();
            ConsistencyClass& c = dg < p.consistency_short_max_m    ? cls[0]
                                  : dg < p.consistency_medium_max_m ? cls[1]
                                                                    : cls[2];
            ++c.pairs;
            c.mean_error_m += countedError(std::abs(d_gt - d_map), slack[i] + slack[j], p);
        }
    }
    for (auto& c : cls)
        if (c.pairs > 0)
        {
            c.mean_error_m /= double(c.pairs);
            c.score = invScore(c.mean_error_m, p.consistency_scale_m);
        }
    return cls;
}

// The 95 % quantile of Fisher's F distribution with 3 and `dof` degrees of freedom (tables;
// between rows, the next smaller dof, which is larger: conservative).
double f3Quantile95(int dof)
{
    static const std::pair<int, double> rows[] = {
        {1, 215.7}, {2, 19.16}, {3, 9.28},  {4, 6.59},  {5, 5.41},  {6, 4.76},
        {7, 4.35},  {8, 4.07},  {9, 3.86},  {10, 3.71}, {12, 3.49}, {15, 3.29},
        {20, 3.10}, {30, 2.92}, {40, 2.84}, {60, 2.76}, {120, 2.68}};
    double q = rows[0].second;
    for (const auto& [d, v] : rows)
        if (dof >= d) q = v;
    return q;
}

// Ours (brokenness_wall_margin_m): a group's transform from the walls around its vertices. The
// vertices' fit decides the group; its turn is then as good as a few vertices that slide along
// the medial axis (0.1-0.2 degrees typically, 2-5 degrees on a small part near its cut), while
// the walls around them hold hundreds of points. ICP from the vertices' fit.
Transform2D refinedByWalls(const TopologyGraph& gt, const TopologyGraph& map,
                           const internal::WallIndex& gt_walls,
                           const internal::WallIndex& map_walls,
                           const std::vector<std::pair<int, int>>& pairs, const Transform2D& fit,
                           const QualityParameters& p)
{
    const auto walls_fit = internal::alignWalls(gt, map, gt_walls, map_walls, pairs,
                                                p.brokenness_wall_margin_m, fit, p);
    if (!walls_fit) return fit;
    const Transform2D& t = *walls_fit;
    // The walls' transform replaces the vertices' fit within the group's threshold, and where
    // the vertices do not reject it: inside the fit's 95 % confidence region (an F test of the
    // rise in the vertices' squared error, 3 parameters of a rigid fit against 2n - 3 degrees
    // of freedom left), or where the walls vouch for it (brokenness_walls_vouch, below). Walls
    // that slid along a corridor, or that disagree with the vertices, leave the fit as it is.
    auto sse = [&](const Transform2D& x)
    {
        double sum = 0.0;
        for (const auto& [a, b] : pairs)
            sum += (gt.vertices[static_cast<std::size_t>(a)].position_m -
                    x.apply(map.vertices[static_cast<std::size_t>(b)].position_m))
                       .squaredNorm();
        return sum;
    };
    const double n = double(pairs.size()), sse_fit = sse(fit), sse_walls = sse(t);
    if (sse_walls / n > p.brokenness_max_squared_error_m2) return fit;
    const int dof = 2 * static_cast<int>(pairs.size()) - 3;
    if (dof < 1) return fit;
    if ((sse_walls - sse_fit) / 3.0 <= f3Quantile95(dof) * sse_fit / double(dof)) return t;
    if (!p.brokenness_walls_vouch) return fit;
    // The test took the vertices' residual for their noise; a small part's vertices near its
    // cut slide with the cut's walls and their fit turns to absorb it. The walls vouch for
    // their transform when they agree under it, as well as under the vertices' fit at least,
    // and pin it (a corridor's walls that slid along it do not).
    const double tolerance = internal::pairWallTolerance(gt, map, p);
    const internal::WallAgreement by_walls =
        internal::wallAgreement(gt, map, gt_walls, map_walls, pairs, t, p.brokenness_wall_margin_m,
                                tolerance, p.pair_wall_min_agreement, p.pair_wall_max_pinning);
    if (!by_walls.walls_on_both ||
        !by_walls.vouches(p.pair_wall_min_agreement, p.pair_wall_max_pinning))
        return fit;
    // Its share only (a share never reaches 2: no pinning asked).
    const internal::WallAgreement by_fit = internal::wallAgreement(
        gt, map, gt_walls, map_walls, pairs, fit, p.brokenness_wall_margin_m, tolerance, 2.0);
    return by_walls.share >= by_fit.share ? t : fit;
}

// Paper IV, brokenness: grow groups of connected matched vertices by wavefront while their
// Horn alignment's mean squared error stays under the threshold; keep groups of at least the
// minimum size; the degree is the number of groups minus one.
Brokenness brokenness(const TopologyGraph& gt, const TopologyGraph& map,
                      const internal::MatchView& view, const GraphMatch& m,
                      const QualityParameters& p, internal::Walls& walls)
{
    Brokenness b;
    if (m.pairs.empty()) return b;
    std::vector<int> partner(gt.vertices.size(), -1), iso(gt.vertices.size(), -1);
    for (const auto& pr : m.pairs)
    {
        partner[pr.ground_truth] = pr.map;
        iso[pr.ground_truth] = pr.isomorphism;
    }
    // Neighbours in the ground truth, directly or through one unmatched vertex (as neighbour
    // growing links them).
    auto neighbours = [&](int v)
    {
        std::vector<int> out;
        for (const auto& inc : view.v[v].ring)
        {
            if (partner[inc.other] >= 0)
                out.push_back(inc.other);
            else
                for (const auto& inc2 : view.v[inc.other].ring)
                    if (inc2.other != v && partner[inc2.other] >= 0) out.push_back(inc2.other);
        }
        return out;
    };
    // Seeds: vertices of the biggest isomorphisms first, then by id.
    std::vector<std::size_t> iso_size(m.isomorphism_sizes.begin(), m.isomorphism_sizes.end());
    std::vector<int> seeds;
    for (const auto& pr : m.pairs) seeds.push_back(pr.ground_truth);
    std::stable_sort(seeds.begin(), seeds.end(),
                     [&](int x, int y)
                     {
                         const std::size_t sx =
                             iso[x] >= 0 && iso[x] < int(iso_size.size()) ? iso_size[iso[x]] : 0;
                         const std::size_t sy =
                             iso[y] >= 0 && iso[y] < int(iso_size.size()) ? iso_size[iso[y]] : 0;
                         return sx > sy;
                     });

    // The positions of `vs` and of their partners.
    auto pointsOf = [&](const std::vector<int>& vs)
    {
        std::pair<std::vector<Eigen::Vector2d>, std::vector<Eigen::Vector2d>> pts;
        for (int v : vs)
        {
            pts.first.push_back(gt.vertices[v].position_m);
            pts.second.push_back(map.vertices[partner[v]].position_m);
        }
        return pts;
    };
    auto fitOf = [&](const std::vector<int>& vs, double* mse)
    {
        const auto [pg, pm] = pointsOf(vs);
        return internal::hornAlign(pg, pm, mse);
    };
    // Sum over `vs`' map vertices q of |T_x(q) - T_y(q)|^2: how differently two transforms place
    // the same part.
    auto squaredGap = [&](const Transform2D& x, const Transform2D& y, const std::vector<int>& vs)
    {
        double sum = 0.0;
        for (int v : vs)
        {
            const Eigen::Vector2d q = map.vertices[partner[v]].position_m;
            sum += (x.apply(q) - y.apply(q)).squaredNorm();
        }
        return sum;
    };
    // |p - T(q)|^2 of ground-truth vertex v and its partner q: how far a transform places it.
    auto squaredErrorOf = [&](const Transform2D& t, int v)
    {
        return (gt.vertices[v].position_m - t.apply(map.vertices[partner[v]].position_m))
            .squaredNorm();
    };
    // Its mean over `vs`: how far a transform places a set's map vertices.
    auto squaredErrorUnder = [&](const Transform2D& t, const std::vector<int>& vs)
    {
        double sum = 0.0;
        for (int v : vs) sum += squaredErrorOf(t, v);
        return vs.empty() ? 0.0 : sum / double(vs.size());
    };
    // Step 2b: `vs` as its parts. A split into two sets, each connected and of at least
    // brokenness_min_part_vertices, is kept when each set's own fit is within the threshold,
    // the bigger set's fit places the smaller set beyond it (mean squared error; so step 4
    // would not absorb it) and the two fits lower the squared error by more than chance (F
    // test, 95 %, of 3 more parameters against 2n - 6 degrees of freedom); each set is then
    // split again.
    std::vector<int> index_of(gt.vertices.size(), -1);  // a vertex's place in the set split
    auto splitIntoParts = [&](const std::vector<int>& vs)
    {
        std::vector<std::vector<int>> done, todo{vs};
        while (!todo.empty())
        {
            std::vector<int> cur = std::move(todo.back());
            todo.pop_back();
            const auto [cg, cm] = pointsOf(cur);
            // Each member's neighbours among the members, as indices into `cur`.
            for (std::size_t i = 0; i < cur.size(); ++i) index_of[cur[i]] = static_cast<int>(i);
            std::vector<std::vector<int>> links(cur.size());
            for (std::size_t i = 0; i < cur.size(); ++i)
                for (int w : neighbours(cur[i]))
                    if (index_of[w] >= 0) links[i].push_back(index_of[w]);
            for (int v : cur) index_of[v] = -1;
            const auto split = internal::bestRigidSplit(
                cg, cm, links, p.brokenness_min_part_vertices, p.brokenness_min_vertices,
                p.brokenness_max_squared_error_m2);
            bool apart = false;
            std::vector<int> side[2];
            if (split)
            {
                for (std::size_t i = 0; i < cur.size(); ++i) side[split->side[i]].push_back(cur[i]);
                const double n = double(cur.size());
                double mse_whole = 0.0;
                internal::hornAlign(cg, cm, &mse_whole);
                const double sse_parts = split->squared_error_m2[0] * double(side[0].size()) +
                                         split->squared_error_m2[1] * double(side[1].size());
                const int dof = 2 * static_cast<int>(cur.size()) - 6;
                const int big = side[1].size() > side[0].size() ? 1 : 0;
                const double off = squaredErrorUnder(split->fit[big], side[1 - big]);
                apart =
                    dof >= 1 && split->squared_error_m2[0] <= p.brokenness_max_squared_error_m2 &&
                    split->squared_error_m2[1] <= p.brokenness_max_squared_error_m2 &&
                    off > p.brokenness_max_squared_error_m2 &&
                    (mse_whole * n - sse_parts) / 3.0 > f3Quantile95(dof) * sse_parts / double(dof);
            }
            if (!apart)
            {
                done.push_back(std::move(cur));
                continue;
            }
            todo.push_back(std::move(side[0]));
            todo.push_back(std::move(side[1]));
        }
        return done;
    };
    std::vector<char> taken(gt.vertices.size(), 0), seeded(gt.vertices.size(), 0);
    std::vector<std::vector<int>> small;  // groups under brokenness_min_vertices (step 6)
    // A group's parts (step 2b): a part of brokenness_min_vertices is a group, its vertices
    // taken; a smaller one of brokenness_min_part_vertices waits for step 6 and its vertices
    // stay free for the growth (a small group of the match can hold a pair of the neighbouring
    // part, which held there would keep the growth from the part's own group).
    auto keepParts = [&](const std::vector<int>& members)
    {
        const std::vector<std::vector<int>> parts = p.brokenness_split_parts
                                                        ? splitIntoParts(members)
                                                        : std::vector<std::vector<int>>{members};
        for (const std::vector<int>& part : parts)
        {
            const bool counted = static_cast<int>(part.size()) >= p.brokenness_min_vertices;
            if (!counted && static_cast<int>(part.size()) >= p.brokenness_min_part_vertices)
                small.push_back(part);
            if (!counted) continue;
            for (int v : part) taken[v] = seeded[v] = 1;
            BrokennessGroup g;
            g.gt_vertices = part;
            g.transform = fitOf(part, &g.squared_error_m2);
            b.groups.push_back(std::move(g));
        }
    };
    // Step 1a (ours, brokenness_from_match_groups): the match's groups first, the biggest
    // first, each its core pairs: found as one group by the matcher, their distances, fit and
    // walls verified. The pairs grown from a group are not taken along (growing places a pair
    // by the fit of the group's pairs near it, near a cut the other part's): the growth below
    // gives them to a part. A core whose own fit is beyond the threshold (the paper's
    // isomorphisms are not rigid fits) is left to the growth too.
    if (p.brokenness_from_match_groups)
    {
        std::vector<int> order(m.isomorphism_sizes.size());
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(),
                         [&](int x, int y)
                         { return m.isomorphism_sizes[x] > m.isomorphism_sizes[y]; });
        for (int k : order)
        {
            std::vector<int> core;
            for (const auto& pr : m.pairs)
                if (pr.isomorphism == k && pr.stage != MatchStage::NeighbourGrowing &&
                    !taken[pr.ground_truth])
                    core.push_back(pr.ground_truth);
            if (static_cast<int>(core.size()) < p.brokenness_min_part_vertices) continue;
            double mse = 0.0;
            fitOf(core, &mse);
            if (mse <= p.brokenness_max_squared_error_m2) keepParts(core);
        }
    }
    for (int seed : seeds)
    {
        if (taken[seed] || seeded[seed]) continue;
        seeded[seed] = 1;
        BrokennessGroup grp;
        std::vector<Eigen::Vector2d> pg, pm;
        std::vector<char> in(gt.vertices.size(), 0);
        std::queue<int> wave;
        auto tryAdd = [&](int v)
        {
            pg.push_back(gt.vertices[v].position_m);
            pm.push_back(map.vertices[partner[v]].position_m);
            double mse = 0.0;
            internal::hornAlign(pg, pm, &mse);
            if (mse <= p.brokenness_max_squared_error_m2)
            {
                grp.gt_vertices.push_back(v);
                in[v] = 1;
                wave.push(v);
                return true;
            }
            pg.pop_back();
            pm.pop_back();
            return false;
        };
        tryAdd(seed);
        while (!wave.empty())
        {
            const int v = wave.front();
            wave.pop();
            for (int n : neighbours(v))
                if (!taken[n] && !in[n]) tryAdd(n);
        }
        // Refinement: greedy growth lets an early, small group accept vertices with a
        // compromise transform (near a break both sides fit a little). Re-estimate the group's
        // transform and collect again, from the seed, the connected vertices that this
        // transform places within the threshold each; repeat until the group is stable.
        for (int round = 0; round < 5 && grp.gt_vertices.size() >= 2; ++round)
        {
            const Transform2D t = internal::hornAlign(pg, pm);
            auto fits = [&](int v)
            { return squaredErrorOf(t, v) <= p.brokenness_max_squared_error_m2; };
            std::vector<int> members;
            std::vector<char> mark(gt.vertices.size(), 0);
            std::queue<int> q;
            if (!fits(seed)) break;
            q.push(seed);
            mark[seed] = 1;
            while (!q.empty())
            {
                const int v = q.front();
                q.pop();
                members.push_back(v);
                for (int n : neighbours(v))
                    if (!taken[n] && !mark[n] && fits(n))
                    {
                        mark[n] = 1;
                        q.push(n);
                    }
            }
            if (members == grp.gt_vertices) break;
            grp.gt_vertices = members;
            pg.clear();
            pm.clear();
            for (int v : members)
            {
                pg.push_back(gt.vertices[v].position_m);
                pm.push_back(map.vertices[partner[v]].position_m);
            }
        }
        // Step 2b (ours): a group that is two parts. The threshold bounds the group's mean
        // squared error, not its shape: two parts turned 10 degrees against each other about a
        // pivot between them can both fit one compromise within it (held-out
        // angled_8004/broken_2: 13 vertices of two parts 11.5 degrees apart, mean squared error
        // 0.186 m^2 together, 0.005 each). Each part is then split off while its own fit and
        // the other's place it apart (brokenness_split_parts).
        keepParts(grp.gt_vertices);
    }
    // Brokenness counts parts misplaced against each other. Two groups whose transforms put
    // their vertices in the same places (mean squared difference of T_i(q) and T_j(q) over
    // both groups' map vertices within the threshold) are one part, split only by vertex noise
    // or by unmatched vertices between them: merge them.
    auto placementGap = [&](const BrokennessGroup& x, const BrokennessGroup& y)
    {
        const std::size_t n = x.gt_vertices.size() + y.gt_vertices.size();
        return n ? (squaredGap(x.transform, y.transform, x.gt_vertices) +
                    squaredGap(x.transform, y.transform, y.gt_vertices)) /
                       double(n)
                 : 0.0;
    };
    // The walls' refinement of a fit of `vs` (brokenness_wall_margin_m, below).
    auto byWalls = [&](const std::vector<int>& vs, const Transform2D& fit)
    {
        std::vector<std::pair<int, int>> pairs;
        for (int v : vs) pairs.emplace_back(v, partner[v]);
        return refinedByWalls(gt, map, walls.gt(), walls.map(), pairs, fit, p);
    };
    // Groups whose transforms place them alike are merged; the merged group's transform is its
    // vertices' fit, refined by its walls when the groups' transforms are (`walls_refined`).
    auto mergeSamePlacement = [&](bool walls_refined)
    {
        for (bool merged = true; merged;)
        {
            merged = false;
            for (std::size_t i = 0; i < b.groups.size() && !merged; ++i)
                for (std::size_t j = i + 1; j < b.groups.size() && !merged; ++j)
                {
                    if (placementGap(b.groups[i], b.groups[j]) > p.brokenness_max_squared_error_m2)
                        continue;
                    std::vector<int> u = b.groups[i].gt_vertices;
                    u.insert(u.end(), b.groups[j].gt_vertices.begin(),
                             b.groups[j].gt_vertices.end());
                    double mse = 0.0;
                    const Transform2D fit = fitOf(u, &mse);
                    // Merged by their walls, the whole must still be one group by its vertices
                    // (the paper's threshold), as every group the growth makes is.
                    if (walls_refined && mse > p.brokenness_max_squared_error_m2) continue;
                    b.groups[i].transform = walls_refined ? byWalls(u, fit) : fit;
                    b.groups[i].squared_error_m2 = mse;
                    b.groups[i].gt_vertices = std::move(u);
                    b.groups.erase(b.groups.begin() + static_cast<long>(j));
                    merged = true;
                }
        }
    };
    mergeSamePlacement(false);
    // A vertex that a bigger part's transform places within the threshold belongs to that
    // part: near a break, leftovers of both sides plus a few wrong pairs can form a small group
    // with a compromise rotation. Bigger groups take such members; what falls below the
    // minimum size is no group.
    std::stable_sort(b.groups.begin(), b.groups.end(),
                     [](const auto& x, const auto& y)
                     { return x.gt_vertices.size() > y.gt_vertices.size(); });
    for (std::size_t j = 1; j < b.groups.size(); ++j)
    {
        std::vector<int> keep;
        for (int v : b.groups[j].gt_vertices)
        {
            const Eigen::Vector2d q = map.vertices[partner[v]].position_m;
            bool moved = false;
            for (std::size_t i = 0; i < j && !moved; ++i)
                if ((gt.vertices[v].position_m - b.groups[i].transform.apply(q)).squaredNorm() <=
                    p.brokenness_max_squared_error_m2)
                {
                    b.groups[i].gt_vertices.push_back(v);
                    moved = true;
                }
            if (!moved) keep.push_back(v);
        }
        b.groups[j].gt_vertices = std::move(keep);
    }
    for (const auto& g : b.groups)
        if (static_cast<int>(g.gt_vertices.size()) < p.brokenness_min_vertices &&
            static_cast<int>(g.gt_vertices.size()) >= p.brokenness_min_part_vertices)
            small.push_back(g.gt_vertices);
    b.groups.erase(std::remove_if(b.groups.begin(), b.groups.end(),
                                  [&](const BrokennessGroup& g) {
                                      return static_cast<int>(g.gt_vertices.size()) <
                                             p.brokenness_min_vertices;
                                  }),
                   b.groups.end());
    // Ours: one wrong pair must not turn a part's fit. A pair a few metres off joins a group
    // when the compromise fit keeps the mean squared error within the threshold; each group's
    // member that the fit of the others places worst leaves while that error exceeds
    // brokenness_outlier_ratio x the threshold's root (leave-one-out, as robust registration
    // checks a correspondence against the rest), down to brokenness_min_vertices.
    const double outlier2 =
        p.brokenness_outlier_ratio * p.brokenness_outlier_ratio * p.brokenness_max_squared_error_m2;
    if (p.brokenness_outlier_ratio > 0.0)
        for (auto& g : b.groups)
            while (static_cast<int>(g.gt_vertices.size()) > p.brokenness_min_vertices)
            {
                const auto [pg, pm] = pointsOf(g.gt_vertices);
                const std::vector<double> e2 = internal::leaveOneOutSquaredErrors(pg, pm);
                const auto worst = std::max_element(e2.begin(), e2.end());
                if (*worst <= outlier2) break;
                g.gt_vertices.erase(g.gt_vertices.begin() + (worst - e2.begin()));
            }
    for (auto& g : b.groups) g.transform = fitOf(g.gt_vertices, &g.squared_error_m2);
    // Without their outliers two groups of one part may now place it alike: merge again.
    mergeSamePlacement(false);
    // Small parts (ours): a part of 3-4 matched vertices is too small for the paper's rule, but
    // when its own fit is good and every counted group places its map vertices clearly
    // elsewhere (mean squared gap of at least brokenness_part_min_gap_m2), it is a part turned
    // against the rest, as the parts of a map broken three times often are.
    // Or when its walls set it apart (brokenness_part_wall_ratio): 3-4 vertices near the cut
    // sit within a metre of where the neighbouring part's fit puts them even when their part
    // is turned 12 degrees; the hundreds of wall points around them are not. They must agree
    // under the part's own fit, refined by them (at least pair_wall_min_agreement), and every
    // counted group's fit must keep at most the ratio of that agreement.
    const double wall_tolerance = internal::pairWallTolerance(gt, map, p);
    auto wallsSetApart = [&](const std::vector<int>& part, const Transform2D& fit)
    {
        if (!(p.brokenness_part_wall_ratio > 0.0) || !(p.pair_wall_margin_m > 0.0) || !walls.ok())
            return false;
        std::vector<std::pair<int, int>> pairs;
        for (int v : part) pairs.emplace_back(v, partner[v]);
        // The pinning is not asked for (a share above 1 never reaches it): two fits are
        // compared, and walls that cannot tell them apart give both the same share.
        auto share = [&](const Transform2D& t)
        {
            return internal::wallAgreement(gt, map, walls.gt(), walls.map(), pairs, t,
                                           p.pair_wall_margin_m, wall_tolerance, 2.0);
        };
        const internal::WallAgreement own = share(byWalls(part, fit));
        if (!own.walls_on_both || own.share < p.pair_wall_min_agreement) return false;
        for (const auto& g : b.groups)
            if (share(g.transform).share > p.brokenness_part_wall_ratio * own.share) return false;
        return true;
    };
    std::stable_sort(small.begin(), small.end(),
                     [](const auto& x, const auto& y) { return x.size() > y.size(); });
    std::vector<char> in_group(gt.vertices.size(), 0);
    for (const auto& g : b.groups)
        for (int v : g.gt_vertices) in_group[v] = 1;
    if (!b.groups.empty())
        for (auto& cand : small)
        {
            std::vector<int> free;
            for (int v : cand)
                if (!in_group[v]) free.push_back(v);
            if (static_cast<int>(free.size()) < p.brokenness_min_part_vertices) continue;
            BrokennessGroup grp;
            grp.gt_vertices = free;
            grp.transform = fitOf(free, &grp.squared_error_m2);
            if (grp.squared_error_m2 > p.brokenness_max_squared_error_m2) continue;
            // The counted group that places it nearest: at least the clear gap, or beyond the
            // paper's threshold (where its growth would not take the part in) with the walls.
            double gap = std::numeric_limits<double>::infinity();
            for (const auto& g : b.groups)
                gap = std::min(gap,
                               squaredGap(g.transform, grp.transform, free) / double(free.size()));
            const bool separate =
                gap >= p.brokenness_part_min_gap_m2 ||
                (gap > p.brokenness_max_squared_error_m2 && wallsSetApart(free, grp.transform));
            if (!separate) continue;
            for (int v : free) in_group[v] = 1;
            b.groups.push_back(std::move(grp));
        }
    // Ours (brokenness_best_fit_part): each vertex of a counted group belongs to the group
    // whose transform places it best. Near a cut both parts' fits place a vertex within the
    // threshold, and whichever group met it first kept it; its walls, turned with the other
    // part, then turn its group's walls' fit by a degree or two (step 7). One pass, each group
    // refitted; skipped when a group would keep fewer than brokenness_min_part_vertices (or
    // fewer than it had): a counted part stays counted.
    if (p.brokenness_best_fit_part && b.groups.size() > 1)
    {
        std::vector<std::vector<int>> to(b.groups.size());
        std::vector<char> changed(b.groups.size(), 0);
        for (std::size_t i = 0; i < b.groups.size(); ++i)
            for (int v : b.groups[i].gt_vertices)
            {
                std::size_t best = i;
                double best_e = squaredErrorOf(b.groups[i].transform, v);
                for (std::size_t j = 0; j < b.groups.size(); ++j)
                    if (const double e = squaredErrorOf(b.groups[j].transform, v); e < best_e)
                        best_e = e, best = j;
                to[best].push_back(v);
                if (best != i) changed[i] = changed[best] = 1;
            }
        bool kept = true;
        for (std::size_t i = 0; i < b.groups.size(); ++i)
            kept = kept && static_cast<int>(to[i].size()) >=
                               std::min(p.brokenness_min_part_vertices,
                                        static_cast<int>(b.groups[i].gt_vertices.size()));
        for (std::size_t i = 0; i < b.groups.size() && kept; ++i)
        {
            if (!changed[i]) continue;
            std::sort(to[i].begin(), to[i].end());
            b.groups[i].gt_vertices = std::move(to[i]);
            b.groups[i].transform = fitOf(b.groups[i].gt_vertices, &b.groups[i].squared_error_m2);
        }
    }
    // Ours: each counted part's turn and shift from its walls (brokenness_wall_margin_m). The
    // groups are decided by their vertices; the reported transforms change (the squared error
    // stays the vertices' fit's, the paper's figure), and only groups that the walls place
    // alike merge.
    if (p.brokenness_wall_margin_m > 0.0 && !b.groups.empty() && walls.ok())
    {
        for (auto& g : b.groups) g.transform = byWalls(g.gt_vertices, g.transform);
        // Ours: groups that their walls place alike are one part, kept apart by a compromise
        // fit of their vertices (brokenness_merge_by_walls).
        if (p.brokenness_merge_by_walls) mergeSamePlacement(true);
    }
    std::stable_sort(b.groups.begin(), b.groups.end(),
                     [](const auto& x, const auto& y)
                     { return x.gt_vertices.size() > y.gt_vertices.size(); });
    b.degree = std::max(0, static_cast<int>(b.groups.size()) - 1);
    b.score = 1.0 / (1.0 + b.degree);
    // Ours: how far each part is off, against the larger part that places its vertices
    // nearest (a chain of breaks: each break's own size). Reported, not scored (doc/quality.md,
    // "How far a part is off").
    std::vector<Transform2D> larger;
    for (auto& g : b.groups)
    {
        if (!larger.empty())
            g.offset_m = internal::partOffset(g.transform, larger, pointsOf(g.gt_vertices).second);
        larger.push_back(g.transform);
    }
    return b;
}

/** The rule of a missed part's placement (wall_part_*), tolerances at least 1.5 cells. */
internal::WallPartRule wallPartRule(const TopologyGraph& gt, const TopologyGraph& map,
                                    const QualityParameters& p)
{
    internal::WallPartRule rule;
    rule.tolerance_m = internal::wallTolerance(p.wall_part_tolerance_m, gt, map);
    rule.link_m = p.wall_part_link_m;
    rule.min_length_m = p.wall_part_min_length_m;
    rule.min_share = p.wall_part_min_share;
    rule.max_runner_up = p.wall_part_max_runner_up;
    rule.min_pin_lead = p.wall_part_min_pin_lead;
    rule.free_space = p.wall_part_free_space;
    rule.turn_step_deg = p.wall_part_turn_step_deg;
    rule.pair_distance_m = p.wall_part_pair_distance_m;
    return rule;
}

/** The rule of a part singled out by its region (map_by_walls_*; steps 9 and 10). */
internal::WallMapRule wallMapRule(const TopologyGraph& gt, const TopologyGraph& map,
                                  const QualityParameters& p)
{
    internal::WallMapRule rule;
    rule.part = wallPartRule(gt, map, p);
    rule.explained_tolerance_m = internal::wallTolerance(
        p.explained_wall_tolerance_m > 0.0 ? p.explained_wall_tolerance_m : p.wall_part_tolerance_m,
        gt, map);
    rule.region_m = p.map_by_walls_region_m;
    rule.region_share = p.map_by_walls_region_share;
    rule.min_explained = p.map_by_walls_min_explained;
    rule.max_parts = p.map_by_walls_max_parts;
    rule.whole_min_share = p.map_by_walls_whole_min_share;
    rule.slack_share = p.vertex_slack_share;
    rule.max_overlap = p.wall_part_max_overlap;
    return rule;
}

/** The map placed by its walls (map_by_walls) when `given` holds no group (`walls`: both
 * graphs' wall points, shared with the steps after it); `out` its match
 * (the parts' pairs, stage Walls, each pair's isomorphism its part) when parts are kept. */
internal::WallMap mapByWalls(const TopologyGraph& gt, const TopologyGraph& map,
                             const GraphMatch& given, const QualityParameters& p,
                             internal::Walls& walls, GraphMatch& out)
{
    const internal::WallMapRule rule = wallMapRule(gt, map, p);
    if (!walls.ok()) return {};
    std::vector<std::pair<int, int>> pairs;
    for (const VertexPair& pr : given.pairs) pairs.emplace_back(pr.ground_truth, pr.map);
    internal::WallMap placed =
        internal::placeMapByWalls(gt, map, walls.gt(), walls.map(), pairs, rule);
    if (placed.parts.empty()) return placed;
    out = GraphMatch{};
    out.messages = given.messages;
    for (std::size_t k = 0; k < placed.parts.size(); ++k)
        for (const auto& [g, m] : placed.parts[k].pairs)
        {
            // A pair of the match keeps its stage and similarity; the part is its group.
            VertexPair pr{g, m, MatchStage::Walls, 0.0, int(k)};
            for (const VertexPair& q : given.pairs)
                if (q.ground_truth == g && q.map == m)
                    pr.stage = q.stage, pr.similarity = q.similarity;
            out.pairs.push_back(pr);
        }
    std::sort(out.pairs.begin(), out.pairs.end(),
              [](const VertexPair& a, const VertexPair& b)
              { return a.ground_truth < b.ground_truth; });
    std::size_t matchable = 0;
    for (const auto& v : gt.vertices) matchable += v.spurious ? 0 : 1;
    out.missing = matchable - out.pairs.size();
    char note[400];
    std::snprintf(note, sizeof note,
                  "the match held %zu pair(s), no group of %d to measure the map by: the map is "
                  "placed by its walls in %zu part(s) explaining %.1f %% of its walls, and the "
                  "%zu vertex pair(s) they place within %.2f m (+ %.0f %% of their clearance) are "
                  "its match",
                  given.pairs.size(), p.brokenness_min_vertices, placed.parts.size(),
                  100.0 * placed.explained, out.pairs.size(), rule.part.pair_distance_m,
                  100.0 * rule.slack_share);
    out.messages.push_back(note);
    if (placed.whole)
    {
        std::snprintf(note, sizeof note,
                      "no region of the map's walls is placed on its own: "
                      "the whole map is one part, its best placement putting %.1f %% of its "
                      "walls on the ground truth's, the next %.1f %%",
                      100.0 * placed.whole_share, 100.0 * placed.whole_runner_up);
        out.messages.push_back(note);
    }
    return placed;
}

/** Brokenness of a map placed by its walls: one group per part (by_walls), largest first. */
Brokenness wallMapBrokenness(const TopologyGraph& gt, const TopologyGraph& map,
                             const internal::WallMap& placed)
{
    Brokenness b;
    std::vector<Transform2D> larger;
    for (const internal::WallPart& part : placed.parts)
    {
        BrokennessGroup g;
        g.by_walls = true;
        g.transform = part.transform;
        double sq = 0.0;
        std::vector<Eigen::Vector2d> at;
        for (const auto& [a, m] : part.pairs)
        {
            g.gt_vertices.push_back(a);
            g.map_vertices.push_back(m);
            at.push_back(map.vertices[size_t(m)].position_m);
            sq +=
                (gt.vertices[size_t(a)].position_m - part.transform.apply(at.back())).squaredNorm();
        }
        g.squared_error_m2 = part.pairs.empty() ? 0.0 : sq / double(part.pairs.size());
        g.offset_m = larger.empty()
                         ? 0.0
                         : internal::partOffset(g.transform, larger, at.empty() ? part.points : at);
        larger.push_back(g.transform);
        b.groups.push_back(std::move(g));
    }
    b.degree = int(b.groups.size()) - 1;
    b.score = 1.0 / (1.0 + b.degree);
    return b;
}
}  // namespace

QualityReport evaluateMatch(const TopologyGraph& ground_truth, const TopologyGraph& map,
                            const GraphMatch& match, const QualityParameters& p, unsigned threads)
{
    return internal::evaluateMatchAt(ground_truth, map, map, match, p, threads);
}

QualityReport internal::evaluateMatchAt(const TopologyGraph& ground_truth, const TopologyGraph& map,
                                        const TopologyGraph& map_for_brokenness,
                                        const GraphMatch& given, const QualityParameters& p,
                                        unsigned threads)
{
    p.validate();
    // Both graphs' wall points, indexed on first use, for the steps on this thread that align
    // walls (the brokenness thread has its own: they are not for concurrent use).
    internal::Walls walls(ground_truth, map);
    // A match with no group to measure the map by: the map placed by its walls, whose pairs
    // are then the match (doc/quality.md, "A map placed by its walls").
    std::optional<internal::WallMap> by_walls;
    GraphMatch walls_match;
    std::optional<internal::WallMap> refused;  // parts too few to explain it, or whole, no pair
    if (p.map_by_walls && given.pairs.size() < std::size_t(p.brokenness_min_vertices) &&
        &map_for_brokenness == &map)
    {
        by_walls = mapByWalls(ground_truth, map, given, p, walls, walls_match);
        if (by_walls->parts.empty())
        {
            refused = std::move(by_walls);
            by_walls.reset();
        }
    }
    const GraphMatch& match = by_walls ? walls_match : given;
    if (map_for_brokenness.vertices.size() != map.vertices.size())
        throw InputError("the map's graph for brokenness is not the map's graph at another scale");
    // Before anything indexes the graphs with the match's pairs.
    for (const auto& pr : match.pairs)
        if (pr.ground_truth < 0 || pr.ground_truth >= int(ground_truth.vertices.size()) ||
            pr.map < 0 || pr.map >= int(map.vertices.size()))
            throw InputError("the match names a vertex the graphs do not have");
    QualityReport r;
    r.match = match;
    // The ground truth's matching view: its matchable vertices and, for brokenness, adjacency.
    const internal::MatchView gt_view = internal::makeMatchView(ground_truth);
    r.gt_vertices = static_cast<std::size_t>(gt_view.numActive());
    r.map_vertices = static_cast<std::size_t>(internal::makeMatchView(map).numActive());
    r.messages = match.messages;
    // Brokenness needs two groups of brokenness_min_vertices: say so when the ground truth is
    // too small for that (a bare floor plan of a few rooms), so a 0 is not read as "unbroken".
    if (r.gt_vertices < 2 * static_cast<std::size_t>(p.brokenness_min_vertices) && !by_walls)
        r.messages.push_back("the ground truth's graph has " + std::to_string(r.gt_vertices) +
                             " matchable vertices, fewer than two brokenness groups of " +
                             std::to_string(p.brokenness_min_vertices) +
                             ": brokenness cannot be measured on it");
    if (by_walls)
        r.brokenness = wallMapBrokenness(ground_truth, map, *by_walls);
    else if (refused && refused->parts_sought > 0)
    {
        char note[300];
        std::snprintf(note, sizeof note,
                      "the map's walls placed %d part(s) explaining %.1f %% of them, less than "
                      "map_by_walls_min_explained (%.1f %%): the map is not placed by its walls",
                      refused->parts_sought, 100.0 * refused->explained,
                      100.0 * p.map_by_walls_min_explained);
        r.messages.push_back(note);
    }
    else if (refused && refused->whole)
    {
        char note[300];
        std::snprintf(note, sizeof note,
                      "the whole map's best placement puts %.1f %% of its walls on the ground "
                      "truth's (the next %.1f %%), but no vertex of it near a ground-truth vertex: "
                      "it is not placed by its walls",
                      100.0 * refused->whole_share, 100.0 * refused->whole_runner_up);
        r.messages.push_back(note);
    }
    if (match.pairs.empty())
    {
        r.local_consistency = localConsistency(ground_truth, match, {}, {}, p);
        r.messages.push_back("nothing was matched: coverage and quality are 0");
        return r;
    }

    // Brokenness does not depend on the accuracy steps below: with a second thread it runs there,
    // with its own wall indexes (they are not for concurrent use), while this one places the
    // pairs by their walls (an ICP each); the report is the same.
    std::future<Brokenness> broken_future;
    if (threads > 1 && !by_walls)
    {
        try
        {
            broken_future = std::async(std::launch::async,
                                       [&]
                                       {
                                           internal::Walls own(ground_truth, map_for_brokenness);
                                           return brokenness(ground_truth, map_for_brokenness,
                                                             gt_view, match, p, own);
                                       });
        }
        catch (const std::system_error&)
        {
            // No thread to be had (a process or container limit): it runs here, below.
        }
    }

    // Coverage (paper IV): share of the ground truth's matchable vertices that were matched.
    r.coverage = r.gt_vertices ? double(match.pairs.size()) / double(r.gt_vertices) : 0.0;

    std::vector<Eigen::Vector2d> pg, pm;
    for (const auto& pr : match.pairs)
    {
        pg.push_back(ground_truth.vertices[pr.ground_truth].position_m);
        pm.push_back(map.vertices[pr.map].position_m);
    }
    // Global accuracy: positions compared as they are, in the ground truth's frame.
    double sum = 0.0;
    for (std::size_t i = 0; i < pg.size(); ++i) sum += (pg[i] - pm[i]).squaredNorm();
    r.global_accuracy.pairs = pg.size();
    r.global_accuracy.rmse_m = std::sqrt(sum / double(pg.size()));
    r.global_accuracy.score = invScore(r.global_accuracy.rmse_m, p.accuracy_scale_m);
    // Relative accuracy: after the best rigid alignment (Horn), refitted without the pairs
    // beyond the outlier distance; each pair's error counted beyond its slack and at most the
    // outlier distance (doc/quality.md), so one wrong pair does not decide the score.
    std::vector<double> slack;
    for (const auto& pr : match.pairs) slack.push_back(pairSlack(ground_truth, map, pr, p));
    // The sum of the squared counted errors of the pairs placed at `pts` under `x`.
    auto countedSquares = [&](const Transform2D& x, const std::vector<Eigen::Vector2d>& pts)
    {
        double c = 0.0;
        for (std::size_t i = 0; i < pg.size(); ++i)
        {
            const double e = countedError((pg[i] - x.apply(pts[i])).norm(), slack[i], p);
            c += e * e;
        }
        return c;
    };
    auto refit = [&](Transform2D t)
    {
        for (int round = 0; round < 3 && p.outlier_distance_m > 0.0; ++round)
        {
            const InlierFit f = fitOfInliers(pg, pm, t, p.outlier_distance_m);
            if (f.inliers < 3 || f.inliers == pg.size()) break;
            t = f.transform;
        }
        return t;
    };
    Transform2D t = refit(internal::hornAlign(pg, pm));
    // The counted errors are not convex in the alignment: on a broken map Horn's fit of every
    // pair is a compromise between the parts, and the refits from it reach the nearest minimum
    // (a few more pairs of a small part turned the fit of column_hall_1002/broken_2 by 8 deg and
    // its relative RMSE from 0.65 to 0.95 m). So each group's own fit starts the refits too,
    // and the alignment whose vertices' counted errors are the smallest wins (ties: the fit of
    // all pairs); chosen on the vertices, before the walls place the pairs (an ICP per pair and
    // start; doc/quality.md, "The best alignment").
    if (p.outlier_distance_m > 0.0)
    {
        double best = countedSquares(t, pm);
        std::map<int, std::vector<std::size_t>> groups;
        for (std::size_t i = 0; i < match.pairs.size(); ++i)
            if (match.pairs[i].isomorphism >= 0) groups[match.pairs[i].isomorphism].push_back(i);
        for (const auto& [group, members] : groups)
        {
            if (members.size() < 3 || members.size() == pg.size()) continue;
            std::vector<Eigen::Vector2d> a, b;
            for (std::size_t i : members) a.push_back(pg[i]), b.push_back(pm[i]);
            const Transform2D start = refit(internal::hornAlign(a, b));
            const double c = countedSquares(start, pm);
            if (c < best - 1e-9) t = start, best = c;
        }
    }
    // Each pair's map place: its vertex (with the jitter slack) or, where the walls around it
    // agree, the point they put on its ground-truth vertex (pair_wall_margin_m). The alignment
    // is refitted to the places, without the pairs beyond the outlier distance.
    std::vector<Eigen::Vector2d> places = pm;
    internal::placeByWalls(ground_truth, map, match, t, p, walls, places, slack,
                           r.relative_accuracy.by_walls);
    if (r.relative_accuracy.by_walls > 0)
    {
        const InlierFit f = fitOfInliers(pg, places, t, p.outlier_distance_m);
        if (f.inliers >= 2) t = f.transform;
    }
    const double sq = countedSquares(t, places);
    r.local_consistency = localConsistency(ground_truth, match, places, slack, p);
    r.relative_accuracy.pairs = pg.size();
    r.relative_accuracy.transform = t;
    r.relative_accuracy.rmse_m = std::sqrt(sq / double(pg.size()));
    r.relative_accuracy.score = invScore(r.relative_accuracy.rmse_m, p.accuracy_scale_m);

    if (!by_walls)  // a map placed by its walls has its parts as its groups (above)
    {
        if (broken_future.valid())
            r.brokenness = broken_future.get();
        else if (&map_for_brokenness == &map)
            r.brokenness = brokenness(ground_truth, map, gt_view, match, p, walls);
        else
        {
            internal::Walls own(ground_truth, map_for_brokenness);
            r.brokenness = brokenness(ground_truth, map_for_brokenness, gt_view, match, p, own);
        }
    }

    // Brokenness step 9 (ours, wall_parts): a region of the map's walls that no group explains,
    // placed clearly by one rigid fit of its own, is a part the match missed (doc/quality.md,
    // "A part placed by its walls").
    if (p.wall_parts && walls.ok() && !r.brokenness.groups.empty() && !by_walls)
    {
        const TopologyGraph& placed = map_for_brokenness;
        std::vector<Transform2D> fits;
        for (const BrokennessGroup& g : r.brokenness.groups) fits.push_back(g.transform);
        std::vector<char> gt_free(ground_truth.vertices.size(), 0),
            map_free(placed.vertices.size(), 0);
        for (const auto& v : ground_truth.vertices) gt_free[size_t(v.id)] = !v.spurious;
        for (const auto& v : placed.vertices) map_free[size_t(v.id)] = !v.spurious;
        for (const auto& pr : match.pairs)
            gt_free[size_t(pr.ground_truth)] = 0, map_free[size_t(pr.map)] = 0;
        // The walls no group explains, by the explained walls' own rule, in placed's frame.
        std::vector<Eigen::Vector2f> stood_on;
        const ExplainedWalls before = internal::explainedWalls(
            placed, placed, fits, walls.gt(),
            internal::wallTolerance(p.explained_wall_tolerance_m, ground_truth, placed), &stood_on);
        const internal::WallMapRule rule = wallMapRule(ground_truth, placed, p);
        std::vector<Transform2D> larger = fits;
        for (internal::WallPart& part :
             internal::findWallParts(ground_truth, placed, walls.gt(), before.unexplained_m,
                                     gt_free, map_free, rule, stood_on, p.wall_part_split))
        {
            BrokennessGroup g;
            g.by_walls = true;
            g.transform = part.transform;
            double pairs_sq = 0.0;
            for (const auto& [a, b] : part.pairs)
            {
                g.gt_vertices.push_back(a);
                g.map_vertices.push_back(b);
                pairs_sq += (ground_truth.vertices[size_t(a)].position_m -
                             part.transform.apply(placed.vertices[size_t(b)].position_m))
                                .squaredNorm();
            }
            g.squared_error_m2 = part.pairs.empty() ? 0.0 : pairs_sq / double(part.pairs.size());
            // How far it is off, as for the other groups: over its vertices' map partners, or
            // its region's wall points when it places no vertex.
            std::vector<Eigen::Vector2d> at;
            for (const int m : g.map_vertices) at.push_back(placed.vertices[size_t(m)].position_m);
            g.offset_m = internal::partOffset(g.transform, larger, at.empty() ? part.points : at);
            larger.push_back(g.transform);
            r.brokenness.groups.push_back(std::move(g));
        }
        r.brokenness.degree = int(r.brokenness.groups.size()) - 1;
        r.brokenness.score = 1.0 / (1.0 + r.brokenness.degree);
    }

    // The map's walls that the match explains: each placed by the part whose transform puts it
    // on a ground-truth wall, brokenness's groups on the map at the scale they were fitted at,
    // else the relative alignment on the map as given (doc/quality.md, "Explained walls").
    if (p.explained_wall_tolerance_m > 0.0)
    {
        std::vector<Transform2D> fits;
        for (const BrokennessGroup& g : r.brokenness.groups) fits.push_back(g.transform);
        const bool by_groups = !fits.empty();
        if (!by_groups) fits.push_back(r.relative_accuracy.transform);
        const TopologyGraph& placed = by_groups ? map_for_brokenness : map;
        const double tolerance =
            internal::wallTolerance(p.explained_wall_tolerance_m, ground_truth, placed);
        if (walls.ok())
            r.explained_walls = internal::explainedWalls(map, placed, fits, walls.gt(), tolerance);
        const ExplainedWalls& ew = r.explained_walls;
        if (ew.measured && ew.share < p.explained_walls_note_below)
        {
            char note[320];
            std::snprintf(note, sizeof(note),
                          "the match explains %.1f %% of the map's walls (%zu of %zu within %.2f m "
                          "of a ground-truth wall under a part's fit): the rest, red in the "
                          "picture, is where no matched part puts it, a part broken beyond what "
                          "brokenness counts or what the ground truth lacks",
                          100.0 * ew.share, ew.explained, ew.wall_points, ew.tolerance_m);
            r.messages.push_back(note);
        }
    }

    // Quality: weighted mean of coverage, relative accuracy, the mean of the non-empty
    // consistency classes, brokenness and, when measured, the explained walls (doc/quality.md).
    const double consistency = r.consistencyScore();
    const double w_explained = r.explained_walls.measured ? p.weight_explained_walls : 0.0;
    const double wsum = p.weight_coverage + p.weight_relative_accuracy + p.weight_consistency +
                        p.weight_brokenness + w_explained;
    r.quality =
        (p.weight_coverage * r.coverage + p.weight_relative_accuracy * r.relative_accuracy.score +
         p.weight_consistency * consistency + p.weight_brokenness * r.brokenness.score +
         w_explained * r.explained_walls.share) /
        wsum;
    // Accuracy, consistency and brokenness are measured on the matched part only; when that is
    // a small share of the ground truth they say little about the whole map (one part of a map
    // broken three times, a chance match with another building), and when it explains a small
    // share of the map's walls, little about the rest of the map (parts broken beyond
    // recognition). Below min_trusted_coverage the quality shrinks with the square root of the
    // smaller share, as the confidence in an estimate from a sample does with the sample's size
    // (ours; doc/quality.md).
    const double trusted =
        r.explained_walls.measured ? std::min(r.coverage, r.explained_walls.share) : r.coverage;
    if (p.min_trusted_coverage > 0.0 && trusted < p.min_trusted_coverage)
        r.quality *= std::sqrt(trusted / p.min_trusted_coverage);
    return r;
}

}  // namespace mrpt_topoeval
