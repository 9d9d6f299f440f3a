/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// Procedural buildings for the validation corpus (doc/validation.md): styles that differ from the
// test maps the code was developed on (tests/support/synthetic_maps.h), deterministic per seed.

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace mrpt_topoeval::validation
{
/** A generated building: its grid (walls occupied, inside free, outside occupied or unknown)
 * and a robot's tour through it. */
struct Building
{
    std::string name;   //!< "<style>_<seed>", e.g. "corridor_office_3".
    std::string style;  //!< One of buildingStyles() or heldOutStyles().
    std::uint32_t seed = 0;
    mrpt::maps::COccupancyGridMap2D grid;
    /** Waypoints of a tour that enters every room and hall [m, world frame]: consecutive
     * waypoints are joined by straight segments that keep >= 0.3 m from every obstacle, so a
     * simulated robot can drive it. The tour returns to its start (loop closures). */
    std::vector<Eigen::Vector2d> tour;
};

/** The styles, in a fixed order: "corridor_office", "column_hall", "angled", "multi_wing". */
std::vector<std::string> buildingStyles();

/** Styles held out of the standard corpus (`topoeval_validate --styles`): "ring" (a rotunda),
 * "warehouse" (rack aisles), "house" (a home of 10-25 m). The matcher was never tuned on them,
 * so they measure how it generalises to a building type it has not seen (doc/validation.md,
 * "Session 36"). */
std::vector<std::string> heldOutStyles();

/** buildingStyles(), then heldOutStyles(): every style makeBuilding() builds. */
std::vector<std::string> allStyles();

/** Builds one building of `style` (one of allStyles()) from `seed` at
 * `resolution_m`. Same inputs, same grid (bit for bit). \throws std::invalid_argument on an
 * unknown style. */
Building makeBuilding(const std::string& style, std::uint32_t seed, double resolution_m = 0.05);
}  // namespace mrpt_topoeval::validation
