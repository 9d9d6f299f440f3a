/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace mrpt_topoeval
{
/** Which stage of the matcher made an assignment (the columns of the paper's Table II). */
enum class MatchStage
{
    Isomorphism,
    NeighbourGrowing,
    /** Ours: a vertex pair of a map placed by its walls (QualityParameters::map_by_walls). */
    Walls
};

/** "isomorphism" / "neighbour_growing" / "walls". */
std::string toString(MatchStage s);

/** One assigned vertex pair. */
struct VertexPair
{
    int ground_truth = -1;  //!< Vertex id in the ground-truth graph.
    int map = -1;           //!< Vertex id in the map's graph.
    MatchStage stage = MatchStage::Isomorphism;
    double similarity = 0.0;  //!< Vertex similarity of the pair [0, 1].
    /** Which isomorphism (0, 1, ...) found it; for neighbour growing, the one it grew from. */
    int isomorphism = -1;
};

/** The result of matching two Topology Graphs (paper III-B). Plain data. */
struct GraphMatch
{
    /** Pairs ordered by ground-truth vertex id. */
    std::vector<VertexPair> pairs;
    std::size_t isomorphism = 0;        //!< Pairs found by isomorphism.
    std::size_t neighbour_growing = 0;  //!< Pairs added by neighbour growing.
    std::size_t missing = 0;            //!< Non-spurious ground-truth vertices left unmatched.
    /** Size of each accepted isomorphism, in the order they were found. */
    std::vector<std::size_t> isomorphism_sizes;
    /** Notes for the user (nothing to match, no vertex of a matching degree, ...). */
    std::vector<std::string> messages;
    /** Milliseconds per stage ("similarity", "isomorphism", "neighbour_growing", "total"). */
    std::map<std::string, double> timing_ms;

    /** Pairs of a map placed by its walls (stage Walls). */
    std::size_t byWalls() const;
    /** The map vertex matched to ground-truth vertex `gt`, or -1. */
    int mapVertexOf(int gt) const;
    /** The ground-truth vertex matched to map vertex `m`, or -1. */
    int groundTruthVertexOf(int m) const;
};

}  // namespace mrpt_topoeval
