/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Two rigid parts in one set of point pairs (brokenness, doc/quality.md step 2b): the model of
// two fits, each proposed by two local fits and refined by reassignment, as k-means does with
// two centres (here two transforms).

#include "geometry/rigid_split.h"

#include <algorithm>
#include <limits>
#include <set>

#include "geometry/horn.h"

namespace mrpt_topoeval::internal
{
namespace
{
// Whether the pairs on `side` == s are connected by `links`.
bool connected(const std::vector<int>& side, int s, const std::vector<std::vector<int>>& links)
{
    const std::size_t n = side.size();
    std::vector<char> seen(n, 0);
    std::vector<int> stack;
    std::size_t members = 0, reached = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (side[i] == s)
        {
            ++members;
            if (stack.empty() && !reached) stack.push_back(int(i)), seen[i] = 1, reached = 1;
        }
    while (!stack.empty())
    {
        const int v = stack.back();
        stack.pop_back();
        for (int w : links[std::size_t(v)])
            if (side[std::size_t(w)] == s && !seen[std::size_t(w)])
                seen[std::size_t(w)] = 1, ++reached, stack.push_back(w);
    }
    return reached == members;
}
}  // namespace

std::optional<RigidSplit> bestRigidSplit(const std::vector<Eigen::Vector2d>& gt,
                                         const std::vector<Eigen::Vector2d>& map,
                                         const std::vector<std::vector<int>>& links, int min_size,
                                         int local_size, double min_gap_m2)
{
    const int n = int(gt.size());
    if (min_size < 2 || n < 2 * min_size || int(map.size()) != n || int(links.size()) != n)
        return std::nullopt;
    // Each pair's local fit: with its local_size nearest pairs (ground-truth distance).
    const int k = std::clamp(local_size, 2, n);
    std::vector<Transform2D> local(static_cast<std::size_t>(n));
    std::vector<std::vector<int>> near(static_cast<std::size_t>(n));
    for (int s = 0; s < n; ++s)
    {
        std::vector<std::pair<double, int>> d;
        for (int j = 0; j < n; ++j)
            d.emplace_back((gt[std::size_t(j)] - gt[std::size_t(s)]).squaredNorm(), j);
        std::partial_sort(d.begin(), d.begin() + k, d.end());
        std::vector<Eigen::Vector2d> a, b;
        for (int r = 0; r < k; ++r)
        {
            near[std::size_t(s)].push_back(d[std::size_t(r)].second);
            a.push_back(gt[std::size_t(d[std::size_t(r)].second)]);
            b.push_back(map[std::size_t(d[std::size_t(r)].second)]);
        }
        local[std::size_t(s)] = hornAlign(a, b);
    }
    auto err2 = [&](const Transform2D& t, int i)
    { return (gt[std::size_t(i)] - t.apply(map[std::size_t(i)])).squaredNorm(); };
    auto fitSide = [&](const std::vector<int>& side, int s, double* mse)
    {
        std::vector<Eigen::Vector2d> a, b;
        for (int i = 0; i < n; ++i)
            if (side[std::size_t(i)] == s)
                a.push_back(gt[std::size_t(i)]), b.push_back(map[std::size_t(i)]);
        return hornAlign(a, b, mse);
    };

    std::optional<RigidSplit> best;
    double best_cost = std::numeric_limits<double>::infinity();
    std::set<std::vector<int>> tried;
    for (int s = 0; s < n; ++s)
        for (int t = s + 1; t < n; ++t)
        {
            // Two local fits that place their own pairs alike propose no split.
            double gap = 0.0;
            for (int u : {s, t})
                for (int i : near[std::size_t(u)])
                    gap += (local[std::size_t(s)].apply(map[std::size_t(i)]) -
                            local[std::size_t(t)].apply(map[std::size_t(i)]))
                               .squaredNorm();
            if (gap / double(2 * k) <= min_gap_m2) continue;
            Transform2D fit[2] = {local[std::size_t(s)], local[std::size_t(t)]};
            std::vector<int> side(static_cast<std::size_t>(n), 0);
            bool valid = false;
            for (int round = 0; round < 20; ++round)
            {
                std::vector<int> next(static_cast<std::size_t>(n), 0);
                int count1 = 0;
                for (int i = 0; i < n; ++i)
                {
                    next[std::size_t(i)] = err2(fit[1], i) < err2(fit[0], i) ? 1 : 0;
                    count1 += next[std::size_t(i)];
                }
                valid = count1 >= 2 && n - count1 >= 2;
                if (!valid) break;
                const bool stable = round > 0 && next == side;
                side = std::move(next);
                if (stable) break;
                fit[0] = fitSide(side, 0, nullptr);
                fit[1] = fitSide(side, 1, nullptr);
            }
            if (!valid) continue;
            if (side[0] == 1)
                for (int& x : side) x = 1 - x;
            if (!tried.insert(side).second) continue;
            const int count1 = int(std::count(side.begin(), side.end(), 1));
            if (count1 < min_size || n - count1 < min_size) continue;
            if (!connected(side, 0, links) || !connected(side, 1, links)) continue;
            RigidSplit r;
            r.side = side;
            r.fit[0] = fitSide(side, 0, &r.squared_error_m2[0]);
            r.fit[1] = fitSide(side, 1, &r.squared_error_m2[1]);
            const double cost =
                r.squared_error_m2[0] * double(n - count1) + r.squared_error_m2[1] * double(count1);
            if (cost < best_cost) best_cost = cost, best = std::move(r);
        }
    return best;
}

}  // namespace mrpt_topoeval::internal
