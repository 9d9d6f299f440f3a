/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// [QualityEvaluator]: every key once (common/parameter_table.h); units and reasons in
// evaluate_match.h.

#include <mrpt_topoeval/evaluation/evaluate_match.h>

#include <cmath>

#include "common/parameter_table.h"

namespace mrpt_topoeval
{
TOPOEVAL_PARAMETER_TABLE(
    QualityParameters, NumberText::Stream,
    real(TOPOEVAL_KEY(consistency_short_max_m), "m",
         "local consistency: short pairs have graph distance < this", above(0)),
    real(TOPOEVAL_KEY(consistency_medium_max_m), "m", "... medium < this <= long"),
    relation(&P::consistency_medium_max_m, "consistency_medium_max_m > consistency_short_max_m",
             [](const P& p)
             {
                 return std::isfinite(p.consistency_medium_max_m) &&
                        p.consistency_medium_max_m > p.consistency_short_max_m;
             }),
    real(TOPOEVAL_KEY(brokenness_max_squared_error_m2), "m^2",
         "a brokenness group's largest mean squared error", above(0)),
    integer(TOPOEVAL_KEY(brokenness_min_vertices), "1",
            "smallest brokenness group counted (paper: 5)", atLeast(2)),
    integer(TOPOEVAL_KEY(brokenness_min_part_vertices), "1",
            "a smaller group counts when clearly separate (paper: = min)"),
    relation(&P::brokenness_min_part_vertices,
             "2 <= brokenness_min_part_vertices <= brokenness_min_vertices",
             [](const P& p)
             {
                 return p.brokenness_min_part_vertices >= 2 &&
                        p.brokenness_min_part_vertices <= p.brokenness_min_vertices;
             }),
    real(TOPOEVAL_KEY(brokenness_part_min_gap_m2), "m^2",
         "... placed this far (mean sq.) from every counted group", above(0)),
    real(TOPOEVAL_KEY(brokenness_part_wall_ratio), "ratio",
         "... or every counted group's fit keeps at most this of its walls' agreement (0 = off)",
         atLeast(0).atMost(1)),
    flag(TOPOEVAL_KEY(brokenness_split_parts),
         "a group whose two connected sets fit apart is two parts (false = paper)"),
    flag(TOPOEVAL_KEY(brokenness_from_match_groups),
         "the match's groups are brokenness groups before the growth (false = paper)"),
    flag(TOPOEVAL_KEY(brokenness_best_fit_part),
         "a counted group's vertex goes to the group whose fit places it best (false = paper)"),
    real(TOPOEVAL_KEY(brokenness_outlier_ratio), "ratio",
         "a member the others' fit places this x the threshold's root off leaves (0 = paper)",
         atLeast(0)),
    real(TOPOEVAL_KEY(brokenness_wall_margin_m), "m",
         "a group's turn refined by ICP of the walls within clearance + this (0 = paper)",
         atLeast(0)),
    flag(TOPOEVAL_KEY(brokenness_walls_vouch),
         "... also kept where the vertices' test refuses it but the walls agree and pin it"),
    flag(TOPOEVAL_KEY(brokenness_merge_by_walls),
         "groups that the walls' transforms place alike are one part (needs the margin above)"),
    real(TOPOEVAL_KEY(pair_wall_margin_m), "m",
         "a pair's error measured by ICP of the walls within clearance + this (0 = vertices)",
         atLeast(0)),
    real(TOPOEVAL_KEY(pair_wall_min_agreement), "0..1",
         "... kept when this share of those walls agree under the walls' alignment",
         atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(pair_wall_max_pinning), "ratio",
         "... and it moved by 2 tolerances keeps at most this of that share", atLeast(0)),
    real(TOPOEVAL_KEY(pair_wall_tolerance_m), "m",
         "... a wall point agrees with one this near (or 1.5 cells)", above(0)),
    real(TOPOEVAL_KEY(vertex_slack_share), "ratio",
         "a pair's vertex error up to this share of the clearance is jitter (0 = paper)",
         atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(outlier_distance_m), "m",
         "a pair's error counts at most this much in accuracy and consistency (0 = paper)",
         atLeast(0)),
    real(TOPOEVAL_KEY(accuracy_scale_m), "m", "accuracy score = 1 / (1 + rmse / this)", above(0)),
    real(TOPOEVAL_KEY(consistency_scale_m), "m", "consistency score = 1 / (1 + mean error / this)",
         above(0)),
    real(TOPOEVAL_KEY(weight_coverage), "1", "weight of coverage in quality", atLeast(0)),
    real(TOPOEVAL_KEY(weight_relative_accuracy), "1",
         "weight of the relative accuracy score in quality", atLeast(0)),
    real(TOPOEVAL_KEY(weight_consistency), "1",
         "weight of the mean local consistency score in quality", atLeast(0)),
    real(TOPOEVAL_KEY(weight_brokenness), "1", "weight of the brokenness score in quality",
         atLeast(0)),
    real(TOPOEVAL_KEY(weight_explained_walls), "1",
         "weight of the explained walls' share in quality", atLeast(0)),
    real(TOPOEVAL_KEY(explained_wall_tolerance_m), "m",
         "a map wall point is explained this near a ground-truth wall under a part's fit (0 = off)",
         atLeast(0)),
    real(TOPOEVAL_KEY(explained_walls_note_below), "ratio",
         "below this share of explained walls the report says so (0 = never)",
         atLeast(0).atMost(1)),
    flag(TOPOEVAL_KEY(wall_parts),
         "a region of unexplained walls one fit clearly places is a missed part (false = paper)"),
    real(TOPOEVAL_KEY(wall_part_link_m), "m", "... a region: unexplained wall points this near",
         above(0)),
    real(TOPOEVAL_KEY(wall_part_min_length_m), "m", "... of at least this much wall", above(0)),
    real(TOPOEVAL_KEY(wall_part_tolerance_m), "m",
         "... a point placed on a ground-truth wall this near (or 1.5 cells)", above(0)),
    real(TOPOEVAL_KEY(wall_part_min_share), "ratio", "... for this share of its points at least",
         above(0).atMost(1)),
    real(TOPOEVAL_KEY(wall_part_max_runner_up), "ratio",
         "... the next distinct placement reaching at most this of that share",
         atLeast(0).atMost(1)),
    integer(TOPOEVAL_KEY(wall_part_min_pin_lead), "1",
            "... or the best pinning this many vertices more than each closer rival (0 = off)",
            atLeast(0)),
    flag(TOPOEVAL_KEY(wall_part_free_space),
         "... or by share x its free space clear of walls, each rival's at most max_runner_up of "
         "it"),
    real(TOPOEVAL_KEY(wall_part_turn_step_deg), "deg", "... turns tried before ICP",
         above(0).atMost(90)),
    real(TOPOEVAL_KEY(wall_part_pair_distance_m), "m",
         "... its pairs: free vertices it places this near each other", above(0)),
    flag(TOPOEVAL_KEY(wall_part_split),
         "... a region no one fit places: parts singled out in it (map_by_walls_region_*)"),
    real(TOPOEVAL_KEY(wall_part_max_overlap), "ratio",
         "... a part's points on walls a matched part stands on at most this share",
         atLeast(0).atMost(1)),
    flag(TOPOEVAL_KEY(map_by_walls),
         "fewer pairs than brokenness_min_vertices: the map placed by its walls (false = paper)"),
    real(TOPOEVAL_KEY(map_by_walls_region_m), "m",
         "... a part's region: points whose neighbourhood this wide its fit places", above(0)),
    real(TOPOEVAL_KEY(map_by_walls_region_share), "ratio", "... on walls for this share of it",
         above(0).atMost(1)),
    real(TOPOEVAL_KEY(map_by_walls_min_explained), "ratio",
         "... the parts explain this share of the map's walls, else none is kept",
         atLeast(0).atMost(1)),
    integer(TOPOEVAL_KEY(map_by_walls_max_parts), "1", "... parts sought at most", atLeast(1)),
    real(TOPOEVAL_KEY(map_by_walls_whole_min_share), "ratio",
         "... no region: the whole map one part if its best fit puts this share on walls (0 = off)",
         atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(min_trusted_coverage), "ratio",
         "below this coverage or explained walls' share quality x sqrt(that / this) (0 = paper)",
         atLeast(0).atMost(1)),
    // All weights 0 would leave the weighted mean undefined (the explained walls' weight does
    // not count: they are not measured on every pair of graphs).
    relation(&P::weight_coverage, "at least one weight > 0",
             [](const P& p)
             {
                 return p.weight_coverage + p.weight_relative_accuracy + p.weight_consistency +
                            p.weight_brokenness >
                        0.0;
             }))

}  // namespace mrpt_topoeval
