/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Paper III-A, first approach: vertex similarity from attributes.

#include <gtest/gtest.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <cmath>

#include "synthetic_maps.h"

using namespace mrpt_topoeval;
using namespace mrpt_topoeval::testing;

TEST(AttributeSimilarity, SelfSimilarityIsOneAndRangeIsUnit)
{
    const TopologyGraph g = buildTopologyGraph(makeOfficeMap());
    const SimilarityMatrix s = attributeSimilarity(g, g, {});
    ASSERT_EQ(s.rows(), static_cast<Eigen::Index>(g.vertices.size()));
    EXPECT_GE(s.minCoeff(), 0.0);
    EXPECT_LE(s.maxCoeff(), 1.0 + 1e-12);
    for (std::size_t i = 0; i < g.vertices.size(); ++i)
    {
        if (g.vertices[i].spurious) continue;
        EXPECT_NEAR(s(i, i), 1.0, 1e-12) << i;
    }
}

TEST(AttributeSimilarity, IsRotationInvariantAndFindsTruePartners)
{
    // The similarity uses no position: in a rotated copy the most similar vertex of almost
    // every vertex is its true partner.
    const auto grid = makeOfficeMap();
    const double yaw = 133.0 * M_PI / 180.0;
    const Eigen::Vector2d shift(3.0, -2.0);
    const TopologyGraph a = buildTopologyGraph(grid);
    const TopologyGraph b = buildTopologyGraph(transformGrid(grid, yaw, shift));
    const SimilarityMatrix s = attributeSimilarity(a, b, {});
    int rows = 0, right = 0;
    for (std::size_t i = 0; i < a.vertices.size(); ++i)
    {
        if (a.vertices[i].spurious) continue;
        Eigen::Index best = 0;
        s.row(i).maxCoeff(&best);
        const Eigen::Vector2d want = transformPoint(grid, yaw, shift, a.vertices[i].position_m);
        ++rows;
        right +=
            (b.vertices[best].position_m - want).norm() < std::max(0.3, a.vertices[i].clearance_m);
    }
    EXPECT_GE(double(right) / rows, 0.75) << right << " of " << rows;
}

TEST(AttributeSimilarity, DegreeMismatchAndNeighboursAreWeighed)
{
    // A T junction (degree 3) against a crossing (degree 4): one unit of degree difference.
    const TopologyGraph t = buildTopologyGraph(makeTJunctionMap());
    const TopologyGraph plus = buildTopologyGraph(makePlusMap());
    VertexSimilarityParameters p;
    p.neighbour_weight = 0.0;
    int jt = -1, jp = -1;
    for (const auto& v : t.vertices)
        if (v.degree() == 3) jt = v.id;
    for (const auto& v : plus.vertices)
        if (v.degree() == 4) jp = v.id;
    ASSERT_GE(jt, 0);
    ASSERT_GE(jp, 0);
    const double full = attributeSimilarity(t, plus, p)(jt, jp);
    EXPECT_GT(full, 0.0);
    EXPECT_LE(full, 0.5);  // at most the factor 0.5 for one unit of difference
    p.degree_mismatch_factor = 0.0;
    EXPECT_EQ(attributeSimilarity(t, plus, p)(jt, jp), 0.0);
}

TEST(AttributeSimilarity, InvalidParametersAreRejected)
{
    const TopologyGraph g = buildTopologyGraph(makeTJunctionMap());
    VertexSimilarityParameters p;
    p.angle_tolerance_deg = 0.0;
    EXPECT_THROW(attributeSimilarity(g, g, p), InputError);
    p = {};
    p.neighbour_weight = 1.0;
    EXPECT_THROW(attributeSimilarity(g, g, p), InputError);
    EXPECT_THROW(similarityModeFromString("sift"), InputError);
    EXPECT_EQ(similarityModeFromString("icp"), SimilarityMode::Icp);
}

TEST(AttributeSimilarity, EmptyGraphsGiveEmptyMatrices)
{
    const TopologyGraph empty;
    const TopologyGraph g = buildTopologyGraph(makePlusMap());
    EXPECT_EQ(attributeSimilarity(empty, g, {}).rows(), 0);
    EXPECT_EQ(attributeSimilarity(g, empty, {}).cols(), 0);
}
