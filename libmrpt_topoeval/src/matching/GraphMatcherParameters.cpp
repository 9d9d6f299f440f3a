/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// [GraphMatcher]: every key once (common/parameter_table.h); units and reasons in match_graphs.h.

#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/matching/match_graphs.h>

#include "common/parameter_table.h"

namespace mrpt_topoeval
{
std::string toString(MatchMethod m) { return m == MatchMethod::Paper ? "paper" : "consistent"; }

MatchMethod matchMethodFromString(const std::string& s)
{
    if (s == "consistent") return MatchMethod::Consistent;
    if (s == "paper") return MatchMethod::Paper;
    throw InputError("matching method '" + s + "' is not one of: consistent, paper");
}

TOPOEVAL_PARAMETER_TABLE(
    GraphMatcherParameters, NumberText::Stream,
    choice(TOPOEVAL_KEY(method), matchMethodFromString,
           {MatchMethod::Consistent, MatchMethod::Paper},
           "consistent groups (default) or the paper's isomorphisms"),
    real(TOPOEVAL_KEY(edge_length_factor), "ratio",
         "matched edges agree in length within factor x length", atLeast(0)),
    real(TOPOEVAL_KEY(edge_length_allowance_m), "m", "... plus this allowance", atLeast(0)),
    real(TOPOEVAL_KEY(max_angle_difference_deg), "deg",
         "largest difference of matched edges' ring angles", above(0).atMost(180)),
    real(TOPOEVAL_KEY(min_isomorphism_similarity), "0..1",
         "pairs less similar are never assigned by isomorphism", atLeast(0).atMost(1)),
    integer(TOPOEVAL_KEY(min_isomorphism_vertices), "1", "smallest isomorphism accepted",
            atLeast(1)),
    real(TOPOEVAL_KEY(min_isomorphism_share), "ratio",
         "... or this share of the smaller graph (at least 3)", above(0).atMost(1)),
    integer(TOPOEVAL_KEY(max_branches_per_seed), "1",
            "wavefront branches explored per seed (bounds recursion)", atLeast(1)),
    flag(TOPOEVAL_KEY(neighbour_growing), "extend the match by neighbour growing"),
    real(TOPOEVAL_KEY(min_growing_similarity), "0..1",
         "neighbour growing assigns pairs at least this similar", atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(growing_edge_length_factor), "ratio",
         "neighbour growing's relaxed edge-length factor", atLeast(0)),
    real(TOPOEVAL_KEY(growing_edge_length_allowance_m), "m",
         "neighbour growing's relaxed edge-length allowance", atLeast(0)),
    integer(TOPOEVAL_KEY(candidates_per_vertex), "1",
            "consistent: most similar partners per vertex as candidates", atLeast(1)),
    integer(TOPOEVAL_KEY(leftover_candidates_per_vertex), "1",
            "consistent: ... per free vertex once no further group is found (at most "
            "candidates_per_vertex: off)",
            atLeast(0)),
    flag(TOPOEVAL_KEY(first_group_wider_look),
         "consistent: ... and once no first group is found among the first lists"),
    real(TOPOEVAL_KEY(min_candidate_similarity), "0..1",
         "consistent: candidate pairs are at least this similar", atLeast(0).atMost(1)),
    integer(TOPOEVAL_KEY(max_degree_difference), "1",
            "consistent: largest degree difference of a pair", atLeast(0)),
    real(TOPOEVAL_KEY(distance_tolerance_m), "m",
         "consistent: distances of two pairs agree within this", atLeast(0)),
    real(TOPOEVAL_KEY(distance_tolerance_ratio), "ratio", "... plus this x the distance",
         atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(clearance_tolerance_share), "ratio",
         "... plus this x each vertex's clearance", atLeast(0)),
    integer(TOPOEVAL_KEY(min_group_vertices), "1",
            "consistent: smallest group of consistent pairs accepted", atLeast(3)),
    real(TOPOEVAL_KEY(min_small_group_similarity), "0..1",
         "consistent: smallest mean similarity of a smaller group on a small graph",
         atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(min_small_graph_group_share), "ratio",
         "consistent: ... whose group holds this share of the smaller graph (at least 3)",
         above(0).atMost(1)),
    integer(TOPOEVAL_KEY(support_hops), "1",
            "consistent: pairs linked within this many edges in both maps", atLeast(1)),
    real(TOPOEVAL_KEY(min_group_extent_m), "m",
         "consistent: a group spans at least this in the ground truth", atLeast(0)),
    real(TOPOEVAL_KEY(max_group_squared_error_m2), "m^2",
         "consistent: a group's rigid fit has at most this mean squared error", above(0)),
    flag(TOPOEVAL_KEY(trim_further_groups_to_rigid),
         "consistent: a further group over that error loses its worst-placed pair until it is "
         "not"),
    integer(TOPOEVAL_KEY(max_groups), "1", "consistent: most groups (rigid parts)", atLeast(1)),
    integer(TOPOEVAL_KEY(max_clique_steps), "1",
            "consistent: branch-and-bound steps per clique search", atLeast(1)),
    real(TOPOEVAL_KEY(max_false_alarms), "1",
         "consistent: the first group's expected number of chance groups as big at most this",
         above(0)),
    real(TOPOEVAL_KEY(min_consensus_baseline_m), "m",
         "consistent: a further group is the fit of two pairs at least this far apart", atLeast(0)),
    integer(TOPOEVAL_KEY(min_part_group_vertices), "1",
            "consistent: smallest further group, bridged to an accepted one (a broken part)",
            atLeast(3)),
    integer(TOPOEVAL_KEY(min_joined_piece_pairs), "1",
            "consistent: a further group's other linked pieces of this many pairs join it when "
            "its fit places them and the walls agree (0: off)",
            atLeast(0)),
    flag(TOPOEVAL_KEY(scattered_part_groups),
         "consistent: a further group in pieces too small is kept whole when significant, its "
         "walls agree and it is another part"),
    integer(TOPOEVAL_KEY(min_scattered_part_pairs), "1",
            "consistent: ... of at least this many pairs (its significance decides)", atLeast(3)),
    flag(TOPOEVAL_KEY(link_across_map_pieces),
         "consistent: last, a further group's pairs in different pieces of the map's graph are "
         "linked by the ground truth's edges alone"),
    flag(TOPOEVAL_KEY(scattered_part_when_piece_refused),
         "consistent: a further group whose biggest linked piece is refused is kept whole when "
         "it is a scattered part"),
    flag(TOPOEVAL_KEY(first_group_from_maximal_cliques),
         "consistent: when the maximum clique does not settle, the maximal clique that settles "
         "best is the first group if its walls agree and pin it"),
    flag(TOPOEVAL_KEY(first_group_maximal_cliques_in_turn),
         "consistent: ... asked also when the maximum clique's group is refused, and tried in "
         "turn, best first, until one passes"),
    real(TOPOEVAL_KEY(first_group_in_turn_min_wall_agreement), "0..1",
         "consistent: ... each but the best of a clique that did not settle needs this share of "
         "its walls agreeing",
         atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(max_pair_turn_deg), "deg",
         "consistent: a pair whose own walls turn more than this against its group's leaves it "
         "(0: off)",
         atLeast(0).atMost(180)),
    real(TOPOEVAL_KEY(min_unlinked_part_wall_agreement), "ratio",
         "consistent: a small further group whose links leave no piece big enough is kept whole "
         "when its walls agree on this share and pin it (0: off)",
         atLeast(0).atMost(1)),
    flag(TOPOEVAL_KEY(walls_under_own_alignment),
         "consistent: a scattered or unlinked small part whose walls fail under its fit is "
         "asked again under their own ICP alignment, when it keeps every pair within tolerance"),
    real(TOPOEVAL_KEY(own_alignment_min_wall_agreement), "0..1",
         "consistent: ... when this share of its walls agree under its fit", atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(part_bridge_ratio), "ratio",
         "consistent: a further group's neighbour pairs keep their distance within this",
         atLeast(0)),
    real(TOPOEVAL_KEY(part_pivot_distance_m), "m",
         "consistent: a further group bridges when its turn's pivot is this near both groups "
         "(a small one if its walls agree too)",
         atLeast(0)),
    flag(TOPOEVAL_KEY(isolated_part_bridge),
         "consistent: a small further group with no matched neighbour bridges by its similarity "
         "and walls"),
    flag(TOPOEVAL_KEY(part_wall_bridge),
         "consistent: a further group as big as a first group whose neighbour pairs moved "
         "bridges when its walls agree and pin it"),
    real(TOPOEVAL_KEY(min_unconfirmed_group_similarity), "0..1",
         "consistent: a further group whose walls disagree needs at least this mean similarity "
         "(0: off)",
         atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(min_part_wall_agreement), "0..1",
         "consistent: a small further group, or a pair grown without links, less similar "
         "needs this share of its walls agreeing (0: off)",
         atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(max_wall_pinning), "ratio",
         "consistent: ... whose fit moved by 2 wall tolerances keeps at most this of it", above(0)),
    real(TOPOEVAL_KEY(min_first_group_wall_agreement), "0..1",
         "consistent: a small first group needs this share of its walls agreeing (0: off)",
         atLeast(0).atMost(1)),
    integer(TOPOEVAL_KEY(first_group_wall_check_pairs), "1",
            "consistent: ... a first group of fewer pairs than this", atLeast(0)),
    real(TOPOEVAL_KEY(first_group_disagreeing_pair_share), "0..1",
         "consistent: a first group is refused when this share of its pairs' walls disagree "
         "(0: off)",
         atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(further_group_disagreeing_pair_share), "0..1",
         "consistent: ... and a further group likewise (0: off)", atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(further_group_min_wall_agreement), "0..1",
         "consistent: a further group whose walls agree on less than this share, under its fit "
         "and their own alignment, is refused (0: off)",
         atLeast(0).atMost(1)),
    integer(TOPOEVAL_KEY(max_rival_placements), "count",
            "consistent: rival placements of the first group played out (0: off)",
            atLeast(0).atMost(16)),
    real(TOPOEVAL_KEY(min_rival_size_ratio), "ratio",
         "consistent: ... when it keeps this share of the first group's pairs", above(0).atMost(1)),
    real(TOPOEVAL_KEY(wall_margin_m), "m",
         "consistent: walls within a vertex's clearance plus this are compared", atLeast(0)),
    real(TOPOEVAL_KEY(wall_tolerance_m), "m",
         "consistent: a wall point agrees with one this near (or 1.5 cells)", above(0)),
    real(TOPOEVAL_KEY(growing_radius_m), "m",
         "consistent growing: rigid fit of the group's pairs this near", atLeast(0)),
    real(TOPOEVAL_KEY(position_tolerance_m), "m",
         "consistent growing: predicted partner within this", atLeast(0)),
    real(TOPOEVAL_KEY(min_consistent_growing_similarity), "0..1",
         "consistent growing: pairs at least this similar", atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(min_grown_wall_agreement), "0..1",
         "consistent growing: ... whose walls agree under the fit at least this much (0: off)",
         atLeast(0).atMost(1)),
    integer(TOPOEVAL_KEY(clutter_passes), "count",
            "consistent: the map's free-standing obstacles the ground truth lacks where the "
            "match puts them are freed and the map matched again, at most this often (0: off)",
            atLeast(0).atMost(16)),
    real(TOPOEVAL_KEY(clutter_max_size_m), "m",
         "clutter pass: islands at most this wide (enclosing circle) may be clutter", above(0)),
    real(TOPOEVAL_KEY(clutter_reach_m), "m",
         "clutter pass: ... and within this of a matched map vertex", atLeast(0)),
    real(TOPOEVAL_KEY(clutter_wall_tolerance_m), "m",
         "clutter pass: an island border cell this near a ground-truth wall (aligned) is on it",
         above(0)),
    real(TOPOEVAL_KEY(clutter_min_wall_share), "ratio",
         "clutter pass: an island with this share of its border on the ground truth's walls "
         "stays",
         above(0).atMost(1)),
    real(TOPOEVAL_KEY(clutter_min_share), "ratio",
         "clutter pass: runs when its first round finds this share of the islands judged clutter",
         atLeast(0).atMost(1)),
    flag(TOPOEVAL_KEY(clutter_start_without_islands),
         "clutter pass: a map whose match pairs fewer than 3 vertices is judged by the match of "
         "the map without all its islands"),
    real(TOPOEVAL_KEY(scale_min_error), "ratio",
         "scale pass: the map read at the ground truth's scale when its match shows its distances "
         "off by more than this (0: off)",
         atLeast(0).atMost(0.5)),
    real(TOPOEVAL_KEY(scale_min_sigmas), "1",
         "scale pass: ... and by this many standard errors of the estimate", atLeast(0)),
    real(TOPOEVAL_KEY(scale_min_pair_share), "ratio",
         "scale pass: ... kept in fewer brokenness groups with this share of the pairs before "
         "it",
         atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(scale_search_step), "ratio",
         "scale search: a map whose match pairs nothing is matched again read at the factors "
         "(1 + this)^-k and ^k (0: off)",
         atLeast(0).atMost(0.5)),
    integer(TOPOEVAL_KEY(scale_search_steps), "count", "scale search: ... k = 1 .. this",
            atLeast(0).atMost(10)),
    real(TOPOEVAL_KEY(scale_search_min_group_share), "ratio",
         "scale search: a reading counts when its biggest group holds this share of the smaller "
         "graph's matchable vertices",
         atLeast(0).atMost(1)))

}  // namespace mrpt_topoeval
