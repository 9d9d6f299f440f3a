/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Grid maps built in code whose Topology Graph is known, and perturbations of maps (rotation,
// shift, resampling, speckle noise) for tests and benchmarks.

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>
#include <cstdint>
#include <functional>

namespace mrpt_topoeval::testing
{
/** A canvas in metres: starts solid (all occupied); corridors and rooms are carved free. The
 * world frame has its origin at the lower-left corner. */
class GridSketch
{
public:
    GridSketch(double width_m, double height_m, double resolution_m = 0.05);

    /** Axis-aligned rectangle [x0,x1] x [y0,y1] set free. */
    GridSketch& carve(double x0, double y0, double x1, double y1);
    /** Axis-aligned rectangle set occupied (walls, pillars). */
    GridSketch& fill(double x0, double y0, double x1, double y1);
    /** Axis-aligned rectangle set unknown (P = 0.5). */
    GridSketch& unknown(double x0, double y0, double x1, double y1);

    const mrpt::maps::COccupancyGridMap2D& grid() const { return m_grid; }

private:
    void set(double x0, double y0, double x1, double y1, float p_free);
    mrpt::maps::COccupancyGridMap2D m_grid;
};

/** A floor of 44 m x 20 m: a corridor with six offices south of it, a hall north of it (1-21 m
 * x 8-13 m, its door at x 9-11 m) with three rooms off it, two offices east of the hall. A
 * sketch, so that a test adds its own furniture or columns before taking the grid. */
GridSketch hallBuildingSketch();

/** Corridors 1.5 m wide: a horizontal corridor 12 m long with a branch 5 m long from its middle.
 * Graph: one junction of degree 3 at (7, 6.75) and three dead ends. */
mrpt::maps::COccupancyGridMap2D makeTJunctionMap(double resolution_m = 0.05);

/** Two corridors 1.5 m wide crossing at (8, 8), arms 6 m long: one degree-4 vertex and four
 * dead ends. */
mrpt::maps::COccupancyGridMap2D makePlusMap(double resolution_m = 0.05);

/** Two 4 m x 4 m rooms joined by a 1 m wide door through a 0.2 m wall: two dead-end room
 * centres joined by one edge through the door (no junction). */
mrpt::maps::COccupancyGridMap2D makeTwoRoomsMap(double resolution_m = 0.05);

/** A square ring corridor 1.5 m wide around a 6 m x 6 m solid block: a pure cycle. */
mrpt::maps::COccupancyGridMap2D makeCorridorLoopMap(double resolution_m = 0.05);

/** The corridor loop with a 4 m dead-end corridor leaving one side: one junction of degree 3
 * with a loop edge back to itself and one dead-end edge. */
mrpt::maps::COccupancyGridMap2D makeLoopWithSpurMap(double resolution_m = 0.05);

/** An asymmetric office floor about 30 m x 20 m: a corridor loop, rooms of several sizes on
 * doors, dead-end corridors. Used where a richer graph is wanted (stability, matching). */
mrpt::maps::COccupancyGridMap2D makeOfficeMap(double resolution_m = 0.05);

/** A pinwheel floor 44 m x 44 m, symmetric under turns of 90 degrees about its centre
 * (22, 22) but for one room: a 6 m hall in the middle, four wings 14 m long (a corridor 2 m
 * wide, three rooms on one side and two on the other), and a marker room at the end of the east
 * wing only. Any part of it but the east wing's end fits four places of the whole. */
mrpt::maps::COccupancyGridMap2D makePinwheelMap(double resolution_m = 0.05);

/** `src` moved rigidly by (yaw about the map centre, then shift) and resampled on a grid of
 * `resolution_m` (0 keeps the source resolution). At the same resolution each target cell
 * takes the source cell under its centre; when coarsening, a target cell is occupied if any of
 * k x k points of its footprint is (as a map made at that resolution would show the same
 * walls), else it gets their mean P(free). */
mrpt::maps::COccupancyGridMap2D transformGrid(const mrpt::maps::COccupancyGridMap2D& src,
                                              double yaw_rad, const Eigen::Vector2d& shift_m,
                                              double resolution_m = 0.0);

/** Where transformGrid() puts a world point of `src` (for checking positions). */
Eigen::Vector2d transformPoint(const mrpt::maps::COccupancyGridMap2D& src, double yaw_rad,
                               const Eigen::Vector2d& shift_m, const Eigen::Vector2d& p);

/** A map broken once (paper IV, brokenness): the part of `src` where `in_part(x, y)` holds
 * (world coordinates of the source) is rotated by `yaw_rad` about `pivot`, the rest stays.
 * Where the moved part overlaps the rest, obstacles win; cells covered by neither are unknown. */
mrpt::maps::COccupancyGridMap2D breakMap(const mrpt::maps::COccupancyGridMap2D& src,
                                         const Eigen::Vector2d& pivot, double yaw_rad,
                                         const std::function<bool(double x, double y)>& in_part);

/** Where breakMap() puts a world point of `src`. */
Eigen::Vector2d breakPoint(const Eigen::Vector2d& pivot, double yaw_rad,
                           const std::function<bool(double x, double y)>& in_part,
                           const Eigen::Vector2d& p);

/** Flips a fraction of the free cells that touch an obstacle to occupied, and the same
 * fraction of those obstacle cells to free: light, seeded speckle on the walls. */
mrpt::maps::COccupancyGridMap2D addSpeckleNoise(const mrpt::maps::COccupancyGridMap2D& src,
                                                double fraction, std::uint32_t seed);

/** A big irregular floor, about 62 m x 38 m: corridors at uneven spacings form a network of
 * loops; every block between them is split into rooms of seeded random sizes, each with a door
 * at a random place on a corridor. Nothing repeats, so every part of it is recognisable (for
 * brokenness and coverage tests). Deterministic for a seed. */
mrpt::maps::COccupancyGridMap2D makeCampusMap(std::uint32_t seed = 1, double resolution_m = 0.05);

/** A large synthetic building for benchmarks: a lattice of rooms on corridors filling a grid
 * of `cells` x `cells`. */
mrpt::maps::COccupancyGridMap2D makeLargeBuilding(int cells, double resolution_m = 0.05);

}  // namespace mrpt_topoeval::testing
