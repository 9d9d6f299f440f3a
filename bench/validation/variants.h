/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// Variants of a ground-truth grid with their truth (doc/validation.md, "Variants"): rigid moves,
// resampling, noise, crops, breaks, furniture. Each is made by construction, so the mapping of
// every point of the variant into the ground truth is exact.

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cstdint>
#include <string>
#include <vector>

#include "truth.h"

namespace mrpt_topoeval::validation
{
/** A map made from a ground truth, and how it relates to it. */
struct Variant
{
    mrpt::maps::COccupancyGridMap2D map;
    Truth truth;
};

/** One rigid piece of a piecewise-rigid warp: the ground-truth points for which `contains`
 * holds are moved by `gt_to_map`. */
struct WarpPart
{
    Rigid2D gt_to_map;
    std::function<bool(const Eigen::Vector2d& p_gt)> contains;
};

/** Moves each part of `src` rigidly into a new grid of `resolution_m` (0 = the source's).
 * Where parts overlap obstacles win; cells no part covers are unknown. When coarsening, a cell
 * is occupied if any of k x k points of its footprint is. The truth maps every map point back
 * through the part whose preimage contains it. */
Variant warpGrid(const mrpt::maps::COccupancyGridMap2D& src, const std::vector<WarpPart>& parts,
                 double resolution_m = 0.0);

/** The same map, cell for cell. */
Variant makeIdentical(const mrpt::maps::COccupancyGridMap2D& gt);

/** Rotated by `yaw_rad` about the origin and shifted by `shift_m` (a rigid move). */
Variant makeRigid(const mrpt::maps::COccupancyGridMap2D& gt, double yaw_rad,
                  const Eigen::Vector2d& shift_m);

/** Resampled to `resolution_m` in place (same world frame). */
Variant makeResampled(const mrpt::maps::COccupancyGridMap2D& gt, double resolution_m);

/** A rigid move (`yaw_rad`, `shift_m`) of a map whose scale is off by `scale`: every world
 * point of the moved map multiplied by it, as a floor plan drawn with a wrong resolution or a
 * map whose odometry misjudged distances (the same cells, a cell `scale` times as wide). */
Variant makeScaled(const mrpt::maps::COccupancyGridMap2D& gt, double scale, double yaw_rad,
                   const Eigen::Vector2d& shift_m);

/** Obstacle speckles: `wall_fraction` of the cells on wall borders flipped (as
 * tests/support's addSpeckleNoise), plus isolated obstacle specks of 1-2 cells in open free
 * space, `specks_per_m2` of free area (clutter, left out of the truth check). */
Variant makeSpeckled(const mrpt::maps::COccupancyGridMap2D& gt, double wall_fraction,
                     double specks_per_m2, std::uint32_t seed);

/** Gaps of one cell cut through walls at `gaps_per_m` of wall border length (sensor dropouts,
 * thin walls seen at a glancing angle). */
Variant makeWallGaps(const mrpt::maps::COccupancyGridMap2D& gt, double gaps_per_m,
                     std::uint32_t seed);

/** Ragged walls: wall borders moved in or out by up to `amplitude_cells` cells along a smooth
 * random field of wavelength ~1 m (rotation and resampling artefacts, laser noise). Walls are
 * never cut through. */
Variant makeRagged(const mrpt::maps::COccupancyGridMap2D& gt, int amplitude_cells,
                   std::uint32_t seed);

/** The part of the map inside a rectangle holding `keep_share` of the known cells, at a seeded
 * side of the building; the rest is not in the map at all (a partial exploration). */
Variant makeCrop(const mrpt::maps::COccupancyGridMap2D& gt, double keep_share, std::uint32_t seed);

/** Broken `breaks` times (paper IV, brokenness; 1-3), like a SLAM run that turned wrong in
 * `breaks` places: the building is cut into breaks + 1 compact parts of equal known area
 * (halves; a third and two sixths; quadrants, across a seeded direction); part 0 stays, each
 * other part is turned 10-30 degrees (seeded sign, at least 10 degrees from every other part)
 * about a pivot on free space of its border. The whole map is then moved rigidly by a seeded
 * yaw and shift. part_yaw_deg per part.
 * `chained` false (the standard corpus): each part is turned about a point of its border with
 * any other part, independently of the others, so two turned neighbours are moved apart at
 * their common cut. true (`topoeval_validate --chained-breaks`): the parts are visited in a
 * chain of neighbours (0, 1, 2; quadrants 0, 1, 3, 2), each turned 10-30 degrees against the
 * previous one about a point of their common border and carried with it, as a SLAM map's error
 * at a place is carried into everything mapped after it. With one break both are the same. */
Variant makeBroken(const mrpt::maps::COccupancyGridMap2D& gt, int breaks, std::uint32_t seed,
                   bool chained = false);

/** Furniture: desks, shelves and leg groups of tables and chairs placed in free space with at
 * least 0.5 m clearance (so no passage is closed), about `items_per_m2` of free area
 * (clutter, left out of the truth check). */
Variant makeFurnished(const mrpt::maps::COccupancyGridMap2D& gt, double items_per_m2,
                      std::uint32_t seed);

/** A random rigid move for a seed: yaw at least 8 degrees from every multiple of 90. */
Rigid2D randomRigid(std::uint32_t seed, double max_shift_m = 10.0);
}  // namespace mrpt_topoeval::validation
