/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt/config/CLoadableOptions.h>

#include <cstdint>
#include <string>

namespace mrpt_topoeval
{
/** How to read map files whose format does not carry everything (plain images), INI section
 * `[MapLoad]` (the command line's --resolution overrides resolution_m). */
struct MapLoadOptions : public mrpt::config::CLoadableOptions
{
    /** The INI section of these keys, named by validate() in its messages. */
    static constexpr const char* kIniSection = "MapLoad";

    /** Cell size for plain images and for rendering `.simplemap` files [m/cell]. */
    double resolution_m = 0.05;
    /** Plain images only: a pixel is occupied when (255 - grey)/255 > this (ROS default). */
    double occupied_thresh = 0.65;
    /** Plain images only: a pixel is free when (255 - grey)/255 < this (ROS default). */
    double free_thresh = 0.196;
    /** Pixels between the thresholds of an image without an explicit ROS `mode` (ROS
     * trinary: unknown). "auto" (default): keep their probability when the image holds more
     * than 4 distinct grey levels between the thresholds, as probabilistic renderings do
     * (MRPT's: unknown is 127, a cell seen free a few times is 150-200 grey, below ROS's
     * free_thresh 0.196), so that the [GraphBuilder] thresholds classify them; else unknown,
     * as in a ROS trinary image (one unknown grey, 205). "unknown" or "probability" force
     * one reading. */
    std::string grey_between_thresholds = "auto";
    /** The grey ROS map_saver writes for unknown cells (205: (255 - 205) / 255 = 0.196). A
     * ROS YAML in trinary mode whose free_thresh is above that reads it as free: nav2 Humble's
     * map_saver wrote free_thresh 0.25 (fixed in navigation2 PR #5278), and every unknown cell
     * of such a map, the whole outside of the building, became free space. When a trinary
     * map's image holds only map_saver's greys (0, this, 254, and 255), this grey is read as
     * unknown whatever the thresholds say, with a note. -1 = off: the thresholds decide, as in
     * map_server. */
    int trinary_unknown_grey = 205;
    /** Largest map accepted, in cells (width x height). Image headers are checked against it
     * before any pixel is decoded. Default 10^8 cells (10000 x 10000). */
    std::uint64_t max_cells = 100'000'000ULL;

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
    /** \throws InputError naming the section, field and value, e.g.
     * "[MapLoad] resolution_m = -1 violates resolution_m > 0". */
    void validate() const;
};

}  // namespace mrpt_topoeval
