/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/QualityReport.h>
#include <mrpt_topoeval/TopologyGraph.h>

#include <string>

namespace mrpt_topoeval
{
/** Parameters of the map attributes and scores (paper IV), INI section `[QualityEvaluator]`. */
struct QualityParameters : public mrpt::config::CLoadableOptions
{
    /** The INI section of these keys, named by validate() in its messages. */
    static constexpr const char* kIniSection = "QualityEvaluator";

    /** Local consistency classes by shortest graph distance: short < this [m] ... */
    double consistency_short_max_m = 3.0;
    /** ... medium < this <= long [m]. */
    double consistency_medium_max_m = 9.0;
    /** A brokenness group grows while its mean squared alignment error stays at or below
     * this [m^2] (paper: SquaredErrorThreshold). */
    double brokenness_max_squared_error_m2 = 0.2;
    /** Groups smaller than this are not counted (paper: MinNumberVertices = 5) [1]. */
    int brokenness_min_vertices = 5;
    /** A group of at least this many vertices but fewer than brokenness_min_vertices still
     * counts when every counted group places its map vertices at least
     * brokenness_part_min_gap_m2 (mean squared) from where its own fit does: a small part
     * turned against the rest. = brokenness_min_vertices is the paper's rule [1]. */
    int brokenness_min_part_vertices = 3;
    /** See brokenness_min_part_vertices [m^2]. */
    double brokenness_part_min_gap_m2 = 1.0;
    /** A small part closer than brokenness_part_min_gap_m2, but beyond
     * brokenness_max_squared_error_m2, still counts when its walls set it apart: the wall
     * points around its vertices (pair_wall_margin_m, pair_wall_tolerance_m) agree under its
     * own fit, refined by them, for at least pair_wall_min_agreement, and every counted group's
     * transform keeps at most this ratio of that agreement. 3-4 vertices near a cut sit within
     * a metre of where the neighbouring part's fit puts them though their part is turned 12
     * degrees (corridor_office_1004/broken_3: agreement 0.78 under its own fit, 0.23 under the
     * neighbour's). Small candidates of generated maps that are not broken keep 0.96-1.00 of
     * it, of real pairs 0.55-1.00 (0.17 in the bent Intel map) (doc/quality.md). 0 = the
     * vertices' gap only [ratio]. */
    double brokenness_part_wall_ratio = 0.5;
    /** A grown group is split into two parts when two fits, each of a connected set of at
     * least brokenness_min_part_vertices of its vertices and each within
     * brokenness_max_squared_error_m2, leave the smaller set beyond that threshold under the
     * bigger set's fit and lower the group's squared error by more than chance (F test, 95 %);
     * repeated on each part. The threshold bounds a group's mean squared error only: two parts
     * turned about 10 degrees against each other about a pivot between them fit one
     * compromise within it (held-out angled_8004/broken_2: two parts 11.5 degrees apart, one
     * group of 13 vertices at 0.186 m^2, each part alone 0.005). false = the paper's grown
     * groups [bool]. */
    bool brokenness_split_parts = true;
    /** The match's groups are the brokenness candidates (issue 11: "locally consistent groups
     * are the brokenness candidates"): each group's core pairs, verified by the matcher as one
     * rigid part, are a group before the paper's growth runs on the other pairs, and are then
     * split, merged and thinned as a grown group is. The growth, seeded from a vertex near a
     * cut, can mix two parts turned 10-20 degrees about it into one compromise (held-out
     * seeds 9-12: 10 broken maps with a group more than 3 degrees off, where the matcher's
     * groups were right in most). false = the paper's growth from every matched vertex
     * [bool]. */
    bool brokenness_from_match_groups = true;
    /** Before the walls' refinement, each vertex of a counted group moves to the group whose
     * transform places it best (near a cut both fits place it within the threshold; the group
     * that met it first kept it, and its walls, turned with the other part, turn the walls'
     * fit). false = the groups as grown [bool]. */
    bool brokenness_best_fit_part = true;
    /** One wrong pair must not turn a part's fit: a group member that the fit of the group's
     * other members places farther than this x sqrt(brokenness_max_squared_error_m2) from its
     * ground-truth vertex leaves the group (the worst first, down to brokenness_min_vertices).
     * A pair 2.6 m off can join a group of 6 by turning its fit 3.9 degrees while the mean
     * squared error stays within the threshold. 1.5 and 2 give the same corpus results, 2.5
     * keeps one such pair (doc/quality.md). 0 = the paper's groups [ratio]. */
    double brokenness_outlier_ratio = 2.0;
    /** Each counted group's transform (its part's turn and shift, as reported) is refined by
     * aligning the walls around its vertices with ICP (MRPT's CICP, from the vertices' fit):
     * the walls within a vertex's clearance plus this margin, in both maps. A few vertices
     * that slide along the medial axis fix a part's turn to about 0.3 degrees, hundreds of
     * wall points to about 0.02 (doc/quality.md). Kept only when it still places the group's
     * vertices within brokenness_max_squared_error_m2. Membership is decided before, by the
     * vertices alone (then brokenness_merge_by_walls). 0 = the paper's vertex fit [m]. */
    double brokenness_wall_margin_m = 1.0;
    /** The walls' transform is also kept where the vertices' 95 % confidence test refuses it
     * but the walls vouch for it: under it at least pair_wall_min_agreement of the walls
     * around the group agree, no less than under the vertices' fit, and they pin it
     * (pair_wall_max_pinning). The test trusts the vertices' own residual as their noise;
     * a small part's few vertices near its cut slide 0.3-0.4 m with the cut's walls, their
     * fit absorbs it into a turn 3-6 degrees off, and its small residual then refuses the
     * walls that place the part right (doc/quality.md, brokenness step 7). false = the test
     * alone decides [bool]. */
    bool brokenness_walls_vouch = true;
    /** After that refinement, two groups whose walls' transforms put their vertices in the
     * same places (step 5's merge test, within brokenness_max_squared_error_m2, applied to the
     * walls' transforms) are one part: merged when the whole's vertex fit stays within that
     * threshold, and the whole refined by its walls again. Near a cut a group can keep two
     * pairs of the neighbouring part, whose compromise fit keeps it apart from the rest of its
     * own part (held-out multi_wing_3001/broken_2: two groups of one part, both turned -80.41
     * degrees by their walls, counted as a break). Needs brokenness_wall_margin_m > 0 and maps
     * with walls; false = membership by the vertices alone [bool]. */
    bool brokenness_merge_by_walls = true;
    /** Each pair's error in relative accuracy and local consistency is measured at its walls:
     * the walls within the ground-truth vertex's clearance plus this margin and those within
     * the map vertex's are aligned by ICP (MRPT's CICP, from the relative alignment; its first
     * matching distance the larger of the pair's own error and the root of
     * brokenness_max_squared_error_m2), and the map point they put at the ground-truth vertex
     * stands in for the map vertex. A vertex of an open room slides along the medial axis
     * between two maps by a fraction of the room's half width; the walls do not. Kept only
     * when the walls agree and pin that alignment (pair_wall_min_agreement,
     * pair_wall_max_pinning) and the point lies within the larger clearance of the two
     * vertices; then vertex_slack_share does not apply. 0 = the vertices' positions [m]. */
    double pair_wall_margin_m = 1.0;
    /** A pair's walls' place is kept when at least this share of the walls around it, from
     * both maps, lie within pair_wall_tolerance_m of the other map's walls under the walls'
     * alignment: an ICP that found nothing to align leaves the pair's error where it started,
     * and would count a room off by more than its matching distance as exact. As the matcher's
     * min_part_wall_agreement [0..1]. */
    double pair_wall_min_agreement = 0.7;
    /** ... and when that alignment moved by 2 x pair_wall_tolerance_m keeps at most this share
     * of the agreement: walls along a corridor do not fix a place along it. As the matcher's
     * max_wall_pinning [ratio]. */
    double pair_wall_max_pinning = 0.9;
    /** A wall point agrees with one this near (at least 1.5 cells). As the matcher's
     * wall_tolerance_m [m]. */
    double pair_wall_tolerance_m = 0.15;
    /** A pair's position error up to this share of its vertices' clearance (the larger of the
     * two) is vertex jitter, not map error: a vertex in a room sits on the medial axis, which
     * slides with furniture, noise and resolution by a fraction of the room's half width.
     * Relative accuracy and local consistency count only the error beyond it, for the pairs
     * not measured at their walls (pair_wall_margin_m). 0 = the paper's plain errors [ratio]. */
    double vertex_slack_share = 0.10;
    /** A pair's error counts at most this much in relative accuracy and local consistency, and
     * the relative alignment is refitted without pairs beyond it: one wrong pair must not decide
     * a score. 0 = the paper's plain RMS [m]. */
    double outlier_distance_m = 1.0;
    /** Accuracy score = 1 / (1 + rmse / this) [m]. */
    double accuracy_scale_m = 0.5;
    /** Consistency score = 1 / (1 + mean error / this) [m]. */
    double consistency_scale_m = 0.25;
    /** Weights of the scores in `quality` [1]. */
    double weight_coverage = 1.0;
    double weight_relative_accuracy = 1.0;
    double weight_consistency = 1.0;
    double weight_brokenness = 1.0;
    /** Weight of the explained walls' share in `quality` (explained_wall_tolerance_m) [1]. */
    double weight_explained_walls = 0.0;
    /** The map's side of coverage: a map wall point is explained when some brokenness group's
     * transform (the relative alignment when there is none) puts it this near a ground-truth
     * wall point (at least 1.5 cells). Larger than the walls' error of a map the match
     * places right, so what is left is the map's content that no matched part accounts for
     * (doc/quality.md, "Explained walls"). 0 = not measured (the paper) [m]. */
    double explained_wall_tolerance_m = 0.3;
    /** Below this share of explained walls the report says so in a message: a part of the map
     * that no matched part accounts for, broken beyond what brokenness counts or holding what
     * the ground truth lacks. On five corpora every broken map whose breaks were all found
     * explained at least 0.91 of its walls, and 41 of the 43 that missed one less than 0.9
     * (doc/quality.md, "Explained walls"). 0 = no message [ratio]. */
    double explained_walls_note_below = 0.9;
    /** Ours (brokenness step 9, doc/quality.md "A part placed by its walls"): a region of the
     * map's walls that no group explains, placed clearly on the ground truth's walls by one
     * rigid fit, is a part the match missed and counts as a break. On the standard corpus 5
     * more broken maps exactly right (68 -> 73 of 93), on fresh seeds 27 and 28 5 each, none
     * over-counted; a drifted region of a few SLAM maps counts too (doc/validation.md,
     * "Session 43"). false = the paper [bool]. */
    bool wall_parts = true;
    /** ... a region is the map's unexplained wall points within this of each other [m]. */
    double wall_part_link_m = 2.0;
    /** ... of at least this much wall (points x cell size): more than one room's walls (a room
     * of 3 m x 4 m has 14 m), since a single room placed elsewhere is what a building holds
     * more than once. 20 m until session 45; 15 m with wall_part_split found the third part of
     * gazebo_office/broken_2, 10 m let 15 m of a SLAM map's outer wall be placed 13.9 m away
     * on held-out seed 28 (doc/validation.md, "Session 45") [m]. */
    double wall_part_min_length_m = 15.0;
    /** ... its points lie on a ground-truth wall within this (at least 1.5 cells) [m]. */
    double wall_part_tolerance_m = 0.15;
    /** ... for at least this share of them under the best placement [ratio]. */
    double wall_part_min_share = 0.95;
    /** ... while the next distinct placement (5 degrees or 0.5 m away) reaches at most this
     * share of the best's: a placement the walls do not single out is refused [ratio]. */
    double wall_part_max_runner_up = 0.8;
    /** ... or, when a rival comes closer, the best pins at least this many more of the
     * region's free map vertices (within wall_part_pair_distance_m of a free ground-truth
     * vertex) than every rival above that share: walls alone leave a corridor in doubt along
     * itself, and a corridor slid by a door's spacing pins fewer (one more broken map exactly
     * right on the standard corpus, floorplan_Freiburg79_scan/broken_3; doc/validation.md,
     * "Session 46"). 0 = walls alone [vertices]. */
    int wall_part_min_pin_lead = 2;
    /** ... or, when a rival comes closer, the best is clear by its walls and its free space
     * together: each placement's share of walls on walls times the share of the map's free
     * space around the region (the clearance discs along its Topology Graph's edges, the medial
     * axis's own picture of the free space) that holds no ground-truth wall, the rivals' at
     * most wall_part_max_runner_up of the best's. Walls on walls cannot tell a room from the
     * same room turned half round, or from a like room elsewhere; a wall across its doorway or
     * through its middle can (doc/quality.md, brokenness step 9). false = walls and vertices
     * alone. */
    bool wall_part_free_space = true;
    /** ... placements tried at turns this far apart before ICP refines the best [deg]. */
    double wall_part_turn_step_deg = 3.0;
    /** ... the part's pairs: free ground-truth vertices it puts this near a free map vertex,
     * for the report and the validator's truth; they do not join the match [m]. */
    double wall_part_pair_distance_m = 0.5;
    /** ... a region no one fit places clearly may hold more than one part (two parts that
     * touch at a cut): parts are singled out within it as a whole map's are
     * (map_by_walls_region_*, at most map_by_walls_max_parts per region), each of which must
     * also put a free map vertex within wall_part_pair_distance_m of a free ground-truth vertex.
     * false = session 44's step 9 [bool]. */
    bool wall_part_split = true;
    /** ... a part (found either way) that puts more than this share of its points on
     * ground-truth walls where a group or an accepted part already puts the map's walls is
     * refused: one place of the building is the image of one part of the map, and a region the
     * ground truth lacks (a robot map beyond the plan's extent) finds rooms of its own shape
     * among the matched ones (doc/quality.md, step 9) [ratio]. */
    double wall_part_max_overlap = 0.5;
    /** Ours (doc/quality.md, "A map placed by its walls"): when the match holds fewer pairs
     * than brokenness_min_vertices (no group to measure a map by: a flat's graph of 4-6
     * vertices broken once has none), the map is placed part by part by its walls (each part
     * as a missed part is, wall_part_*), and the vertices those parts place near ground-truth
     * vertices are its match. On the standard corpus 5 more broken maps exactly right (73 ->
     * 78 of 93) and no other building placed (doc/validation.md, "Session 44"). false = the
     * paper [bool]. */
    bool map_by_walls = true;
    /** ... a part's region: the points whose neighbourhood of this radius its fit puts on the
     * ground truth's walls (a straight wall of another building lying along one of the ground
     * truth's has a neighbourhood that does not follow) [m]. */
    double map_by_walls_region_m = 3.0;
    /** ... for at least this share of that neighbourhood's points [ratio]. */
    double map_by_walls_region_share = 0.9;
    /** ... the parts found must together explain this share of the map's walls (within
     * explained_wall_tolerance_m), else none is kept [ratio]. */
    double map_by_walls_min_explained = 0.9;
    /** ... parts sought at most (a map broken three times has four) [1]. */
    int map_by_walls_max_parts = 4;
    /** ... when no part's region is singled out, the whole map is one part if its best
     * placement puts at least this share of its wall points on the ground truth's walls (within
     * wall_part_tolerance_m) and the next distinct placement at most wall_part_max_runner_up of
     * that: a robot map against its floor plan (furniture along the walls, clutter, doors closed)
     * has no clean 3 m neighbourhood, yet one placement puts most of it on the plan. Half: the
     * placement explains the map's majority (as min_trusted_coverage); the best placement of
     * another building put at most 0.41 (doc/quality.md, "The whole map"). 0 = off [ratio]. */
    double map_by_walls_whole_min_share = 0.5;
    /** Accuracy, consistency and brokenness describe the matched part only: below this
     * coverage, or share of the map's walls explained, the quality is multiplied by
     * sqrt(the smaller / this). 0 = the paper's plain weighted mean [ratio]. */
    double min_trusted_coverage = 0.5;

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
    /** \throws InputError naming the section, field and value, e.g.
     * "[QualityEvaluator] accuracy_scale_m = 0 violates accuracy_scale_m > 0". */
    void validate() const;
};

/** Paper IV: coverage, global and relative accuracy (Horn's closed form in double precision on
 * centred points), local consistency per class of graph distance, brokenness groups, and one
 * quality score, from a match of the ground truth's graph with the map's. With `threads` above
 * 1 brokenness is measured on a second thread while this one measures accuracy; the report
 * does not depend on it. evaluate() passes `[VertexSimilarity] threads` (0: all cores). */
QualityReport evaluateMatch(const TopologyGraph& ground_truth, const TopologyGraph& map,
                            const GraphMatch& match, const QualityParameters& params = {},
                            unsigned threads = 1);

}  // namespace mrpt_topoeval
