/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <cmath>
#include <vector>

namespace mrpt_topoeval::internal
{
/** The angles between consecutive edges of a ring sorted by angle (each element has an
 * `angle_rad`), the last one wrapping round so that they add up to 2 pi: the ring-angle
 * attribute of a vertex (paper II-C), on the graph and on its matching view alike. */
template <typename Ring>
std::vector<double> ringGaps(const Ring& ring)
{
    const std::size_t n = ring.size();
    std::vector<double> gaps(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        double d = ring[(i + 1) % n].angle_rad - ring[i].angle_rad;
        if (i + 1 == n) d += 2.0 * M_PI;
        gaps[i] = d;
    }
    return gaps;
}

}  // namespace mrpt_topoeval::internal
