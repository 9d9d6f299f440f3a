/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>

namespace mrpt_topoeval::validation
{
namespace
{
const double kNaN = std::numeric_limits<double>::quiet_NaN();
/** A broken case is exactly right when the found brokenness equals the injected one and every
 * group's rotation is within this of its part's (issue 11's "each group's rotation within 3
 * degrees") [deg]. */
constexpr double kExactRotationErrorDeg = 3.0;
/** A found part's offset (BrokennessGroup::offset_m) is right when within the larger of this
 * [m] (half the pair tolerance of the generated maps' vertices) ... */
constexpr double kOffsetToleranceM = 0.25;
/** ... and this share of the truth's offset (a part's turn fitted 0.5 degrees off moves its far
 * vertices by about 1 % of their distance from the pivot; 10 % leaves room for the vertices'
 * own jitter) [ratio]. */
constexpr double kOffsetToleranceShare = 0.10;

/** Issue 11: the right number of breaks, and each group turned as its part is. */
bool exactlyRight(const CaseScore& s)
{
    return s.brokenness_found == s.brokenness_injected &&
           !(s.max_group_rotation_error_deg > kExactRotationErrorDeg);
}

/** Every part holds 3 ground-truth vertices with a counterpart: its break is observable. */
bool observable(const CaseScore& s)
{
    return s.parts_with_3_counterparts >= s.brokenness_injected + 1;
}

/** A map of another building ("different", "twin"): no truth, every pair is false. */
bool otherBuilding(const std::string& kind) { return kind == "different" || kind == "twin"; }

const std::vector<std::string>& kindOrder()
{
    static const std::vector<std::string> k = {
        "identical", "rigid",  "resample",  "scaled", "speckle",   "gaps", "ragged",
        "crop",      "broken", "furniture", "slam",   "different", "twin"};
    return k;
}

std::string num(double v, int decimals = 3)
{
    if (!std::isfinite(v)) return "-";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::vector<double> ranks(const std::vector<double>& v)
{
    std::vector<std::size_t> idx(v.size());
    std::iota(idx.begin(), idx.end(), 0);
    std::stable_sort(idx.begin(), idx.end(), [&](auto a, auto b) { return v[a] < v[b]; });
    std::vector<double> r(v.size());
    for (std::size_t i = 0; i < idx.size();)
    {
        std::size_t j = i;
        while (j + 1 < idx.size() && v[idx[j + 1]] == v[idx[i]]) ++j;
        const double mean_rank = 0.5 * (static_cast<double>(i) + static_cast<double>(j)) + 1.0;
        for (std::size_t k = i; k <= j; ++k) r[idx[k]] = mean_rank;
        i = j + 1;
    }
    return r;
}
}  // namespace

double Aggregate::precision() const
{
    return matched ? static_cast<double>(true_pairs) / matched : kNaN;
}
double Aggregate::recall() const
{
    return counterparts ? static_cast<double>(true_pairs) / counterparts : kNaN;
}

std::string brokenCause(const CaseScore& s)
{
    if (exactlyRight(s)) return "";
    if (s.matched == 0)
        return observable(s) ? "nothing matched" : "nothing matched, a part not observable";
    if (s.brokenness_found > s.brokenness_injected) return "a break too many";
    if (s.max_group_rotation_error_deg > kExactRotationErrorDeg) return "a group turned wrong";
    std::set<int> represented;
    for (const auto& g : s.groups)
        if (g.part >= 0) represented.insert(g.part);
    std::set<std::string> causes;  // sorted, each once
    for (const auto& p : s.parts)
    {
        if (represented.count(p.part)) continue;
        if (p.counterparts < 3)
            causes.insert("a part not observable");
        else if (p.true_pairs == 0)
            causes.insert("a part unmatched");
        else if (p.true_pairs < 3)
            causes.insert("a part with 1-2 pairs");
        else
            causes.insert("a part inside another's group");
    }
    std::string out;
    for (const auto& c : causes) out += (out.empty() ? "" : " + ") + c;
    // Every part has a group and none is turned wrong: two groups of one part, one lost.
    return out.empty() ? "two groups of one part" : out;
}

void CropErrors::add(const std::string& id, double coverage, std::size_t kept, std::size_t at_cut,
                     std::size_t total)
{
    if (total == 0) return;  // no ground-truth vertex: no share
    ++crops;
    const double low = static_cast<double>(kept) / total,
                 high = static_cast<double>(kept + at_cut) / total;
    const double error = std::max({0.0, low - coverage, coverage - high});
    mean += (error - mean) / static_cast<double>(crops);  // running mean
    if (max_case.empty() || error > max) max = error, max_case = id;
    if (kept + at_cut >= 3)
    {
        ++observable;
        observable_within += error <= kCropCoverageTolerance ? 1 : 0;
        max_observable = std::max(max_observable, error);
    }
}

Aggregate aggregate(const std::string& name, const std::vector<const CaseResult*>& cases)
{
    Aggregate a;
    a.name = name;
    for (const CaseResult* r : cases)
    {
        ++a.cases;
        if (!r->error.empty())
        {
            ++a.errors;
            continue;
        }
        if (!r->spec.kind.empty() && !otherBuilding(r->spec.kind))
            a.truth_min = std::min(a.truth_min, r->truth_check.share());
        const CaseScore& s = r->score;
        a.matched += s.matched;
        a.true_pairs += s.true_pairs;
        if (s.matched == s.true_pairs) ++a.clean;
        a.counterparts += std::max(s.gt_with_counterpart, s.true_pairs);
        a.lost += s.lost;
        if (s.brokenness_injected >= 0 && r->spec.kind == "broken")
        {
            ++a.broken;
            const bool exact = exactlyRight(s);
            if (exact)
                ++a.broken_exact;
            else
                ++a.broken_causes[brokenCause(s)];
            if (s.parts_with_5_counterparts >= s.brokenness_injected + 1)
            {
                ++a.broken_measurable;
                if (exact) ++a.broken_measurable_exact;
            }
            if (observable(s))
            {
                ++a.broken_observable;
                if (exact) ++a.broken_observable_exact;
            }
            if (s.parts_with_3_kept >= s.brokenness_injected + 1)
            {
                ++a.broken_kept;
                if (exact) ++a.broken_kept_exact;
                if (!observable(s)) a.broken_kept_graph_lost.push_back(r->spec.id);
            }
            if (std::isfinite(s.max_group_rotation_error_deg))
                a.max_rotation_error_deg =
                    std::max(a.max_rotation_error_deg, s.max_group_rotation_error_deg);
            for (std::size_t g = 1; g < s.groups.size(); ++g)
                if (const double truth = s.groups[g].true_offset_m; std::isfinite(truth))
                {
                    const double err = std::abs(s.groups[g].offset_m - truth);
                    a.offset_errors_m.push_back(err);
                    a.offsets_within +=
                        err <= std::max(kOffsetToleranceM, kOffsetToleranceShare * truth) ? 1 : 0;
                }
        }
        a.mean_coverage += s.coverage;
        a.max_coverage = std::max(a.max_coverage, s.coverage);
        a.mean_quality += s.quality;
        if (std::isfinite(s.explained_walls))
        {
            a.mean_explained_walls += s.explained_walls;
            ++a.explained_measured;
        }
        a.mean_time_ms += r->time_ms;
        if (r->spec.kind == "crop" && s.gt_vertices)
        {
            a.crop_kept.add(r->spec.id, s.coverage, s.gt_kept, s.gt_at_cut, s.gt_vertices);
            a.crop_counterparts.add(r->spec.id, s.coverage, s.gt_with_counterpart, 0,
                                    s.gt_vertices);
        }
    }
    const std::size_t ok = a.cases - a.errors;
    if (ok)
    {
        a.mean_coverage /= ok;
        a.mean_quality /= ok;
        a.mean_time_ms /= ok;
    }
    a.mean_explained_walls =
        a.explained_measured ? a.mean_explained_walls / double(a.explained_measured) : kNaN;
    for (CropErrors* c : {&a.crop_kept, &a.crop_counterparts})
        if (c->crops == 0) c->mean = kNaN;
    return a;
}

double spearman(const std::vector<double>& a, const std::vector<double>& b)
{
    if (a.size() != b.size() || a.size() < 3) return kNaN;
    const auto ra = ranks(a), rb = ranks(b);
    const double n = static_cast<double>(a.size());
    const double ma = std::accumulate(ra.begin(), ra.end(), 0.0) / n;
    const double mb = std::accumulate(rb.begin(), rb.end(), 0.0) / n;
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < ra.size(); ++i)
    {
        sab += (ra[i] - ma) * (rb[i] - mb);
        saa += (ra[i] - ma) * (ra[i] - ma);
        sbb += (rb[i] - mb) * (rb[i] - mb);
    }
    if (saa <= 0 || sbb <= 0) return kNaN;
    return sab / std::sqrt(saa * sbb);
}

Summary summarize(const std::vector<CaseResult>& results)
{
    Summary s;
    std::vector<const CaseResult*> pooled, pooled_gen, real;
    std::map<std::string, std::vector<const CaseResult*>> by_family;
    for (const auto& kind : kindOrder())
    {
        std::vector<const CaseResult*> of_kind;
        for (const auto& r : results)
            if (r.spec.kind == kind) of_kind.push_back(&r);
        if (!of_kind.empty()) s.kinds.push_back(aggregate(kind, of_kind));
    }
    for (const auto& r : results)
    {
        if (r.spec.source == "real_pair")
        {
            real.push_back(&r);
            continue;
        }
        if (r.error.empty() && !otherBuilding(r.spec.kind) &&
            (r.truth_check.share() < 0.95 || r.truth_check.freeShare() < 0.95))
            ++s.truth_failures;
        if (otherBuilding(r.spec.kind)) continue;
        pooled.push_back(&r);
        if (r.spec.source == "generated") pooled_gen.push_back(&r);
        by_family[r.spec.family].push_back(&r);
    }
    s.pooled = aggregate("pooled", pooled);
    s.pooled_generated = aggregate("pooled generated", pooled_gen);
    for (const auto& [family, cases] : by_family) s.families.push_back(aggregate(family, cases));
    s.real = aggregate("real pairs", real);
    // Spearman per family and ladder, pooled over the family's buildings and within each.
    // Points of each building's ladder; the pooled ladder is their union (ranks do not depend on
    // the order of the points).
    struct Points
    {
        std::vector<double> damage;  // -severity: higher is less damaged
        std::vector<double> quality;
        std::vector<std::size_t> counterparts;  // ground-truth vertices with a counterpart
    };
    std::map<std::pair<std::string, std::string>, std::map<std::string, Points>> per_building;
    for (const auto& r : results)
    {
        if (!r.error.empty() || r.spec.severity < 0) continue;
        std::vector<std::string> which;
        if (r.spec.severity == 0)
            which = {"breaks", "slam"};  // the undamaged map starts both ladders
        else
            which = {r.spec.ladder};
        for (const auto& l : which)
        {
            if (l == "slam" && r.spec.source != "generated") continue;
            const double severity = l == "slam"
                                        ? (std::isfinite(r.distortion_m) ? r.distortion_m : 0.0)
                                        : static_cast<double>(r.spec.severity);
            auto& own = per_building[{r.spec.family, l}][r.spec.building];
            own.damage.push_back(-severity);
            own.quality.push_back(r.score.quality);
            own.counterparts.push_back(r.score.gt_with_counterpart);
        }
    }
    for (const auto& [key, buildings] : per_building)
    {
        Points pts;
        for (const auto& [building, own] : buildings)
        {
            pts.damage.insert(pts.damage.end(), own.damage.begin(), own.damage.end());
            pts.quality.insert(pts.quality.end(), own.quality.begin(), own.quality.end());
        }
        if (pts.damage.size() < 3) continue;
        FamilyLadder f;
        f.family = key.first;
        f.ladder = key.second;
        f.points = pts.damage.size();
        f.spearman = spearman(pts.damage, pts.quality);
        double sum = 0.0;
        for (const auto& [building, own] : buildings)
        {
            for (std::size_t i = 0; i < own.damage.size(); ++i)
                for (std::size_t j = 0; j < own.damage.size(); ++j)
                {
                    if (own.damage[i] <= own.damage[j]) continue;  // i is the less damaged
                    if (own.quality[i] < own.quality[j])
                    {
                        ++f.inversions;
                        f.inversions_less_complete += own.counterparts[i] < own.counterparts[j];
                        // Only the slam ladder's severity is a distortion in metres.
                        f.inversions_within_a_cell +=
                            key.second == "slam" &&
                            own.damage[i] - own.damage[j] < kResolvableDistortionM;
                    }
                    f.ties += own.quality[i] == own.quality[j];
                }
            const double rho = spearman(own.damage, own.quality);
            if (!std::isfinite(rho)) continue;
            sum += rho;
            ++f.buildings;
        }
        f.spearman_per_building = f.buildings ? sum / double(f.buildings) : kNaN;
        s.ladders.push_back(f);
    }
    return s;
}

std::string formatSummary(const Summary& s, const std::vector<CaseResult>& results)
{
    std::ostringstream o;
    auto row = [&](const Aggregate& a)
    {
        char buf[400];
        std::snprintf(
            buf, sizeof buf, "%-18s %5zu %4zu %7s %6zu %6zu %6s %6s %7s %6s %6s %6s %6s %6s %8s\n",
            a.name.c_str(), a.cases, a.errors, num(a.truth_min).c_str(), a.matched, a.true_pairs,
            num(a.precision()).c_str(), num(a.recall()).c_str(),
            a.broken ? (std::to_string(a.broken_exact) + "/" + std::to_string(a.broken)).c_str()
                     : "-",
            a.broken ? num(a.max_rotation_error_deg, 1).c_str() : "-", num(a.mean_coverage).c_str(),
            num(a.max_coverage).c_str(), num(a.mean_quality).c_str(),
            num(a.mean_explained_walls).c_str(), num(a.mean_time_ms, 0).c_str());
        o << buf;
    };
    o << "kind               cases  err truth_min matched   true  prec recall broken rot_err"
         "  cov  covmax quality  walls  time_ms\n";
    for (const auto& a : s.kinds) row(a);
    row(s.pooled_generated);
    row(s.pooled);
    // The pooled rows again, per building family (every kind but other buildings).
    o << "\nfamily             cases  err truth_min matched   true  prec recall broken rot_err"
         "  cov  covmax quality  walls  time_ms\n";
    for (const auto& a : s.families) row(a);
    o << "broken, by the truth alone, per family:";
    for (const auto& a : s.families)
        if (a.broken)
            o << " " << a.name << " " << a.broken_kept_exact << " of " << a.broken_kept << ";";
    o << "\n";
    o << "\nfamily             ladder  points  spearman(severity, quality)  per building (mean "
         "of)  inversions (less complete, within a cell)  ties\n";
    for (const auto& f : s.ladders)
    {
        char buf[200];
        std::snprintf(buf, sizeof buf, "%-18s %-7s %6zu  %-28s %-5s (%zu)%12zu (%zu, %zu)%32zu\n",
                      f.family.c_str(), f.ladder.c_str(), f.points, num(f.spearman).c_str(),
                      num(f.spearman_per_building).c_str(), f.buildings, f.inversions,
                      f.inversions_less_complete, f.inversions_within_a_cell, f.ties);
        o << buf;
    }
    for (const auto& a : s.kinds)
        if (a.name == "broken")
        {
            o << "\nbroken: exactly right in " << a.broken_exact << " of " << a.broken << "; in "
              << a.broken_measurable_exact << " of the " << a.broken_measurable
              << " whose every part holds 5 ground-truth vertices with a counterpart; in "
              << a.broken_observable_exact << " of the " << a.broken_observable
              << " whose every part holds 3 (with fewer a part's break is not observable)\n"
              << "broken, by the truth alone: exactly right in " << a.broken_kept_exact
              << " of the " << a.broken_kept
              << " whose every part keeps 3 ground-truth vertices whole (their walls in the map, "
                 "undisturbed by another part); "
              << a.broken_kept_graph_lost.size()
              << " of them with a part whose graph lost them (fewer than 3 counterparts)";
            for (std::size_t k = 0; k < a.broken_kept_graph_lost.size(); ++k)
                o << (k ? ", " : ": ") << a.broken_kept_graph_lost[k];
            o << "\n";
            if (!a.offset_errors_m.empty())
            {
                std::vector<double> e = a.offset_errors_m;
                std::sort(e.begin(), e.end());
                o << "broken, how far each found part is off (brokenness groups' offset_m) against "
                     "the truth's: "
                  << e.size() << " groups, |error| median " << num(e[(e.size() - 1) / 2], 3)
                  << " m, max " << num(e.back(), 3) << " m; within the larger of "
                  << num(kOffsetToleranceM, 2) << " m and " << num(100 * kOffsetToleranceShare, 0)
                  << " %: " << a.offsets_within << " of " << e.size() << "\n";
            }
        }
    for (const auto& a : s.kinds)
        if (a.name == "broken" && !a.broken_causes.empty())
        {
            std::vector<std::pair<std::size_t, std::string>> by_count;
            for (const auto& [cause, n] : a.broken_causes) by_count.emplace_back(n, cause);
            std::stable_sort(by_count.begin(), by_count.end(),
                             [](const auto& x, const auto& y) { return x.first > y.first; });
            o << "broken, not exactly right, by cause:";
            for (std::size_t k = 0; k < by_count.size(); ++k)
                o << (k ? "; " : " ") << by_count[k].first << " " << by_count[k].second;
            o << "\n";
        }
    for (const auto& a : s.kinds)
        if (a.name == "crop")
        {
            auto line = [&](const char* how, const CropErrors& c)
            {
                o << "crop, share kept " << how
                  << ": mean distance of coverage to it = " << num(c.mean) << ", max " << num(c.max)
                  << " (" << c.max_case << "); of the " << c.observable
                  << " crops that keep 3 or more, " << c.observable_within << " within "
                  << num(kCropCoverageTolerance) << ", max " << num(c.max_observable) << "\n";
            };
            o << "\n";
            line(
                "by the crop's rectangle (between the vertices whose clearance disc is kept "
                "and those whose centre is)",
                a.crop_kept);
            line("by counterparts in the map's graph (before session 29)", a.crop_counterparts);
        }
    // What changes the graph between two maps of one place (issue 11, item 1).
    o << "\ngraph stability: ground-truth vertices with no counterpart in the map's graph, by what "
         "the map's graph has within "
      << num(kLostNearM, 1)
      << " m of where the truth puts them; dead ends lost by their tip's clearance (narrow: "
         "under "
      << num(kNarrowTipM, 2)
      << " m); per kind, then per family over those kinds\n"
         "kind or family   vertices  lost  dead end: moved absent  junction: with its dead end "
         "moved absent  dead ends lost: narrow tips  wide tips\n";
    auto share = [](std::size_t n, std::size_t of)
    {
        return std::to_string(n) + " of " + std::to_string(of) + " (" +
               num(of ? static_cast<double>(n) / static_cast<double>(of) : kNaN) + ")";
    };
    auto lostRow = [&](const Aggregate& a)
    {
        const LostVertices& l = a.lost;
        if (l.vertices == 0) return;
        char buf[300];
        std::snprintf(buf, sizeof buf, "%-16s %8zu %5zu %16zu %6zu %28zu %5zu %6zu  %26s  %s\n",
                      a.name.c_str(), l.vertices, l.lost(), l.dead_end_moved, l.dead_end_absent,
                      l.junction_with_dead_end, l.junction_moved, l.junction_absent,
                      share(l.narrow_tips_lost, l.narrow_tips).c_str(),
                      share(l.wide_tips_lost, l.wide_tips).c_str());
        o << buf;
    };
    for (const auto& a : s.kinds) lostRow(a);
    for (const auto& a : s.families) lostRow(a);
    o << "\nreal pairs           truth  matched   true  prec recall counterp  cov  quality broken"
         "  time_ms\n";
    for (const auto& r : results)
    {
        if (r.spec.source != "real_pair") continue;
        char buf[400];
        std::snprintf(buf, sizeof buf, "%-22s %5s %7zu %6zu %6s %6s %8zu %6s %6s %4d %8s  %s\n",
                      r.spec.building.c_str(), num(r.truth_check.share()).c_str(), r.score.matched,
                      r.score.true_pairs, num(r.score.precision).c_str(),
                      num(r.score.recall).c_str(), r.score.gt_with_counterpart,
                      num(r.score.coverage).c_str(), num(r.score.quality).c_str(),
                      r.score.brokenness_found, num(r.time_ms, 0).c_str(),
                      r.error.empty() ? "" : ("ERROR " + r.error).c_str());
        o << buf;
    }
    row(s.real);
    o << "\ntruth check: " << s.truth_failures
      << " corpus case(s) under 95 % of occupied cells on ground-truth walls or of free space "
         "kept\n";
    return o.str();
}

std::vector<std::string> checkFloors(const Summary& s, const std::string& text,
                                     const std::string& file)
{
    std::vector<std::string> failures;
    std::istringstream in(text);
    std::string line;
    int line_no = 0;
    while (std::getline(in, line))
    {
        ++line_no;
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        std::istringstream ls(line);
        std::string metric, which;
        double minimum = 0;
        if (!(ls >> metric)) continue;
        if (!(ls >> which >> minimum))
            throw std::invalid_argument(file + ":" + std::to_string(line_no) +
                                        ": expected '<metric> <aggregate> <minimum>'");
        const Aggregate* a = nullptr;
        if (which == "pooled") a = &s.pooled;
        if (which == "real") a = &s.real;
        for (const auto& k : s.kinds)
            if (k.name == which) a = &k;
        // "family:NAME": one building family's pooled row; a family the run lacks fails.
        const std::string family_prefix = "family:";
        if (which.rfind(family_prefix, 0) == 0)
        {
            const std::string family = which.substr(family_prefix.size());
            for (const auto& f : s.families)
                if (f.name == family) a = &f;
            if (!a)
            {
                failures.push_back("no case of family '" + family + "' was run (" + file + ":" +
                                   std::to_string(line_no) + ")");
                continue;
            }
        }
        const auto& kinds = kindOrder();
        if (!a && std::find(kinds.begin(), kinds.end(), which) == kinds.end())
            throw std::invalid_argument(file + ":" + std::to_string(line_no) +
                                        ": unknown aggregate '" + which + "'");
        if (!a || a->cases == 0) continue;  // none run (real pairs without ../shared/data)
        double v = 0;
        if (metric == "precision")
            v = a->precision();
        else if (metric == "recall")
            v = a->recall();
        else if (metric == "brokenness_exact")
            v = a->broken ? static_cast<double>(a->broken_exact) / a->broken : kNaN;
        else if (metric == "clean_cases")
            v = static_cast<double>(a->clean) / static_cast<double>(a->cases);
        else if (metric == "truth_min")
            v = a->truth_min;
        else if (metric == "explained_walls")
            v = a->mean_explained_walls;
        else if (metric == "crop_within")
            v = a->crop_kept.observable ? static_cast<double>(a->crop_kept.observable_within) /
                                              static_cast<double>(a->crop_kept.observable)
                                        : kNaN;
        else
            throw std::invalid_argument(file + ":" + std::to_string(line_no) +
                                        ": unknown metric '" + metric + "'");
        if (!(v >= minimum))
            failures.push_back(metric + " of " + which + " = " + num(v) + " is under its floor " +
                               num(minimum) + " (" + file + ":" + std::to_string(line_no) + ")");
    }
    return failures;
}
}  // namespace mrpt_topoeval::validation
