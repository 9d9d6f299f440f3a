/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Matching two Topology Graphs: the paper's method (III-B: isomorphisms first, then neighbour
// growing) or groups of geometrically consistent pairs (method = consistent).

#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/matching/match_graphs.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>

#include "matching/matching.h"

namespace mrpt_topoeval
{
namespace
{
using Clock = std::chrono::steady_clock;
using Elapsed = std::function<double(Clock::time_point)>;

// method = paper: isomorphisms (Algorithm 1), then neighbour growing.
void matchPaper(internal::MatchContext& ctx, GraphMatch& match, const Elapsed& ms)
{
    const auto t_iso = std::chrono::steady_clock::now();
    const std::vector<internal::Isomorphism> isos = internal::findIsomorphisms(ctx);
    match.timing_ms["isomorphism"] = ms(t_iso);

    std::vector<int> iso_of_gt(ctx.gt.v.size(), -1);
    for (int i = 0; i < static_cast<int>(isos.size()); ++i)
    {
        match.isomorphism_sizes.push_back(isos[i].pairs.size());
        for (const auto& [a, b] : isos[i].pairs)
        {
            iso_of_gt[a] = i;
            match.pairs.push_back({a, b, MatchStage::Isomorphism, ctx.similarity(a, b), i});
        }
    }
    match.isomorphism = match.pairs.size();

    if (ctx.params.neighbour_growing && !isos.empty())
    {
        const auto t_grow = std::chrono::steady_clock::now();
        for (const auto& g : internal::growNeighbours(ctx, iso_of_gt))
            match.pairs.push_back({g.gt, g.map, MatchStage::NeighbourGrowing,
                                   ctx.similarity(g.gt, g.map), g.isomorphism});
        match.timing_ms["neighbour_growing"] = ms(t_grow);
    }
    match.neighbour_growing = match.pairs.size() - match.isomorphism;
    match.missing = static_cast<std::size_t>(ctx.gt.numActive()) - match.pairs.size();
    std::sort(match.pairs.begin(), match.pairs.end(),
              [](const VertexPair& x, const VertexPair& y)
              { return x.ground_truth < y.ground_truth; });

    if (isos.empty())
    {
        bool any_degree = false;
        for (const auto& va : ctx.gt.v)
            for (const auto& vb : ctx.map.v)
                any_degree = any_degree || (va.active && vb.active && va.degree() == vb.degree());
        match.messages.push_back(
            any_degree
                ? "no isomorphism of at least " +
                      std::to_string(internal::minIsomorphismSize(ctx.params, ctx.gt.numActive(),
                                                                  ctx.map.numActive())) +
                      " vertices was found (graphs of " + std::to_string(ctx.gt.numActive()) +
                      " and " + std::to_string(ctx.map.numActive()) +
                      " matchable vertices): the maps share no structure the matcher trusts"
                : "no vertex of the map has the degree of any ground-truth vertex: "
                  "nothing is matched");
    }
}

// method = consistent: groups of geometrically consistent pairs, then growing. The groups play
// the isomorphisms' part in the result (stage "isomorphism" for a group's core pairs,
// "neighbour_growing" for grown ones; isomorphism_sizes = the cores' sizes), so brokenness
// seeds from the biggest groups as before.
void matchConsistent(const TopologyGraph& ground_truth, const TopologyGraph& map,
                     internal::MatchContext& ctx, GraphMatch& match, const Elapsed& ms)
{
    const auto t_groups = Clock::now();
    const internal::ConsistentMatch found = internal::findConsistentGroups(ground_truth, map, ctx);
    match.timing_ms["isomorphism"] = ms(t_groups);
    for (std::size_t g = 0; g < found.cores.size(); ++g)
    {
        match.isomorphism_sizes.push_back(found.cores[g].size());
        for (const auto& [a, b] : found.cores[g])
            match.pairs.push_back({a, b, MatchStage::Isomorphism, ctx.similarity(a, b), int(g)});
    }
    match.isomorphism = match.pairs.size();
    for (const auto& g : found.grown)
        match.pairs.push_back({g.gt, g.map, MatchStage::NeighbourGrowing,
                               ctx.similarity(g.gt, g.map), g.isomorphism});
    match.neighbour_growing = match.pairs.size() - match.isomorphism;
    match.missing = static_cast<std::size_t>(ctx.gt.numActive()) - match.pairs.size();
    std::sort(match.pairs.begin(), match.pairs.end(),
              [](const VertexPair& x, const VertexPair& y)
              { return x.ground_truth < y.ground_truth; });
    if (!found.rivals.empty())
        // A symmetric building: say so, since a user reading a low coverage should know that
        // part of the map fitted several places (doc/matching.md, "Rival placements").
        match.messages.push_back(
            "the first group of geometrically consistent pairs had " +
            std::to_string(found.rivals.size()) +
            " rival placement(s) as acceptable (the building is symmetric there); each was "
            "played out and the match kept is the one whose pairs are the most similar in sum (" +
            (found.rival_won > 0 ? "rival " + std::to_string(found.rival_won)
                                 : std::string("the biggest group's")) +
            ")");
    if (!found.cores.empty()) return;
    const std::string graphs = " candidate pairs (graphs of " + std::to_string(ctx.gt.numActive()) +
                               " and " + std::to_string(ctx.map.numActive()) +
                               " matchable vertices): ";
    auto twoDigits = [](double v)
    {
        std::ostringstream out;
        out << std::setprecision(2) << v;
        return out.str();
    };
    const std::string too_little = "; the maps share too little structure to be matched";
    // "the biggest [significant ]group ... (N) among M candidate pairs (graphs of ...): "
    auto refused = [&](const std::string& kind)
    {
        return "the biggest " + kind + "group of geometrically consistent pairs (" +
               std::to_string(found.refused_size) + ") among " +
               std::to_string(found.refused_candidates) + graphs;
    };
    if (found.refused_size > 0 && found.refused_width_m >= 0.0)
        match.messages.push_back(
            refused("") + "it lies along one line (its vertices " +
            twoDigits(found.refused_width_m) +
            " m from it, RMS, less than [GraphMatcher] distance_tolerance_m), so it checks "
            "only a spacing along that line" +
            too_little);
    else if (found.refused_size > 0 && found.refused_wall_share >= 0.0)
        match.messages.push_back(
            refused("significant ") + "only a share of " + twoDigits(found.refused_wall_share) +
            " of the walls around it agree under its fit, less than [GraphMatcher] "
            "min_first_group_wall_agreement asks" +
            too_little);
    else if (found.refused_size > 0 && found.refused_disagreeing_pairs >= 0.0)
        match.messages.push_back(
            refused("significant ") + "the walls around " +
            std::to_string(std::lround(100.0 * found.refused_disagreeing_pairs)) +
            " % of its pairs disagree, each aligned where the pair is, at least [GraphMatcher] "
            "first_group_disagreeing_pair_share" +
            too_little);
    else if (found.refused_size > 0)
        match.messages.push_back(
            "the biggest group of geometrically consistent pairs (" +
            std::to_string(found.refused_size) + ") is not significant among " +
            std::to_string(found.refused_candidates) + graphs +
            "chance alone is expected to make " + twoDigits(found.refused_false_alarms) +
            " groups as big, more than [GraphMatcher] max_false_alarms allows" + too_little);
    else
        match.messages.push_back("no group of at least " + std::to_string(found.min_group_size) +
                                 " geometrically consistent pairs was found among " +
                                 std::to_string(found.candidates) + graphs +
                                 "the maps share no structure the matcher trusts");
}
}  // namespace

GraphMatch matchGraphs(const TopologyGraph& ground_truth, const TopologyGraph& map,
                       const SimilarityMatrix& similarity, const GraphMatcherParameters& params)
{
    params.validate();
    const auto t0 = std::chrono::steady_clock::now();
    auto ms = [&](std::chrono::steady_clock::time_point since)
    {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since)
            .count();
    };
    if (similarity.rows() != static_cast<Eigen::Index>(ground_truth.vertices.size()) ||
        similarity.cols() != static_cast<Eigen::Index>(map.vertices.size()))
        throw InputError("similarity matrix is " + std::to_string(similarity.rows()) + " x " +
                         std::to_string(similarity.cols()) + " but the graphs have " +
                         std::to_string(ground_truth.vertices.size()) + " and " +
                         std::to_string(map.vertices.size()) + " vertices");

    const internal::MatchView gt_view = internal::makeMatchView(ground_truth);
    const internal::MatchView map_view = internal::makeMatchView(map);
    GraphMatch match;
    const int n_gt = gt_view.numActive(), n_map = map_view.numActive();
    if (n_gt == 0 || n_map == 0)
    {
        match.messages.push_back(
            n_gt == 0 ? "the ground truth's graph has no vertex to match: nothing is matched"
                      : "the map's graph has no vertex to match: nothing is matched");
        match.missing = static_cast<std::size_t>(n_gt);
        match.timing_ms["total"] = ms(t0);
        return match;
    }

    internal::MatchContext ctx{gt_view,
                               map_view,
                               similarity,
                               params,
                               std::vector<int>(ground_truth.vertices.size(), -1),
                               std::vector<int>(map.vertices.size(), -1)};
    if (params.method == MatchMethod::Consistent)
        matchConsistent(ground_truth, map, ctx, match, ms);
    else
        matchPaper(ctx, match, ms);
    match.timing_ms["total"] = ms(t0);
    return match;
}

}  // namespace mrpt_topoeval
