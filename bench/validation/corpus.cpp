/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "corpus.h"

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "buildings.h"
#include "slam_sim.h"
#include "synthetic_maps.h"

namespace mrpt_topoeval::validation
{
namespace
{
/** Whether the real pair NAME becomes a case: quick, only four small ones, one of each kind of
 * truth but keypoints; and its id must contain `only`. */
bool realPairWanted(const CorpusOptions& opts, const std::string& name)
{
    static const std::vector<std::string> quick_pairs = {
        "gh25_vs_icp_slam", "house_6ccdcaa_vs_2333d24", "gazebo_gmapping",
        "floorplan_office_a_furnished"};
    if (opts.quick && std::find(quick_pairs.begin(), quick_pairs.end(), name) == quick_pairs.end())
        return false;
    return opts.only.empty() || ("real/" + name).find(opts.only) != std::string::npos;
}

/** A seed per (corpus seed, ground truth, variant): stable when cases are added elsewhere. */
std::uint32_t caseSeed(std::uint32_t seed, const std::string& id)
{
    std::uint32_t h = 2166136261u ^ seed;  // FNV-1a
    for (unsigned char ch : id) h = (h ^ ch) * 16777619u;
    return h;
}

void addVariants(Corpus& corpus, std::size_t gi, std::size_t other, bool generated, bool quick,
                 std::uint32_t seed)
{
    const GroundTruthMap& g = corpus.ground_truths[gi];
    auto add = [&](const std::string& kind, const std::string& suffix, double param,
                   const std::string& ladder = {}, int severity = -1)
    {
        CaseSpec c;
        c.id = g.name + "/" + kind + suffix;
        c.building = g.name;
        c.family = g.family;
        c.source = generated ? "generated" : "real_map";
        c.kind = kind;
        c.ladder = ladder;
        c.severity = severity;
        c.param = param;
        c.seed = caseSeed(seed, c.id);
        c.gt = gi;
        c.other = other;
        corpus.cases.push_back(c);
    };
    const double res = g.grid.getResolution();
    add("identical", "", 0.0, "breaks", 0);
    const int rigid_n = generated ? 2 : 1;
    for (int i = 1; i <= rigid_n; ++i)
        add("rigid", "_" + std::to_string(i),
            mrpt::RAD2DEG(std::remainder(
                randomRigid(caseSeed(seed, g.name + "/rigid_" + std::to_string(i))).yaw_rad,
                2 * M_PI)));
    if (res < 0.099) add("resample", "_0.10", 0.10);
    if (generated) add("resample", "_x1.37", res * 1.37);
    add("scaled", "_1.05", 1.05);
    if (generated) add("scaled", "_0.97", 0.97);
    add("speckle", "", 0.15);
    if (generated) add("gaps", "", 0.5);
    add("ragged", "", 2.0);
    if (generated) add("crop", "_0.75", 0.75);
    add("crop", "_0.50", 0.50);
    for (int b = 1; b <= 3; ++b) add("broken", "_" + std::to_string(b), b, "breaks", b);
    if (generated) add("furniture", "", 0.06);
    if (generated && !g.tour.empty())
        for (int level = 1; level <= 3; ++level)
            add("slam", "_" + std::to_string(level), level, "slam", level);
    if (other != gi) add("different", "", 0.0);
    (void)quick;
}
}  // namespace

Corpus buildCorpus(const CorpusOptions& opts)
{
    Corpus corpus;
    corpus.chained_breaks = opts.chained_breaks;
    if (opts.chained_breaks)
        corpus.notes.push_back("broken maps: parts turned in a chain (--chained-breaks)");
    // Generated buildings: every style with four seeds (quick: two standard styles, one seed
    // each).
    const auto standard = buildingStyles();
    const auto styles = opts.styles.empty() ? standard : opts.styles;
    if (!opts.styles.empty())
    {
        std::string list;
        for (const auto& style : styles) list += (list.empty() ? "" : ", ") + style;
        corpus.notes.push_back("building styles: " + list + " (--styles)");
    }
    std::vector<std::pair<std::string, std::uint32_t>> wanted;
    if (opts.quick)
        wanted = {{standard[0], opts.seed * 1000 + 1}, {standard[2], opts.seed * 1000 + 1}};
    else
        for (const auto& style : styles)
            for (std::uint32_t k = 1; k <= 4; ++k) wanted.emplace_back(style, opts.seed * 1000 + k);
    for (const auto& [style, s] : wanted)
    {
        Building b = makeBuilding(style, s);
        GroundTruthMap g;
        g.name = b.name;
        g.family = b.style;
        g.file = "(generated)";
        g.generated = true;
        g.grid = std::move(b.grid);
        g.tour = std::move(b.tour);
        corpus.ground_truths.push_back(std::move(g));
    }
    const std::size_t n_generated = corpus.ground_truths.size();

    const bool have_data =
        opts.real && !opts.data_dir.empty() && std::filesystem::is_directory(opts.data_dir);
    if (opts.real && !have_data)
        corpus.notes.push_back("real data: " +
                               (opts.data_dir.empty() ? std::string("no folder given")
                                                      : opts.data_dir + " is absent") +
                               ": generated buildings only");
    if (have_data)
    {
        std::vector<std::string> skipped;
        if (!opts.quick)
            for (auto& rb : loadRealBuildings(opts.data_dir, &skipped))
            {
                GroundTruthMap g;
                g.name = rb.name;
                g.family = rb.family;
                g.file = rb.file;
                g.grid = std::move(rb.grid);
                corpus.ground_truths.push_back(std::move(g));
            }
        corpus.real_pairs =
            loadRealPairs(opts.data_dir, &skipped,
                          [&](const std::string& name) { return realPairWanted(opts, name); });
        for (const auto& s : skipped) corpus.notes.push_back("skipped: " + s);
    }

    // Variants. "different": the next ground truth of the same family if there is one (a
    // building of the same style is the hard case), else the next one at all.
    const std::size_t n = corpus.ground_truths.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        const bool generated = i < n_generated;
        std::size_t other = i;
        const std::size_t lo = generated ? 0 : n_generated, hi = generated ? n_generated : n;
        for (std::size_t k = 1; k < hi - lo && other == i; ++k)
        {
            const std::size_t j = lo + (i - lo + k) % (hi - lo);
            if (corpus.ground_truths[j].family == corpus.ground_truths[i].family) other = j;
        }
        if (other == i && hi - lo > 1) other = lo + (i - lo + 1) % (hi - lo);
        addVariants(corpus, i, other, generated, opts.quick, opts.seed);
    }
    // Near-twins ("twin"): the unit tests' campus (tests/support, makeCampusMap) with three
    // seeds, each against the next. One style, one corridor width, one room rule; only the
    // corridors' spacing (7.5-14 m) and the rooms differ. Different buildings that share a
    // building code: the hard case for "never trust a wrong pair". Ground truths of their own,
    // with no other variants (their figures stay out of the other kinds').
    if (!opts.quick)
    {
        const std::size_t first = corpus.ground_truths.size();
        for (std::uint32_t k = 1; k <= 3; ++k)
        {
            GroundTruthMap g;
            g.name = "campus_" + std::to_string(opts.seed * 1000 + k);
            g.family = "campus";
            g.file = "(generated: tests/support makeCampusMap)";
            g.generated = true;
            g.grid = testing::makeCampusMap(opts.seed * 1000 + k);
            corpus.ground_truths.push_back(std::move(g));
        }
        for (std::size_t k = 0; k < 3; ++k)
        {
            const GroundTruthMap& g = corpus.ground_truths[first + k];
            CaseSpec c;
            c.id = g.name + "/twin";
            c.building = g.name;
            c.family = g.family;
            c.source = "generated";
            c.kind = "twin";
            c.seed = caseSeed(opts.seed, c.id);
            c.gt = first + k;
            c.other = first + (k + 1) % 3;
            corpus.cases.push_back(c);
        }
    }
    for (std::size_t p = 0; p < corpus.real_pairs.size(); ++p)
    {
        const RealPair& rp = corpus.real_pairs[p];
        if (opts.quick && !realPairWanted(opts, rp.name)) continue;
        CaseSpec c;
        c.id = "real/" + rp.name;
        c.building = rp.name;
        c.family = rp.family;
        c.source = "real_pair";
        c.kind = "real";
        c.real_pair = static_cast<int>(p);
        corpus.cases.push_back(c);
    }
    return corpus;
}

const mrpt::maps::COccupancyGridMap2D& groundTruthOf(const Corpus& corpus, const CaseSpec& c)
{
    if (c.real_pair >= 0) return corpus.real_pairs[static_cast<std::size_t>(c.real_pair)].gt;
    return corpus.ground_truths[c.gt].grid;
}

Variant makeCaseMap(const Corpus& corpus, const CaseSpec& c)
{
    if (c.real_pair >= 0)
    {
        const RealPair& rp = corpus.real_pairs[static_cast<std::size_t>(c.real_pair)];
        return {rp.map, rp.truth};
    }
    const GroundTruthMap& g = corpus.ground_truths[c.gt];
    const auto& grid = g.grid;
    if (c.kind == "identical") return makeIdentical(grid);
    if (c.kind == "rigid")
    {
        const Rigid2D r = randomRigid(c.seed);
        return makeRigid(grid, r.yaw_rad, r.t_m);
    }
    if (c.kind == "resample") return makeResampled(grid, c.param);
    if (c.kind == "scaled")
    {
        const Rigid2D r = randomRigid(c.seed);
        return makeScaled(grid, c.param, r.yaw_rad, r.t_m);
    }
    if (c.kind == "speckle") return makeSpeckled(grid, c.param, 0.03, c.seed);
    if (c.kind == "gaps") return makeWallGaps(grid, c.param, c.seed);
    if (c.kind == "ragged") return makeRagged(grid, static_cast<int>(c.param), c.seed);
    if (c.kind == "crop") return makeCrop(grid, c.param, c.seed);
    if (c.kind == "broken")
        return makeBroken(grid, static_cast<int>(c.param), c.seed, corpus.chained_breaks);
    if (c.kind == "furniture") return makeFurnished(grid, c.param, c.seed);
    if (c.kind == "slam")
    {
        SlamRun run = simulateIcpSlam(grid, g.tour, static_cast<int>(c.param), c.seed);
        Variant v;
        v.map = std::move(run.map);
        v.truth.mapping = run.truth;
        v.truth.source =
            "keyframe poses (" + std::to_string(run.true_keyframes.size()) +
            " keyframes, odometry drift " + fmt(run.odometry_drift_m, 2) + " m" +
            (run.restarted_at_waypoint > 0
                 ? "; restarted at waypoint " + std::to_string(run.restarted_at_waypoint) + ", " +
                       std::to_string(run.first_start_keyframes) +
                       " keyframes from the tour's start"
                 : std::string()) +
            ")";
        v.truth.wall_tolerance_m = 0.15;
        return v;
    }
    if (c.kind == "different" || c.kind == "twin")
    {
        const Rigid2D r = randomRigid(c.seed);
        Variant v = makeRigid(corpus.ground_truths[c.other].grid, r.yaw_rad, r.t_m);
        v.truth = Truth{};
        v.truth.different_building = true;
        v.truth.source = "another building: " + corpus.ground_truths[c.other].name;
        return v;
    }
    throw std::invalid_argument("unknown case kind '" + c.kind + "'");
}
}  // namespace mrpt_topoeval::validation
