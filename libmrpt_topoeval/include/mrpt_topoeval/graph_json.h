/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/graph/build_graph.h>

#include <string>

namespace mrpt_topoeval
{
/** The graph as JSON (the format of `topoeval graph --json`, documented in doc/cli.md):
 * `{"map", "summary", "vertices", "edges", "outer_boundary", "warnings", "build",
 * "timing_ms"}`, coordinates in metres in the map's world frame. Byte-identical for the same
 * graph, apart from the `timing_ms` object; `build` and `timing_ms` are omitted when `stats` is
 * null. NaN and infinities are written as null. */
std::string graphToJson(const TopologyGraph& graph, const GraphBuildStats* stats = nullptr);

}  // namespace mrpt_topoeval
