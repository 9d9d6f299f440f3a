/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The scale pass (ours, issue 11; doc/matching.md, "A map at another scale"): a map whose
// distances are all off by one factor (a floor plan with a wrong resolution in its YAML) is
// matched and its brokenness measured at the ground truth's scale, and the factor is reported.
// On maps made in code whose answer is known: the campus, moved and read 5 % too large.

#include <gtest/gtest.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/GraphMatch.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/pipeline/evaluate.h>

#include <Eigen/Core>
#include <cmath>

#include "../libmrpt_topoeval/src/pipeline/map_scale.h"
#include "synthetic_maps.h"

using namespace mrpt_topoeval;
using namespace mrpt_topoeval::testing;
using mrpt::maps::COccupancyGridMap2D;

namespace
{
constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Every vertex of `g` paired with itself, as group `group` (an isomorphism of the match).
GraphMatch selfMatch(const TopologyGraph& g)
{
    GraphMatch m;
    for (const auto& v : g.vertices)
        if (!v.spurious) m.pairs.push_back({v.id, v.id, MatchStage::Isomorphism, 1.0, 0});
    m.isomorphism = m.pairs.size();
    m.isomorphism_sizes = {m.pairs.size()};
    return m;
}

// The campus moved (turned 31 degrees and shifted) and read `factor` times too large.
COccupancyGridMap2D campusMovedAndReadAt(double factor)
{
    return internal::scaledGrid(transformGrid(makeCampusMap(), 31 * kDeg, {4.0, -2.0}), factor);
}

// The map's graph given back by evaluate() is the map's own, not the one read at the ground
// truth's scale.
void expectTheMapsOwnGraph(const TopologyGraph& given, const COccupancyGridMap2D& map)
{
    const TopologyGraph own = buildTopologyGraph(map, Parameters{}.graph);
    ASSERT_EQ(given.vertices.size(), own.vertices.size());
    for (std::size_t i = 0; i < own.vertices.size(); ++i)
        EXPECT_EQ(given.vertices[i].position_m, own.vertices[i].position_m);
}
}  // namespace

// The factor from the match's groups: exact on a graph read at another scale, and the same
// when one part of it is also turned (the parts' rotations do not enter).
TEST(MapScale, IsTheFactorTheGroupsShow)
{
    const TopologyGraph g = buildTopologyGraph(makeCampusMap(), {});
    const TopologyGraph big = internal::scaledGraph(g, 1.05);
    EXPECT_NEAR(big.vertices[3].position_m.x(), 1.05 * g.vertices[3].position_m.x(), 1e-12);
    EXPECT_NEAR(big.vertices[3].clearance_m, 1.05 * g.vertices[3].clearance_m, 1e-12);
    EXPECT_NEAR(big.totalEdgeLength(), 1.05 * g.totalEdgeLength(), 1e-9);

    GraphMatch m = selfMatch(g);
    const internal::MapScale one = internal::mapScaleOf(g, big, m);
    EXPECT_NEAR(one.scale, 1.0 / 1.05, 1e-9);
    EXPECT_LT(one.std_error, 1e-9);
    EXPECT_EQ(one.groups, 1u);

    // The east half of the map turned 20 degrees, as its own group: the same factor.
    TopologyGraph turned = big;
    const double c = std::cos(20 * kDeg), s = std::sin(20 * kDeg);
    for (auto& v : turned.vertices)
        if (v.position_m.x() > 1.05 * 30.0)
            v.position_m = Eigen::Vector2d(c * v.position_m.x() - s * v.position_m.y(),
                                           s * v.position_m.x() + c * v.position_m.y());
    for (auto& p : m.pairs)
        if (g.vertices[p.ground_truth].position_m.x() > 30.0) p.isomorphism = 1;
    m.isomorphism_sizes = {0, 0};
    for (const auto& p : m.pairs) ++m.isomorphism_sizes[p.isomorphism];
    const internal::MapScale two = internal::mapScaleOf(g, turned, m);
    EXPECT_EQ(two.groups, 2u);
    EXPECT_NEAR(two.scale, 1.0 / 1.05, 1e-9);

    // Fewer than 3 pairs per group: no evidence.
    GraphMatch few;
    few.pairs = {m.pairs[0], m.pairs[1]};
    EXPECT_EQ(internal::mapScaleOf(g, big, few).groups, 0u);
    EXPECT_EQ(internal::mapScaleOf(g, big, few).scale, 1.0);

    // The grid read with wider cells: the same cells, at `s` times their world points.
    const COccupancyGridMap2D grid = makeCampusMap();
    const COccupancyGridMap2D wide = internal::scaledGrid(grid, 1.05);
    ASSERT_EQ(wide.getSizeX(), grid.getSizeX());
    ASSERT_EQ(wide.getSizeY(), grid.getSizeY());
    EXPECT_NEAR(wide.idx2x(17), 1.05 * grid.idx2x(17), 1e-6);  // MRPT keeps cells in float
    EXPECT_EQ(wide.getCell(120, 80), grid.getCell(120, 80));
}

// The campus, moved and read 5 % too large: without the pass its match falls into groups no
// wider than the pairwise tolerance forgives, counted as breaks; with it the map is one part,
// the factor is reported, and accuracy still pays for the map's distances as given.
TEST(ScalePass, AMapReadFivePercentTooLargeIsOnePartAtItsScale)
{
    const COccupancyGridMap2D campus = makeCampusMap();
    const COccupancyGridMap2D big = campusMovedAndReadAt(1.05);

    Parameters off;
    off.matcher.scale_min_error = 0.0;
    const QualityReport without = evaluate(campus, big, off);
    EXPECT_GE(without.brokenness.degree, 1);
    EXPECT_EQ(without.map_scale, 1.0);

    TopologyGraph m;
    const QualityReport with = evaluate(campus, big, Parameters{}, nullptr, &m);
    EXPECT_NEAR(with.map_scale, 1.0 / 1.05, 0.003);
    EXPECT_EQ(with.brokenness.degree, 0);
    EXPECT_GE(with.coverage, 0.9);
    EXPECT_GE(with.coverage, without.coverage);
    EXPECT_GT(with.quality, without.quality);
    // Accuracy measures the map as given: 5 % of a 60 m campus is metres off at its ends.
    EXPECT_GT(with.relative_accuracy.rmse_m, 0.3);
    expectTheMapsOwnGraph(m, big);

    // A map at the ground truth's scale is left as it is.
    const QualityReport same = evaluate(campus, campusMovedAndReadAt(1.0), Parameters{});
    EXPECT_EQ(same.map_scale, 1.0);
    EXPECT_EQ(same.brokenness.degree, 0);
}

// The scale search: the campus, moved and read 12 % too large, matches nothing as it is (no
// group as wide as the pairwise tolerance forgives is significant; at 10 % the scale pass
// still finds it); read at the search's steps it is found, its factor refined from the
// groups, and it is one part. Another building stays unmatched at every step.
TEST(ScaleSearch, AMapThatMatchesNothingAtItsOwnScaleIsFoundAtAnother)
{
    const COccupancyGridMap2D campus = makeCampusMap();
    const COccupancyGridMap2D big = campusMovedAndReadAt(1.12);

    Parameters off;
    off.matcher.scale_search_step = 0.0;
    const QualityReport without = evaluate(campus, big, off);
    EXPECT_TRUE(without.match.pairs.empty());
    EXPECT_EQ(without.quality, 0.0);

    TopologyGraph m;
    const QualityReport with = evaluate(campus, big, Parameters{}, nullptr, &m);
    EXPECT_NEAR(with.map_scale, 1.0 / 1.12, 0.003);
    EXPECT_EQ(with.brokenness.degree, 0);
    EXPECT_GE(with.coverage, 0.9);
    // Accuracy measures the map as given (12 % of 60 m), and the graph given back is the map's.
    EXPECT_GT(with.relative_accuracy.rmse_m, 0.6);
    expectTheMapsOwnGraph(m, big);
    bool said = false;
    for (const auto& text : with.messages) said |= text.rfind("scale search:", 0) == 0;
    EXPECT_TRUE(said);

    // Another campus (another seed) read at every step: still nothing.
    const QualityReport other = evaluate(campus, makeCampusMap(2), Parameters{});
    EXPECT_LE(other.coverage, 0.1);
    EXPECT_EQ(other.map_scale, 1.0);
}
