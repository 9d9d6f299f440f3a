/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/matching/match_graphs.h>

#include <cmath>
#include <sstream>

#include "common/validation.h"

namespace mrpt_topoeval
{
std::string toString(MatchMethod m) { return m == MatchMethod::Paper ? "paper" : "consistent"; }

MatchMethod matchMethodFromString(const std::string& s)
{
    if (s == "consistent") return MatchMethod::Consistent;
    if (s == "paper") return MatchMethod::Paper;
    throw InputError("matching method '" + s + "' is not one of: consistent, paper");
}

void GraphMatcherParameters::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                                const std::string& s)
{
    method = matchMethodFromString(c.read_string(s, "method", toString(method)));
    MRPT_LOAD_CONFIG_VAR(edge_length_factor, double, c, s);
    MRPT_LOAD_CONFIG_VAR(edge_length_allowance_m, double, c, s);
    MRPT_LOAD_CONFIG_VAR(max_angle_difference_deg, double, c, s);
    MRPT_LOAD_CONFIG_VAR(min_isomorphism_similarity, double, c, s);
    MRPT_LOAD_CONFIG_VAR(min_isomorphism_vertices, int, c, s);
    MRPT_LOAD_CONFIG_VAR(min_isomorphism_share, double, c, s);
    MRPT_LOAD_CONFIG_VAR(max_branches_per_seed, int, c, s);
    MRPT_LOAD_CONFIG_VAR(neighbour_growing, bool, c, s);
    MRPT_LOAD_CONFIG_VAR(min_growing_similarity, double, c, s);
    MRPT_LOAD_CONFIG_VAR(growing_edge_length_factor, double, c, s);
    MRPT_LOAD_CONFIG_VAR(growing_edge_length_allowance_m, double, c, s);
    MRPT_LOAD_CONFIG_VAR(candidates_per_vertex, int, c, s);
    MRPT_LOAD_CONFIG_VAR(min_candidate_similarity, double, c, s);
    MRPT_LOAD_CONFIG_VAR(max_degree_difference, int, c, s);
    MRPT_LOAD_CONFIG_VAR(distance_tolerance_m, double, c, s);
    MRPT_LOAD_CONFIG_VAR(distance_tolerance_ratio, double, c, s);
    MRPT_LOAD_CONFIG_VAR(clearance_tolerance_share, double, c, s);
    MRPT_LOAD_CONFIG_VAR(min_group_vertices, int, c, s);
    MRPT_LOAD_CONFIG_VAR(min_small_group_similarity, double, c, s);
    MRPT_LOAD_CONFIG_VAR(support_hops, int, c, s);
    MRPT_LOAD_CONFIG_VAR(min_group_extent_m, double, c, s);
    MRPT_LOAD_CONFIG_VAR(max_groups, int, c, s);
    MRPT_LOAD_CONFIG_VAR(max_clique_steps, int, c, s);
    MRPT_LOAD_CONFIG_VAR(min_consensus_baseline_m, double, c, s);
    MRPT_LOAD_CONFIG_VAR(min_part_group_vertices, int, c, s);
    MRPT_LOAD_CONFIG_VAR(part_bridge_ratio, double, c, s);
    MRPT_LOAD_CONFIG_VAR(growing_radius_m, double, c, s);
    MRPT_LOAD_CONFIG_VAR(position_tolerance_m, double, c, s);
    MRPT_LOAD_CONFIG_VAR(min_consistent_growing_similarity, double, c, s);
}

void GraphMatcherParameters::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                              const std::string& s) const
{
    const int np = mrpt::config::MRPT_SAVE_NAME_PADDING();
    const int vp = mrpt::config::MRPT_SAVE_VALUE_PADDING();
    c.write(s, "method", toString(method), np, vp,
            "[consistent|paper] consistent groups (default) or the paper's isomorphisms");
    MRPT_SAVE_CONFIG_VAR_COMMENT(edge_length_factor,
                                 "[ratio] matched edges agree in length within factor x length");
    MRPT_SAVE_CONFIG_VAR_COMMENT(edge_length_allowance_m, "[m] ... plus this allowance");
    MRPT_SAVE_CONFIG_VAR_COMMENT(max_angle_difference_deg,
                                 "[deg] largest difference of matched edges' ring angles");
    MRPT_SAVE_CONFIG_VAR_COMMENT(min_isomorphism_similarity,
                                 "[0..1] pairs less similar are never assigned by isomorphism");
    MRPT_SAVE_CONFIG_VAR_COMMENT(min_isomorphism_vertices, "[1] smallest isomorphism accepted");
    MRPT_SAVE_CONFIG_VAR_COMMENT(min_isomorphism_share,
                                 "[ratio] ... or this share of the smaller graph (at least 3)");
    MRPT_SAVE_CONFIG_VAR_COMMENT(max_branches_per_seed,
                                 "[1] wavefront branches explored per seed (bounds recursion)");
    MRPT_SAVE_CONFIG_VAR_COMMENT(neighbour_growing, "[bool] extend the match by neighbour growing");
    MRPT_SAVE_CONFIG_VAR_COMMENT(min_growing_similarity,
                                 "[0..1] neighbour growing assigns pairs at least this similar");
    MRPT_SAVE_CONFIG_VAR_COMMENT(growing_edge_length_factor,
                                 "[ratio] neighbour growing's relaxed edge-length factor");
    MRPT_SAVE_CONFIG_VAR_COMMENT(growing_edge_length_allowance_m,
                                 "[m] neighbour growing's relaxed edge-length allowance");
    MRPT_SAVE_CONFIG_VAR_COMMENT(candidates_per_vertex,
                                 "[1] consistent: most similar partners per vertex as candidates");
    MRPT_SAVE_CONFIG_VAR_COMMENT(min_candidate_similarity,
                                 "[0..1] consistent: candidate pairs are at least this similar");
    MRPT_SAVE_CONFIG_VAR_COMMENT(max_degree_difference,
                                 "[1] consistent: largest degree difference of a pair");
    MRPT_SAVE_CONFIG_VAR_COMMENT(distance_tolerance_m,
                                 "[m] consistent: distances of two pairs agree within this");
    MRPT_SAVE_CONFIG_VAR_COMMENT(distance_tolerance_ratio, "[ratio] ... plus this x the distance");
    MRPT_SAVE_CONFIG_VAR_COMMENT(clearance_tolerance_share,
                                 "[ratio] ... plus this x each vertex's clearance");
    MRPT_SAVE_CONFIG_VAR_COMMENT(min_group_vertices,
                                 "[1] consistent: smallest group of consistent pairs accepted");
    MRPT_SAVE_CONFIG_VAR_COMMENT(
        min_small_group_similarity,
        "[0..1] consistent: smallest mean similarity of a smaller group on a small graph");
    MRPT_SAVE_CONFIG_VAR_COMMENT(
        support_hops, "[1] consistent: pairs linked within this many edges in both maps");
    MRPT_SAVE_CONFIG_VAR_COMMENT(min_group_extent_m,
                                 "[m] consistent: a group spans at least this in the ground truth");
    MRPT_SAVE_CONFIG_VAR_COMMENT(max_groups, "[1] consistent: most groups (rigid parts)");
    MRPT_SAVE_CONFIG_VAR_COMMENT(max_clique_steps,
                                 "[1] consistent: branch-and-bound steps per clique search");
    MRPT_SAVE_CONFIG_VAR_COMMENT(
        min_consensus_baseline_m,
        "[m] consistent: a further group is the fit of two pairs at least this far apart");
    MRPT_SAVE_CONFIG_VAR_COMMENT(
        min_part_group_vertices,
        "[1] consistent: smallest further group, bridged to an accepted one (a broken part)");
    MRPT_SAVE_CONFIG_VAR_COMMENT(
        part_bridge_ratio,
        "[ratio] consistent: a further group's neighbour pairs keep their distance within this");
    MRPT_SAVE_CONFIG_VAR_COMMENT(
        growing_radius_m, "[m] consistent growing: rigid fit of the group's pairs this near");
    MRPT_SAVE_CONFIG_VAR_COMMENT(position_tolerance_m,
                                 "[m] consistent growing: predicted partner within this");
    MRPT_SAVE_CONFIG_VAR_COMMENT(min_consistent_growing_similarity,
                                 "[0..1] consistent growing: pairs at least this similar");
}

void GraphMatcherParameters::validate() const
{
    internal::require(internal::isNonNegative(edge_length_factor), "edge_length_factor",
                      edge_length_factor, "edge_length_factor >= 0");
    internal::require(internal::isNonNegative(edge_length_allowance_m), "edge_length_allowance_m",
                      edge_length_allowance_m, "edge_length_allowance_m >= 0");
    internal::require(std::isfinite(max_angle_difference_deg) && max_angle_difference_deg > 0.0 &&
                          max_angle_difference_deg <= 180.0,
                      "max_angle_difference_deg", max_angle_difference_deg,
                      "0 < max_angle_difference_deg <= 180");
    internal::require(internal::isUnit(min_isomorphism_similarity), "min_isomorphism_similarity",
                      min_isomorphism_similarity, "0 <= min_isomorphism_similarity <= 1");
    internal::require(min_isomorphism_vertices >= 1, "min_isomorphism_vertices",
                      min_isomorphism_vertices, "min_isomorphism_vertices >= 1");
    internal::require(std::isfinite(min_isomorphism_share) && min_isomorphism_share > 0.0 &&
                          min_isomorphism_share <= 1.0,
                      "min_isomorphism_share", min_isomorphism_share,
                      "0 < min_isomorphism_share <= 1");
    internal::require(max_branches_per_seed >= 1, "max_branches_per_seed", max_branches_per_seed,
                      "max_branches_per_seed >= 1");
    internal::require(internal::isUnit(min_growing_similarity), "min_growing_similarity",
                      min_growing_similarity, "0 <= min_growing_similarity <= 1");
    internal::require(internal::isNonNegative(growing_edge_length_factor),
                      "growing_edge_length_factor", growing_edge_length_factor,
                      "growing_edge_length_factor >= 0");
    internal::require(internal::isNonNegative(growing_edge_length_allowance_m),
                      "growing_edge_length_allowance_m", growing_edge_length_allowance_m,
                      "growing_edge_length_allowance_m >= 0");
    internal::require(candidates_per_vertex >= 1, "candidates_per_vertex", candidates_per_vertex,
                      "candidates_per_vertex >= 1");
    internal::require(internal::isUnit(min_candidate_similarity), "min_candidate_similarity",
                      min_candidate_similarity, "0 <= min_candidate_similarity <= 1");
    internal::require(max_degree_difference >= 0, "max_degree_difference", max_degree_difference,
                      "max_degree_difference >= 0");
    internal::require(internal::isNonNegative(distance_tolerance_m), "distance_tolerance_m",
                      distance_tolerance_m, "distance_tolerance_m >= 0");
    internal::require(internal::isUnit(distance_tolerance_ratio), "distance_tolerance_ratio",
                      distance_tolerance_ratio, "0 <= distance_tolerance_ratio <= 1");
    internal::require(internal::isNonNegative(clearance_tolerance_share),
                      "clearance_tolerance_share", clearance_tolerance_share,
                      "clearance_tolerance_share >= 0");
    internal::require(min_group_vertices >= 3, "min_group_vertices", min_group_vertices,
                      "min_group_vertices >= 3");
    internal::require(std::isfinite(min_small_group_similarity) &&
                          min_small_group_similarity >= 0.0 && min_small_group_similarity <= 1.0,
                      "min_small_group_similarity", min_small_group_similarity,
                      "0 <= min_small_group_similarity <= 1");
    internal::require(support_hops >= 1, "support_hops", support_hops, "support_hops >= 1");
    internal::require(internal::isNonNegative(min_group_extent_m), "min_group_extent_m",
                      min_group_extent_m, "min_group_extent_m >= 0");
    internal::require(max_groups >= 1, "max_groups", max_groups, "max_groups >= 1");
    internal::require(max_clique_steps >= 1, "max_clique_steps", max_clique_steps,
                      "max_clique_steps >= 1");
    internal::require(internal::isNonNegative(min_consensus_baseline_m), "min_consensus_baseline_m",
                      min_consensus_baseline_m, "min_consensus_baseline_m >= 0");
    internal::require(internal::isNonNegative(part_bridge_ratio), "part_bridge_ratio",
                      part_bridge_ratio, "part_bridge_ratio >= 0");
    internal::require(min_part_group_vertices >= 3, "min_part_group_vertices",
                      min_part_group_vertices, "min_part_group_vertices >= 3");
    internal::require(internal::isNonNegative(growing_radius_m), "growing_radius_m",
                      growing_radius_m, "growing_radius_m >= 0");
    internal::require(internal::isNonNegative(position_tolerance_m), "position_tolerance_m",
                      position_tolerance_m, "position_tolerance_m >= 0");
    internal::require(internal::isUnit(min_consistent_growing_similarity),
                      "min_consistent_growing_similarity", min_consistent_growing_similarity,
                      "0 <= min_consistent_growing_similarity <= 1");
}

}  // namespace mrpt_topoeval
