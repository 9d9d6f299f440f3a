/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Paper III-A, second approach: vertex similarity by ICP on the obstacles around each vertex.
//
// Each vertex's obstacle cells within icp_radius_m become a point cloud in coordinates relative
// to the vertex, so two clouds start with their vertices on top of each other and mainly the
// rotation is unknown. The paper starts ICP from 12 angles; here the start angles come from the
// two vertices' rings of edges (the d rotations that lay one ring of d edges onto the other),
// pairs whose degrees differ are not aligned at all, and of the d starts ICP runs only from
// those that begin about as well as the best (usually one). Clouds and KD-trees are built once
// per vertex; vertex rows are shared out to threads.
//
// Cost on the Intel lab pair (116 x 44 vertices): about 0.8 s of CPU time, split over the
// threads (README, "Performance"), against "typically less than one minute" in the paper.

#include <mrpt/core/cpu.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/maps/metric_map_types.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPosePDF.h>
#include <mrpt/slam/CICP.h>
#include <mrpt/tfest/TMatchingPair.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

#include "common/clock.h"
#include "common/threads.h"
#include "graph/MatchView.h"

namespace mrpt_topoeval
{
namespace
{
using internal::Clock;
using internal::MatchView;
using internal::msSince;
using internal::ViewVertex;
using mrpt::maps::COccupancyGridMap2D;
using mrpt::maps::CSimplePointsMap;
/** Fewer obstacle points than this carry no shape to align: the pair gets 0. */
constexpr std::size_t kMinCloudPoints = 3;
/** The moving cloud of ICP is thinned on a coarser cell lattice until it has at most this
 * many points: ICP's cost is one KD-tree query per moving point and iteration, while the
 * reference cloud stays complete (its size costs only a logarithm). */
constexpr std::size_t kMaxMovingPoints = 200;
/** Two start angles closer than this are run once [rad]. */
constexpr double kSameStartRad = 5.0 * M_PI / 180.0;
/** CICP iteration budget per start. Classic ICP on grid cells rarely meets its 1e-6 step
 * criterion (correspondences flip between neighbouring cells), so each run spends the whole
 * budget at the first threshold and then halves it once per iteration. 20 instead of CICP's
 * 40 halved the cost with the same best partners on the office and Intel test pairs. */
constexpr unsigned kIcpMaxIterations = 20;
/** Before running ICP, each seed start is rated by how many of b's points lie within this of
 * a's cloud at the start pose (half of ICP's first correspondence distance) [m]. */
constexpr double kRankingDist_m = 0.375;
/** ICP runs only from the starts whose rating is at least this fraction of the best one's: a
 * degree-3 pair then usually needs one run instead of three, with the same best partners on
 * the office and Intel test pairs (measured). */
constexpr double kCompetingStartRatio = 0.9;
/** A start whose alignment scores at least this ends the search for the pair: later starts
 * could only add a few hundredths. */
constexpr double kGoodEnoughScore = 0.95;

double wrapToPi(double a) { return std::atan2(std::sin(a), std::cos(a)); }

/** One vertex's obstacles, relative to the vertex position. */
struct VertexCloud
{
    /** Every obstacle cell within the radius: the reference side of matching, with KD-tree. */
    CSimplePointsMap full;
    /** At most kMaxMovingPoints of them, spread evenly: the moving side. */
    CSimplePointsMap thinned;
    bool usable = false;
};

/** The occupied cells (P(occupied) >= occupied_min_prob, the GraphBuilder's obstacle rule)
 * within `radius_m` of `centre`, relative to `centre`. Loops over the cells itself:
 * getAsPointCloud() only returns walls bordering free space. */
void buildCloud(const COccupancyGridMap2D& grid, const Eigen::Vector2d& centre, double radius_m,
                float max_free_prob, VertexCloud& out)
{
    const double res = grid.getResolution();
    const int sx = static_cast<int>(grid.getSizeX());
    const int sy = static_cast<int>(grid.getSizeY());
    const auto& raw = grid.getRawMap();
    // Cell index of a coordinate, clamped in floating point first so a huge radius cannot
    // overflow the conversion.
    auto cellIndex = [res](double v, double v_min, int n)
    {
        const double c = std::floor((v - v_min) / res);
        return static_cast<int>(std::clamp(c, -1.0, static_cast<double>(n)));
    };
    const int cx0 = std::max(0, cellIndex(centre.x() - radius_m, grid.getXMin(), sx));
    const int cx1 = std::min(sx - 1, cellIndex(centre.x() + radius_m, grid.getXMin(), sx));
    const int cy0 = std::max(0, cellIndex(centre.y() - radius_m, grid.getYMin(), sy));
    const int cy1 = std::min(sy - 1, cellIndex(centre.y() + radius_m, grid.getYMin(), sy));
    const double r2 = radius_m * radius_m;

    std::vector<float> xs, ys;
    for (int cy = cy0; cy <= cy1; ++cy)
    {
        const double dy = grid.idx2y(cy) - centre.y();
        for (int cx = cx0; cx <= cx1; ++cx)
        {
            if (COccupancyGridMap2D::l2p(
                    raw[static_cast<std::size_t>(cx) + static_cast<std::size_t>(cy) * sx]) >
                max_free_prob)
                continue;
            const double dx = grid.idx2x(cx) - centre.x();
            if (dx * dx + dy * dy > r2) continue;
            xs.push_back(static_cast<float>(dx));
            ys.push_back(static_cast<float>(dy));
        }
    }
    out.full.setAllPoints(xs, ys);
    out.usable = xs.size() >= kMinCloudPoints;

    // Thinning: keep the first point in each cell of a lattice k times coarser than the grid,
    // anchored at the vertex (so the result depends on the cloud alone). A lattice cell holds
    // at most k^2 points, so k below sqrt(n / cap) cannot meet the cap: start there.
    std::vector<float> tx = xs, ty = ys;
    float extent = 0.0f;  // the points' reach, not the radius: a huge radius is cut by the grid
    for (std::size_t i = 0; i < xs.size(); ++i)
        extent = std::max({extent, std::abs(xs[i]), std::abs(ys[i])});
    int k = std::max(
        2,
        static_cast<int>(std::floor(std::sqrt(static_cast<double>(xs.size()) / kMaxMovingPoints))));
    for (; tx.size() > kMaxMovingPoints; ++k)
    {
        const double cell = k * res;
        const int half = static_cast<int>(std::ceil(extent / cell)) + 1;
        const int width = 2 * half;
        std::vector<char> taken(static_cast<std::size_t>(width) * width, 0);
        tx.clear();
        ty.clear();
        for (std::size_t i = 0; i < xs.size(); ++i)
        {
            const int ix = static_cast<int>(std::floor(xs[i] / cell)) + half;
            const int iy = static_cast<int>(std::floor(ys[i] / cell)) + half;
            char& t = taken[static_cast<std::size_t>(iy) * width + ix];
            if (t) continue;
            t = 1;
            tx.push_back(xs[i]);
            ty.push_back(ys[i]);
        }
    }
    out.thinned.setAllPoints(tx, ty);

    // Build the lazy caches now, in this thread: the clouds are then only read by the workers
    // (the KD-tree has its own lock, but the bounding box cache of CPointsMap has none).
    if (out.usable)
    {
        out.full.kdTreeEnsureIndexBuilt2D();
        out.full.boundingBox();
        out.thinned.boundingBox();
    }
}

/** The radius of a vertex's cloud: icp_radius_m, but reaching at least a third of it beyond
 * the vertex's clearance. A vertex in the middle of a big room is farther than icp_radius_m
 * from every wall; with the plain radius its cloud would be empty and the vertex unmatchable. */
double cloudRadius(const TopoVertex& v, double icp_radius_m)
{
    return std::max(icp_radius_m, v.clearance_m + icp_radius_m / 3.0);
}

/** Rotations of b's frame into a's (A_pt ~ R(phi) B_pt) to start ICP from. */
std::vector<double> startAngles(const ViewVertex& va, const ViewVertex& vb, int n_even)
{
    const int da = va.degree();
    const int db = vb.degree();
    std::vector<double> cand;
    if (da > 0 && da == db)
    {
        // For each cyclic shift k of the ring (edge j of a <-> edge j+k of b), the rotation
        // that best lays b's edge directions onto a's: the circular mean of the differences.
        for (int k = 0; k < da; ++k)
        {
            double s = 0.0, c = 0.0;
            for (int j = 0; j < da; ++j)
            {
                const double d = va.ring[j].angle_rad - vb.ring[(j + k) % da].angle_rad;
                s += std::sin(d);
                c += std::cos(d);
            }
            if (std::hypot(s, c) < 1e-6 * da) continue;  // differences cancel: no direction
            cand.push_back(std::atan2(s, c));
        }
    }
    else if (da > 0 && db > 0)
    {
        // Unequal degrees (allowed by icp_max_degree_difference): every single-edge pairing,
        // unless that is more than the paper's evenly spread starts.
        for (const auto& ia : va.ring)
            for (const auto& ib : vb.ring) cand.push_back(wrapToPi(ia.angle_rad - ib.angle_rad));
        if (cand.size() > static_cast<std::size_t>(n_even)) cand.clear();
    }

    std::vector<double> starts;
    for (double a : cand)
    {
        const bool dup =
            std::any_of(starts.begin(), starts.end(),
                        [a](double b) { return std::abs(wrapToPi(a - b)) < kSameStartRad; });
        if (!dup) starts.push_back(a);
    }
    if (starts.empty())
    {
        // No ring to go by (degree 0, or rings whose directions cancel): the paper's evenly
        // spaced start angles.
        for (int i = 0; i < n_even; ++i) starts.push_back(wrapToPi(2.0 * M_PI * i / n_even));
    }
    return starts;
}

/** Coverage and error of one alignment, measured both ways at `match_dist_m`. */
struct Alignment
{
    double goodness = 0.0;  //!< Mean of the two clouds' fractions of points with a partner.
    double rmse_m = 0.0;    //!< RMS distance of all matched points, both directions.
    double score = 0.0;
};

/** How well b's cloud, placed at T_a_b in a's frame, fits a's cloud, and the other way. */
Alignment evaluate(const VertexCloud& a, const VertexCloud& b, const mrpt::poses::CPose2D& T_a_b,
                   double match_dist_m, double rmse_tolerance_m)
{
    mrpt::maps::TMatchingParams mp;
    mp.maxDistForCorrespondence = static_cast<float>(match_dist_m);
    mp.maxAngularDistForCorrespondence = 0.0f;
    mp.onlyKeepTheClosest = true;
    mp.decimation_other_map_points = 1;
    mrpt::tfest::TMatchingPairList corrs;
    mrpt::maps::TMatchingExtraResults extra;

    double sum_sq = 0.0;
    std::size_t matched = 0;
    auto oneWay = [&](const VertexCloud& ref, const VertexCloud& moving,
                      const mrpt::poses::CPose2D& T_ref_moving)
    {
        ref.full.determineMatching2D(&moving.thinned, T_ref_moving, corrs, mp, extra);
        for (const auto& c : corrs) sum_sq += c.errorSquareAfterTransformation;
        matched += corrs.size();
        return static_cast<double>(corrs.size()) / static_cast<double>(moving.thinned.size());
    };
    const double f_b = oneWay(a, b, T_a_b);
    const double f_a = oneWay(b, a, -T_a_b);

    Alignment r;
    r.goodness = 0.5 * (f_a + f_b);
    r.rmse_m = matched > 0 ? std::sqrt(sum_sq / static_cast<double>(matched)) : match_dist_m;
    // The similarity (paper III-A: "the lowest mean squared error ... is used to calculate the
    // similarity"):
    //   s = goodness * max(0, 1 - rmse / icp_rmse_tolerance_m)
    // goodness alone would rate a short wall that fits anywhere on a long one as perfect, and
    // the error alone would rate a few well-matched points as perfect.
    r.score = r.goodness * std::max(0.0, 1.0 - r.rmse_m / rmse_tolerance_m);
    return r;
}

/** Everything the workers share, read-only. */
struct Job
{
    const MatchView* view_a = nullptr;
    const MatchView* view_b = nullptr;
    const std::vector<VertexCloud>* clouds_a = nullptr;
    const std::vector<VertexCloud>* clouds_b = nullptr;
    const VertexSimilarityParameters* p = nullptr;
    mrpt::slam::CICP::TConfigParams icp_options;
    double match_dist_m = 0.0;
};

/** The seed start angles ordered by how much of b's cloud lies near a's cloud before any
 * iteration (ties keep the seed order), with those counts. */
std::vector<std::pair<double, std::size_t>> rankStarts(const VertexCloud& ca, const VertexCloud& cb,
                                                       const std::vector<double>& starts)
{
    mrpt::maps::TMatchingParams mp;
    mp.maxDistForCorrespondence = static_cast<float>(kRankingDist_m);
    mp.maxAngularDistForCorrespondence = 0.0f;
    mp.onlyKeepTheClosest = true;
    mrpt::tfest::TMatchingPairList corrs;
    mrpt::maps::TMatchingExtraResults extra;
    std::vector<std::pair<double, std::size_t>> ranked;
    for (double phi : starts)
    {
        ca.full.determineMatching2D(&cb.thinned, mrpt::poses::CPose2D(0.0, 0.0, phi), corrs, mp,
                                    extra);
        ranked.emplace_back(phi, corrs.size());
    }
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const auto& x, const auto& y) { return x.second > y.second; });
    return ranked;
}

/** The ICP similarity of a's vertex i and b's vertex j (0 for pruned pairs). */
double pairSimilarity(const Job& job, mrpt::slam::CICP& icp, std::size_t i, std::size_t j)
{
    const ViewVertex& va = job.view_a->v[i];
    const ViewVertex& vb = job.view_b->v[j];
    if (!va.active || !vb.active) return 0.0;
    if (std::abs(va.degree() - vb.degree()) > job.p->icp_max_degree_difference) return 0.0;
    const VertexCloud& ca = (*job.clouds_a)[i];
    const VertexCloud& cb = (*job.clouds_b)[j];
    if (!ca.usable || !cb.usable) return 0.0;

    const auto ranked = rankStarts(ca, cb, startAngles(va, vb, job.p->icp_start_angles));
    double best = 0.0;
    for (const auto& [phi, overlap] : ranked)
    {
        // Starts that begin clearly worse than the best one converge, if at all, to the same
        // alignment or a worse one: skip them (the paper's "lowest error of the runs" is kept
        // among the starts that compete).
        if (static_cast<double>(overlap) < kCompetingStartRatio * ranked.front().second) break;
        // A = ground-truth vertex's cloud (reference), B = map vertex's cloud (moving); the
        // result is B's pose in A's frame.
        mrpt::slam::CICP::TReturnInfo info;
        const auto pdf =
            icp.Align(&ca.full, &cb.thinned, mrpt::poses::CPose2D(0.0, 0.0, phi), info);
        const Alignment al =
            evaluate(ca, cb, pdf->getMeanVal(), job.match_dist_m, job.p->icp_rmse_tolerance_m);
        best = std::max(best, al.score);
        if (best >= kGoodEnoughScore) break;
    }
    return best;
}

void requireGrid(const COccupancyGridMap2D& grid, const TopologyGraph& g, const char* name)
{
    if (g.vertices.empty()) return;
    const double res = grid.getResolution();
    if (!(std::isfinite(res) && res > 0.0) || grid.getSizeX() == 0 || grid.getSizeY() == 0)
    {
        std::ostringstream os;
        os << "icpSimilarity: " << name << " has " << g.vertices.size()
           << " vertices but its grid is empty (size " << grid.getSizeX() << " x "
           << grid.getSizeY() << ", resolution " << res << ")";
        throw InputError(os.str());
    }
    for (const TopoVertex& v : g.vertices)
    {
        if (!v.position_m.allFinite())
        {
            std::ostringstream os;
            os << "icpSimilarity: " << name << " vertex " << v.id << " has a non-finite position";
            throw InputError(os.str());
        }
    }
}

}  // namespace

SimilarityMatrix icpSimilarity(const TopologyGraph& a, const COccupancyGridMap2D& grid_a,
                               const TopologyGraph& b, const COccupancyGridMap2D& grid_b,
                               const VertexSimilarityParameters& p,
                               std::map<std::string, double>* timing_ms)
{
    const auto t_start = Clock::now();
    p.validate();
    requireGrid(grid_a, a, "graph a");
    requireGrid(grid_b, b, "graph b");

    const std::size_t na = a.vertices.size();
    const std::size_t nb = b.vertices.size();
    SimilarityMatrix s =
        SimilarityMatrix::Zero(static_cast<Eigen::Index>(na), static_cast<Eigen::Index>(nb));
    const MatchView view_a = internal::makeMatchView(a);
    const MatchView view_b = internal::makeMatchView(b);

    // Clouds once per vertex (not per pair), only for vertices that take part.
    const float max_free_prob =
        static_cast<float>(1.0 - GraphBuilderParameters{}.occupied_min_prob);
    std::vector<VertexCloud> clouds_a(na), clouds_b(nb);
    for (std::size_t i = 0; i < na; ++i)
        if (view_a.v[i].active)
            buildCloud(grid_a, a.vertices[i].position_m, cloudRadius(a.vertices[i], p.icp_radius_m),
                       max_free_prob, clouds_a[i]);
    for (std::size_t j = 0; j < nb; ++j)
        if (view_b.v[j].active)
            buildCloud(grid_b, b.vertices[j].position_m, cloudRadius(b.vertices[j], p.icp_radius_m),
                       max_free_prob, clouds_b[j]);
    const double ms_clouds = msSince(t_start);
    const auto t_icp = Clock::now();

    Job job;
    job.view_a = &view_a;
    job.view_b = &view_b;
    job.clouds_a = &clouds_a;
    job.clouds_b = &clouds_b;
    job.p = &p;
    // Cells of 0.05 m: correspondences start at 0.75 m (a basin of about +-30 deg, enough for
    // starts seeded from the edge directions) and halve down to two cells. No angular slack:
    // the clouds are small and centred on the vertex.
    const double coarse_res =
        std::max(na ? grid_a.getResolution() : 0.0, nb ? grid_b.getResolution() : 0.0);
    auto& o = job.icp_options;
    o.ICP_algorithm = mrpt::slam::icpClassic;
    o.maxIterations = kIcpMaxIterations;
    o.thresholdDist = 0.75;
    o.thresholdAng = 0.0;
    o.ALFA = 0.5;
    o.smallestThresholdDist = std::max(0.10, 2.0 * coarse_res);
    o.corresponding_points_decimation = 1;
    o.skip_cov_calculation = true;
    o.skip_quality_calculation = true;
    // Points count as matched within three cells of the coarser grid: walls drawn one cell
    // thick in one map and three in the other still match.
    job.match_dist_m = std::max(0.15, 3.0 * coarse_res);

    unsigned n_threads = internal::workerThreads(p.threads);
    n_threads =
        static_cast<unsigned>(std::min<std::size_t>(n_threads, std::max<std::size_t>(na, 1)));

    // Rows handed out by an atomic counter; each pair's value depends only on the pair, and is
    // written to its own element, so the matrix does not depend on the thread count.
    std::atomic<std::size_t> next_row{0};
    std::atomic<bool> failed{false};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto worker = [&]()
    {
        try
        {
            mrpt::slam::CICP icp(job.icp_options);
            for (std::size_t i = next_row++; i < na && !failed; i = next_row++)
                for (std::size_t j = 0; j < nb; ++j)
                    s(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
                        pairSimilarity(job, icp, i, j);
        }
        catch (...)
        {
            std::lock_guard<std::mutex> lock(error_mutex);
            if (!error) error = std::current_exception();
            failed = true;
        }
    };
    // MRPT's CPU-feature singleton (read by se2_l2 in every ICP iteration) is created here,
    // before the threads, so they only ever read it.
    [[maybe_unused]] const bool sse2 = mrpt::cpu::supports(mrpt::cpu::feature::SSE2);
    if (n_threads <= 1)
        worker();
    else
    {
        std::vector<std::thread> pool;
        pool.reserve(n_threads);
        for (unsigned t = 0; t < n_threads; ++t) pool.emplace_back(worker);
        for (auto& th : pool) th.join();
    }
    if (error) std::rethrow_exception(error);

    if (timing_ms)
    {
        (*timing_ms)["clouds"] = ms_clouds;
        (*timing_ms)["icp"] = msSince(t_icp);
        (*timing_ms)["total"] = msSince(t_start);
    }
    return s;
}

}  // namespace mrpt_topoeval
