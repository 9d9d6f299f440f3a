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

namespace fs = std::filesystem;

namespace mrpt_topoeval::cli
{
void prepareOutputFolder(const std::string& dir, const std::vector<std::string>& names, bool force)
{
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw OutputError(dir + ": exists and is not a folder (--out)");
    fs::create_directories(dir, ec);
    if (ec) throw OutputError(dir + ": cannot create the output folder: " + ec.message());
    if (force) return;
    for (const auto& name : names)
    {
        const fs::path p = fs::path(dir) / name;
        if (fs::exists(fs::symlink_status(p.string().back() == '/' ? p.parent_path() : p, ec)))
            throw OutputError(p.string() + ": exists; pass --force to replace it");
    }
}

ScoresCsv::ScoresCsv(const std::string& path) : m_path(path), m_part(path + ".part")
{
    m_out.open(m_part, std::ios::binary | std::ios::trunc);
    if (!m_out) throw OutputError(m_part + ": cannot open for writing");
    m_out << scoreCsvHeader() << "\n" << std::flush;
    if (!m_out) throw OutputError(m_part + ": write failed");
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

std::string jsonString(const std::string& s)
{
    std::string out = "\"";
    for (const char ch : s)
    {
        switch (ch)
        {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\r':
                out += "\\r";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(ch) < 0x20)
                {
                    char buf[8];
                    std::snprintf(buf, sizeof(buf), "\\u%04x", static_cast<unsigned char>(ch));
                    out += buf;
                }
                else
                    out += ch;
        }
    }
    return out + "\"";
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
