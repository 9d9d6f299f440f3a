/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Paper III-A, second approach: ICP similarity of vertices. The answer is built first: the
// office map and a copy moved by a known rotation and shift, so each ground-truth vertex's true
// partner is the map vertex where the transform puts it; ICP must rate that one the highest.

#include <gtest/gtest.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <cmath>
#include <functional>
#include <map>
#include <string>

#include "synthetic_maps.h"

using namespace mrpt_topoeval;
using namespace mrpt_topoeval::testing;
using mrpt::maps::COccupancyGridMap2D;

namespace
{
constexpr double kYaw = 37.0 * M_PI / 180.0;
const Eigen::Vector2d kShift{2.5, -1.0};

/** Degree counting only non-spurious edges to non-spurious vertices (what the matcher and the
 * ICP pruning see); -1 for a spurious vertex. */
int nonSpuriousDegree(const TopologyGraph& g, int v)
{
    const TopoVertex& tv = g.vertices[v];
    if (tv.spurious) return -1;
    int d = 0;
    for (const Incidence& inc : tv.ring)
        if (!g.edges[inc.edge].spurious && !g.vertices[inc.other_vertex].spurious) ++d;
    return d;
}

VertexSimilarityParameters icpParams(int threads)
{
    VertexSimilarityParameters p;
    p.mode = SimilarityMode::Icp;
    p.threads = threads;
    return p;
}

/** The office and its moved copy, graphs and the ICP similarity (2 threads), built once. */
class IcpOffice : public ::testing::Test
{
protected:
    static void SetUpTestSuite()
    {
        grid_gt = new COccupancyGridMap2D(makeOfficeMap());
        grid_map = new COccupancyGridMap2D(transformGrid(*grid_gt, kYaw, kShift));
        gt = new TopologyGraph(buildTopologyGraph(*grid_gt));
        map = new TopologyGraph(buildTopologyGraph(*grid_map));
        timing = new std::map<std::string, double>();
        sim = new SimilarityMatrix(
            icpSimilarity(*gt, *grid_gt, *map, *grid_map, icpParams(2), timing));
    }
    static void TearDownTestSuite()
    {
        delete sim;
        delete timing;
        delete map;
        delete gt;
        delete grid_map;
        delete grid_gt;
    }

    /** The map vertex within 0.3 m of where the transform puts gt vertex i, or -1. */
    static int truePartner(int i)
    {
        const Eigen::Vector2d want =
            transformPoint(*grid_gt, kYaw, kShift, gt->vertices[i].position_m);
        int best = -1;
        double best_d = 0.3;
        for (const TopoVertex& v : map->vertices)
        {
            const double d = (v.position_m - want).norm();
            if (d <= best_d)
            {
                best_d = d;
                best = v.id;
            }
        }
        return best;
    }

    static COccupancyGridMap2D* grid_gt;
    static COccupancyGridMap2D* grid_map;
    static TopologyGraph* gt;
    static TopologyGraph* map;
    static SimilarityMatrix* sim;
    static std::map<std::string, double>* timing;
};
COccupancyGridMap2D* IcpOffice::grid_gt = nullptr;
COccupancyGridMap2D* IcpOffice::grid_map = nullptr;
TopologyGraph* IcpOffice::gt = nullptr;
TopologyGraph* IcpOffice::map = nullptr;
SimilarityMatrix* IcpOffice::sim = nullptr;
std::map<std::string, double>* IcpOffice::timing = nullptr;

}  // namespace

TEST_F(IcpOffice, MatrixHasOneRowPerGroundTruthVertexAndValuesInUnitRange)
{
    ASSERT_GE(gt->numNonSpuriousVertices(), 10u) << "the office should give a rich graph";
    ASSERT_EQ(sim->rows(), static_cast<Eigen::Index>(gt->vertices.size()));
    ASSERT_EQ(sim->cols(), static_cast<Eigen::Index>(map->vertices.size()));
    EXPECT_GE(sim->minCoeff(), 0.0);
    EXPECT_LE(sim->maxCoeff(), 1.0);
    for (const char* key : {"clouds", "icp", "total"})
    {
        ASSERT_TRUE(timing->count(key)) << key;
        EXPECT_GE(timing->at(key), 0.0) << key;
    }
}

TEST_F(IcpOffice, TruePartnerIsTheMostSimilarMapVertex)
{
    int with_partner = 0, right = 0, high = 0, non_spurious = 0;
    for (const TopoVertex& v : gt->vertices)
    {
        if (nonSpuriousDegree(*gt, v.id) <= 0) continue;
        ++non_spurious;
        const int partner = truePartner(v.id);
        if (partner < 0) continue;
        ++with_partner;
        Eigen::Index best = 0;
        sim->row(v.id).maxCoeff(&best);
        const double s_true = (*sim)(v.id, partner);
        // Ties with the true partner (symmetric rooms) count as right.
        if (best == partner || s_true >= (*sim)(v.id, best)) ++right;
        if (s_true > 0.6) ++high;
        EXPECT_EQ(nonSpuriousDegree(*gt, v.id), nonSpuriousDegree(*map, partner))
            << "gt vertex " << v.id << ": the moved copy should keep the degree";
    }
    ASSERT_GE(with_partner, 0.9 * non_spurious) << "the moved copy's graph should be the same";
    EXPECT_GE(right, 0.9 * with_partner) << right << " of " << with_partner;
    EXPECT_GE(high, 0.8 * with_partner) << high << " of " << with_partner << " above 0.6";
}

TEST_F(IcpOffice, PairsOfDifferentDegreeAndSpuriousVerticesGetZero)
{
    int checked = 0;
    for (const TopoVertex& a : gt->vertices)
        for (const TopoVertex& b : map->vertices)
        {
            const int da = nonSpuriousDegree(*gt, a.id);
            const int db = nonSpuriousDegree(*map, b.id);
            if (da > 0 && db > 0 && da == db) continue;
            EXPECT_EQ((*sim)(a.id, b.id), 0.0) << "degrees " << da << ", " << db;
            ++checked;
        }
    EXPECT_GT(checked, 0);
}

TEST_F(IcpOffice, ResultDoesNotDependOnTheThreadCount)
{
    const SimilarityMatrix one = icpSimilarity(*gt, *grid_gt, *map, *grid_map, icpParams(1));
    EXPECT_TRUE(one == *sim) << "max difference " << (one - *sim).cwiseAbs().maxCoeff();
}

TEST_F(IcpOffice, GraphAgainstItselfHasSimilarityOneOnTheDiagonal)
{
    const SimilarityMatrix self = icpSimilarity(*gt, *grid_gt, *gt, *grid_gt, icpParams(2));
    for (const TopoVertex& v : gt->vertices)
    {
        if (nonSpuriousDegree(*gt, v.id) <= 0)
            EXPECT_EQ(self(v.id, v.id), 0.0) << "spurious vertex " << v.id;
        else
            EXPECT_GT(self(v.id, v.id), 0.99) << "vertex " << v.id;
    }
}

TEST(IcpSimilarity, DegreeDifferenceAllowanceAlignsJunctionsOfDifferentDegree)
{
    // A T-junction (degree 3) against a crossing (degree 4): pruned by default, aligned from
    // the single-edge start angles when one unit of degree difference is allowed.
    const COccupancyGridMap2D t = makeTJunctionMap();
    const COccupancyGridMap2D plus = makePlusMap();
    const TopologyGraph gt = buildTopologyGraph(t);
    const TopologyGraph map = buildTopologyGraph(plus);
    auto junction = [](const TopologyGraph& g, int degree)
    {
        for (const TopoVertex& v : g.vertices)
            if (nonSpuriousDegree(g, v.id) == degree) return v.id;
        return -1;
    };
    const int j3 = junction(gt, 3);
    const int j4 = junction(map, 4);
    ASSERT_GE(j3, 0);
    ASSERT_GE(j4, 0);

    VertexSimilarityParameters p = icpParams(1);
    EXPECT_EQ(icpSimilarity(gt, t, map, plus, p)(j3, j4), 0.0);
    p.icp_max_degree_difference = 1;
    EXPECT_GT(icpSimilarity(gt, t, map, plus, p)(j3, j4), 0.3)
        << "a T is three quarters of a crossing";
}

TEST(IcpSimilarity, VerticesWithoutObstacleCellsAroundGetZero)
{
    // The same corridors, but walls only unknown (P = 0.5): the graph is unchanged, the clouds
    // are empty, and empty clouds have nothing to align.
    const COccupancyGridMap2D t = makeTJunctionMap();
    COccupancyGridMap2D walls_unknown = t;
    for (unsigned y = 0; y < t.getSizeY(); ++y)
        for (unsigned x = 0; x < t.getSizeX(); ++x)
            if (t.getCell(x, y) < 0.35f) walls_unknown.setCell(x, y, 0.5f);
    const TopologyGraph g = buildTopologyGraph(t);
    ASSERT_GT(g.numNonSpuriousVertices(), 0u);
    const SimilarityMatrix s = icpSimilarity(g, walls_unknown, g, walls_unknown, icpParams(1));
    EXPECT_EQ(s.cwiseAbs().maxCoeff(), 0.0);
    // ... while the real walls give the junction a perfect match with itself.
    EXPECT_GT(icpSimilarity(g, t, g, t, icpParams(1)).maxCoeff(), 0.99);
}

TEST(IcpSimilarity, EmptyGraphsGiveAnEmptyMatrix)
{
    const COccupancyGridMap2D grid = makeTJunctionMap();
    const TopologyGraph g = buildTopologyGraph(grid);
    const TopologyGraph empty;
    const COccupancyGridMap2D unknown_grid;  // MRPT's default: 40 m x 40 m, all unknown
    EXPECT_EQ(icpSimilarity(empty, unknown_grid, g, grid, icpParams(1)).size(), 0);
    const SimilarityMatrix s = icpSimilarity(g, grid, empty, unknown_grid, icpParams(1));
    EXPECT_EQ(s.rows(), static_cast<Eigen::Index>(g.vertices.size()));
    EXPECT_EQ(s.cols(), 0);
}

TEST(IcpSimilarity, BadInputThrowsInputError)
{
    const COccupancyGridMap2D grid = makeTJunctionMap();
    const TopologyGraph g = buildTopologyGraph(grid);
    auto run = [&](const std::function<void(VertexSimilarityParameters&)>& change)
    {
        VertexSimilarityParameters p = icpParams(1);
        change(p);
        icpSimilarity(g, grid, g, grid, p);
    };
    EXPECT_THROW(run([](auto& p) { p.icp_radius_m = -1.0; }), InputError);
    EXPECT_THROW(run([](auto& p) { p.icp_radius_m = std::nan(""); }), InputError);
    EXPECT_THROW(run([](auto& p) { p.icp_start_angles = 0; }), InputError);
    EXPECT_THROW(run([](auto& p) { p.icp_rmse_tolerance_m = 0.0; }), InputError);
    EXPECT_THROW(run([](auto& p) { p.icp_max_degree_difference = -1; }), InputError);
    EXPECT_THROW(run([](auto& p) { p.threads = -2; }), InputError);
    // A vertex without a place to cut its cloud at.
    TopologyGraph broken = g;
    broken.vertices.front().position_m.x() = std::nan("");
    EXPECT_THROW(icpSimilarity(broken, grid, g, grid, icpParams(1)), InputError);
}
