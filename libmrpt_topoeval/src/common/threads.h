/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// How many worker threads a `threads` parameter asks for: the one rule of every parallel step.

#include <algorithm>
#include <thread>

namespace mrpt_topoeval::internal
{
/** `requested` > 0 as is; 0 = the hardware's concurrency (at least 1). */
inline unsigned workerThreads(int requested)
{
    return requested > 0 ? static_cast<unsigned>(requested)
                         : std::max(1u, std::thread::hardware_concurrency());
}
}  // namespace mrpt_topoeval::internal
