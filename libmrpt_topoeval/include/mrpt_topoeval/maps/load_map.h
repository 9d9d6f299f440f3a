/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/maps/MapLoadOptions.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mrpt_topoeval
{
/** A grid map and where it came from. */
struct LoadedMap
{
    mrpt::maps::COccupancyGridMap2D grid;
    std::string file;    //!< The path as given.
    std::string format;  //!< "ros_yaml", "image", "gridmap" or "simplemap".
    /** Where the file was read otherwise than its literal meaning, and why (e.g. a ROS map
     * whose free_thresh would make its unknown cells free). Empty for most maps. */
    std::vector<std::string> notes;
};

/** The map file formats loadMap() reads. */
enum class MapFormat
{
    RosYaml,    //!< `*.yaml`, `*.yml`: ROS map_server description and its image
    Image,      //!< `*.png|*.pgm|*.bmp|*.jpg|*.jpeg`: a plain image
    Gridmap,    //!< `*.gridmap`, `*.gridmap.gz`: MRPT serialized COccupancyGridMap2D
    Simplemap,  //!< `*.simplemap`, `*.simplemap.gz`: MRPT CSimpleMap, rendered
};

/** The format loadMap() reads `path` as, from its file name (any case); nullopt if none. */
std::optional<MapFormat> mapFormatFromName(const std::string& path);

/** Whether `path` names a map file loadMap() can read, by its name only (`a.yaml`, not a bare
 * `.yaml`): how `topoeval series` picks the maps of a folder. */
bool isMapFile(const std::string& path);

/** Reads any supported map file into a `COccupancyGridMap2D`; the one loader every app uses.
 *
 * Formats, chosen by file name:
 * - `*.yaml` / `*.yml`: ROS map_server description (image, resolution, origin, negate,
 *   occupied_thresh, free_thresh, optional mode trinary|scale|raw). Cells become occupied
 *   (P(free)=0), free (1) or unknown (0.5); in `scale` mode cells between the thresholds keep
 *   their probability. The origin's x, y are honoured (snapped to the cell grid by MRPT); a
 *   non-zero yaw is refused, as MRPT grids are axis aligned.
 * - `*.png|*.pgm|*.bmp|*.jpg|*.jpeg`: a plain image, top row = max y, lower-left pixel at the
 *   world origin, grey classified with `opts` thresholds.
 * - `*.gridmap`, `*.gridmap.gz`: an MRPT serialized `COccupancyGridMap2D`.
 * - `*.simplemap`, `*.simplemap.gz`: an MRPT `CSimpleMap`, rendered into a grid of
 *   `opts.resolution_m`.
 *
 * \throws InputError with a one-line message naming the file and the problem (missing file,
 *         unreadable or truncated image, missing or invalid YAML key, a size over
 *         `opts.max_cells`, wrong serialized class, ...). Never crashes on bad bytes. */
LoadedMap loadMap(const std::string& path, const MapLoadOptions& opts = {});

/** How mapFromCells() reads its values. */
enum class CellEncoding
{
    /** P(occupied) in [0, 1] per cell, NaN = unknown; kept as probabilities (the
     * [GraphBuilder] thresholds classify them, as for a ROS `scale` image). */
    OccupancyProbability,
    /** nav_msgs/OccupancyGrid values: -1 unknown, 0..100 percent occupied, classified with
     * `occupied_thresh` / `free_thresh` of MapLoadOptions as map_server's trinary mode does
     * (occupied above, free below, unknown between). */
    RosOccupancyGrid,
};

/** A map from cell values held in memory (a numpy array, a ROS OccupancyGrid message): the
 * loader for maps that are not files.
 *
 * `cells` is row-major, `width` values per row, row 0 at the lowest y (OccupancyGrid order);
 * the lower-left corner of cell (0, 0) is at (`origin_x_m`, `origin_y_m`), snapped to the cell
 * grid as the file readers snap a ROS origin. `name` becomes LoadedMap::file and starts every
 * message; the format is "array".
 * \throws InputError naming `name` and the problem: no cells, `cells.size()` not
 *         width x height, over `opts.max_cells`, resolution not > 0, origin not finite, or a
 *         value out of range (with its row, column and value). */
LoadedMap mapFromCells(const std::vector<double>& cells, std::size_t width, std::size_t height,
                       double resolution_m, double origin_x_m, double origin_y_m,
                       CellEncoding encoding, const MapLoadOptions& opts, const std::string& name);

}  // namespace mrpt_topoeval
