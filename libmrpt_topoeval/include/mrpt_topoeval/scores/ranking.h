/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <string>
#include <vector>

namespace mrpt_topoeval
{
/** Ranks of `values` (higher is better) among the entries with `valid`, as the paper's Table I
 * and `topoeval rank` give them: "1" is the best; entries whose values agree to `decimals`
 * decimals share their positions, written "2-3"; invalid entries get "". A value that is not
 * finite ranks last. Ties keep no order of their own: equal entries get the same text. Used
 * by `topoeval rank` and the Python `rank()` and batch, so that all three agree. */
std::vector<std::string> rankPositions(const std::vector<double>& values,
                                       const std::vector<bool>& valid, int decimals = 3);

}  // namespace mrpt_topoeval
