/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "scoring.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <sstream>

#include "geometry/horn.h"
#include "matching/wall_agreement.h"

namespace mrpt_topoeval::validation
{
TruthCheck checkTruth(const mrpt::maps::COccupancyGridMap2D& gt,
                      const mrpt::maps::COccupancyGridMap2D& map, const Truth& truth)
{
    TruthCheck check;
    if (truth.different_building || !truth.mapping) return check;
    const int gx = static_cast<int>(gt.getSizeX()), gy = static_cast<int>(gt.getSizeY());
    cv::Mat walls(gy, gx, CV_8UC1);
    for (int y = 0; y < gy; ++y)
        for (int x = 0; x < gx; ++x)
            walls.at<std::uint8_t>(y, x) = gt.getCell(x, y) < 0.35f ? 0 : 255;
    cv::Mat dist;
    cv::distanceTransform(walls, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    const double res = gt.getResolution();
    const int mx = static_cast<int>(map.getSizeX()), my = static_cast<int>(map.getSizeY());
    for (int y = 0; y < my; ++y)
        for (int x = 0; x < mx; ++x)
        {
            if (!(map.getCell(x, y) < 0.35f)) continue;
            const Eigen::Vector2d p(map.idx2x(x), map.idx2y(y));
            if (truth.is_clutter && truth.is_clutter(p)) continue;
            ++check.cells;
            const auto q = truth.mapping(p);
            if (!q)
            {
                ++check.unmapped;
                continue;
            }
            const int cx = static_cast<int>(std::floor((q->x() - gt.getXMin()) / res));
            const int cy = static_cast<int>(std::floor((q->y() - gt.getYMin()) / res));
            if (cx < 0 || cy < 0 || cx >= gx || cy >= gy) continue;
            // Distance between cell centres, less half a cell for the mapped point's offset.
            if (dist.at<float>(cy, cx) * res <= truth.wall_tolerance_m + 1e-9) ++check.on_wall;
        }
    if (!truth.keeps_free_space || !truth.forward) return check;
    // Free space kept: every free ground-truth cell's image in the map is known (free, or under
    // a wall or clutter laid over it).
    for (int y = 0; y < gy; ++y)
        for (int x = 0; x < gx; ++x)
        {
            if (!(gt.getCell(x, y) > 0.65f)) continue;
            ++check.free_cells;
            const auto q = truth.forward(Eigen::Vector2d(gt.idx2x(x), gt.idx2y(y)));
            if (!q) continue;
            const int cx = map.x2idx(q->x()), cy = map.y2idx(q->y());
            if (cx < 0 || cy < 0 || cx >= mx || cy >= my) continue;
            const float c = map.getCell(cx, cy);
            check.free_kept += (c < 0.35f || c > 0.65f) ? 1 : 0;
        }
    return check;
}

double mapDistortion(const mrpt::maps::COccupancyGridMap2D& map, const Truth& truth, int stride)
{
    if (truth.different_building || !truth.mapping) return std::numeric_limits<double>::quiet_NaN();
    std::vector<Eigen::Vector2d> gt_pts, map_pts;
    const int mx = static_cast<int>(map.getSizeX()), my = static_cast<int>(map.getSizeY());
    for (int y = 0; y < my; y += stride)
        for (int x = 0; x < mx; x += stride)
        {
            if (!(map.getCell(x, y) < 0.35f)) continue;
            const Eigen::Vector2d p(map.idx2x(x), map.idx2y(y));
            if (truth.is_clutter && truth.is_clutter(p)) continue;
            const auto q = truth.mapping(p);
            if (!q) continue;
            map_pts.push_back(p);
            gt_pts.push_back(*q);
        }
    if (gt_pts.size() < 3) return std::numeric_limits<double>::quiet_NaN();
    double mse = 0.0;
    internal::hornAlign(gt_pts, map_pts, &mse);
    return std::sqrt(mse);
}

double CaseScore::pairTolerance(const TopoVertex& g, const TopoVertex& m)
{
    return std::max(0.5, 0.5 * std::max(g.clearance_m, m.clearance_m));
}

LostVertices& LostVertices::operator+=(const LostVertices& o)
{
    vertices += o.vertices;
    dead_end_moved += o.dead_end_moved;
    dead_end_absent += o.dead_end_absent;
    junction_with_dead_end += o.junction_with_dead_end;
    junction_moved += o.junction_moved;
    junction_absent += o.junction_absent;
    narrow_tips += o.narrow_tips;
    narrow_tips_lost += o.narrow_tips_lost;
    wide_tips += o.wide_tips;
    wide_tips_lost += o.wide_tips_lost;
    return *this;
}

namespace
{
/** The causes of LostVertices for the ground-truth vertices without a counterpart
 * (`has_counterpart`), from the truth places of the map's vertices (`places`, the first the
 * most likely). */
LostVertices lostVertices(const TopologyGraph& gt, const TopologyGraph& map,
                          const std::vector<std::vector<std::pair<int, Eigen::Vector2d>>>& places,
                          const std::vector<char>& has_counterpart)
{
    LostVertices lost;
    auto lostAt = [&](int id) { return !has_counterpart[static_cast<std::size_t>(id)]; };
    // A map vertex of the kind (dead end or not) within kLostNearM of where g is.
    auto nearOfItsKind = [&](const TopoVertex& g)
    {
        const bool dead_end = g.degree() == 1;
        for (const auto& m : map.vertices)
        {
            if (m.spurious || (m.degree() == 1) != dead_end) continue;
            for (const auto& [part, q] : places[static_cast<std::size_t>(m.id)])
                if ((q - g.position_m).norm() <= kLostNearM) return true;
        }
        return false;
    };
    for (const auto& g : gt.vertices)
    {
        if (g.spurious) continue;
        ++lost.vertices;
        const bool is_lost = lostAt(g.id);
        if (g.degree() == 1)
        {
            const bool narrow = g.clearance_m < kNarrowTipM;
            ++(narrow ? lost.narrow_tips : lost.wide_tips);
            if (!is_lost) continue;
            ++(narrow ? lost.narrow_tips_lost : lost.wide_tips_lost);
            ++(nearOfItsKind(g) ? lost.dead_end_moved : lost.dead_end_absent);
            continue;
        }
        if (!is_lost) continue;
        bool dead_end_lost = false;
        for (const auto& inc : g.ring)
        {
            const auto& other = gt.vertices[static_cast<std::size_t>(inc.other_vertex)];
            dead_end_lost |=
                other.id != g.id && other.degree() == 1 && !other.spurious && lostAt(other.id);
        }
        if (g.degree() == 3 && dead_end_lost)
            ++lost.junction_with_dead_end;  // without that branch, a bend of a corridor
        else
            ++(nearOfItsKind(g) ? lost.junction_moved : lost.junction_absent);
    }
    return lost;
}
}  // namespace

CaseScore scoreCase(const TopologyGraph& gt, const TopologyGraph& map, const QualityReport& report,
                    const Truth& truth)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CaseScore s;
    s.gt_vertices = gt.numNonSpuriousVertices();
    s.map_vertices = map.numNonSpuriousVertices();
    // What the truth alone keeps of each ground-truth vertex: in a crop's rectangle (2 kept,
    // 1 at the cut, 0 cut away), and the part of a broken map that keeps it whole (-1 none).
    std::vector<int> kept_part(gt.vertices.size(), -1);
    for (const auto& g : gt.vertices)
    {
        if (g.spurious) continue;
        const int kept = truth.kept ? truth.kept(g.position_m, g.clearance_m) : 2;
        s.gt_kept += kept == 2 ? 1 : 0;
        s.gt_at_cut += kept == 1 ? 1 : 0;
        if (truth.kept_part)
            kept_part[static_cast<std::size_t>(g.id)] =
                truth.kept_part(g.position_m, g.clearance_m);
    }
    // The truth places of every map vertex, once: (part, ground-truth position), the first
    // the most likely; a vertex on a broken map's seam has one per part that made it.
    std::vector<std::vector<std::pair<int, Eigen::Vector2d>>> places(map.vertices.size());
    if (!truth.different_building && truth.mapping)
        for (const auto& v : map.vertices)
        {
            auto& own = places[static_cast<std::size_t>(v.id)];
            if (truth.vertex_places)
            {
                own = truth.vertex_places(v.position_m, v.clearance_m);
                continue;
            }
            if (const auto q = truth.mapping(v.position_m))
                own.emplace_back(truth.part_of ? truth.part_of(v.position_m) : -1, *q);
        }
    // The part by which map vertex m stands for ground-truth vertex g (kNotTrue: it does not;
    // -1: a truth without parts).
    constexpr int kNotTrue = -2;
    auto trueBy = [&](int g, int m)
    {
        const auto& gv = gt.vertices[static_cast<std::size_t>(g)];
        const double tol = CaseScore::pairTolerance(gv, map.vertices[static_cast<std::size_t>(m)]);
        for (const auto& [part, q] : places[static_cast<std::size_t>(m)])
            if ((q - gv.position_m).norm() <= tol) return part;
        return kNotTrue;
    };
    std::map<int, int> counterparts_per_part;
    std::vector<char> has_counterpart(gt.vertices.size(), 0);
    for (const auto& g : gt.vertices)
    {
        if (g.spurious) continue;
        for (const auto& m : map.vertices)
        {
            const int by = m.spurious ? kNotTrue : trueBy(g.id, m.id);
            if (by == kNotTrue) continue;
            ++s.gt_with_counterpart;
            const int partner = report.match.mapVertexOf(g.id);
            s.counterpart_lines.push_back("gt " + std::to_string(g.id) + " -> map " +
                                          std::to_string(m.id) + " (part " + std::to_string(by) +
                                          ", matched to " + std::to_string(partner) + ")");
            if (truth.part_of) ++counterparts_per_part[by];
            has_counterpart[static_cast<std::size_t>(g.id)] = 1;
            break;
        }
        // For the pictures: a vertex whose walls a part keeps whole, that the map's graph lost.
        const int part = kept_part[static_cast<std::size_t>(g.id)];
        if (!has_counterpart[static_cast<std::size_t>(g.id)] && part >= 0)
            s.counterpart_lines.push_back("gt " + std::to_string(g.id) + " kept whole by part " +
                                          std::to_string(part) +
                                          ": no counterpart in the map's graph");
    }
    if (!truth.different_building && truth.mapping && !truth.kept && !truth.part_of)
        s.lost = lostVertices(gt, map, places, has_counterpart);
    std::map<int, int> true_per_part;
    for (const auto& p : report.match.pairs)
    {
        ++s.matched;
        const int by = trueBy(p.ground_truth, p.map);
        if (by == kNotTrue)
        {
            const auto& own = places[static_cast<std::size_t>(p.map)];
            const Eigen::Vector2d* q = own.empty() ? nullptr : &own.front().second;
            std::ostringstream line;
            line << "gt " << p.ground_truth << " -> map " << p.map << " ("
                 << (p.stage == MatchStage::NeighbourGrowing ? "grown" : "core") << "), ";
            if (q)
            {
                line << "truth puts map " << p.map << " "
                     << (*q - gt.vertices[static_cast<std::size_t>(p.ground_truth)].position_m)
                            .norm()
                     << " m from gt " << p.ground_truth;
                // The ground-truth vertex the truth puts nearest: a neighbour taken in its place,
                // or none near where the map's vertex has no counterpart.
                int nearest = -1;
                double nearest_d = std::numeric_limits<double>::infinity();
                for (const auto& g : gt.vertices)
                {
                    const double d = (*q - g.position_m).norm();
                    if (!g.spurious && d < nearest_d) nearest_d = d, nearest = g.id;
                }
                if (nearest >= 0)
                    line << "; nearest to it: gt " << nearest << " at " << nearest_d << " m";
            }
            else
                line << "the truth does not place map " << p.map;
            s.false_pairs.push_back(line.str());
            ++(p.stage == MatchStage::NeighbourGrowing ? s.false_grown : s.false_core);
            continue;
        }
        ++s.true_pairs;
        if (truth.part_of) ++true_per_part[by];
    }
    if (truth.part_of && truth.injected_breaks >= 0)
    {
        s.parts_with_3_pairs = s.parts_with_5_pairs = s.parts_with_5_counterparts =
            s.parts_with_3_counterparts = 0;
        for (const auto& [part, n] : counterparts_per_part)
        {
            s.parts_with_5_counterparts += (part >= 0 && n >= 5) ? 1 : 0;
            s.parts_with_3_counterparts += (part >= 0 && n >= 3) ? 1 : 0;
        }
        if (truth.kept_part)
        {
            std::map<int, int> kept_per_part;
            for (const int part : kept_part) ++kept_per_part[part];
            s.parts_with_3_kept = 0;
            for (const auto& [part, n] : kept_per_part)
                s.parts_with_3_kept += (part >= 0 && n >= 3) ? 1 : 0;
        }
        for (const auto& [part, n] : true_per_part)
        {
            s.parts_with_3_pairs += (part >= 0 && n >= 3) ? 1 : 0;
            s.parts_with_5_pairs += (part >= 0 && n >= 5) ? 1 : 0;
        }
        for (std::size_t k = 0; k < truth.part_yaw_deg.size(); ++k)
        {
            const int part = static_cast<int>(k);
            s.parts.push_back({part, truth.part_yaw_deg[k],
                               static_cast<std::size_t>(counterparts_per_part[part]),
                               static_cast<std::size_t>(true_per_part[part])});
        }
    }
    s.precision = s.matched ? static_cast<double>(s.true_pairs) / s.matched : nan;
    s.recall = s.gt_with_counterpart
                   ? std::min(1.0, static_cast<double>(s.true_pairs) / s.gt_with_counterpart)
                   : nan;
    s.messages = report.messages;  // the match's, then the evaluation's
    s.coverage = report.coverage;
    s.quality = report.quality;
    s.relative_rmse_m = report.relative_accuracy.rmse_m;
    s.explained_walls = report.explained_walls.measured ? report.explained_walls.share : nan;
    s.brokenness_found = report.brokenness.degree;
    for (std::size_t i = 1; i < report.brokenness.groups.size(); ++i)
        s.break_offsets_m.push_back(report.brokenness.groups[i].offset_m);
    s.brokenness_injected = truth.injected_breaks;
    s.max_group_rotation_error_deg = nan;
    if (truth.part_of && !truth.part_yaw_deg.empty() && !report.brokenness.groups.empty())
    {
        // Each part's true transform (T_gt_map), fitted to where the truth places the map
        // vertices of that part: the truth of a group's offset.
        std::map<int, std::pair<std::vector<Eigen::Vector2d>, std::vector<Eigen::Vector2d>>>
            part_points;
        for (const auto& m : map.vertices)
            for (const auto& [part, q] : places[static_cast<std::size_t>(m.id)])
                if (part >= 0)
                    part_points[part].first.push_back(q),
                        part_points[part].second.push_back(m.position_m);
        std::map<int, Transform2D> part_fit;
        for (const auto& [part, pts] : part_points)
            if (pts.first.size() >= 3) part_fit[part] = internal::hornAlign(pts.first, pts.second);
        double worst = 0.0;
        // The map vertex of a group's k-th ground-truth vertex: a part placed by its walls names
        // its map vertices; the others' are their pairs'.
        auto mapVertexOf = [&](const BrokennessGroup& group, std::size_t k) {
            return group.by_walls ? group.map_vertices[k]
                                  : report.match.mapVertexOf(group.gt_vertices[k]);
        };
        // A group placed by its walls is its walls: its part is the one most of whose wall
        // points its fit puts on a ground-truth wall (within the truth check's tolerance), not
        // the one most of its two or three vertices vote for (vertices at a cut are made by two
        // parts: fresh seed 50's multi_wing_50002/broken_2, two groups each on one vertex of
        // two parts, session 49).
        const double reach = std::max(0.10, 1.5 * std::max(gt.map.resolution_m, 1e-6));
        std::optional<internal::WallIndex> gt_walls;  // built for the first such group
        auto wallPart = [&](const BrokennessGroup& group)
        {
            if (!gt_walls) gt_walls.emplace(gt.wall_points_m);
            std::map<int, int> on;
            for (const auto& w : map.wall_points_m)
            {
                const Eigen::Vector2d q = w.cast<double>();
                if (gt_walls->near(group.transform.apply(q), reach)) ++on[truth.part_of(q)];
            }
            int part = -1, best = 0;
            for (const auto& [k, n] : on)
                if (k >= 0 && n > best) part = k, best = n;
            return part;
        };
        for (const auto& group : report.brokenness.groups)
        {
            std::map<int, int> votes;
            for (std::size_t k = 0; k < group.gt_vertices.size(); ++k)
            {
                const int g = group.gt_vertices[k];
                const int m = mapVertexOf(group, k);
                if (m < 0) continue;
                // A true pair's part is the one that makes it true; else the likeliest.
                const int by = trueBy(g, m);
                const auto& own = places[static_cast<std::size_t>(m)];
                ++votes[by != kNotTrue ? by : own.empty() ? -1 : own.front().first];
            }
            int part = -1, best = 0;
            for (const auto& [k, n] : votes)
                if (k >= 0 && n > best) part = k, best = n;
            if (group.by_walls) part = wallPart(group);
            GroupScore g{group.transform.yaw_deg, {}, part};
            for (const auto& [k, n] : votes) g.vertices_per_part[k] = static_cast<std::size_t>(n);
            g.offset_m = group.offset_m;
            const auto own = part_fit.find(part);
            if (!s.groups.empty())
            {
                // BrokennessGroup::offset_m with each part's true fit in place of the groups'.
                std::vector<Transform2D> larger;
                for (const GroupScore& l : s.groups)
                    if (const auto fit = part_fit.find(l.part); fit != part_fit.end())
                        larger.push_back(fit->second);
                std::vector<Eigen::Vector2d> points;
                for (std::size_t k = 0; k < group.gt_vertices.size(); ++k)
                    if (const int m = mapVertexOf(group, k); m >= 0)
                        points.push_back(map.vertices[static_cast<std::size_t>(m)].position_m);
                const double offset = own == part_fit.end()
                                          ? std::numeric_limits<double>::infinity()
                                          : internal::partOffset(own->second, larger, points);
                g.true_offset_m =
                    std::isfinite(offset) ? offset : std::numeric_limits<double>::quiet_NaN();
            }
            s.groups.push_back(std::move(g));
            if (part < 0) continue;
            const double err = std::remainder(
                group.transform.yaw_deg - truth.part_yaw_deg[static_cast<std::size_t>(part)],
                360.0);
            worst = std::max(worst, std::abs(err));
        }
        s.max_group_rotation_error_deg = worst;
    }
    return s;
}
}  // namespace mrpt_topoeval::validation
