/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "scores_output.h"

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/io/zip.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/output.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli_common.h"

namespace fs = std::filesystem;

namespace mrpt_topoeval::cli
{
void checkOutputFolder(const std::string& dir, const std::vector<std::string>& names, bool force,
                       const std::vector<std::string>& inputs)
{
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw OutputError(dir + ": exists and is not a folder (--out)");
    for (const auto& name : names)
    {
        const fs::path p = fs::path(dir) / name;
        if (name.back() == '/')
        {
            if (!force && fs::exists(fs::symlink_status(p.parent_path(), ec)))
                throw OutputError(p.string() + ": exists; pass --force to replace it");
        }
        else
            checkOutputPath(p.string(), force, inputs);
    }
}

OutputFolder::OutputFolder(const std::string& dir) : m_dir(dir) { create(dir); }

OutputFolder::~OutputFolder()
{
    if (m_keep) return;
    // rmdir semantics: a folder that holds anything (a file this run kept, or one someone
    // else put there meanwhile) stays.
    std::error_code ec;
    for (auto it = m_created.rbegin(); it != m_created.rend(); ++it)
        if (fs::is_directory(fs::symlink_status(*it, ec)) && fs::is_empty(*it, ec))
            fs::remove(*it, ec);
}

std::string OutputFolder::file(const std::string& name) const
{
    return (fs::path(m_dir) / name).string();
}

std::string OutputFolder::createSubfolder(const std::string& name)
{
    const std::string path = file(name);
    create(path);
    return path;
}

void OutputFolder::create(const std::string& path)
{
    // One level at a time, so that exactly the folders this run made are known: a folder that
    // create_directory() did not make (it existed, or appeared meanwhile) is not ours.
    fs::path sofar;
    for (const auto& part : fs::path(path))
    {
        if (part.empty()) continue;  // the end of a trailing '/'
        sofar /= part;
        std::error_code ec;
        if (fs::is_directory(sofar, ec)) continue;
        const bool made = fs::create_directory(sofar, ec);
        if (ec)
            throw OutputError(path + ": cannot create the output folder '" + sofar.string() +
                              "': " + ec.message());
        if (made) m_created.push_back(sofar.string());
    }
}

ScoresCsv::ScoresCsv(const std::string& path) : m_path(path), m_part(path + ".part")
{
    m_out.open(m_part, std::ios::binary | std::ios::trunc);
    if (!m_out) throw OutputError(m_part + ": cannot open for writing");
    m_out << scoreCsvHeader() << "\n" << std::flush;
    if (!m_out)
    {
        // Not even the header: nothing worth keeping (the destructor does not run).
        m_out.close();
        std::error_code ec;
        fs::remove(m_part, ec);
        throw OutputError(m_part + ": write failed");
    }
}

ScoresCsv::~ScoresCsv()
{
    // Not committed: an error ended the run. Rows already scored stay in the .part file; a
    // file with the header only is removed.
    if (m_committed || m_rows > 0) return;
    m_out.close();
    std::error_code ec;
    fs::remove(m_part, ec);
}

void ScoresCsv::append(const ScoreRow& row)
{
    ++m_rows;
    m_out << scoreCsvLine(row) << "\n" << std::flush;
    if (!m_out) throw OutputError(m_part + ": write failed");
}

void ScoresCsv::commit()
{
    if (m_committed) return;
    m_out.close();
    if (!m_out) throw OutputError(m_part + ": write failed");
    std::error_code ec;
    fs::rename(m_part, m_path, ec);
    if (ec) throw OutputError(m_path + ": cannot rename from " + m_part + ": " + ec.message());
    m_committed = true;
}

void writeGridMapGz(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid,
                    bool overwrite)
{
    mrpt::io::CMemoryStream mem;
    mrpt::serialization::archiveFrom(mem) << grid;
    const auto* p = static_cast<const std::uint8_t*>(mem.getRawBufferData());
    const std::vector<std::uint8_t> raw(p, p + mem.getTotalBytesCount());
    std::vector<std::uint8_t> gz;
    if (!mrpt::io::zip::compress_gz_data_block(raw, gz, 6))
        throw OutputError(path + ": gzip compression failed");
    writeFileAtomic(path, std::string(gz.begin(), gz.end()), overwrite);
}

void writeGridPng(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid,
                  bool overwrite)
{
    mrpt::img::CImage img;
    grid.getAsImage(img);
    writePngAtomic(path, img, overwrite);
}

void keepPartialRun(OutputFolder& folder, ScoresCsv& csv, const std::string& noun,
                    const std::function<std::string(const std::string& error)>& report_json,
                    bool force)
{
    folder.keep();
    const std::string error = currentErrorText();
    std::string kept;
    try
    {
        csv.commit();
        kept = "scores.csv";
    }
    catch (const std::exception&)
    {
        kept = "scores.csv.part";
    }
    try
    {
        writeFileAtomic(folder.file("report.json"), report_json(error), force);
        kept += ", report.json";
    }
    catch (const std::exception&)
    {
    }
    printWarning(folder.dir() + ": kept the " + std::to_string(csv.rows()) + " " + noun +
                 " scored before the error (" + kept + ")");
}

std::string jsonNumber(double v)
{
    if (!std::isfinite(v)) return "null";
    char buf[40];
    std::snprintf(buf, sizeof(buf), "%.10g", v);
    return buf;
}

std::string scoreRowJson(const ScoreRow& r)
{
    return "{\"step\": " + std::to_string(r.step) + ", \"entry\": " + std::to_string(r.entry) +
           ", \"time_s\": " + jsonNumber(r.time_s) + ", \"scans\": " + std::to_string(r.scans) +
           ", \"vertices\": " + std::to_string(r.vertices) +
           ", \"coverage\": " + jsonNumber(r.coverage) +
           ", \"relative_accuracy\": " + jsonNumber(r.relative_accuracy) +
           ", \"consistency_short\": " + jsonNumber(r.consistency_short) +
           ", \"consistency_medium\": " + jsonNumber(r.consistency_medium) +
           ", \"consistency_long\": " + jsonNumber(r.consistency_long) +
           ", \"brokenness\": " + std::to_string(r.brokenness) +
           ", \"quality\": " + jsonNumber(r.quality) +
           ", \"scoring_ms\": " + jsonNumber(r.scoring_ms) + "}";
}

}  // namespace mrpt_topoeval::cli
