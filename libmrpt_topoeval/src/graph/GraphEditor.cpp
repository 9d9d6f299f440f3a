/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "graph/GraphEditor.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <tuple>

namespace mrpt_topoeval::internal
{
namespace
{
// Deterministic order of positions, for tie-breaks that must not depend on CGAL's iteration.
bool lessPos(const Eigen::Vector2d& p, const Eigen::Vector2d& q)
{
    return std::tie(p.x(), p.y()) < std::tie(q.x(), q.y());
}

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
}  // namespace

int GraphEditor::addVertex(const Eigen::Vector2d& pos, double clearance)
{
    Vertex v;
    v.pos = pos;
    v.clearance = clearance;
    m_v.push_back(std::move(v));
    return static_cast<int>(m_v.size()) - 1;
}

int GraphEditor::addSegment(int a, int b, double min_clearance)
{
    Edge e;
    e.a = a;
    e.b = b;
    e.path = {m_v[a].pos, m_v[b].pos};
    e.clearance = {m_v[a].clearance, m_v[b].clearance};
    e.min_clearance = min_clearance;
    e.length = (m_v[b].pos - m_v[a].pos).norm();
    const int id = static_cast<int>(m_e.size());
    m_e.push_back(std::move(e));
    m_v[a].edges.push_back(id);
    m_v[b].edges.push_back(id);
    return id;
}

std::size_t GraphEditor::numAliveVertices() const
{
    return static_cast<std::size_t>(
        std::count_if(m_v.begin(), m_v.end(), [](const Vertex& v) { return v.alive; }));
}

double GraphEditor::pathLength(const std::vector<Eigen::Vector2d>& path)
{
    double len = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) len += (path[i] - path[i - 1]).norm();
    return len;
}

void GraphEditor::removeEdge(int e)
{
    Edge& E = m_e[e];
    if (!E.alive) return;
    E.alive = false;
    for (int end : {E.a, E.b})
    {
        auto& inc = m_v[end].edges;
        const auto it = std::find(inc.begin(), inc.end(), e);
        if (it != inc.end()) inc.erase(it);  // a loop is listed twice: one erase per end
    }
}

void GraphEditor::removeVertex(int v)
{
    while (!m_v[v].edges.empty()) removeEdge(m_v[v].edges.back());
    m_v[v].alive = false;
}

void GraphEditor::reverseEdge(Edge& E)
{
    std::swap(E.a, E.b);
    std::reverse(E.path.begin(), E.path.end());
    std::reverse(E.clearance.begin(), E.clearance.end());
}

void GraphEditor::truncateEdge(int e, std::size_t keep)
{
    keep = std::max<std::size_t>(keep, 1);
    const int old_end = m_e[e].b;
    auto& inc = m_v[old_end].edges;
    inc.erase(std::find(inc.begin(), inc.end(), e));
    Edge& E = m_e[e];
    E.path.resize(keep);
    E.clearance.resize(keep);
    if (keep == 1)
    {
        // The path leaves the region at once: nothing of it is inside.
        E.path.push_back(E.path[0]);
        E.clearance.push_back(E.clearance[0]);
    }
    const int nv = addVertex(m_e[e].path.back(), m_e[e].clearance.back());
    Edge& E2 = m_e[e];
    E2.b = nv;
    E2.length = pathLength(E2.path);
    m_v[nv].edges.push_back(e);
    if (E2.length == 0.0) removeEdge(e);
}

void GraphEditor::dissolveDegreeTwo()
{
    const int nv = static_cast<int>(m_v.size());
    std::vector<char> anchor(nv, 0), used(m_e.size(), 0);
    for (int v = 0; v < nv; ++v)
    {
        const auto& inc = m_v[v].edges;
        // A degree-2 vertex on its own loop (a pure ring's vertex) stays a vertex.
        anchor[v] = m_v[v].alive && (inc.size() != 2 || inc[0] == inc[1]);
    }

    std::vector<Edge> new_edges;
    // Follows edge e0 from vertex v0 through degree-2 vertices up to the next anchor.
    auto trace = [&](int v0, int e0)
    {
        Edge out;
        out.a = v0;
        out.path = {m_v[v0].pos};
        out.clearance = {m_v[v0].clearance};
        out.min_clearance = std::numeric_limits<double>::infinity();
        int v = v0, e = e0;
        for (;;)
        {
            used[e] = 1;
            const Edge& E = m_e[e];
            const bool forward = E.a == v;
            const std::size_t n = E.path.size();
            for (std::size_t k = 1; k < n; ++k)
            {
                const std::size_t j = forward ? k : n - 1 - k;
                out.path.push_back(E.path[j]);
                out.clearance.push_back(E.clearance[j]);
            }
            out.min_clearance = std::min(out.min_clearance, E.min_clearance);
            const int w = forward ? E.b : E.a;
            // Stop at an anchor before looking at its edges: a dead end has only inc[0].
            if (anchor[w])
            {
                out.b = w;
                break;
            }
            const auto& inc = m_v[w].edges;
            const int next = inc[0] == e ? inc[1] : inc[0];
            if (used[next])
            {
                out.b = w;
                break;
            }
            v = w;
            e = next;
        }
        out.length = pathLength(out.path);
        new_edges.push_back(std::move(out));
    };

    for (int v = 0; v < nv; ++v)
        if (anchor[v])
            for (int e : m_v[v].edges)
                if (!used[e]) trace(v, e);

    // What is left are cycles of degree-2 vertices only: anchor each at its vertex of largest
    // clearance (ties: smallest position) so the choice does not depend on storage order.
    for (int e0 = 0; e0 < static_cast<int>(m_e.size()); ++e0)
    {
        if (!m_e[e0].alive || used[e0]) continue;
        int best = m_e[e0].a, v = m_e[e0].a, e = e0;
        do
        {
            const Edge& E = m_e[e];
            v = E.a == v ? E.b : E.a;
            const auto& inc = m_v[v].edges;
            e = inc[0] == e ? inc[1] : inc[0];
            if (m_v[v].clearance > m_v[best].clearance ||
                (m_v[v].clearance == m_v[best].clearance && lessPos(m_v[v].pos, m_v[best].pos)))
                best = v;
        } while (e != e0);
        anchor[best] = 1;
        trace(best, m_v[best].edges[0]);
    }

    // Rebuild: anchors with at least one edge, renumbered in their old order.
    std::vector<int> remap(nv, -1);
    std::vector<Vertex> new_vertices;
    for (const Edge& E : new_edges)
        for (int end : {E.a, E.b})
            if (remap[end] < 0) remap[end] = 0;  // mark: has an edge
    for (int v = 0; v < nv; ++v)
        if (anchor[v] && remap[v] == 0)
        {
            remap[v] = static_cast<int>(new_vertices.size());
            Vertex nvx;
            nvx.pos = m_v[v].pos;
            nvx.clearance = m_v[v].clearance;
            new_vertices.push_back(std::move(nvx));
        }
        else
            remap[v] = -1;
    for (int i = 0; i < static_cast<int>(new_edges.size()); ++i)
    {
        Edge& E = new_edges[i];
        E.a = remap[E.a];
        E.b = remap[E.b];
        new_vertices[E.a].edges.push_back(i);
        new_vertices[E.b].edges.push_back(i);
    }
    m_v = std::move(new_vertices);
    m_e = std::move(new_edges);
}

std::size_t GraphEditor::pruneDeadEnds(double max_length, double corner_ratio, double disc_ratio,
                                       double disc_max_chord)
{
    std::size_t removed = 0;
    for (;;)
    {
        std::vector<int> victims;
        for (int e = 0; e < static_cast<int>(m_e.size()); ++e)
        {
            const Edge& E = m_e[e];
            if (!E.alive || E.a == E.b) continue;
            const bool a_end = degree(E.a) == 1, b_end = degree(E.b) == 1;
            if (!a_end && !b_end) continue;
            const int junction = a_end ? E.b : E.a, end = a_end ? E.a : E.b;
            // A branch into a convex corner runs straight to it: its chord (not its path, which
            // wiggles on noisy walls) is sqrt(2) times the clearance it loses.
            const double drop = m_v[junction].clearance - m_v[end].clearance;
            const double chord = (m_v[junction].pos - m_v[end].pos).norm();
            if (E.length < max_length || chord < corner_ratio * drop ||
                (chord < disc_max_chord && chord < disc_ratio * m_v[junction].clearance))
                victims.push_back(e);
        }
        if (victims.empty()) break;
        for (int e : victims)
        {
            const int a = m_e[e].a, b = m_e[e].b;
            removeEdge(e);
            if (degree(a) == 0) m_v[a].alive = false;
            if (degree(b) == 0) m_v[b].alive = false;
        }
        removed += victims.size();
        dissolveDegreeTwo();
    }
    return removed;
}

std::size_t GraphEditor::retractDeadEndTails(double share, double wedge_ratio)
{
    if (share <= 0.0 || wedge_ratio <= 0.0) return 0;
    std::size_t moved = 0;
    // Edge e runs from its anchor a to the dead end b. The tail is what a wedge (a corner of
    // the free space) makes of the branch: points q whose clearance exceeds the tip's by at
    // least 1 / wedge_ratio of their straight distance to the tip (a corner of angle t gives
    // 1 / sin(t / 2)). Its largest clearance is the width the branch had before the corner;
    // the tip goes back to the last point with `share` of it. Points within the anchor's
    // clearance disc are not looked at.
    auto retract = [&](int e, double disc)
    {
        Edge& E = m_e[e];
        const std::size_t n = E.path.size();
        const Eigen::Vector2d anchor = E.path.front(), tip = E.path.back();
        const double c_tip = E.clearance.back();
        double widest = c_tip;
        for (std::size_t i = n - 1; i-- > 1;)
        {
            if ((E.path[i] - anchor).norm() <= disc) break;
            if ((E.path[i] - tip).norm() <= wedge_ratio * (E.clearance[i] - c_tip))
                widest = std::max(widest, E.clearance[i]);
        }
        std::size_t k = n - 1;
        while (k > 0 && E.clearance[k] < share * widest) --k;
        if (k == 0 || k + 1 == n) return;
        const int old_end = E.b;
        truncateEdge(e, k + 1);
        if (degree(old_end) == 0) m_v[old_end].alive = false;
        ++moved;
    };
    const int ne = static_cast<int>(m_e.size());
    for (int e = 0; e < ne; ++e)
    {
        if (!m_e[e].alive || m_e[e].a == m_e[e].b) continue;
        const bool a_end = degree(m_e[e].a) == 1, b_end = degree(m_e[e].b) == 1;
        if (!a_end && !b_end) continue;
        if (a_end && b_end)
        {
            // A lone corridor: both of its ends.
            retract(e, 0.0);
            if (!m_e[e].alive) continue;
            reverseEdge(m_e[e]);
            retract(e, 0.0);
            continue;
        }
        if (a_end) reverseEdge(m_e[e]);  // a: the junction, b: the dead end
        retract(e, m_v[m_e[e].a].clearance);
    }
    return moved;
}

void GraphEditor::keepComponents(double min_length)
{
    const int nv = static_cast<int>(m_v.size());
    std::vector<int> comp(nv, -1);
    struct Score
    {
        double length = 0.0;
        int vertices = 0;
        Eigen::Vector2d min_pos;
    };
    std::vector<Score> scores;
    for (int s = 0; s < nv; ++s)
    {
        if (!m_v[s].alive || comp[s] >= 0) continue;
        const int c = static_cast<int>(scores.size());
        Score sc;
        sc.min_pos = m_v[s].pos;
        std::vector<int> stack{s};
        comp[s] = c;
        while (!stack.empty())
        {
            const int v = stack.back();
            stack.pop_back();
            ++sc.vertices;
            if (lessPos(m_v[v].pos, sc.min_pos)) sc.min_pos = m_v[v].pos;
            for (int e : m_v[v].edges)
            {
                const Edge& E = m_e[e];
                const int w = E.a == v ? E.b : E.a;
                if (E.a == v || E.a == E.b) sc.length += E.length;  // count each edge once
                if (comp[w] < 0)
                {
                    comp[w] = c;
                    stack.push_back(w);
                }
            }
        }
        scores.push_back(sc);
    }
    if (scores.size() <= 1) return;
    int best = 0;
    for (int c = 1; c < static_cast<int>(scores.size()); ++c)
    {
        const Score &x = scores[c], &y = scores[best];
        if (x.length > y.length ||
            (x.length == y.length && (x.vertices > y.vertices ||
                                      (x.vertices == y.vertices && lessPos(x.min_pos, y.min_pos)))))
            best = c;
    }
    for (int v = 0; v < nv; ++v)
        if (m_v[v].alive && comp[v] != best && !(scores[comp[v]].length >= min_length))
            removeVertex(v);
    dissolveDegreeTwo();  // rebuilds the storage from what is alive
}

std::size_t GraphEditor::joinClose(double max_length)
{
    const int nv = static_cast<int>(m_v.size());
    UnionFind uf(nv);
    for (const Edge& E : m_e)
        if (E.alive && E.a != E.b && E.length < max_length) uf.unite(E.a, E.b);

    std::vector<int> group_size(nv, 0);
    for (int v = 0; v < nv; ++v)
        if (m_v[v].alive) ++group_size[uf.find(v)];

    // One new vertex per group of two or more, at the group's mean position.
    std::vector<int> merged(nv, -1);
    std::size_t removed = 0;
    for (int v = 0; v < nv; ++v)
    {
        const int r = uf.find(v);
        if (!m_v[v].alive || group_size[r] < 2) continue;
        if (merged[r] < 0)
        {
            merged[r] = addVertex(Eigen::Vector2d::Zero(), 0.0);
            removed += static_cast<std::size_t>(group_size[r]) - 1;
        }
        Vertex& m = m_v[merged[r]];
        m.pos += m_v[v].pos / group_size[r];
        m.clearance += m_v[v].clearance / group_size[r];
    }
    if (removed == 0) return 0;

    for (int e = 0; e < static_cast<int>(m_e.size()); ++e)
    {
        Edge& E = m_e[e];
        if (!E.alive) continue;
        const int ga = merged[uf.find(E.a)], gb = merged[uf.find(E.b)];
        if (ga < 0 && gb < 0) continue;
        if (ga >= 0 && ga == gb && E.a != E.b && E.length < max_length)
        {
            E.alive = false;  // collapsed into the new vertex
            continue;
        }
        // Reattach the ends to the new vertex, extending the path to its position.
        if (ga >= 0)
        {
            E.a = ga;
            E.path.insert(E.path.begin(), m_v[ga].pos);
            E.clearance.insert(E.clearance.begin(), m_v[ga].clearance);
        }
        if (gb >= 0)
        {
            E.b = gb;
            E.path.push_back(m_v[gb].pos);
            E.clearance.push_back(m_v[gb].clearance);
        }
        E.length = pathLength(E.path);
    }
    for (int v = 0; v < nv; ++v)
        if (merged[uf.find(v)] >= 0) m_v[v].alive = false;
    // Incidence lists are rebuilt from the edges.
    for (Vertex& v : m_v) v.edges.clear();
    for (int e = 0; e < static_cast<int>(m_e.size()); ++e)
        if (m_e[e].alive)
        {
            m_v[m_e[e].a].edges.push_back(e);
            m_v[m_e[e].b].edges.push_back(e);
        }
    dissolveDegreeTwo();
    return removed;
}

}  // namespace mrpt_topoeval::internal
