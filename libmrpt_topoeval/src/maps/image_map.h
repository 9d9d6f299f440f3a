/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Images -> cells, shared by plain images (format_image.cpp) and ROS YAML maps.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/maps/load_map.h>

#include <cstdint>
#include <string>

#include "maps/image_header.h"

namespace mrpt_topoeval::map_formats
{
/** ROS map_server interpretation modes. */
enum class PixelMode
{
    Trinary,  //!< occupied / free / unknown only
    Scale,    //!< between the thresholds, keep the probability
    Raw       //!< P(free) = 1 - grey, no thresholds
};

/** How grey levels become cell probabilities (ROS map_server semantics). */
struct PixelRule
{
    double occupied_thresh = 0.65;
    double free_thresh = 0.196;
    bool negate = false;
    PixelMode mode = PixelMode::Trinary;
    /** Trinary without an explicit mode: switch to Scale when the image has many grey levels
     * between the thresholds (a probabilistic rendering). */
    bool detect_probabilistic = false;
    /** Trinary only, >= 0: the grey ROS map_saver writes for unknown cells. If the thresholds
     * make it free and the image holds no grey but 0, this, 254 and 255 (a map_saver image),
     * it is read as unknown (MapLoadOptions::trinary_unknown_grey says why). */
    int map_saver_unknown_grey = -1;
};

/** Sets `grid` to exactly `w` x `h` cells of `res` metres, lower-left corner at (x0, y0)
 * snapped to the cell grid (format_image.cpp says why); `prefix` starts every message. */
void allocateGrid(mrpt::maps::COccupancyGridMap2D& grid, std::uint64_t w, std::uint64_t h,
                  double res, double x0, double y0, const std::string& prefix);

/** Clears MRPT's "nothing inserted yet" flag after cells were written directly. */
void markAsLoaded(mrpt::maps::COccupancyGridMap2D& grid);

/** The rule for an image without an explicit ROS mode, from MapLoadOptions. */
void applyGreyOption(PixelRule& rule, const MapLoadOptions& opts, const std::string& path);

/** Decodes an image file whose header has already been checked, and fills `grid` with it,
 * lower-left pixel corner at (x0, y0). `prefix` starts every message. Returns notes on where
 * the image was read otherwise than the rule's literal meaning (see PixelRule). */
std::vector<std::string> imageToGrid(const std::string& image_path,
                                     const internal::ImageHeader& hdr, const PixelRule& rule_in,
                                     double res, double x0, double y0,
                                     mrpt::maps::COccupancyGridMap2D& grid,
                                     const std::string& prefix);

/** Reads and size-checks an image header; `prefix` replaces the image path at the start of
 * any message (used when the image is named by a YAML file). */
internal::ImageHeader checkedImageHeader(const std::string& image_path, const std::string& prefix,
                                         const MapLoadOptions& opts);

}  // namespace mrpt_topoeval::map_formats
