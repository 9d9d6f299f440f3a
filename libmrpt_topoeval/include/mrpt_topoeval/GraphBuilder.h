/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Deprecated name (no class GraphBuilder exists), kept so that existing code compiles: include
// <mrpt_topoeval/graph/build_graph.h> (or <mrpt_topoeval/topoeval.h>).
#include <mrpt_topoeval/graph/build_graph.h>
