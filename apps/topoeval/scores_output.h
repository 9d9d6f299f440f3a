/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// The outputs `rawlog` and `series` share: an output folder whose files are refused without
// --force and which a failed run leaves as it found it, `scores.csv` written row by row under
// a temporary name (mrpt_topoeval/scores/scores.h), maps as .gridmap.gz.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CSerializable.h>
#include <mrpt_topoeval/output.h>
#include <mrpt_topoeval/scores/scores.h>

#include <functional>
#include <string>
#include <vector>

namespace mrpt_topoeval::cli
{
/** Checks the output folder `dir` before any input is read and before anything is created:
 * refuses `dir` if it is not a folder, any of `names` in it that exists unless `force` (exit
 * 3), and a file of `names` that is one of `inputs` even with `force` (exit 2). Names ending
 * in '/' are folders. \throws OutputError, UsageError */
void checkOutputFolder(const std::string& dir, const std::vector<std::string>& names, bool force,
                       const std::vector<std::string>& inputs);

/** The output folder of a run, created (like `mkdir -p`) once its inputs have been checked.
 * It remembers which folders it created: unless keep() was called, the destructor removes
 * those of them that are empty again, deepest first. So a run that fails before it has
 * written anything leaves the file system as it found it, and a folder that existed before
 * the run, or one that holds any file, is never removed. */
class OutputFolder
{
public:
    /** Creates `dir` and its missing parents. \throws OutputError */
    explicit OutputFolder(const std::string& dir);
    ~OutputFolder();
    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;

    /** `dir/name`. */
    std::string file(const std::string& name) const;
    /** The folder, as given. */
    const std::string& dir() const { return m_dir; }
    /** Creates the folder `dir/name` if missing (removed like `dir` unless kept).
     * \throws OutputError */
    std::string createSubfolder(const std::string& name);
    /** The run has written results: nothing is removed. */
    void keep() { m_keep = true; }

private:
    void create(const std::string& path);

    std::string m_dir;
    std::vector<std::string> m_created;  // outermost first
    bool m_keep = false;
};

/** Called while an error that ends a run propagates (inside a catch), once `csv` holds rows:
 * they are results, so `folder` is kept, `scores.csv` committed (or its `.part` left), a
 * `report.json` written from `report_json(error text)` (best effort: the error reported is the
 * first one), and a warning names what was kept, e.g. "DIR: kept the 3 snapshots scored before
 * the error (scores.csv, report.json)". The caller rethrows. */
void keepPartialRun(OutputFolder& folder, ScoresCsv& csv, const std::string& noun,
                    const std::function<std::string(const std::string& error)>& report_json,
                    bool force);

/** Writes an MRPT serialized object, gz-compressed (as MRPT's `.gridmap.gz` and `.simplemap`
 * files are), through a temporary name.
 * \throws OutputError */
void writeSerializedGz(const std::string& path, const mrpt::serialization::CSerializable& object,
                       bool overwrite);

/** Writes an MRPT serialized grid, gz-compressed, through a temporary name.
 * \throws OutputError */
void writeGridMapGz(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid,
                    bool overwrite);

/** The grid as a grey picture, top = +y (as `saveAsBitmapFile`), written atomically. */
void writeGridPng(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid,
                  bool overwrite);

}  // namespace mrpt_topoeval::cli
