/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt_topoeval/GraphMatcher.h>
#include <mrpt_topoeval/errors.h>

#include <cmath>
#include <sstream>

#include "internal/validation.h"

namespace mrpt_topoeval
{
void GraphMatcherParameters::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                                const std::string& s)
{
    MRPT_LOAD_CONFIG_VAR(edge_length_factor, double, c, s);
    MRPT_LOAD_CONFIG_VAR(edge_length_allowance_m, double, c, s);
    MRPT_LOAD_CONFIG_VAR(max_angle_difference_deg, double, c, s);
    MRPT_LOAD_CONFIG_VAR(min_isomorphism_similarity, double, c, s);
    MRPT_LOAD_CONFIG_VAR(min_isomorphism_vertices, int, c, s);
    MRPT_LOAD_CONFIG_VAR(min_isomorphism_share, double, c, s);
    MRPT_LOAD_CONFIG_VAR(max_branches_per_seed, int, c, s);
    MRPT_LOAD_CONFIG_VAR(neighbour_growing, bool, c, s);
    MRPT_LOAD_CONFIG_VAR(min_growing_similarity, double, c, s);
    MRPT_LOAD_CONFIG_VAR(growing_edge_length_factor, double, c, s);
    MRPT_LOAD_CONFIG_VAR(growing_edge_length_allowance_m, double, c, s);
}

void GraphMatcherParameters::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                              const std::string& s) const
{
    MRPT_SAVE_CONFIG_VAR_COMMENT(edge_length_factor,
                                 "[ratio] matched edges agree in length within factor x length");
    MRPT_SAVE_CONFIG_VAR_COMMENT(edge_length_allowance_m, "[m] ... plus this allowance");
    MRPT_SAVE_CONFIG_VAR_COMMENT(max_angle_difference_deg,
                                 "[deg] largest difference of matched edges' ring angles");
    MRPT_SAVE_CONFIG_VAR_COMMENT(min_isomorphism_similarity,
                                 "[0..1] pairs less similar are never assigned by isomorphism");
    MRPT_SAVE_CONFIG_VAR_COMMENT(min_isomorphism_vertices, "[1] smallest isomorphism accepted");
    MRPT_SAVE_CONFIG_VAR_COMMENT(min_isomorphism_share,
                                 "[ratio] ... or this share of the smaller graph (at least 3)");
    MRPT_SAVE_CONFIG_VAR_COMMENT(max_branches_per_seed,
                                 "[1] wavefront branches explored per seed (bounds recursion)");
    MRPT_SAVE_CONFIG_VAR_COMMENT(neighbour_growing, "[bool] extend the match by neighbour growing");
    MRPT_SAVE_CONFIG_VAR_COMMENT(min_growing_similarity,
                                 "[0..1] neighbour growing assigns pairs at least this similar");
    MRPT_SAVE_CONFIG_VAR_COMMENT(growing_edge_length_factor,
                                 "[ratio] neighbour growing's relaxed edge-length factor");
    MRPT_SAVE_CONFIG_VAR_COMMENT(growing_edge_length_allowance_m,
                                 "[m] neighbour growing's relaxed edge-length allowance");
}

void GraphMatcherParameters::validate() const
{
    internal::require(internal::isNonNegative(edge_length_factor), "edge_length_factor",
                      edge_length_factor, "edge_length_factor >= 0");
    internal::require(internal::isNonNegative(edge_length_allowance_m), "edge_length_allowance_m",
                      edge_length_allowance_m, "edge_length_allowance_m >= 0");
    internal::require(std::isfinite(max_angle_difference_deg) && max_angle_difference_deg > 0.0 &&
                          max_angle_difference_deg <= 180.0,
                      "max_angle_difference_deg", max_angle_difference_deg,
                      "0 < max_angle_difference_deg <= 180");
    internal::require(internal::isUnit(min_isomorphism_similarity), "min_isomorphism_similarity",
                      min_isomorphism_similarity, "0 <= min_isomorphism_similarity <= 1");
    internal::require(min_isomorphism_vertices >= 1, "min_isomorphism_vertices",
                      min_isomorphism_vertices, "min_isomorphism_vertices >= 1");
    internal::require(std::isfinite(min_isomorphism_share) && min_isomorphism_share > 0.0 &&
                          min_isomorphism_share <= 1.0,
                      "min_isomorphism_share", min_isomorphism_share,
                      "0 < min_isomorphism_share <= 1");
    internal::require(max_branches_per_seed >= 1, "max_branches_per_seed", max_branches_per_seed,
                      "max_branches_per_seed >= 1");
    internal::require(internal::isUnit(min_growing_similarity), "min_growing_similarity",
                      min_growing_similarity, "0 <= min_growing_similarity <= 1");
    internal::require(internal::isNonNegative(growing_edge_length_factor),
                      "growing_edge_length_factor", growing_edge_length_factor,
                      "growing_edge_length_factor >= 0");
    internal::require(internal::isNonNegative(growing_edge_length_allowance_m),
                      "growing_edge_length_allowance_m", growing_edge_length_allowance_m,
                      "growing_edge_length_allowance_m >= 0");
}

}  // namespace mrpt_topoeval
