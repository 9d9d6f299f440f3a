/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "matching/cliques.h"

#include <algorithm>

namespace mrpt_topoeval::internal
{
MaxClique::MaxClique(const std::vector<std::uint8_t>& adjacent, int n, std::size_t budget)
    : m_adj(adjacent), m_n(n), m_budget(budget)
{
}

std::vector<int> MaxClique::run(std::vector<int> vertices)
{
    m_best.clear();
    m_steps = 0;
    // Highest consistency-graph degree first (MCQ's initial order), stable for ties.
    const std::vector<int> deg = countEdges(vertices);
    std::stable_sort(vertices.begin(), vertices.end(),
                     [&](int a, int b) { return deg[a] > deg[b]; });
    std::vector<int> order, colour;
    colourSort(vertices, order, colour);
    std::vector<int> r;
    expand(r, order, colour);
    return m_best;
}

std::vector<int> MaxClique::countEdges(const std::vector<int>& vertices)
{
    std::vector<int> deg(m_n, 0);
    m_edges = 0;
    for (int v : vertices)
        for (int u : vertices) deg[v] += adj(u, v);
    for (int v : vertices) m_edges += std::size_t(deg[v]);
    m_edges /= 2;
    return deg;
}

// Greedy colouring of p: order by colour class, colour[i] = class number (1-based) of
// order[i]; the colour is an upper bound of the clique size within order[0..i].
void MaxClique::colourSort(const std::vector<int>& p, std::vector<int>& order,
                           std::vector<int>& colour)
{
    std::vector<std::vector<int>> classes;
    for (int v : p)
    {
        std::size_t k = 0;
        for (; k < classes.size(); ++k)
        {
            bool free = true;
            for (int u : classes[k])
                if (adj(u, v))
                {
                    free = false;
                    break;
                }
            if (free) break;
        }
        if (k == classes.size()) classes.emplace_back();
        classes[k].push_back(v);
    }
    order.clear();
    colour.clear();
    for (std::size_t k = 0; k < classes.size(); ++k)
        for (int v : classes[k])
        {
            order.push_back(v);
            colour.push_back(int(k) + 1);
        }
}

void MaxClique::expand(std::vector<int>& r, const std::vector<int>& p,
                       const std::vector<int>& colour)
{
    for (int i = int(p.size()) - 1; i >= 0; --i)
    {
        if (++m_steps > m_budget) return;
        if (r.size() + std::size_t(colour[i]) <= m_best.size()) return;
        const int v = p[i];
        r.push_back(v);
        std::vector<int> np;
        for (int j = 0; j < i; ++j)
            if (adj(v, p[j])) np.push_back(p[j]);
        if (np.empty())
        {
            if (r.size() > m_best.size()) m_best = r;
        }
        else
        {
            std::vector<int> no, nc;
            colourSort(np, no, nc);
            expand(r, no, nc);
        }
        r.pop_back();
    }
}

namespace
{
struct BronKerbosch
{
    const std::vector<std::uint8_t>& adjacent;
    int n;
    std::size_t min_size, budget, steps = 0;
    std::vector<std::vector<int>> found;

    bool adj(int a, int b) const { return adjacent[std::size_t(a) * n + b] != 0; }

    // r: the clique so far; p: vertices that extend it; x: vertices that extended it before
    // (a clique they extend was reported already).
    void extend(std::vector<int>& r, std::vector<int> p, std::vector<int> x)
    {
        if (++steps > budget) return;
        if (p.empty())
        {
            if (x.empty() && r.size() >= min_size)
            {
                found.push_back(r);
                std::sort(found.back().begin(), found.back().end());
            }
            return;
        }
        if (r.size() + p.size() < min_size) return;
        // Tomita's pivot: the vertex of p or x with the most neighbours in p; only its
        // non-neighbours are branched on (a maximal clique holds the pivot or a non-neighbour).
        int pivot = p.front();
        std::size_t most = 0;
        for (const std::vector<int>* set : {&p, &x})
            for (int u : *set)
            {
                std::size_t count = 0;
                for (int v : p) count += adj(u, v);
                if (count > most) most = count, pivot = u;
            }
        const std::vector<int> branch = p;
        for (int v : branch)
        {
            if (adj(pivot, v)) continue;
            std::vector<int> np, nx;
            for (int u : p)
                if (adj(v, u)) np.push_back(u);
            for (int u : x)
                if (adj(v, u)) nx.push_back(u);
            r.push_back(v);
            extend(r, std::move(np), std::move(nx));
            r.pop_back();
            p.erase(std::find(p.begin(), p.end(), v));
            x.push_back(v);
        }
    }
};
}  // namespace

std::vector<std::vector<int>> maximalCliques(const std::vector<std::uint8_t>& adjacent, int n,
                                             const std::vector<int>& vertices, int min_size,
                                             std::size_t budget, std::size_t* steps)
{
    BronKerbosch bk{adjacent, n, std::size_t(std::max(min_size, 1)), budget, 0, {}};
    std::vector<int> r;
    bk.extend(r, vertices, {});
    if (steps) *steps = std::min(bk.steps, budget);
    return std::move(bk.found);
}

}  // namespace mrpt_topoeval::internal
