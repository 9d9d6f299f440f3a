/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// method = consistent (doc/matching.md, "Consistent groups"): the paper's strict isomorphism
// stops at every local difference of topology between two maps of one place (a missing dead
// end, a split junction, a degree changed by a small loop). Here topology and similarity only
// propose candidate pairs; geometry decides, as in correspondence-based registration
// (TEASER++'s maximum clique of the pairwise-consistency graph, CLIPPER's consistency graph,
// Parra Bustos et al. 2019 "A practical maximum clique algorithm for matching with pairwise
// constraints"): two pairs are consistent when the distance between their ground-truth
// vertices equals the distance between their map vertices. A distance within one map does not
// depend on that map's frame, so the global frames of the maps play no part.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <tuple>

#include "geometry/horn.h"
#include "geometry/line_spread.h"
#include "matching/cliques.h"
#include "matching/matching.h"
#include "matching/wall_agreement.h"

namespace mrpt_topoeval::internal
{
namespace
{
struct Candidate
{
    int gt = -1, map = -1;
    double similarity = 0.0;
    double uncertainty_m = 0.0;  //!< clearance_tolerance_share x the smaller clearance
};

/** The distances between a graph's vertices, |p_a - p_b| as (p_a - p_b).norm() gives it, made
 * once per search: the consistency graph asks for two of them for every two candidates, again
 * after every accepted group, and the consensus for every pair it places (on the Intel pair
 * these square roots were a fifth of the match's time). Only while a table holds at most
 * kMaxTable entries (graphs of up to 1024 vertices, 8 MB); else each is computed when asked,
 * alike. */
class VertexDistances
{
public:
    explicit VertexDistances(const TopologyGraph& g) : m_g(g), m_n(g.vertices.size())
    {
        if (m_n * m_n > kMaxTable) return;
        m_table.resize(m_n * m_n);
        for (std::size_t a = 0; a < m_n; ++a)
            for (std::size_t b = 0; b < m_n; ++b) m_table[a * m_n + b] = computed(int(a), int(b));
    }
    double operator()(int a, int b) const
    {
        return m_table.empty() ? computed(a, b) : m_table[std::size_t(a) * m_n + std::size_t(b)];
    }

private:
    static constexpr std::size_t kMaxTable = std::size_t(1) << 20;
    double computed(int a, int b) const
    {
        return (m_g.vertices[std::size_t(a)].position_m - m_g.vertices[std::size_t(b)].position_m)
            .norm();
    }
    const TopologyGraph& m_g;
    std::size_t m_n;
    std::vector<double> m_table;
};

/** log10 of the number of false alarms (Desolneux, Moisan and Morel's a contrario test, as in
 * Moisan and Stival's AC-RANSAC) of a clique of s among n candidates whose consistency graph
 * has this density: the number of s-subsets times the chance that all their s(s-1)/2 distances
 * agree, each with the chance of one agreement. The density counts the true agreements too, so
 * it overestimates chance and the test errs towards refusing. */
double log10FalseAlarms(double n, double s, double density)
{
    if (!(density > 0.0) || s < 2.0 || n < s) return -std::numeric_limits<double>::infinity();
    const double log_subsets =
        std::lgamma(n + 1.0) - std::lgamma(s + 1.0) - std::lgamma(n - s + 1.0);
    return (log_subsets + 0.5 * s * (s - 1.0) * std::log(density)) / std::log(10.0);
}

/** Vertices within `hops` view edges of v (v included). */
std::vector<int> nearInGraph(const MatchView& view, int v, int hops)
{
    std::vector<int> out{v}, frontier{v};
    for (int h = 0; h < hops; ++h)
    {
        std::vector<int> next;
        for (int x : frontier)
            for (const auto& inc : view.v[x].ring)
                if (std::find(out.begin(), out.end(), inc.other) == out.end())
                {
                    out.push_back(inc.other);
                    next.push_back(inc.other);
                }
        frontier = std::move(next);
    }
    return out;
}

// Each vertex's piece (connected component) of the view's graph, numbered 0, 1, ... in the order
// of each piece's first vertex.
std::vector<int> piecesOf(const MatchView& view)
{
    const int n = int(view.v.size());
    std::vector<int> piece(n, -1);
    for (int v0 = 0, pieces = 0; v0 < n; ++v0)
    {
        if (piece[v0] >= 0) continue;
        std::vector<int> stack{v0};
        piece[v0] = pieces;
        while (!stack.empty())
        {
            const int x = stack.back();
            stack.pop_back();
            for (const auto& inc : view.v[x].ring)
                if (piece[inc.other] < 0) piece[inc.other] = pieces, stack.push_back(inc.other);
        }
        ++pieces;
    }
    return piece;
}

// The given pairs' components connected by links (`linked(x, y)` on two candidates: (g1, m1)
// and (g2, m2) are linked when g2 lies within support_hops view edges of g1 and m2 within
// support_hops of m1, or, in the last look for further groups, when m1 and m2 lie in different
// pieces of the map's graph: link_across_map_pieces), the biggest first (ties: the first
// found), each's members in the given order.
template <typename Linked>
std::vector<std::vector<int>> linkedComponents(const std::vector<int>& set,
                                               const std::vector<Candidate>& cands, Linked linked)
{
    const std::size_t n = set.size();
    std::vector<int> component(n, -1);
    std::vector<std::vector<int>> out;
    for (std::size_t s = 0; s < n; ++s)
    {
        if (component[s] >= 0) continue;
        std::vector<int> members{int(s)};
        component[s] = int(s);
        for (std::size_t k = 0; k < members.size(); ++k)
        {
            const int i = members[k];
            for (std::size_t j = 0; j < n; ++j)
                if (component[j] < 0 && linked(cands[set[i]], cands[set[j]]))
                {
                    component[j] = int(s);
                    members.push_back(int(j));
                }
        }
        std::sort(members.begin(), members.end());
        for (int& k : members) k = set[k];
        out.push_back(std::move(members));
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const auto& a, const auto& b) { return a.size() > b.size(); });
    return out;
}

/** findConsistentGroups() from a given first clique (`first`, pairs (gt, map), tried before the
 * maximum clique) or, with none, from the maximum clique; then as below. */
ConsistentMatch findGroups(const TopologyGraph& gt, const TopologyGraph& map, MatchContext& ctx,
                           const std::vector<std::pair<int, int>>* first,
                           std::map<std::size_t, std::optional<double>>& pair_turns)
{
    const GraphMatcherParameters& p = ctx.params;
    const SimilarityMatrix& S = ctx.similarity;
    const int n_gt = int(gt.vertices.size()), n_map = int(map.vertices.size());
    auto pg = [&](int a) -> const Eigen::Vector2d& { return gt.vertices[a].position_m; };
    auto pm = [&](int b) -> const Eigen::Vector2d& { return map.vertices[b].position_m; };
    const VertexDistances dist_gt(gt), dist_map(map);
    auto degreeOk = [&](int a, int b)
    { return std::abs(ctx.gt.v[a].degree() - ctx.map.v[b].degree()) <= p.max_degree_difference; };
    auto uncertainty = [&](int a, int b)
    {
        return p.clearance_tolerance_share *
               std::min(gt.vertices[a].clearance_m, map.vertices[b].clearance_m);
    };
    ConsistentMatch out;
    out.min_group_size = p.min_group_vertices;

    // 1. Candidates: each free gt vertex's k most similar free map vertices, and each free map
    //    vertex's k most similar free gt vertices, of a degree within max_degree_difference.
    //    Made again after every accepted group: once a part is matched its vertices no longer
    //    crowd the other parts' lists (a part whose attributes changed at a break keeps its true
    //    partners a few ranks down, doc/matching.md).
    std::vector<Candidate> cands;
    std::vector<std::uint8_t> adjacent;
    int n = 0;
    std::size_t consistent_pairs = 0;  // edges of the consistency graph
    auto isFree = [&](int a, int b) { return ctx.gt_to_map[a] < 0 && ctx.map_to_gt[b] < 0; };
    // Partners per vertex: candidates_per_vertex, then leftover_candidates_per_vertex once no
    // further group is found (below).
    int per_vertex = p.candidates_per_vertex;
    auto buildCandidates = [&]()
    {
        std::vector<std::uint8_t> is_cand(std::size_t(n_gt) * n_map, 0);
        auto topK = [&](int n_rows, int n_cols, bool rows_are_gt)
        {
            for (int i = 0; i < n_rows; ++i)
            {
                if (!(rows_are_gt ? ctx.gt.v[i] : ctx.map.v[i]).active) continue;
                std::vector<std::pair<double, int>> ranked;
                for (int j = 0; j < n_cols; ++j)
                {
                    const int a = rows_are_gt ? i : j, b = rows_are_gt ? j : i;
                    if (!ctx.gt.v[a].active || !ctx.map.v[b].active || !degreeOk(a, b) ||
                        !isFree(a, b))
                        continue;
                    const double s = S(a, b);
                    if (s >= p.min_candidate_similarity) ranked.emplace_back(-s, j);
                }
                const std::size_t k = std::min<std::size_t>(ranked.size(), per_vertex);
                std::partial_sort(ranked.begin(), ranked.begin() + k, ranked.end());
                for (std::size_t r = 0; r < k; ++r)
                {
                    const int j = ranked[r].second;
                    is_cand[rows_are_gt ? std::size_t(i) * n_map + j : std::size_t(j) * n_map + i] =
                        1;
                }
            }
        };
        topK(n_gt, n_map, true);
        topK(n_map, n_gt, false);
        cands.clear();
        for (int a = 0; a < n_gt; ++a)
            for (int b = 0; b < n_map; ++b)
                if (is_cand[std::size_t(a) * n_map + b])
                    cands.push_back({a, b, S(a, b), uncertainty(a, b)});
        n = int(cands.size());
        out.candidates = std::max(out.candidates, cands.size());

        // 2. The pairwise consistency graph (TEASER++'s "translation and rotation invariant
        //    measurements"): one-to-one, and distances that agree.
        auto distanceTolerance = [&](const Candidate& x, const Candidate& y, double dg, double dm)
        {
            return p.distance_tolerance_m + p.distance_tolerance_ratio * std::max(dg, dm) +
                   x.uncertainty_m + y.uncertainty_m;
        };
        adjacent.assign(std::size_t(n) * n, 0);
        consistent_pairs = 0;
        for (int i = 0; i < n; ++i)
            for (int j = i + 1; j < n; ++j)
            {
                const Candidate &x = cands[i], &y = cands[j];
                if (x.gt == y.gt || x.map == y.map) continue;
                const double dg = dist_gt(x.gt, y.gt), dm = dist_map(x.map, y.map);
                if (std::abs(dg - dm) <= distanceTolerance(x, y, dg, dm))
                {
                    adjacent[std::size_t(i) * n + j] = adjacent[std::size_t(j) * n + i] = 1;
                    ++consistent_pairs;
                }
            }
    };
    buildCandidates();

    // Pairs of rejected first-group cliques (gt * n_map + map), not tried again.
    std::vector<std::uint8_t> rejected(std::size_t(n_gt) * n_map, 0);
    auto pairKey = [&](const Candidate& c) { return std::size_t(c.gt) * n_map + c.map; };
    // On graphs too small for min_group_vertices (a bare plan of a few rooms, a robot map of a
    // flat) a group needs min_small_graph_group_share of the smaller graph's matchable
    // vertices, and never fewer than 3 (doc/matching.md, "A small graph").
    const int smaller = std::min(ctx.gt.numActive(), ctx.map.numActive());
    const int min_size = std::min(
        p.min_group_vertices,
        std::max(3, int(std::ceil(p.min_small_graph_group_share * double(smaller) - 1e-9))));
    const bool small_graph = min_size < p.min_group_vertices;
    out.min_group_size = min_size;
    auto tolerance = [&](const Candidate& c, double dist)
    { return p.distance_tolerance_m + c.uncertainty_m + p.distance_tolerance_ratio * dist; };
    // How far a fit (map to ground truth) puts a candidate's map vertex from its ground-truth
    // vertex, and the centre of a set's ground-truth vertices (settling measures a pair's
    // tolerance from it).
    auto offBy = [&](const Candidate& c, const Transform2D& T)
    { return (pg(c.gt) - T.apply(pm(c.map))).norm(); };
    auto centreOf = [&](const std::vector<int>& set)
    {
        Eigen::Vector2d centre = Eigen::Vector2d::Zero();
        for (int i : set) centre += pg(cands[i].gt);
        return Eigen::Vector2d(centre / double(set.size()));
    };
    // Whether a fit places a candidate within its tolerance, the distance taken from `centre`
    // (a set's centre, as settling measures it).
    auto placedBy = [&](const Candidate& c, const Transform2D& T, const Eigen::Vector2d& centre)
    { return offBy(c, T) <= tolerance(c, (pg(c.gt) - centre).norm()); };
    // Vertices within support_hops edges, sorted, for the links between pairs.
    std::vector<std::vector<int>> near_gt(n_gt), near_map(n_map);
    for (int a = 0; a < n_gt; ++a)
    {
        near_gt[a] = nearInGraph(ctx.gt, a, p.support_hops);
        std::sort(near_gt[a].begin(), near_gt[a].end());
    }
    for (int b = 0; b < n_map; ++b)
    {
        near_map[b] = nearInGraph(ctx.map, b, p.support_hops);
        std::sort(near_map[b].begin(), near_map[b].end());
    }
    // The pieces (connected components) of the map's graph. In the last look for further
    // groups (link_across_map_pieces) two pairs whose map vertices lie in different pieces are
    // linked by the ground truth alone: at a break the map's graph falls into pieces that no
    // edge joins (a corridor closed at the cut, a part laid over another's rooms and cut by
    // their walls), and there the map cannot vouch for the link either way (doc/matching.md,
    // "A part cut into pieces of the map's graph").
    // The pieces are those of the match's view of the graph (the edges near_map walks).
    const std::vector<int> map_piece = piecesOf(ctx.map);
    bool link_across = false;
    auto linkedPairs = [&](const Candidate& x, const Candidate& y)
    {
        if (!std::binary_search(near_gt[x.gt].begin(), near_gt[x.gt].end(), y.gt)) return false;
        if (link_across && map_piece[x.map] != map_piece[y.map]) return true;
        return std::binary_search(near_map[x.map].begin(), near_map[x.map].end(), y.map);
    };
    // Once a group is accepted the maps are known to show one place, and a further part (a
    // broken map's small part) needs only min_part_group_vertices pairs, with a bridge to an
    // accepted group (checked in settle()).
    auto needed = [&]()
    {
        return !out.cores.empty() && p.min_part_group_vertices < min_size
                   ? p.min_part_group_vertices
                   : min_size;
    };
    // Horn's fit of a set of candidates, map to ground truth.
    // The ground-truth and map positions of a set of candidates.
    auto pointsOf = [&](const std::vector<int>& set)
    {
        std::pair<std::vector<Eigen::Vector2d>, std::vector<Eigen::Vector2d>> pts;
        for (int i : set)
            pts.first.push_back(pg(cands[i].gt)), pts.second.push_back(pm(cands[i].map));
        return pts;
    };
    auto fitOf = [&](const std::vector<int>& set, double* mse)
    {
        const auto [a, b] = pointsOf(set);
        return hornAlign(a, b, mse);
    };
    // Each accepted group's fit, made once in accept() (settle() asks for it on every try).
    std::vector<Transform2D> core_fits;
    // A further group less similar than a small group must be (a part whose vertices'
    // attributes changed at the cut) is kept when the walls around it agree under its fit and
    // pin it (min_part_wall_agreement, max_wall_pinning); a small first group needs walls that
    // agree too (min_first_group_wall_agreement, below). The walls are indexed on first use.
    std::optional<WallIndex> gt_walls, map_walls;
    auto indexWalls = [&]
    {
        if (!gt_walls) gt_walls.emplace(gt.wall_points_m);
        if (!map_walls) map_walls.emplace(map.wall_points_m);
    };
    const double wall_tolerance = wallTolerance(p.wall_tolerance_m, gt, map);
    // Walls that agree on at least `min_share` of their length and pin the fit
    // (max_wall_pinning). A share is 0 where either map has no walls.
    auto agreeOnAndPin = [&](const WallAgreement& w, double min_share)
    { return w.vouches(min_share, p.max_wall_pinning); };
    // The small part's wall test (also a grown pair's that only its walls vouch for).
    auto agreeAndPin = [&](const WallAgreement& w)
    { return agreeOnAndPin(w, p.min_part_wall_agreement); };
    // The agreement of the walls around a group under a fit; their pinning only when the share
    // is at least pinning_from_share (a caller that refuses a smaller share need not pay for it;
    // above 1: never), and only as far as max_wall_pinning, the most any caller accepts.
    auto wallsOf =
        [&](const std::vector<int>& group, const Transform2D& fit, double pinning_from_share)
    {
        indexWalls();
        std::vector<std::pair<int, int>> pairs;
        for (int i : group) pairs.emplace_back(cands[i].gt, cands[i].map);
        return wallAgreement(gt, map, *gt_walls, *map_walls, pairs, fit, p.wall_margin_m,
                             wall_tolerance, pinning_from_share, p.max_wall_pinning);
    };
    // One pair's walls: their agreement under a transform (pinning asked when
    // pinning_from_share <= 1), and their ICP alignment from a transform, reaching as far as
    // the pair's error under it or the wall tolerance.
    auto pairWallsUnder = [&](int a, int b, const Transform2D& t, double pinning_from_share)
    {
        indexWalls();
        return wallAgreement(gt, map, *gt_walls, *map_walls, {{a, b}}, t, p.wall_margin_m,
                             wall_tolerance, pinning_from_share, p.max_wall_pinning);
    };
    auto pairWallsByIcp = [&](int a, int b, const Transform2D& start, double error)
    {
        indexWalls();
        return alignWallsByIcp(gt, map, *gt_walls, *map_walls, {{a, b}}, p.wall_margin_m, start,
                               std::max(error, wall_tolerance));
    };
    // A further group's walls under their own alignment (walls_under_own_alignment): the ICP
    // of the walls around its vertices from its fit, reaching as far as its pairs' largest
    // error, kept when it still places every pair within its tolerance (as settling measures
    // it, from the group's centre); none otherwise, for a first group, or with the rule off.
    auto ownWallsAlignment = [&](const std::vector<int>& group,
                                 const Transform2D& fit) -> std::optional<Transform2D>
    {
        if (!p.walls_under_own_alignment || out.cores.empty()) return std::nullopt;
        indexWalls();
        std::vector<std::pair<int, int>> pairs;
        double reach = wall_tolerance;
        for (int i : group)
        {
            pairs.emplace_back(cands[i].gt, cands[i].map);
            reach = std::max(reach, offBy(cands[i], fit));
        }
        const auto own =
            alignWallsByIcp(gt, map, *gt_walls, *map_walls, pairs, p.wall_margin_m, fit, reach);
        if (!own) return std::nullopt;
        const Eigen::Vector2d centre = centreOf(group);
        for (int i : group)
            if (!placedBy(cands[i], *own, centre)) return std::nullopt;
        return own;
    };
    // The walls' agreement around a group under its fit, or, when that fails `passes` and
    // `own_alignment` is asked, under their own alignment (above) if it has one and at least
    // own_alignment_min_wall_agreement of the walls agree under the fit.
    auto wallsOfGroup = [&](const std::vector<int>& group, const Transform2D& fit,
                            double pinning_from_share, auto passes, bool own_alignment)
    {
        const WallAgreement w = wallsOf(group, fit, pinning_from_share);
        if (passes(w) || !own_alignment || w.share < p.own_alignment_min_wall_agreement) return w;
        const auto own = ownWallsAlignment(group, fit);
        return own ? wallsOf(group, *own, pinning_from_share) : w;
    };
    // The small part's wall test of a group under a fit (or their own alignment, when asked);
    // never passed with the test off (min_part_wall_agreement = 0).
    auto wallsAgreeAndPin =
        [&](const std::vector<int>& group, const Transform2D& fit, bool own_alignment = false)
    {
        return p.min_part_wall_agreement > 0.0 &&
               agreeAndPin(
                   wallsOfGroup(group, fit, p.min_part_wall_agreement, agreeAndPin, own_alignment));
    };
    // Asked of further groups, and of a small graph's first group: a first group that decides
    // that two big maps show one place has its own tests (significance, its walls and its
    // pairs' walls), but a small graph's has only its similarity or its walls.
    auto wallsConfirm = [&](const std::vector<int>& group, const Transform2D& fit)
    { return (!out.cores.empty() || small_graph) && wallsAgreeAndPin(group, fit); };
    // Whether a pair's walls agree where it is, made once per pair: under the fit of the first
    // group that asks or, failing that, under an ICP of the pair's own walls from it (a drifted
    // map's pair lies a few decimetres off one rigid fit of a big group); -1 without walls
    // around both vertices. Every group the consensus proposes asks again, and the groups that
    // hold one pair place it alike, within the ICP's reach.
    std::map<std::size_t, int> pair_walls;
    // The ICP of a pair's own walls from `fit`, when they agree under it
    // (min_part_wall_agreement); none otherwise.
    auto ownWallsFit = [&](int i, const Transform2D& fit) -> std::optional<Transform2D>
    {
        const int a = cands[i].gt, b = cands[i].map;
        const auto walls_fit = pairWallsByIcp(a, b, fit, offBy(cands[i], fit));
        if (walls_fit && pairWallsUnder(a, b, *walls_fit, 2.0).share >= p.min_part_wall_agreement)
            return walls_fit;
        return std::nullopt;
    };
    auto pairWallsAgree = [&](int i, const Transform2D& fit)
    {
        const auto [known, fresh] = pair_walls.emplace(pairKey(cands[i]), -1);
        if (!fresh) return known->second;
        const int a = cands[i].gt, b = cands[i].map;
        const WallAgreement w = pairWallsUnder(a, b, fit, 2.0);
        if (!w.walls_on_both) return known->second;
        const bool agrees = w.share >= p.min_part_wall_agreement || ownWallsFit(i, fit).has_value();
        known->second = agrees ? 1 : 0;
        return known->second;
    };
    // The share of a group's pairs (those with walls around both vertices) whose walls disagree
    // where they are (pairWallsAgree), when it is at least `limit`; none otherwise. Stops once
    // too many agree for it.
    auto pairWallsDisagree = [&](const std::vector<int>& group,
                                 double limit) -> std::optional<double>
    {
        indexWalls();
        const Transform2D fit = fitOf(group, nullptr);
        const double size = double(group.size());
        int agree = 0, disagree = 0;
        for (int i : group)
        {
            const int agrees = pairWallsAgree(i, fit);
            if (agrees < 0) continue;
            agrees ? ++agree : ++disagree;
            // Fewer than `limit` of the counted pairs can disagree now, whatever the rest do.
            if (double(agree) > (1.0 - limit) * size) return std::nullopt;
        }
        const int counted = agree + disagree;
        if (counted == 0 || double(disagree) < limit * double(counted)) return std::nullopt;
        return double(disagree) / double(counted);
    };
    // A pair's turn by its own walls: their ICP from the fit of the first group that asks (as
    // pairWallsAgree), when the walls agree under it; none otherwise. Made once per pair, for
    // every placement played out (`pair_turns`, by pairKey()).
    auto pairTurn = [&](int i, const Transform2D& fit)
    {
        const auto [known, fresh] = pair_turns.emplace(pairKey(cands[i]), std::nullopt);
        if (fresh)
            if (const auto walls_fit = ownWallsFit(i, fit)) known->second = walls_fit->yaw_deg;
        return known->second;
    };
    // Drops the group's pairs whose walls turn more than max_pair_turn_deg from the turn that
    // most of its pairs' walls agree with (ties: the one they deviate from least in sum), and
    // the pairs without a turn (walls that do not agree under their own ICP: a vertex on the
    // seam of two parts has half of each's) that the fit of the agreeing pairs puts beyond
    // their tolerance. True when a pair left.
    auto dropTurnedPairs = [&](std::vector<int>& group, const Transform2D& fit)
    {
        if (!(p.max_pair_turn_deg > 0.0) || group.size() < 3) return false;
        std::vector<std::optional<double>> turn;  // each pair's, in the group's order
        std::size_t measured = 0;
        for (int i : group)
        {
            turn.push_back(pairTurn(i, fit));
            if (turn.back()) ++measured;
        }
        if (measured < 3) return false;
        auto apart = [](double a, double b) { return std::abs(std::remainder(a - b, 360.0)); };
        double centre = 0.0;
        std::pair<std::size_t, double> best{0, 0.0};  // agreeing pairs, minus their deviations
        for (const auto& t : turn)
        {
            if (!t) continue;
            std::pair<std::size_t, double> key{0, 0.0};
            for (const auto& other : turn)
                if (other)
                    if (const double d = apart(*other, *t); d <= p.max_pair_turn_deg)
                        ++key.first, key.second -= d;
            if (key > best) best = key, centre = *t;
        }
        auto agrees = [&](std::size_t k)
        { return turn[k] && apart(*turn[k], centre) <= p.max_pair_turn_deg; };
        std::vector<int> agreeing;  // in the group's order
        for (std::size_t k = 0; k < group.size(); ++k)
            if (agrees(k)) agreeing.push_back(group[k]);
        // The agreeing pairs' fit places the pairs without a turn, when they are 3 or more.
        std::optional<Transform2D> agreeing_fit;
        Eigen::Vector2d agreeing_centre = Eigen::Vector2d::Zero();
        if (agreeing.size() >= 3)
            agreeing_fit = fitOf(agreeing, nullptr), agreeing_centre = centreOf(agreeing);
        std::vector<int> kept;
        for (std::size_t k = 0; k < group.size(); ++k)
        {
            const Candidate& c = cands[group[k]];
            if (turn[k] ? agrees(k)
                        : !agreeing_fit || offBy(c, *agreeing_fit) <=
                                               tolerance(c, (pg(c.gt) - agreeing_centre).norm()))
                kept.push_back(group[k]);
        }
        if (kept.size() == group.size()) return false;
        group = std::move(kept);
        return true;
    };
    auto meanSimilarity = [&](const std::vector<int>& set)
    {
        double sum = 0.0;
        for (int i : set) sum += S(cands[i].gt, cands[i].map);
        return set.empty() ? 0.0 : sum / double(set.size());
    };
    // Significant among the current candidates by the first group's a contrario test
    // (max_false_alarms): fewer than that many groups as big expected by chance in a
    // consistency graph of this density.
    auto significantAmongCandidates = [&](const std::vector<int>& group)
    {
        const double density =
            n > 1 ? double(consistent_pairs) / (0.5 * double(n) * double(n - 1)) : 0.0;
        return log10FalseAlarms(double(n), double(group.size()), density) <=
               std::log10(p.max_false_alarms);
    };
    // In the wider look at the leftovers (leftover_candidates_per_vertex) the longer lists
    // make chance groups likelier: there a group must be significant as a first group must
    // be. Without it, near-twins (whose first group is a chance one) gained 47 false pairs
    // on corpus seeds 2-16; with it 6 (doc/matching.md, "A wider look at the leftovers").
    // So must a group found with the links across the map's pieces, which come after the
    // wider look (with it off, on the first lists).
    auto significantWhereAsked = [&](const std::vector<int>& group)
    {
        return !(per_vertex > p.candidates_per_vertex || link_across) ||
               significantAmongCandidates(group);
    };
    // The rules a linked group must meet: extent, one rigid part, a bridge to the accepted
    // groups, similarity.
    auto acceptable = [&](const std::vector<int>& group)
    {
        double extent = 0.0;
        for (int i : group)
            for (int j : group) extent = std::max(extent, dist_gt(cands[i].gt, cands[j].gt));
        if (extent < p.min_group_extent_m || !significantWhereAsked(group)) return false;
        // One rigid part, as the paper's brokenness groups are (its SquaredErrorThreshold): a
        // chance group keeps every pair within its own tolerance but spreads the errors to the
        // limit (two column halls of different buildings: 0 of 17 pairs true).
        double mse = 0.0;
        const Transform2D fit = fitOf(group, &mse);
        if (mse > p.max_group_squared_error_m2) return false;
        // Its mean similarity, and the walls' test under its fit made once (several rules ask
        // for each).
        const double similarity = meanSimilarity(group);
        std::optional<bool> walls_confirm;
        auto wallsAgree = [&]
        {
            if (!walls_confirm) walls_confirm = wallsConfirm(group, fit);
            return *walls_confirm;
        };
        if (!out.cores.empty())
        {
            // A further part meets the accepted groups at its cut: where one of its
            // ground-truth vertices lies within support_hops edges of an accepted group's
            // vertex, their map partners lie about as far apart (a turn at the cut changes that
            // distance by at most part_bridge_ratio of it; in the map the cut itself often
            // severs the edges between them, so map edges are not asked for). A set that sits
            // next to an accepted group in the ground truth but elsewhere in the map is a
            // chance group (a hall's lattice of columns repeats). A small part needs such a
            // bridge; a big one needs it only when it has a ground-truth neighbour at all (a
            // graph piece of its own has none).
            bool neighbour = false, bridge = false;
            for (int i : group)
                for (int g : near_gt[cands[i].gt])
                {
                    const int m = ctx.gt_to_map[g];
                    if (m < 0) continue;
                    neighbour = true;
                    const double dg = dist_gt(g, cands[i].gt);
                    const double dm = dist_map(m, cands[i].map);
                    bridge = bridge || std::abs(dg - dm) <= p.distance_tolerance_m +
                                                                cands[i].uncertainty_m +
                                                                p.part_bridge_ratio * dg;
                }
            // A big group's neighbour pairs may all lie far from the pivot of its turn, where
            // the turn changes their distances by more than part_bridge_ratio (a cut across a
            // whole building, turned about its one end). Where the robot crossed the break
            // both fits place the map alike: that pivot lies next to both groups. A small group
            // may lack a neighbour pair for the same reason, or because the vertices at its cut
            // changed (a junction that lost an edge to the cut is no candidate): it bridges by
            // its pivot too, when its walls also agree and pin its fit (three pairs are weaker
            // evidence than five; doc/matching.md, "The pivot of a small part").
            const bool small = int(group.size()) < min_size;
            const bool by_neighbour = bridge;
            for (std::size_t k = 0; k < out.cores.size() && !bridge && (small || neighbour); ++k)
            {
                const auto pivot = agreementPoint(fit, core_fits[k]);
                if (!pivot) continue;
                auto near = [&](int g)
                { return (pg(g) - *pivot).norm() <= p.part_pivot_distance_m; };
                bridge = std::any_of(group.begin(), group.end(),
                                     [&](int i) { return near(cands[i].gt); }) &&
                         std::any_of(out.cores[k].begin(), out.cores[k].end(),
                                     [&](const auto& pair) { return near(pair.first); });
            }
            // A small group that touches no accepted group in the ground truth (the parts
            // between them unmatched) may have neither: it bridges when it is as similar as a
            // small graph's group must be, and, as every small group not bridged by a
            // neighbour pair, its walls agree and pin its fit (isolated_part_bridge;
            // doc/matching.md, "A part that touches no matched part").
            if (small && !bridge && !neighbour && p.isolated_part_bridge)
                bridge = similarity >= p.min_small_group_similarity;
            // A big group whose neighbour pairs the turn moved and whose pivot lies far from
            // the accepted groups (both parts turned, each about its own pivot) bridges when
            // its walls agree and pin its fit, as a small part's must (part_wall_bridge).
            if (!small && neighbour && !bridge && p.part_wall_bridge) bridge = wallsAgree();
            if (small ? !bridge : (neighbour && !bridge)) return false;
            if (small && !by_neighbour && !wallsAgree()) return false;
            // A further group that neither its attributes nor its walls vouch for has only its
            // distances, which a hall's lattice or a symmetric building repeats
            // (min_unconfirmed_group_similarity; doc/matching.md, "A group that only distances
            // vouch for").
            if (similarity < p.min_unconfirmed_group_similarity && !wallsAgree()) return false;
        }
        if (int(group.size()) < p.min_group_vertices)
        {
            // As similar as a small graph's group must be (below).
            if (similarity < p.min_small_group_similarity && !wallsAgree()) return false;
        }
        return true;
    };
    // A further group none of whose linked pieces is big enough (a part whose vertices between
    // its counterparts changed at the cut) is kept whole when it has min_scattered_part_pairs
    // and is as significant among the candidates as a first group must be, it is another part (its
    // fit misplaces at least half of every accepted group's pairs: scattered pairs of an accepted
    // part are growing's to reach, and their own fit puts them a few decimetres off), it is
    // acceptable as every group must be, and its walls agree and pin its fit
    // (scattered_part_groups; doc/matching.md, "A part in scattered pieces"). The walls last: they
    // cost the most (on the Intel pair four such tests, all refusing, took 6 ms when asked before
    // the rest).
    auto scatteredPart = [&](const std::vector<int>& group)
    {
        if (!p.scattered_part_groups || out.cores.empty() ||
            int(group.size()) < p.min_scattered_part_pairs || !significantAmongCandidates(group))
            return false;
        const Transform2D fit = fitOf(group, nullptr);
        const Eigen::Vector2d centre = centreOf(group);
        for (const auto& core : out.cores)
        {
            std::size_t placed = 0;
            for (const auto& [a, b] : core)
                placed += placedBy({a, b, S(a, b), uncertainty(a, b)}, fit, centre) ? 1 : 0;
            if (2 * placed >= core.size()) return false;
        }
        // Its walls under their own alignment when their fit's fails (walls_under_own_alignment):
        // the whole is otherwise a part already.
        return acceptable(group) && wallsAgreeAndPin(group, fit, true);
    };
    // A small further group whose links leave no piece big enough (a part of 3 or 4 pairs
    // whose vertices between them changed at the cut, or lie farther apart than support_hops
    // edges) is kept whole when its walls agree on min_unlinked_part_wall_agreement of their
    // length and pin its fit, and it is acceptable as every small group must be (a bridge,
    // similarity or walls). The wider look and the links across the map's pieces ask a group
    // to be significant, which 3 or 4 pairs seldom are (doc/matching.md, "A small part whose
    // pairs the links do not join").
    auto unlinkedSmallPart = [&](const std::vector<int>& group)
    {
        if (!(p.min_unlinked_part_wall_agreement > 0.0) || out.cores.empty() ||
            int(group.size()) < needed() || int(group.size()) >= min_size)
            return false;
        // Significance (where acceptable() asks for it) first: it is cheap, and the walls are
        // not (on the Intel pair 271 groups asked for them, 232 of them in the later looks;
        // with the pinning too, 70 ms). The pinning only when the share passes.
        if (!significantWhereAsked(group)) return false;
        auto passes = [&](const WallAgreement& w)
        { return agreeOnAndPin(w, p.min_unlinked_part_wall_agreement); };
        return passes(wallsOfGroup(group, fitOf(group, nullptr), p.min_unlinked_part_wall_agreement,
                                   passes, true)) &&
               acceptable(group);
    };
    // A candidate group becomes a group: a rigid fit (distances alone accept a mirror image)
    // that drops the worst pair while any lies farther from its place than its tolerance; the
    // biggest part linked in both graphs (a further group's other linked pieces joined when
    // they may be, or the whole kept when it is a scattered or an unlinked small part); then the
    // size, extent, bridge and similarity rules. Returns false (and the group as far as it got)
    // when it is not acceptable.
    auto settleOnce = [&](std::vector<int>& group)
    {
        const int need = needed();
        for (;;)
        {
            if (int(group.size()) < need) return false;
            double mse = 0.0;
            const Transform2D T = fitOf(group, &mse);
            const Eigen::Vector2d centre = centreOf(group);
            // The pair farthest beyond its tolerance, and the one placed worst against it.
            int worst = -1, worst_placed = 0;
            double worst_excess = 0.0, worst_ratio = -1.0;
            for (std::size_t k = 0; k < group.size(); ++k)
            {
                const Candidate& c = cands[group[k]];
                const double error = offBy(c, T), tol = tolerance(c, (pg(c.gt) - centre).norm());
                if (error - tol > worst_excess) worst_excess = error - tol, worst = int(k);
                if (error / tol > worst_ratio) worst_ratio = error / tol, worst_placed = int(k);
            }
            // Every pair within its tolerance, but the fit not one rigid part: a further
            // group loses the pair placed worst against its tolerance (a hall's vertex that
            // slid along the medial axis; trim_further_groups_to_rigid). A first group is
            // refused whole by acceptable() instead.
            if (worst < 0 && p.trim_further_groups_to_rigid && !out.cores.empty() &&
                mse > p.max_group_squared_error_m2 && int(group.size()) > need)
                worst = worst_placed;
            if (worst < 0) break;
            group.erase(group.begin() + worst);
        }
        // Topological support: a true group is a connected piece of both graphs; a set
        // consistent by chance (different buildings made of the same corridors and rooms) is
        // scattered. Only the biggest linked component stays; a further group's other pieces
        // join it when its own fit places them and the walls vouch for the whole
        // (min_joined_piece_pairs). A further group no piece of which is big enough, or whose
        // biggest piece is refused (scattered_part_when_piece_refused), stays whole when
        // scatteredPart() finds it a part; a small one no piece of which is big enough, when
        // unlinkedSmallPart() does.
        const std::vector<std::vector<int>> pieces = linkedComponents(group, cands, linkedPairs);
        if ((pieces.empty() || int(pieces.front().size()) < need) &&
            (scatteredPart(group) || unlinkedSmallPart(group)))
            return true;
        const std::vector<int> whole = group;
        group = pieces.empty() ? std::vector<int>{} : pieces.front();
        if (int(group.size()) < need) return false;
        if (!out.cores.empty() && p.min_joined_piece_pairs > 0 && pieces.size() > 1)
        {
            std::vector<int> joined = group;
            const Transform2D piece_fit = fitOf(group, nullptr);
            const Eigen::Vector2d centre = centreOf(group);
            auto placed = [&](int i) { return placedBy(cands[i], piece_fit, centre); };
            for (std::size_t k = 1; k < pieces.size(); ++k)
                if (int(pieces[k].size()) >= p.min_joined_piece_pairs &&
                    std::all_of(pieces[k].begin(), pieces[k].end(), placed))
                    joined.insert(joined.end(), pieces[k].begin(), pieces[k].end());
            std::sort(joined.begin(), joined.end());
            // Joined only when the whole is a group too (a piece can give it a neighbour pair
            // whose distance the turn changed, which a piece of its own does not have).
            if (joined.size() > group.size() && wallsConfirm(joined, fitOf(joined, nullptr)) &&
                acceptable(joined))
            {
                group = std::move(joined);
                return true;
            }
        }
        if (acceptable(group)) return true;
        // The biggest piece refused (a few pairs of a part spanning less than
        // min_group_extent_m, or without a bridge) while the whole is a part by the scattered
        // part's tests: the part's other pairs lie more than support_hops edges away, because
        // the vertices between them changed at the cut.
        if (p.scattered_part_when_piece_refused && pieces.size() > 1 && scatteredPart(whole))
        {
            group = whole;
            return true;
        }
        return false;
    };
    // Then the settled group's pairs whose own walls turn away from the group's turn leave it
    // (another part's pairs near the pivot of the turn between the two: max_pair_turn_deg),
    // and what is left is settled again. It replaces the group when it is still a group; else
    // the group stays as it was (a small part's pair at its cut, whose walls are half the
    // neighbour part's, can be its only bridge; doc/matching.md, "A pair whose walls turn
    // away").
    auto settle = [&](std::vector<int>& group)
    {
        if (!settleOnce(group)) return false;
        std::vector<int> pure = group;
        if (dropTurnedPairs(pure, fitOf(pure, nullptr)) && settleOnce(pure))
            group = std::move(pure);
        return true;
    };
    // A further group whose walls agree on less than further_group_min_wall_agreement of their
    // length, under its fit and under their own alignment: its vertices agree, its walls do
    // not. A hall's lattice of columns repeats under a quarter turn, and its junctions paired a
    // quarter turn off keep their distances and enough similarity, while the rooms' walls
    // around them do not agree (fresh corpus seed 26's column_hall_26004/broken_3: 5 pairs,
    // similarity 0.65, walls 0.16; doc/matching.md, "A further group whose walls disagree").
    // Never where either map lacks walls around the group.
    auto wallsDisagreeOutright = [&](const std::vector<int>& group)
    {
        if (out.cores.empty() || !(p.further_group_min_wall_agreement > 0.0)) return false;
        const Transform2D fit = fitOf(group, nullptr);
        const WallAgreement w = wallsOf(group, fit, 2.0);
        if (!w.walls_on_both || w.share >= p.further_group_min_wall_agreement) return false;
        const auto own = ownWallsAlignment(group, fit);
        return !own || wallsOf(group, *own, 2.0).share < p.further_group_min_wall_agreement;
    };
    // A further group (a broken map's other part): the best acceptable consensus of the pool.
    // Near a break a clique mixes two parts (within a few metres of the pivot a turn of 10-30
    // degrees keeps distances within tolerance) and ties between such cliques are common; a fit
    // of a mixed clique is a compromise between the parts, dropping its worst pairs can leave
    // neither, and a rejected clique takes the part's true pairs with it. So every two linked,
    // consistent pairs at least min_consensus_baseline_m apart propose the rigid transform they
    // define; the pairs it places within tolerance (position noise, plus the ratio over the
    // distance for bending), one per vertex, are settled, and the biggest acceptable group wins
    // (then the smallest placement error). The first group only falls back to it, within a
    // clique that does not settle (below): over all candidates the consensus also finds chance
    // groups between different buildings (doc/matching.md).
    auto bestConsensus = [&](const std::vector<int>& pool)
    {
        std::vector<int> best;
        double best_err = 0.0;
        std::vector<std::pair<double, int>> in;
        std::set<std::vector<int>> tried;
        for (std::size_t i = 0; i < pool.size(); ++i)
            for (std::size_t j = i + 1; j < pool.size(); ++j)
            {
                const Candidate &ci = cands[pool[i]], &cj = cands[pool[j]];
                if (!adjacent[std::size_t(pool[i]) * n + pool[j]] || !linkedPairs(ci, cj)) continue;
                if (dist_gt(ci.gt, cj.gt) < p.min_consensus_baseline_m) continue;
                const Transform2D T = hornAlign({pg(ci.gt), pg(cj.gt)}, {pm(ci.map), pm(cj.map)});
                in.clear();
                for (int k : pool)
                {
                    const Candidate& c = cands[k];
                    const double dist = std::min(dist_gt(c.gt, ci.gt), dist_gt(c.gt, cj.gt));
                    const double err = offBy(c, T);
                    if (err <= tolerance(c, dist)) in.emplace_back(err, k);
                }
                if (in.size() < std::max<std::size_t>(best.size(), 3)) continue;
                // One to one: the best placed pair of each vertex.
                std::sort(in.begin(), in.end());
                std::vector<int> kept;
                for (const auto& [err, k] : in)
                {
                    bool clash = false;
                    for (int q : kept)
                        clash = clash || cands[q].gt == cands[k].gt || cands[q].map == cands[k].map;
                    if (!clash) kept.push_back(k);
                }
                if (kept.size() < best.size()) continue;
                std::sort(kept.begin(), kept.end());
                // Many pairs of one part propose the same set: settle it once.
                if (!tried.insert(kept).second) continue;
                if (!settle(kept)) continue;
                double err_sum = 0.0;
                for (int k : kept) err_sum += offBy(cands[k], T);
                if (!(kept.size() > best.size() ||
                      (kept.size() == best.size() && err_sum < best_err)))
                    continue;
                // A further group half of whose pairs have walls that disagree where they are,
                // as a first group is refused for (further_group_disagreeing_pair_share;
                // doc/matching.md, "The walls of each pair of a further group"): a wing of a
                // symmetric building placed by its symmetry, its vertices alike and its
                // distances kept. Asked only of a group that would be the best so far: it may
                // cost an ICP per pair.
                if (!out.cores.empty() && p.further_group_disagreeing_pair_share > 0.0 &&
                    pairWallsDisagree(kept, p.further_group_disagreeing_pair_share))
                    continue;
                if (wallsDisagreeOutright(kept)) continue;
                best = std::move(kept), best_err = err_sum;
            }
        return best;
    };
    auto accept = [&](const std::vector<int>& group)
    {
        std::vector<std::pair<int, int>> core;
        for (int i : group)
        {
            core.emplace_back(cands[i].gt, cands[i].map);
            ctx.gt_to_map[cands[i].gt] = cands[i].map;
            ctx.map_to_gt[cands[i].map] = cands[i].gt;
        }
        out.cores.push_back(std::move(core));
        core_fits.push_back(fitOf(group, nullptr));
        buildCandidates();
    };
    // The maximal cliques of the pool with at least the size needed (within max_clique_steps),
    // each with the group it settles to; those that do not settle are left out.
    auto settledMaximalCliques = [&](const std::vector<int>& pool)
    {
        std::size_t steps = 0;
        const std::vector<std::vector<int>> cliques =
            maximalCliques(adjacent, n, pool, needed(), std::size_t(p.max_clique_steps), &steps);
        out.clique_steps += steps;
        std::vector<std::pair<std::vector<int>, std::vector<int>>> settled;
        for (const std::vector<int>& clique : cliques)
        {
            std::vector<int> group = clique;
            if (settle(group)) settled.emplace_back(clique, std::move(group));
        }
        return settled;
    };
    // On a small graph the maximum clique is often tied (a flat's layout and its robot map:
    // among 26 candidates two cliques of 4, one of them true), and which one the search
    // returns is chance; rejected, it takes the pairs it shares with the other along. So every
    // maximal clique of at least the size needed is settled, and the first group is the
    // clique that settles to the most pairs, then the one whose walls agree best under its fit,
    // then the most similar; `fallback` (the maximum clique) when none settles.
    auto bestMaximalClique = [&](const std::vector<int>& pool, const std::vector<int>& fallback)
    {
        std::vector<int> best = fallback;
        std::tuple<std::size_t, double, double> best_key{0, 0.0, 0.0};
        for (const auto& [clique, group] : settledMaximalCliques(pool))
        {
            const double walls = wallsOf(group, fitOf(group, nullptr), 2.0).share;
            const std::tuple<std::size_t, double, double> key{group.size(), walls,
                                                              meanSimilarity(group)};
            if (key > best_key) best_key = key, best = clique;
        }
        return best;
    };
    // The groups the maximal cliques of the pool settle to, each once, best first: the most
    // pairs, then the most similar (not by their walls: first_group_from_maximal_cliques,
    // below).
    auto maximalCliqueGroups = [&](const std::vector<int>& pool)
    {
        std::vector<std::pair<std::tuple<std::size_t, double>, std::vector<int>>> groups;
        std::set<std::vector<int>> seen;
        for (auto& [clique, group] : settledMaximalCliques(pool))
        {
            std::sort(group.begin(), group.end());
            if (!seen.insert(group).second) continue;
            groups.push_back({{group.size(), meanSimilarity(group)}, std::move(group)});
        }
        std::stable_sort(groups.begin(), groups.end(),
                         [](const auto& x, const auto& y) { return x.first > y.first; });
        std::vector<std::vector<int>> ranked;
        for (auto& g : groups) ranked.push_back(std::move(g.second));
        return ranked;
    };
    // Asked once per search (first_group_from_maximal_cliques), not of a rival placement given
    // in advance (below).
    bool maximal_cliques_asked = false;
    // 3. Groups. The first: the maximum clique of the free candidates, settled; a clique that
    //    is not acceptable leaves the pool (more tries, more chance groups between different
    //    buildings); once, the best settling maximal clique when the maximum one settles into
    //    nothing. Then, while groups are found, the best acceptable consensus of the pool:
    //    each rigid part of a broken or bent map becomes its own group.
    // A first group not found among the first candidate lists is sought once more among
    // leftover_candidates_per_vertex lists (first_group_wider_look): in a hall's lattice, whose
    // junctions all look alike, a true partner can rank below the first lists when a break
    // changed its attributes (doc/matching.md, "A wider look for the first group"). The pairs
    // of the cliques refused in the first look are asked again: among the longer lists they can
    // belong to a bigger clique. The significance test counts the longer lists' candidates.
    bool wider = false;
    int attempt = 0;
    // Starts the wider look, its attempts counted afresh (false: there is none to make).
    auto widen = [&]
    {
        if (wider || !p.first_group_wider_look || first ||
            per_vertex >= p.leftover_candidates_per_vertex)
            return false;
        wider = true;
        per_vertex = p.leftover_candidates_per_vertex;
        buildCandidates();
        std::fill(rejected.begin(), rejected.end(), 0);
        maximal_cliques_asked = false;
        attempt = -1;
        return true;
    };
    for (; out.cores.empty(); ++attempt)
    {
        if (attempt >= 2 * p.max_groups)
        {
            if (!widen()) break;
            continue;
        }
        std::vector<int> pool;
        for (int i = 0; i < n; ++i)
            if (!rejected[pairKey(cands[i])]) pool.push_back(i);
        MaxClique search(adjacent, n, std::size_t(p.max_clique_steps));
        std::vector<int> clique;
        if (attempt == 0 && first)
        {
            // A rival placement of another run's first group (below), in place of the maximum
            // clique: no search, only the density of the pool for the significance test.
            search.countEdges(pool);
            for (int i : pool)
                if (std::find(first->begin(), first->end(),
                              std::make_pair(cands[i].gt, cands[i].map)) != first->end())
                    clique.push_back(i);
        }
        else
        {
            clique = search.run(pool);
            out.clique_steps += search.steps();
            if (small_graph && int(clique.size()) >= needed())
                clique = bestMaximalClique(pool, clique);
        }
        if (int(clique.size()) < needed())
        {
            if (!widen()) break;
            continue;
        }
        for (int i : clique) rejected[pairKey(cands[i])] = 1;
        std::sort(clique.begin(), clique.end());
        // Significance: the first group decides that the maps show one place. Among a few
        // hundred candidates a group of 5 consistent pairs happens by chance (two buildings of
        // one building code, a hall's lattice: the corpus's false first groups were all 5
        // pairs); how big a group must be grows with the candidates. A smaller group (a small
        // graph's) has the similarity rule instead.
        // A small significant group must also have walls that agree under its fit. The a
        // contrario count takes the candidates' agreements as independent, but two buildings
        // of one style share room sizes and corridor spacings, which makes consistent chance
        // groups of 5-6 pairs more likely than it says; their walls disagree (held-out corpus
        // seeds: shares 0.28-0.49, true first groups of this size 0.51 and more;
        // doc/matching.md, "The walls of a small first group").
        const double m = double(pool.size());
        const double density = m > 1.0 ? double(search.edges()) / (0.5 * m * (m - 1.0)) : 0.0;
        // A group along one line (a corridor's junctions) checks a spacing pattern only: its
        // vertices within distance_tolerance_m of the line, every distance between them is
        // fixed, within tolerance, by their places along it, so the a contrario count, which
        // takes its s(s-1)/2 distances as independent, overstates it. Such a group cannot be
        // the first (a small graph's group, judged by its similarity instead, is not asked):
        // a true first group also holds vertices off the line (rooms), and every
        // chance first group of corpus seeds 1-5 narrower than 0.25 m was one (0.08-0.13 m
        // wide; true ones 0.34 m and more; doc/matching.md, "A first group along one line").
        double log_nfa = 0.0, wall_share = -1.0, width = -1.0, disagreeing = -1.0;
        auto significant = [&](const std::vector<int>& group)
        {
            wall_share = width = disagreeing = -1.0;
            if (int(group.size()) < p.min_group_vertices) return true;
            log_nfa = log10FalseAlarms(m, double(group.size()), density);
            if (log_nfa > std::log10(p.max_false_alarms)) return false;
            if (int(group.size()) < p.first_group_wall_check_pairs &&
                p.min_first_group_wall_agreement > 0.0)
            {
                wall_share = wallsOf(group, fitOf(group, nullptr), 2.0).share;
                if (wall_share < p.min_first_group_wall_agreement) return false;
            }
            if (p.first_group_disagreeing_pair_share > 0.0)
                if (const auto share =
                        pairWallsDisagree(group, p.first_group_disagreeing_pair_share))
                {
                    disagreeing = *share;
                    wall_share = -1.0;  // the whole group's walls passed; its pairs' did not
                    return false;
                }
            const auto [a, b] = pointsOf(group);
            width = std::min(lineSpread(a), lineSpread(b));
            if (width < p.distance_tolerance_m) return false;
            width = -1.0;
            return true;
        };
        // A clique that mixes two parts (near a pivot their distances agree) settles into
        // neither: its fit is a compromise and dropping the worst pairs drops true ones. Then
        // the best consensus of the clique's own pairs may still be a group; not confirmed by
        // the whole clique, it must be as similar as a small group (a chance group between
        // different buildings is not: 17 false pairs on `different` with this rule, 34 without).
        const std::vector<int> whole = clique;
        bool ok = settle(clique);
        if (!ok)
        {
            clique = bestConsensus(whole);
            ok = !clique.empty() && meanSimilarity(clique) >= p.min_small_group_similarity;
        }
        const bool settled = ok;
        // The first group's tests (significant() above); the biggest group refused is reported.
        auto firstGroupTests = [&](const std::vector<int>& group)
        {
            if (significant(group)) return true;
            if (group.size() > out.refused_size)
            {
                out.refused_size = group.size();
                out.refused_false_alarms = std::pow(10.0, log_nfa);
                out.refused_candidates = pool.size();
                out.refused_wall_share = wall_share;
                out.refused_width_m = width;
                out.refused_disagreeing_pairs = disagreeing;
            }
            return false;
        };
        if (ok) ok = firstGroupTests(clique);
        // A maximum clique that mixes a broken map's parts, and whose own consensus is no
        // group, takes the parts' true pairs with it when it leaves the pool: the next
        // maximum clique is mixed again or a chance one. So, once per search, every maximal
        // clique of the pool is settled, and the best group (the most pairs, then the most
        // similar; not chosen by its walls) is the first group when its walls agree and pin its
        // fit, as a small part's must, and it passes the first group's tests above
        // (doc/matching.md, "A first group among the maximal cliques"). With
        // first_group_maximal_cliques_in_turn they are asked also when the maximum clique
        // settled but its group failed those tests (one part's corridor, along one line, while
        // the clique held another part's pairs too), and the groups are tried in turn until one
        // passes.
        const bool in_turn = p.first_group_maximal_cliques_in_turn;
        // Never with the small part's wall test off (min_part_wall_agreement = 0).
        if (!ok && !small_graph && p.first_group_from_maximal_cliques && !maximal_cliques_asked &&
            !(attempt == 0 && first) && (!settled || in_turn) && p.min_part_wall_agreement > 0.0)
        {
            maximal_cliques_asked = true;
            bool best = true;
            for (std::vector<int>& group : maximalCliqueGroups(pool))
            {
                // The best group after a maximum clique that did not settle needs the walls of
                // a small part (session 31). Every other group asked (a later one in turn, or
                // any after a refused maximum clique) is one more chance for a chance group's
                // walls to agree: it needs first_group_in_turn_min_wall_agreement of them.
                const double min_share = best && !settled
                                             ? p.min_part_wall_agreement
                                             : std::max(p.min_part_wall_agreement,
                                                        p.first_group_in_turn_min_wall_agreement);
                best = false;
                const WallAgreement w = wallsOf(group, fitOf(group, nullptr), min_share);
                if (agreeOnAndPin(w, min_share) && firstGroupTests(group))
                {
                    clique = std::move(group);
                    ok = true;
                    break;
                }
                if (!in_turn) break;
            }
        }
        // In the wider look, longer lists hold more chance groups, and two buildings of one
        // building code share its layouts: there the first group also needs the walls of a
        // small part (min_part_wall_agreement, max_wall_pinning), as a first group among the
        // maximal cliques does. Measured on corpus seeds 1-8 and 27-28: the three true first
        // groups found there have walls agreeing on 0.65-1.00 and pinning 0.75-0.92 (one, 0.65
        // and 0.92, is refused), the four chance ones (three near-twins, a different building)
        // 0.61-0.66 and 0.87-1.25. Asked before the rival placements of an accepted group.
        if (ok && wider && !wallsAgreeAndPin(clique, fitOf(clique, nullptr))) ok = false;
        if (ok && !first)
        {
            // Rival placements: maximum cliques of the candidates that pair the group's
            // vertices otherwise and that its fit places out of tolerance; each found leaves
            // the pool with the candidates its own fit places (a building symmetric under turns
            // of 72 degrees has 4). One nearly as big as the group (min_rival_size_ratio, as in
            // a ratio test) and as acceptable as a first group leaves the choice undecided by
            // size: findConsistentGroups() plays it out.
            std::vector<std::uint8_t> gt_in(n_gt, 0), map_in(n_map, 0), member(n, 0);
            for (int i : clique) gt_in[cands[i].gt] = map_in[cands[i].map] = member[i] = 1;
            auto misplaced = [&](const Candidate& c, const Transform2D& fit)
            { return offBy(c, fit) > tolerance(c, 0.0); };
            std::vector<int> rival_pool;
            const Transform2D fit = fitOf(clique, nullptr);
            for (int i : pool)
                if (!member[i] && (gt_in[cands[i].gt] || map_in[cands[i].map]) &&
                    misplaced(cands[i], fit))
                    rival_pool.push_back(i);
            for (int k = 0; k < p.max_rival_placements; ++k)
            {
                MaxClique rival_search(adjacent, n, std::size_t(p.max_clique_steps));
                std::vector<int> rival = rival_search.run(rival_pool);
                out.clique_steps += rival_search.steps();
                if (int(rival.size()) < needed()) break;
                std::fill(member.begin(), member.end(), 0);
                for (int i : rival) member[i] = 1;
                const Transform2D rival_fit = fitOf(rival, nullptr);
                rival_pool.erase(
                    std::remove_if(rival_pool.begin(), rival_pool.end(),
                                   [&](int i)
                                   { return member[i] || !misplaced(cands[i], rival_fit); }),
                    rival_pool.end());
                std::sort(rival.begin(), rival.end());
                // Nearly as big before settling (a cheap test first) and after.
                auto nearlyAsBig = [&]
                { return double(rival.size()) >= p.min_rival_size_ratio * double(clique.size()); };
                if (!nearlyAsBig() || !settle(rival) || !nearlyAsBig() || !significant(rival))
                    continue;
                out.rivals.emplace_back();
                for (int i : rival) out.rivals.back().emplace_back(cands[i].gt, cands[i].map);
            }
        }
        if (ok) accept(clique);
    }
    // Further groups start from the first lists, as after every group found (below).
    if (wider && !out.cores.empty())
    {
        per_vertex = p.candidates_per_vertex;
        buildCandidates();
    }
    while (!out.cores.empty() && int(out.cores.size()) < p.max_groups)
    {
        std::vector<int> pool(static_cast<std::size_t>(n));
        std::iota(pool.begin(), pool.end(), 0);
        const std::vector<int> group = bestConsensus(pool);
        if (!group.empty())
        {
            // Back to the first lists and links: the wider look and the links across the
            // map's pieces are the last resorts, asked again only when these find nothing more
            // (a group accepted there may be the bridge another part needs).
            per_vertex = p.candidates_per_vertex;
            link_across = false;
            accept(group);
            continue;
        }
        // No further group: look once more at the vertices left free, with longer candidate
        // lists (doc/matching.md, "A wider look at the leftovers"). A part cut off at a break
        // changed its vertices' attributes at the cut, and their true partners rank a few
        // places down. Ends: a last look (below) that finds nothing stops the search, and each
        // look that finds a group adds one (at most max_groups).
        if (per_vertex < p.leftover_candidates_per_vertex)
        {
            per_vertex = p.leftover_candidates_per_vertex;
            buildCandidates();
            continue;
        }
        // Last, with those lists, links across the pieces of the map's graph (above). Only
        // where nothing else is found: asked of every further group it found 73 true pairs more
        // on held-out corpus seeds 2-16 but 43 false, and groups mixing two parts; as the last
        // look 45 and 10, and near-twins unchanged.
        if (link_across || !p.link_across_map_pieces) break;
        link_across = true;
    }
    if (out.cores.empty()) return out;

    // 4. Growing: an unmatched gt vertex within two edges of a group's vertex is paired with the
    //    unmatched map vertex, within two edges of the partners, that the rigid fit of the
    //    group's nearby pairs puts nearest to it (within its tolerance). Every group proposes,
    //    the best proposals are taken first, until nothing changes.
    //    Then once more without the links (`geometric`): a vertex of a graph piece no group
    //    reaches (a hall's inner piece, cut off by its walls) is paired with any free map vertex
    //    the fit puts within its tolerance, when the pair is as similar as a small group must
    //    be (min_small_group_similarity), or less similar (down to the linked pass's
    //    similarity) when the walls around it agree under the fit and pin it, as a small
    //    part's must (a room off a furnished hall: the desks changed its dead end's junction,
    //    not its walls; doc/matching.md). Then along the links again, from what that pass
    //    placed: the rest of such a piece is linked to it (a room's junction whose edges a
    //    table changed is less similar than a small group's pair, but next to one).
    std::vector<int> group_of_gt(n_gt, -1);
    for (std::size_t g = 0; g < out.cores.size(); ++g)
        for (const auto& [a, b] : out.cores[g]) group_of_gt[a] = int(g);
    // Vertices within two edges, once (every round asks them again).
    std::vector<std::vector<int>> two_gt(n_gt), two_map(n_map);
    for (int a = 0; a < n_gt; ++a) two_gt[a] = nearInGraph(ctx.gt, a, 2);
    for (int b = 0; b < n_map; ++b) two_map[b] = nearInGraph(ctx.map, b, 2);
    // The ground truth's graph pieces, and which hold a group's core pair.
    const std::vector<int> piece_of_gt = piecesOf(ctx.gt);
    std::vector<char> piece_has_core(n_gt, 0);
    for (int a = 0; a < n_gt; ++a)
        if (group_of_gt[a] >= 0) piece_has_core[piece_of_gt[a]] = 1;
    std::vector<int> all_map(static_cast<std::size_t>(n_map));
    std::iota(all_map.begin(), all_map.end(), 0);
    for (const bool geometric : {false, true, false})
        for (int round = 0; round < n_gt; ++round)
        {
            struct Proposal
            {
                double score;
                int gt, map, group;
                Transform2D fit;   //!< the group's local fit that placed it
                double error;      //!< how far from its vertex that fit puts the partner
                double tolerance;  //!< ... and how far it may
                bool by_walls;     //!< less similar than the pass asks: its walls must confirm
            };
            std::vector<Proposal> proposals;
            for (int a = 0; a < n_gt; ++a)
            {
                if (!ctx.gt.v[a].active || ctx.gt_to_map[a] >= 0) continue;
                for (std::size_t g = 0; g < out.cores.size(); ++g)
                {
                    // The group's pairs near a, nearest first.
                    std::vector<std::pair<double, int>> near;
                    std::vector<int> map_near;
                    bool linked = false;
                    for (int x = 0; x < n_gt; ++x)
                        if (group_of_gt[x] == int(g)) near.emplace_back(dist_gt(x, a), x);
                    // The pairs within growing_radius_m. In the pass without links, a vertex
                    // of a graph piece that holds no group's core (a room the plan's walls cut
                    // off) farther than that from all of a group's pairs but one is placed by
                    // the group's 3 nearest pairs, its tolerance grown with the distance. Not
                    // elsewhere: far from a group in a piece it holds, the map may be broken.
                    const auto within = std::partition(near.begin(), near.end(),
                                                       [&](const auto& q)
                                                       { return q.first <= p.growing_radius_m; });
                    if (geometric && within - near.begin() < 2 && !piece_has_core[piece_of_gt[a]])
                    {
                        const std::size_t k = std::min<std::size_t>(3, near.size());
                        std::partial_sort(near.begin(), near.begin() + k, near.end());
                        near.resize(k);
                    }
                    else
                    {
                        near.erase(within, near.end());
                        std::sort(near.begin(), near.end());
                    }
                    if (near.size() < 2) continue;
                    if (geometric)
                        map_near = all_map;
                    else
                    {
                        for (int x : two_gt[a])
                            if (group_of_gt[x] == int(g) && x != a)
                            {
                                linked = true;
                                const auto& m2 = two_map[ctx.gt_to_map[x]];
                                map_near.insert(map_near.end(), m2.begin(), m2.end());
                            }
                        if (!linked) continue;
                    }
                    if (near.size() > 8) near.resize(8);
                    std::vector<Eigen::Vector2d> ga, mb;
                    for (const auto& [d, x] : near)
                        ga.push_back(pg(x)), mb.push_back(pm(ctx.gt_to_map[x]));
                    const Transform2D T = hornAlign(ga, mb);
                    std::sort(map_near.begin(), map_near.end());
                    map_near.erase(std::unique(map_near.begin(), map_near.end()), map_near.end());
                    for (int b : map_near)
                    {
                        if (!ctx.map.v[b].active || ctx.map_to_gt[b] >= 0 || !degreeOk(a, b))
                            continue;
                        const bool similar =
                            S(a, b) >= (geometric ? p.min_small_group_similarity
                                                  : p.min_consistent_growing_similarity);
                        const bool by_walls = geometric && !similar &&
                                              p.min_part_wall_agreement > 0.0 &&
                                              S(a, b) >= p.min_consistent_growing_similarity;
                        if (!similar && !by_walls) continue;
                        const double tol = p.position_tolerance_m + uncertainty(a, b) +
                                           p.distance_tolerance_ratio * near.front().first;
                        const double err = (T.apply(pm(b)) - pg(a)).norm();
                        if (err > tol) continue;
                        proposals.push_back(
                            {(1.0 - err / tol) + S(a, b), a, b, int(g), T, err, tol, by_walls});
                    }
                }
            }
            if (proposals.empty()) break;
            std::sort(proposals.begin(), proposals.end(),
                      [](const Proposal& x, const Proposal& y)
                      { return std::tie(y.score, x.gt, x.map) < std::tie(x.score, y.gt, y.map); });
            // Take only the best proposal per vertex in this round; the fits then change. A
            // proposal whose walls do not agree under its fit is not taken
            // (min_grown_wall_agreement; maps without walls are not asked).
            const bool check_walls = p.min_grown_wall_agreement > 0.0 &&
                                     !gt.wall_points_m.empty() && !map.wall_points_m.empty();
            int taken = 0;
            for (const Proposal& pr : proposals)
            {
                if (ctx.gt_to_map[pr.gt] >= 0 || ctx.map_to_gt[pr.map] >= 0) continue;
                if (pr.by_walls)
                {
                    // The walls decide: aligned by ICP from the fit (which, made of pairs up to
                    // growing_radius_m away, may put a room a few decimetres off), they must
                    // still put the partner within the pair's tolerance, agree and pin.
                    const auto walls_fit = pairWallsByIcp(pr.gt, pr.map, pr.fit, pr.error);
                    if (!walls_fit ||
                        (pg(pr.gt) - walls_fit->apply(pm(pr.map))).norm() > pr.tolerance ||
                        !agreeAndPin(
                            pairWallsUnder(pr.gt, pr.map, *walls_fit, p.min_part_wall_agreement)))
                        continue;
                }
                else if (check_walls)
                {
                    // The share only (its pinning is not asked: pinning_from_share above 1).
                    // Walls on one side only (a vertex bounded by unexplored space) say nothing.
                    const WallAgreement w = pairWallsUnder(pr.gt, pr.map, pr.fit, 2.0);
                    if (w.walls_on_both && w.share < p.min_grown_wall_agreement) continue;
                }
                ctx.gt_to_map[pr.gt] = pr.map;
                ctx.map_to_gt[pr.map] = pr.gt;
                group_of_gt[pr.gt] = pr.group;
                out.grown.push_back({pr.gt, pr.map, pr.group});
                ++taken;
            }
            if (taken == 0) break;
        }

    // 5. Polish: a group's pairs are consistent within tolerance, so of two close twins (two
    //    junctions 0.3 m apart, a room's two dead ends) the group keeps whichever it met first.
    //    Under the group's own rigid fit, a pair takes a free map vertex near its partner, or
    //    two pairs of the group swap partners, when that lowers the group's squared placement
    //    error (degrees within max_degree_difference, similarity at least
    //    min_consistent_growing_similarity). The fit is held fixed, so every change lowers the
    //    error and the loop ends.
    for (std::size_t g = 0; g < out.cores.size(); ++g)
    {
        std::vector<std::pair<int, int*>> refs;  // gt vertex, its map partner in out
        for (auto& [a, b] : out.cores[g]) refs.emplace_back(a, &b);
        for (auto& gp : out.grown)
            if (gp.isomorphism == int(g)) refs.emplace_back(gp.gt, &gp.map);
        if (refs.size() < 3) continue;
        std::vector<Eigen::Vector2d> ga, mb;
        for (const auto& [a, b] : refs) ga.push_back(pg(a)), mb.push_back(pm(*b));
        const Transform2D T = hornAlign(ga, mb);
        auto err2 = [&](int a, int b) { return (pg(a) - T.apply(pm(b))).squaredNorm(); };
        auto fits = [&](int a, int b) {
            return ctx.map.v[b].active && degreeOk(a, b) &&
                   S(a, b) >= p.min_consistent_growing_similarity;
        };
        for (bool changed = true; changed;)
        {
            changed = false;
            for (std::size_t i = 0; i < refs.size(); ++i)
            {
                const int a = refs[i].first, b = *refs[i].second;
                double best_gain = 1e-9;
                int best_b = -1;
                std::size_t best_j = refs.size();
                for (int b2 : near_map[b])
                {
                    if (b2 == b || !fits(a, b2)) continue;
                    const int owner = ctx.map_to_gt[b2];
                    double gain = 0.0;
                    std::size_t j = refs.size();
                    if (owner < 0)
                        gain = err2(a, b) - err2(a, b2);
                    else
                    {
                        for (std::size_t k = 0; k < refs.size(); ++k)
                            if (refs[k].first == owner) j = k;
                        if (j == refs.size() || !fits(owner, b)) continue;
                        gain = err2(a, b) + err2(owner, b2) - err2(a, b2) - err2(owner, b);
                    }
                    if (gain > best_gain) best_gain = gain, best_b = b2, best_j = j;
                }
                if (best_b < 0) continue;
                if (best_j < refs.size())
                {
                    *refs[best_j].second = b;
                    ctx.gt_to_map[refs[best_j].first] = b;
                    ctx.map_to_gt[b] = refs[best_j].first;
                }
                else
                    ctx.map_to_gt[b] = -1;
                *refs[i].second = best_b;
                ctx.gt_to_map[a] = best_b;
                ctx.map_to_gt[best_b] = a;
                changed = true;
            }
        }
    }
    return out;
}

}  // namespace

ConsistentMatch findConsistentGroups(const TopologyGraph& gt, const TopologyGraph& map,
                                     MatchContext& ctx)
{
    // A maximum clique is one placement of the map; in a building symmetric under a turn or a
    // mirror another placement of its part is as consistent, and which one the clique search
    // returns is chance (a pentagonal floor plan broken in two: every one of 49 pairs placed one
    // wing over; doc/matching.md, "Rival placements"). Only the whole match tells them apart:
    // the true placement also pairs the vertices where the symmetry ends, with their true
    // attributes. So each rival placement as acceptable as the first group is played out to
    // the end, and the match whose pairs are the most similar in sum wins (ties: the maximum
    // clique's).
    const std::vector<int> gt_to_map = ctx.gt_to_map, map_to_gt = ctx.map_to_gt;
    auto similaritySum = [&](const ConsistentMatch& m)
    {
        double sum = 0.0;
        for (const auto& core : m.cores)
            for (const auto& [a, b] : core) sum += ctx.similarity(a, b);
        for (const auto& g : m.grown) sum += ctx.similarity(g.gt, g.map);
        return sum;
    };
    std::map<std::size_t, std::optional<double>> pair_turns;
    ConsistentMatch best = findGroups(gt, map, ctx, nullptr, pair_turns);
    double best_sum = similaritySum(best);
    const std::vector<std::vector<std::pair<int, int>>> rivals = best.rivals;
    std::size_t steps = best.clique_steps;
    std::vector<int> best_gt_to_map = ctx.gt_to_map, best_map_to_gt = ctx.map_to_gt;
    for (std::size_t r = 0; r < rivals.size(); ++r)
    {
        ctx.gt_to_map = gt_to_map;
        ctx.map_to_gt = map_to_gt;
        ConsistentMatch other = findGroups(gt, map, ctx, &rivals[r], pair_turns);
        steps += other.clique_steps;
        const double sum = similaritySum(other);
        if (sum > best_sum)
        {
            best_sum = sum;
            best = std::move(other);
            best.rival_won = int(r) + 1;
            best_gt_to_map = ctx.gt_to_map, best_map_to_gt = ctx.map_to_gt;
        }
    }
    best.rivals = rivals;
    best.clique_steps = steps;
    ctx.gt_to_map = best_gt_to_map;
    ctx.map_to_gt = best_map_to_gt;
    return best;
}

}  // namespace mrpt_topoeval::internal
