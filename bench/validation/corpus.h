/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// The validation corpus (doc/validation.md): ground truths (generated buildings and real maps),
// the cases made from them, and real pairs. Cases are recipes: a case's map is made when it is
// scored, so the corpus never holds hundreds of grids at once.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/TopologyGraph.h>

#include <cstdint>
#include <string>
#include <vector>

#include "real_pairs.h"
#include "variants.h"

namespace mrpt_topoeval::validation
{
/** A ground truth the variants are made from. */
struct GroundTruthMap
{
    std::string name, family, file;
    bool generated = false;
    mrpt::maps::COccupancyGridMap2D grid;
    std::vector<Eigen::Vector2d> tour;  //!< Generated buildings only (for simulated SLAM).
};

/** One case: which ground truth, which variant, with which seed. */
struct CaseSpec
{
    std::string id;        //!< "<building>/<kind>[_<n>]", unique.
    std::string building;  //!< Ground truth's name (real pairs: the pair's name).
    std::string family;    //!< Building style or real family.
    std::string source;    //!< "generated", "real_map" (variants of a real map), "real_pair".
    std::string kind;      //!< identical, rigid, resample, speckle, gaps, ragged, crop, broken,
                           //!< furniture, slam, different, real.
    std::string ladder;    //!< "breaks" or "slam" for the severity ladders, else empty.
    int severity = -1;     //!< Position on the ladder (0 = undamaged), -1 off the ladders.
    double param = 0.0;    //!< The variant's figure: deg, m/cell, share, breaks or noise level.
    std::uint32_t seed = 0;
    std::size_t gt = 0;     //!< Index into Corpus::ground_truths (not for real pairs).
    std::size_t other = 0;  //!< "different": the other ground truth.
    int real_pair = -1;     //!< Index into Corpus::real_pairs, or -1.
};

struct CorpusOptions
{
    bool quick = false;      //!< The CI subset (~40 cases).
    std::uint32_t seed = 1;  //!< Everything random derives from it.
    std::string data_dir;    //!< ../shared/data; empty or absent = generated only.
    bool real = true;        //!< Use the real data when present.
    std::string only;        //!< Case ids must contain it (real pairs made at run time).
    /** Broken maps' parts turned in a chain, each against the previous one (makeBroken()). */
    bool chained_breaks = false;
    /** Building styles to generate (buildingStyles() and heldOutStyles()); empty = the
     * standard corpus's buildingStyles(). */
    std::vector<std::string> styles;
};

struct Corpus
{
    std::vector<GroundTruthMap> ground_truths;
    std::vector<RealPair> real_pairs;
    std::vector<CaseSpec> cases;
    std::vector<std::string> notes;  //!< What was skipped, and why.
    bool chained_breaks = false;     //!< CorpusOptions::chained_breaks.
};

/** Generates the buildings, reads the real data and lists the cases. Deterministic. */
Corpus buildCorpus(const CorpusOptions& opts);

/** The map of `c` and its truth (runs simulated SLAM for "slam" cases). Deterministic. */
Variant makeCaseMap(const Corpus& corpus, const CaseSpec& c);

/** The ground-truth grid of `c`. */
const mrpt::maps::COccupancyGridMap2D& groundTruthOf(const Corpus& corpus, const CaseSpec& c);
}  // namespace mrpt_topoeval::validation
