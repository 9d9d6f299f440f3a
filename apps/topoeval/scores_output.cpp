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

void writeSerializedGz(const std::string& path, const mrpt::serialization::CSerializable& object,
                       bool overwrite)
{
    mrpt::io::CMemoryStream mem;
    mrpt::serialization::archiveFrom(mem) << object;
    const auto* p = static_cast<const std::uint8_t*>(mem.getRawBufferData());
    const std::vector<std::uint8_t> raw(p, p + mem.getTotalBytesCount());
    std::vector<std::uint8_t> gz;
    if (!mrpt::io::zip::compress_gz_data_block(raw, gz, 6))
        throw OutputError(path + ": gzip compression failed");
    writeFileAtomic(path, std::string(gz.begin(), gz.end()), overwrite);
}

void writeGridMapGz(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid,
                    bool overwrite)
{
    writeSerializedGz(path, grid, overwrite);
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

}  // namespace mrpt_topoeval::cli
