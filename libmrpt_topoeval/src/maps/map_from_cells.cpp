/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// mapFromCells(): maps held in memory (numpy arrays, ROS OccupancyGrid messages), with the
// checks and messages of the file readers.

#include <mrpt_topoeval/maps/load_map.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "maps/image_map.h"
#include "maps/map_formats.h"

namespace mrpt_topoeval
{
namespace
{
using map_formats::fail;
using map_formats::num;

std::string cellName(std::size_t row, std::size_t col, double v)
{
    return "cell (row " + std::to_string(row) + ", column " + std::to_string(col) + ") = " + num(v);
}
}  // namespace

LoadedMap mapFromCells(const std::vector<double>& cells, std::size_t width, std::size_t height,
                       double resolution_m, double origin_x_m, double origin_y_m,
                       CellEncoding encoding, const MapLoadOptions& opts, const std::string& name)
{
    if (width == 0 || height == 0)
        fail(name,
             "a " + std::to_string(height) + " x " + std::to_string(width) + " array has no cells");
    // Overflow-safe: width * height may not fit when both are absurd.
    if (static_cast<double>(width) * static_cast<double>(height) >
        static_cast<double>(opts.max_cells))
        fail(name, std::to_string(width) + " x " + std::to_string(height) +
                       " cells, over max_cells = " + std::to_string(opts.max_cells));
    if (cells.size() != width * height)
        fail(name, std::to_string(cells.size()) + " values for " + std::to_string(width) + " x " +
                       std::to_string(height) + " cells");
    if (!(std::isfinite(resolution_m) && resolution_m > 0.0))
        fail(name, "resolution_m = " + num(resolution_m) + " violates resolution_m > 0");
    if (!std::isfinite(origin_x_m) || !std::isfinite(origin_y_m))
        fail(name, "origin (" + num(origin_x_m) + ", " + num(origin_y_m) + ") is not finite");

    LoadedMap out;
    out.file = name;
    out.format = "array";
    map_formats::allocateGrid(out.grid, width, height, resolution_m, origin_x_m, origin_y_m, name);
    using Grid = mrpt::maps::COccupancyGridMap2D;
    for (std::size_t row = 0; row < height; ++row)
    {
        Grid::cellType* dst = out.grid.getRow(static_cast<int>(row));
        for (std::size_t col = 0; col < width; ++col)
        {
            const double v = cells[row * width + col];
            double p_free = 0.5;
            if (encoding == CellEncoding::OccupancyProbability)
            {
                if (std::isnan(v))
                    p_free = 0.5;
                else if (v >= 0.0 && v <= 1.0)
                    p_free = 1.0 - v;
                else
                    fail(name, cellName(row, col, v) +
                                   " violates 0 <= occupancy probability <= 1 (NaN = unknown)");
            }
            else
            {
                // -1 and 0..100 only, whole numbers, as nav_msgs/OccupancyGrid holds int8.
                if (!(v == -1.0 || (v >= 0.0 && v <= 100.0 && v == std::floor(v))))
                    fail(name, cellName(row, col, v) +
                                   " is not an OccupancyGrid value (-1 unknown, 0..100)");
                const double p_occ = v / 100.0;
                if (v == -1.0)
                    p_free = 0.5;
                else if (p_occ > opts.occupied_thresh)
                    p_free = 0.0;
                else if (p_occ < opts.free_thresh)
                    p_free = 1.0;
            }
            dst[col] = Grid::p2l(static_cast<float>(p_free));
        }
    }
    map_formats::markAsLoaded(out.grid);
    return out;
}

}  // namespace mrpt_topoeval
