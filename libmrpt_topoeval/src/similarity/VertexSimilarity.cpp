/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Parameters of vertex similarity (paper III-A); the two approaches are in their own files.

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <cmath>
#include <sstream>

#include "common/validation.h"

namespace mrpt_topoeval
{
std::string toString(SimilarityMode m) { return m == SimilarityMode::Icp ? "icp" : "attributes"; }

SimilarityMode similarityModeFromString(const std::string& s)
{
    if (s == "attributes") return SimilarityMode::Attributes;
    if (s == "icp") return SimilarityMode::Icp;
    throw InputError("similarity mode '" + s + "' is not one of: attributes, icp");
}

void VertexSimilarityParameters::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                                    const std::string& s)
{
    mode = similarityModeFromString(c.read_string(s, "mode", toString(mode)));
    MRPT_LOAD_CONFIG_VAR(angle_tolerance_deg, double, c, s);
    MRPT_LOAD_CONFIG_VAR(length_tolerance, double, c, s);
    MRPT_LOAD_CONFIG_VAR(clearance_tolerance_m, double, c, s);
    MRPT_LOAD_CONFIG_VAR(weight_angles, double, c, s);
    MRPT_LOAD_CONFIG_VAR(weight_lengths, double, c, s);
    MRPT_LOAD_CONFIG_VAR(weight_vertex_clearance, double, c, s);
    MRPT_LOAD_CONFIG_VAR(weight_edge_clearance, double, c, s);
    MRPT_LOAD_CONFIG_VAR(degree_mismatch_factor, double, c, s);
    MRPT_LOAD_CONFIG_VAR(neighbour_weight, double, c, s);
    MRPT_LOAD_CONFIG_VAR(neighbour_iterations, int, c, s);
    MRPT_LOAD_CONFIG_VAR(icp_radius_m, double, c, s);
    MRPT_LOAD_CONFIG_VAR(icp_start_angles, int, c, s);
    MRPT_LOAD_CONFIG_VAR(icp_rmse_tolerance_m, double, c, s);
    MRPT_LOAD_CONFIG_VAR(icp_max_degree_difference, int, c, s);
    MRPT_LOAD_CONFIG_VAR(threads, int, c, s);
}

void VertexSimilarityParameters::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                                  const std::string& s) const
{
    const int np = mrpt::config::MRPT_SAVE_NAME_PADDING();
    const int vp = mrpt::config::MRPT_SAVE_VALUE_PADDING();
    c.write(s, "mode", toString(mode), np, vp,
            "[attributes|icp] how vertex similarity is computed (paper III-A)");
    MRPT_SAVE_CONFIG_VAR_COMMENT(angle_tolerance_deg,
                                 "[deg] mean ring-angle difference where the angle term is 0");
    MRPT_SAVE_CONFIG_VAR_COMMENT(length_tolerance,
                                 "[ratio] relative edge-length difference where that term is 0");
    MRPT_SAVE_CONFIG_VAR_COMMENT(clearance_tolerance_m,
                                 "[m] clearance difference where the clearance terms are 0");
    MRPT_SAVE_CONFIG_VAR_COMMENT(weight_angles, "[1] weight of the ring-angle term");
    MRPT_SAVE_CONFIG_VAR_COMMENT(weight_lengths, "[1] weight of the edge-length term");
    MRPT_SAVE_CONFIG_VAR_COMMENT(weight_vertex_clearance, "[1] weight of the vertex clearance");
    MRPT_SAVE_CONFIG_VAR_COMMENT(weight_edge_clearance, "[1] weight of the edges' clearance");
    MRPT_SAVE_CONFIG_VAR_COMMENT(degree_mismatch_factor,
                                 "[ratio] similarity factor per unit of degree difference");
    MRPT_SAVE_CONFIG_VAR_COMMENT(neighbour_weight,
                                 "[ratio] weight of the neighbours' similarity; 0 = off");
    MRPT_SAVE_CONFIG_VAR_COMMENT(neighbour_iterations, "[1] neighbour refinement rounds");
    MRPT_SAVE_CONFIG_VAR_COMMENT(icp_radius_m,
                                 "[m] obstacles within this of a vertex form its cloud");
    MRPT_SAVE_CONFIG_VAR_COMMENT(icp_start_angles,
                                 "[1] ICP start angles when edges give none (paper: 12)");
    MRPT_SAVE_CONFIG_VAR_COMMENT(icp_rmse_tolerance_m,
                                 "[m] ICP alignment RMS error where the similarity is 0");
    MRPT_SAVE_CONFIG_VAR_COMMENT(icp_max_degree_difference,
                                 "[1] ICP only for pairs whose degrees differ by at most this");
    MRPT_SAVE_CONFIG_VAR_COMMENT(threads, "[1] ICP worker threads; 0 = all cores");
}

void VertexSimilarityParameters::validate() const
{
    const auto pos = internal::isPositive;
    internal::require(pos(angle_tolerance_deg), "angle_tolerance_deg", angle_tolerance_deg,
                      "angle_tolerance_deg > 0");
    internal::require(pos(length_tolerance), "length_tolerance", length_tolerance,
                      "length_tolerance > 0");
    internal::require(pos(clearance_tolerance_m), "clearance_tolerance_m", clearance_tolerance_m,
                      "clearance_tolerance_m > 0");
    internal::require(internal::isNonNegative(weight_angles), "weight_angles", weight_angles,
                      "weight_angles >= 0");
    internal::require(internal::isNonNegative(weight_lengths), "weight_lengths", weight_lengths,
                      "weight_lengths >= 0");
    internal::require(internal::isNonNegative(weight_vertex_clearance), "weight_vertex_clearance",
                      weight_vertex_clearance, "weight_vertex_clearance >= 0");
    internal::require(internal::isNonNegative(weight_edge_clearance), "weight_edge_clearance",
                      weight_edge_clearance, "weight_edge_clearance >= 0");
    internal::require(
        weight_angles + weight_lengths + weight_vertex_clearance + weight_edge_clearance > 0,
        "weight_angles", weight_angles, "at least one weight > 0");
    internal::require(std::isfinite(degree_mismatch_factor) && degree_mismatch_factor >= 0.0 &&
                          degree_mismatch_factor <= 1.0,
                      "degree_mismatch_factor", degree_mismatch_factor,
                      "0 <= degree_mismatch_factor <= 1");
    internal::require(
        std::isfinite(neighbour_weight) && neighbour_weight >= 0.0 && neighbour_weight < 1.0,
        "neighbour_weight", neighbour_weight, "0 <= neighbour_weight < 1");
    internal::require(neighbour_iterations >= 0 && neighbour_iterations <= 10,
                      "neighbour_iterations", neighbour_iterations,
                      "0 <= neighbour_iterations <= 10");
    internal::require(pos(icp_radius_m), "icp_radius_m", icp_radius_m, "icp_radius_m > 0");
    internal::require(icp_start_angles >= 1 && icp_start_angles <= 72, "icp_start_angles",
                      icp_start_angles, "1 <= icp_start_angles <= 72");
    internal::require(pos(icp_rmse_tolerance_m), "icp_rmse_tolerance_m", icp_rmse_tolerance_m,
                      "icp_rmse_tolerance_m > 0");
    internal::require(icp_max_degree_difference >= 0, "icp_max_degree_difference",
                      icp_max_degree_difference, "icp_max_degree_difference >= 0");
    internal::require(threads >= 0 && threads <= 256, "threads", threads, "0 <= threads <= 256");
}

}  // namespace mrpt_topoeval
