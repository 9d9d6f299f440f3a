/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Downstream consumer: builds a plus-shaped corridor and checks its Topology Graph has one
// junction of degree 4 (and otherwise only dead ends).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/graph/build_graph.h>
// The deprecated header names still compile in an installed package (they forward).
#include <mrpt_topoeval/GraphBuilder.h>
#include <mrpt_topoeval/GraphMatcher.h>
#include <mrpt_topoeval/QualityEvaluator.h>
#include <mrpt_topoeval/VertexSimilarity.h>

#include <cmath>
#include <exception>
#include <iostream>

namespace
{
// A 16 m x 16 m solid block with two corridors 1.5 m wide crossing at (8, 8), arms 6 m long.
mrpt::maps::COccupancyGridMap2D makePlus()
{
    constexpr float res = 0.05f, size = 16.0f, centre = 8.0f, half_width = 0.75f, arm = 6.0f;
    mrpt::maps::COccupancyGridMap2D grid(0.0f, size, 0.0f, size, res);
    grid.fill(0.0f);  // P(free) = 0: occupied
    // Whole cells [x0, x1) x [y0, y1), rounded (x2idx truncates 7.25 / 0.05 to 144).
    const auto cell = [&](float m) { return static_cast<int>(std::lround(m / res)); };
    const auto carve = [&](float x0, float y0, float x1, float y1)
    {
        for (int cy = cell(y0); cy < cell(y1); ++cy)
            for (int cx = cell(x0); cx < cell(x1); ++cx) grid.setCell(cx, cy, 1.0f);
    };
    carve(centre - arm, centre - half_width, centre + arm, centre + half_width);
    carve(centre - half_width, centre - arm, centre + half_width, centre + arm);
    return grid;
}
}  // namespace

int main()
{
    try
    {
        const auto grid = makePlus();
        const mrpt_topoeval::TopologyGraph graph = mrpt_topoeval::buildTopologyGraph(grid);

        int degree4 = 0, dead_ends = 0, other = 0;
        for (const auto& v : graph.vertices)
        {
            if (v.degree() == 4)
                ++degree4;
            else if (v.degree() == 1)
                ++dead_ends;
            else
                ++other;
        }
        std::cout << "vertices: " << graph.vertices.size() << " (degree 4: " << degree4
                  << ", dead ends: " << dead_ends << ", other: " << other
                  << "), edges: " << graph.edges.size() << "\n";
        if (degree4 != 1 || other != 0)
        {
            std::cerr << "expected exactly one vertex of degree 4 and otherwise dead ends\n";
            return 1;
        }
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
}
