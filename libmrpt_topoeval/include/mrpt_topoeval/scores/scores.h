/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Scores over time: one row per map snapshot (a rawlog's, or a series of saved maps), written
// as `scores.csv` row by row, as JSON objects, and drawn as `scores.png` (doc/rawlog.md). Used
// by `topoeval rawlog` and `topoeval series` alike.

#include <mrpt/img/CImage.h>
#include <mrpt_topoeval/QualityReport.h>
#include <mrpt_topoeval/json/JsonWriter.h>

#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

namespace mrpt_topoeval
{
/** One row of `scores.csv`: a map snapshot and its scores (doc/rawlog.md, "CSV columns"). */
struct ScoreRow
{
    int step = 0;              //!< Snapshot number, from 1.
    std::size_t entry = 0;     //!< Rawlog entry (from 0) after which the snapshot was taken;
                               //!< for `series`, the number in the map's file name or its index.
    double time_s = 0.0;       //!< Time of the last scan since the first one [s]; NaN if none.
    std::size_t scans = 0;     //!< Scans processed so far (0 for `series`).
    std::size_t vertices = 0;  //!< Matchable vertices of the snapshot's Topology Graph.
    double coverage = 0.0;     //!< Paper IV coverage [0, 1].
    double relative_accuracy = 0.0;  //!< Relative accuracy score [0, 1].
    double consistency_short = 0.0;  //!< Local consistency scores per class [0, 1].
    double consistency_medium = 0.0;
    double consistency_long = 0.0;
    int brokenness = 0;       //!< Brokenness degree (0 = not broken).
    double quality = 0.0;     //!< The combined quality score [0, 1].
    double scoring_ms = 0.0;  //!< Wall time of the copy and evaluate() [ms].
    /** Share of the map's wall points that the match explains [0, 1]; 0 when not measured
     * (nothing matched): QualityReport::explained_walls. */
    double explained_walls = 0.0;
};

/** A row from a quality report; `step`, `entry`, `time_s`, `scans`, `scoring_ms` are the
 * caller's. */
ScoreRow scoreRowFromReport(const QualityReport& report);

/** The CSV header line (no newline):
 * `step,entry,time_s,scans,vertices,coverage,relative_accuracy,consistency_short,`
 * `consistency_medium,consistency_long,brokenness,quality,scoring_ms,explained_walls` (the last
 * added in session 42, after the columns a reader may know by position). */
std::string scoreCsvHeader();
/** One CSV line (no newline); a NaN time is an empty field. */
std::string scoreCsvLine(const ScoreRow& row);

/** The scores over time as a picture (`scores.png`): quality, coverage, relative accuracy and
 * the three consistency scores against time (or against the entry number when any row has no
 * time), with axes, ticks and a legend. `title` goes above the plot. Deterministic. */
mrpt::img::CImage drawScorePlot(const std::vector<ScoreRow>& rows, const std::string& title);

/** A row as a single-line JSON object with the CSV's columns (numbers with 10 significant
 * digits, NaN as null): `final_scores` of report.json, and the maps of `series`. */
void writeScoreRow(JsonWriter& w, const ScoreRow& row);

/** `scores.csv` appended and flushed row by row to `<path>.part`, renamed to `path` by
 * commit() (also after a stop, so the part done is kept). A run that dies leaves the
 * `.part` file with every row scored so far. \throws OutputError when a write fails. */
class ScoresCsv
{
public:
    explicit ScoresCsv(const std::string& path);
    ~ScoresCsv();
    ScoresCsv(const ScoresCsv&) = delete;
    ScoresCsv& operator=(const ScoresCsv&) = delete;
    void append(const ScoreRow& row);
    /** Closes and renames. \throws OutputError */
    void commit();
    /** Rows appended so far. */
    std::size_t rows() const { return m_rows; }
    /** The final name (`path` of the constructor). */
    const std::string& path() const { return m_path; }

private:
    std::string m_path, m_part;
    std::ofstream m_out;
    bool m_committed = false;
    std::size_t m_rows = 0;
};

}  // namespace mrpt_topoeval
