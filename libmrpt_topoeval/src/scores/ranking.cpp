/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt_topoeval/scores/ranking.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace mrpt_topoeval
{
std::vector<std::string> rankPositions(const std::vector<double>& values,
                                       const std::vector<bool>& valid, int decimals)
{
    const double scale = std::pow(10.0, decimals);
    std::vector<std::int64_t> key(values.size(), 0);
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < values.size(); ++i)
        if (i < valid.size() && valid[i])
        {
            // NaN never comes from the evaluator; should it, it ranks last.
            key[i] = std::isfinite(values[i]) ? std::llround(values[i] * scale)
                                              : std::numeric_limits<std::int64_t>::min();
            order.push_back(i);
        }
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return key[a] > key[b]; });
    std::vector<std::string> out(values.size());
    for (std::size_t first = 0; first < order.size();)
    {
        std::size_t last = first;
        while (last + 1 < order.size() && key[order[last + 1]] == key[order[first]]) ++last;
        const std::string r = first == last
                                  ? std::to_string(first + 1)
                                  : std::to_string(first + 1) + "-" + std::to_string(last + 1);
        for (std::size_t k = first; k <= last; ++k) out[order[k]] = r;
        first = last + 1;
    }
    return out;
}

}  // namespace mrpt_topoeval
