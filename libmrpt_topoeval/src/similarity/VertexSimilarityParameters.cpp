/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// [VertexSimilarity]: every key once (common/parameter_table.h); units and reasons in
// vertex_similarity.h. The two approaches are in their own files.

#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include "common/parameter_table.h"

namespace mrpt_topoeval
{
std::string toString(SimilarityMode m) { return m == SimilarityMode::Icp ? "icp" : "attributes"; }

SimilarityMode similarityModeFromString(const std::string& s)
{
    if (s == "attributes") return SimilarityMode::Attributes;
    if (s == "icp") return SimilarityMode::Icp;
    throw InputError("similarity mode '" + s + "' is not one of: attributes, icp");
}

TOPOEVAL_PARAMETER_TABLE(
    VertexSimilarityParameters, NumberText::Stream,
    choice(TOPOEVAL_KEY(mode), similarityModeFromString,
           {SimilarityMode::Attributes, SimilarityMode::Icp},
           "how vertex similarity is computed (paper III-A)"),
    real(TOPOEVAL_KEY(angle_tolerance_deg), "deg",
         "mean ring-angle difference where the angle term is 0", above(0)),
    real(TOPOEVAL_KEY(length_tolerance), "ratio",
         "relative edge-length difference where that term is 0", above(0)),
    real(TOPOEVAL_KEY(clearance_tolerance_m), "m",
         "clearance difference where the clearance terms are 0", above(0)),
    real(TOPOEVAL_KEY(weight_angles), "1", "weight of the ring-angle term", atLeast(0)),
    real(TOPOEVAL_KEY(weight_lengths), "1", "weight of the edge-length term", atLeast(0)),
    real(TOPOEVAL_KEY(weight_vertex_clearance), "1", "weight of the vertex clearance", atLeast(0)),
    real(TOPOEVAL_KEY(weight_edge_clearance), "1", "weight of the edges' clearance", atLeast(0)),
    // All weights 0 would leave the weighted mean undefined.
    relation(&P::weight_angles, "at least one weight > 0",
             [](const P& p)
             {
                 return p.weight_angles + p.weight_lengths + p.weight_vertex_clearance +
                            p.weight_edge_clearance >
                        0;
             }),
    real(TOPOEVAL_KEY(degree_mismatch_factor), "ratio",
         "similarity factor per unit of degree difference", atLeast(0).atMost(1)),
    real(TOPOEVAL_KEY(neighbour_weight), "ratio", "weight of the neighbours' similarity; 0 = off",
         atLeast(0).below(1)),
    integer(TOPOEVAL_KEY(neighbour_iterations), "1", "neighbour refinement rounds",
            atLeast(0).atMost(10)),
    real(TOPOEVAL_KEY(icp_radius_m), "m", "obstacles within this of a vertex form its cloud",
         above(0)),
    integer(TOPOEVAL_KEY(icp_start_angles), "1",
            "ICP start angles when edges give none (paper: 12)", atLeast(1).atMost(72)),
    real(TOPOEVAL_KEY(icp_rmse_tolerance_m), "m",
         "ICP alignment RMS error where the similarity is 0", above(0)),
    integer(TOPOEVAL_KEY(icp_max_degree_difference), "1",
            "ICP only for pairs whose degrees differ by at most this", atLeast(0)),
    integer(TOPOEVAL_KEY(threads), "1",
            "worker threads (ICP pairs; evaluate(): both graphs, brokenness); 0 = all cores",
            atLeast(0).atMost(256)))

}  // namespace mrpt_topoeval
