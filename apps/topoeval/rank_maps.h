/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// The logic of `topoeval rank`, testable in-process (tests/cli_units_test.cpp): several maps
// scored against one ground truth by a pool of workers, ranked per attribute and overall like
// the paper's Table I, as a table and as CSV.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/QualityReport.h>
#include <mrpt_topoeval/TopologyGraph.h>
#include <mrpt_topoeval/html_report.h>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace mrpt_topoeval::cli
{
/** One map's outcome: a report, or the reason there is none. */
struct MapResult
{
    std::string file;  //!< As given.
    bool ok = false;
    bool internal_error = false;  //!< A bug or resource failure rather than a bad file.
    std::string error;
    QualityReport report;
    std::string name;  //!< As the table and the page show it.
    HtmlEntry html;    //!< Its part of the --html page, if asked for.

    bool matched() const { return ok && !report.match.pairs.empty(); }
};

/** The maps of `files` scored against the (shared, read-only) ground truth and its graph, in
 * the order given, by up to `params.similarity.threads` workers (0: all cores), ICP similarity
 * sharing what is left; with `html` each map's part of the page is made in its worker. Never
 * throws for a bad map: its outcome is in its result. Results do not depend on the thread
 * count; `workers`, if given, receives how many ran at once. */
std::vector<MapResult> scoreMaps(const TopologyGraph& gt_graph,
                                 const mrpt::maps::COccupancyGridMap2D& gt_grid,
                                 const std::vector<std::string>& files, const Parameters& params,
                                 bool html, std::size_t* workers = nullptr);

/** All ranks of the maps, in the order given. */
struct Ranking
{
    std::vector<std::string> overall, coverage, relative_accuracy, consistency, brokenness;
};

Ranking rankMaps(const std::vector<MapResult>& results);

/** The ranking as CSV, a header row first (--csv). */
std::string rankCsv(const std::vector<MapResult>& results, const Ranking& rk);

/** The ranking as a text table with a legend. */
void printRankTable(std::ostream& os, const std::vector<MapResult>& results, const Ranking& rk);

/** `v` with fixed `decimals`, "-" if not finite. */
std::string fixed(double v, int decimals);

}  // namespace mrpt_topoeval::cli
