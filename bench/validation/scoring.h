/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// How one case of the validation corpus is scored against its truth (doc/validation.md,
// "Measures"): the truth check, true pairs, precision, recall, brokenness.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/QualityReport.h>
#include <mrpt_topoeval/TopologyGraph.h>

#include <map>
#include <string>
#include <vector>

#include "truth.h"

namespace mrpt_topoeval::validation
{
/** The truth check: occupied map cells (clutter left out) mapped into the ground truth. */
struct TruthCheck
{
    std::size_t cells = 0;     //!< Occupied map cells checked.
    std::size_t on_wall = 0;   //!< ... that land within the tolerance of a ground-truth wall.
    std::size_t unmapped = 0;  //!< ... for which the truth gives no point.
    /** Free ground-truth cells, and those whose image in the map (Truth::forward) is known,
     * free or occupied; counted when Truth::keeps_free_space. */
    std::size_t free_cells = 0, free_kept = 0;
    double share() const { return cells ? static_cast<double>(on_wall) / cells : 1.0; }
    double freeShare() const
    {
        return free_cells ? static_cast<double>(free_kept) / free_cells : 1.0;
    }
};

/** Checks `truth` on `map` against `gt` (distance to the nearest ground-truth obstacle cell). */
TruthCheck checkTruth(const mrpt::maps::COccupancyGridMap2D& gt,
                      const mrpt::maps::COccupancyGridMap2D& map, const Truth& truth);

/** How far the map is from a rigid copy of the ground truth [m]: the RMS distance between its
 * occupied cells mapped by the truth and the same cells moved by the one rigid transform that
 * fits them best (Horn). 0 for moved, resampled and noisy maps; the SLAM maps' real error;
 * NaN for a different building. Every `stride`-th cell in x and y. */
double mapDistortion(const mrpt::maps::COccupancyGridMap2D& map, const Truth& truth,
                     int stride = 3);

/** Ground-truth vertices that a map of the whole place lost in its graph, by what the map's
 * graph has near where the truth puts them (doc/validation.md, "Measures", "graph
 * stability"): what changes a Topology Graph between two maps of one place (issue 11, item 1).
 * A vertex is lost when no map vertex lies within CaseScore::pairTolerance() of it. */
struct LostVertices
{
    std::size_t vertices = 0;  //!< Non-spurious ground-truth vertices looked at.
    /** Dead ends (degree 1): a non-spurious map dead end within kLostNearM of it, but beyond
     * the tolerance (its tip stops elsewhere), or none. */
    std::size_t dead_end_moved = 0, dead_end_absent = 0;
    /** Junctions (degree 3 or more; degree 2 on a loop with no junction): one of its dead ends
     * lost too, so that the map's graph has no branch to make it a junction; else a map
     * junction within kLostNearM, or none. */
    std::size_t junction_with_dead_end = 0, junction_moved = 0, junction_absent = 0;
    /** Every non-spurious ground-truth dead end, by the clearance at its tip (below
     * kNarrowTipM: a branch the clearance filter cut, not a wall), and of those the lost. */
    std::size_t narrow_tips = 0, narrow_tips_lost = 0, wide_tips = 0, wide_tips_lost = 0;
    std::size_t lost() const
    {
        return dead_end_moved + dead_end_absent + junction_with_dead_end + junction_moved +
               junction_absent;
    }
    LostVertices& operator+=(const LostVertices& o);
};
/** A lost vertex "moved" when the map's graph has one of its kind this near [m]: four times
 * the smallest pair tolerance, a room's or a corridor's width; farther is another place. */
constexpr double kLostNearM = 2.0;
/** A dead end's tip is narrow below this clearance [m]: within 0.2 m of the graph's
 * min_clearance_m (0.3 m), where a branch ends because the clearance filter cut it. */
constexpr double kNarrowTipM = 0.5;

/** Broken maps: one injected part (Truth::part_of), its turn, and how much of it the match has. */
struct PartScore
{
    int part = -1;
    double yaw_deg = 0.0;          //!< The part's injected rotation [deg].
    std::size_t counterparts = 0;  //!< Its ground-truth vertices with a counterpart.
    std::size_t true_pairs = 0;    //!< ... and of those, truly matched.
};

/** Broken maps: one brokenness group found, its rotation, and in which injected part the map
 * partners of its vertices lie (part -1: in none). */
struct GroupScore
{
    double yaw_deg = 0.0;
    std::map<int, std::size_t> vertices_per_part;
    /** The part most of its vertices lie in; for a group placed by its walls, the part most of
     * whose wall points its fit puts on a ground-truth wall (since session 49). -1: none. */
    int part = -1;
    /** Every group but the largest: how far the report says its part is off
     * (BrokennessGroup::offset_m), and how far the truth says: the same measure with each
     * part's own transform, fitted to where the truth places that part's map vertices (NaN
     * when a group has no part). 0 for the largest group [m]. */
    double offset_m = 0.0, true_offset_m = 0.0;
};

/** The figures of one case. Counts are of non-spurious vertices. */
struct CaseScore
{
    std::size_t gt_vertices = 0, map_vertices = 0;
    /** Ground-truth vertices that truly have a counterpart: a map vertex that the truth maps
     * within the pair tolerance of it. */
    std::size_t gt_with_counterpart = 0;
    /** Ground-truth vertices in the part of the map that was kept, by Truth::kept (all of them
     * when the whole ground truth is kept), and those at the cut (their centre kept, their
     * clearance disc cut): a crop's coverage should lie between the share of the first and
     * that of both. Unlike gt_with_counterpart they do not depend on the map's graph. */
    std::size_t gt_kept = 0, gt_at_cut = 0;
    std::size_t matched = 0, true_pairs = 0;
    /** False pairs made by a group's core (isomorphism) and by growing (neighbour growing). */
    std::size_t false_core = 0, false_grown = 0;
    /** One line per false pair, for the pictures: "gt G -> map M (stage), truth puts M D m from
     * G" (D absent when the truth does not place M). */
    std::vector<std::string> false_pairs;
    /** One line per ground-truth vertex with a counterpart, for the pictures: "gt G -> map M
     * (part P, matched to X)", X the map vertex the match pairs G with (-1: none); and one per
     * vertex that a part keeps whole (Truth::kept_part) without a counterpart: "gt G kept whole
     * by part P: no counterpart in the map's graph". */
    std::vector<std::string> counterpart_lines;
    /** The ground-truth vertices without a counterpart, by cause; counted when the truth
     * places the map's vertices and keeps the whole ground truth (no crop, no broken map, no
     * other building: there a vertex may be lost by the variant, not by the graph). */
    LostVertices lost;
    /** The match's and the evaluation's messages (why nothing matched, what was refused). */
    std::vector<std::string> messages;
    double precision = 0.0;  //!< true / matched (NaN when nothing was matched).
    double recall = 0.0;     //!< true / gt_with_counterpart (NaN when there is no counterpart).
    int brokenness_found = 0;
    /** Each found break's size: the offset_m of every brokenness group but the largest [m]. */
    std::vector<double> break_offsets_m;
    int brokenness_injected = -1;
    /** Broken maps: parts with at least 3 and at least 5 true pairs (how many groups a
     * brokenness measure could find from this match); -1 when not broken. */
    int parts_with_3_pairs = -1, parts_with_5_pairs = -1;
    /** Broken maps: parts holding at least 5 ground-truth vertices with a counterpart, i.e.
     * parts that any matcher could make a 5-vertex group of (a break is measurable when every
     * part is one); -1 when not broken. */
    int parts_with_5_counterparts = -1;
    /** Broken maps: parts holding at least 3 ground-truth vertices with a counterpart. A part
     * with fewer has no rigid fit that any matcher could find (two pairs fit any turn): its
     * break is not observable in the Topology Graphs; -1 when not broken. */
    int parts_with_3_counterparts = -1;
    /** Broken maps: parts that keep at least 3 ground-truth vertices whole (Truth::kept_part:
     * their walls all in the map, undisturbed by another part), by the truth alone; -1 when not
     * broken. A part with 3 such vertices but fewer than 3 counterparts lost them in the map's
     * graph, not in the map. */
    int parts_with_3_kept = -1;
    /** Largest |yaw error| of an accepted brokenness group against its part (GroupScore::part)
     * [deg]; NaN when not a broken case or no group. */
    double max_group_rotation_error_deg = 0.0;
    /** Broken maps: every injected part and every brokenness group, for brokenCause(). */
    std::vector<PartScore> parts;
    std::vector<GroupScore> groups;
    double coverage = 0.0, quality = 0.0, relative_rmse_m = 0.0;
    /** QualityReport::explained_walls.share; NaN when not measured (nothing matched). */
    double explained_walls = 0.0;
    /** Pairs whose map vertex is more than this from its partner count as false [m]:
     * max(0.5 m, half the larger clearance of the two vertices), since a dead end or a room's
     * vertex sits on a medial axis that slides by a fraction of its clearance. */
    static double pairTolerance(const TopoVertex& gt_vertex, const TopoVertex& map_vertex);
};

/** Scores a report of `gt_graph` vs `map_graph` against `truth`. */
CaseScore scoreCase(const TopologyGraph& gt_graph, const TopologyGraph& map_graph,
                    const QualityReport& report, const Truth& truth);
}  // namespace mrpt_topoeval::validation
