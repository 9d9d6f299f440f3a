/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "graph/GraphEditor.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <tuple>

#include "common/union_find.h"

namespace mrpt_topoeval::internal
{
namespace
{
// Deterministic order of positions, for tie-breaks that must not depend on CGAL's iteration.
bool lessPos(const Eigen::Vector2d& p, const Eigen::Vector2d& q)
{
    return std::tie(p.x(), p.y()) < std::tie(q.x(), q.y());
}

// Length of a polyline [cells].
double polylineLength(const std::vector<Eigen::Vector2d>& path)
{
    double len = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) len += (path[i] - path[i - 1]).norm();
    return len;
}

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
    return polylineLength(path);
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

namespace
{
// Paper II-B: every chain through degree-2 vertices of `g` becomes one edge (the body of
// GraphEditor::dissolveDegreeTwo(), on any graph that `View` shows: the editor's own storage,
// or the Voronoi segments before they are stored). View: numVertices(), alive(v), pos(v),
// clearance(v), incident(v) (the incident edges in order, a loop twice), numEdges(),
// edgeAlive(e), edgeA(e), edgeB(e), pathSize(e), pathPoint(e, j), pathClearance(e, j),
// minClearance(e).
template <class View>
void joinChains(const View& g, std::vector<GraphEditor::Vertex>& new_vertices,
                std::vector<GraphEditor::Edge>& new_edges)
{
    using Edge = GraphEditor::Edge;
    const int nv = g.numVertices(), ne = g.numEdges();
    std::vector<char> anchor(nv, 0), used(ne, 0);
    for (int v = 0; v < nv; ++v)
    {
        const auto& inc = g.incident(v);
        // A degree-2 vertex on its own loop (a pure ring's vertex) stays a vertex.
        anchor[v] = g.alive(v) && (inc.size() != 2 || inc[0] == inc[1]);
    }

    // Follows edge e0 from vertex v0 through degree-2 vertices up to the next anchor.
    auto trace = [&](int v0, int e0)
    {
        Edge out;
        out.a = v0;
        out.path = {g.pos(v0)};
        out.clearance = {g.clearance(v0)};
        out.min_clearance = std::numeric_limits<double>::infinity();
        int v = v0, e = e0;
        for (;;)
        {
            used[e] = 1;
            const bool forward = g.edgeA(e) == v;
            const std::size_t n = g.pathSize(e);
            for (std::size_t k = 1; k < n; ++k)
            {
                const std::size_t j = forward ? k : n - 1 - k;
                out.path.push_back(g.pathPoint(e, j));
                out.clearance.push_back(g.pathClearance(e, j));
            }
            out.min_clearance = std::min(out.min_clearance, g.minClearance(e));
            const int w = forward ? g.edgeB(e) : g.edgeA(e);
            // Stop at an anchor before looking at its edges: a dead end has only inc[0].
            if (anchor[w])
            {
                out.b = w;
                break;
            }
            const auto& inc = g.incident(w);
            const int next = inc[0] == e ? inc[1] : inc[0];
            if (used[next])
            {
                out.b = w;
                break;
            }
            v = w;
            e = next;
        }
        out.length = polylineLength(out.path);
        new_edges.push_back(std::move(out));
    };

    for (int v = 0; v < nv; ++v)
        if (anchor[v])
            for (int e : g.incident(v))
                if (!used[e]) trace(v, e);

    // What is left are cycles of degree-2 vertices only: anchor each at its vertex of largest
    // clearance (ties: smallest position) so the choice does not depend on storage order.
    for (int e0 = 0; e0 < ne; ++e0)
    {
        if (!g.edgeAlive(e0) || used[e0]) continue;
        int best = g.edgeA(e0), v = g.edgeA(e0), e = e0;
        do
        {
            v = g.edgeA(e) == v ? g.edgeB(e) : g.edgeA(e);
            const auto& inc = g.incident(v);
            e = inc[0] == e ? inc[1] : inc[0];
            if (g.clearance(v) > g.clearance(best) ||
                (g.clearance(v) == g.clearance(best) && lessPos(g.pos(v), g.pos(best))))
                best = v;
        } while (e != e0);
        anchor[best] = 1;
        trace(best, g.incident(best)[0]);
    }

    // Rebuild: anchors with at least one edge, renumbered in their old order.
    std::vector<int> remap(nv, -1);
    for (const Edge& E : new_edges)
        for (int end : {E.a, E.b})
            if (remap[end] < 0) remap[end] = 0;  // mark: has an edge
    for (int v = 0; v < nv; ++v)
        if (anchor[v] && remap[v] == 0)
        {
            remap[v] = static_cast<int>(new_vertices.size());
            GraphEditor::Vertex nvx;
            nvx.pos = g.pos(v);
            nvx.clearance = g.clearance(v);
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
}

// The editor's own storage, for joinChains().
struct EditorView
{
    const std::vector<GraphEditor::Vertex>& v;
    const std::vector<GraphEditor::Edge>& e;
    int numVertices() const { return static_cast<int>(v.size()); }
    bool alive(int i) const { return v[i].alive; }
    const Eigen::Vector2d& pos(int i) const { return v[i].pos; }
    double clearance(int i) const { return v[i].clearance; }
    const std::vector<int>& incident(int i) const { return v[i].edges; }
    int numEdges() const { return static_cast<int>(e.size()); }
    bool edgeAlive(int i) const { return e[i].alive; }
    int edgeA(int i) const { return e[i].a; }
    int edgeB(int i) const { return e[i].b; }
    std::size_t pathSize(int i) const { return e[i].path.size(); }
    const Eigen::Vector2d& pathPoint(int i, std::size_t j) const { return e[i].path[j]; }
    double pathClearance(int i, std::size_t j) const { return e[i].clearance[j]; }
    double minClearance(int i) const { return e[i].min_clearance; }
};

// Incident edges of one vertex in a shared array (compressed rows), for SkeletonView.
struct IncidentRange
{
    const int* first;
    std::size_t n;
    std::size_t size() const { return n; }
    int operator[](std::size_t k) const { return first[k]; }
    const int* begin() const { return first; }
    const int* end() const { return first + n; }
};

// The Voronoi segments as the editor would store them (vertices numbered in order of first
// use by the segments, each segment a straight edge), without a path vector per segment.
struct SkeletonView
{
    const VoronoiSkeleton& vd;
    std::vector<int> node;            // vertex -> Voronoi node
    std::vector<int> vertex;          // Voronoi node -> vertex (-1: unused)
    std::vector<std::size_t> row;     // vertex -> first entry in `incident_edges`
    std::vector<int> incident_edges;  // per vertex, its segments in order
    explicit SkeletonView(const VoronoiSkeleton& d) : vd(d), vertex(d.node_pos.size(), -1)
    {
        for (const auto& s : vd.edges)
            for (int n : {s.a, s.b})
                if (vertex[n] < 0)
                {
                    vertex[n] = static_cast<int>(node.size());
                    node.push_back(n);
                }
        row.assign(node.size() + 1, 0);
        for (const auto& s : vd.edges) ++row[vertex[s.a] + 1], ++row[vertex[s.b] + 1];
        for (std::size_t i = 1; i < row.size(); ++i) row[i] += row[i - 1];
        incident_edges.resize(row.back());
        std::vector<std::size_t> next(row.begin(), row.end() - 1);
        for (int i = 0; i < static_cast<int>(vd.edges.size()); ++i)
        {
            incident_edges[next[vertex[vd.edges[i].a]]++] = i;
            incident_edges[next[vertex[vd.edges[i].b]]++] = i;
        }
    }
    int numVertices() const { return static_cast<int>(node.size()); }
    bool alive(int) const { return true; }
    const Eigen::Vector2d& pos(int i) const { return vd.node_pos[node[i]]; }
    double clearance(int i) const { return vd.node_clearance[node[i]]; }
    IncidentRange incident(int i) const
    {
        return {incident_edges.data() + row[i], row[i + 1] - row[i]};
    }
    int numEdges() const { return static_cast<int>(vd.edges.size()); }
    bool edgeAlive(int) const { return true; }
    int edgeA(int i) const { return vertex[vd.edges[i].a]; }
    int edgeB(int i) const { return vertex[vd.edges[i].b]; }
    std::size_t pathSize(int) const { return 2; }
    const Eigen::Vector2d& pathPoint(int i, std::size_t j) const
    {
        return vd.node_pos[j == 0 ? vd.edges[i].a : vd.edges[i].b];
    }
    double pathClearance(int i, std::size_t j) const
    {
        return vd.node_clearance[j == 0 ? vd.edges[i].a : vd.edges[i].b];
    }
    double minClearance(int i) const { return vd.edges[i].min_clearance; }
};
}  // namespace

void GraphEditor::dissolveDegreeTwo()
{
    std::vector<Vertex> new_vertices;
    std::vector<Edge> new_edges;
    joinChains(EditorView{m_v, m_e}, new_vertices, new_edges);
    m_v = std::move(new_vertices);
    m_e = std::move(new_edges);
}

GraphEditor GraphEditor::fromSkeleton(const VoronoiSkeleton& vd)
{
    GraphEditor g;
    joinChains(SkeletonView(vd), g.m_v, g.m_e);
    return g;
}

std::size_t GraphEditor::pruneDeadEnds(double max_length, double corner_ratio, double disc_ratio,
                                       double disc_max_chord)
{
    std::size_t removed = 0;
    // Two phases: the junction-disc rule judges a dead end by its junction, so it waits until
    // the short branches and the branches into corners, which make junctions of their own, are
    // gone (phase 0); then all three rules run together (phase 1). Judged at once, a wall with
    // gaps every metre (a robot map's) gave the corridor's axis a junction per gap, and the
    // corridor's real dead end, within the first such junction's disc, was cut with them.
    for (int phase = 0; phase < 2;)
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
                (phase == 1 && chord < disc_max_chord &&
                 chord < disc_ratio * m_v[junction].clearance))
                victims.push_back(e);
        }
        if (victims.empty())
        {
            ++phase;
            continue;
        }
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

void GraphEditor::keepComponents(
    double min_length, double min_room_length,
    const std::function<bool(const std::vector<const Edge*>&)>& is_room)
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
    // A part under min_length but of min_room_length is kept when it is a room (its edges
    // gathered in one pass, asked once).
    const int nc = static_cast<int>(scores.size());
    auto maybeRoom = [&](int c)
    { return c != best && scores[c].length < min_length && scores[c].length >= min_room_length; };
    std::vector<std::vector<const Edge*>> room_edges(nc);
    for (const Edge& E : m_e)
        if (E.alive && maybeRoom(comp[E.a])) room_edges[comp[E.a]].push_back(&E);
    std::vector<char> keep(nc, 0);
    for (int c = 0; c < nc; ++c)
        keep[c] = c == best || scores[c].length >= min_length ||
                  (maybeRoom(c) && is_room && is_room(room_edges[c]));
    for (int v = 0; v < nv; ++v)
        if (m_v[v].alive && !keep[comp[v]]) removeVertex(v);
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
