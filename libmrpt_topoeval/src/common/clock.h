/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// The wall clock of the timings the library reports (steps of evaluate(), ICP similarity,
// rawlog scoring), in one place.

#include <chrono>

namespace mrpt_topoeval::internal
{
using Clock = std::chrono::steady_clock;

/** Milliseconds since t0. */
inline double msSince(Clock::time_point t0)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace mrpt_topoeval::internal
