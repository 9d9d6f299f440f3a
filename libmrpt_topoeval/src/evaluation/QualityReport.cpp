/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt_topoeval/QualityReport.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/format.h"

namespace mrpt_topoeval
{
namespace
{
using internal::fmt;

std::string consistencyLine(const QualityReport& r)
{
    std::string s;
    for (const auto& c : r.local_consistency)
        s += (s.empty() ? "" : "  ") + c.name + " " +
             (c.pairs ? fmt("%.2f", c.score) : std::string("-"));
    return s;
}
}  // namespace

double QualityReport::consistencyScore() const
{
    double sum = 0.0;
    int n = 0;
    for (const ConsistencyClass& c : local_consistency)
        if (c.pairs > 0)
        {
            sum += c.score;
            ++n;
        }
    return n ? sum / n : 0.0;
}

std::string QualityReport::briefReport() const
{
    std::string s;
    s += "quality     " + fmt("%.3f", quality) + "\n";
    s += "coverage    " + fmt("%.3f", coverage) + "  (" + std::to_string(match.pairs.size()) +
         " of " + std::to_string(gt_vertices) +
         " ground-truth vertices matched: " + std::to_string(match.isomorphism) + " isomorphism, " +
         std::to_string(match.neighbour_growing) + " neighbour growing" +
         (match.byWalls() ? ", " + std::to_string(match.byWalls()) + " placed by walls" : "") +
         ")\n";
    s += "accuracy    relative " + fmt("%.3f", relative_accuracy.rmse_m) + " m rmse (score " +
         fmt("%.2f", relative_accuracy.score) + "; " + std::to_string(relative_accuracy.by_walls) +
         " of " + std::to_string(relative_accuracy.pairs) + " pairs at their walls), global " +
         fmt("%.3f", global_accuracy.rmse_m) + " m rmse\n";
    s += "consistency " + consistencyLine(*this) + "\n";
    const std::size_t ng = brokenness.groups.size();
    const auto by_walls = std::count_if(brokenness.groups.begin(), brokenness.groups.end(),
                                        [](const BrokennessGroup& g) { return g.by_walls; });
    s += "brokenness  " + std::to_string(brokenness.degree) + " (" + std::to_string(ng) +
         (ng == 1 ? " group" : " groups") +
         (by_walls ? ", " + std::to_string(by_walls) + " placed by its walls" : std::string()) +
         ")\n";
    if (explained_walls.measured)
        s += "walls       " + fmt("%.3f", explained_walls.share) +
             " of the map's wall points explained (" + std::to_string(explained_walls.explained) +
             " of " + std::to_string(explained_walls.wall_points) + " within " +
             fmt("%.2f", explained_walls.tolerance_m) +
             " m of a ground-truth wall under a part's fit)\n";
    if (map_scale != 1.0)
        s += "scale       the map's distances x " + fmt("%.4f", map_scale) +
             " are the ground truth's (matched and brokenness measured at that scale)\n";
    return s;
}

std::string QualityReport::fullReport() const
{
    std::string s = briefReport();
    s += "\nvertices    ground truth " + std::to_string(gt_vertices) + ", map " +
         std::to_string(map_vertices) + " (matchable)\n";
    s += "isomorphisms";
    for (auto n : match.isomorphism_sizes) s += " " + std::to_string(n);
    s += "\n";
    const Transform2D& t = relative_accuracy.transform;
    s += "alignment   T_gt_map: x " + fmt("%.3f", t.x_m) + " m, y " + fmt("%.3f", t.y_m) +
         " m, yaw " + fmt("%.2f", t.yaw_deg) + " deg\n";
    s += "consistency class   graph distance      pairs   mean error   score\n";
    for (const auto& c : local_consistency)
    {
        char line[160];
        std::snprintf(line, sizeof(line), "            %-7s %6.1f .. %-8s %7zu   %8.3f m   %5.2f\n",
                      c.name.c_str(), c.min_graph_distance_m,
                      std::isfinite(c.max_graph_distance_m)
                          ? fmt("%.1f m", c.max_graph_distance_m).c_str()
                          : "inf",
                      c.pairs, c.mean_error_m, c.score);
        s += line;
    }
    s += "brokenness  group  vertices  squared error   yaw          off by\n";
    for (std::size_t i = 0; i < brokenness.groups.size(); ++i)
    {
        const auto& g = brokenness.groups[i];
        char line[160];
        std::snprintf(
            line, sizeof(line), "            %5zu  %8zu  %9.3f m^2  %6.1f deg  %s\n", i,
            g.gt_vertices.size(), g.squared_error_m2, g.transform.yaw_deg,
            i ? (fmt("%6.2f m", g.offset_m) + (g.by_walls ? "  (by its walls)" : "")).c_str()
              : "     -");
        s += line;
    }
    for (const auto& m : messages) s += "note        " + m + "\n";
    return s;
}

}  // namespace mrpt_topoeval
