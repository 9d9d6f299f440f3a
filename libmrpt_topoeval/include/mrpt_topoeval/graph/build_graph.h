/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt_topoeval/TopologyGraph.h>

#include <cstddef>
#include <functional>
#include <map>
#include <string>

namespace mrpt::maps
{
// Only references to grids here: the full class (a heavy header) where a grid is made or read.
class COccupancyGridMap2D;
}  // namespace mrpt::maps

namespace mrpt_topoeval
{
/** Thresholds of the Topology Graph construction (paper II-B), INI section `[GraphBuilder]`.
 * Lengths in metres, so one configuration fits maps of any resolution. */
struct GraphBuilderParameters : public mrpt::config::CLoadableOptions
{
    /** The INI section of these keys, named by validate() in its messages. */
    static constexpr const char* kIniSection = "GraphBuilder";

    /** A cell is an obstacle (a Voronoi site) when P(occupied) >= this [probability]. */
    double occupied_min_prob = 0.65;
    /** A cell is free space when P(occupied) <= this [probability]. */
    double free_max_prob = 0.35;
    /** Unknown specks inside free space narrower than about twice this are filled as free
     * (a morphological closing of the free cells; walls are never changed): the dotted free
     * space of laser fans looks the same at every resolution. 0 disables [m]. */
    double unknown_fill_radius_m = 0.10;
    /** Gaps in walls up to about twice this wide are closed before the Voronoi diagram (a
     * morphological closing of the obstacle cells with a disc of this radius): one-cell holes
     * that rotation, resampling or sensor noise open in a wall neither join its two sides nor
     * cut it into pieces, and its notches grow no branches. Points with at least this
     * clearance keep their clearance, so it must stay below `min_clearance_m`. 0 disables [m]. */
    double wall_gap_close_radius_m = 0.10;
    /** Free-standing obstacles (8-connected occupied or unknown cells surrounded by free space,
     * not touching the grid's edge) whose smallest enclosing circle is narrower than this
     * become free space: specks of sensor noise, table and chair legs, small furniture, which
     * otherwise put small loops and dead ends into a room that the same room without them does
     * not have. Columns narrower than this go too, in every map alike. 0 disables [m]. */
    double min_island_size_m = 0.25;
    /** Unknown regions enclosed by the map (8-connected unknown cells that do not reach the
     * grid's edge through unknown cells) become free when at least this share of their border
     * cells is free: the middle of a large hall that the laser crossed too sparsely to mark, the
     * wedges behind columns. Regions bounded mostly by walls (an unexplored room seen through a
     * door, the inside of a thick wall) stay unknown. 0 disables [ratio]. */
    double enclosed_unknown_min_free_share = 0.9;
    /** Unknown cells next to free space bound it like obstacles: the graph is the skeleton of
     * the known free space, so half-seen areas (laser fans through doors, frontiers) do not
     * grow branches that change with every pass of the robot [bool]. */
    bool unknown_is_obstacle = true;
    /** Keep only skeleton points lying on free cells: the skeleton stops where the map stops
     * being known (unexplored rooms, the outside of a robot map) [bool]. */
    bool skeleton_on_free_cells_only = true;
    /** Voronoi edges closer than this to an obstacle are dropped (paper: 30 cm) [m]. */
    double min_clearance_m = 0.30;
    /** Dead-end edges shorter than this are removed (paper II-B "short dead-end edges") [m]. */
    double prune_dead_end_length_m = 0.50;
    /** Dead ends into convex corners of free space are removed too: a medial-axis branch into
     * a corner is sqrt(2) times as long as the clearance it loses, so a dead end shorter than
     * this factor times (clearance at its junction - clearance at its end), measured as the
     * straight distance between its ends, is such a branch,
     * whatever the room's size. 0 disables [ratio]. */
    double corner_spur_ratio = 1.5;
    /** A dead end whose end lies within this factor times its junction's clearance of the
     * junction ends inside the junction's empty disc: it shows nothing the junction does not,
     * and flips in and out with small changes of the walls (a room's end next to its door).
     * It is removed. 0 disables [ratio]. */
    double junction_disc_ratio = 1.0;
    /** ... but only dead ends shorter than this (straight distance) are judged by the disc
     * rule: a long branch of a big room is a real feature even inside the room's disc [m]. */
    double junction_disc_max_length_m = 1.50;
    /** A dead end stops where its room or corridor ends, not in a corner. A corner branch
     * that survives pruning on one map and not on the other (an acute corner, or the cells of
     * a right one) moves the dead end from the end of its room or corridor into the corner,
     * 1-2 m away. The branch's tail into a corner is the points whose clearance exceeds the
     * tip's by at least 1 / dead_end_tail_ratio of their distance to the tip; the tip is moved
     * back to where the clearance reaches this share of the tail's largest. 0 keeps the tips
     * where the skeleton ends (paper) [ratio]. */
    double dead_end_tail_share = 0.9;
    /** A corner of angle t makes a tail whose distance to the tip is 1 / sin(t / 2) times the
     * clearance it gains: 4 takes corners from 29 degrees up [ratio]. */
    double dead_end_tail_ratio = 4.0;
    /** Remaining dead-end edges shorter than this, and their end vertex, are marked spurious
     * (paper II-C) [m]. */
    double spurious_dead_end_length_m = 1.00;
    /** Radius of the alpha shape whose longest polygon is the map's outer boundary; vertices
     * outside it are removed (paper: 2.5 m) [m]. 0 disables the cut. */
    double alpha_radius_m = 2.50;
    /** The alpha cut removes only what lies in free space reaching the map's edge (the page
     * around a floor plan). The polygon is made of the walls alone: a room wider than twice the
     * radius that touches the outer wall, or one walled by a line of collinear cells (no faces),
     * falls outside it, though walls or unknown enclose it (floorplan lab_intel's stair hall),
     * and so does a wing a broken map drew apart (its own loop, not the longest). Free space
     * enclosed by walls or unknown is the map's inside. false = the paper's cut of everything
     * outside the polygon [bool]. */
    bool alpha_keep_enclosed = true;
    /** Free space reaching the map's edge is the page around a floor plan only when at most
     * this share of the cells on the map's edge (the whole grid's) is unknown. A map with more
     * says its outside is unknown (a robot map): free space at its edge is its inside cut by
     * the map's border (a crop through a hall), and the alpha cut spares it (with
     * alpha_keep_enclosed). Measured on the validation corpus's crops whose free space reaches
     * the edge: white-page plans 0-0.004, every other map 0.59-0.96. 1 = free space at the edge
     * is always outside (session 28) [ratio]. */
    double alpha_page_max_edge_unknown = 0.25;
    /** Connected parts of the graph whose total edge length is at least this are all kept; the
     * longest part is always kept. The paper keeps only the biggest part, but a map cut into
     * pieces by a narrow or closed door then loses whole regions, and which piece is biggest
     * can flip between two maps of one place. A large value keeps only the biggest, as the
     * paper does [m]. */
    double min_component_length_m = 5.0;
    /** ... and a shorter part of at least this much edge length when it is a room: a room
     * sealed off (a closed door, a crop, a break's cut) is a part of one edge, about its length
     * minus its width (2-4 m), where laser-fan and outside fragments are parts too (session 48,
     * doc/topology_graph.md). A value of min_component_length_m or more turns it off [m]. */
    double room_piece_min_length_m = 2.0;
    /** ... a room: at least this share of the obstacle cells nearest its skeleton are walls,
     * not unknown: mostly walls (a room's door open onto the unknown is a small share of them;
     * a laser fan is bounded by the unknown). Measured: rooms 0.51-1.0 (0.51: a room a crop cut
     * open, walls on three sides), the Radish maps' laser-fan pieces 0-0.31 [ratio]. */
    double room_piece_min_wall_share = 0.5;
    /** Vertices joined by an edge shorter than this are merged into one vertex at their mean
     * position (paper II-B, last step) [m]. */
    double join_distance_m = 0.60;
    /** An edge's direction at a vertex is measured from the path point at a quarter of this
     * distance to the point at this distance (capped at a quarter and half of the edge) [m]. */
    double edge_direction_distance_m = 2.00;

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
    /** \throws InputError naming the section, field and value, e.g.
     * "[GraphBuilder] min_clearance_m = -1 violates min_clearance_m > 0". */
    void validate() const;
};

/** What happened while building, for summaries and benchmarks. */
struct GraphBuildStats
{
    std::size_t islands_removed = 0;         //!< Free-standing obstacles below min_island_size_m.
    std::size_t unknown_regions_filled = 0;  //!< Enclosed unknown regions made free.
    /** Cells the cleaning steps ran on: the known cells' bounding box with a margin of unknown
     * cells, or the whole grid when that box is over 90 % of it. */
    std::size_t work_cells = 0;
    std::size_t sites = 0;               //!< Obstacle cells used as Voronoi sites.
    std::size_t voronoi_vertices = 0;    //!< Voronoi vertices inside the grid (after merging).
    std::size_t voronoi_edges = 0;       //!< Voronoi edges inside the grid.
    std::size_t voronoi_edges_kept = 0;  //!< ... with enough clearance.
    std::size_t vertices_initial = 0;    //!< Topology Graph before pruning.
    std::size_t vertices_after_prune = 0;
    std::size_t vertices_after_alpha = 0;
    std::size_t vertices_after_component = 0;
    std::size_t vertices_final = 0;
    std::size_t alpha_polygon_segments = 0;
    /** Milliseconds per step, keyed by step name; "total" is the whole call. */
    std::map<std::string, double> timing_ms;
};

/** Called after each construction step with the graph as it stands then (attributes computed,
 * numbering canonical), to draw or inspect the steps. Step names, in order: "voronoi" (the
 * clearance-filtered Voronoi diagram with degree-2 chains merged), "pruned", "alpha_cut",
 * "largest_component", "joined" (the final graph). */
using GraphBuildObserver = std::function<void(const std::string& step, const TopologyGraph&)>;

/** Builds the Topology Graph of a grid map (paper II-B and II-C): Voronoi diagram of the
 * obstacle cells, clearance filter, degree-2 chains merged into edges, short dead ends pruned,
 * cut to the outer alpha shape, connected parts of a useful size (the paper: the largest
 * only), close vertices joined, attributes.
 *
 * Deterministic: the same grid and parameters give the same graph, with vertices numbered by
 * position. A map with no obstacles or no free space gives an empty graph and a warning; a
 * graph that is a pure cycle (no vertex of degree != 2) gives one degree-2 vertex on a loop
 * edge (see doc/topology_graph.md).
 * \throws InputError if `params.validate()` fails. */
TopologyGraph buildTopologyGraph(const mrpt::maps::COccupancyGridMap2D& grid,
                                 const GraphBuilderParameters& params = {},
                                 GraphBuildStats* stats = nullptr,
                                 const GraphBuildObserver& observer = {});

}  // namespace mrpt_topoeval
