/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// Score rows: from a quality report, as CSV lines and as JSON; scores.csv written row by row.

#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/scores/scores.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace mrpt_topoeval
{
ScoreRow scoreRowFromReport(const QualityReport& report)
{
    ScoreRow row;
    row.vertices = report.map_vertices;
    row.coverage = report.coverage;
    row.relative_accuracy = report.relative_accuracy.score;
    for (const auto& c : report.local_consistency)
    {
        if (c.name == "short") row.consistency_short = c.score;
        if (c.name == "medium") row.consistency_medium = c.score;
        if (c.name == "long") row.consistency_long = c.score;
    }
    row.brokenness = report.brokenness.degree;
    row.quality = report.quality;
    row.explained_walls = report.explained_walls.measured ? report.explained_walls.share : 0.0;
    return row;
}

std::string scoreCsvHeader()
{
    return "step,entry,time_s,scans,vertices,coverage,relative_accuracy,consistency_short,"
           "consistency_medium,consistency_long,brokenness,quality,scoring_ms,explained_walls";
}

std::string scoreCsvLine(const ScoreRow& r)
{
    char time_buf[32] = "";
    if (std::isfinite(r.time_s)) std::snprintf(time_buf, sizeof(time_buf), "%.3f", r.time_s);
    char buf[320];
    std::snprintf(buf, sizeof(buf), "%d,%zu,%s,%zu,%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%d,%.4f,%.1f,%.4f",
                  r.step, r.entry, time_buf, r.scans, r.vertices, r.coverage, r.relative_accuracy,
                  r.consistency_short, r.consistency_medium, r.consistency_long, r.brokenness,
                  r.quality, r.scoring_ms, r.explained_walls);
    return buf;
}

void writeScoreRow(JsonWriter& w, const ScoreRow& r)
{
    constexpr int kDigits = 10;  // significant digits, as printf %.10g
    w.beginObject(true);
    w.key("step").value(r.step).key("entry").value(static_cast<std::uint64_t>(r.entry));
    w.key("time_s").valueSignificant(r.time_s, kDigits);
    w.key("scans").value(static_cast<std::uint64_t>(r.scans));
    w.key("vertices").value(static_cast<std::uint64_t>(r.vertices));
    w.key("coverage").valueSignificant(r.coverage, kDigits);
    w.key("relative_accuracy").valueSignificant(r.relative_accuracy, kDigits);
    w.key("consistency_short").valueSignificant(r.consistency_short, kDigits);
    w.key("consistency_medium").valueSignificant(r.consistency_medium, kDigits);
    w.key("consistency_long").valueSignificant(r.consistency_long, kDigits);
    w.key("brokenness").value(r.brokenness);
    w.key("quality").valueSignificant(r.quality, kDigits);
    w.key("scoring_ms").valueSignificant(r.scoring_ms, kDigits);
    w.key("explained_walls").valueSignificant(r.explained_walls, kDigits);
    w.endObject();
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

}  // namespace mrpt_topoeval
