/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/geometry/Transform2D.h>

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

namespace mrpt_topoeval
{
/** Position error of matched vertices (paper IV: global and relative accuracy). */
struct Accuracy
{
    std::size_t pairs = 0;
    double rmse_m = 0.0;    //!< Root mean square distance of matched vertices [m].
    double score = 0.0;     //!< In [0, 1], 1 = exact (doc/quality.md).
    Transform2D transform;  //!< Relative accuracy only: the best rigid alignment (Horn).
    /** Relative accuracy only: pairs whose error was measured at their walls
     * (pair_wall_margin_m), the others at their vertices. */
    std::size_t by_walls = 0;
};

/** One class of local consistency (paper IV): ground-truth vertex pairs grouped by their
 * shortest graph distance. */
struct ConsistencyClass
{
    std::string name;                                               //!< "short", "medium", "long"
    double min_graph_distance_m = 0.0, max_graph_distance_m = 0.0;  //!< [min, max)
    std::size_t pairs = 0;
    double mean_error_m = 0.0;  //!< Mean |d_gt - d_map| of the pairs' geometric distances [m].
    double score = 0.0;         //!< In [0, 1] (doc/quality.md); 0 when the class is empty.
};

/** A brokenness group (paper IV, Table III): connected matched vertices that one rigid
 * transform aligns with the ground truth. */
struct BrokennessGroup
{
    std::vector<int> gt_vertices;   //!< Ground-truth vertex ids, in the order they joined.
    double squared_error_m2 = 0.0;  //!< Mean squared alignment error [m^2].
    Transform2D transform;          //!< The group's T_gt_map.
    /** How far this part is off: the root mean square, over its vertices' partners q, of
     * |T(q) - T'(q)|, T this group's transform and T' the larger group's that places them
     * nearest [m]. 0 for the largest group. */
    double offset_m = 0.0;
    /** Ours: a part placed by its walls. A part the match missed (wall_parts): its
     * `gt_vertices` are then the free ground-truth vertices it places near free map vertices,
     * `map_vertices` those map vertices (pair by pair; not pairs of the match). A part of a map
     * placed by its walls (map_by_walls; every group is one): its vertices' pairs are the
     * match's. Its squared error theirs. */
    bool by_walls = false;
    std::vector<int> map_vertices;
};

/** Brokenness (paper IV): how many locally consistent parts are misplaced against each other. */
struct Brokenness
{
    int degree = 0;  //!< Accepted groups - 1 (0 when there is at most one group).
    /** Accepted groups, largest first; the parts placed by their walls (by_walls) after them. */
    std::vector<BrokennessGroup> groups;
    double score = 0.0;  //!< 1 / (1 + degree); 0 when nothing matched.
};

/** Ours (issue 11): the map's side of coverage. Coverage counts the ground truth's vertices
 * that the match found; this counts the map's walls that it explains: the map's wall points
 * (occupied cells bordering free or unknown space) that some brokenness group's transform, or
 * the relative alignment when there is no group, puts within `tolerance_m` of a ground-truth
 * wall point. What it leaves: a part matched nowhere (broken beyond recognition, another
 * building), clutter the ground truth lacks, walls drawn farther off than the tolerance
 * (doc/quality.md, "Explained walls"). */
struct ExplainedWalls
{
    /** False when it could not be measured: nothing matched, or a graph without wall points
     * (a graph made in code). Then `share` is 0 and `quality` does not use it. */
    bool measured = false;
    std::size_t wall_points = 0;  //!< The map's wall points.
    std::size_t explained = 0;    //!< Of them, those within tolerance_m of a ground-truth wall.
    double share = 0.0;           //!< explained / wall_points [0, 1].
    double tolerance_m = 0.0;     //!< The tolerance used (at least 1.5 cells) [m].
    /** The map's wall points not explained, in the map's frame as given [m]: where the map
     * disagrees with the ground truth, drawn by drawQualityReport(). */
    std::vector<Eigen::Vector2f> unexplained_m;
};

/** Everything `compare` reports. Plain data; text and JSON in QualityReport.cpp / report_json. */
struct QualityReport
{
    std::size_t gt_vertices = 0;   //!< Matchable (non-spurious) ground-truth vertices.
    std::size_t map_vertices = 0;  //!< Matchable map vertices.
    GraphMatch match;
    double coverage = 0.0;  //!< Matched share of the matchable ground-truth vertices [0, 1].
    Accuracy global_accuracy;
    Accuracy relative_accuracy;
    std::vector<ConsistencyClass> local_consistency;  //!< short, medium, long
    Brokenness brokenness;
    ExplainedWalls explained_walls;
    double quality = 0.0;  //!< Weighted combination of the scores [0, 1] (doc/quality.md).
    /** The factor the map's distances were multiplied by to be matched, and its brokenness
     * measured, at the ground truth's scale (the scale pass, [GraphMatcher] scale_min_error);
     * 1 = as given. Accuracy and consistency measure the map as given, so a scale error costs
     * there; the brokenness groups' transforms apply to the map's points times it [ratio]. */
    double map_scale = 1.0;
    std::vector<std::string> messages;
    std::map<std::string, double> timing_ms;

    /** Mean score of the non-empty local consistency classes, as `quality` combines them; 0
     * when there is none. */
    double consistencyScore() const;

    /** A few lines, like Ceres' brief report. */
    std::string briefReport() const;
    /** Every figure, group and class. */
    std::string fullReport() const;
};

}  // namespace mrpt_topoeval
