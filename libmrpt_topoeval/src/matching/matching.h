/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// The two stages of the matcher (paper III-B), on the matching views of both graphs.

#include <mrpt_topoeval/matching/match_graphs.h>

#include <vector>

#include "graph/MatchView.h"

namespace mrpt_topoeval::internal
{
/** What both stages read, and the vertices already assigned. */
struct MatchContext
{
    const MatchView& gt;
    const MatchView& map;
    const SimilarityMatrix& similarity;
    const GraphMatcherParameters& params;
    std::vector<int> gt_to_map;  //!< Assigned map vertex per gt vertex, -1 if none.
    std::vector<int> map_to_gt;  //!< Assigned gt vertex per map vertex, -1 if none.
};

/** The smallest isomorphism accepted between graphs of `n_gt` and `n_map` matchable vertices:
 * min_isomorphism_vertices, or on graphs too small for that min_isomorphism_share of the smaller
 * one (never fewer than 3). */
int minIsomorphismSize(const GraphMatcherParameters& params, int n_gt, int n_map);

/** One accepted isomorphism: its pairs in the order the wavefront found them. */
struct Isomorphism
{
    std::vector<std::pair<int, int>> pairs;  //!< (gt vertex, map vertex)
};

/** Paper III-B, Algorithm 1: from every unassigned gt vertex (most similar first), tries every
 * map vertex of the same degree as a seed, grows each by wavefront propagation, and accepts the
 * biggest isomorphism for that vertex if it has at least minIsomorphismSize() pairs. Accepted
 * pairs are written into ctx. */
std::vector<Isomorphism> findIsomorphisms(MatchContext& ctx);

/** Paper III-B, end: extends the assignment from its border, pairing unassigned neighbours of
 * assigned pairs by similarity with relaxed constraints. Returns the new pairs (gt, map, the
 * isomorphism index they grew from) in the order they were accepted. */
struct GrownPair
{
    int gt = -1, map = -1, isomorphism = -1;
};
std::vector<GrownPair> growNeighbours(MatchContext& ctx, std::vector<int>& iso_of_gt);

/** The consistent method's result: the groups' pairs (gt, map) as found by the clique search
 * (group i's core) and the pairs added by growing, with the group they joined. */
struct ConsistentMatch
{
    std::vector<std::vector<std::pair<int, int>>> cores;
    std::vector<GrownPair> grown;
    std::size_t candidates = 0;    //!< Candidate pairs (vertices of the consistency graph).
    int min_group_size = 0;        //!< The effective smallest group (small graphs: fewer).
    std::size_t clique_steps = 0;  //!< Branch-and-bound steps spent, all searches.
    /** The biggest first group refused as insignificant (max_false_alarms), for its walls
     * (min_first_group_wall_agreement) or as a line (distance_tolerance_m), 0 if none, the number
     * of chance groups as big expected among its candidates, and its walls' share when they refused
     * it (else -1). */
    std::size_t refused_size = 0;
    double refused_false_alarms = 0.0;
    std::size_t refused_candidates = 0;
    double refused_wall_share = -1.0;
    /** ... and its width across its line when that refused it (else -1) [m]. */
    double refused_width_m = -1.0;
    /** ... or the share of its pairs whose walls disagree (first_group_disagreeing_pair_share),
     * or -1 when not refused by that test. */
    double refused_disagreeing_pairs = -1.0;
    /** Rival placements of the first group (the same part of the map placed elsewhere, each as
     * acceptable as a first group), their pairs (gt, map); rival_won: which one the returned
     * match was played out from (1-based), 0 for the maximum clique. */
    std::vector<std::vector<std::pair<int, int>>> rivals;
    int rival_won = 0;
};

/** method = consistent: candidate pairs by similarity and degree, groups as maximum cliques of
 * the pairwise distance-consistency graph (verified by a rigid fit), then growing of every
 * group by local rigid fits. Writes the pairs into ctx. Uses the graphs' vertex positions only
 * through distances within one map and rigid fits of one group's pairs. */
ConsistentMatch findConsistentGroups(const TopologyGraph& gt, const TopologyGraph& map,
                                     MatchContext& ctx);

/** Smallest absolute difference of two angles [rad]. */
double angleDistance(double a, double b);

}  // namespace mrpt_topoeval::internal
