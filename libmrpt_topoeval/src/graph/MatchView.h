/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// The graph as the matcher sees it (paper III-B: "spurious edges and vertices ... may have to
// be ignored"): spurious vertices and edges are left out, and a vertex left with two edges is
// only a point on a corridor, so the view passes through it: its two edges become one view
// edge. Two maps of the same place then agree on the view even where one has a spur the other
// lacks.

#include <mrpt_topoeval/TopologyGraph.h>

#include <vector>

namespace mrpt_topoeval::internal
{
struct ViewIncidence
{
    int edge = -1;   //!< Edge index in the TopologyGraph.
    int other = -1;  //!< Vertex at the other end (itself for a loop).
    double length_m = 0.0;
    double mean_clearance_m = 0.0;
    double angle_rad = 0.0;  //!< Leaving direction, world frame.
};

struct ViewVertex
{
    /** Matchable: non-spurious, with at least one non-spurious edge, and not a pass-through
     * vertex of degree 2 (a ring vertex on its own loop is active). */
    bool active = false;
    double clearance_m = 0.0;
    /** Non-spurious incident edges, counter-clockwise (the TopologyGraph's ring order). */
    std::vector<ViewIncidence> ring;
    /** Angle from ring[i] to ring[i+1] counter-clockwise; sums to 2 pi [rad]. */
    std::vector<double> gaps_rad;

    int degree() const { return static_cast<int>(ring.size()); }
};

struct MatchView
{
    std::vector<ViewVertex> v;  //!< Indexed by vertex id.
    int numActive() const;
};

MatchView makeMatchView(const TopologyGraph& g);

}  // namespace mrpt_topoeval::internal
