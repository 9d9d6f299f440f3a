/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// [GraphBuilder]: every key once (common/parameter_table.h); units and reasons in build_graph.h.

#include <mrpt_topoeval/graph/build_graph.h>

#include "common/parameter_table.h"

namespace mrpt_topoeval
{
TOPOEVAL_PARAMETER_TABLE(
    GraphBuilderParameters, NumberText::Stream,
    real(TOPOEVAL_KEY(occupied_min_prob), "probability",
         "a cell is an obstacle (Voronoi site) if P(occ) >= this", above(0.5).atMost(1)),
    real(TOPOEVAL_KEY(free_max_prob), "probability", "a cell is free if P(occ) <= this",
         atLeast(0).below(0.5)),
    real(TOPOEVAL_KEY(wall_gap_close_radius_m), "m",
         "close gaps in walls up to ~2x this (< min_clearance_m); 0 = off", atLeast(0)),
    real(TOPOEVAL_KEY(min_island_size_m), "m",
         "free-standing obstacles narrower than this (enclosing circle) become free; 0 = off",
         atLeast(0)),
    real(TOPOEVAL_KEY(unknown_fill_radius_m), "m",
         "fill unknown specks in free space up to ~2x this; 0 = off", atLeast(0)),
    real(TOPOEVAL_KEY(enclosed_unknown_min_free_share), "ratio",
         "enclosed unknown regions whose border is this share free become free; 0 = off",
         atLeast(0).atMost(1)),
    flag(TOPOEVAL_KEY(unknown_is_obstacle), "unknown cells next to free space bound it like walls"),
    flag(TOPOEVAL_KEY(skeleton_on_free_cells_only), "keep only skeleton points on free cells"),
    real(TOPOEVAL_KEY(min_clearance_m), "m",
         "drop Voronoi edges nearer than this to an obstacle (paper: 0.3)", above(0)),
    // Only points with at least the closing radius of clearance keep their clearance.
    relation(&P::wall_gap_close_radius_m, "wall_gap_close_radius_m < min_clearance_m",
             [](const P& p) { return p.wall_gap_close_radius_m < p.min_clearance_m; }),
    real(TOPOEVAL_KEY(prune_dead_end_length_m), "m", "remove dead-end edges shorter than this",
         atLeast(0)),
    real(TOPOEVAL_KEY(corner_spur_ratio), "ratio",
         "remove dead ends shorter than this x their clearance drop (corner branches)", atLeast(0)),
    real(TOPOEVAL_KEY(junction_disc_ratio), "ratio",
         "remove dead ends ending within this x their junction's clearance of it", atLeast(0)),
    real(TOPOEVAL_KEY(junction_disc_max_length_m), "m",
         "... only for dead ends shorter than this (straight)", atLeast(0)),
    real(TOPOEVAL_KEY(dead_end_tail_share), "ratio",
         "move a dead end out of its corner: back to this share of the tail's clearance; 0 = off",
         atLeast(0)),
    real(TOPOEVAL_KEY(dead_end_tail_ratio), "ratio",
         "a tail into a corner gains 1/this of its length in clearance (4: corners >= 29 deg)",
         atLeast(0)),
    real(TOPOEVAL_KEY(spurious_dead_end_length_m), "m",
         "mark remaining dead ends shorter than this as spurious", atLeast(0)),
    real(TOPOEVAL_KEY(alpha_radius_m), "m",
         "alpha-shape radius of the outer boundary (paper: 2.5); 0 = no cut", atLeast(0)),
    flag(TOPOEVAL_KEY(alpha_keep_enclosed),
         "the cut spares free space that does not reach the map's edge (false = paper)"),
    real(TOPOEVAL_KEY(alpha_page_max_edge_unknown), "ratio",
         "free space at the map's edge is outside only if at most this share of the edge is "
         "unknown (a page); 1 = always",
         atLeast(0).atMost(1)),
    // Infinity keeps only the biggest part, as the paper does.
    real(TOPOEVAL_KEY(min_component_length_m), "m",
         "keep every connected part with at least this much edge length (and the "
         "longest)",
         atLeast(0).orInfinity()),
    real(TOPOEVAL_KEY(room_piece_min_length_m), "m",
         "... and every part with at least this much that is a room (its skeleton between walls)",
         atLeast(0).orInfinity()),
    real(TOPOEVAL_KEY(room_piece_min_wall_share), "ratio",
         "... a room: this share of the obstacle cells nearest its skeleton are walls, not unknown",
         atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(join_distance_m), "m", "merge vertices joined by an edge shorter than this",
         atLeast(0)),
    real(TOPOEVAL_KEY(edge_direction_distance_m), "m",
         "an edge's direction at a vertex is measured up to this far along it", above(0)))

}  // namespace mrpt_topoeval
