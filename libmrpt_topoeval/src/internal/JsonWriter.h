/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Forwarding header for bench/validation, which includes this path (moved files keep it until
// the merge with the matching work): the writer is <mrpt_topoeval/json/JsonWriter.h>.
#include <mrpt_topoeval/json/JsonWriter.h>

namespace mrpt_topoeval::internal
{
using mrpt_topoeval::JsonWriter;
using mrpt_topoeval::writeTiming;
}  // namespace mrpt_topoeval::internal
