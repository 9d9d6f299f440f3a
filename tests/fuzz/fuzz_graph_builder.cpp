/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The whole pipeline on small random grids: buildTopologyGraph, attributeSimilarity against a
// fixed plus-shaped corridor map and back, matchGraphs and evaluateMatch. Bytes: width, height
// (1..64 cells each), resolution (0.05, 0.1 or 0.2 m), then 4 cells per byte (2 bits each:
// free, occupied, unknown, free); missing bytes are free.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/evaluation/evaluate_match.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/matching/match_graphs.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <cstdlib>

#include "fuzz_common.h"

namespace
{
using mrpt::maps::COccupancyGridMap2D;

/** A plus-shaped corridor crossing (4 dead ends and a junction) of 60 x 60 cells at 0.1 m. */
COccupancyGridMap2D makePlus()
{
    constexpr int n = 60, half_width = 6;
    COccupancyGridMap2D g(0.0f, n * 0.1f, 0.0f, n * 0.1f, 0.1f);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
        {
            const bool in_h = std::abs(y - n / 2) <= half_width && x > 2 && x < n - 3;
            const bool in_v = std::abs(x - n / 2) <= half_width && y > 2 && y < n - 3;
            g.setCell(x, y, in_h || in_v ? 1.0f : 0.0f);
        }
    return g;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace mrpt_topoeval;
    if (size < 3) return 0;
    static const TopologyGraph fixed = buildTopologyGraph(makePlus());

    const int w = 1 + data[0] % 64, h = 1 + data[1] % 64;
    static const float kRes[] = {0.05f, 0.1f, 0.2f};
    const float res = kRes[data[2] % 3];
    COccupancyGridMap2D grid(0.0f, w * res, 0.0f, h * res, res);
    static const float kCell[] = {1.0f, 0.0f, 0.5f, 1.0f};
    for (int i = 0; i < w * h; ++i)
    {
        const std::size_t byte = 3 + static_cast<std::size_t>(i) / 4;
        const int code = byte < size ? (data[byte] >> (2 * (i % 4))) & 3 : 0;
        // setCell on the grid's own size; x2idx rounding could otherwise leave a row unset.
        if (i % w < static_cast<int>(grid.getSizeX()) && i / w < static_cast<int>(grid.getSizeY()))
            grid.setCell(i % w, i / w, kCell[code]);
    }

    // Valid parameters and a valid grid: nothing here may throw, not even InputError.
    const TopologyGraph graph = buildTopologyGraph(grid);
    const VertexSimilarityParameters sim;
    for (const auto& [gt, map] : {std::pair{&fixed, &graph}, std::pair{&graph, &fixed}})
    {
        const SimilarityMatrix s = attributeSimilarity(*gt, *map, sim);
        const GraphMatch match = matchGraphs(*gt, *map, s);
        evaluateMatch(*gt, *map, match);
    }
    return 0;
}
