/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The one-call pipeline: both graphs, vertex similarity, match, evaluation (paper II-IV).

#include <mrpt/maps/COccupancyGridMap2D.h>  // the clutter pass keeps an edited copy
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/evaluation/evaluate_match.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/matching/match_graphs.h>
#include <mrpt_topoeval/pipeline/evaluate.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <future>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <utility>

#include "common/clock.h"
#include "common/threads.h"
#include "evaluation/evaluate_match_at.h"
#include "graph/MatchView.h"
#include "pipeline/clutter.h"
#include "pipeline/map_scale.h"

namespace mrpt_topoeval
{
SimilarityMatrix vertexSimilarity(const TopologyGraph& gt,
                                  const mrpt::maps::COccupancyGridMap2D& gt_grid,
                                  const TopologyGraph& map,
                                  const mrpt::maps::COccupancyGridMap2D& map_grid,
                                  const VertexSimilarityParameters& p,
                                  std::map<std::string, double>* timing_ms)
{
    return p.mode == SimilarityMode::Icp ? icpSimilarity(gt, gt_grid, map, map_grid, p, timing_ms)
                                         : attributeSimilarity(gt, map, p);
}

namespace
{
using internal::Clock;
using internal::msSince;

// Vertex similarity and match of two graphs, timed.
struct Matched
{
    GraphMatch match;
    double similarity_ms = 0.0, match_ms = 0.0;
};

Matched matchStep(const TopologyGraph& gt, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                  const TopologyGraph& map, const mrpt::maps::COccupancyGridMap2D& map_grid,
                  const Parameters& params)
{
    Matched m;
    const auto t1 = Clock::now();
    const SimilarityMatrix s = vertexSimilarity(gt, gt_grid, map, map_grid, params.similarity);
    m.similarity_ms = msSince(t1);
    const auto t2 = Clock::now();
    m.match = matchGraphs(gt, map, s, params.matcher);
    m.match_ms = msSince(t2);
    return m;
}

// The clutter pass (GraphMatcherParameters::clutter_passes; doc/matching.md): the map without
// the free-standing obstacles that the ground truth lacks where the match `m` puts them, built
// and matched again; kept, with its graph in `map`, when it pairs more vertices. A match that
// grew reaches further islands: the pass repeats on the edited map. A match of fewer than 3
// pairs gives nothing to judge by: the first round then judges by the match of the map with
// all its islands freed (clutter_start_without_islands). The edited grid of the map kept is
// left in `current` (the scale pass reads it). Returns what it did, for the report's messages
// (empty when it changed nothing).
std::string clutterPasses(const TopologyGraph& gt, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                          TopologyGraph& map, const mrpt::maps::COccupancyGridMap2D& map_grid,
                          const Parameters& params, Matched& m,
                          std::optional<mrpt::maps::COccupancyGridMap2D>& current)
{
    const GraphMatcherParameters& p = params.matcher;
    if (p.method != MatchMethod::Consistent || p.clutter_passes <= 0) return {};
    // What the first round judges by: the match itself, or that of the map without islands.
    struct Start
    {
        TopologyGraph graph;
        GraphMatch match;
    };
    std::optional<Start> start;
    std::size_t start_islands = 0;
    if (m.match.pairs.size() < 3 && p.clutter_start_without_islands)
    {
        if (auto bare = internal::withoutIslands(map_grid, params, start_islands))
        {
            TopologyGraph graph = buildTopologyGraph(*bare, params.graph);
            Matched bare_match = matchStep(gt, gt_grid, graph, *bare, params);
            if (bare_match.match.pairs.size() >= 3)
                start = Start{std::move(graph), std::move(bare_match.match)};
        }
    }
    const std::size_t first_pairs = m.match.pairs.size();
    std::size_t removed_total = 0;
    int passes = 0;
    for (int pass = 0; pass < p.clutter_passes; ++pass)
    {
        const bool from_start = pass == 0 && start;
        std::size_t removed = 0, judged = 0;
        auto edited = internal::withoutClutter(
            gt, from_start ? start->graph : map, current ? *current : map_grid,
            from_start ? start->match : m.match, params, removed, judged);
        if (!edited) break;
        // Is the map furnished where its ground truth is not? A ground truth drawn from a robot
        // map holds the same furniture; the few islands it lacks are noise and not worth a
        // rebuild.
        if (pass == 0 && double(removed) < p.clutter_min_share * double(judged)) break;
        TopologyGraph graph = buildTopologyGraph(*edited, params.graph);
        Matched next = matchStep(gt, gt_grid, graph, *edited, params);
        if (next.match.pairs.size() <= m.match.pairs.size()) break;
        m.match = std::move(next.match);
        map = std::move(graph);
        current = std::move(edited);
        removed_total += removed;
        ++passes;
    }
    if (passes == 0) return {};
    std::string text = "clutter pass: " + std::to_string(removed_total) +
                       " free-standing obstacle(s) of the map that the ground truth lacks where "
                       "the match puts them made free and the map matched again (" +
                       std::to_string(passes) + " pass(es)";
    if (start)
        text += "; judged first by the " + std::to_string(start->match.pairs.size()) +
                " pairs of the map with all its " + std::to_string(start_islands) +
                " islands freed, as its own match paired fewer than 3";
    return text + "): " + std::to_string(first_pairs) + " -> " +
           std::to_string(m.match.pairs.size()) +
           " pairs; the map's graph reported is without them";
}

// The map's graph read at a scale, and its match.
struct AtScale
{
    double scale = 1.0;
    TopologyGraph graph;
    GraphMatch match;
    internal::MapScale first;  // the first round's estimate
    double searched = 0.0;     // the scale search's factor it started from; 0: none
};

// `map` read at `scale` (its grid too, for ICP similarity alone: a map of 10^8 cells is 100 MB)
// and matched.
AtScale matchAtScale(const TopologyGraph& gt, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                     const TopologyGraph& map, const mrpt::maps::COccupancyGridMap2D& map_grid,
                     const Parameters& params, double scale)
{
    AtScale out;
    out.scale = scale;
    out.graph = internal::scaledGraph(map, scale);
    std::optional<mrpt::maps::COccupancyGridMap2D> icp_grid;
    if (params.similarity.mode == SimilarityMode::Icp)
        icp_grid = internal::scaledGrid(map_grid, scale);
    out.match = matchStep(gt, gt_grid, out.graph, icp_grid ? *icp_grid : map_grid, params).match;
    return out;
}

// The scale search (GraphMatcherParameters::scale_search_step): when the match `m` pairs
// nothing, `map` read at (1 + step)^-k and (1 + step)^k, k = 1, 2, ..., nearest first; the
// reading with the most pairs (ties: the smaller factor) at the first k that pairs any. A map
// off by more than the pairwise tolerance forgives shows no group to estimate its factor from.
std::optional<AtScale> searchScale(const TopologyGraph& gt,
                                   const mrpt::maps::COccupancyGridMap2D& gt_grid,
                                   const TopologyGraph& map,
                                   const mrpt::maps::COccupancyGridMap2D& map_grid,
                                   const Parameters& params, const GraphMatch& m)
{
    const GraphMatcherParameters& p = params.matcher;
    if (!m.pairs.empty() || p.scale_min_error <= 0.0 || p.scale_search_step <= 0.0) return {};
    // Each reading is one more chance for a chance group. So a reading's first group must be
    // significant among all the readings tried (Bonferroni's count, as the a contrario test
    // counts its tests: max_false_alarms shared by them), big enough to be trusted on that
    // alone (first_group_wall_check_pairs: the walls that vouch for a smaller one are a test
    // of their own, which the count does not cover; a chance group of 8 pairs between two
    // multi-wing buildings, its walls agreeing, at one reading of four), and its biggest group
    // must show the map as one part or a few big ones (scale_search_min_group_share: two
    // campuses of one building code share their rooms, and a group of 11 of their 80 vertices
    // was significant).
    Parameters strict = params;
    strict.matcher.max_false_alarms /= double(1 + 2 * p.scale_search_steps);
    const double smaller = double(std::min(internal::makeMatchView(gt).numActive(),
                                           internal::makeMatchView(map).numActive()));
    const int min_pairs = std::max(p.first_group_wall_check_pairs, 1);
    // No group of a smaller graph can count: its readings need not be matched.
    if (smaller < double(min_pairs)) return {};
    const auto trusted = [&](const GraphMatch& match)
    {
        const std::size_t biggest =
            match.isomorphism_sizes.empty()
                ? 0
                : *std::max_element(match.isomorphism_sizes.begin(), match.isomorphism_sizes.end());
        return biggest >= std::size_t(min_pairs) &&
               double(biggest) >= p.scale_search_min_group_share * smaller;
    };
    for (int k = 1; k <= p.scale_search_steps; ++k)
    {
        std::optional<AtScale> best;
        for (const int sign : {-1, 1})
        {
            const double scale = std::pow(1.0 + p.scale_search_step, sign * k);
            AtScale next = matchAtScale(gt, gt_grid, map, map_grid, strict, scale);
            if (trusted(next.match) &&
                next.match.pairs.size() > (best ? best->match.pairs.size() : 0))
            {
                next.searched = scale;
                best = std::move(next);
            }
        }
        if (best) return best;
    }
    return {};
}

// The scale pass (GraphMatcherParameters::scale_min_error; doc/matching.md, "A map at another
// scale"), its first half: when the match `m` shows the distances of `map` (the graph of
// `map_grid`) off from the ground truth's by one clear factor, the graph read at the ground
// truth's scale and its match (at most two rounds, each keeping scale_min_pair_share of the
// pairs before it), from the scale search's reading `out` when it made one. None when neither
// shows a factor.
std::optional<AtScale> readAtScale(const TopologyGraph& gt,
                                   const mrpt::maps::COccupancyGridMap2D& gt_grid,
                                   const TopologyGraph& map,
                                   const mrpt::maps::COccupancyGridMap2D& map_grid,
                                   const Parameters& params, const GraphMatch& m,
                                   std::optional<AtScale> out)
{
    const GraphMatcherParameters& p = params.matcher;
    if (p.scale_min_error <= 0.0) return {};
    for (int round = 0; round < 2; ++round)
    {
        const internal::MapScale est =
            internal::mapScaleOf(gt, out ? out->graph : map, out ? out->match : m);
        const double off = std::abs(est.scale - 1.0);
        if (est.groups == 0 || off <= p.scale_min_error ||
            off <= p.scale_min_sigmas * est.std_error)
            break;
        // Read from the map's own graph.
        AtScale next =
            matchAtScale(gt, gt_grid, map, map_grid, params, (out ? out->scale : 1.0) * est.scale);
        const std::size_t before = (out ? out->match : m).pairs.size();
        if (double(next.match.pairs.size()) < p.scale_min_pair_share * double(before)) break;
        next.first = out && out->first.groups > 0 ? out->first : est;
        next.searched = out ? out->searched : 0.0;
        out = std::move(next);
    }
    return out;
}

// Its second half: the reading at the ground truth's scale is kept when it explains the map with
// fewer parts: fewer brokenness groups, keeping scale_min_pair_share of the pairs. A map off by
// one factor falls into more groups than it has parts, each only as wide as the pairwise
// tolerance forgives; at its scale they join. A reading that joins none was not the map's
// error: a bent SLAM map a few % shorter in one wing then showed a break more, and a broken
// map's small groups near their cuts showed a factor of 1.03 +- 0.008 and a group 1 degree off
// at it (doc/matching.md, "A map at another scale").
// The parts placed by their walls (brokenness step 9) are left out: the reading is judged on
// the groups of the match's pairs, as before that step, so the step never changes the match.
// Counted, a map broken three times (held-out warehouse_43001/broken_3) was read at scale 1.028
// for its part placed as given, and that reading's match held 5 false pairs of 11.
std::size_t matchedGroups(const QualityReport& r)
{
    return std::size_t(std::count_if(r.brokenness.groups.begin(), r.brokenness.groups.end(),
                                     [](const BrokennessGroup& g) { return !g.by_walls; }));
}

bool keepAtScale(const QualityReport& as_given, const QualityReport& at_scale, double min_share)
{
    return matchedGroups(at_scale) < matchedGroups(as_given) &&
           double(at_scale.match.pairs.size()) >= min_share * double(as_given.match.pairs.size());
}

// Similarity, match (with the clutter pass, which may replace `map`'s graph, and the scale
// pass) and evaluation of two graphs built since `t0` (their time is "graphs").
QualityReport scoreGraphs(const TopologyGraph& gt, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                          TopologyGraph& map, const mrpt::maps::COccupancyGridMap2D& map_grid,
                          const Parameters& params, Clock::time_point t0)
{
    const double t_graphs = msSince(t0);
    Matched m = matchStep(gt, gt_grid, map, map_grid, params);
    const auto tc = Clock::now();
    std::optional<mrpt::maps::COccupancyGridMap2D> edited;  // by the clutter pass
    const std::string clutter = clutterPasses(gt, gt_grid, map, map_grid, params, m, edited);
    const double t_clutter = msSince(tc);
    const auto ts = Clock::now();
    const mrpt::maps::COccupancyGridMap2D& current = edited ? *edited : map_grid;
    const std::optional<AtScale> scaled =
        readAtScale(gt, gt_grid, map, current, params, m.match,
                    searchScale(gt, gt_grid, map, current, params, m.match));
    const double t_scale = msSince(ts);
    const auto t3 = Clock::now();
    const unsigned threads = internal::workerThreads(params.similarity.threads);
    // A reading the scale search found replaces the map as given, which matched nothing: that
    // one is not placed by its walls (map_by_walls), work for nothing.
    QualityParameters as_given = params.quality;
    if (scaled && scaled->searched > 0.0) as_given.map_by_walls = false;
    QualityReport r = evaluateMatch(gt, map, m.match, as_given, threads);
    std::string scale_text;
    if (scaled)
    {
        // Accuracy and consistency measure the map as given, brokenness where the factor is
        // undone (the same graph, vertex for vertex).
        QualityReport at = internal::evaluateMatchAt(gt, map, scaled->graph, scaled->match,
                                                     params.quality, threads);
        const internal::MapScale& f = scaled->first;
        char text[500];
        // A reading the search found is kept: the map as given paired nothing.
        const bool kept =
            scaled->searched > 0.0 || keepAtScale(r, at, params.matcher.scale_min_pair_share);
        if (scaled->searched > 0.0)
        {
            std::snprintf(text, sizeof text,
                          "scale search: the map as given matched nothing; read at x %.4f it "
                          "matched",
                          scaled->searched);
            scale_text = text;
            if (f.groups > 0)
            {
                std::snprintf(text, sizeof text,
                              ", and its groups' factor %.4f +- %.4f (%zu pairs in %zu groups) "
                              "gave x %.4f",
                              f.scale, f.std_error, f.pairs, f.groups, scaled->scale);
                scale_text += text;
            }
            std::snprintf(text, sizeof text,
                          ": %zu pairs in %zu brokenness group(s); brokenness is measured at that "
                          "scale, accuracy and consistency on the map as given",
                          at.match.pairs.size(), matchedGroups(at));
            scale_text += text;
        }
        else
        {
            std::snprintf(
                text, sizeof text,
                "scale pass: the match showed the map's distances %s by %.1f %% (scale "
                "%.4f +- %.4f from %zu pairs in %zu groups); read at the ground truth's "
                "scale (x %.4f): %zu pairs in %zu brokenness groups against %zu in %zu; %s",
                f.scale > 1.0 ? "too short" : "too long", 100.0 * std::abs(1.0 - 1.0 / f.scale),
                f.scale, f.std_error, f.pairs, f.groups, scaled->scale, at.match.pairs.size(),
                matchedGroups(at), r.match.pairs.size(), matchedGroups(r),
                kept ? "kept: brokenness is measured at that scale, accuracy and "
                       "consistency on the map as given"
                     : "not kept (it explains the map with no fewer parts)");
            scale_text = text;
        }
        if (kept)
        {
            r = std::move(at);
            r.map_scale = scaled->scale;
        }
    }
    r.timing_ms["graphs"] = t_graphs;
    r.timing_ms["similarity"] = m.similarity_ms;
    r.timing_ms["match"] = m.match_ms;
    if (params.matcher.clutter_passes > 0) r.timing_ms["clutter"] = t_clutter;
    if (params.matcher.scale_min_error > 0.0) r.timing_ms["scale"] = t_scale;
    r.timing_ms["evaluation"] = msSince(t3);
    r.timing_ms["total"] = msSince(t0);
    if (!clutter.empty()) r.messages.push_back(clutter);
    if (!scale_text.empty()) r.messages.push_back(scale_text);
    for (const auto& w : gt.warnings) r.messages.push_back("ground truth: " + w);
    for (const auto& w : map.warnings) r.messages.push_back("map: " + w);
    return r;
}
}  // namespace

QualityReport evaluate(const TopologyGraph& gt, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                       const mrpt::maps::COccupancyGridMap2D& map_grid, const Parameters& params,
                       TopologyGraph* map_out)
{
    const auto t0 = Clock::now();
    TopologyGraph map = buildTopologyGraph(map_grid, params.graph);
    QualityReport r = scoreGraphs(gt, gt_grid, map, map_grid, params, t0);
    if (map_out) *map_out = std::move(map);
    return r;
}

QualityReport evaluate(const mrpt::maps::COccupancyGridMap2D& gt_grid,
                       const mrpt::maps::COccupancyGridMap2D& map_grid, const Parameters& params,
                       TopologyGraph* gt_out, TopologyGraph* map_out)
{
    const auto t0 = Clock::now();
    // The two graphs do not depend on each other: with more than one worker thread the ground
    // truth's is built on a second thread while this one builds the map's (each build is
    // deterministic and shares nothing, so the result does not depend on it).
    TopologyGraph gt, map;
    std::future<TopologyGraph> gt_future;
    if (internal::workerThreads(params.similarity.threads) > 1)
    {
        try
        {
            gt_future = std::async(std::launch::async,
                                   [&] { return buildTopologyGraph(gt_grid, params.graph); });
        }
        catch (const std::system_error&)
        {
            // No thread to be had (a process or container limit): build both here.
        }
    }
    if (gt_future.valid())
    {
        std::exception_ptr map_error;
        try
        {
            map = buildTopologyGraph(map_grid, params.graph);
        }
        catch (...)
        {
            map_error = std::current_exception();
        }
        gt = gt_future.get();  // the ground truth's error first, as without threads
        if (map_error) std::rethrow_exception(map_error);
    }
    else
    {
        gt = buildTopologyGraph(gt_grid, params.graph);
        map = buildTopologyGraph(map_grid, params.graph);
    }
    QualityReport r = scoreGraphs(gt, gt_grid, map, map_grid, params, t0);
    if (gt_out) *gt_out = std::move(gt);
    if (map_out) *map_out = std::move(map);
    return r;
}

}  // namespace mrpt_topoeval
