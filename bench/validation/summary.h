/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// Summaries of the validation corpus (doc/validation.md, "Measures"): per kind, pooled, per
// family (Spearman of severity vs quality), the real pairs; and the floors of the CI subset.

#include <map>
#include <string>
#include <vector>

#include "corpus.h"
#include "scoring.h"

namespace mrpt_topoeval::validation
{
/** One scored case. */
struct CaseResult
{
    CaseSpec spec;
    std::string truth_source;
    TruthCheck truth_check;
    double wall_tolerance_m = 0.0;
    CaseScore score;
    double distortion_m = 0.0;  //!< mapDistortion() of the case's map.
    double time_ms = 0.0;       //!< evaluate() on the case (graph of the map, match, scores).
    std::string error;          //!< Non-empty when the case threw.
};

/** A crop's coverage against the share of ground-truth vertices it keeps. */
struct CropErrors
{
    std::size_t crops = 0;
    double mean = 0.0;  //!< Mean distance of coverage to the share kept (NaN: no crop).
    double max = 0.0;   //!< The largest, and its case.
    std::string max_case;
    /** Over the crops that keep at least 3 ground-truth vertices (the fewest a group holds:
     * with fewer, no matcher that asks a group for its pairs can match the share): how many,
     * how many within kCropCoverageTolerance, the largest error. Vertices at the cut count. */
    std::size_t observable = 0, observable_within = 0;
    double max_observable = 0.0;
    /** Adds a crop whose coverage is `coverage`, which keeps `kept` of `total` vertices and
     * `at_cut` more that it may or may not keep: the error is the coverage's distance to the
     * shares between kept / total and (kept + at_cut) / total. A crop of no vertex is skipped. */
    void add(const std::string& id, double coverage, std::size_t kept, std::size_t at_cut,
             std::size_t total);
};

/** Aggregates of a set of cases. Precision and recall are pooled (sums of pairs). */
struct Aggregate
{
    std::string name;
    std::size_t cases = 0, errors = 0;
    double truth_min = 1.0;  //!< Smallest truth-check share.
    std::size_t matched = 0, true_pairs = 0, counterparts = 0;
    std::size_t clean = 0;  //!< Cases scored without an error and without a false pair.
    double precision() const;
    double recall() const;
    /** Ground-truth vertices lost in the map's graph, by cause, over the cases that count them
     * (CaseScore::lost). */
    LostVertices lost;
    std::size_t broken = 0, broken_exact = 0;  //!< Cases with injected breaks, found exactly.
    /** Broken cases whose every part holds 5 ground-truth vertices with a counterpart (so a
     * 5-vertex group could be made in each), and of those the ones found exactly. */
    std::size_t broken_measurable = 0, broken_measurable_exact = 0;
    /** Broken cases whose every part holds 3 (the fewest a rigid fit can be checked on), and
     * of those the ones found exactly. */
    std::size_t broken_observable = 0, broken_observable_exact = 0;
    /** Broken cases whose every part keeps 3 ground-truth vertices whole by the truth alone
     * (CaseScore::parts_with_3_kept), of those the ones found exactly, and the ones that the
     * counterparts call not observable (a part's vertices lost in the map's graph; their ids). */
    std::size_t broken_kept = 0, broken_kept_exact = 0;
    std::vector<std::string> broken_kept_graph_lost;
    double max_rotation_error_deg = 0.0;  //!< Over every group of every broken case.
    /** Over every group but the largest of every broken case whose parts the truth places:
     * |offset_m - true_offset_m| (how far the report and the truth say its part is off). */
    std::vector<double> offset_errors_m;
    /** ... and how many are within the larger of 0.25 m and 10 % of the truth (summary.cpp). */
    std::size_t offsets_within = 0;
    /** Broken cases not exactly right, by brokenCause(). */
    std::map<std::string, std::size_t> broken_causes;
    double mean_coverage = 0.0, max_coverage = 0.0, mean_quality = 0.0;
    /** Mean of CaseScore::explained_walls over the cases where it was measured (NaN: none). */
    double mean_explained_walls = 0.0;
    std::size_t explained_measured = 0;
    /** Crops: |coverage - share of ground-truth vertices kept|, the share counted two ways:
     * `crop_kept` by the crop's rectangle (CaseScore::gt_kept, the truth; since session 29) and
     * `crop_counterparts` by the vertices with a counterpart in the map's graph (before). */
    CropErrors crop_kept, crop_counterparts;
    double mean_time_ms = 0.0;
};

Aggregate aggregate(const std::string& name, const std::vector<const CaseResult*>& cases);

/** Why a broken case is not exactly right (doc/validation.md, "Measures", "why a broken case
 * fails"): "" when it is; else "nothing matched" (", a part not observable" added when a part
 * has fewer than 3 ground-truth vertices with a counterpart), "a break too many", "a group
 * turned wrong" (more than 3 degrees from its part's turn); else, for the parts that no group
 * stands for, joined by " + ": "a part not observable", "a part unmatched" (none of its
 * counterparts matched), "a part with 1-2 pairs", "a part inside another's group" (3 or more
 * true pairs, but no group of its own). */
std::string brokenCause(const CaseScore& s);

/** Issue 11's crop target: coverage within this of the share of ground-truth vertices kept. */
constexpr double kCropCoverageTolerance = 0.15;

/** Two maps whose measured distortion differs by less than this are not ordered by it [m]: one
 * cell of the generated maps (0.05 m). Session 12 found every inversion of the angled and
 * corridor-office SLAM ladders between such maps (gaps 0.004-0.033 m; doc/validation.md). */
constexpr double kResolvableDistortionM = 0.05;

/** Spearman's rank correlation (ties get mean ranks); NaN for fewer than 3 points or no spread. */
double spearman(const std::vector<double>& a, const std::vector<double>& b);

struct FamilyLadder
{
    std::string family, ladder;
    std::size_t points = 0;
    /** Of -severity vs quality: 1 = quality falls as damage grows. Severity on the breaks
     * ladder is the number of breaks; on the slam ladder the map's measured distortion (the
     * noise level does not order the maps' real error: ICP undoes much of it). */
    double spearman = 0.0;
    /** The same within each building of the family (its own ladder, 4 points), averaged over
     * the buildings: without the differences between buildings (one building's coverage is
     * lower at every level), which the pooled figure mixes in. NaN when no building has 3
     * points with a spread. */
    double spearman_per_building = 0.0;
    std::size_t buildings = 0;  //!< Buildings in that mean.
    /** Within each building, the pairs of maps that quality orders against the ladder (the
     * less damaged map scores lower), and of those the pairs in which the less damaged map is
     * also the less complete one (fewer ground-truth vertices with a counterpart, by the truth):
     * each map is worse in one respect, and the ladder's severity sees only the other. */
    std::size_t inversions = 0, inversions_less_complete = 0;
    /** On the slam ladder, the inversions between maps whose measured distortions differ by
     * less than kResolvableDistortionM (within one cell of each other: the truth does not order
     * them); 0 on the breaks ladder. */
    std::size_t inversions_within_a_cell = 0;
    /** Within each building, the pairs of maps of different severity with the same quality
     * (two levels of which nothing is matched both score 0). */
    std::size_t ties = 0;
};

struct Summary
{
    std::vector<Aggregate> kinds;  //!< Corpus cases (not real pairs), per kind.
    Aggregate pooled;              //!< Every corpus case but other buildings (different, twin).
    Aggregate pooled_generated;    //!< ... of generated buildings only.
    /** ... per building family (a generated style, or a real set such as radish), in name
     * order: how each style of buildings fares, the held-out styles among them. */
    std::vector<Aggregate> families;
    std::vector<FamilyLadder> ladders;  //!< Per family and ladder.
    Aggregate real;                     //!< The real pairs, pooled.
    std::size_t truth_failures = 0;     //!< Corpus cases under 95 % in the truth check.
};

Summary summarize(const std::vector<CaseResult>& results);

/** The table printed on stdout and written to summary.txt. */
std::string formatSummary(const Summary& s, const std::vector<CaseResult>& results);

/** Checks `floors_text` (lines "<metric> <aggregate> <minimum>", '#' comments; metrics:
 * precision, recall, brokenness_exact, clean_cases, truth_min, crop_within, explained_walls (the
 * mean share of the map's walls explained); aggregates: a kind, "pooled", "real" or
 * "family:NAME", which fails when the run has no case of that family) against
 * the summary. Returns the failures, one line each; throws std::invalid_argument on a bad line. */
std::vector<std::string> checkFloors(const Summary& s, const std::string& floors_text,
                                     const std::string& floors_file);
}  // namespace mrpt_topoeval::validation
