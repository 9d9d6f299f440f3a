/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "evaluation/explained_walls.h"

#include <mrpt_topoeval/errors.h>

namespace mrpt_topoeval::internal
{
ExplainedWalls explainedWalls(const TopologyGraph& map, const TopologyGraph& placed,
                              const std::vector<Transform2D>& fits, const WallIndex& gt_walls,
                              double tolerance_m, std::vector<Eigen::Vector2f>* placed_explained)
{
    ExplainedWalls e;
    e.tolerance_m = tolerance_m;
    if (placed.wall_points_m.size() != map.wall_points_m.size())
        throw InputError("the map's graph for its walls' places is not the map's graph");
    if (fits.empty() || map.wall_points_m.empty() || gt_walls.empty()) return e;
    e.measured = true;
    e.wall_points = map.wall_points_m.size();
    for (std::size_t i = 0; i < map.wall_points_m.size(); ++i)
    {
        const Eigen::Vector2d q = placed.wall_points_m[i].cast<double>();
        bool near = false;
        // Any part explains a wall: a broken map's parts each carry their own walls.
        for (const Transform2D& t : fits)
            if (const Eigen::Vector2d at = t.apply(q); gt_walls.near(at, tolerance_m))
            {
                near = true;
                if (placed_explained) placed_explained->push_back(at.cast<float>());
                break;
            }
        if (near)
            ++e.explained;
        else
            e.unexplained_m.push_back(map.wall_points_m[i]);
    }
    e.share = double(e.explained) / double(e.wall_points);
    return e;
}
}  // namespace mrpt_topoeval::internal
