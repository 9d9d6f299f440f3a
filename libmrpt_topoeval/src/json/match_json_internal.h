/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// The pieces of matchToJson() that other JSON documents embed (`topoeval compare` writes the
// same "ground_truth", "map" and "matches" objects), so the formats cannot drift apart.

#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/TopologyGraph.h>

// By its own folder, not "internal/...": tests include this header by path, without src/ on
// their include path.
#include <mrpt_topoeval/json/JsonWriter.h>

#include "decimals.h"  // beside this header, so found without src/ on the include path

namespace mrpt_topoeval::internal
{
/** Writes the object `{"file", "vertices", "non_spurious_vertices", "half_edges"}` describing
 * one side of a match, as the value of the member whose key the caller has written; with
 * `matchable` (the quality report's), also "matchable_vertices" and "edge_length_m". */
void writeMatchedGraph(JsonWriter& w, const TopologyGraph& g,
                       const std::size_t* matchable = nullptr);

/** Writes the "matches" object (counts, isomorphism sizes, pairs, messages; see
 * matchToJson()) as the value of the member whose key the caller has written. */
void writeMatches(JsonWriter& w, const GraphMatch& match);

}  // namespace mrpt_topoeval::internal
