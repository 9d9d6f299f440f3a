/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// Ours (issue 11): the walls around matched vertices, aligned by ICP, measure what the vertices
// cannot: where a pair's ground-truth vertex lies in the map though the vertex slid along the
// medial axis (relative accuracy and local consistency, doc/quality.md "Measured at the walls"),
// and a part's turn (brokenness step 7, in evaluate_match.cpp).

#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/evaluation/evaluate_match.h>
#include <mrpt_topoeval/geometry/Transform2D.h>

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "matching/wall_agreement.h"

namespace mrpt_topoeval::internal
{
// The ICP of walls (a brokenness group's turn, a pair's place): alignWallsByIcp() with a first
// matching distance of the larger of reach_m and the error a part's fit allows (the root of
// brokenness_max_squared_error_m2). None when either map has fewer than 20 wall points there (a
// bare plan's few walls).
std::optional<Transform2D> alignWalls(const TopologyGraph& gt, const TopologyGraph& map,
                                      const WallIndex& gt_walls, const WallIndex& map_walls,
                                      const std::vector<std::pair<int, int>>& pairs,
                                      double margin_m, const Transform2D& start,
                                      const QualityParameters& p, double reach_m = 0.0);

// A wall point agrees with the other map's when one lies within this: pair_wall_tolerance_m,
// at least 1.5 cells of the coarser map (a point's place is only known to its cell).
double pairWallTolerance(const TopologyGraph& gt, const TopologyGraph& map,
                         const QualityParameters& p);

// Both graphs' wall points in KD-trees, built on first use and shared by the steps that align
// walls (pair places, brokenness groups' turns). `ok()` is false when either graph has none.
class Walls
{
public:
    Walls(const TopologyGraph& gt, const TopologyGraph& map) : m_gt_graph(gt), m_map_graph(map) {}
    bool ok() const
    {
        return !m_gt_graph.wall_points_m.empty() && !m_map_graph.wall_points_m.empty();
    }
    const WallIndex& gt()
    {
        if (!m_gt) m_gt.emplace(m_gt_graph.wall_points_m);
        return *m_gt;
    }
    const WallIndex& map()
    {
        if (!m_map) m_map.emplace(m_map_graph.wall_points_m);
        return *m_map;
    }

private:
    const TopologyGraph &m_gt_graph, &m_map_graph;
    std::optional<WallIndex> m_gt, m_map;
};

// Ours (pair_wall_margin_m): where the map's walls put each pair's ground-truth vertex. The
// walls around the ground-truth vertex and those around its partner are aligned by ICP from the
// relative alignment `t`; the map point that alignment puts on the ground-truth vertex stands in
// for the map vertex in relative accuracy and local consistency, with no slack: a vertex slides
// along the medial axis of its room between two maps, its walls stay. Kept only when the walls
// agree under that alignment and pin it (an ICP that found nothing to align would leave the
// error where it started, and walls along a corridor do not fix a place along it), and within
// the larger clearance of the two vertices (farther, ICP was caught by other walls: the vertex
// cannot have slid that far from its place). `places` and `slack` come in as the vertices'.
void placeByWalls(const TopologyGraph& gt, const TopologyGraph& map, const GraphMatch& m,
                  const Transform2D& t, const QualityParameters& p, Walls& walls,
                  std::vector<Eigen::Vector2d>& places, std::vector<double>& slack,
                  std::size_t& by_walls);

}  // namespace mrpt_topoeval::internal
