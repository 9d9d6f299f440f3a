/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// `topoeval rank`'s logic: the worker pool over the maps, the ranks, the table and the CSV.

#include "rank_maps.h"

#include <mrpt/core/exceptions.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <mrpt_topoeval/pipeline/evaluate.h>
#include <mrpt_topoeval/scores/ranking.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <new>
#include <set>
#include <system_error>
#include <thread>

namespace fs = std::filesystem;

namespace mrpt_topoeval::cli
{
namespace
{
/** Loads and evaluates one map against the (shared, read-only) ground truth and its graph,
 * and with `html` makes its part of the page (pictures encoded here, in the worker). Never
 * throws: the outcome, good or bad, is in the result, so one bad map does not stop the
 * others. */
void evaluateOne(const TopologyGraph& gt_graph, const mrpt::maps::COccupancyGridMap2D& gt_grid,
                 const Parameters& params, bool html, MapResult& res)
{
    try
    {
        const LoadedMap m = loadMap(res.file, params.map_load);
        TopologyGraph graph;
        res.report = evaluate(gt_graph, gt_grid, m.grid, params, &graph);
        // Evaluations run in threads: the loader's notes go with the map's report.
        for (const auto& note : m.notes) res.report.messages.push_back("map: " + note);
        if (graph.vertices.empty() && graph.warnings.empty())
            res.report.messages.push_back("map: the Topology Graph is empty");
        if (html)
            res.html = makeHtmlEntry(res.name, gt_grid, gt_graph, m.grid, graph, res.report, true);
        res.ok = true;
    }
    catch (const InputError& e)
    {
        res.error = e.what();
    }
    catch (const std::bad_alloc&)
    {
        res.error = "out of memory";
        res.internal_error = true;
    }
    catch (const std::exception& e)
    {
        res.error = "internal error: " + mrpt::exception_to_str(e);
        res.internal_error = true;
    }
    catch (...)
    {
        res.error = "internal error: unknown exception";
        res.internal_error = true;
    }
}

}  // namespace

namespace
{
/** `v` with `decimals` decimals, trailing zeros removed; "" if not finite. Locale
 * independent (CSV readers expect a '.'). */
std::string num(double v, int decimals)
{
    if (!std::isfinite(v)) return "";
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::fixed, decimals);
    std::string s(buf, res.ptr);
    if (s.find('.') != std::string::npos)
    {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    return s == "-0" ? "0" : s;
}

/** A CSV field, quoted when it holds a comma, quote or line break (RFC 4180). */
std::string csvField(const std::string& s)
{
    if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
    std::string out = "\"";
    for (const char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return out + "\"";
}

}  // namespace

Ranking rankMaps(const std::vector<MapResult>& results)
{
    const std::size_t n = results.size();
    std::vector<bool> valid(n);
    std::vector<double> quality(n), coverage(n), accuracy(n), consistency(n), brokenness(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const MapResult& m = results[i];
        valid[i] = m.ok;
        if (!m.ok) continue;
        quality[i] = m.report.quality;
        coverage[i] = m.report.coverage;
        accuracy[i] = m.report.relative_accuracy.score;
        consistency[i] = m.report.consistencyScore();
        // By score (1 / (1 + degree), 0 when nothing matched): a map that matched nothing
        // has degree 0 but is not the least broken.
        brokenness[i] = m.report.brokenness.score;
    }
    return {rankPositions(quality, valid), rankPositions(coverage, valid),
            rankPositions(accuracy, valid), rankPositions(consistency, valid),
            rankPositions(brokenness, valid)};
}

namespace
{
std::string consistencyScore(const MapResult& m, std::size_t cls, bool for_csv)
{
    const auto& classes = m.report.local_consistency;
    if (cls >= classes.size() || classes[cls].pairs == 0) return for_csv ? "" : "-";
    return for_csv ? num(classes[cls].score, 4) : fixed(classes[cls].score, 2);
}

}  // namespace

std::string rankCsv(const std::vector<MapResult>& results, const Ranking& rk)
{
    std::string out =
        "file,rank,quality,coverage,relative_accuracy_rmse_m,relative_accuracy_score,"
        "consistency_short,consistency_medium,consistency_long,brokenness,rank_coverage,"
        "rank_relative_accuracy,rank_consistency,rank_brokenness,map_scale,explained_walls\n";
    for (std::size_t i = 0; i < results.size(); ++i)
    {
        const MapResult& m = results[i];
        std::vector<std::string> f = {csvField(m.file)};
        if (m.ok)
        {
            const QualityReport& r = m.report;
            // Quantities measured on matched vertices are empty when nothing was matched.
            const bool matched = m.matched();
            f.insert(f.end(), {rk.overall[i], num(r.quality, 4), num(r.coverage, 4),
                               matched ? num(r.relative_accuracy.rmse_m, 4) : "",
                               num(r.relative_accuracy.score, 4), consistencyScore(m, 0, true),
                               consistencyScore(m, 1, true), consistencyScore(m, 2, true),
                               matched ? std::to_string(r.brokenness.degree) : "", rk.coverage[i],
                               rk.relative_accuracy[i], rk.consistency[i], rk.brokenness[i],
                               num(r.map_scale, 4),
                               r.explained_walls.measured ? num(r.explained_walls.share, 4) : ""});
        }
        else
            f.resize(16);  // a map that could not be evaluated: its file, nothing else
        for (std::size_t k = 0; k < f.size(); ++k) out += (k ? "," : "") + f[k];
        out += "\n";
    }
    return out;
}

namespace
{
/** The names the table shows: file names, or the paths as given where two maps share one. */
std::vector<std::string> displayNames(const std::vector<MapResult>& results)
{
    std::vector<std::string> names;
    for (const MapResult& m : results) names.push_back(fs::path(m.file).filename().string());
    std::set<std::string> seen, twice;
    for (const auto& n : names)
        if (!seen.insert(n).second) twice.insert(n);
    for (std::size_t i = 0; i < names.size(); ++i)
        if (twice.count(names[i]) || names[i].empty()) names[i] = results[i].file;
    return names;
}

}  // namespace

std::vector<MapResult> scoreMaps(const TopologyGraph& gt_graph,
                                 const mrpt::maps::COccupancyGridMap2D& gt_grid,
                                 const std::vector<std::string>& files, const Parameters& params,
                                 bool html, std::size_t* workers_out)
{
    std::vector<MapResult> results(files.size());
    for (std::size_t i = 0; i < results.size(); ++i) results[i].file = files[i];
    const std::vector<std::string> names = displayNames(results);
    for (std::size_t i = 0; i < results.size(); ++i) results[i].name = names[i];
    if (results.empty())
    {
        if (workers_out) *workers_out = 0;
        return results;
    }

    // The thread budget: maps at once, and what is left for each one's ICP similarity (so N
    // maps with ICP do not start N x cores threads).
    const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t budget =
        params.similarity.threads > 0 ? static_cast<std::size_t>(params.similarity.threads) : hw;
    const std::size_t workers = std::min(budget, results.size());
    Parameters worker_params = params;
    worker_params.similarity.threads = static_cast<int>(std::max<std::size_t>(1, budget / workers));

    std::atomic<std::size_t> next{0};
    const auto work = [&]
    {
        for (std::size_t i = next++; i < results.size(); i = next++)
            evaluateOne(gt_graph, gt_grid, worker_params, html, results[i]);
    };
    std::vector<std::thread> pool;
    try
    {
        for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work);
    }
    catch (const std::system_error&)
    {
        // The system gave fewer threads than asked: those started, and this one, share the maps.
    }
    work();  // the main thread is a worker too
    for (auto& t : pool) t.join();
    if (workers_out) *workers_out = pool.size() + 1;
    return results;
}

void printRankTable(std::ostream& os, const std::vector<MapResult>& results, const Ranking& rk)
{
    const std::vector<std::string> header = {"map",   "rank",   "quality", "coverage", "rel.acc.",
                                             "short", "medium", "long",    "broken",   "r.cov",
                                             "r.acc", "r.cons", "r.broken"};
    std::vector<std::vector<std::string>> rows;
    for (std::size_t i = 0; i < results.size(); ++i)
    {
        const MapResult& m = results[i];
        const std::string& name = m.name;
        if (!m.ok)
        {
            rows.push_back({name, "error: " + m.error});
            continue;
        }
        const QualityReport& r = m.report;
        rows.push_back({name, rk.overall[i], fixed(r.quality, 3), fixed(r.coverage, 3),
                        fixed(r.relative_accuracy.score, 3), consistencyScore(m, 0, false),
                        consistencyScore(m, 1, false), consistencyScore(m, 2, false),
                        m.matched() ? std::to_string(r.brokenness.degree) : "-", rk.coverage[i],
                        rk.relative_accuracy[i], rk.consistency[i], rk.brokenness[i]});
    }
    std::vector<std::size_t> width(header.size());
    for (std::size_t c = 0; c < header.size(); ++c) width[c] = header[c].size();
    for (const auto& row : rows)
        if (row.size() == header.size())
            for (std::size_t c = 0; c < row.size(); ++c)
                width[c] = std::max(width[c], row[c].size());
    const auto print = [&](const std::vector<std::string>& row)
    {
        std::string line;
        for (std::size_t c = 0; c < row.size(); ++c)
        {
            const std::string& cell = row[c];
            // The map name and an error message left-aligned, numbers and ranks right-aligned.
            const bool left = c == 0 || row.size() != header.size();
            const std::size_t pad = width[c] > cell.size() ? width[c] - cell.size() : 0;
            if (c) line += "  ";
            line += left ? cell + (c + 1 < row.size() ? std::string(pad, ' ') : "")
                         : std::string(pad, ' ') + cell;
        }
        os << line << "\n";
    };
    print(header);
    for (const auto& row : rows) print(row);
    os << "\nrank: by quality. rel.acc.: relative accuracy score. short, medium, long: local "
          "consistency scores (-: no pair in that class).\n"
          "broken: brokenness degree. r.*: rank by coverage, relative accuracy, mean consistency "
          "score, brokenness (1 / (1 + degree); 0 if nothing matched).\n"
          "Higher scores rank first; values equal to 3 decimals share a rank (\"1-2\").\n";
}
std::string fixed(double v, int decimals)
{
    if (!std::isfinite(v)) return "-";
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::fixed, decimals);
    return std::string(buf, res.ptr);
}

}  // namespace mrpt_topoeval::cli
