/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The clutter pass (ours, issue 11; doc/matching.md, "The clutter pass"): after a first match,
// the map's free-standing obstacles that the ground truth lacks where the match puts them are
// made free and the map is matched again. On maps made in code whose answer is known: a plan
// with a columned hall, and the same building furnished with desks.

#include <gtest/gtest.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/pipeline/evaluate.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "../libmrpt_topoeval/src/pipeline/clutter.h"
#include "synthetic_maps.h"
#include "test_paths.h"

using namespace mrpt_topoeval;
using namespace mrpt_topoeval::testing;
using mrpt::maps::COccupancyGridMap2D;

namespace
{
constexpr double kPi = 3.14159265358979323846;

// The desks of the furnished building [m]: 1.6 x 0.8 m, free-standing, in the hall and in the
// offices east of it.
const std::vector<std::pair<double, double>> kDesks{{3.0, 10.0},  {7.0, 11.6}, {12.6, 9.0},
                                                    {17.5, 11.5}, {25.8, 9.6}, {36.0, 9.8}};
// The hall's columns (0.6 m square), in the plan and in the map alike: building structure.
const std::vector<std::pair<double, double>> kColumns{{10.0, 11.0}, {15.0, 10.0}};

// hallBuildingSketch() with two columns in its hall; `furnished` adds the desks.
COccupancyGridMap2D building(bool furnished)
{
    GridSketch s = hallBuildingSketch();
    for (auto [cx, cy] : kColumns) s.fill(cx - 0.3, cy - 0.3, cx + 0.3, cy + 0.3);
    if (furnished)
        for (auto [x0, y0] : kDesks) s.fill(x0, y0, x0 + 1.6, y0 + 0.8);
    return s.grid();
}

bool occupiedAt(const COccupancyGridMap2D& g, const Eigen::Vector2d& p)
{
    return g.getCell(g.x2idx(p.x()), g.y2idx(p.y())) < 0.5f;
}

// Pairs whose map vertex lies within 0.5 m of its ground-truth vertex once moved back by
// `to_gt` (the validation corpus's pair tolerance).
std::size_t truePairs(const TopologyGraph& gt, const TopologyGraph& map, const QualityReport& r,
                      const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& to_gt)
{
    std::size_t n = 0;
    for (const auto& pr : r.match.pairs)
        n += (to_gt(map.vertices[pr.map].position_m) - gt.vertices[pr.ground_truth].position_m)
                 .norm() <= 0.5;
    return n;
}

bool saysClutter(const QualityReport& r)
{
    return std::any_of(r.messages.begin(), r.messages.end(),
                       [](const std::string& m) { return m.rfind("clutter pass", 0) == 0; });
}
}  // namespace

TEST(ClutterPass, TheMapsDesksAreClutterTheColumnsAreNot)
{
    // Known answer: every desk is within the reach of a matched vertex (the hall's, the
    // offices'), no desk lies on a wall of the plan, and the columns are the plan's. The map is
    // turned and shifted: the pass uses the match's alignments, never the maps' frames.
    const COccupancyGridMap2D plain = building(false);
    const double yaw = 37.0 * kPi / 180.0;
    const Eigen::Vector2d shift(3.0, -2.0);
    const COccupancyGridMap2D furnished = transformGrid(building(true), yaw, shift);
    Parameters p;
    p.matcher.clutter_passes = 0;
    TopologyGraph gt, map;
    const QualityReport first = evaluate(plain, furnished, p, &gt, &map);
    ASSERT_GE(first.match.pairs.size(), 5u);

    std::size_t removed = 0, judged = 0;
    const auto edited =
        internal::withoutClutter(gt, map, furnished, first.match, p, removed, judged);
    ASSERT_TRUE(edited.has_value());
    EXPECT_EQ(removed, kDesks.size());
    EXPECT_EQ(judged, kDesks.size() + kColumns.size());
    const COccupancyGridMap2D source = building(true);
    for (auto [x0, y0] : kDesks)
    {
        const Eigen::Vector2d c = transformPoint(source, yaw, shift, {x0 + 0.8, y0 + 0.4});
        EXPECT_TRUE(occupiedAt(furnished, c));
        EXPECT_FALSE(occupiedAt(*edited, c)) << "desk at " << x0 << ", " << y0;
    }
    for (auto [cx, cy] : kColumns)
        EXPECT_TRUE(occupiedAt(*edited, transformPoint(source, yaw, shift, {cx, cy})))
            << "column at " << cx << ", " << cy;
}

TEST(ClutterPass, AFurnishedMapIsMatchedAsItsPlan)
{
    // The desks make the hall a mesh of loops: the first match misses the hall's and the east
    // offices' vertices. Without the desks the map's graph is the plan's, so the second match
    // pairs every vertex of the plan, each true.
    const COccupancyGridMap2D plain = building(false), furnished = building(true);
    Parameters off;
    off.matcher.clutter_passes = 0;
    const Parameters on;
    TopologyGraph gt, map_off, map_on;
    const QualityReport r_off = evaluate(plain, furnished, off, &gt, &map_off);
    const QualityReport r_on = evaluate(plain, furnished, on, nullptr, &map_on);
    const auto same = [](const Eigen::Vector2d& q) { return q; };
    EXPECT_FALSE(saysClutter(r_off));
    EXPECT_TRUE(saysClutter(r_on));
    EXPECT_GT(r_on.match.pairs.size(), r_off.match.pairs.size());
    EXPECT_EQ(r_on.match.pairs.size(), r_on.gt_vertices);  // coverage 1
    EXPECT_EQ(truePairs(gt, map_on, r_on, same), r_on.match.pairs.size());
    EXPECT_GT(r_on.quality, r_off.quality);
    // The graph returned is the one the match was made on: no loop around a desk is left.
    EXPECT_LT(map_on.vertices.size(), map_off.vertices.size());
}

TEST(ClutterPass, NothingChangesWithoutClutterOrWithThePapersMethod)
{
    // An unfurnished copy has no island the plan lacks (its columns are the plan's): the pass
    // finds nothing and the report is the first match's. method = paper keeps the paper's
    // pipeline: no pass.
    const COccupancyGridMap2D plain = building(false), furnished = building(true);
    Parameters off;
    off.matcher.clutter_passes = 0;
    const Parameters on;
    const QualityReport same_on = evaluate(plain, plain, on);
    const QualityReport same_off = evaluate(plain, plain, off);
    EXPECT_FALSE(saysClutter(same_on));
    EXPECT_EQ(same_on.match.pairs.size(), same_off.match.pairs.size());
    EXPECT_DOUBLE_EQ(same_on.quality, same_off.quality);
    Parameters paper;
    paper.matcher.method = MatchMethod::Paper;
    EXPECT_FALSE(saysClutter(evaluate(plain, furnished, paper)));
}

TEST(ClutterPass, AMapFurnishedEverywhereStartsFromItsIslandsFreed)
{
    // Held-out warehouse_1002/furniture (tests/data/furnished_everywhere): pallets around every
    // junction, and the plan's columns in both maps. The map's own match pairs nothing, so the
    // pass has no alignment to judge by. With clutter_start_without_islands it judges first by
    // the match of the map with all its islands freed (the columns too), and frees only what
    // the plan lacks. Known answer: the map is the plan's grid (same frame), so a pair is true
    // when its vertices are within the corpus's tolerance of each other.
    const auto [gt_grid, map_grid] = corpusCase("furnished_everywhere", "warehouse_1002_furniture");
    Parameters off;
    off.matcher.clutter_start_without_islands = false;
    const Parameters on;
    const QualityReport r_off = evaluate(gt_grid, map_grid, off);
    EXPECT_TRUE(r_off.match.pairs.empty());
    EXPECT_FALSE(saysClutter(r_off));

    TopologyGraph gt, map;
    const QualityReport r_on = evaluate(gt_grid, map_grid, on, &gt, &map);
    const auto message =
        std::find_if(r_on.messages.begin(), r_on.messages.end(),
                     [](const std::string& m) { return m.rfind("clutter pass", 0) == 0; });
    ASSERT_NE(message, r_on.messages.end());
    EXPECT_NE(message->find("with all its"), std::string::npos) << *message;
    EXPECT_GE(r_on.coverage, 0.9);
    std::size_t true_pairs = 0;
    for (const auto& pr : r_on.match.pairs)
    {
        const auto& g = gt.vertices[pr.ground_truth];
        const auto& m = map.vertices[pr.map];
        true_pairs += (g.position_m - m.position_m).norm() <=
                      std::max(0.5, 0.5 * std::max(g.clearance_m, m.clearance_m));
    }
    EXPECT_EQ(true_pairs, r_on.match.pairs.size());
    EXPECT_GT(r_on.quality, 0.9);

    // The first round, step by step: the map with all its islands freed (the columns too) is
    // matched, and by that match only what the plan lacks is freed: every column of the plan
    // (its own islands) is still in the map. (13 of the map's 27 islands are freed in this
    // round, those within reach of its 5 pairs; the next pass frees 5 more.)
    Parameters no_pass;
    no_pass.matcher.clutter_passes = 0;
    std::size_t n_map_islands = 0, n_columns = 0, removed = 0, judged = 0;
    const auto bare = internal::withoutIslands(map_grid, on, n_map_islands);
    const auto columns = internal::withoutIslands(gt_grid, on, n_columns);
    ASSERT_TRUE(bare && columns);
    TopologyGraph bare_graph;
    const QualityReport start = evaluate(gt, gt_grid, *bare, no_pass, &bare_graph);
    ASSERT_GE(start.match.pairs.size(), 3u);
    const auto edited =
        internal::withoutClutter(gt, bare_graph, map_grid, start.match, on, removed, judged);
    ASSERT_TRUE(edited);
    EXPECT_GT(removed, 0u);
    EXPECT_GT(n_columns, 0u);
    EXPECT_LE(removed + n_columns, n_map_islands);
    std::size_t column_cells = 0, kept = 0;
    for (unsigned y = 0; y < gt_grid.getSizeY(); ++y)
        for (unsigned x = 0; x < gt_grid.getSizeX(); ++x)
            if (gt_grid.getCell(x, y) < 0.5f && columns->getCell(x, y) > 0.5f)
            {
                ++column_cells;
                kept += edited->getCell(x, y) < 0.5f;
            }
    EXPECT_GT(column_cells, 0u);
    EXPECT_EQ(kept, column_cells);
}
