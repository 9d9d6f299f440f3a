/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// Real maps for the validation corpus, from ../shared/data when present (doc/validation.md):
// real ground truths to make variants of, and real (ground truth, robot map) pairs whose truth
// was established without the matcher.

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <functional>
#include <string>
#include <vector>

#include "truth.h"

namespace mrpt_topoeval::validation
{
/** A real map used as a ground truth for generated variants. */
struct RealBuilding
{
    std::string name;    //!< e.g. "radish_intel", "floorplan_office_a", "gazebo_office".
    std::string family;  //!< "radish", "floorplan", "gh25", "house", "gazebo", "halmstad".
    std::string file;    //!< Path it was read from.
    mrpt::maps::COccupancyGridMap2D grid;
};

/** A real ground truth and a real robot (or furnished) map of the same place, with the truth. */
struct RealPair
{
    std::string name;  //!< e.g. "gh25_vs_icp_slam", "gazebo_gmapping", "halmstad_HIH_01".
    std::string family;
    std::string gt_file, map_file;
    mrpt::maps::COccupancyGridMap2D gt, map;
    Truth truth;
};

/** Every real map of `data_dir` (../shared/data) usable as a ground truth; empty if the folder
 * is absent. Maps that cannot be read are skipped with a line in `skipped`. */
std::vector<RealBuilding> loadRealBuildings(const std::string& data_dir,
                                            std::vector<std::string>* skipped = nullptr);

/** Every real pair of `data_dir` whose truth can be established; empty if absent. A pair whose
 * map is made at run time (ICP-SLAM of a rawlog, seconds each) only when `wanted(NAME)` (none:
 * all). */
std::vector<RealPair> loadRealPairs(
    const std::string& data_dir, std::vector<std::string>* skipped = nullptr,
    const std::function<bool(const std::string&)>& wanted = nullptr);
}  // namespace mrpt_topoeval::validation
