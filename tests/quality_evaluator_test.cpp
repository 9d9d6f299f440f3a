/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Paper IV: map attributes from a match. The answers are built first: maps moved rigidly,
// broken once, twice and three times by known rotations, cropped, or of another building.

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/evaluation/evaluate_match.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/map_io.h>
#include <mrpt_topoeval/matching/match_graphs.h>
#include <mrpt_topoeval/output.h>
#include <mrpt_topoeval/pipeline/evaluate.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <set>

#include "../libmrpt_topoeval/src/geometry/horn.h"
#include "../libmrpt_topoeval/src/geometry/rigid_split.h"
#include "synthetic_maps.h"
#include "test_paths.h"

using namespace mrpt_topoeval;
using namespace mrpt_topoeval::testing;
using mrpt::maps::COccupancyGridMap2D;

namespace
{
constexpr double kDeg = M_PI / 180.0;

QualityReport compare(const COccupancyGridMap2D& gt, const COccupancyGridMap2D& map,
                      const std::string& name)
{
    TopologyGraph g, m;
    // TOPOEVAL_MATCH_INI=file.ini: other parameters, to explore settings without recompiling.
    const char* ini = std::getenv("TOPOEVAL_MATCH_INI");
    const QualityReport r =
        evaluate(gt, map, ini ? Parameters::fromIniFile(ini) : Parameters{}, &g, &m);
    if (std::getenv("TOPOEVAL_DEBUG")) std::cout << "== " << name << "\n" << r.fullReport();
    if (const char* dir = std::getenv("TOPOEVAL_DUMP_DIR"))
        writePngAtomic(std::string(dir) + "/" + name + ".png", drawMatch(gt, g, map, m, r.match),
                       true);
    return r;
}

// The campus broken `n` times: each break rotates everything east of a cut (in the map as it
// is by then) about a point on the cut.
struct Break
{
    double cut_x, pivot_y, yaw_deg;
};
const std::vector<Break> kBreaks = {{16.5, 12.0, 14.0}, {31.0, 28.0, -22.0}, {46.0, 14.0, 18.0}};

// Where the n-times broken campus puts a point of the campus.
Eigen::Vector2d brokenPoint(int n, Eigen::Vector2d p)
{
    for (int k = 0; k < n; ++k)
    {
        const Break b = kBreaks[k];
        p = breakPoint(
            {b.cut_x, b.pivot_y}, b.yaw_deg * kDeg,
            [cut = b.cut_x](double x, double) { return x > cut; }, p);
    }
    return p;
}

COccupancyGridMap2D brokenCampus(int n)
{
    COccupancyGridMap2D m = makeCampusMap();
    for (int k = 0; k < n; ++k)
    {
        const Break b = kBreaks[k];
        m = breakMap(m, {b.cut_x, b.pivot_y}, b.yaw_deg * kDeg,
                     [cut = b.cut_x](double x, double) { return x > cut; });
    }
    return m;
}
}  // namespace

TEST(Horn, RecoversAKnownTransformFarFromTheOrigin)
{
    // 10 km from the origin, where float-based estimators lose metres.
    const Transform2D truth{10000.3, -7000.7, 33.0};
    std::vector<Eigen::Vector2d> map = {{10.0, 5.0}, {12.0, 9.0}, {15.0, 4.0}, {9.0, 1.0}};
    for (auto& p : map) p += Eigen::Vector2d(9000.0, -8000.0);
    std::vector<Eigen::Vector2d> gt;
    for (const auto& p : map) gt.push_back(truth.apply(p));
    double mse = 1.0;
    const Transform2D t = internal::hornAlign(gt, map, &mse);
    EXPECT_NEAR(t.yaw_deg, 33.0, 1e-9);
    EXPECT_NEAR(t.x_m, truth.x_m, 1e-6);
    EXPECT_NEAR(t.y_m, truth.y_m, 1e-6);
    EXPECT_LT(mse, 1e-12);
}

TEST(Horn, ApplyKeepsNoStaleRotation)
{
    // apply() keeps the last yaw's sine and cosine: transforms taken in turn, repeated, of yaws
    // a hair apart, of -0 and 0 (whose sines differ in sign) and of no number must each give
    // bit for bit what the rotation computed afresh gives.
    auto fresh = [](const Transform2D& t, const Eigen::Vector2d& p)
    {
        const double a = t.yaw_deg * M_PI / 180.0;
        return Eigen::Vector2d(t.x_m + std::cos(a) * p.x() - std::sin(a) * p.y(),
                               t.y_m + std::sin(a) * p.x() + std::cos(a) * p.y());
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<Transform2D> ts = {{0.0, 0.0, 0.0},
                                         {-0.0, -0.0, -0.0},
                                         {1.5, -2.0, -0.0},
                                         {1.5, -2.0, 33.0},
                                         {1.5, -2.0, std::nextafter(33.0, 34.0)},
                                         {-7.0, 0.25, -179.9},
                                         {0.0, 0.0, nan},
                                         {3.0, 4.0, 90.0}};
    const std::vector<Eigen::Vector2d> ps = {{0.0, 0.0},  {-0.0, -0.0}, {-0.0, 1.0},
                                             {1.0, -0.0}, {2.5, -1.0},  {-3e4, 7e3}};
    auto same = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b)
    {
        for (int k = 0; k < 2; ++k)
            if (std::memcmp(&a[k], &b[k], sizeof(double)) != 0) return false;
        return true;
    };
    for (const std::size_t order : {0u, 1u, 2u})
        for (std::size_t i = 0; i < 3 * ts.size(); ++i)
        {
            // In turn, each twice in a row, and back and forth.
            const std::size_t k = order == 0   ? i % ts.size()
                                  : order == 1 ? (i / 2) % ts.size()
                                               : (i * 5) % ts.size();
            for (const auto& p : ps)
                EXPECT_TRUE(same(ts[k].apply(p), fresh(ts[k], p)))
                    << "yaw " << ts[k].yaw_deg << " at " << p.transpose();
        }
}

TEST(Horn, LeaveOneOutErrorsEqualRefitsWithoutEachPair)
{
    // 2 km from the origin; one pair 2.6 m off. Every value equals an explicit refit.
    const Transform2D truth{2000.0, -1500.0, 27.0};
    std::vector<Eigen::Vector2d> map = {{0, 0}, {6, 1}, {11, -2}, {4, 8}, {-5, 6}, {9, 9}};
    for (auto& p : map) p += Eigen::Vector2d(300.0, 200.0);
    std::vector<Eigen::Vector2d> gt;
    for (const auto& p : map) gt.push_back(truth.apply(p));
    gt[5] += Eigen::Vector2d(1.8, -1.9);
    const std::vector<double> e2 = internal::leaveOneOutSquaredErrors(gt, map);
    ASSERT_EQ(e2.size(), gt.size());
    for (std::size_t k = 0; k < gt.size(); ++k)
    {
        std::vector<Eigen::Vector2d> g2 = gt, m2 = map;
        g2.erase(g2.begin() + long(k));
        m2.erase(m2.begin() + long(k));
        const Transform2D t = internal::hornAlign(g2, m2);
        EXPECT_NEAR(e2[k], (gt[k] - t.apply(map[k])).squaredNorm(), 1e-6) << k;
    }
    // Without the wrong pair the fit is exact, so its error is its offset; the others' errors
    // are what the wrong pair does to the fit of the rest, smaller.
    EXPECT_NEAR(std::sqrt(e2[5]), std::hypot(1.8, 1.9), 1e-6);
    EXPECT_EQ(std::max_element(e2.begin(), e2.end()) - e2.begin(), 5);
}

TEST(Horn, AgreementPointIsThePivotOfABreak)
{
    // A map's part turned by 25 degrees about a pivot: the whole map's transform and the part's
    // agree at the pivot (in the ground truth's frame) and nowhere else; a shift has no such
    // point.
    const Transform2D whole{3.0, -2.0, 40.0};
    const Eigen::Vector2d pivot_gt(12.0, 7.5);
    // part(m) = R(-25) (whole(m) - pivot) + pivot: the part, put back by a further turn.
    const double t = -25.0 * M_PI / 180.0;
    const Eigen::Rotation2Dd turn(t);
    const Eigen::Vector2d at0 = turn * (whole.apply({0.0, 0.0}) - pivot_gt) + pivot_gt;
    const Transform2D part{at0.x(), at0.y(), whole.yaw_deg - 25.0};
    const auto p = internal::agreementPoint(whole, part);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->x(), pivot_gt.x(), 1e-9);
    EXPECT_NEAR(p->y(), pivot_gt.y(), 1e-9);
    EXPECT_FALSE(internal::agreementPoint(whole, Transform2D{5.0, 1.0, 40.0}).has_value());
}

namespace
{
// Pairs along a corridor with rooms off it (ground truth), their map points placed by the
// inverse of T_gt_map = (3 m, -2 m, 40 deg); pairs from x >= 7 m also turned by `turn_deg`
// about (7, 0) in the ground truth, a break; each point jittered by up to `jitter_m`, as vertices
// slide. Links: consecutive pairs.
struct SplitCase
{
    std::vector<Eigen::Vector2d> gt, map;
    std::vector<std::vector<int>> links;
};
SplitCase brokenCorridor(double turn_deg, double jitter_m)
{
    SplitCase c;
    const double yaw = 40.0 * M_PI / 180.0, t = turn_deg * M_PI / 180.0;
    const Eigen::Rotation2Dd r_inv(-yaw), turn(-t);
    const Eigen::Vector2d shift(3.0, -2.0), pivot(7.0, 0.0);
    for (int i = 0; i < 14; ++i)
    {
        const Eigen::Vector2d g(1.0 * i + 0.3, (i % 3 == 0) ? 2.5 : (i % 3 == 1 ? 0.0 : -1.5));
        Eigen::Vector2d placed = g.x() >= 7.0 ? Eigen::Vector2d(turn * (g - pivot) + pivot) : g;
        placed += jitter_m * Eigen::Vector2d(std::sin(1.7 * i), std::cos(2.3 * i));
        c.gt.push_back(g);
        c.map.push_back(r_inv * (placed - shift));
    }
    c.links.resize(c.gt.size());
    for (int i = 0; i + 1 < int(c.gt.size()); ++i)
    {
        c.links[std::size_t(i)].push_back(i + 1);
        c.links[std::size_t(i + 1)].push_back(i);
    }
    return c;
}
}  // namespace

// Two parts turned 11 degrees against each other about their cut: the split is at the cut, and
// each side's fit is its part's (40 and 51 degrees).
TEST(RigidSplit, TwoPartsTurnedAboutTheirCutAreSplitThere)
{
    const SplitCase c = brokenCorridor(11.0, 0.05);
    const auto split = internal::bestRigidSplit(c.gt, c.map, c.links, 3, 5, 0.2);
    ASSERT_TRUE(split.has_value());
    for (std::size_t i = 0; i < c.gt.size(); ++i)
        EXPECT_EQ(split->side[i], c.gt[i].x() >= 7.0 ? 1 : 0) << i;
    EXPECT_NEAR(split->fit[0].yaw_deg, 40.0, 0.5);
    EXPECT_NEAR(split->fit[1].yaw_deg, 51.0, 0.5);
    EXPECT_LT(split->squared_error_m2[0], 0.01);
    EXPECT_LT(split->squared_error_m2[1], 0.01);
    // One fit of all is a compromise the paper's threshold (0.2 m^2) lets through, ten times
    // worse than either part's.
    double mse = 0.0;
    internal::hornAlign(c.gt, c.map, &mse);
    EXPECT_LT(mse, 0.2);
    EXPECT_GT(mse, 10.0 * std::max(split->squared_error_m2[0], split->squared_error_m2[1]));
}

// One rigid part with the same jitter: its local fits agree, so there is no split to propose.
TEST(RigidSplit, ARigidPartHasNoSplit)
{
    const SplitCase c = brokenCorridor(0.0, 0.05);
    EXPECT_FALSE(internal::bestRigidSplit(c.gt, c.map, c.links, 3, 5, 0.2).has_value());
    // Sets that are not connected are no split: without links every split is refused.
    const SplitCase b = brokenCorridor(11.0, 0.05);
    const std::vector<std::vector<int>> none(b.gt.size());
    EXPECT_FALSE(internal::bestRigidSplit(b.gt, b.map, none, 3, 5, 0.2).has_value());
}

namespace
{
/** A graph of the given vertices (world positions) and edges (straight), with rings as the
 * builder makes them; clearance 0.5 m everywhere. */
TopologyGraph handGraph(const std::vector<Eigen::Vector2d>& at,
                        const std::vector<std::pair<int, int>>& edges)
{
    TopologyGraph g;
    for (std::size_t i = 0; i < at.size(); ++i)
    {
        TopoVertex v;
        v.id = int(i);
        v.position_m = at[i];
        v.clearance_m = 0.5;
        g.vertices.push_back(v);
    }
    for (const auto& [a, b] : edges)
    {
        TopoEdge e;
        e.id = int(g.edges.size());
        e.from = a;
        e.to = b;
        e.path_m = {at[a], at[b]};
        e.clearance_m = {0.5, 0.5};
        e.length_m = (at[b] - at[a]).norm();
        e.min_clearance_m = e.mean_clearance_m = 0.5;
        e.dead_end = true;
        const Eigen::Vector2d d = at[b] - at[a];
        g.vertices[a].ring.push_back({e.id, b, true, std::atan2(d.y(), d.x())});
        g.vertices[b].ring.push_back({e.id, a, false, std::atan2(-d.y(), -d.x())});
        g.edges.push_back(e);
    }
    return g;
}

/** Stars of a junction with four rooms 2.5 m round it and a corridor's dead end 15 m away, one
 * per offset along x (graph pieces of their own); the map is the ground truth turned by 20
 * degrees, but the first star's dead end sits 1 m across its corridor from where the turn puts
 * it: a wrong pair. Every vertex is matched to its own, one isomorphism per star. */
struct TurnedStars
{
    TopologyGraph gt, map;
    GraphMatch match;
};
TurnedStars turnedStarsWithAWrongPair(const std::vector<double>& offsets)
{
    const std::vector<Eigen::Vector2d> star = {{0, 0},    {0, 2.5},    {0, -2.5},
                                               {-2.5, 0}, {-1.8, 1.8}, {15, 0}};
    std::vector<Eigen::Vector2d> at;
    std::vector<std::pair<int, int>> edges;
    TurnedStars t;
    for (const double dx : offsets)
    {
        const int base = static_cast<int>(at.size());
        for (const auto& p : star) at.push_back(p + Eigen::Vector2d(dx, 0.0));
        for (int k = 1; k < 6; ++k) edges.emplace_back(base, base + k);
        t.match.isomorphism_sizes.push_back(6);
    }
    const Transform2D turn{4.0, -3.0, 20.0};  // ground truth -> map
    std::vector<Eigen::Vector2d> moved;
    for (const auto& p : at) moved.push_back(turn.apply(p));
    moved[5] += Eigen::Rotation2Dd(20.0 * kDeg) * Eigen::Vector2d(0.0, 1.0);
    t.gt = handGraph(at, edges);
    t.map = handGraph(moved, edges);
    const int n = static_cast<int>(at.size());
    for (int i = 0; i < n; ++i) t.match.pairs.push_back({i, i, MatchStage::Isomorphism, 1.0, 0});
    t.match.isomorphism = n;
    return t;
}
}  // namespace

TEST(QualityEvaluator, OneWrongPairDoesNotTurnAPart)
{
    // A junction with four rooms 2.5 m round it and a corridor's dead end 15 m away; the map
    // is the same turned by 20 degrees, but its dead end sits 1 m across the corridor from
    // where the turn puts it: a wrong pair. The paper's group takes it (the fit of all six
    // turns by about 3 degrees to absorb it, within the mean squared error); the fit of the
    // other five places it 1 m off, over brokenness_outlier_ratio x the threshold's root
    // (0.89 m), so it leaves and the part keeps its own turn.
    const TurnedStars t = turnedStarsWithAWrongPair({0.0});
    const TopologyGraph &g = t.gt, &m = t.map;
    const GraphMatch& match = t.match;
    auto groupTurn = [&](const QualityParameters& qp)
    {
        const QualityReport r = evaluateMatch(g, m, match, qp);
        EXPECT_EQ(r.brokenness.groups.size(), 1u);
        return r.brokenness.groups.empty()
                   ? 180.0
                   : std::abs(
                         std::remainder(r.brokenness.groups[0].transform.yaw_deg + 20.0, 360.0));
    };
    QualityParameters paper;
    paper.brokenness_outlier_ratio = 0.0;
    EXPECT_LT(groupTurn(QualityParameters{}), 0.01);
    EXPECT_GT(groupTurn(paper), 2.0);
}

// Two groups of one part are merged once their outliers have left: the star of the test above
// (its dead end a wrong pair, 1 m off) and the same star 30 m east, exact, two graph pieces, so
// growth makes two groups. The wrong pair turns the first group's fit by about 3 degrees, which
// places the other group's vertices 1.5 m apart: not merged then. Without it, both fits are the
// map's turn: one part, brokenness 0 (before session 19 the merging ran only before the
// outliers left, and the part counted as a break; the validation corpus's
// multi_wing_1001/broken_1 found its wing as two groups turned -83.7 and -83.6 degrees).
TEST(QualityEvaluator, GroupsOfOnePartMergeOnceTheirOutliersLeave)
{
    const auto [g, m, match] = turnedStarsWithAWrongPair({0.0, 30.0});
    const QualityReport r = evaluateMatch(g, m, match, QualityParameters{});
    EXPECT_EQ(r.brokenness.degree, 0);
    ASSERT_EQ(r.brokenness.groups.size(), 1u);
    EXPECT_EQ(r.brokenness.groups[0].gt_vertices.size(), 11u);  // the wrong pair left
    EXPECT_LT(std::abs(std::remainder(r.brokenness.groups[0].transform.yaw_deg + 20.0, 360.0)),
              0.01);
}

// Two groups of one part whose walls place them alike are merged (brokenness_merge_by_walls):
// held-out corpus case multi_wing_3001/broken_2 (seed 3, the maps the validator made, kept in
// tests/data/merged_part), a building cut in three whose parts the truth turned by -80.40,
// -96.39 and -57.51 degrees. Near a cut one group of part 0 keeps two pairs of part 1; their
// compromise fit places the rest of part 0, a group of its own, elsewhere by its vertices, so
// the vertex merge leaves them apart, but the walls turn both by -80.41 degrees.
namespace
{
// The part whose known turn [deg] a brokenness group's turn is nearest, and how far from it.
std::pair<int, double> nearestTurn(const BrokennessGroup& g, const std::vector<double>& turns)
{
    int best = -1;
    double error = 1e9;
    for (std::size_t k = 0; k < turns.size(); ++k)
    {
        const double e = std::abs(std::remainder(g.transform.yaw_deg - turns[k], 360.0));
        if (e < error) error = e, best = int(k);
    }
    return {best, error};
}

// The parts whose turns a report's brokenness groups take, each group checked to be within 3
// degrees of its part's known turn (the validator's "exactly right").
std::set<int> partsOfGroups(const QualityReport& r, const std::vector<double>& turns)
{
    std::set<int> parts;
    for (const auto& g : r.brokenness.groups)
    {
        const auto [part, error] = nearestTurn(g, turns);
        EXPECT_LT(error, 3.0) << g.transform.yaw_deg;
        parts.insert(part);
    }
    return parts;
}
}  // namespace

TEST(QualityEvaluator, GroupsThatTheirWallsPlaceAlikeAreOnePart)
{
    const auto [gt, map] = corpusCase("merged_part", "multi_wing_3001_broken_2");
    const std::vector<double> turns = {-80.40, -96.39, -57.51};
    auto partOf = [&](const BrokennessGroup& g) { return nearestTurn(g, turns); };
    Parameters with = Parameters{}, without = Parameters{};
    // The graphs as built when the rule was made (before session 48's room pieces).
    with.graph.room_piece_min_length_m = with.graph.min_component_length_m;
    without.graph.room_piece_min_length_m = without.graph.min_component_length_m;
    without.quality.brokenness_merge_by_walls = false;
    // The rule on the paper's growth (the match's groups alone get this case right, and the
    // best-fit part moves a vertex between part 0's two groups: session 27).
    without.quality.brokenness_from_match_groups = false;
    without.quality.brokenness_best_fit_part = false;
    // With max_pair_turn_deg the matcher's groups leave the paper's growth one group of part 0
    // here: the rule is checked on the match it was found on, with that one off.
    with.matcher.max_pair_turn_deg = 0.0;
    without.matcher.max_pair_turn_deg = 0.0;
    const QualityReport r = evaluate(gt, map, with);
    const QualityReport r0 = evaluate(gt, map, without);
    // Three parts, three groups, each within 3 degrees of its own part's turn.
    EXPECT_EQ(r.brokenness.degree, 2);
    const std::set<int> parts = partsOfGroups(r, turns);
    EXPECT_EQ(parts, (std::set<int>{0, 1, 2}));
    EXPECT_EQ(parts.size(), r.brokenness.groups.size());  // no part counted twice
    // Without the rule part 0 is two groups: a break too many.
    EXPECT_EQ(r0.brokenness.degree, 3);
    int of_part_0 = 0;
    for (const auto& g : r0.brokenness.groups)
        of_part_0 += partOf(g).first == 0 && partOf(g).second < 0.1;
    EXPECT_EQ(of_part_0, 2);
}

// A grown group that is two parts is split (brokenness_split_parts): held-out corpus case
// angled_8004/broken_2 (seed 8, the maps the validator made, kept in tests/data/split_part), a
// building cut in three whose parts the truth turned by 27.12, 38.61 and 9.19 degrees. Every
// pair is true, but the paper's growth holds the first two parts, 11.5 degrees apart, as one
// group of 13 vertices whose compromise fit (33.6 degrees) stays within the 0.2 m^2 threshold.
TEST(QualityEvaluator, TwoPartsInOneGrownGroupAreSplit)
{
    const auto [gt, map] = corpusCase("split_part", "angled_8004_broken_2");
    const std::vector<double> turns = {27.12, 38.61, 9.19};
    Parameters with = Parameters{}, without = Parameters{};
    without.quality.brokenness_split_parts = false;
    // The rule on the paper's growth: the match's groups alone get this case right (session 27).
    without.quality.brokenness_from_match_groups = false;
    without.quality.brokenness_best_fit_part = false;
    const QualityReport r = evaluate(gt, map, with);
    const QualityReport r0 = evaluate(gt, map, without);
    // Three parts, three groups, each within 3 degrees of its own part's turn.
    EXPECT_EQ(r.brokenness.degree, 2);
    const std::set<int> parts = partsOfGroups(r, turns);
    EXPECT_EQ(parts, (std::set<int>{0, 1, 2}));
    EXPECT_EQ(parts.size(), r.brokenness.groups.size());
    // Without the rule: two groups, one of them the compromise, more than 3 degrees off.
    EXPECT_EQ(r0.brokenness.degree, 1);
    double worst = 0.0;
    for (const auto& g : r0.brokenness.groups)
        worst = std::max(worst, nearestTurn(g, turns).second);
    EXPECT_GT(worst, 3.0);
}

// The match's groups are the brokenness candidates (brokenness_from_match_groups): held-out
// angled_9002/broken_1 (tests/data/match_groups), a building cut in two, parts turned -30.33
// and -46.14 degrees. The matcher's groups hold each part apart; the paper's growth, seeded next
// to the cut, makes one group of both parts' vertices turned -40.1 degrees and no break.
TEST(QualityEvaluator, TheMatchsGroupsAreTheBrokennessCandidates)
{
    const auto [gt, map] = corpusCase("match_groups", "angled_9002_broken_1");
    const std::vector<double> turns = {-30.33, -46.14};
    Parameters with = Parameters{}, without = Parameters{};
    without.quality.brokenness_from_match_groups = false;
    // The growth alone (session 28's walls then count the compromise's leftover as a part).
    without.quality.brokenness_part_wall_ratio = 0.0;
    // The compromise's turn by its vertices: its walls, most of them part 1's, vouch for part
    // 1's turn (0.05 degrees off) once the vertices' test refuses them (brokenness_walls_vouch).
    without.quality.brokenness_walls_vouch = false;
    // ... and no part placed by its walls (step 9 places both true parts beside the compromise,
    // whose fit explains neither part's walls).
    without.quality.wall_parts = false;
    const QualityReport r = evaluate(gt, map, with);
    const QualityReport r0 = evaluate(gt, map, without);
    EXPECT_EQ(r.brokenness.degree, 1);
    const std::set<int> parts = partsOfGroups(r, turns);
    EXPECT_EQ(parts, (std::set<int>{0, 1}));
    EXPECT_EQ(parts.size(), r.brokenness.groups.size());
    // Without: one compromise group, more than 3 degrees from either part.
    EXPECT_EQ(r0.brokenness.degree, 0);
    ASSERT_EQ(r0.brokenness.groups.size(), 1u);
    EXPECT_GT(nearestTurn(r0.brokenness.groups.front(), turns).second, 3.0);
    // The match is the same either way: only the groups change.
    EXPECT_EQ(r.match.pairs.size(), r0.match.pairs.size());
}

// A vertex at a cut goes to the group whose transform places it best (brokenness_best_fit_part):
// held-out multi_wing_9002/broken_3 (tests/data/match_groups), four parts. Without the rule a
// vertex of part 0 stays in part 1's group, whose walls then turn it 1.0 degrees off, and part
// 0's 1.6 degrees off; with it every group is within 0.25 degrees of its part's turn.
TEST(QualityEvaluator, AVertexAtACutGoesToThePartThatPlacesItBest)
{
    const auto [gt, map] = corpusCase("match_groups", "multi_wing_9002_broken_3");
    const std::vector<double> turns = {135.61, 147.57, 161.08, 115.30};
    Parameters with = Parameters{}, without = Parameters{};
    without.quality.brokenness_best_fit_part = false;
    const QualityReport r = evaluate(gt, map, with);
    const QualityReport r0 = evaluate(gt, map, without);
    EXPECT_EQ(r.brokenness.degree, 3);
    EXPECT_EQ(partsOfGroups(r, turns), (std::set<int>{0, 1, 2, 3}));
    for (const auto& g : r.brokenness.groups)
        EXPECT_LT(nearestTurn(g, turns).second, 0.25) << g.transform.yaw_deg;
    double worst = 0.0;
    for (const auto& g : r0.brokenness.groups)
        worst = std::max(worst, nearestTurn(g, turns).second);
    EXPECT_GT(worst, 1.0);
}

// A small part's turn from its walls where its vertices' fit refuses them
// (brokenness_walls_vouch): held-out ring_13001/broken_2 (tests/data/match_groups), three parts
// turned -27.76, 2.20 and -53.83 degrees. Part 0's group holds 5 vertices near its cuts, which
// slid with the cuts' walls: their fit turns it -32.99 degrees. Its walls turn it -27.84, but
// the vertices' squared error rises from 0.10 to 0.60 m^2, beyond their 95 % confidence region
// (which takes their own small residual for their noise). The walls agree under that turn and
// pin it: the group is reported at its part's turn. The groups and the match are the same.
TEST(QualityEvaluator, ASmallPartsWallsVouchForItsTurn)
{
    const auto [gt, map] = corpusCase("match_groups", "ring_13001_broken_2");
    const std::vector<double> turns = {-27.76, 2.20, -53.83};
    Parameters with = Parameters{}, without = Parameters{};
    without.quality.brokenness_walls_vouch = false;
    // The rule alone: without it, a part placed by its walls (step 9) would count part 0 again.
    with.quality.wall_parts = without.quality.wall_parts = false;
    const QualityReport r = evaluate(gt, map, with);
    const QualityReport r0 = evaluate(gt, map, without);
    EXPECT_EQ(r.brokenness.degree, 2);
    EXPECT_EQ(partsOfGroups(r, turns), (std::set<int>{0, 1, 2}));
    for (const auto& g : r.brokenness.groups)
        EXPECT_LT(nearestTurn(g, turns).second, 0.2) << g.transform.yaw_deg;
    double worst = 0.0;
    for (const auto& g : r0.brokenness.groups)
        worst = std::max(worst, nearestTurn(g, turns).second);
    EXPECT_GT(worst, 3.0);  // the validator's "a group turned wrong"
    ASSERT_EQ(r.brokenness.groups.size(), r0.brokenness.groups.size());
    for (std::size_t i = 0; i < r.brokenness.groups.size(); ++i)
        EXPECT_EQ(r.brokenness.groups[i].gt_vertices, r0.brokenness.groups[i].gt_vertices);
    EXPECT_EQ(r.match.pairs.size(), r0.match.pairs.size());
}

// A small part that its walls set apart counts (brokenness_part_wall_ratio). Standard corpus
// case corridor_office_1004/broken_3 (tests/data/small_part_walls): part 2, turned 34.12
// degrees against part 0's 22.83, is matched by 4 vertices near its cut with part 0, which
// part 0's fit places 0.49 m^2 (mean squared) from where their own fit does: under the 1 m^2
// gap, so without the rule no break. Under their own fit 0.78 of the walls around them agree,
// under part 0's 0.23. Held-out angled_4003/broken_2 (seed 4): part 0, turned 14 degrees
// against part 2, keeps 3 vertices once part 2's core holds its vertex at the cut.
TEST(QualityEvaluator, ASmallPartThatItsWallsSetApartCounts)
{
    struct Case
    {
        const char* name;
        std::vector<double> turns;
        std::set<int> parts;
    };
    for (const Case& c : {Case{"corridor_office_1004_broken_3", {22.83, 3.99, 34.12, 52.8}, {0, 2}},
                          Case{"angled_4003_broken_2", {-108.21, -91.79, -122.19}, {0, 1, 2}}})
    {
        SCOPED_TRACE(c.name);
        const auto [gt, map] = corpusCase("small_part_walls", c.name);
        Parameters with = Parameters{}, without = Parameters{};
        without.quality.brokenness_part_wall_ratio = 0.0;
        // The rule alone: a part placed by its walls (step 9) finds corridor_office_1004's part
        // 1 (turned 3.99 degrees) with or without it.
        with.quality.wall_parts = without.quality.wall_parts = false;
        const QualityReport r = evaluate(gt, map, with);
        const QualityReport r0 = evaluate(gt, map, without);
        const std::set<int> parts = partsOfGroups(r, c.turns);
        EXPECT_EQ(parts, c.parts);
        EXPECT_EQ(parts.size(), r.brokenness.groups.size());  // no part counted twice
        EXPECT_EQ(r.brokenness.degree, static_cast<int>(c.parts.size()) - 1);
        EXPECT_EQ(r0.brokenness.degree, static_cast<int>(c.parts.size()) - 2);
        EXPECT_EQ(r.match.pairs.size(), r0.match.pairs.size());
    }
}

// Relative accuracy takes the best rigid alignment: the one whose counted errors (beyond the
// slack, at most outlier_distance_m) are the smallest. A map broken in two: a star of six
// vertices in place and, 12 m east, a star of five turned by 80 degrees about its east end (its
// other four vertices 3-6 m off under the first star's fit). Horn's fit of all eleven pairs is
// a compromise (6 degrees) that puts every pair more than 1 m off, and the refits from it keep
// it (counted errors 10.6 m^2); the first star's own fit counts only the four turned vertices,
// each at the 1 m cap: RMSE sqrt(4 / 11) m. Before session 21 the compromise decided
// (column_hall_1002/broken_2: three more true pairs of a small part turned the alignment by
// 8 degrees and the relative RMSE went from 0.65 to 0.95 m).
TEST(QualityEvaluator, RelativeAccuracyTakesTheBestAlignmentOfABrokenMap)
{
    std::vector<Eigen::Vector2d> at = {{0, 0},      {0, 2.5},  {0, -2.5}, {-2.5, 0},
                                       {-1.8, 1.8}, {2.5, 0},  {12, 0},   {14.5, 0},
                                       {9.5, 0},    {12, 2.5}, {12, -2.5}};
    const std::vector<std::pair<int, int>> edges = {{0, 1}, {0, 2}, {0, 3}, {0, 4}, {0, 5},
                                                    {6, 7}, {6, 8}, {6, 9}, {6, 10}};
    std::vector<Eigen::Vector2d> moved = at;
    const Eigen::Rotation2Dd turn(80.0 * kDeg);
    for (int i = 6; i < 11; ++i) moved[i] = at[7] + turn * (at[i] - at[7]);
    const TopologyGraph g = handGraph(at, edges), m = handGraph(moved, edges);
    GraphMatch match;
    for (int i = 0; i < 11; ++i)
        match.pairs.push_back({i, i, MatchStage::Isomorphism, 1.0, i < 6 ? 0 : 1});
    match.isomorphism = 11;
    match.isomorphism_sizes = {6, 5};
    const QualityReport r = evaluateMatch(g, m, match, QualityParameters{});
    EXPECT_NEAR(r.relative_accuracy.rmse_m, std::sqrt(4.0 / 11.0), 1e-6);
    EXPECT_NEAR(r.relative_accuracy.transform.yaw_deg, 0.0, 1e-6);
    EXPECT_NEAR(r.relative_accuracy.transform.x_m, 0.0, 1e-6);
    EXPECT_NEAR(r.relative_accuracy.transform.y_m, 0.0, 1e-6);
    // The paper's (no outlier distance): Horn's fit of every pair, errors uncapped.
    QualityParameters paper;
    paper.outlier_distance_m = 0.0;
    const QualityReport rp = evaluateMatch(g, m, match, paper);
    EXPECT_GT(std::abs(rp.relative_accuracy.transform.yaw_deg), 1.0);
}

// A pair's error is measured at its walls (pair_wall_margin_m): a vertex of a room slides along
// the medial axis between two maps of it by a fraction of the room's half width, its walls do
// not. Nine rooms (boxes 2 m wide, 3 m apart), each vertex in its room's middle; the map is the
// same turned by 30 degrees and shifted. Known answers: (a) one map vertex slid 0.3 m in its
// room, walls exact: error 0 at the walls, not at the vertices; (b) one room, walls and vertex,
// 0.2 m off, or 0.6 m, or a corridor's 0.3 m along it: the walls give the vertices' own figure,
// never 0; (c) a wrong pair (the map
// vertex in the next room) is not made right by walls: it keeps its vertex error, clipped at
// outlier_distance_m.
TEST(QualityEvaluator, APairsErrorIsMeasuredAtItsWalls)
{
    std::vector<Eigen::Vector2d> at;
    std::vector<std::pair<int, int>> edges;
    for (int k = 0; k < 9; ++k)
    {
        at.emplace_back(3.0 * (k % 3), 3.0 * (k / 3));
        if (k % 3) edges.emplace_back(k - 1, k);
        if (k >= 3) edges.emplace_back(k - 3, k);
    }
    const std::size_t n = at.size();
    const Transform2D turn{4.0, -3.0, 30.0};  // ground truth -> map
    // A room's walls: a box, or (corridor) only its two walls along x.
    auto addBox = [](const Transform2D& T, const Eigen::Vector2d& c, bool corridor,
                     std::vector<Eigen::Vector2f>& out)
    {
        for (int k = -20; k <= 20; ++k)
        {
            const double u = 0.05 * k;
            for (const Eigen::Vector2d& q : {Eigen::Vector2d(u, -1.0), Eigen::Vector2d(u, 1.0)})
                out.push_back(T.apply(c + q).cast<float>());
            if (corridor) continue;
            for (const Eigen::Vector2d& q : {Eigen::Vector2d(-1.0, u), Eigen::Vector2d(1.0, u)})
                out.push_back(T.apply(c + q).cast<float>());
        }
    };
    // room_offset: where each room (walls and vertex) lies off in the map, in the ground
    // truth's frame; vertex_slide: how far each map vertex slid from its room's middle;
    // corridor: the room with only two walls (none: -1).
    auto graphs = [&](const std::vector<Eigen::Vector2d>& room_offset,
                      const std::vector<Eigen::Vector2d>& vertex_slide, int corridor = -1)
    {
        std::vector<Eigen::Vector2d> moved;
        for (std::size_t i = 0; i < n; ++i)
            moved.push_back(turn.apply(at[i] + room_offset[i] + vertex_slide[i]));
        TopologyGraph g = handGraph(at, edges), m = handGraph(moved, edges);
        g.map.resolution_m = m.map.resolution_m = 0.05;
        for (auto* graph : {&g, &m})
            for (auto& v : graph->vertices) v.clearance_m = 1.0;  // a 2 m room's middle
        for (std::size_t i = 0; i < n; ++i)
        {
            addBox(Transform2D{}, at[i], int(i) == corridor, g.wall_points_m);
            addBox(turn, at[i] + room_offset[i], int(i) == corridor, m.wall_points_m);
        }
        return std::make_pair(g, m);
    };
    GraphMatch match;
    for (int i = 0; i < int(n); ++i) match.pairs.push_back({i, i, MatchStage::Isomorphism, 1.0, 0});
    match.isomorphism = int(n);
    match.isomorphism_sizes = {n};
    QualityParameters walls, vertices;
    walls.pair_wall_margin_m = 0.5;  // a room's own walls, not the next room's (2 m away)
    vertices.pair_wall_margin_m = 0.0;
    walls.vertex_slack_share = vertices.vertex_slack_share = 0.0;
    const std::vector<Eigen::Vector2d> none(n, Eigen::Vector2d::Zero());

    // (a) Vertex 4 slid 0.3 m along its room.
    auto slid = none;
    slid[4] = {0.3, 0.0};
    const auto [ga, ma] = graphs(none, slid);
    const QualityReport a_walls = evaluateMatch(ga, ma, match, walls),
                        a_vertices = evaluateMatch(ga, ma, match, vertices);
    EXPECT_EQ(a_walls.relative_accuracy.by_walls, n);
    EXPECT_EQ(a_vertices.relative_accuracy.by_walls, 0u);
    EXPECT_LT(a_walls.relative_accuracy.rmse_m, 0.01);
    EXPECT_GT(a_vertices.relative_accuracy.rmse_m, 0.08);
    for (const auto& c : a_walls.local_consistency) EXPECT_LT(c.mean_error_m, 0.01) << c.name;

    // Room 8 (walls and vertex) `offset` off, as a box or (corridor) a stretch of corridor:
    // the graphs, and the reports at the walls and at the vertices.
    struct RoomOff
    {
        TopologyGraph g, m;
        QualityReport at_walls, at_vertices;
    };
    auto roomOff = [&](const Eigen::Vector2d& offset, bool corridor)
    {
        auto off = none;
        off[8] = offset;
        auto [g, m] = graphs(off, none, corridor ? 8 : -1);
        RoomOff r{g, m, evaluateMatch(g, m, match, walls), evaluateMatch(g, m, match, vertices)};
        return r;
    };

    // (b) Room 8 0.2 m off: the map's own error, as its vertices show it.
    const RoomOff b = roomOff({0.0, 0.2}, false);
    EXPECT_EQ(b.at_walls.relative_accuracy.by_walls, n);
    EXPECT_GT(b.at_vertices.relative_accuracy.rmse_m, 0.05);
    EXPECT_NEAR(b.at_walls.relative_accuracy.rmse_m, b.at_vertices.relative_accuracy.rmse_m, 0.01);

    // (b') Room 8 0.6 m off, farther than ICP's first matching distance (0.45 m): the walls
    // still give the vertices' figure, never an error of 0 from an ICP that found nothing.
    const RoomOff f = roomOff({0.6, 0.0}, false);
    EXPECT_GT(f.at_vertices.relative_accuracy.rmse_m, 0.15);
    EXPECT_NEAR(f.at_walls.relative_accuracy.rmse_m, f.at_vertices.relative_accuracy.rmse_m, 0.01);

    // (b'') Room 8 is a stretch of corridor, 0.3 m off along it: its walls do not fix a place
    // along it (pair_wall_max_pinning), so the pair keeps its vertex's figure, not 0.
    const RoomOff c8 = roomOff({0.3, 0.0}, true);
    EXPECT_EQ(c8.at_walls.relative_accuracy.by_walls, n - 1);
    EXPECT_GT(c8.at_vertices.relative_accuracy.rmse_m, 0.08);
    EXPECT_NEAR(c8.at_walls.relative_accuracy.rmse_m, c8.at_vertices.relative_accuracy.rmse_m,
                0.01);

    // Graphs without walls: the vertices, as with pair_wall_margin_m = 0.
    TopologyGraph bare_g = b.g, bare_m = b.m;
    bare_g.wall_points_m.clear();
    bare_m.wall_points_m.clear();
    const QualityReport bare = evaluateMatch(bare_g, bare_m, match, walls);
    EXPECT_EQ(bare.relative_accuracy.by_walls, 0u);
    EXPECT_DOUBLE_EQ(bare.relative_accuracy.rmse_m, b.at_vertices.relative_accuracy.rmse_m);

    // (c) The map vertex of pair 4 sits in room 5, 3 m off (a wrong pair): the walls around
    // it do not agree with those around the ground-truth vertex under any alignment ICP finds
    // within reach, so it keeps its vertex error (clipped).
    auto wrong = none;
    wrong[4] = at[5] - at[4] + Eigen::Vector2d(0.0, 0.4);
    const auto [gc, mc] = graphs(none, wrong);
    const QualityReport c_walls = evaluateMatch(gc, mc, match, walls);
    EXPECT_EQ(c_walls.relative_accuracy.by_walls, n - 1);
    EXPECT_NEAR(c_walls.relative_accuracy.rmse_m, walls.outlier_distance_m / std::sqrt(double(n)),
                0.01);
}

TEST(QualityEvaluator, RigidlyMovedMap)
{
    const auto campus = makeCampusMap();
    for (double yaw : {0.0, 37.0, 151.0, 292.0})
    {
        const QualityReport r = compare(campus, transformGrid(campus, yaw * kDeg, {5.0, -3.0}),
                                        "moved_" + std::to_string(int(yaw)));
        EXPECT_GE(r.coverage, 0.9) << yaw;
        EXPECT_EQ(r.brokenness.degree, 0) << yaw;
        EXPECT_LT(r.relative_accuracy.rmse_m, 2 * 0.05) << yaw;
        EXPECT_NEAR(std::remainder(r.relative_accuracy.transform.yaw_deg + yaw, 360.0), 0.0, 1.0)
            << yaw;
    }
}

TEST(QualityEvaluator, BrokenOnceTwiceThrice)
{
    const auto campus = makeCampusMap();
    for (int n = 1; n <= 3; ++n)
    {
        const auto broken = brokenCampus(n);
        TopologyGraph g, m;
        const QualityReport r = evaluate(campus, broken, Parameters{}, &g, &m);
        if (std::getenv("TOPOEVAL_DEBUG"))
            for (const auto& grp : r.brokenness.groups)
            {
                int ok = 0;
                for (int v : grp.gt_vertices)
                {
                    const int mv = r.match.mapVertexOf(v);
                    const double err =
                        (m.vertices[mv].position_m - brokenPoint(n, g.vertices[v].position_m))
                            .norm();
                    ok += err <= std::max(0.3, 0.5 * g.vertices[v].clearance_m);
                }
                std::cout << "broken " << n << ": group of " << grp.gt_vertices.size() << " at "
                          << grp.transform.yaw_deg << " deg: " << ok << " correct\n";
            }
        EXPECT_EQ(r.brokenness.degree, n);
        // Each group's rotation is the sum of the breaks west of it (the group's T_gt_map
        // undoes it): 0, -14, -14+22, -14+22-18.
        std::vector<double> expected = {0.0};
        double acc = 0.0;
        for (int k = 0; k < n; ++k) expected.push_back(-(acc += kBreaks[k].yaw_deg));
        for (const auto& grp : r.brokenness.groups)
        {
            double best = 1e9;
            for (double e : expected)
                best = std::min(best, std::abs(std::remainder(grp.transform.yaw_deg - e, 360.0)));
            EXPECT_LE(best, 3.0) << "broken " << n << ": group yaw " << grp.transform.yaw_deg;
        }
    }
}

// How far each found part is off (BrokennessGroup::offset_m), against the known answer: the
// same measure with each group's true transform, fitted to where the breaks put its vertices
// (brokenPoint), never the matcher's. The campus broken once, twice, three times: parts 3.2-5.9 m
// off.
TEST(QualityEvaluator, APartsOffsetIsHowFarItsBreakMovedIt)
{
    const auto campus = makeCampusMap();
    for (int n = 1; n <= 3; ++n)
    {
        TopologyGraph g, m;
        const QualityReport r = evaluate(campus, brokenCampus(n), Parameters{}, &g, &m);
        ASSERT_EQ(r.brokenness.degree, n);
        std::vector<Transform2D> truth;
        for (const auto& grp : r.brokenness.groups)
        {
            std::vector<Eigen::Vector2d> pg, pm;
            for (int v : grp.gt_vertices)
            {
                pg.push_back(g.vertices[v].position_m);
                pm.push_back(brokenPoint(n, g.vertices[v].position_m));
            }
            truth.push_back(internal::hornAlign(pg, pm));
        }
        EXPECT_EQ(r.brokenness.groups[0].offset_m, 0.0);
        for (std::size_t i = 1; i < truth.size(); ++i)
        {
            const auto& grp = r.brokenness.groups[i];
            double nearest = std::numeric_limits<double>::infinity();
            for (std::size_t j = 0; j < i; ++j)
            {
                double sum = 0.0;
                for (int v : grp.gt_vertices)
                {
                    const Eigen::Vector2d q = m.vertices[r.match.mapVertexOf(v)].position_m;
                    sum += (truth[i].apply(q) - truth[j].apply(q)).squaredNorm();
                }
                nearest = std::min(nearest, std::sqrt(sum / double(grp.gt_vertices.size())));
            }
            EXPECT_GT(nearest, 1.0) << "broken " << n << ", group " << i;
            EXPECT_NEAR(grp.offset_m, nearest, 0.05 * nearest) << "broken " << n << ", group " << i;
        }
    }
}

// With a second thread brokenness is measured there, on its own wall indexes, while this one
// measures accuracy: the report must be the one a single thread makes, field by field.
TEST(QualityEvaluator, TheReportDoesNotDependOnTheThreads)
{
    const auto campus = makeCampusMap();
    const auto broken = brokenCampus(2);
    const TopologyGraph g = buildTopologyGraph(campus), m = buildTopologyGraph(broken);
    const GraphMatch match = matchGraphs(g, m, attributeSimilarity(g, m, {}));
    const QualityReport one = evaluateMatch(g, m, match, {}, 1);
    ASSERT_EQ(one.brokenness.degree, 2);  // groups to compare
    ASSERT_GT(one.relative_accuracy.by_walls, 0u);
    for (unsigned threads : {2u, 3u})
    {
        const QualityReport r = evaluateMatch(g, m, match, {}, threads);
        EXPECT_EQ(r.quality, one.quality) << threads;
        EXPECT_EQ(r.relative_accuracy.rmse_m, one.relative_accuracy.rmse_m) << threads;
        EXPECT_EQ(r.relative_accuracy.by_walls, one.relative_accuracy.by_walls) << threads;
        EXPECT_EQ(r.brokenness.degree, one.brokenness.degree) << threads;
        ASSERT_EQ(r.brokenness.groups.size(), one.brokenness.groups.size()) << threads;
        for (std::size_t k = 0; k < r.brokenness.groups.size(); ++k)
        {
            const BrokennessGroup &a = r.brokenness.groups[k], &b = one.brokenness.groups[k];
            EXPECT_EQ(a.gt_vertices, b.gt_vertices) << threads << " group " << k;
            EXPECT_EQ(a.squared_error_m2, b.squared_error_m2) << threads << " group " << k;
            EXPECT_EQ(a.transform.x_m, b.transform.x_m) << threads << " group " << k;
            EXPECT_EQ(a.transform.y_m, b.transform.y_m) << threads << " group " << k;
            EXPECT_EQ(a.transform.yaw_deg, b.transform.yaw_deg) << threads << " group " << k;
        }
    }
}

// A part's turn is reported from the walls around its vertices (brokenness_wall_margin_m):
// the vertices alone slide along the medial axis and leave a part's fit a few tenths of a
// degree off; the walls pin it to a few hundredths.
TEST(QualityEvaluator, APartsTurnComesFromItsWalls)
{
    const auto campus = makeCampusMap();
    for (int n = 1; n <= 2; ++n)
    {
        const auto broken = brokenCampus(n);
        std::vector<double> expected = {0.0};
        double acc = 0.0;
        for (int k = 0; k < n; ++k) expected.push_back(-(acc += kBreaks[k].yaw_deg));
        auto worstError = [&](double margin_m)
        {
            Parameters params;
            params.quality.brokenness_wall_margin_m = margin_m;
            const QualityReport r = evaluate(campus, broken, params);
            EXPECT_EQ(r.brokenness.degree, n);
            double worst = 0.0;
            for (const auto& grp : r.brokenness.groups)
            {
                double best = 1e9;
                for (double e : expected)
                    best =
                        std::min(best, std::abs(std::remainder(grp.transform.yaw_deg - e, 360.0)));
                worst = std::max(worst, best);
            }
            return worst;
        };
        const double walls = worstError(1.0), vertices = worstError(0.0);
        if (std::getenv("TOPOEVAL_DEBUG"))
            std::cout << "broken " << n << ": worst group yaw error " << vertices
                      << " deg from the vertices, " << walls << " deg from the walls\n";
        EXPECT_LE(walls, 0.05) << "broken " << n;
        EXPECT_LT(walls, vertices) << "broken " << n;
    }
}

TEST(QualityEvaluator, WorseMapsScoreLower)
{
    const auto campus = makeCampusMap();
    const double identical = compare(campus, campus, "identical").quality;
    const double noisy = compare(campus, addSpeckleNoise(campus, 0.03, 5), "noisy").quality;
    double previous = noisy;
    EXPECT_GT(identical, noisy);
    for (int n = 1; n <= 3; ++n)
    {
        const double q = compare(campus, brokenCampus(n), "family_" + std::to_string(n)).quality;
        EXPECT_LT(q, previous) << "broken " << n << " times";
        previous = q;
    }
}

TEST(QualityEvaluator, CroppedMapCoversPart)
{
    // The west half of the campus only (the east half unknown, as if never explored).
    GridSketch east_unknown(62.0, 37.0);
    COccupancyGridMap2D half = makeCampusMap();
    for (unsigned cy = 0; cy < half.getSizeY(); ++cy)
        for (unsigned cx = 0; cx < half.getSizeX(); ++cx)
            if (half.idx2x(cx) > 31.0) half.setCell(cx, cy, 0.5f);
    const QualityReport r = compare(makeCampusMap(), half, "cropped");
    EXPECT_GE(r.coverage, 0.2);
    EXPECT_LE(r.coverage, 0.65);
}

// The map's side of coverage (doc/quality.md, "Explained walls"): each case's known answer
// from the maps alone.
// Brokenness step 9 (wall_parts): a part the match missed is placed by its walls. The known
// answer: the campus broken once turns everything east of x = 16.5 m by 14 degrees, so the
// missed part's T_gt_map turns by -14 degrees, and the breaks say where each of its vertices is.
TEST(QualityEvaluator, APartTheMatchMissedIsPlacedByItsWalls)
{
    const auto campus = makeCampusMap();
    TopologyGraph g, m;
    const QualityReport full = evaluate(campus, brokenCampus(1), Parameters{}, &g, &m);
    ASSERT_EQ(full.brokenness.degree, 1);
    // The match without the turned part's pairs, as if the matcher had missed it.
    GraphMatch missed = full.match;
    const double cut = kBreaks[0].cut_x;
    missed.pairs.erase(std::remove_if(missed.pairs.begin(), missed.pairs.end(),
                                      [&](const VertexPair& p)
                                      { return g.vertices[p.ground_truth].position_m.x() > cut; }),
                       missed.pairs.end());
    ASSERT_GE(missed.pairs.size(), 10u);
    ASSERT_LT(missed.pairs.size(), full.match.pairs.size() - 10);
    QualityParameters qp;
    EXPECT_TRUE(qp.wall_parts);  // on by default
    qp.wall_parts = false;
    const QualityReport without = evaluateMatch(g, m, missed, qp);
    EXPECT_EQ(without.brokenness.degree, 0);
    EXPECT_LT(without.explained_walls.share, 0.9);

    qp.wall_parts = true;
    const QualityReport with = evaluateMatch(g, m, missed, qp);
    ASSERT_EQ(with.brokenness.degree, 1);
    const BrokennessGroup& part = with.brokenness.groups.back();
    EXPECT_TRUE(part.by_walls);
    EXPECT_FALSE(with.brokenness.groups.front().by_walls);
    EXPECT_NEAR(std::remainder(part.transform.yaw_deg + kBreaks[0].yaw_deg, 360.0), 0.0, 0.5);
    // Where it puts the part: the breaks' own place for every ground-truth point east of the cut.
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(30.0, 10.0), Eigen::Vector2d(45.0, 25.0)})
        EXPECT_LT((part.transform.apply(brokenPoint(1, p)) - p).norm(), 0.3) << p.transpose();
    // Its pairs are not the match's, and each is true by the breaks.
    EXPECT_EQ(with.match.pairs.size(), missed.pairs.size());
    ASSERT_EQ(part.gt_vertices.size(), part.map_vertices.size());
    EXPECT_GE(part.gt_vertices.size(), 3u);
    for (std::size_t k = 0; k < part.gt_vertices.size(); ++k)
        EXPECT_LT((brokenPoint(1, g.vertices[part.gt_vertices[k]].position_m) -
                   m.vertices[part.map_vertices[k]].position_m)
                      .norm(),
                  1.0)
            << "gt " << part.gt_vertices[k];
    EXPECT_GT(part.offset_m, 1.0);
    EXPECT_GE(with.explained_walls.share, 0.97);
    EXPECT_LT(with.quality, without.quality);  // a break found costs
    EXPECT_NE(with.briefReport().find("1 placed by its walls"), std::string::npos);

    // Nothing is added where the groups explain the walls: the full match, the identical map.
    EXPECT_EQ(evaluateMatch(g, m, full.match, qp).brokenness.degree, 1);
    TopologyGraph sg, sm;
    const QualityReport same = evaluate(campus, campus, Parameters{}, &sg, &sm);
    EXPECT_EQ(evaluateMatch(sg, sm, same.match, qp).brokenness.groups.size(), 1u);
}

// Step 9 on a region that no one fit places (wall_part_split): the campus broken twice, with a
// match of its west part only, leaves the two turned parts' walls unexplained, and they touch at
// the second cut (one region). The known answer: two parts, turned back by -14 and +8 degrees,
// each putting its own points of the campus back where they were.
TEST(QualityEvaluator, TwoMissedPartsThatTouchArePlacedEachByItsWalls)
{
    TopologyGraph g, m;
    const QualityReport full = evaluate(makeCampusMap(), brokenCampus(2), Parameters{}, &g, &m);
    GraphMatch west = full.match;
    west.pairs.erase(
        std::remove_if(west.pairs.begin(), west.pairs.end(),
                       [&](const VertexPair& p)
                       { return g.vertices[p.ground_truth].position_m.x() > kBreaks[0].cut_x; }),
        west.pairs.end());
    ASSERT_GE(west.pairs.size(), 5u);
    QualityParameters qp;
    EXPECT_TRUE(qp.wall_part_split);  // on by default
    qp.wall_part_split = false;
    const QualityReport whole = evaluateMatch(g, m, west, qp);
    EXPECT_EQ(whole.brokenness.degree, 0);

    qp.wall_part_split = true;
    const QualityReport r = evaluateMatch(g, m, west, qp);
    ASSERT_EQ(r.brokenness.degree, 2);
    // The middle part (between the cuts) is turned by the first break only; the east part by
    // both. Each part's fit puts the campus's points of its own side back.
    const Eigen::Vector2d middle(24.0, 20.0), east(40.0, 20.0);
    int found = 0;
    for (std::size_t k = 1; k < r.brokenness.groups.size(); ++k)
    {
        const BrokennessGroup& part = r.brokenness.groups[k];
        EXPECT_TRUE(part.by_walls);
        const double yaw = std::remainder(part.transform.yaw_deg, 360.0);
        if (std::abs(yaw + kBreaks[0].yaw_deg) < 0.5)
        {
            EXPECT_LT((part.transform.apply(brokenPoint(2, middle)) - middle).norm(), 0.3);
            found |= 1;
        }
        if (std::abs(yaw + kBreaks[0].yaw_deg + kBreaks[1].yaw_deg) < 0.5)
        {
            EXPECT_LT((part.transform.apply(brokenPoint(2, east)) - east).norm(), 0.3);
            found |= 2;
        }
    }
    EXPECT_EQ(found, 3);
    EXPECT_GT(r.explained_walls.share, whole.explained_walls.share + 0.2);
}

// A map the match holds no group of (map_by_walls): placed part by part by its walls. The known
// answer: the campus broken once, given to evaluateMatch() with no pair (as a flat's graph of a
// few vertices gives none), is two parts, the one west of the cut as it was and the one east of
// it turned by 14 degrees; every pair its parts make is where the breaks put its ground-truth
// vertex. Another building is not placed.
TEST(QualityEvaluator, AMapTheMatchCannotGroupIsPlacedByItsWalls)
{
    TopologyGraph g, m;
    evaluate(makeCampusMap(), brokenCampus(1), Parameters{}, &g, &m);
    QualityParameters qp;
    EXPECT_TRUE(qp.map_by_walls);  // on by default
    qp.map_by_walls = false;
    const QualityReport paper = evaluateMatch(g, m, GraphMatch{}, qp);
    EXPECT_EQ(paper.quality, 0.0);
    EXPECT_TRUE(paper.brokenness.groups.empty());

    qp.map_by_walls = true;
    const QualityReport r = evaluateMatch(g, m, GraphMatch{}, qp);
    ASSERT_EQ(r.brokenness.degree, 1);
    // Each part's fit puts the broken campus back where the campus is, on its side of the cut.
    const Transform2D* west = nullptr;
    const Transform2D* east = nullptr;
    for (const BrokennessGroup& part : r.brokenness.groups)
    {
        EXPECT_TRUE(part.by_walls);
        if (std::abs(std::remainder(part.transform.yaw_deg, 360.0)) < 0.5) west = &part.transform;
        if (std::abs(std::remainder(part.transform.yaw_deg + kBreaks[0].yaw_deg, 360.0)) < 0.5)
            east = &part.transform;
    }
    ASSERT_TRUE(west && east);
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(5.0, 5.0), Eigen::Vector2d(10.0, 20.0)})
        EXPECT_LT((west->apply(brokenPoint(1, p)) - p).norm(), 0.3) << p.transpose();
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(30.0, 10.0), Eigen::Vector2d(45.0, 25.0)})
        EXPECT_LT((east->apply(brokenPoint(1, p)) - p).norm(), 0.3) << p.transpose();
    // Its pairs are the match, each true by the breaks: where one part puts its ground-truth
    // vertex (a vertex at the cut is made by both parts' walls, as the validator's truth says).
    ASSERT_GE(r.match.pairs.size(), 20u);
    EXPECT_EQ(r.match.byWalls(), r.match.pairs.size());
    const Break b = kBreaks[0];
    auto turned = [&](const Eigen::Vector2d& p)
    {
        return breakPoint(
            {b.cut_x, b.pivot_y}, b.yaw_deg * kDeg, [](double, double) { return true; }, p);
    };
    for (const VertexPair& pr : r.match.pairs)
    {
        const Eigen::Vector2d& p = g.vertices[pr.ground_truth].position_m;
        const Eigen::Vector2d& q = m.vertices[pr.map].position_m;
        EXPECT_LT(std::min((p - q).norm(), (turned(p) - q).norm()), 1.0)
            << "gt " << pr.ground_truth << ", map " << pr.map;
    }
    EXPECT_GT(r.coverage, 0.5);
    EXPECT_GT(r.quality, 0.3);
    EXPECT_NE(r.briefReport().find("placed by walls"), std::string::npos);
    EXPECT_NE(r.briefReport().find("2 placed by its walls"), std::string::npos);

    // Another building (the office) and the campus's own twin of another seed: nothing placed.
    for (const COccupancyGridMap2D& other : {makeOfficeMap(), makeCampusMap(2)})
    {
        TopologyGraph og, om;
        evaluate(makeCampusMap(), other, Parameters{}, &og, &om);
        const QualityReport o = evaluateMatch(og, om, GraphMatch{}, qp);
        EXPECT_TRUE(o.match.pairs.empty());
        EXPECT_TRUE(o.brokenness.groups.empty());
        EXPECT_EQ(o.quality, 0.0);
    }
}

// A robot map against its floor plan (map_by_walls_whole_min_share): furniture along every wall
// leaves no 3 m neighbourhood of the map's walls on the plan's walls for 0.9 of it, so no part's
// region is singled out; the whole map, whose best placement puts most of its walls on the plan
// far ahead of every other, is one part. The known answer: the office with walls 0.1 m thick
// and a dash of furniture 0.3 m off every wall each 2.25 m, moved by 30 degrees and (2, -1) m,
// given to evaluateMatch() with no pair (as a flat's closed doors leave too few), is placed
// where the move puts it (its best placement 0.80 of the walls, the next 0.46), no break, and
// each pair its placement makes is a vertex the move puts within 1 m of its own.
TEST(QualityEvaluator, ARobotMapWithNoCleanRegionIsPlacedWhole)
{
    const COccupancyGridMap2D plan = makeOfficeMap();
    // Dashes 0.6 m x 0.15 m, 0.3 m (6 cells) from each wall face along the plan's axes, every
    // 2.25 m (45 cells): wider than min_island_size_m, so they stay as a robot map's clutter.
    COccupancyGridMap2D furnished = plan;
    const int nx = int(plan.getSizeX()), ny = int(plan.getSizeY());
    auto isFree = [&](int x, int y)
    { return x >= 0 && y >= 0 && x < nx && y < ny && plan.getCell(x, y) > 0.5f; };
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x)
        {
            if (!isFree(x, y)) continue;
            for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
            {
                bool open = true;
                for (int k = 1; k <= 5 && open; ++k) open = isFree(x + k * dx, y + k * dy);
                const int x6 = x + 6 * dx, y6 = y + 6 * dy;
                const bool wall = x6 >= 0 && y6 >= 0 && x6 < nx && y6 < ny && !isFree(x6, y6) &&
                                  plan.getCell(x6, y6) < 0.5f;
                const int along = dx != 0 ? y : x;
                if (open && wall && along % 45 < 12)
                    for (int t = 0; t < 3; ++t) furnished.setCell(x - t * dx, y - t * dy, 0.0f);
            }
        }
    // As a robot sees walls: 0.1 m thick from the free space, unknown behind (the plan's solid
    // mass would be a clean region of its own).
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x)
        {
            bool near = false;
            for (int dy = -2; dy <= 2 && !near; ++dy)
                for (int dx = -2; dx <= 2 && !near; ++dx) near = isFree(x + dx, y + dy);
            if (!near) furnished.setCell(x, y, 0.5f);
        }
    const double yaw = 30.0 * kDeg;
    const Eigen::Vector2d shift(2.0, -1.0);
    const COccupancyGridMap2D map = transformGrid(furnished, yaw, shift);
    // As built (evaluate()'s clutter pass would free the dashes the match puts off the plan).
    const TopologyGraph g = buildTopologyGraph(plan), m = buildTopologyGraph(map);

    QualityParameters qp;
    EXPECT_EQ(qp.map_by_walls_whole_min_share, 0.5);  // the default
    qp.map_by_walls_whole_min_share = 0.0;
    const QualityReport regions = evaluateMatch(g, m, GraphMatch{}, qp);
    EXPECT_TRUE(regions.match.pairs.empty()) << "a region placed: the furniture is too sparse";
    EXPECT_EQ(regions.quality, 0.0);

    qp.map_by_walls_whole_min_share = 0.5;
    const QualityReport r = evaluateMatch(g, m, GraphMatch{}, qp);
    ASSERT_EQ(r.brokenness.groups.size(), 1u);
    EXPECT_EQ(r.brokenness.degree, 0);
    const Transform2D& t = r.brokenness.groups[0].transform;
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(5.0, 5.0), Eigen::Vector2d(25.0, 15.0)})
        EXPECT_LT((t.apply(transformPoint(plan, yaw, shift, p)) - p).norm(), 0.1) << p.transpose();
    ASSERT_GE(r.match.pairs.size(), 5u);
    EXPECT_EQ(r.match.byWalls(), r.match.pairs.size());
    for (const VertexPair& pr : r.match.pairs)
    {
        const Eigen::Vector2d& p = g.vertices[pr.ground_truth].position_m;
        EXPECT_LT((transformPoint(plan, yaw, shift, p) - m.vertices[pr.map].position_m).norm(), 1.0)
            << "gt " << pr.ground_truth << ", map " << pr.map;
    }
    EXPECT_GT(r.quality, 0.5);
    bool said = false;
    for (const std::string& s : r.messages)
        said |= s.find("the whole map is one part") != std::string::npos;
    EXPECT_TRUE(said);
}

// One place, one part (wall_part_max_overlap) in step 10: the house plan's west 60 % as the
// ground truth, the whole plan as the map (a robot map that runs beyond its plan). Its graph
// pairs too few vertices for a group, so the map is placed by its walls: its west part where it
// is, and, without the rule, its east rooms as a second part onto the west ones, a break that is
// not there. With it no break is counted.
TEST(QualityEvaluator, AMapBeyondItsGroundTruthIsNotPlacedTwice)
{
    const auto whole = loadMap(shareDir() + "/maps/house_gt_trinary_res0.05.yaml").grid;
    COccupancyGridMap2D west = whole;
    const unsigned cut = unsigned(0.6 * west.getSizeX());
    for (unsigned cy = 0; cy < west.getSizeY(); ++cy)
        for (unsigned cx = cut; cx < west.getSizeX(); ++cx) west.setCell(cx, cy, 0.5f);
    Parameters p;
    EXPECT_EQ(p.quality.wall_part_max_overlap, 0.5);  // the default
    p.quality.wall_part_max_overlap = 1.0;
    const QualityReport without = evaluate(west, whole, p);
    EXPECT_GE(without.brokenness.degree, 1) << "the east rooms placed onto the west ones";
    p.quality.wall_part_max_overlap = 0.5;
    const QualityReport with = evaluate(west, whole, p);
    EXPECT_EQ(with.brokenness.degree, 0);
    for (const BrokennessGroup& part : with.brokenness.groups)
        EXPECT_LT(std::abs(std::remainder(part.transform.yaw_deg, 360.0)), 1.0);
}

TEST(QualityEvaluator, ExplainedWallsAreTheMapsSideOfCoverage)
{
    const COccupancyGridMap2D campus = makeCampusMap();
    // The campus west of x = 31 m, the rest unknown (as if never explored).
    auto westHalf = [](COccupancyGridMap2D g)
    {
        for (unsigned cy = 0; cy < g.getSizeY(); ++cy)
            for (unsigned cx = 0; cx < g.getSizeX(); ++cx)
                if (g.idx2x(cx) > 31.0) g.setCell(cx, cy, 0.5f);
        return g;
    };
    const COccupancyGridMap2D half = westHalf(campus);
    auto check = [](const QualityReport& r, const char* what)
    {
        EXPECT_TRUE(r.explained_walls.measured) << what;
        EXPECT_EQ(r.explained_walls.unexplained_m.size(),
                  r.explained_walls.wall_points - r.explained_walls.explained)
            << what;
        EXPECT_DOUBLE_EQ(r.explained_walls.share, double(r.explained_walls.explained) /
                                                      double(r.explained_walls.wall_points))
            << what;
    };

    // Identical, and moved: every wall explained.
    const QualityReport same = compare(campus, campus, "explained_same");
    check(same, "same");
    EXPECT_DOUBLE_EQ(same.explained_walls.share, 1.0);
    const QualityReport moved =
        compare(campus, transformGrid(campus, 151.0 * kDeg, {5.0, -3.0}), "explained_moved");
    check(moved, "moved");
    EXPECT_GE(moved.explained_walls.share, 0.99);

    // A crop: half the ground truth matched, but all of the map's walls are the ground truth's.
    const QualityReport crop = compare(campus, half, "explained_crop");
    check(crop, "crop");
    EXPECT_LE(crop.coverage, 0.65);
    EXPECT_GE(crop.explained_walls.share, 0.99);

    // The reverse: the whole campus against its west half. Every ground-truth vertex is
    // matched, but the map's walls east of the cut (beyond the tolerance) have no ground-truth
    // wall: the share is that of the map's wall points west of it.
    // (The cut seals a room of the half off, a piece of its graph since session 48 that the
    // whole campus, where the room is open, does not have: off here, so that every vertex can
    // be matched.)
    TopologyGraph gt_graph, map_graph;
    Parameters no_room_pieces;
    no_room_pieces.graph.room_piece_min_length_m = no_room_pieces.graph.min_component_length_m;
    const QualityReport more = evaluate(half, campus, no_room_pieces, &gt_graph, &map_graph);
    check(more, "more");
    EXPECT_GE(more.coverage, 0.9);
    const double tolerance = more.explained_walls.tolerance_m;
    EXPECT_DOUBLE_EQ(tolerance, QualityParameters{}.explained_wall_tolerance_m);
    std::size_t west = 0;
    for (const auto& q : map_graph.wall_points_m) west += q.x() <= 31.0 + tolerance;
    const double expected = double(west) / double(map_graph.wall_points_m.size());
    EXPECT_NEAR(more.explained_walls.share, expected, 0.02);
    for (const auto& q : more.explained_walls.unexplained_m) EXPECT_GT(q.x(), 31.0) << q.y();
    // Under explained_walls_note_below (0.9) the report says so; the crop and the identical
    // map explain theirs.
    auto noted = [](const QualityReport& r)
    {
        return std::any_of(r.messages.begin(), r.messages.end(),
                           [](const std::string& m)
                           { return m.rfind("the match explains ", 0) == 0; });
    };
    EXPECT_TRUE(noted(more));
    EXPECT_FALSE(noted(same));
    EXPECT_FALSE(noted(crop));
    // The picture draws them as pure red dots, and the legend's swatch of them: no other mark
    // of it is pure red.
    auto redPixels = [](const mrpt::img::CImage& img)
    {
        std::size_t n = 0;  // channels in OpenCV's order: blue, green, red
        for (unsigned y = 0; y < img.getHeight(); ++y)
            for (unsigned x = 0; x < img.getWidth(); ++x)
                n += img.at<std::uint8_t>(x, y, 0) == 0 && img.at<std::uint8_t>(x, y, 1) == 0 &&
                     img.at<std::uint8_t>(x, y, 2) == 255;
        return n;
    };
    TopologyGraph same_g, same_m;
    QualityReport all_explained = evaluate(campus, campus, Parameters{}, &same_g, &same_m);
    const std::size_t swatch =
        redPixels(drawQualityReport(campus, same_g, campus, same_m, all_explained));
    EXPECT_GT(swatch, 0u);
    all_explained.explained_walls.measured = false;  // no legend entry either
    EXPECT_EQ(redPixels(drawQualityReport(campus, same_g, campus, same_m, all_explained)), 0u);
    EXPECT_GE(redPixels(drawQualityReport(half, gt_graph, campus, map_graph, more)),
              swatch + more.explained_walls.unexplained_m.size() / 4);

    // Broken once: each part's walls are explained by its own group.
    const QualityReport broken = compare(campus, brokenCampus(1), "explained_broken");
    check(broken, "broken");
    ASSERT_EQ(broken.brokenness.degree, 1);
    EXPECT_GE(broken.explained_walls.share, 0.97);

    // Graphs without wall points (made in code): not measured, and quality as without it.
    TopologyGraph bare = buildTopologyGraph(campus);
    bare.wall_points_m.clear();
    GraphMatch match;
    for (const auto& v : bare.vertices)
        if (!v.spurious) match.pairs.push_back({v.id, v.id, MatchStage::Isomorphism, 1.0, 0});
    match.isomorphism = match.pairs.size();
    match.isomorphism_sizes = {match.pairs.size()};
    QualityParameters off;
    off.explained_wall_tolerance_m = 0.0;
    const QualityReport unmeasured = evaluateMatch(bare, bare, match);
    EXPECT_FALSE(unmeasured.explained_walls.measured);
    EXPECT_EQ(unmeasured.explained_walls.share, 0.0);
    EXPECT_DOUBLE_EQ(unmeasured.quality, evaluateMatch(bare, bare, match, off).quality);
}

TEST(QualityEvaluator, DifferentBuildingHasLowCoverage)
{
    // Different floor plans. (Two floors of one corridor-grid architecture with different rooms,
    // makeCampusMap(1) against makeCampusMap(2), share about 65% of their structure: a limit
    // of structural matching, measured and reported in doc/quality.md.)
    EXPECT_LE(compare(makeCampusMap(1), makeOfficeMap(), "other_office").coverage, 0.3);
    EXPECT_LE(compare(makeOfficeMap(), makeCampusMap(1), "other_campus").coverage, 0.3);
    for (auto [a, b] :
         {std::pair{"radish/intel-corrected_ref.yaml", "radish/aces-corrected_ref.yaml"},
          {"radish/freiburg-079-corrected_ref.yaml", "radish/csail-corrected_ref.yaml"}})
    {
        const auto fa = sharedDataFile(a), fb = sharedDataFile(b);
        if (!fa || !fb) GTEST_SKIP() << "no ../shared/data";
        EXPECT_LE(compare(loadMap(*fa).grid, loadMap(*fb).grid, "real_other").coverage, 0.3) << a;
    }
}

TEST(QualityEvaluator, NothingMatchedIsZeroNotNaN)
{
    const QualityReport r = compare(makePlusMap(), makeOfficeMap(), "nothing");
    EXPECT_EQ(r.coverage, 0.0);
    EXPECT_EQ(r.quality, 0.0);
    EXPECT_FALSE(r.messages.empty());
    for (const auto& c : r.local_consistency) EXPECT_FALSE(std::isnan(c.score));
}

TEST(QualityEvaluator, InvalidParametersAreRejected)
{
    QualityParameters p;
    p.consistency_medium_max_m = 1.0;  // below short
    EXPECT_THROW(p.validate(), InputError);
    p = {};
    p.brokenness_max_squared_error_m2 = -0.1;
    EXPECT_THROW(p.validate(), InputError);
}

TEST(QualityEvaluator, RealIntelSlamScoresBelowTheReference)
{
    const auto iref = sharedDataFile("radish/intel-corrected_ref.yaml");
    const auto islam = sharedDataFile("slam_maps/intel_icp-slam_app-final.yaml");
    if (!iref || !islam) GTEST_SKIP() << "no ../shared/data";
    const auto ir = loadMap(*iref).grid, is = loadMap(*islam).grid;
    const QualityReport self = compare(ir, ir, "intel_self");
    const QualityReport slam = compare(ir, is, "intel_slam");
    EXPECT_DOUBLE_EQ(self.quality, 1.0);
    EXPECT_EQ(self.brokenness.degree, 0);
    EXPECT_LT(slam.quality, self.quality);
}

TEST(QualityEvaluator, RealHousePairsAreReportedWithoutNaN)
{
    // The house ground truth is a bare floor plan whose graph has 4 vertices; the robot maps are
    // furnished, and differently in 2019 and 2020 (doc/quality.md reports the figures). What must
    // hold: finite scores in [0, 1].
    const auto gt = sharedDataFile("house/house_gt_trinary_res0.05.yaml");
    const auto m2020 = sharedDataFile("house/map_6ccdcaa.yaml");
    const auto m2019 = sharedDataFile("house/map_2333d24.yaml");
    if (!gt || !m2020 || !m2019) GTEST_SKIP() << "no ../shared/data";
    const auto g = loadMap(*gt).grid, a = loadMap(*m2020).grid, b = loadMap(*m2019).grid;
    for (const QualityReport& r : {compare(g, a, "house_gt_2020"), compare(g, b, "house_gt_2019"),
                                   compare(a, b, "house_2020_2019")})
    {
        EXPECT_TRUE(std::isfinite(r.quality));
        EXPECT_GE(r.quality, 0.0);
        EXPECT_LE(r.quality, 1.0);
        EXPECT_GE(r.coverage, 0.0);
        EXPECT_LE(r.coverage, 1.0);
    }
}

namespace
{
// The true correspondence of two maps recorded in one world frame: mutually nearest
// non-spurious vertices closer than `max_m`.
GraphMatch correspondenceByPosition(const TopologyGraph& gt, const TopologyGraph& map, double max_m)
{
    const auto nearest = [](const TopologyGraph& g, const Eigen::Vector2d& p)
    {
        int best = -1;
        double best_d = std::numeric_limits<double>::infinity();
        for (const TopoVertex& v : g.vertices)
        {
            const double d = (v.position_m - p).norm();
            if (!v.spurious && d < best_d) best_d = d, best = v.id;
        }
        return std::pair{best, best_d};
    };
    GraphMatch m;
    for (const TopoVertex& v : gt.vertices)
    {
        if (v.spurious) continue;
        const auto [j, d] = nearest(map, v.position_m);
        if (j < 0 || d > max_m || nearest(gt, map.vertices[j].position_m).first != v.id) continue;
        VertexPair p;
        p.ground_truth = v.id;
        p.map = j;
        p.similarity = 1.0;
        p.isomorphism = 0;
        m.pairs.push_back(p);
    }
    m.isomorphism = m.pairs.size();
    return m;
}
}  // namespace

// The house pair. Both robot maps are in the house's world frame (../shared/data
// README), so their true vertex correspondence is known from positions: this measures what
// brokenness can say about the 2019 map, independently of the matcher. Its left wing is rotated
// by about 2 degrees against the rest, which moves its vertices by 0.2 m at most: one rigid fit
// of all pairs leaves a mean squared error of 0.03 m^2, several times under the paper's
// 0.2 m^2 and of the order of the vertex jitter the moved furniture causes. At the paper's
// threshold the 2019 map is one piece. The figures are in doc/quality.md.
TEST(QualityEvaluator, RealHouse2019LeftWingAgainstThe2020Map)
{
    const std::string maps = shareDir() + "/maps/";
    const auto m2020 = loadMap(maps + "map_6ccdcaa.yaml").grid;
    const auto m2019 = loadMap(maps + "map_2333d24.yaml").grid;
    const TopologyGraph g2020 = buildTopologyGraph(m2020), g2019 = buildTopologyGraph(m2019);
    const GraphMatch truth = correspondenceByPosition(g2020, g2019, 0.4);
    ASSERT_GE(truth.pairs.size(), 14u) << "15 were measured";

    // The break itself: each wing aligned on its own (the left wing is everything west of the
    // wall at x = -3 m; the rest is east of x = -1 m).
    std::vector<Eigen::Vector2d> left_gt, left_map, rest_gt, rest_map;
    for (const VertexPair& p : truth.pairs)
    {
        const Eigen::Vector2d a = g2020.vertices[p.ground_truth].position_m;
        const Eigen::Vector2d b = g2019.vertices[p.map].position_m;
        if (a.x() < -3.0) left_gt.push_back(a), left_map.push_back(b);
        if (a.x() > -1.0) rest_gt.push_back(a), rest_map.push_back(b);
    }
    ASSERT_GE(left_gt.size(), 6u);
    ASSERT_GE(rest_gt.size(), 5u);
    const double yaw_left = internal::hornAlign(left_gt, left_map).yaw_deg;
    const double yaw_rest = internal::hornAlign(rest_gt, rest_map).yaw_deg;
    // Vertices measure these angles only to about 2 degrees: a handful of junctions per wing,
    // each with 0.1-0.2 m of furniture jitter (with furniture legs ignored, [GraphBuilder]
    // min_island_size_m, the set of vertices changes and the measured rest moves to 1.6 deg).
    EXPECT_NEAR(yaw_rest, 0.0, 2.0) << "the rest of the house is where it was";
    // T_gt_map turns the 2019 map back: its left wing is turned counter-clockwise by ~2 deg.
    EXPECT_LT(yaw_left - yaw_rest, -1.0) << "the left wing is rotated by about 2 degrees";
    EXPECT_GT(yaw_left - yaw_rest, -5.0);

    // What brokenness makes of it at the paper's threshold: one piece.
    const QualityReport r = evaluateMatch(g2020, g2019, truth, QualityParameters{});
    EXPECT_EQ(r.brokenness.degree, 0);
    ASSERT_EQ(r.brokenness.groups.size(), 1u);
    EXPECT_LT(r.brokenness.groups[0].squared_error_m2, 0.05);

    // The matcher on the same pair (no positions used): it finds the left wing, where the
    // furniture stayed, and every pair it makes is a true one: within 0.4 m, or within half
    // the vertex's clearance for a room's vertex (defined only up to its room's medial-axis
    // plateau; the consistent matcher pairs 2020 vertex 19, clearance 1.77 m, with the 2019
    // vertex of the same degree 0.48 m away).
    TopologyGraph ga, gb;
    const QualityReport found = evaluate(m2020, m2019, Parameters{}, &ga, &gb);
    EXPECT_GE(found.match.pairs.size(), 8u) << "15 were measured";
    for (const VertexPair& p : found.match.pairs)
        EXPECT_LT((ga.vertices[p.ground_truth].position_m - gb.vertices[p.map].position_m).norm(),
                  std::max(0.4, 0.5 * ga.vertices[p.ground_truth].clearance_m))
            << "2020 vertex " << p.ground_truth << " paired with 2019 vertex " << p.map;
    EXPECT_EQ(found.brokenness.degree, 0);
    if (std::getenv("TOPOEVAL_DEBUG"))
        std::cout << "house 2019 vs 2020, true pairs " << truth.pairs.size() << ": left wing yaw "
                  << yaw_left << " deg, rest " << yaw_rest << " deg; one group, "
                  << r.brokenness.groups[0].squared_error_m2 << " m^2\n";
}

// Writes the campus and its broken copies as MRPT .gridmap.gz files for the pictures in
// doc/quality.md: TOPOEVAL_DOC_DIR=folder ./quality_evaluator_test
// --gtest_also_run_disabled_tests --gtest_filter=*WriteDocMaps
TEST(QualityEvaluator, DISABLED_WriteDocMaps)
{
    const char* dir = std::getenv("TOPOEVAL_DOC_DIR");
    ASSERT_NE(dir, nullptr) << "set TOPOEVAL_DOC_DIR";
    auto save = [&](const COccupancyGridMap2D& g, const std::string& name)
    {
        mrpt::io::CFileGZOutputStream f(std::string(dir) + "/" + name + ".gridmap.gz");
        mrpt::serialization::archiveFrom(f) << g;
    };
    save(makeCampusMap(), "campus");
    for (int n = 1; n <= 3; ++n) save(brokenCampus(n), "campus_broken_" + std::to_string(n));
}

// rank, series and rawlog build the ground truth's graph once and pass it in: the same report.
TEST(QualityEvaluator, PrebuiltGroundTruthGraphGivesTheSameReport)
{
    const auto campus = makeCampusMap();
    const auto broken = brokenCampus(1);
    const Parameters params;
    const QualityReport a = evaluate(campus, broken, params);
    const TopologyGraph gt = buildTopologyGraph(campus, params.graph);
    const QualityReport b = evaluate(gt, campus, broken, params);
    EXPECT_EQ(a.quality, b.quality);
    EXPECT_EQ(a.coverage, b.coverage);
    EXPECT_EQ(a.brokenness.degree, b.brokenness.degree);
    ASSERT_EQ(a.match.pairs.size(), b.match.pairs.size());
    for (std::size_t i = 0; i < a.match.pairs.size(); ++i)
    {
        EXPECT_EQ(a.match.pairs[i].ground_truth, b.match.pairs[i].ground_truth);
        EXPECT_EQ(a.match.pairs[i].map, b.match.pairs[i].map);
    }
    EXPECT_EQ(a.messages, b.messages);
}

// Issue 11, brokenness from small parts. The campus's graph, and a copy in which one junction
// and its dead ends (3 or 4 vertices, a small part) are turned by 20 degrees about a
// point 5 m away, matched vertex for vertex: what brokenness makes of a given match. The paper's
// rule (a group needs brokenness_min_vertices = 5) cannot count a part that small; a group of
// brokenness_min_part_vertices (3) whose fit is clearly separate from the rest does.
TEST(QualityEvaluator, SmallTurnedPartCountsWhenClearlySeparate)
{
    const TopologyGraph g = buildTopologyGraph(makeCampusMap());
    // The first junction with 2 or 3 dead ends.
    std::vector<int> star;
    for (const auto& v : g.vertices)
    {
        if (v.spurious || v.degree() < 3) continue;
        std::vector<int> s{v.id};
        for (const auto& inc : v.ring)
        {
            const auto& o = g.vertices[inc.other_vertex];
            if (!o.spurious && o.degree() == 1) s.push_back(o.id);
        }
        if (s.size() >= 3 && s.size() <= 4)
        {
            star = s;
            break;
        }
    }
    ASSERT_FALSE(star.empty());
    auto inStar = [&](int v) { return std::find(star.begin(), star.end(), v) != star.end(); };
    const Eigen::Vector2d pivot = g.vertices[star[0]].position_m + Eigen::Vector2d(5.0, 0.0);
    auto turned = [&](double yaw_deg)
    {
        TopologyGraph m = g;
        for (int v : star)
            m.vertices[v].position_m =
                pivot + Eigen::Rotation2Dd(yaw_deg * kDeg) * (g.vertices[v].position_m - pivot);
        return m;
    };
    GraphMatch match;
    for (const auto& v : g.vertices)
        if (!v.spurious) match.pairs.push_back({v.id, v.id, MatchStage::Isomorphism, 1.0, 0});
    match.isomorphism = match.pairs.size();
    match.isomorphism_sizes = {match.pairs.size()};

    const TopologyGraph m = turned(20.0);
    // Only the vertices are turned, not the walls around them: the part's turn is the
    // vertices' fit here (brokenness_wall_margin_m = 0), as it is for a map without walls.
    QualityParameters vertices_only;
    vertices_only.brokenness_wall_margin_m = 0.0;
    const QualityReport r = evaluateMatch(g, m, match, vertices_only);
    if (std::getenv("TOPOEVAL_DEBUG")) std::cout << r.fullReport();
    ASSERT_EQ(r.brokenness.degree, 1);
    const auto& part = r.brokenness.groups.back();
    EXPECT_EQ(part.gt_vertices.size(), star.size());
    for (int v : part.gt_vertices) EXPECT_TRUE(inStar(v)) << v;
    EXPECT_NEAR(
        std::remainder(part.transform.yaw_deg - r.brokenness.groups[0].transform.yaw_deg, 360.0),
        -20.0, 1.0);

    QualityParameters paper;
    paper.brokenness_min_part_vertices = paper.brokenness_min_vertices;
    EXPECT_EQ(evaluateMatch(g, m, match, paper).brokenness.degree, 0);
    // Turned by 3 degrees (0.26 m at 5 m), the star is not clearly separate: no break.
    EXPECT_EQ(evaluateMatch(g, turned(3.0), match).brokenness.degree, 0);
}

// Issue 11, quality that measures the map: the scores of a small matched part do not speak for
// the whole map. The campus matched with itself on a share of its vertices only: accuracy,
// consistency and brokenness are perfect either way; below min_trusted_coverage (0.5) the
// quality shrinks with sqrt(coverage / 0.5), above it the plain weighted mean stays.
TEST(QualityEvaluator, QualityOfASmallMatchedPartShrinksWithItsCoverage)
{
    const TopologyGraph g = buildTopologyGraph(makeCampusMap());
    QualityParameters paper;
    paper.min_trusted_coverage = 0.0;
    for (double share : {0.2, 0.35, 0.8})
    {
        GraphMatch match;
        std::vector<int> ids;
        for (const auto& v : g.vertices)
            if (!v.spurious) ids.push_back(v.id);
        const std::size_t n = static_cast<std::size_t>(std::lround(share * double(ids.size())));
        for (std::size_t i = 0; i < n; ++i)
            match.pairs.push_back({ids[i], ids[i], MatchStage::Isomorphism, 1.0, 0});
        match.isomorphism = n;
        match.isomorphism_sizes = {n};
        const QualityReport r = evaluateMatch(g, g, match);
        const QualityReport plain = evaluateMatch(g, g, match, paper);
        ASSERT_NEAR(r.coverage, share, 0.01);
        const double expected =
            plain.quality * (r.coverage < 0.5 ? std::sqrt(r.coverage / 0.5) : 1.0);
        EXPECT_NEAR(r.quality, expected, 1e-12) << share;
        if (share < 0.5)
        {
            EXPECT_LT(r.quality, plain.quality) << share;
        }
    }
}
