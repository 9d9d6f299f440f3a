/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Example 3: score snapshots of a map being explored, as `topoeval series` and `rawlog` do:
// the ground truth's graph is built once, each snapshot gives one row of scores.csv.
#include <mrpt_topoeval/topoeval.h>

#include <iostream>

#include "floor.h"

int main()
{
    using namespace mrpt_topoeval;
    const Parameters params;
    const mrpt::maps::COccupancyGridMap2D gt_grid = examples::floor();
    const TopologyGraph gt_graph = buildTopologyGraph(gt_grid, params.graph);

    std::cout << scoreCsvHeader() << "\n";
    int step = 0;
    for (const double explored_x_m : {8.0, 14.0, 20.0, 26.0})
    {
        const mrpt::maps::COccupancyGridMap2D snapshot = examples::floor(0.0, explored_x_m);
        const QualityReport r = evaluate(gt_graph, gt_grid, snapshot, params);
        ScoreRow row = scoreRowFromReport(r);
        row.step = ++step;
        row.entry = static_cast<std::size_t>(explored_x_m);
        std::cout << scoreCsvLine(row) << "\n";
    }
    return 0;
}
