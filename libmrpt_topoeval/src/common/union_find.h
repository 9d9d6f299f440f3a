/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// Disjoint sets with path halving; a set's root is its smallest member, so the result does not
// depend on the order the unions come in.

#include <algorithm>
#include <numeric>
#include <vector>

namespace mrpt_topoeval::internal
{
struct UnionFind
{
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    int find(int x)
    {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(int a, int b)
    {
        a = find(a), b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
    std::vector<int> parent;
};
}  // namespace mrpt_topoeval::internal
