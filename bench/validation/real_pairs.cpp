/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "real_pairs.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPosePDF.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/slam/CICP.h>
#include <mrpt_topoeval/RawlogScorer.h>
#include <mrpt_topoeval/map_io.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

// How each truth is established (none uses the matcher):
// - known transforms and shared frames: a Rigid2D, or the identity;
// - Gazebo: rigid fits to the estimated -> true robot positions near each map point;
// - Halmstad: a fit to hand-labelled keypoints;
// - Intel: the SLAM keyframes' estimated poses against their true poses, which come from the
//   corrected log where the keyframe's scan is in it, else from odometry seeded ICP of the scan
//   against the reference map;
// - Radish logs with corrected poses: topoeval's own ICP-SLAM (`topoeval rawlog`) maps the log,
//   and each keyframe's true pose is the corrected pose of its scan.
// Every truth is checked against the ground truth's walls (checkTruth) and the numbers are
// written into Truth::source, so a reader of the corpus sees how good each truth is.

namespace mrpt_topoeval::validation
{
namespace
{
namespace fs = std::filesystem;
using mrpt::maps::COccupancyGridMap2D;
using mrpt::poses::CPose2D;
using Points = std::vector<Eigen::Vector2d>;

/** Cells below this P(free) count as occupied (loaded maps are 0 / 0.5 / 1 but for `scale`). */
constexpr float kOccupiedBelow = 0.4f;
/** Distances of the truth check [m]; the first is Truth::wall_tolerance_m by default. */
constexpr double kCheckTol015_m = 0.15, kCheckTol025_m = 0.25;
/** Gazebo local truth: estimated poses whose estimated -> true positions are fitted per point. */
constexpr int kLocalFitPoses = 6;
/** Hand-labelled corners: local rigid fits to this many of the nearest; the one whose truth check
 * puts most of the map's walls on reference walls is used (the truth check, not the matcher,
 * decides: Cartographer 64.2 / 65.0 / 62.3 / 59.9 % within 0.10 m for 2 / 3 / 4 / 6). */
constexpr int kLocalFitKeypoints[] = {2, 3, 4, 6};

COccupancyGridMap2D loadGrid(const fs::path& file, double resolution_m = 0.05)
{
    MapLoadOptions opts;
    opts.resolution_m = resolution_m;
    return loadMap(file.string(), opts).grid;
}

bool occupied(const COccupancyGridMap2D& g, int cx, int cy)
{
    return cx >= 0 && cy >= 0 && cx < static_cast<int>(g.getSizeX()) &&
           cy < static_cast<int>(g.getSizeY()) && g.getCell(cx, cy) < kOccupiedBelow;
}

/** Centres of the occupied cells [m]. */
Points occupiedCells(const COccupancyGridMap2D& g)
{
    Points pts;
    for (int cy = 0; cy < static_cast<int>(g.getSizeY()); ++cy)
        for (int cx = 0; cx < static_cast<int>(g.getSizeX()); ++cx)
            if (occupied(g, cx, cy)) pts.emplace_back(g.idx2x(cx), g.idx2y(cy));
    return pts;
}

// ---------------------------------------------------------------------------------------------
// Truth check: distance of mapped map walls to the ground truth's walls.

/** Exact squared Euclidean distance transform of one line (Felzenszwalb & Huttenlocher 2012). */
void edt1d(const std::vector<double>& f, std::vector<double>& d, std::vector<int>& v,
           std::vector<double>& z)
{
    const int n = static_cast<int>(f.size());
    constexpr double inf = std::numeric_limits<double>::infinity();
    int k = 0;
    v[0] = 0;
    z[0] = -inf;
    z[1] = inf;
    for (int q = 1; q < n; ++q)
    {
        if (f[q] == inf) continue;
        while (true)
        {
            if (f[v[k]] == inf)
            {
                v[k] = q;  // only infinite parabolas so far: replace
                break;
            }
            const double s = ((f[q] + q * q) - (f[v[k]] + v[k] * v[k])) / (2.0 * (q - v[k]));
            if (s <= z[k])
            {
                if (k == 0)
                {
                    v[0] = q;
                    break;
                }
                --k;
                continue;
            }
            ++k;
            v[k] = q;
            z[k] = s;
            z[k + 1] = inf;
            break;
        }
    }
    k = 0;
    for (int q = 0; q < n; ++q)
    {
        while (z[k + 1] < q) ++k;
        d[q] = f[v[k]] == inf ? inf : (q - v[k]) * (q - v[k]) + f[v[k]];
    }
}

/** Distance of any world point to the nearest occupied cell of a grid [m]. */
class WallDistance
{
public:
    explicit WallDistance(const COccupancyGridMap2D& g)
        : m_x0(g.getXMin()),
          m_y0(g.getYMin()),
          m_res(g.getResolution()),
          m_w(static_cast<int>(g.getSizeX())),
          m_h(static_cast<int>(g.getSizeY())),
          m_d2(static_cast<std::size_t>(m_w) * m_h)
    {
        constexpr double inf = std::numeric_limits<double>::infinity();
        const int n = std::max(m_w, m_h);
        std::vector<double> f(n), d(n), z(n + 1);
        std::vector<int> v(n);
        for (int cy = 0; cy < m_h; ++cy)
            for (int cx = 0; cx < m_w; ++cx) m_d2[idx(cx, cy)] = occupied(g, cx, cy) ? 0.0 : inf;
        f.resize(m_h), d.resize(m_h);
        for (int cx = 0; cx < m_w; ++cx)
        {
            for (int cy = 0; cy < m_h; ++cy) f[cy] = m_d2[idx(cx, cy)];
            edt1d(f, d, v, z);
            for (int cy = 0; cy < m_h; ++cy) m_d2[idx(cx, cy)] = d[cy];
        }
        f.resize(m_w), d.resize(m_w);
        for (int cy = 0; cy < m_h; ++cy)
        {
            for (int cx = 0; cx < m_w; ++cx) f[cx] = m_d2[idx(cx, cy)];
            edt1d(f, d, v, z);
            for (int cx = 0; cx < m_w; ++cx) m_d2[idx(cx, cy)] = d[cx];
        }
    }

    /** Infinite outside the grid. */
    double at(const Eigen::Vector2d& p) const
    {
        const int cx = static_cast<int>(std::floor((p.x() - m_x0) / m_res));
        const int cy = static_cast<int>(std::floor((p.y() - m_y0) / m_res));
        if (cx < 0 || cy < 0 || cx >= m_w || cy >= m_h)
            return std::numeric_limits<double>::infinity();
        return std::sqrt(m_d2[idx(cx, cy)]) * m_res;
    }

private:
    std::size_t idx(int cx, int cy) const { return static_cast<std::size_t>(cy) * m_w + cx; }
    double m_x0, m_y0, m_res;
    int m_w, m_h;
    std::vector<double> m_d2;  //!< Squared distance [cells^2].
};

/** Shares of the map's occupied cells (clutter left out) that the truth maps near a wall. */
struct WallShares
{
    std::size_t cells = 0;  //!< Occupied, not clutter, with a mapping.
    double within_tol = 0;  //!< Share within Truth::wall_tolerance_m.
    double within_015 = 0;  //!< Share within 0.15 m.
    double within_025 = 0;  //!< Share within 0.25 m.
    std::string text() const
    {
        return fmt(100 * within_tol, 1) + " / " + fmt(100 * within_015, 1) + " / " +
               fmt(100 * within_025, 1) + " % of " + std::to_string(cells) + " cells";
    }
};

WallShares wallShares(const WallDistance& gt_walls, const COccupancyGridMap2D& map,
                      const Truth& truth)
{
    WallShares c;
    std::size_t n_tol = 0, n_015 = 0, n_025 = 0;
    for (const Eigen::Vector2d& p : occupiedCells(map))
    {
        if (truth.is_clutter && truth.is_clutter(p)) continue;
        const std::optional<Eigen::Vector2d> q = truth.mapping(p);
        if (!q) continue;
        ++c.cells;
        const double d = gt_walls.at(*q);
        n_tol += d <= truth.wall_tolerance_m;
        n_015 += d <= kCheckTol015_m;
        n_025 += d <= kCheckTol025_m;
    }
    if (c.cells == 0) return c;
    c.within_tol = static_cast<double>(n_tol) / c.cells;
    c.within_015 = static_cast<double>(n_015) / c.cells;
    c.within_025 = static_cast<double>(n_025) / c.cells;
    return c;
}

WallShares wallShares(const COccupancyGridMap2D& gt, const COccupancyGridMap2D& map,
                      const Truth& truth)
{
    return wallShares(WallDistance(gt), map, truth);
}

// ---------------------------------------------------------------------------------------------
// Fits.

/** Least-squares p_dst = s R p_src + t in 2D (Horn / Umeyama); s = 1 unless `with_scale`. */
struct Fit2D
{
    Rigid2D rigid;  //!< Rotation and translation; with a scale, t already includes it.
    double scale = 1.0;
    double rmse_m = 0.0;
    Eigen::Vector2d apply(const Eigen::Vector2d& p) const
    {
        const double c = std::cos(rigid.yaw_rad), s = std::sin(rigid.yaw_rad);
        return scale * Eigen::Vector2d(c * p.x() - s * p.y(), s * p.x() + c * p.y()) + rigid.t_m;
    }
};

Fit2D fitPoints(const Points& src, const Points& dst, bool with_scale)
{
    Fit2D fit;
    const std::size_t n = std::min(src.size(), dst.size());
    if (n < 2) return fit;
    Eigen::Vector2d cs(0, 0), cd(0, 0);
    for (std::size_t i = 0; i < n; ++i) cs += src[i], cd += dst[i];
    cs /= n, cd /= n;
    double sxx = 0, sxy = 0, ss = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const Eigen::Vector2d a = src[i] - cs, b = dst[i] - cd;
        sxx += a.dot(b);
        sxy += a.x() * b.y() - a.y() * b.x();
        ss += a.squaredNorm();
    }
    fit.rigid.yaw_rad = std::atan2(sxy, sxx);
    if (with_scale && ss > 0) fit.scale = std::hypot(sxx, sxy) / ss;
    fit.rigid.t_m = Eigen::Vector2d::Zero();
    fit.rigid.t_m = cd - fit.apply(cs);
    double e2 = 0;
    for (std::size_t i = 0; i < n; ++i) e2 += (fit.apply(src[i]) - dst[i]).squaredNorm();
    fit.rmse_m = std::sqrt(e2 / n);
    return fit;
}

TruthMapping identityMapping()
{
    return [](const Eigen::Vector2d& p) { return std::optional<Eigen::Vector2d>(p); };
}

TruthMapping rigidMapping(const Rigid2D& T_gt_map)
{
    return [T_gt_map](const Eigen::Vector2d& p)
    { return std::optional<Eigen::Vector2d>(T_gt_map.apply(p)); };
}

/** Truth from matched positions: for a map point, the rigid fit of the `k` estimated positions
 * nearest to it onto their true positions. A wing that the SLAM rotated maps back as a whole. */
TruthMapping localPoseFitMapping(Points est, Points truth, int k)
{
    auto e = std::make_shared<const Points>(std::move(est));
    auto t = std::make_shared<const Points>(std::move(truth));
    return [e, t, k](const Eigen::Vector2d& p) -> std::optional<Eigen::Vector2d>
    {
        const std::size_t n = e->size();
        std::vector<std::pair<double, std::size_t>> near(n);
        for (std::size_t i = 0; i < n; ++i) near[i] = {((*e)[i] - p).squaredNorm(), i};
        const std::size_t m = std::min<std::size_t>(n, static_cast<std::size_t>(k));
        if (m < 2) return std::nullopt;
        std::partial_sort(near.begin(), near.begin() + m, near.end());
        Points a, b;
        for (std::size_t i = 0; i < m; ++i)
            a.push_back((*e)[near[i].second]), b.push_back((*t)[near[i].second]);
        return fitPoints(a, b, false).rigid.apply(p);
    };
}

/** Truth from keyframes: a map point is placed like the scans that drew the obstacles nearest to
 * it, p_gt = true_k (+) (est_k (-) p).
 *
 * The nearest keyframe by position (sessions 4-8) is not enough in a bent map that overlaps
 * itself: where two passes were drawn over each other the nearest pose can belong to the pass
 * that did not draw the walls around the point. So the scan endpoints, in the map's frame, that
 * lie as far from the point as its nearest obstacles (from kTruthRingInM nearer to kTruthRingOutM
 * farther, within kTruthMaxRadiusM) are taken as the scans' share in drawing it: a topology
 * vertex's walls from its clearance on (the graph's, which ignores the specks a raw distance
 * would find; below), a wall cell's own wall at 0 (the map's nearest occupied cell for other
 * points; a person one scan saw in a corridor is nearer than the walls and is left out). Each
 * keyframe with at least kTruthMinEndpoints of them votes with their number for its placement of
 * the point; the placement with the most votes within kTruthAgreeM of it wins, and the mean of
 * those votes' placements is the point's. With no such keyframe the nearest one places it. On the
 * Intel map the share of occupied cells the truth puts on a reference wall rose from 0.738 to 0.955
 * (session 9, doc/validation.md).
 *
 * A topology vertex takes the walls around it, from its clearance to kTruthVertexRingOutM
 * farther (the matcher's wall margin), not only its nearest wall: where a later pass drew one
 * stray wall into a room, that wall is the vertex's nearest and the ring at 0.25 m held only its
 * keyframe (Intel map vertex 11: 3 endpoints of one late keyframe placed it 11.5 m from the
 * dead end that some 600 endpoints of 20 keyframes within 1.5 m put it 0.25 m from; session 12,
 * doc/validation.md). */
constexpr double kTruthMaxRadiusM = 3.0;
constexpr double kTruthRingInM = 0.15, kTruthRingOutM = 0.25;
constexpr double kTruthVertexRingOutM = 1.0;
constexpr int kTruthMinEndpoints = 3;
constexpr double kTruthAgreeM = 1.0;

struct KeyframeMappings
{
    TruthMapping point;
    std::function<std::optional<Eigen::Vector2d>(const Eigen::Vector2d&, double)> vertex;
};

KeyframeMappings keyframeMapping(std::vector<CPose2D> est, std::vector<CPose2D> truth,
                                 const std::vector<Points>& scans_local,
                                 const COccupancyGridMap2D& map)
{
    struct Index
    {
        std::vector<CPose2D> est, truth;
        std::unique_ptr<WallDistance> walls;
        double cell = 1.0;
        std::map<std::pair<long, long>, std::vector<std::pair<Eigen::Vector2d, int>>> buckets;
        std::pair<long, long> key(const Eigen::Vector2d& q) const
        {
            return {static_cast<long>(std::floor(q.x() / cell)),
                    static_cast<long>(std::floor(q.y() / cell))};
        }
    };
    auto ix = std::make_shared<Index>();
    ix->est = std::move(est);
    ix->truth = std::move(truth);
    ix->walls = std::make_unique<WallDistance>(map);
    for (std::size_t k = 0; k < scans_local.size() && k < ix->est.size(); ++k)
        for (const auto& l : scans_local[k])
        {
            double gx = 0, gy = 0;
            ix->est[k].composePoint(l.x(), l.y(), gx, gy);
            const Eigen::Vector2d q(gx, gy);
            ix->buckets[ix->key(q)].emplace_back(q, static_cast<int>(k));
        }
    std::shared_ptr<const Index> cix = ix;
    // The placement of p whose nearest obstacles lie d0 away, by the scan endpoints from
    // kTruthRingInM nearer to ring_out farther than d0.
    auto placeAt = [cix](const Eigen::Vector2d& p, double d0,
                         double ring_out) -> std::optional<Eigen::Vector2d>
    {
        const Index& x = *cix;
        if (x.est.empty()) return std::nullopt;
        auto place = [&](std::size_t k)
        {
            double lx = 0, ly = 0, gx = 0, gy = 0;
            x.est[k].inverseComposePoint(p.x(), p.y(), lx, ly);
            x.truth[k].composePoint(lx, ly, gx, gy);
            return Eigen::Vector2d(gx, gy);
        };
        // The endpoints within kTruthMaxRadiusM of p, with their distances.
        std::vector<std::pair<double, int>> near;  // distance, keyframe
        const double r = kTruthMaxRadiusM;
        const auto lo = x.key(p - Eigen::Vector2d(r, r)), hi = x.key(p + Eigen::Vector2d(r, r));
        for (long bx = lo.first; bx <= hi.first; ++bx)
            for (long by = lo.second; by <= hi.second; ++by)
            {
                const auto it = x.buckets.find({bx, by});
                if (it == x.buckets.end()) continue;
                for (const auto& [q, k] : it->second)
                {
                    const double d = (q - p).norm();
                    if (d <= r) near.emplace_back(d, k);
                }
            }
        std::map<int, int> votes;  // keyframe -> its endpoints on the obstacles nearest to p
        for (const auto& [d, k] : near)
            if (d >= d0 - kTruthRingInM && d <= d0 + ring_out) ++votes[k];
        for (auto it = votes.begin(); it != votes.end();)
            it = it->second < kTruthMinEndpoints ? votes.erase(it) : std::next(it);
        if (votes.empty())
        {
            std::size_t best = 0;
            double best_d2 = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < x.est.size(); ++i)
            {
                const double d2 =
                    std::pow(x.est[i].x() - p.x(), 2) + std::pow(x.est[i].y() - p.y(), 2);
                if (d2 < best_d2) best_d2 = d2, best = i;
            }
            return place(best);
        }
        std::vector<std::pair<Eigen::Vector2d, int>> placed;  // placement, votes
        for (const auto& [k, n] : votes) placed.emplace_back(place(static_cast<std::size_t>(k)), n);
        std::size_t best = 0;
        int best_support = -1;
        for (std::size_t i = 0; i < placed.size(); ++i)
        {
            int support = 0;
            for (const auto& [q, n] : placed)
                if ((q - placed[i].first).norm() <= kTruthAgreeM) support += n;
            if (support > best_support) best_support = support, best = i;
        }
        // The votes' mean placement within kTruthAgreeM of the winner (one keyframe's truth pose
        // has its own error, which its distance to the point multiplies).
        Eigen::Vector2d sum = Eigen::Vector2d::Zero();
        for (const auto& [q, n] : placed)
            if ((q - placed[best].first).norm() <= kTruthAgreeM) sum += double(n) * q;
        return Eigen::Vector2d(sum / double(best_support));
    };
    KeyframeMappings out;
    out.point = [cix, placeAt](const Eigen::Vector2d& p)
    { return placeAt(p, cix->walls->at(p), kTruthRingOutM); };
    out.vertex = [placeAt](const Eigen::Vector2d& p, double d0)
    { return placeAt(p, d0, kTruthVertexRingOutM); };
    return out;
}

/** Sets `pair`'s truth to the keyframes' (keyframeMapping) on its map. */
void setKeyframeTruth(RealPair& pair, std::vector<CPose2D> est, std::vector<CPose2D> truth,
                      const std::vector<Points>& scans_local)
{
    KeyframeMappings km = keyframeMapping(std::move(est), std::move(truth), scans_local, pair.map);
    pair.truth.mapping = std::move(km.point);
    pair.truth.vertex_places =
        [vertex = std::move(km.vertex)](const Eigen::Vector2d& q, double clearance_m)
    {
        std::vector<std::pair<int, Eigen::Vector2d>> places;
        if (const auto at = vertex(q, clearance_m)) places.emplace_back(-1, *at);
        return places;
    };
}

/** A scan's endpoints in the robot's frame. */
Points scanEndpoints(const mrpt::maps::CSimplePointsMap& pts)
{
    Points local;
    for (std::size_t i = 0; i < pts.size(); ++i)
    {
        float x = 0, y = 0;
        pts.getPoint(i, x, y);
        local.emplace_back(x, y);
    }
    return local;
}

// ---------------------------------------------------------------------------------------------
// Small readers.

/** Gazebo poses/<system>.csv: `slam_x;slam_y;gt_x;gt_y;error`, UTF-8 BOM, header row. */
void readPoseCsv(const fs::path& file, Points& est, Points& truth)
{
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot open");
    std::string line;
    std::getline(in, line);  // header (with the BOM)
    while (std::getline(in, line))
    {
        std::replace(line.begin(), line.end(), ';', ' ');
        std::istringstream s(line);
        double ex, ey, tx, ty;
        if (s >> ex >> ey >> tx >> ty) est.emplace_back(ex, ey), truth.emplace_back(tx, ty);
    }
    if (est.size() < 3) throw std::runtime_error(file.string() + ": fewer than 3 poses");
}

/** Hand-labelled keypoints `gt_x_m,gt_y_m,map_x_m,map_y_m` (`#` comments, a header row), as
 * bench/validation/gazebo_cartographer_keypoints.csv holds them. */
void readKeypointCsv(const fs::path& file, Points& map, Points& gt)
{
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot open");
    std::string line;
    bool header = true;
    while (std::getline(in, line))
    {
        line = line.substr(0, line.find('#'));
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        if (header)
        {
            if (line.rfind("gt_x_m,gt_y_m,map_x_m,map_y_m", 0) != 0)
                throw std::runtime_error(file.string() +
                                         ": the first row must be gt_x_m,gt_y_m,map_x_m,map_y_m");
            header = false;
            continue;
        }
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream s(line);
        double gx, gy, mx, my;
        if (!(s >> gx >> gy >> mx >> my))
            throw std::runtime_error(file.string() + ": bad row '" + line + "'");
        gt.emplace_back(gx, gy), map.emplace_back(mx, my);
    }
    if (gt.size() < 3) throw std::runtime_error(file.string() + ": fewer than 3 keypoints");
}

/** The little JSON that annotations.json needs: objects, arrays, numbers, strings. */
struct Json
{
    std::map<std::string, Json> object;
    std::vector<Json> array;
    double number = 0;
    std::string text;
};

class JsonParser
{
public:
    explicit JsonParser(std::string s) : m_s(std::move(s)) {}
    Json parse()
    {
        Json j;
        ws();
        if (m_i >= m_s.size()) fail("unexpected end");
        const char c = m_s[m_i];
        if (c == '{')
        {
            ++m_i;
            for (ws(); peek() != '}'; ws())
            {
                const std::string key = parse().text;
                ws();
                expect(':');
                j.object[key] = parse();
                ws();
                if (peek() == ',') ++m_i;
            }
            ++m_i;
        }
        else if (c == '[')
        {
            ++m_i;
            for (ws(); peek() != ']'; ws())
            {
                j.array.push_back(parse());
                ws();
                if (peek() == ',') ++m_i;
            }
            ++m_i;
        }
        else if (c == '"')
        {
            for (++m_i; peek() != '"'; ++m_i)
            {
                if (m_s[m_i] == '\\') ++m_i;
                j.text += m_s[m_i];
            }
            ++m_i;
        }
        else
        {
            std::size_t used = 0;
            try
            {
                j.number = std::stod(m_s.substr(m_i, 40), &used);
            }
            catch (const std::exception&)
            {
                fail("bad value");
            }
            m_i += used;
        }
        return j;
    }

private:
    void ws()
    {
        while (m_i < m_s.size() && std::isspace(static_cast<unsigned char>(m_s[m_i]))) ++m_i;
    }
    char peek() const
    {
        if (m_i >= m_s.size()) throw std::runtime_error("annotations.json: unexpected end");
        return m_s[m_i];
    }
    void expect(char c)
    {
        if (peek() != c) fail(std::string("expected '") + c + "'");
        ++m_i;
    }
    [[noreturn]] void fail(const std::string& what) const
    {
        throw std::runtime_error("annotations.json: " + what + " at byte " + std::to_string(m_i));
    }
    std::string m_s;
    std::size_t m_i = 0;
};

/** Halmstad keypoint (pixel x, y from the lower-left corner) in a loaded grid's world frame:
 * loadMap puts the image's lower-left pixel corner at the grid's (x_min, y_min). */
Eigen::Vector2d keypointToWorld(const Json& xy, const COccupancyGridMap2D& g)
{
    const double res = g.getResolution();
    return {g.getXMin() + (xy.array.at(0).number + 0.5) * res,
            g.getYMin() + (xy.array.at(1).number + 0.5) * res};
}

void note(std::vector<std::string>* skipped, const std::string& line)
{
    if (skipped) skipped->push_back(line);
}

/** Fills the pair's truth check numbers into its source text. */
void appendCheck(RealPair& pair)
{
    const WallShares c = wallShares(pair.gt, pair.map, pair.truth);
    pair.truth.source += "; truth check " + c.text() + " within " +
                         fmt(pair.truth.wall_tolerance_m, 2) + " / 0.15 / 0.25 m";
}

// ---------------------------------------------------------------------------------------------
// Families.

void gh25Pair(const fs::path& data, std::vector<RealPair>& out)
{
    RealPair p;
    p.name = "gh25_vs_icp_slam";
    p.family = "gh25";
    p.gt_file = (data / "rawlogs/gh25_gt_trinary_res0.05.yaml").string();
    p.map_file = (data / "slam_maps/driving_in_office_icp-slam_app-final.yaml").string();
    p.gt = loadGrid(p.gt_file);
    p.map = loadGrid(p.map_file);
    Rigid2D T_gt_map;
    T_gt_map.yaw_rad = 0.97 * M_PI / 180.0;
    T_gt_map.t_m = {20.03, 9.08};
    p.truth.mapping = rigidMapping(T_gt_map);
    p.truth.source = "known transform (data README: R(+0.97 deg), t = (20.03, 9.08) m)";
    out.push_back(std::move(p));
}

void housePairs(const fs::path& data, std::vector<RealPair>& out)
{
    const fs::path gt = data / "house/house_gt_trinary_res0.05.yaml";
    const fs::path clean = data / "house/map_6ccdcaa.yaml";
    const fs::path old = data / "house/map_2333d24.yaml";
    const std::vector<std::tuple<std::string, fs::path, fs::path, std::string>> pairs = {
        {"house_gt_vs_6ccdcaa", gt, clean,
         "same frame (data README): walls-only plan, furnished map"},
        {"house_gt_vs_2333d24", gt, old, "same frame (data README): its left wing is rotated"},
        {"house_6ccdcaa_vs_2333d24", clean, old,
         "same frame (data README): 2020 map as ground truth of the 2019 map"}};
    for (const auto& [name, g, m, source] : pairs)
    {
        RealPair p;
        p.name = name;
        p.family = "house";
        p.gt_file = g.string();
        p.map_file = m.string();
        p.gt = loadGrid(g);
        p.map = loadGrid(m);
        p.truth.mapping = identityMapping();
        p.truth.source = source;
        out.push_back(std::move(p));
    }
}

void gazeboPairs(const fs::path& data, std::vector<RealPair>& out)
{
    const fs::path dir = data / "gazebo_slam/office";
    const fs::path gt_file = dir / "office_ground_truth.yaml";
    const COccupancyGridMap2D gt = loadGrid(gt_file);
    const WallDistance gt_walls(gt);
    // map file stem, pose file stem
    const std::vector<std::pair<std::string, std::string>> systems = {
        {"cartographer", "cartographer"},
        {"gmapping", "gmapping"},
        {"slam_toolbox", "slam_toolbox"},
        {"lidar_rtabmap", "lidar_rtab_map"},
        {"rgbd_rtabmap", "rgb_d_rtab_map"}};
    for (const auto& [stem, poses] : systems)
    {
        RealPair p;
        p.name = "gazebo_" + stem;
        p.family = "gazebo";
        p.gt_file = gt_file.string();
        p.map_file = (dir / (stem + "_map.yaml")).string();
        p.gt = gt;
        p.map = loadGrid(p.map_file);

        Truth same;
        same.mapping = identityMapping();
        const WallShares c_same = wallShares(gt_walls, p.map, same);

        Points est, truth;
        readPoseCsv(dir / "poses" / (poses + ".csv"), est, truth);
        const std::size_t n_poses = est.size();
        Truth local;
        local.mapping = localPoseFitMapping(std::move(est), std::move(truth), kLocalFitPoses);
        const WallShares c_local = wallShares(gt_walls, p.map, local);

        const bool use_local = c_local.within_tol > c_same.within_tol;
        p.truth.mapping = use_local ? local.mapping : same.mapping;
        p.truth.source = (use_local ? "local rigid fits to the " + std::to_string(kLocalFitPoses) +
                                          " nearest of " + std::to_string(n_poses) +
                                          " estimated -> true poses (poses/" + poses + ".csv)"
                                    : std::string("same frame (data README)")) +
                         "; truth check local fit " + c_local.text() + ", identity " +
                         c_same.text() + " within 0.10 / 0.15 / 0.25 m";

        // Hand-labelled wall corners where a map's poses place too little of it (Cartographer:
        // session 19). They replace the other truths when they put more walls on walls.
        const fs::path kp_file =
            fs::path(TOPOEVAL_VALIDATION_DIR) / ("gazebo_" + stem + "_keypoints.csv");
        if (fs::exists(kp_file))
        {
            Points kp_map, kp_gt;
            readKeypointCsv(kp_file, kp_map, kp_gt);
            int best_k = 0;
            Truth best;
            WallShares best_check;
            for (const int k : kLocalFitKeypoints)
            {
                Truth by_kp;
                by_kp.mapping = localPoseFitMapping(kp_map, kp_gt, k);
                const WallShares c = wallShares(gt_walls, p.map, by_kp);
                if (best_k == 0 || c.within_tol > best_check.within_tol)
                    best_k = k, best = by_kp, best_check = c;
            }
            p.truth.source += "; keypoints " + best_check.text();
            if (best_check.within_tol > std::max(c_local.within_tol, c_same.within_tol))
            {
                p.truth.mapping = best.mapping;
                p.truth.source = "local rigid fits to the " + std::to_string(best_k) +
                                 " nearest of " + std::to_string(kp_map.size()) +
                                 " hand-labelled wall corners (bench/validation/" +
                                 kp_file.filename().string() + "); " + p.truth.source;
            }
        }
        out.push_back(std::move(p));
    }
}

/** The five plain IPA plans: nominal 0.05 m/px, lab_intel measured at about 0.043. */
std::vector<std::pair<std::string, double>> floorplanNames()
{
    return {{"Freiburg79_scan", 0.05},
            {"lab_intel", 0.043},
            {"lab_ipa", 0.05},
            {"office_a", 0.05},
            {"office_e", 0.05}};
}

void floorplanPairs(const fs::path& data, std::vector<RealPair>& out,
                    std::vector<std::string>* skipped)
{
    for (const auto& [name, res] : floorplanNames())
    {
        const fs::path plain = data / "floorplans" / (name + ".png");
        const fs::path furnished = data / "floorplans" / (name + "_furnitures.png");
        if (!fs::exists(plain) || !fs::exists(furnished))
        {
            note(skipped, "floorplan " + name + ": plain or furnished image missing");
            continue;
        }
        RealPair p;
        p.name = "floorplan_" + name + "_furnished";
        p.family = "floorplan";
        p.gt_file = plain.string();
        p.map_file = furnished.string();
        p.gt = loadGrid(plain, res);
        p.map = loadGrid(furnished, res);
        p.truth.mapping = identityMapping();
        p.truth.source = "same pixels (identity), " + fmt(res, 3) + " m/px";
        // Furniture: occupied in the furnished plan, no plain wall within one cell.
        const COccupancyGridMap2D& g = p.gt;
        const COccupancyGridMap2D& m = p.map;
        auto clutter = std::make_shared<std::vector<bool>>(m.getSizeX() * m.getSizeY(), false);
        for (int cy = 0; cy < static_cast<int>(m.getSizeY()); ++cy)
            for (int cx = 0; cx < static_cast<int>(m.getSizeX()); ++cx)
            {
                if (!occupied(m, cx, cy)) continue;
                bool near_wall = false;
                for (int dy = -1; dy <= 1 && !near_wall; ++dy)
                    for (int dx = -1; dx <= 1 && !near_wall; ++dx)
                        near_wall = occupied(g, cx + dx, cy + dy);
                (*clutter)[static_cast<std::size_t>(cy) * m.getSizeX() + cx] = !near_wall;
            }
        const double x0 = m.getXMin(), y0 = m.getYMin();
        const int w = static_cast<int>(m.getSizeX()), h = static_cast<int>(m.getSizeY());
        p.truth.is_clutter = [clutter, x0, y0, res, w, h](const Eigen::Vector2d& q)
        {
            const int cx = static_cast<int>(std::floor((q.x() - x0) / res));
            const int cy = static_cast<int>(std::floor((q.y() - y0) / res));
            return cx >= 0 && cy >= 0 && cx < w && cy < h &&
                   (*clutter)[static_cast<std::size_t>(cy) * w + cx];
        };
        out.push_back(std::move(p));
    }
}

/** The Halmstad layout's file: its YAML (which carries the fitted resolution) if present. */
fs::path halmstadLayout(const fs::path& data, const std::string& env)
{
    const fs::path dir = data / "halmstad_apartments" / env;
    return fs::exists(dir / (env + "_layout.yaml")) ? dir / (env + "_layout.yaml")
                                                    : dir / (env + "_layout.png");
}

void halmstadPairs(const fs::path& data, std::vector<RealPair>& out,
                   std::vector<std::string>* skipped)
{
    const fs::path ann_file = data / "halmstad_apartments/annotations.json";
    std::ifstream in(ann_file);
    if (!in)
    {
        note(skipped, "halmstad: " + ann_file.string() + " missing");
        return;
    }
    std::stringstream buf;
    buf << in.rdbuf();
    const Json ann = JsonParser(buf.str()).parse();
    const auto& keypoints = ann.object.at("keypoints").object;
    const auto& associations = ann.object.at("associations").object;

    for (const std::string env : {"HIH", "KPT4A"})
    {
        const std::string layout = env + "_layout";
        const fs::path gt_file = halmstadLayout(data, env);
        const COccupancyGridMap2D gt = loadGrid(gt_file, 0.02);
        for (int n = 1; n <= 4; ++n)
        {
            const std::string robot = env + "_0" + std::to_string(n);
            const fs::path map_file = data / "halmstad_apartments" / env / (robot + ".yaml");
            const auto assoc = associations.find(robot + "|" + layout);
            if (!fs::exists(map_file) || assoc == associations.end() || !keypoints.count(robot) ||
                !keypoints.count(layout))
            {
                note(skipped, "halmstad_" + robot + ": map or keypoints missing");
                continue;
            }
            RealPair p;
            p.name = "halmstad_" + robot;
            p.family = "halmstad";
            p.gt_file = gt_file.string();
            p.map_file = map_file.string();
            p.gt = gt;
            p.map = loadGrid(map_file, 0.02);
            Points src, dst;
            for (const Json& ij : assoc->second.array)
            {
                const auto i = static_cast<std::size_t>(ij.array.at(0).number);
                const auto j = static_cast<std::size_t>(ij.array.at(1).number);
                src.push_back(keypointToWorld(keypoints.at(robot).array.at(i), p.map));
                dst.push_back(keypointToWorld(keypoints.at(layout).array.at(j), p.gt));
            }
            const Fit2D rigid = fitPoints(src, dst, false);
            const Fit2D similar = fitPoints(src, dst, true);
            // A similarity only where the scale is clearly not 1 (the YAMLs were made so it is).
            const bool use_scale = std::abs(similar.scale - 1.0) > 0.03;
            const Fit2D fit = use_scale ? similar : rigid;
            p.truth.mapping = [fit](const Eigen::Vector2d& q)
            { return std::optional<Eigen::Vector2d>(fit.apply(q)); };
            p.truth.source = std::to_string(src.size()) + " hand-labelled keypoints, fit rmse " +
                             fmt(fit.rmse_m, 3) + " m (" + (use_scale ? "similarity" : "rigid") +
                             "; similarity fit scale " + fmt(similar.scale, 4) + ", rmse " +
                             fmt(similar.rmse_m, 3) + " m; yaw " +
                             fmt(fit.rigid.yaw_rad * 180 / M_PI, 2) + " deg)";
            out.push_back(std::move(p));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Intel: per-keyframe truth.

struct RawScan
{
    mrpt::obs::CObservation2DRangeScan::Ptr scan;
    CPose2D odometry;  //!< Odometry (raw log) or corrected pose (corrected log) at the scan.
};

std::vector<RawScan> readScans(const fs::path& file)
{
    mrpt::obs::CRawlog log;
    if (!log.loadFromRawLogFile(file.string()))
        throw std::runtime_error(file.string() + ": cannot read rawlog");
    std::vector<RawScan> scans;
    CPose2D odo;
    for (std::size_t i = 0; i < log.size(); ++i)
    {
        if (log.getType(i) != mrpt::obs::CRawlog::etObservation) continue;
        const auto obs = log.getAsObservation(i);
        if (const auto o = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs))
            odo = o->odometry;
        else if (const auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs))
            scans.push_back({s, odo});
    }
    return scans;
}

bool sameRanges(const mrpt::obs::CObservation2DRangeScan& a,
                const mrpt::obs::CObservation2DRangeScan& b)
{
    if (a.getScanSize() != b.getScanSize()) return false;
    for (std::size_t i = 0; i < a.getScanSize(); ++i)
        if (std::abs(a.getScanRange(i) - b.getScanRange(i)) > 1e-3f) return false;
    return true;
}

/** Index of the scan of `scans` with the same ranges as `s`, closest to `hint`; -1 if none. */
int findScan(const std::vector<RawScan>& scans, const mrpt::obs::CObservation2DRangeScan& s,
             int hint)
{
    int best = -1;
    for (int i = 0; i < static_cast<int>(scans.size()); ++i)
        if (sameRanges(*scans[i].scan, s) &&
            (best < 0 || std::abs(i - hint) < std::abs(best - hint)))
            best = i;
    return best;
}

/** True poses of the keyframes of `simplemap` in the corrected log's frame, and how many came
 * from the corrected log directly, from ICP, and were left at the seed. */
struct KeyframeTruth
{
    std::vector<CPose2D> est, truth;
    std::vector<Points> scans;  //!< each keyframe's scan endpoints in its own frame
    int exact = 0, icp = 0, seed_only = 0;
};

KeyframeTruth intelKeyframeTruth(const fs::path& data, const fs::path& simplemap_file,
                                 const COccupancyGridMap2D& ref)
{
    // The SLAM keyframes' scans are scans of the raw log (same ranges); their timestamps are
    // not those of the corrected log (its CARMEN times start at 1e9 s), and only some raw scans
    // are in the corrected log. Anchors: raw scans found in the corrected log, whose true pose
    // is the corrected one. A keyframe's seed is its nearest anchor moved by the raw odometry
    // between them; ICP of its scan against the reference map refines it.
    const std::vector<RawScan> raw = readScans(data / "rawlogs/intel_obs-format.rawlog");
    const std::vector<RawScan> corrected = readScans(data / "rawlogs/intel-corrected.rawlog");
    std::vector<std::pair<int, CPose2D>> anchors;  // raw index, true pose
    for (const RawScan& c : corrected)
    {
        const int r = findScan(raw, *c.scan, anchors.empty() ? 0 : anchors.back().first);
        if (r >= 0) anchors.emplace_back(r, c.odometry);
    }
    if (anchors.empty()) throw std::runtime_error("intel: no corrected scan found in the raw log");

    mrpt::maps::CSimpleMap sm;
    {
        mrpt::io::CFileGZInputStream f(simplemap_file.string());
        auto arch = mrpt::serialization::archiveFrom(f);
        arch >> sm;
    }
    mrpt::slam::CICP icp;
    icp.options.maxIterations = 100;
    icp.options.thresholdDist = 0.3f;
    icp.options.thresholdAng = static_cast<float>(10 * M_PI / 180);
    icp.options.ALFA = 0.5f;
    icp.options.smallestThresholdDist = 0.05f;

    KeyframeTruth kt;
    int hint = 0;
    for (std::size_t k = 0; k < sm.size(); ++k)
    {
        const auto& [pdf, sf] = sm.get(k);
        const auto scan = sf->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
        if (!scan) continue;
        const int r = findScan(raw, *scan, hint);
        if (r < 0) continue;
        hint = r;
        const auto a = std::min_element(anchors.begin(), anchors.end(),
                                        [r](const auto& x, const auto& y)
                                        { return std::abs(x.first - r) < std::abs(y.first - r); });
        CPose2D truth = a->second + (raw[r].odometry - raw[a->first].odometry);
        mrpt::maps::CSimplePointsMap pts;  // the scan's endpoints, for ICP and the truth
        pts.insertObservation(*scan);
        if (a->first == r)
            ++kt.exact;
        else
        {
            mrpt::slam::CICP::TReturnInfo info;
            const auto aligned = icp.Align(&ref, &pts, truth, info);
            const CPose2D refined = aligned->getMeanVal();
            const bool ok = info.goodness > 0.6 && (refined - truth).norm() < 1.0 &&
                            std::abs((refined - truth).phi()) < 0.3;
            if (ok)
                truth = refined, ++kt.icp;
            else
                ++kt.seed_only;
        }
        kt.est.push_back(CPose2D(pdf->getMeanVal()));
        kt.truth.push_back(truth);
        kt.scans.push_back(scanEndpoints(pts));
    }
    return kt;
}

void intelPairs(const fs::path& data, std::vector<RealPair>& out, std::vector<std::string>* skipped)
{
    const fs::path ref_file = data / "radish/intel-corrected_ref.yaml";
    const fs::path map_file = data / "slam_maps/intel_icp-slam_app-final.yaml";
    const fs::path sm_file = data / "slam_maps/intel_icp-slam.simplemap";
    RealPair p;
    p.name = "intel_vs_icp_slam";
    p.family = "radish";
    p.gt_file = ref_file.string();
    p.map_file = map_file.string();
    p.gt = loadGrid(ref_file);
    p.map = loadGrid(map_file);
    KeyframeTruth kt = intelKeyframeTruth(data, sm_file, p.gt);
    const std::size_t n = kt.est.size();
    setKeyframeTruth(p, std::move(kt.est), std::move(kt.truth), kt.scans);
    p.truth.source = "keyframe poses: " + std::to_string(n) +
                     " SLAM keyframes (per point, the ones whose scans drew the obstacles nearest "
                     "to it); true pose from the corrected log for " +
                     std::to_string(kt.exact) +
                     ", odometry-seeded ICP against the reference map for " +
                     std::to_string(kt.icp) + ", seed only for " + std::to_string(kt.seed_only) +
                     " (timestamps of the two logs do not agree)";
    out.push_back(std::move(p));
    note(skipped,
         "intel_corrected_icp_slam (slam_maps/intel-corrected_icp-slam_app-final): no keyframes "
         "of that run are stored, so no per-keyframe truth; a sheared map has no single "
         "transform");
}

// ---------------------------------------------------------------------------------------------
// Radish logs mapped by topoeval's ICP-SLAM: per-keyframe truth from the corrected poses.

/** The Radish logs whose odometry is the corrected trajectory (data README), mapped by the
 * ICP-SLAM of `topoeval rawlog` with its default configuration: real scans and a real SLAM
 * system's errors, drawn from poses that start right and drift only by scan matching. The
 * reference maps are drawn from the same corrected poses, in their frame. Each keyframe's scan
 * is a scan of the log (found by its ranges), whose odometry is its true pose; a map point is
 * placed by the keyframes whose scans drew the obstacles nearest to it, as for Intel. The
 * maps are made when the validator runs (a few seconds each), so only when `wanted`. */
void radishSlamPairs(const fs::path& data, std::vector<RealPair>& out,
                     const std::function<bool(const std::string&)>& wanted,
                     std::vector<std::string>* skipped)
{
    for (const std::string log_name : {"aces", "csail", "freiburg-101", "intel"})
    {
        std::string name = log_name + "_rawlog_icp_slam";
        name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
        if (wanted && !wanted(name)) continue;
        const fs::path ref_file = data / "radish" / (log_name + "-corrected_ref.yaml");
        const fs::path log_file = data / "rawlogs" / (log_name + "-corrected.rawlog");
        try
        {
            RealPair p;
            p.name = name;
            p.family = "radish";
            p.gt_file = ref_file.string();
            p.map_file = log_file.string() + " (ICP-SLAM, topoeval rawlog's default configuration)";
            p.gt = loadGrid(ref_file);
            RawlogScorerOptions o;
            o.every_scans = std::numeric_limits<std::size_t>::max();  // the final map only
            RawlogScoreResult res = RawlogScorer(o, Parameters()).run(log_file.string(), p.gt);
            // A log read only in part would be scored as if it were the whole run.
            if (res.stop != RawlogStop::EndOfFile) throw std::runtime_error(res.stop_message);
            p.map = std::move(res.final_grid);
            const std::vector<RawScan> scans = readScans(log_file);
            std::vector<CPose2D> est, truth;
            std::vector<Points> local;
            int hint = 0, missing = 0;
            for (std::size_t k = 0; k < res.final_keyframes.size(); ++k)
            {
                const auto& [pdf, sf] = res.final_keyframes.get(k);
                const auto scan = sf->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
                const int r = scan ? findScan(scans, *scan, hint) : -1;
                if (r < 0)
                {
                    ++missing;
                    continue;
                }
                hint = r;
                est.push_back(CPose2D(pdf->getMeanVal()));
                truth.push_back(scans[r].odometry);
                mrpt::maps::CSimplePointsMap pts;
                pts.insertObservation(*scan);
                local.push_back(scanEndpoints(pts));
            }
            if (est.empty()) throw std::runtime_error("no keyframe's scan found in the log");
            const std::size_t n = est.size();
            setKeyframeTruth(p, std::move(est), std::move(truth), local);
            p.truth.source =
                "keyframe poses: " + std::to_string(n) + " ICP-SLAM keyframes of " +
                std::to_string(res.stats.scans) +
                " scans (per point, the ones whose scans drew the obstacles nearest "
                "to it), each true pose the corrected pose of its scan" +
                (missing ? "; " + std::to_string(missing) + " keyframes not found" : std::string());
            out.push_back(std::move(p));
        }
        catch (const std::exception& e)
        {
            // Its files there but the pair not made is a failure of the instrument, not a
            // missing input: the run stops (else the floors of its ctest would check nothing).
            if (fs::exists(ref_file) && fs::exists(log_file))
                throw std::runtime_error(name + ": " + e.what());
            note(skipped, name + ": " + e.what());
        }
    }
}
}  // namespace

std::vector<RealBuilding> loadRealBuildings(const std::string& data_dir,
                                            std::vector<std::string>* skipped)
{
    std::vector<RealBuilding> out;
    const fs::path data(data_dir);
    if (!fs::is_directory(data)) return out;
    const auto add = [&](const std::string& name, const std::string& family, const fs::path& file,
                         double resolution_m)
    {
        try
        {
            out.push_back({name, family, file.string(), loadGrid(file, resolution_m)});
        }
        catch (const std::exception& e)
        {
            note(skipped, name + ": " + e.what());
        }
    };
    for (const std::string radish : {"aces", "csail", "freiburg-079", "freiburg-101", "intel"})
        add("radish_" + radish, "radish", data / "radish" / (radish + "-corrected_ref.yaml"), 0.05);
    for (const auto& [name, res] : floorplanNames())
        add("floorplan_" + name, "floorplan", data / "floorplans" / (name + ".png"), res);
    add("gh25", "gh25", data / "rawlogs/gh25_gt_trinary_res0.05.yaml", 0.05);
    add("house", "house", data / "house/house_gt_trinary_res0.05.yaml", 0.05);
    add("gazebo_office", "gazebo", data / "gazebo_slam/office/office_ground_truth.yaml", 0.05);
    for (const std::string env : {"HIH", "KPT4A"})
        add("halmstad_" + env, "halmstad", halmstadLayout(data, env), 0.02);
    return out;
}

std::vector<RealPair> loadRealPairs(const std::string& data_dir, std::vector<std::string>* skipped,
                                    const std::function<bool(const std::string&)>& wanted)
{
    std::vector<RealPair> out;
    const fs::path data(data_dir);
    if (!fs::is_directory(data)) return out;
    // One family failing (a file missing or unreadable) leaves the others.
    const auto family = [&](const std::string& what, const auto& load)
    {
        try
        {
            load();
        }
        catch (const std::exception& e)
        {
            note(skipped, what + ": " + e.what());
        }
    };
    family("gh25", [&] { gh25Pair(data, out); });
    family("house", [&] { housePairs(data, out); });
    family("gazebo", [&] { gazeboPairs(data, out); });
    family("floorplan", [&] { floorplanPairs(data, out, skipped); });
    family("halmstad", [&] { halmstadPairs(data, out, skipped); });
    family("intel", [&] { intelPairs(data, out, skipped); });
    radishSlamPairs(data, out, wanted, skipped);
    for (RealPair& p : out)
        if (p.family != "gazebo") appendCheck(p);
    note(skipped,
         "office_tb3: the drawn plan and the SLAM map share no frame and no truth is "
         "published (different resolutions); only a matcher could align them");
    note(skipped,
         "intel_rbpf-slam_broken (final and snapshots): a diverged RBPF run with no "
         "stored poses, so no truth without the matcher");
    return out;
}
}  // namespace mrpt_topoeval::validation
