/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// The outputs `rawlog` and `series` share: an output folder whose files are refused without
// --force, `scores.csv` written row by row under a temporary name, maps as .gridmap.gz,
// JSON strings.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_topoeval/RawlogScorer.h>

#include <fstream>
#include <string>
#include <vector>

namespace mrpt_topoeval::cli
{
/** Creates `dir` if needed and refuses (OutputError, exit 3) any of `names` that exists in it
 * unless `force`; names ending in '/' are folders. \throws OutputError */
void prepareOutputFolder(const std::string& dir, const std::vector<std::string>& names, bool force);

/** `scores.csv` appended and flushed row by row to `<path>.part`, renamed to `path` by
 * commit() (also after a stop, so the part done is kept). A run that dies leaves the
 * `.part` file with every row scored so far. */
class ScoresCsv
{
public:
    explicit ScoresCsv(const std::string& path);
    ~ScoresCsv();
    void append(const ScoreRow& row);
    /** Closes and renames. \throws OutputError */
    void commit();

private:
    std::string m_path, m_part;
    std::ofstream m_out;
    bool m_committed = false;
    std::size_t m_rows = 0;
};

/** Writes an MRPT serialized grid, gz-compressed, through a temporary name.
 * \throws OutputError */
void writeGridMapGz(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid,
                    bool overwrite);

/** The grid as a grey picture, top = +y (as `saveAsBitmapFile`), written atomically. */
void writeGridPng(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid,
                  bool overwrite);

/** `s` as a JSON string literal. */
std::string jsonString(const std::string& s);
/** A number for JSON: null when not finite. */
std::string jsonNumber(double v);
/** A score row as a JSON object (the CSV's columns). */
std::string scoreRowJson(const ScoreRow& r);

}  // namespace mrpt_topoeval::cli
