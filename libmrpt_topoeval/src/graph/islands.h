/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// How wide a free-standing obstacle (an island of non-free cells) is: the graph builder removes
// the narrower than min_island_size_m, the clutter pass judges those from there up to
// clutter_max_size_m, so both measure it alike.

#include <opencv2/imgproc.hpp>
#include <vector>

namespace mrpt_topoeval::internal
{
/** The island's width [cells]: its smallest enclosing circle, whose diameter the cell centres
 * span, plus about one cell for the cells' squares. */
inline double islandWidthCells(const std::vector<cv::Point2f>& cells, cv::Point2f* centre = nullptr)
{
    cv::Point2f c;
    float radius = 0.0f;
    cv::minEnclosingCircle(cells, c, radius);
    if (centre) *centre = c;
    return 2.0 * radius + 1.0;
}
}  // namespace mrpt_topoeval::internal
