/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt_topoeval/TopologyGraph.h>

#include <Eigen/Core>
#include <map>
#include <string>

namespace mrpt::maps
{
// Only references to grids here: the full class (a heavy header) where a grid is made or read.
class COccupancyGridMap2D;
}  // namespace mrpt::maps

namespace mrpt_topoeval
{
/** How vertex similarity is computed (paper III-A): from the graph's attributes, or by ICP
 * on the obstacles around each vertex. */
enum class SimilarityMode
{
    Attributes,
    Icp
};

/** "attributes" / "icp". */
std::string toString(SimilarityMode m);
/** Parses "attributes" / "icp". \throws InputError naming the value. */
SimilarityMode similarityModeFromString(const std::string& s);

/** Parameters of vertex similarity, INI section `[VertexSimilarity]`. Each attribute term is a
 * ramp: 1 when the two values agree, falling linearly to 0 at its tolerance. */
struct VertexSimilarityParameters : public mrpt::config::CLoadableOptions
{
    /** The INI section of these keys, named by validate() in its messages. */
    static constexpr const char* kIniSection = "VertexSimilarity";

    SimilarityMode mode = SimilarityMode::Attributes;

    // --- attributes (paper III-A, first approach)
    /** Mean difference of the ring's angles (after the best cyclic alignment) at which the
     * angle term reaches 0 [deg]. */
    double angle_tolerance_deg = 45.0;
    /** Relative difference of aligned edge lengths, |la - lb| / max(la, lb), at which the
     * length term reaches 0 [ratio]. */
    double length_tolerance = 0.5;
    /** Difference of vertex clearance, and of aligned edges' mean clearance, at which the
     * clearance terms reach 0 [m]. */
    double clearance_tolerance_m = 0.5;
    /** Weights of the terms in the weighted mean [1]. */
    double weight_angles = 1.0;
    double weight_lengths = 1.0;
    double weight_vertex_clearance = 0.5;
    double weight_edge_clearance = 0.5;
    /** Each unit of degree difference multiplies the similarity by this [ratio]. */
    double degree_mismatch_factor = 0.5;
    /** Refinement by the neighbours (paper III-A, last paragraph): s' = (1 - w) s + w * mean
     * similarity of the aligned neighbours; 0 disables [ratio]. */
    double neighbour_weight = 0.3;
    /** How many refinement rounds [1]. */
    int neighbour_iterations = 1;

    // --- ICP (paper III-A, second approach; mrpt::slam::CICP)
    /** Obstacle cells within max(this, the vertex's clearance + this / 3) of a vertex form its
     * point cloud (a vertex in a room wider than this still sees its walls) [m]. */
    double icp_radius_m = 3.0;
    /** Start angles when the vertices' edges give none (paper: 12) [1]. */
    int icp_start_angles = 12;
    /** Alignment error at which the ICP similarity reaches 0 [m]: similarity = goodness x
     * max(0, 1 - rmse / this), goodness the mean share of each cloud's points matched (both
     * ways), rmse the RMS distance of the matched points. */
    double icp_rmse_tolerance_m = 0.25;
    /** Only pairs whose degrees differ by at most this are aligned; others get 0 [1]. */
    int icp_max_degree_difference = 0;
    /** Worker threads for ICP pairs, and in evaluate() when above 1 for building both graphs
     * side by side and for measuring brokenness beside accuracy; 0 = hardware concurrency.
     * Results do not depend on it. */
    int threads = 0;

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
    /** \throws InputError naming the section, field and value, e.g.
     * "[VertexSimilarity] threads = -1 violates 0 <= threads <= 256". */
    void validate() const;
};

/** Similarity of every vertex pair: rows = vertices of `a`, columns = vertices of `b`, values
 * in [0, 1]. Spurious vertices get 0 with everything. */
using SimilarityMatrix = Eigen::MatrixXd;

/** Attribute similarity (paper III-A, first approach): degree, ring angles, edge lengths and
 * clearances, compared under the best cyclic alignment of the two rings of edges, optionally
 * refined by the neighbours' similarities. */
SimilarityMatrix attributeSimilarity(const TopologyGraph& a, const TopologyGraph& b,
                                     const VertexSimilarityParameters& p);

/** ICP similarity (paper III-A, second approach): the obstacle cells around each vertex,
 * aligned with MRPT's CICP from start angles seeded by the vertices' edge directions; the best
 * alignment's error gives the similarity. Pairs are pruned by degree and run in threads.
 * `timing_ms`, if given, receives "clouds", "icp" and "total". */
SimilarityMatrix icpSimilarity(const TopologyGraph& a,
                               const mrpt::maps::COccupancyGridMap2D& grid_a,
                               const TopologyGraph& b,
                               const mrpt::maps::COccupancyGridMap2D& grid_b,
                               const VertexSimilarityParameters& p,
                               std::map<std::string, double>* timing_ms = nullptr);

}  // namespace mrpt_topoeval
