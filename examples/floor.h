/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// A small floor built in memory for the examples: corridors around two blocks of rooms, as a
// robot's grid map would hold it (occupied walls, free corridors, unknown outside).

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cmath>

namespace examples
{
/** The floor, 24 m x 14 m at 0.05 m/cell; `shift_m` moves it (a map in a different frame),
 * `visible_x_m` hides what lies beyond that x (a map explored so far). */
inline mrpt::maps::COccupancyGridMap2D floor(double shift_m = 0.0, double visible_x_m = 1e9)
{
    mrpt::maps::COccupancyGridMap2D g;
    const float s = static_cast<float>(shift_m);
    g.setSize(-1.0f + s, 25.0f + s, -1.0f + s, 15.0f + s, 0.05f, 0.5f);
    for (unsigned cy = 0; cy < g.getSizeY(); ++cy)
        for (unsigned cx = 0; cx < g.getSizeX(); ++cx)
        {
            const double x = g.idx2x(cx) - shift_m, y = g.idx2y(cy) - shift_m;
            if (x > visible_x_m) continue;
            const bool inside = x > 0 && x < 24 && y > 0 && y < 14;
            // Free: a 2 m corridor along the outline and across the middle.
            const bool corridor = inside && (x < 2 || x > 22 || y < 2 || y > 12 ||
                                             (x > 11 && x < 13) || (y > 6 && y < 8 && x < 11));
            const bool wall = !corridor && std::abs(x - 12) < 14 && std::abs(y - 7) < 9;
            if (corridor)
                g.setCell(static_cast<int>(cx), static_cast<int>(cy), 1.0f);
            else if (wall && (x < 0.3 || x > 23.7 || y < 0.3 || y > 13.7 || inside))
                g.setCell(static_cast<int>(cx), static_cast<int>(cy), 0.0f);
        }
    return g;
}
}  // namespace examples
