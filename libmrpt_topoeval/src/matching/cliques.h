/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Cliques of the pairwise-consistency graph (doc/matching.md, "Consistent groups"): the maximum
// clique, the first group's candidate, and, on a graph too small for the significance test, every
// maximal clique (among a few dozen candidates the maximum is often tied, and which of the tied
// cliques a search returns is chance).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mrpt_topoeval::internal
{
/** Maximum clique by branch and bound with a greedy-colouring bound (Tomita's MCQ, the
 * algorithm of Parra Bustos et al.). `adjacent` is an n x n 0/1 matrix, row-major.
 * Deterministic; each run() stops after `budget` steps with the best clique found so far. */
class MaxClique
{
public:
    MaxClique(const std::vector<std::uint8_t>& adjacent, int n, std::size_t budget);

    /** The largest clique among `vertices` (in the given order of preference). */
    std::vector<int> run(std::vector<int> vertices);
    /** Steps spent by the last run(). */
    std::size_t steps() const { return m_steps; }
    /** Edges among the last run()'s vertices (the consistency graph's density). */
    std::size_t edges() const { return m_edges; }
    /** Sets edges() to the edges among `vertices` without a search (for a clique given in
     * advance); returns each vertex's degree among them, indexed by vertex. */
    std::vector<int> countEdges(const std::vector<int>& vertices);

private:
    bool adj(int a, int b) const { return m_adj[std::size_t(a) * m_n + b] != 0; }
    void colourSort(const std::vector<int>& p, std::vector<int>& order, std::vector<int>& colour);
    void expand(std::vector<int>& r, const std::vector<int>& p, const std::vector<int>& colour);

    const std::vector<std::uint8_t>& m_adj;
    int m_n;
    std::size_t m_budget;
    std::size_t m_steps = 0;
    std::size_t m_edges = 0;
    std::vector<int> m_best;
};

/** Every maximal clique among `vertices` with at least `min_size` members (Bron and Kerbosch
 * with Tomita's pivot), each sorted, in a deterministic order. Stops after `budget` steps (a
 * step is one call); `steps`, when given, receives the steps spent. */
std::vector<std::vector<int>> maximalCliques(const std::vector<std::uint8_t>& adjacent, int n,
                                             const std::vector<int>& vertices, int min_size,
                                             std::size_t budget, std::size_t* steps = nullptr);

}  // namespace mrpt_topoeval::internal
