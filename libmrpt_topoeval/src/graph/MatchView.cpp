/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "graph/MatchView.h"

#include <algorithm>
#include <cmath>

#include "graph/ring.h"

namespace mrpt_topoeval::internal
{
int MatchView::numActive() const
{
    int n = 0;
    for (const auto& x : v) n += x.active ? 1 : 0;
    return n;
}

MatchView makeMatchView(const TopologyGraph& g)
{
    const int nv = static_cast<int>(g.vertices.size());
    // Non-spurious incidences of each vertex, in ring order.
    std::vector<std::vector<Incidence>> kept(nv);
    for (int i = 0; i < nv; ++i)
    {
        if (g.vertices[i].spurious) continue;
        for (const Incidence& inc : g.vertices[i].ring)
            if (!g.edges[inc.edge].spurious && !g.vertices[inc.other_vertex].spurious)
                kept[i].push_back(inc);
    }
    auto passThrough = [&](int i)
    { return kept[i].size() == 2 && kept[i][0].edge != kept[i][1].edge; };

    MatchView view;
    view.v.resize(nv);
    for (int i = 0; i < nv; ++i)
    {
        ViewVertex& vv = view.v[i];
        vv.clearance_m = g.vertices[i].clearance_m;
        if (kept[i].empty() || passThrough(i)) continue;
        vv.active = true;
        for (const Incidence& inc : kept[i])
        {
            // Walk through pass-through vertices to the next active vertex, adding up length
            // and length-weighted clearance. The view edge's id is the smaller of the real
            // edge ids at its two ends, so both ends name it alike.
            double len = 0.0, clr = 0.0;
            int e = inc.edge, at_other = inc.other_vertex;
            const int first = inc.edge;
            int last = inc.edge;
            for (int guard = 0; guard <= nv; ++guard)
            {
                const TopoEdge& te = g.edges[e];
                len += te.length_m;
                clr += te.mean_clearance_m * te.length_m;
                last = e;
                if (!passThrough(at_other) || at_other == i) break;
                const auto& two = kept[at_other];
                const Incidence& next = two[0].edge == e ? two[1] : two[0];
                e = next.edge;
                at_other = next.other_vertex;
            }
            vv.ring.push_back(
                {std::min(first, last), at_other, len, len > 0.0 ? clr / len : 0.0, inc.angle_rad});
        }
        vv.gaps_rad = ringGaps(vv.ring);
    }
    return view;
}

}  // namespace mrpt_topoeval::internal
