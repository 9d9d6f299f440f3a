/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/VertexSimilarity.h>

#include <string>

namespace mrpt_topoeval
{
/** Parameters of the structural matcher (paper III-B), INI section `[GraphMatcher]`. Vertex
 * positions are never used: robot maps have wrong global frames. */
struct GraphMatcherParameters : public mrpt::config::CLoadableOptions
{
    /** Two matched edges must agree in length within factor x the longer + allowance (paper:
     * "the length of the edges must coincide at least to a certain degree") [ratio]. */
    double edge_length_factor = 0.25;
    double edge_length_allowance_m = 0.75;  //!< [m]
    /** Matched edges at a vertex must leave it at angles (relative to the ring's other
     * edges) that differ by at most this [deg]. */
    double max_angle_difference_deg = 40.0;
    /** Pairs less similar than this are never assigned by the isomorphism [0..1]. */
    double min_isomorphism_similarity = 0.4;
    /** An isomorphism is accepted when it has at least this many vertices; on graphs too
     * small for that, at least min_isomorphism_share of the smaller graph's matchable vertices
     * (and never fewer than 3). Small isomorphisms are common between different buildings
     * made of the same corridors and rooms: 8 kept every such pair of our test maps apart [1]. */
    int min_isomorphism_vertices = 8;
    double min_isomorphism_share = 0.75;  //!< [ratio]
    /** Branches the wavefront may explore per seed pair before it takes the best branch
     * without exploring further (bounds recursion on repetitive maps) [1]. */
    int max_branches_per_seed = 64;
    /** Run neighbour growing after the isomorphisms (paper III-B end) [bool]. */
    bool neighbour_growing = true;
    /** Neighbour growing assigns a pair only if its similarity is at least this [0..1]. */
    double min_growing_similarity = 0.5;
    /** Neighbour growing's relaxed edge-length check: factor and allowance [ratio], [m]. */
    double growing_edge_length_factor = 0.5;
    double growing_edge_length_allowance_m = 2.0;

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
    /** \throws InputError naming the field and value. */
    void validate() const;
};

/** Matches a ground-truth graph and a map's graph (paper III-B): subgraph isomorphisms by
 * wavefront propagation from every unassigned vertex (Algorithm 1), biggest first, then
 * neighbour growing from the match's border. Spurious vertices are skipped. `similarity` has a
 * row per ground-truth vertex and a column per map vertex (attributeSimilarity() or
 * icpSimilarity()). Never throws on small or empty graphs: the match is then empty or partial,
 * with a message. Deterministic. \throws InputError on parameters or a matrix of wrong size. */
GraphMatch matchGraphs(const TopologyGraph& ground_truth, const TopologyGraph& map,
                       const SimilarityMatrix& similarity,
                       const GraphMatcherParameters& params = {});

}  // namespace mrpt_topoeval
