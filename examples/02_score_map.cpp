/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Example 2: score a map against a ground truth, both COccupancyGridMap2D in memory (paper IV).
// The map is the floor in another frame: the matcher does not trust global positions, so its
// quality stays high although every vertex is 1.5 m off.
#include <mrpt_topoeval/topoeval.h>

#include <iostream>

#include "floor.h"

int main()
{
    using namespace mrpt_topoeval;
    const mrpt::maps::COccupancyGridMap2D ground_truth = examples::floor();
    const mrpt::maps::COccupancyGridMap2D map = examples::floor(/*shift_m=*/1.5);

    const QualityReport r = evaluate(ground_truth, map, Parameters{});
    std::cout << "quality   " << r.quality << "\ncoverage  " << r.coverage << " ("
              << r.global_accuracy.pairs << " of " << r.gt_vertices << " vertices)\nglobal    "
              << r.global_accuracy.rmse_m << " m rmse\nrelative  " << r.relative_accuracy.rmse_m
              << " m rmse\nbroken    " << r.brokenness.degree << "\n";
    return r.coverage > 0.5 ? 0 : 1;
}
