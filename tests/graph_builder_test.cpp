/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Topology Graph construction (paper II-B, II-C) on maps built in code whose graph is known.
// The expected positions come from the geometry: a corridor of width w ends in a dead end w/2
// before its end wall; a T-junction of corridors of width 1.5 m sits where the top wall and the
// branch's two corners are equidistant (y = 6.5625 for the map below).

#include <gtest/gtest.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/maps/load_map.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "../libmrpt_topoeval/src/graph/GraphEditor.h"
#include "synthetic_maps.h"
#include "test_paths.h"

using namespace mrpt_topoeval;
using namespace mrpt_topoeval::testing;

namespace
{
constexpr double kDeg = M_PI / 180.0;
// Cell centres and the diagonal walls of the discretised skeleton move vertices by up to about
// a cell and a half.
constexpr double kPosTol = 0.12;

const TopoVertex* vertexNear(const TopologyGraph& g, double x, double y, double tol = kPosTol)
{
    for (const auto& v : g.vertices)
        if ((v.position_m - Eigen::Vector2d(x, y)).norm() < tol) return &v;
    return nullptr;
}

std::vector<double> sortedDiffsDeg(const TopoVertex& v)
{
    std::vector<double> d;
    for (double a : v.angle_diffs_rad) d.push_back(a / kDeg);
    std::sort(d.begin(), d.end());
    return d;
}

// Invariants every graph must satisfy, whatever the map.
void expectWellFormed(const TopologyGraph& g)
{
    for (std::size_t i = 0; i < g.vertices.size(); ++i)
    {
        const TopoVertex& v = g.vertices[i];
        EXPECT_EQ(v.id, static_cast<int>(i));
        EXPECT_NE(v.degree(), 0);
        if (v.degree() == 2)
        {
            EXPECT_EQ(v.ring[0].edge, v.ring[1].edge) << "only ring vertices";
        }
        double sum = 0.0;
        for (double d : v.angle_diffs_rad)
        {
            EXPECT_GE(d, 0.0);
            sum += d;
        }
        EXPECT_NEAR(sum, 2 * M_PI, 1e-9);
        for (std::size_t k = 1; k < v.ring.size(); ++k)
            EXPECT_LE(v.ring[k - 1].angle_rad, v.ring[k].angle_rad);
    }
    for (std::size_t i = 0; i < g.edges.size(); ++i)
    {
        const TopoEdge& e = g.edges[i];
        EXPECT_EQ(e.id, static_cast<int>(i));
        ASSERT_GE(e.path_m.size(), 2u);
        EXPECT_EQ(e.path_m.size(), e.clearance_m.size());
        EXPECT_LE(e.from, e.to);
        EXPECT_LT((e.path_m.front() - g.vertices[e.from].position_m).norm(), 1e-9);
        EXPECT_LT((e.path_m.back() - g.vertices[e.to].position_m).norm(), 1e-9);
        EXPECT_GT(e.length_m, 0.0);
        EXPECT_LE(e.min_clearance_m, e.mean_clearance_m + 1e-12);
        EXPECT_EQ(e.dead_end, g.vertices[e.from].degree() == 1 || g.vertices[e.to].degree() == 1);
    }
}
}  // namespace

TEST(GraphBuilder, DefaultsAreThePapers)
{
    const GraphBuilderParameters p;
    EXPECT_DOUBLE_EQ(p.min_clearance_m, 0.30);  // paper Fig. 2
    EXPECT_DOUBLE_EQ(p.alpha_radius_m, 2.50);   // paper Fig. 3
    EXPECT_NO_THROW(p.validate());
}

TEST(GraphBuilder, TJunction)
{
    const TopologyGraph g = buildTopologyGraph(makeTJunctionMap());
    expectWellFormed(g);
    ASSERT_EQ(g.vertices.size(), 4u);
    ASSERT_EQ(g.edges.size(), 3u);

    const TopoVertex* j = vertexNear(g, 7.0, 6.5625);
    ASSERT_NE(j, nullptr);
    EXPECT_EQ(j->degree(), 3);
    // Edges leave west, east and south: angles of 90, 90 and 180 degrees between them.
    const auto d = sortedDiffsDeg(*j);
    EXPECT_NEAR(d[0], 90.0, 8.0);
    EXPECT_NEAR(d[1], 90.0, 8.0);
    EXPECT_NEAR(d[2], 180.0, 8.0);
    EXPECT_NEAR(j->min_angle_rad / kDeg, d[0], 1e-9);
    EXPECT_NEAR(j->max_angle_rad / kDeg, d[2], 1e-9);

    for (auto [x, y] : {std::pair{1.75, 6.75}, {12.25, 6.75}, {7.0, 1.75}})
    {
        const TopoVertex* e = vertexNear(g, x, y);
        ASSERT_NE(e, nullptr) << "dead end at " << x << "," << y;
        EXPECT_EQ(e->degree(), 1);
        EXPECT_FALSE(e->spurious);
        EXPECT_NEAR(e->clearance_m, 0.75, 0.08);
    }
    // Path lengths: 5.25 m west and east (plus the junction's offset), 4.81 m south.
    std::vector<double> len;
    for (const auto& e : g.edges) len.push_back(e.length_m);
    std::sort(len.begin(), len.end());
    EXPECT_NEAR(len[0], 4.81, 0.15);
    EXPECT_NEAR(len[1], 5.28, 0.15);
    EXPECT_NEAR(len[2], 5.28, 0.15);
    for (const auto& e : g.edges)
    {
        EXPECT_TRUE(e.dead_end);
        EXPECT_FALSE(e.spurious);
        EXPECT_NEAR(e.min_clearance_m, 0.75, 0.08);  // half the corridor width
    }
    EXPECT_NEAR(g.totalEdgeLength(), 4.81 + 2 * 5.28, 0.3);
    EXPECT_EQ(g.numHalfEdges(), 6u);
}

TEST(GraphBuilder, PlusCrossing)
{
    const TopologyGraph g = buildTopologyGraph(makePlusMap());
    expectWellFormed(g);
    ASSERT_EQ(g.vertices.size(), 5u);
    ASSERT_EQ(g.edges.size(), 4u);
    const TopoVertex* c = vertexNear(g, 8.0, 8.0);
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->degree(), 4);
    for (double d : sortedDiffsDeg(*c)) EXPECT_NEAR(d, 90.0, 5.0);
    for (auto [x, y] : {std::pair{2.75, 8.0}, {13.25, 8.0}, {8.0, 2.75}, {8.0, 13.25}})
    {
        const TopoVertex* e = vertexNear(g, x, y);
        ASSERT_NE(e, nullptr) << x << "," << y;
        EXPECT_EQ(e->degree(), 1);
    }
    for (const auto& e : g.edges) EXPECT_NEAR(e.length_m, 5.25, 0.12);
    const auto hist = g.degreeHistogram();
    ASSERT_EQ(hist.size(), 5u);
    EXPECT_EQ(hist[1], 4u);
    EXPECT_EQ(hist[4], 1u);
}

TEST(GraphBuilder, TwoRoomsWithADoor)
{
    // Each room's skeleton is an X into its corners; those branches are corner spurs and go,
    // leaving the two room centres joined through the door.
    const TopologyGraph g = buildTopologyGraph(makeTwoRoomsMap());
    expectWellFormed(g);
    ASSERT_EQ(g.vertices.size(), 2u);
    ASSERT_EQ(g.edges.size(), 1u);
    EXPECT_NE(vertexNear(g, 3.0, 3.0), nullptr);
    EXPECT_NE(vertexNear(g, 7.2, 3.0), nullptr);
    const TopoEdge& e = g.edges[0];
    EXPECT_NEAR(e.length_m, 4.2, 0.12);
    EXPECT_NEAR(e.min_clearance_m, 0.5, 0.08);  // half the door
    EXPECT_NEAR(g.vertices[0].clearance_m, 2.0, 0.08);
    // The door is at x = 5.1: the path must go through it.
    const bool through_door = std::any_of(
        e.path_m.begin(), e.path_m.end(),
        [](const auto& p) { return std::abs(p.x() - 5.1) < 0.2 && std::abs(p.y() - 3.0) < 0.3; });
    EXPECT_TRUE(through_door);
}

TEST(GraphBuilder, CorridorLoopIsOneRingVertex)
{
    // A pure cycle has no vertex of degree != 2. We return one degree-2 vertex (the point of
    // largest clearance, ties by position) carrying the cycle as a counter-clockwise loop edge,
    // and say so in a warning, so that the map's topology (one loop) is not lost.
    const TopologyGraph g = buildTopologyGraph(makeCorridorLoopMap());
    expectWellFormed(g);
    ASSERT_EQ(g.vertices.size(), 1u);
    ASSERT_EQ(g.edges.size(), 1u);
    EXPECT_EQ(g.vertices[0].degree(), 2);
    EXPECT_EQ(g.edges[0].from, 0);
    EXPECT_EQ(g.edges[0].to, 0);
    EXPECT_FALSE(g.edges[0].dead_end);
    // The centre line is a 7.5 m square with rounded corners.
    EXPECT_GT(g.edges[0].length_m, 27.0);
    EXPECT_LT(g.edges[0].length_m, 30.5);
    ASSERT_EQ(g.warnings.size(), 1u);
    EXPECT_NE(g.warnings[0].find("single cycle"), std::string::npos);
}

TEST(GraphBuilder, LoopWithSpurHasALoopEdge)
{
    const TopologyGraph g = buildTopologyGraph(makeLoopWithSpurMap());
    expectWellFormed(g);
    ASSERT_EQ(g.vertices.size(), 2u);
    ASSERT_EQ(g.edges.size(), 2u);
    const TopoVertex* j = vertexNear(g, 9.9, 6.0, 0.2);
    ASSERT_NE(j, nullptr);
    EXPECT_EQ(j->degree(), 3);  // the loop counts twice
    int loops = 0;
    for (const auto& e : g.edges) loops += e.from == e.to;
    EXPECT_EQ(loops, 1);
    EXPECT_TRUE(g.warnings.empty());
}

TEST(GraphBuilder, ShortDeadEndIsSpuriousOrInsideTheJunctionDisc)
{
    // A T whose branch is only 1 m deep. Its dead-end edge (~0.8 m) ends inside the junction's
    // empty disc (clearance ~1 m): by default it is removed and the corridor is one edge.
    GridSketch s(14.0, 9.0);
    s.carve(1.0, 6.0, 13.0, 7.5).carve(6.25, 5.0, 7.75, 6.0);
    EXPECT_EQ(buildTopologyGraph(s.grid()).vertices.size(), 2u);

    // Without the disc rule it is kept by pruning (> 0.5 m) but marked spurious (< 1 m), with
    // its end vertex (paper II-C).
    GraphBuilderParameters p;
    p.junction_disc_ratio = 0.0;
    const TopologyGraph g = buildTopologyGraph(s.grid(), p);
    expectWellFormed(g);
    ASSERT_EQ(g.vertices.size(), 4u);
    int spurious_edges = 0;
    for (const auto& e : g.edges)
        if (e.spurious)
        {
            ++spurious_edges;
            EXPECT_LT(e.length_m, 1.0);
            EXPECT_GT(e.length_m, 0.5);
        }
    EXPECT_EQ(spurious_edges, 1);
    EXPECT_EQ(g.numNonSpuriousVertices(), 3u);

    p.spurious_dead_end_length_m = 0.5;
    EXPECT_EQ(buildTopologyGraph(s.grid(), p).numNonSpuriousVertices(), 4u);
    p.prune_dead_end_length_m = 1.2;  // now pruned away by length
    EXPECT_EQ(buildTopologyGraph(s.grid(), p).vertices.size(), 2u);
}

TEST(GraphBuilder, AlphaShapeCutsTheOutside)
{
    // A plus-shaped building with 0.3 m walls standing in open free space with pillars; its
    // east arm is open to the outside. The outside's skeleton (around the pillars) is cut by
    // the outer alpha polygon, and the east corridor is cut at the doorway into a dead end.
    // The pillars stand within 2 x alpha_radius_m of the building, so the alpha polygon takes
    // them in and part of their skeleton stays inside it, as a separate piece: the paper's
    // "largest component only" (min_component_length_m = inf) removes it.
    GridSketch s(30.0, 22.0);
    s.carve(0.0, 0.0, 30.0, 22.0);
    s.fill(4.7, 9.7, 17.3, 12.3).fill(9.7, 4.7, 12.3, 17.3);
    s.carve(5.0, 10.0, 17.3, 12.0).carve(10.0, 5.0, 12.0, 17.0);
    for (double y : {3.0, 8.0, 14.0, 19.0})
        for (double x : {21.0, 25.0}) s.fill(x, y, x + 0.6, y + 0.6);
    GraphBuildStats st;
    GraphBuilderParameters largest;
    largest.min_component_length_m = std::numeric_limits<double>::infinity();
    largest.room_piece_min_length_m = std::numeric_limits<double>::infinity();
    const TopologyGraph g = buildTopologyGraph(s.grid(), largest, &st);
    expectWellFormed(g);
    EXPECT_GT(st.vertices_after_prune, st.vertices_after_alpha);
    ASSERT_EQ(g.vertices.size(), 5u);
    const TopoVertex* centre = vertexNear(g, 11.0, 11.0);
    ASSERT_NE(centre, nullptr);
    EXPECT_EQ(centre->degree(), 4);
    for (const auto& v : g.vertices) EXPECT_LT(v.position_m.x(), 17.6);
    EXPECT_GE(g.outer_boundary_m.size(), 3u);

    // Without the cut the pillars' skeleton is part of the graph.
    GraphBuilderParameters no_cut = largest;
    no_cut.alpha_radius_m = 0.0;
    EXPECT_GT(buildTopologyGraph(s.grid(), no_cut).vertices.size(), 5u);

    // With every piece of a useful size kept (the default), the building's graph is the
    // same and the pillars' piece, east of the building, comes on top.
    const TopologyGraph all = buildTopologyGraph(s.grid());
    std::size_t building = 0;
    for (const auto& v : all.vertices) building += v.position_m.x() < 17.6;
    EXPECT_EQ(building, 5u);
    EXPECT_GT(all.vertices.size(), 5u);
}

TEST(GraphBuilder, UnknownSpaceStopsTheSkeleton)
{
    // The east half of the corridor is unexplored (unknown): the skeleton ends where the known
    // free space ends, as a robot map that has not seen the rest would.
    GridSketch s(14.0, 4.0);
    s.carve(1.0, 1.25, 13.0, 2.75).unknown(7.0, 0.0, 14.0, 4.0);
    const TopologyGraph g = buildTopologyGraph(s.grid());
    ASSERT_EQ(g.vertices.size(), 2u);
    for (const auto& v : g.vertices) EXPECT_LT(v.position_m.x(), 7.05);
}

TEST(GraphBuilder, NoObstaclesOrNoFreeSpaceGiveAnEmptyGraphAndAWarning)
{
    GridSketch solid(5.0, 5.0);
    TopologyGraph g = buildTopologyGraph(solid.grid());
    EXPECT_TRUE(g.vertices.empty());
    ASSERT_EQ(g.warnings.size(), 1u);
    EXPECT_NE(g.warnings[0].find("no free space"), std::string::npos);

    GridSketch open(5.0, 5.0);
    open.carve(0.0, 0.0, 5.0, 5.0);
    g = buildTopologyGraph(open.grid());
    EXPECT_TRUE(g.vertices.empty());
    ASSERT_EQ(g.warnings.size(), 1u);
    EXPECT_NE(g.warnings[0].find("no obstacles"), std::string::npos);

    // Narrower than 2 x min_clearance everywhere: nothing survives the clearance filter.
    GridSketch narrow(6.0, 3.0);
    narrow.carve(1.0, 1.0, 5.0, 1.4);
    g = buildTopologyGraph(narrow.grid());
    EXPECT_TRUE(g.vertices.empty());
    EXPECT_EQ(g.warnings.size(), 1u);

    // A single cell map.
    mrpt::maps::COccupancyGridMap2D one(0.0, 0.05, 0.0, 0.05, 0.05);
    EXPECT_TRUE(buildTopologyGraph(one).vertices.empty());
}

TEST(GraphBuilder, InvalidParametersAreRejectedWithTheirName)
{
    GraphBuilderParameters p;
    p.min_clearance_m = -1;
    try
    {
        buildTopologyGraph(makePlusMap(), p);
        FAIL() << "expected InputError";
    }
    catch (const InputError& e)
    {
        EXPECT_STREQ(e.what(), "[GraphBuilder] min_clearance_m = -1 violates min_clearance_m > 0");
    }
    p = {};
    p.alpha_radius_m = std::nan("");
    EXPECT_THROW(p.validate(), InputError);
    p = {};
    p.occupied_min_prob = 0.3;
    EXPECT_THROW(p.validate(), InputError);
}

TEST(GraphBuilder, OfficeHasTheExpectedJunctionsAndIsDeterministic)
{
    const auto grid = makeOfficeMap();
    const TopologyGraph a = buildTopologyGraph(grid);
    const TopologyGraph b = buildTopologyGraph(grid);
    expectWellFormed(a);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    ASSERT_EQ(a.edges.size(), b.edges.size());
    for (std::size_t i = 0; i < a.vertices.size(); ++i)
        EXPECT_EQ(a.vertices[i].position_m, b.vertices[i].position_m);
    for (std::size_t i = 0; i < a.edges.size(); ++i)
        EXPECT_EQ(a.edges[i].path_m, b.edges[i].path_m);

    // The corridor loop's four corners and the doors on it are junctions of degree 3; every
    // room and dead-end corridor ends in a dead end; no junction of degree > 3.
    const auto hist = a.degreeHistogram(true);
    ASSERT_GE(hist.size(), 4u);
    EXPECT_EQ(hist.size(), 4u);
    EXPECT_EQ(hist[2], 0u);
    EXPECT_GE(hist[3], 10u);
    EXPECT_GE(hist[1], 8u);
}

TEST(GraphBuilder, EveryVertexAndPathPointLiesOnFreeSpace)
{
    // The skeleton is that of the free space (skeleton_on_free_cells_only): no vertex or path
    // point may sit inside a wall or the solid block around the office.
    const auto grid = makeOfficeMap();
    const TopologyGraph g = buildTopologyGraph(grid);
    auto isFree = [&](const Eigen::Vector2d& p)
    { return grid.getPos(static_cast<float>(p.x()), static_cast<float>(p.y())) > 0.65f; };
    for (const auto& v : g.vertices) EXPECT_TRUE(isFree(v.position_m)) << "vertex " << v.id;
    for (const auto& e : g.edges)
        for (const auto& p : e.path_m) EXPECT_TRUE(isFree(p)) << "edge " << e.id;
}

namespace
{
// Same number of vertices and edges and the same vertices (within kPosTol), degree by degree.
void expectSameGraph(const TopologyGraph& a, const TopologyGraph& b)
{
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    EXPECT_EQ(a.edges.size(), b.edges.size());
    for (const auto& v : a.vertices)
    {
        const TopoVertex* w = vertexNear(b, v.position_m.x(), v.position_m.y());
        ASSERT_NE(w, nullptr) << "no vertex near (" << v.position_m.transpose() << ")";
        EXPECT_EQ(v.degree(), w->degree());
    }
}

// Two 5 m x 4 m rooms side by side, a 0.2 m wall between them with a 1 m door.
GridSketch twoRooms()
{
    GridSketch s(12.6, 6.0);
    s.carve(1.0, 1.0, 6.0, 5.0).carve(6.2, 1.0, 11.2, 5.0).carve(6.0, 2.5, 6.2, 3.5);
    return s;
}
}  // namespace

TEST(GraphBuilder, TableLegsGiveTheSameGraphAsTheEmptyRoom)
{
    // A table's four legs (0.05 m posts, 1.0 m x 0.8 m apart) in the left room: the gaps
    // between them are wider than 2 x min_clearance_m, so as Voronoi sites they put a loop
    // around every leg. They are islands smaller than min_island_size_m and become free.
    const TopologyGraph empty = buildTopologyGraph(twoRooms().grid());
    GridSketch s = twoRooms();
    for (double x : {2.5, 3.5})
        for (double y : {2.6, 3.4}) s.fill(x, y, x + 0.05, y + 0.05);
    GraphBuildStats st;
    const TopologyGraph legs = buildTopologyGraph(s.grid(), {}, &st);
    expectWellFormed(legs);
    EXPECT_EQ(st.islands_removed, 4u);
    expectSameGraph(empty, legs);

    GraphBuilderParameters off;
    off.min_island_size_m = 0.0;
    EXPECT_GT(buildTopologyGraph(s.grid(), off).vertices.size(), empty.vertices.size());
}

TEST(GraphBuilder, SpeckInACorridorAddsNoVertex)
{
    // One- and two-cell specks in the middle of a 1.5 m corridor: each would split the
    // corridor's skeleton into a loop around it (0.7 m on either side).
    const TopologyGraph clean = buildTopologyGraph(makeTJunctionMap());
    GridSketch s(14.0, 9.0);
    s.carve(1.0, 6.0, 13.0, 7.5).carve(6.25, 1.0, 7.75, 6.0);
    const TopologyGraph carved = buildTopologyGraph(s.grid());
    expectSameGraph(clean, carved);  // the sketch is the T-junction map
    s.fill(3.0, 6.7, 3.05, 6.75).fill(10.0, 6.7, 10.1, 6.75).fill(6.95, 3.0, 7.0, 3.05);
    const TopologyGraph specks = buildTopologyGraph(s.grid());
    expectWellFormed(specks);
    expectSameGraph(clean, specks);

    GraphBuilderParameters off;
    off.min_island_size_m = 0.0;
    EXPECT_GT(buildTopologyGraph(s.grid(), off).vertices.size(), clean.vertices.size());
}

TEST(GraphBuilder, ColumnsWiderThanTheIslandSizeStay)
{
    // A 0.6 m column in the middle of a 6 m hall is building structure: the skeleton runs
    // around it (a loop), with or without a speck beside it.
    GridSketch s(8.0, 8.0);
    s.carve(1.0, 1.0, 7.0, 7.0).fill(3.7, 3.7, 4.3, 4.3);
    const TopologyGraph g = buildTopologyGraph(s.grid());
    expectWellFormed(g);
    ASSERT_EQ(g.edges.size(), 1u);
    EXPECT_EQ(g.edges[0].from, g.edges[0].to);  // the ring around the column
    GraphBuilderParameters wide;
    wide.min_island_size_m = 1.0;  // now the column is an island too: an empty room
    EXPECT_EQ(buildTopologyGraph(s.grid(), wide).edges.size(), 0u);
}

TEST(GraphBuilder, EnclosedUnknownInAHallBecomesFree)
{
    // A 6 m hall whose middle the laser crossed too sparsely to mark (a 2 m unknown square
    // bordered by free space only): it is free space, so the hall is an empty room. Taken as an
    // obstacle it would put a ring around it.
    GridSketch s(8.0, 8.0);
    s.carve(1.0, 1.0, 7.0, 7.0).unknown(3.0, 3.0, 5.0, 5.0);
    GraphBuildStats st;
    const TopologyGraph g = buildTopologyGraph(s.grid(), {}, &st);
    EXPECT_EQ(st.unknown_regions_filled, 1u);
    EXPECT_EQ(g.edges.size(), 0u);
    GraphBuilderParameters off;
    off.enclosed_unknown_min_free_share = 0.0;
    const TopologyGraph ring = buildTopologyGraph(s.grid(), off);
    ASSERT_EQ(ring.edges.size(), 1u);
    EXPECT_EQ(ring.edges[0].from, ring.edges[0].to);
}

TEST(GraphBuilder, UnexploredRoomBehindADoorStaysUnknown)
{
    // The right room was only seen through its door (a free strip 0.8 m deep): its unknown rest
    // is bounded mostly by walls, so it stays unknown and the graph stops at the door, as it
    // does with the filling off. The unknown inside a thick wall (occupied all round) stays too.
    GridSketch s = twoRooms();
    s.unknown(6.2, 1.0, 11.2, 5.0).carve(6.2, 2.5, 7.0, 3.5);
    s.fill(2.0, 1.0, 2.6, 2.0).unknown(2.15, 1.15, 2.45, 1.85);
    GraphBuildStats st;
    const TopologyGraph g = buildTopologyGraph(s.grid(), {}, &st);
    EXPECT_EQ(st.unknown_regions_filled, 0u);
    GraphBuilderParameters off;
    off.enclosed_unknown_min_free_share = 0.0;
    expectSameGraph(buildTopologyGraph(s.grid(), off), g);
    for (const auto& v : g.vertices) EXPECT_LT(v.position_m.x(), 7.05);
}

TEST(GraphBuilder, UnknownSurroundingsDoNotChangeTheGraph)
{
    // The same office inside a grid 4 m bigger on every side, the new cells unknown (a SLAM
    // map's usual margin): the cleaning steps then run on the known cells' box plus a margin
    // only, and the graph is the same, vertex for vertex, in the same world frame.
    const auto office = makeOfficeMap();
    GraphBuildStats st_office;
    const TopologyGraph a = buildTopologyGraph(office, {}, &st_office);
    EXPECT_EQ(st_office.work_cells, std::size_t(office.getSizeX()) * office.getSizeY());
    auto wide = office;
    wide.resizeGrid(office.getXMin() - 4.0, office.getXMax() + 4.0, office.getYMin() - 4.0,
                    office.getYMax() + 4.0, 0.5f, false);
    ASSERT_GT(wide.getSizeX(), office.getSizeX() + 150);
    GraphBuildStats st_wide;
    const TopologyGraph b = buildTopologyGraph(wide, {}, &st_wide);
    EXPECT_LT(st_wide.work_cells, std::size_t(wide.getSizeX()) * wide.getSizeY() * 9 / 10);
    EXPECT_GT(st_wide.work_cells, std::size_t(office.getSizeX()) * office.getSizeY());
    expectWellFormed(b);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    ASSERT_EQ(a.edges.size(), b.edges.size());
    // MRPT keeps the grid's origin as a float: the moved origin rounds differently (~1e-7 m).
    for (std::size_t i = 0; i < a.vertices.size(); ++i)
    {
        EXPECT_LT((a.vertices[i].position_m - b.vertices[i].position_m).norm(), 1e-5) << i;
        EXPECT_EQ(a.vertices[i].degree(), b.vertices[i].degree()) << i;
    }
    for (std::size_t i = 0; i < a.edges.size(); ++i)
        EXPECT_NEAR(a.edges[i].length_m, b.edges[i].length_m, 1e-5) << i;
    EXPECT_EQ(st_wide.sites, st_office.sites);
    EXPECT_EQ(st_wide.islands_removed, st_office.islands_removed);
}

TEST(GraphBuilder, OneCellWallGapDoesNotChangeTheGraph)
{
    // One-cell slots through the 0.2 m wall: one far from the door, one 0.15 m beside it. The
    // second would leave a 0.15 m piece of wall standing free, an island that would widen the
    // door; closed first, the wall is whole again.
    const TopologyGraph whole = buildTopologyGraph(twoRooms().grid());
    ASSERT_EQ(whole.vertices.size(), 2u);
    GridSketch s = twoRooms();
    s.carve(6.0, 1.6, 6.2, 1.65).carve(6.0, 3.65, 6.2, 3.7);
    GraphBuildStats st;
    const TopologyGraph gaps = buildTopologyGraph(s.grid(), {}, &st);
    expectWellFormed(gaps);
    EXPECT_EQ(st.islands_removed, 0u);
    expectSameGraph(whole, gaps);
    ASSERT_EQ(gaps.edges.size(), 1u);
    EXPECT_NEAR(gaps.edges[0].min_clearance_m, 0.5, 0.08);  // still half the door

    // A gap wider than 2 x min_clearance_m is a door, closing or not: the two rooms now form a
    // ring (one degree-2 vertex on a loop edge).
    s.carve(6.0, 1.2, 6.2, 2.0);
    const TopologyGraph two_doors = buildTopologyGraph(s.grid());
    ASSERT_EQ(two_doors.edges.size(), 1u);
    EXPECT_EQ(two_doors.edges[0].from, two_doors.edges[0].to);
}

// The cleaning closings run in tiles of 256 cells with a margin (build_graph.cpp): a speck or a
// slot on a tile's seam is closed as anywhere else. Two rooms 18 m tall (row 256 is a seam, at
// y = 12.8 m), the left one 5 m wide, the right one 7 m, across the column seam at x = 12.8 m.
// The sketch is all known, so the cleaning works on the whole grid and the seams are the grid's.
TEST(GraphBuilder, SpecksAndWallSlotsOnTileSeamsAreClosedAsElsewhere)
{
    const auto rooms = []
    {
        GridSketch s(14.0, 20.0);
        s.carve(1.0, 1.0, 6.0, 19.0).carve(6.2, 1.0, 13.2, 19.0).carve(6.0, 11.7, 6.2, 12.7);
        return s;
    };
    // Unknown specks of 1 x 2 cells across the row seam (left room) and the column seam (right
    // room). With islands and enclosed unknown off, only the speck filling
    // (unknown_fill_radius_m) removes them.
    GraphBuilderParameters no_islands;
    no_islands.min_island_size_m = 0.0;
    no_islands.enclosed_unknown_min_free_share = 0.0;
    const TopologyGraph clean = buildTopologyGraph(rooms().grid(), no_islands);
    GridSketch specks = rooms();
    specks.unknown(3.0, 12.75, 3.05, 12.85).unknown(12.75, 5.0, 12.85, 5.05);
    expectSameGraph(clean, buildTopologyGraph(specks.grid(), no_islands));
    GraphBuilderParameters no_fill = no_islands;
    no_fill.unknown_fill_radius_m = 0.0;
    // Unfilled, each speck splits its room's skeleton around it: the left room's upper dead end
    // and the right room's lower one move.
    const TopologyGraph unfilled = buildTopologyGraph(specks.grid(), no_fill);
    EXPECT_EQ(vertexNear(unfilled, 3.475, 16.475), nullptr);
    EXPECT_EQ(vertexNear(unfilled, 9.675, 4.475), nullptr);
    ASSERT_NE(vertexNear(clean, 3.475, 16.475), nullptr);
    ASSERT_NE(vertexNear(clean, 9.675, 4.475), nullptr);

    // A one-cell slot 0.15 m above the 1 m door leaves a piece of wall across the row seam
    // (cells 254-256) standing free: the gap closing makes the wall whole (as in
    // OneCellWallGapDoesNotChangeTheGraph); without it the piece is an island and the door
    // 0.2 m wider.
    const TopologyGraph whole = buildTopologyGraph(rooms().grid());
    GridSketch slot = rooms();
    slot.carve(6.0, 12.85, 6.2, 12.9);
    GraphBuildStats st;
    const TopologyGraph closed = buildTopologyGraph(slot.grid(), {}, &st);
    EXPECT_EQ(st.work_cells, 280u * 400u);
    expectSameGraph(whole, closed);
    auto doorClearance = [](const TopologyGraph& g)
    {
        double c = 1e9;
        for (const auto& e : g.edges) c = std::min(c, e.min_clearance_m);
        return c;
    };
    EXPECT_NEAR(doorClearance(closed), doorClearance(whole), 0.03);
    EXPECT_NEAR(doorClearance(whole), 0.5, 0.08);
    GraphBuilderParameters no_closing;
    no_closing.wall_gap_close_radius_m = 0.0;
    EXPECT_GT(doorClearance(buildTopologyGraph(slot.grid(), no_closing)), 0.58);
}

TEST(GraphBuilder, EveryPieceOfAUsefulSizeIsKept)
{
    // Two corridors with no passage between them: 12 m and 8 m long. The paper keeps the
    // biggest piece only; we keep both, as their total edge length (about 10.5 m and 6.5 m) is
    // over min_component_length_m.
    GridSketch s(14.0, 8.0);
    s.carve(1.0, 1.0, 13.0, 2.5).carve(1.0, 5.0, 9.0, 6.5);
    const TopologyGraph g = buildTopologyGraph(s.grid());
    expectWellFormed(g);
    EXPECT_EQ(g.vertices.size(), 4u);
    EXPECT_EQ(g.edges.size(), 2u);

    GraphBuilderParameters largest;
    largest.min_component_length_m = std::numeric_limits<double>::infinity();
    largest.room_piece_min_length_m = std::numeric_limits<double>::infinity();
    const TopologyGraph one = buildTopologyGraph(s.grid(), largest);
    ASSERT_EQ(one.vertices.size(), 2u);
    for (const auto& v : one.vertices) EXPECT_LT(v.position_m.y(), 3.0);
    largest.min_component_length_m = 7.0;  // the short corridor's edge is ~6.5 m
    EXPECT_EQ(buildTopologyGraph(s.grid(), largest).vertices.size(), 2u);
}

TEST(GraphBuilder, ASealedRoomKeepsItsPiece)
{
    // A corridor; beside it a room 4 m x 7 m sealed off (its door closed, or cut by a crop or a
    // break); east of it a free area of the same size bounded by the unknown (a laser fan seen
    // through a door). Each skeleton is a piece of one edge, about 3 m once its corner spurs
    // are pruned: under min_component_length_m. The room's runs between walls and is kept (a
    // missed part can be placed by its vertices); the fan's faces the unknown and goes.
    GridSketch s(16.0, 12.0);
    s.carve(1.0, 1.0, 15.0, 2.5).carve(2.0, 4.0, 6.0, 11.0);
    s.unknown(9.8, 3.8, 14.2, 11.2).carve(10.0, 4.0, 14.0, 11.0);
    auto count = [](const TopologyGraph& g, double x0, double x1)
    {
        return std::count_if(
            g.vertices.begin(), g.vertices.end(),
            [&](const TopoVertex& v)
            { return v.position_m.y() > 3.5 && v.position_m.x() > x0 && v.position_m.x() < x1; });
    };
    const TopologyGraph g = buildTopologyGraph(s.grid());
    expectWellFormed(g);
    EXPECT_EQ(count(g, 1.0, 7.0), 2);   // the room
    EXPECT_EQ(count(g, 9.0, 15.0), 0);  // the fan
    EXPECT_EQ(g.vertices.size(), 4u);

    // Before session 48 the room went too; with no wall share asked, the fan stays.
    GraphBuilderParameters no_rooms, any_piece;
    no_rooms.room_piece_min_length_m = no_rooms.min_component_length_m;
    EXPECT_EQ(count(buildTopologyGraph(s.grid(), no_rooms), 1.0, 7.0), 0);
    any_piece.room_piece_min_wall_share = 0.0;
    EXPECT_EQ(count(buildTopologyGraph(s.grid(), any_piece), 9.0, 15.0), 2);
}

TEST(GraphBuilder, RotatedFloorPlanOnABlackPageKeepsItsGraph)
{
    // A floor plan drawn on a black page (everything but the building occupied), the office
    // 1.5 m from the page's west edge and 8-10 m from the others, rotated by 25 degrees: the
    // page's edge becomes a staircase of obstacle cells bordering the unknown around it, and
    // the alpha shape a band along it, joined to the building's where they are within
    // 2 x alpha_radius_m. The black between page and building is then a hole of the shape
    // whose boundary runs along both, longer than the page's outer loop. Taken as the outer
    // boundary (the floor plan lab_ipa rotated, in the validation corpus), it cut the whole
    // graph. The same plan with unknown instead of the page's black gives the same graph.
    const auto office = makeOfficeMap();
    const Eigen::Vector2d offset(1.5, 10.0);
    GridSketch page(43.0, 42.0);
    auto black = page.grid();
    for (int cy = 0; cy < int(office.getSizeY()); ++cy)
        for (int cx = 0; cx < int(office.getSizeX()); ++cx)
            if (office.getCell(cx, cy) > 0.5f)
                black.setCell(black.x2idx(office.idx2x(cx) + offset.x()),
                              black.y2idx(office.idx2y(cy) + offset.y()), 1.0f);
    auto grey = black;  // the office's own 32 m x 22 m page, unknown around it
    for (int cy = 0; cy < int(grey.getSizeY()); ++cy)
        for (int cx = 0; cx < int(grey.getSizeX()); ++cx)
        {
            const Eigen::Vector2d p(grey.idx2x(cx) - offset.x(), grey.idx2y(cy) - offset.y());
            if (p.x() < 0.0 || p.y() < 0.0 || p.x() > 32.0 || p.y() > 22.0)
                grey.setCell(cx, cy, 0.5f);
        }
    const double yaw = 25.0 * kDeg;
    const TopologyGraph on_grey = buildTopologyGraph(transformGrid(grey, yaw, {0.0, 0.0}));
    ASSERT_GE(on_grey.vertices.size(), 20u);
    GraphBuildStats st;
    const TopologyGraph on_black =
        buildTopologyGraph(transformGrid(black, yaw, {0.0, 0.0}), {}, &st);
    expectWellFormed(on_black);
    EXPECT_EQ(st.vertices_after_alpha, st.vertices_after_prune);  // nothing of it is outside
    expectSameGraph(on_grey, on_black);
}

TEST(GraphBuilder, ADeadEndStopsWhereItsCorridorEndsNotInACorner)
{
    // A corridor 1.5 m wide whose east end wall is slanted, from (10, 1.5) to (12, 3): its
    // north-east corner is acute (37 degrees), and the medial axis's branch into it loses
    // clearance far more slowly than into a right angle, so corner-spur pruning keeps it. The
    // dead end then lies in the corner, at the 0.3 m clearance filter, and moves with every
    // change of that corner's cells. With dead_end_tail_share its tip goes back to where the
    // corridor still has 0.9 of its half width: on the corridor's axis.
    GridSketch s(14.0, 4.5);
    s.carve(1.0, 1.5, 12.0, 3.0);
    auto grid = s.grid();
    for (int cy = 0; cy < int(grid.getSizeY()); ++cy)
        for (int cx = 0; cx < int(grid.getSizeX()); ++cx)
        {
            const double x = grid.idx2x(cx), y = grid.idx2y(cy);
            if (x > 10.0 + (y - 1.5) * 2.0 / 1.5) grid.setCell(cx, cy, 0.0f);
        }
    GraphBuilderParameters paper_tips;
    paper_tips.dead_end_tail_share = 0.0;
    const TopologyGraph tips = buildTopologyGraph(grid, paper_tips);
    ASSERT_EQ(tips.vertices.size(), 2u);
    const TopoVertex& corner = *std::max_element(tips.vertices.begin(), tips.vertices.end(),
                                                 [](const auto& a, const auto& b)
                                                 { return a.position_m.x() < b.position_m.x(); });
    EXPECT_LT(corner.clearance_m, 0.5) << "in the corner";
    EXPECT_GT(corner.position_m.y(), 2.45);

    const TopologyGraph g = buildTopologyGraph(grid);
    expectWellFormed(g);
    ASSERT_EQ(g.vertices.size(), 2u);
    for (const auto& v : g.vertices)
    {
        EXPECT_EQ(v.degree(), 1);
        EXPECT_GE(v.clearance_m, 0.9 * 0.75 - 0.05);
        EXPECT_NEAR(v.position_m.y(), 2.25, 0.12) << "on the corridor's axis";
    }
    // The square west end is as before.
    const TopoVertex* west = vertexNear(g, 1.75, 2.25);
    EXPECT_NE(west, nullptr);
    EXPECT_NE(vertexNear(tips, 1.75, 2.25), nullptr);
}

TEST(GraphBuilder, AWallWithGapsKeepsItsCorridorsDeadEnd)
{
    // RTAB-Map's lidar map of the Gazebo office (../shared/data, MIT; same frame as its ground
    // truth): its corridor walls are one cell thick with gaps of 1-5 cells every metre or so,
    // and behind them stray free and occupied cells. Several gaps grow a branch from the west
    // corridor's axis, each a junction on it. Pruned in one pass, the first junction, 0.9 m
    // from the corridor's dead end, had the dead end within its disc (junction_disc_ratio) and
    // cut it, and the dead end stood 0.85 m east of the ground truth's; the branches themselves
    // go as corner spurs. The junction disc now waits for them (GraphEditor::pruneDeadEnds).
    // (A synthetic wall with clean gaps grows no branch: each would be one Voronoi segment
    // from the gap to the axis, dropped whole by the clearance filter.)
    const auto gt_file = sharedDataFile("gazebo_slam/office/office_ground_truth.yaml");
    const auto map_file = sharedDataFile("gazebo_slam/office/lidar_rtabmap_map.yaml");
    if (!gt_file || !map_file) GTEST_SKIP() << "no ../shared/data";
    auto westDeadEnd = [](const TopologyGraph& g)
    {
        const TopoVertex* west = nullptr;
        for (const auto& v : g.vertices)
            if (v.degree() == 1 && (!west || v.position_m.x() < west->position_m.x())) west = &v;
        return west;
    };
    const TopologyGraph gt = buildTopologyGraph(loadMap(*gt_file).grid);
    const TopologyGraph map = buildTopologyGraph(loadMap(*map_file).grid);
    const TopoVertex* g = westDeadEnd(gt);
    const TopoVertex* m = westDeadEnd(map);
    ASSERT_TRUE(g && m);
    EXPECT_LT((g->position_m - m->position_m).norm(), 0.3)
        << "ground truth (" << g->position_m.transpose() << "), map (" << m->position_m.transpose()
        << ")";
}

// GraphEditor::fromSkeleton() joins the Voronoi segments' chains without storing each segment:
// it must give exactly the graph that storing them and dissolveDegreeTwo() gives (vertex order,
// edge order and direction, paths, clearances), which the build used before. Random skeletons
// with dead ends, junctions, multi-edges, pure rings and unused nodes.
TEST(GraphBuilder, ChainsFromTheSkeletonEqualStoredSegmentsDissolved)
{
    using internal::GraphEditor;
    std::mt19937 rng(7);
    for (int trial = 0; trial < 200; ++trial)
    {
        internal::VoronoiSkeleton vd;
        const int nodes = 4 + trial % 40;
        for (int i = 0; i < nodes; ++i)
        {
            vd.node_pos.emplace_back(double(rng() % 50), double(rng() % 50));
            vd.node_clearance.push_back(double(rng() % 8));  // ties are common
        }
        // A random forest of paths (chains), extra segments (junctions, multi-edges) and a
        // ring of its own; some nodes stay unused.
        for (int i = 1; i < nodes; ++i)
            if (rng() % 4 != 0) vd.edges.push_back({i - 1, i, double(rng() % 5)});
        for (int k = 0; k < nodes / 5; ++k)
        {
            const int a = int(rng() % nodes), b = int(rng() % nodes);
            if (a != b) vd.edges.push_back({a, b, double(rng() % 5)});
        }
        const int ring = int(vd.node_pos.size());
        for (int i = 0; i < 4; ++i)
        {
            vd.node_pos.emplace_back(100.0 + i, 100.0 + (i % 2));
            vd.node_clearance.push_back(i == 2 ? 3.0 : 1.0);
        }
        for (int i = 0; i < 4; ++i) vd.edges.push_back({ring + i, ring + (i + 1) % 4, 0.5});
        std::shuffle(vd.edges.begin(), vd.edges.end(), rng);

        GraphEditor stored;
        std::vector<int> vertex(vd.node_pos.size(), -1);
        auto vertexOf = [&](int n)
        {
            if (vertex[n] < 0) vertex[n] = stored.addVertex(vd.node_pos[n], vd.node_clearance[n]);
            return vertex[n];
        };
        for (const auto& e : vd.edges)
        {
            const int a = vertexOf(e.a), b = vertexOf(e.b);  // first use: a, then b
            stored.addSegment(a, b, e.min_clearance);
        }
        stored.dissolveDegreeTwo();
        const GraphEditor joined = GraphEditor::fromSkeleton(vd);

        ASSERT_EQ(joined.vertices().size(), stored.vertices().size()) << "trial " << trial;
        ASSERT_EQ(joined.edges().size(), stored.edges().size()) << "trial " << trial;
        for (std::size_t v = 0; v < stored.vertices().size(); ++v)
        {
            const auto &x = joined.vertices()[v], &y = stored.vertices()[v];
            EXPECT_EQ(x.pos, y.pos);
            EXPECT_EQ(x.clearance, y.clearance);
            EXPECT_EQ(x.edges, y.edges);
        }
        for (std::size_t e = 0; e < stored.edges().size(); ++e)
        {
            const auto &x = joined.edges()[e], &y = stored.edges()[e];
            EXPECT_EQ(x.a, y.a);
            EXPECT_EQ(x.b, y.b);
            EXPECT_EQ(x.path, y.path);
            EXPECT_EQ(x.clearance, y.clearance);
            EXPECT_EQ(x.min_clearance, y.min_clearance);
            EXPECT_EQ(x.length, y.length);
        }
        // The ring is one loop edge at its vertex of largest clearance.
        const auto ring_vertex = std::find_if(joined.vertices().begin(), joined.vertices().end(),
                                              [](const auto& v) { return v.pos.x() >= 100.0; });
        ASSERT_NE(ring_vertex, joined.vertices().end());
        EXPECT_EQ(ring_vertex->clearance, 3.0);
    }
}

// A map that says its outside is unknown (alpha_page_max_edge_unknown): a hall with two pillars,
// walled north, south and east with unknown beyond, cut open by the map's west edge (a crop
// through it). Its free space reaches the map's edge, and the alpha polygon (walls only, the
// hall wider than twice the radius) leaves it out; but the map's edge is mostly unknown, so
// that free space is the map's inside and the hall's skeleton, the loops around the pillars,
// stays. The same hall drawn on a white page (the outside free) is the page's: it is cut.
TEST(GraphBuilder, AlphaCutSparesAHallTheMapsEdgeCuts)
{
    auto hall = [](bool page)
    {
        GridSketch s(26.0, 18.0);
        if (page)
            s.carve(0.0, 0.0, 26.0, 18.0);
        else
            s.unknown(0.0, 0.0, 26.0, 18.0);
        s.fill(0.0, 1.7, 22.3, 2.0).fill(0.0, 14.0, 22.3, 14.3).fill(22.0, 1.7, 22.3, 14.3);
        s.carve(0.0, 2.0, 22.0, 14.0);
        s.fill(9.7, 7.7, 10.3, 8.3).fill(15.7, 7.7, 16.3, 8.3);
        return s;
    };
    auto inHall = [](const TopologyGraph& g)
    {
        return std::count_if(g.vertices.begin(), g.vertices.end(),
                             [](const TopoVertex& v)
                             {
                                 return v.position_m.x() > 6.0 && v.position_m.x() < 21.0 &&
                                        v.position_m.y() > 3.0 && v.position_m.y() < 13.0;
                             });
    };
    GraphBuilderParameters session28;  // free space at the map's edge is always outside
    session28.alpha_page_max_edge_unknown = 1.0;
    const GridSketch cropped = hall(false), page = hall(true);
    const TopologyGraph g = buildTopologyGraph(cropped.grid());
    expectWellFormed(g);
    // The pillars stand in two loops that share an edge: its two junctions, between them.
    EXPECT_EQ(inHall(g), 2);
    EXPECT_EQ(inHall(buildTopologyGraph(cropped.grid(), session28)), 0);
    EXPECT_EQ(inHall(buildTopologyGraph(page.grid())), 0);
    EXPECT_EQ(inHall(buildTopologyGraph(page.grid(), session28)), 0);
}

// The same on standard corpus case column_hall_1002/crop_0.75 (tests/data/cropped_hall): the
// crop cuts the building's south rooms and corridor open, and both column halls' free space
// reaches the map's edge through them. With free space at the edge always outside (session 28)
// the cut left 2 of the map's vertices; its edge being mostly unknown, it keeps 38. The ground
// truth (unknown all around, no free cell on its edge) is the same either way.
TEST(GraphBuilder, AlphaCutSparesACroppedMapsInside)
{
    const auto [gt, map] = corpusCase("cropped_hall", "column_hall_1002_crop_0.75");
    GraphBuilderParameters session28;
    session28.alpha_page_max_edge_unknown = 1.0;
    session28.room_piece_min_length_m = session28.min_component_length_m;  // none then
    const TopologyGraph g = buildTopologyGraph(map);
    expectWellFormed(g);
    EXPECT_EQ(g.vertices.size(), 38u);
    EXPECT_EQ(buildTopologyGraph(map, session28).vertices.size(), 2u);
    EXPECT_EQ(buildTopologyGraph(gt).vertices.size(), 66u);
    EXPECT_EQ(buildTopologyGraph(gt, session28).vertices.size(), 66u);
}

// The alpha cut spares free space that does not reach the map's edge (alpha_keep_enclosed):
// standard corpus case multi_wing_1001/broken_1 (tests/data/enclosed_free). Its broken map
// draws a wing apart from the rest, an island of walls of its own, enclosed by them and by
// unknown; the paper keeps the longest polygon of the alpha shape only, and the wing's 12
// vertices (all east of x = 8.5 m, the rest west of 6.7 m) went with the outside.
TEST(GraphBuilder, AlphaCutSparesEnclosedFreeSpace)
{
    const auto [gt, map] = corpusCase("enclosed_free", "multi_wing_1001_broken_1");
    GraphBuilderParameters paper;
    paper.alpha_keep_enclosed = false;
    const TopologyGraph g = buildTopologyGraph(map);
    const TopologyGraph g0 = buildTopologyGraph(map, paper);
    expectWellFormed(g);
    auto inWing = [](const TopologyGraph& t)
    {
        return std::count_if(t.vertices.begin(), t.vertices.end(),
                             [](const TopoVertex& v) { return v.position_m.x() > 8.5; });
    };
    EXPECT_EQ(inWing(g), 12);
    EXPECT_EQ(inWing(g0), 0);
    EXPECT_EQ(g.vertices.size(), g0.vertices.size() + 12);
    // The ground truth, one building, has no free space outside the polygon: the same graph.
    EXPECT_EQ(buildTopologyGraph(gt).vertices.size(),
              buildTopologyGraph(gt, paper).vertices.size());
}
