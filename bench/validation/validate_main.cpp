/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// topoeval_validate: runs the validation corpus (doc/validation.md) through the library and
// reports how often the matcher is right. Threads across cases; deterministic for a seed.

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/drawing.h>
#include <mrpt_topoeval/errors.h>
#include <mrpt_topoeval/json/JsonWriter.h>
#include <mrpt_topoeval/pipeline/evaluate.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>

#include "buildings.h"
#include "corpus.h"
#include "scoring.h"
#include "summary.h"

namespace fs = std::filesystem;
using namespace mrpt_topoeval;
using namespace mrpt_topoeval::validation;

namespace
{
const char* kUsage =
    "usage: topoeval_validate [--quick] [--out DIR] [--seed N] [--threads N] [--data DIR]\n"
    "                         [--no-real] [--ini FILE] [--pictures N] [--floors FILE]\n"
    "                         [--only TEXT] [--styles LIST] [--draw-ground-truths]\n"
    "                         [--chained-breaks] [--force]\n"
    "  --quick        the CI subset (~40 cases)\n"
    "  --out DIR      where cases.csv, cases.json, summary.txt, pictures/ go\n"
    "                 (default topoeval-out/validation; an existing cases.csv needs --force)\n"
    "  --seed N       corpus seed (default 1); the same seed gives the same CSV apart from times\n"
    "  --threads N    cases scored at once (default: hardware threads)\n"
    "  --data DIR     real data (default: ../shared/data beside the source tree, if present)\n"
    "  --no-real      generated buildings only\n"
    "  --ini FILE     topoeval parameters (as `topoeval compare --config`)\n"
    "  --pictures N   draw the N worst cases (most false pairs, then lowest recall)\n"
    "  --floors FILE  minimum figures; exit 3 when one is not met "
    "(bench/validation/quick_floors.txt)\n"
    "  --only TEXT    only cases whose id contains TEXT\n"
    "  --styles LIST  generated building styles, comma-separated (default: corridor_office,\n"
    "                 column_hall, angled, multi_wing; held out of that default: ring,\n"
    "                 warehouse, house)\n"
    "  --draw-ground-truths  draw every ground truth's graph into pictures/gt_NAME.png\n"
    "  --chained-breaks  broken maps' parts turned in a chain, each against the previous part\n"
    "                 about a point of their common border (a SLAM map's breaks); default: each\n"
    "                 part about a point of its own border (the standard corpus)\n"
    "Exit codes: 0 done, 2 bad arguments or input, 3 a floor or the truth check failed, 1 other.\n";

struct Options
{
    CorpusOptions corpus;
    std::string out = "topoeval-out/validation";
    int threads = 0;
    std::string ini, floors, only;
    int pictures = 0;
    bool draw_ground_truths = false;
    bool force = false;
};

/** "a,b" -> {"a", "b"}, each a style of allStyles(). */
std::vector<std::string> styleList(const std::string& text)
{
    const std::vector<std::string> known = allStyles();
    std::vector<std::string> out;
    std::stringstream ss(text);
    for (std::string item; std::getline(ss, item, ',');)
    {
        if (std::find(known.begin(), known.end(), item) == known.end())
        {
            std::string list;
            for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
            throw InputError("--styles '" + text + "': unknown style '" + item +
                             "' (known: " + list + ")");
        }
        if (std::find(out.begin(), out.end(), item) == out.end()) out.push_back(item);
    }
    if (out.empty()) throw InputError("--styles '" + text + "': no style given");
    return out;
}

Options parse(int argc, char** argv)
{
    Options o;
    o.corpus.data_dir = TOPOEVAL_SHARED_DATA_DIR;
    auto need = [&](int& i)
    {
        if (i + 1 >= argc) throw InputError(std::string(argv[i]) + " needs a value");
        return std::string(argv[++i]);
    };
    auto integer = [&](const std::string& flag, const std::string& v, long lo, long hi)
    {
        char* end = nullptr;
        const long n = std::strtol(v.c_str(), &end, 10);
        if (v.empty() || *end || n < lo || n > hi)
            throw InputError(flag + " " + v + ": expected an integer in [" + std::to_string(lo) +
                             ", " + std::to_string(hi) + "]");
        return n;
    };
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        if (a == "--quick")
            o.corpus.quick = true;
        else if (a == "--out")
            o.out = need(i);
        else if (a == "--seed")
            o.corpus.seed = static_cast<std::uint32_t>(integer(a, need(i), 0, 4000000));
        else if (a == "--threads")
            o.threads = static_cast<int>(integer(a, need(i), 0, 256));
        else if (a == "--data")
            o.corpus.data_dir = need(i);
        else if (a == "--no-real")
            o.corpus.real = false;
        else if (a == "--chained-breaks")
            o.corpus.chained_breaks = true;
        else if (a == "--ini")
            o.ini = need(i);
        else if (a == "--pictures")
            o.pictures = static_cast<int>(integer(a, need(i), 0, 1000));
        else if (a == "--floors")
            o.floors = need(i);
        else if (a == "--only")
            o.only = o.corpus.only = need(i);
        else if (a == "--styles")
            o.corpus.styles = styleList(need(i));
        else if (a == "--force")
            o.force = true;
        else if (a == "--draw-ground-truths")
            o.draw_ground_truths = true;
        else if (a == "--help" || a == "-h")
        {
            std::cout << kUsage;
            std::exit(0);
        }
        else
            throw InputError("unknown argument '" + a + "'");
    }
    return o;
}

std::string csvField(const std::string& s)
{
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
    return q + "\"";
}

std::string numText(double v, int decimals = 4)
{
    if (!std::isfinite(v)) return "";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

void writeFileAtomically(const fs::path& path, const std::string& text)
{
    const fs::path part = path.string() + ".part";
    {
        std::ofstream f(part, std::ios::binary);
        f << text;
        if (!f) throw std::runtime_error(part.string() + ": cannot write");
    }
    fs::rename(part, path);
}

std::string casesCsv(const std::vector<CaseResult>& results)
{
    std::ostringstream o;
    o << "id,building,family,source,kind,ladder,severity,param,truth_source,truth_cells,"
         "truth_on_wall,truth_share,wall_tolerance_m,distortion_m,gt_vertices,map_vertices,gt_with_"
         "counterpart,gt_kept,gt_at_cut,"
         "matched,true_pairs,precision,recall,coverage,quality,relative_rmse_m,"
         "brokenness_injected,brokenness_found,parts_with_3_pairs,parts_with_5_pairs,"
         "parts_with_5_counterparts,parts_with_3_counterparts,parts_with_3_kept,false_core,"
         "false_grown,"
         "max_group_rotation_error_deg,error,time_ms,explained_walls\n";
    for (const auto& r : results)
    {
        const auto& s = r.score;
        o << csvField(r.spec.id) << ',' << csvField(r.spec.building) << ','
          << csvField(r.spec.family) << ',' << r.spec.source << ',' << r.spec.kind << ','
          << r.spec.ladder << ',' << r.spec.severity << ',' << numText(r.spec.param) << ','
          << csvField(r.truth_source) << ',' << r.truth_check.cells << ',' << r.truth_check.on_wall
          << ',' << numText(r.truth_check.share()) << ',' << numText(r.wall_tolerance_m, 3) << ','
          << numText(r.distortion_m, 4) << ',' << s.gt_vertices << ',' << s.map_vertices << ','
          << s.gt_with_counterpart << ',' << s.gt_kept << ',' << s.gt_at_cut << ',' << s.matched
          << ',' << s.true_pairs << ',' << numText(s.precision) << ',' << numText(s.recall) << ','
          << numText(s.coverage) << ',' << numText(s.quality) << ',' << numText(s.relative_rmse_m)
          << ',' << s.brokenness_injected << ',' << s.brokenness_found << ','
          << s.parts_with_3_pairs << ',' << s.parts_with_5_pairs << ','
          << s.parts_with_5_counterparts << ',' << s.parts_with_3_counterparts << ','
          << s.parts_with_3_kept << ',' << s.false_core << ',' << s.false_grown << ','
          << numText(s.max_group_rotation_error_deg, 2) << ',' << csvField(r.error) << ','
          << numText(r.time_ms, 1) << ',' << numText(s.explained_walls) << '\n';
    }
    return o.str();
}

/** The object "lost": CaseScore::lost (doc/validation.md, "Measures", "graph stability"). */
void lostJson(JsonWriter& j, const LostVertices& l)
{
    auto n = [](std::size_t v) { return static_cast<std::uint64_t>(v); };
    j.key("lost").beginObject();
    j.key("vertices").value(n(l.vertices));
    j.key("lost").value(n(l.lost()));
    j.key("dead_end_moved").value(n(l.dead_end_moved));
    j.key("dead_end_absent").value(n(l.dead_end_absent));
    j.key("junction_with_dead_end").value(n(l.junction_with_dead_end));
    j.key("junction_moved").value(n(l.junction_moved));
    j.key("junction_absent").value(n(l.junction_absent));
    j.key("narrow_tips").value(n(l.narrow_tips));
    j.key("narrow_tips_lost").value(n(l.narrow_tips_lost));
    j.key("wide_tips").value(n(l.wide_tips));
    j.key("wide_tips_lost").value(n(l.wide_tips_lost));
    j.endObject();
}

std::string casesJson(const std::vector<CaseResult>& results, const Summary& sum,
                      const Options& opt, const std::vector<std::string>& notes)
{
    JsonWriter j;
    j.beginObject();
    j.key("seed").value(static_cast<std::uint64_t>(opt.corpus.seed));
    j.key("quick").value(opt.corpus.quick);
    j.key("chained_breaks").value(opt.corpus.chained_breaks);
    j.key("notes").beginArray();
    for (const auto& n : notes) j.value(n);
    j.endArray();
    auto agg = [&](const Aggregate& a)
    {
        j.beginObject();
        j.key("name").value(a.name);
        j.key("cases").value(static_cast<std::uint64_t>(a.cases));
        j.key("errors").value(static_cast<std::uint64_t>(a.errors));
        j.key("truth_min").value(a.truth_min, 4);
        j.key("matched").value(static_cast<std::uint64_t>(a.matched));
        j.key("true_pairs").value(static_cast<std::uint64_t>(a.true_pairs));
        j.key("precision").value(a.precision(), 4);
        j.key("recall").value(a.recall(), 4);
        j.key("broken").value(static_cast<std::uint64_t>(a.broken));
        j.key("broken_exact").value(static_cast<std::uint64_t>(a.broken_exact));
        j.key("max_rotation_error_deg").value(a.max_rotation_error_deg, 2);
        j.key("broken_observable").value(static_cast<std::uint64_t>(a.broken_observable));
        j.key("broken_observable_exact")
            .value(static_cast<std::uint64_t>(a.broken_observable_exact));
        j.key("broken_kept").value(static_cast<std::uint64_t>(a.broken_kept));
        j.key("broken_kept_exact").value(static_cast<std::uint64_t>(a.broken_kept_exact));
        j.key("broken_kept_graph_lost").beginArray();
        for (const auto& id : a.broken_kept_graph_lost) j.value(id);
        j.endArray();
        // Crops: coverage against the share kept, by the crop's rectangle (the target) and by
        // counterparts in the map's graph (before session 29).
        auto crop = [&](const char* key, const CropErrors& c)
        {
            j.key(key).beginObject();
            j.key("crops").value(static_cast<std::uint64_t>(c.crops));
            j.key("mean_error").value(c.mean, 4);
            j.key("max_error").value(c.max, 4);
            j.key("max_case").value(c.max_case);
            j.key("observable").value(static_cast<std::uint64_t>(c.observable));
            j.key("observable_within").value(static_cast<std::uint64_t>(c.observable_within));
            j.key("max_observable_error").value(c.max_observable, 4);
            j.endObject();
        };
        if (a.lost.vertices) lostJson(j, a.lost);
        if (a.crop_kept.crops)
        {
            crop("crop_kept", a.crop_kept);
            crop("crop_counterparts", a.crop_counterparts);
        }
        j.key("mean_coverage").value(a.mean_coverage, 4);
        j.key("max_coverage").value(a.max_coverage, 4);
        j.key("mean_quality").value(a.mean_quality, 4);
        j.key("mean_explained_walls").value(a.mean_explained_walls, 4);
        j.endObject();
    };
    j.key("summary").beginObject();
    j.key("kinds").beginArray();
    for (const auto& a : sum.kinds) agg(a);
    j.endArray();
    j.key("pooled");
    agg(sum.pooled);
    j.key("pooled_generated");
    agg(sum.pooled_generated);
    j.key("real");
    agg(sum.real);
    j.key("ladders").beginArray();
    for (const auto& f : sum.ladders)
    {
        j.beginObject();
        j.key("family").value(f.family);
        j.key("ladder").value(f.ladder);
        j.key("points").value(static_cast<std::uint64_t>(f.points));
        j.key("spearman").value(f.spearman, 4);
        j.key("spearman_per_building").value(f.spearman_per_building, 4);
        j.key("buildings").value(static_cast<std::uint64_t>(f.buildings));
        j.key("inversions").value(static_cast<std::uint64_t>(f.inversions));
        j.key("inversions_less_complete")
            .value(static_cast<std::uint64_t>(f.inversions_less_complete));
        j.key("inversions_within_a_cell")
            .value(static_cast<std::uint64_t>(f.inversions_within_a_cell));
        j.key("ties").value(static_cast<std::uint64_t>(f.ties));
        j.endObject();
    }
    j.endArray();
    j.key("truth_failures").value(static_cast<std::uint64_t>(sum.truth_failures));
    j.endObject();
    j.key("cases").beginArray();
    for (const auto& r : results)
    {
        const auto& s = r.score;
        j.beginObject();
        j.key("id").value(r.spec.id);
        j.key("building").value(r.spec.building);
        j.key("family").value(r.spec.family);
        j.key("source").value(r.spec.source);
        j.key("kind").value(r.spec.kind);
        j.key("severity").value(r.spec.severity);
        j.key("param").value(r.spec.param, 4);
        j.key("truth").beginObject();
        j.key("source").value(r.truth_source);
        j.key("cells").value(static_cast<std::uint64_t>(r.truth_check.cells));
        j.key("on_wall").value(static_cast<std::uint64_t>(r.truth_check.on_wall));
        j.key("share").value(r.truth_check.share(), 4);
        j.key("wall_tolerance_m").value(r.wall_tolerance_m, 3);
        j.key("free_cells").value(static_cast<std::uint64_t>(r.truth_check.free_cells));
        j.key("free_kept").value(r.truth_check.freeShare(), 4);
        j.endObject();
        j.key("distortion_m").value(r.distortion_m, 4);
        j.key("gt_vertices").value(static_cast<std::uint64_t>(s.gt_vertices));
        j.key("map_vertices").value(static_cast<std::uint64_t>(s.map_vertices));
        j.key("gt_with_counterpart").value(static_cast<std::uint64_t>(s.gt_with_counterpart));
        j.key("gt_kept").value(static_cast<std::uint64_t>(s.gt_kept));
        j.key("gt_at_cut").value(static_cast<std::uint64_t>(s.gt_at_cut));
        j.key("matched").value(static_cast<std::uint64_t>(s.matched));
        j.key("true_pairs").value(static_cast<std::uint64_t>(s.true_pairs));
        j.key("precision").value(s.precision, 4);
        j.key("recall").value(s.recall, 4);
        j.key("coverage").value(s.coverage, 4);
        j.key("quality").value(s.quality, 4);
        j.key("relative_rmse_m").value(s.relative_rmse_m, 4);
        j.key("explained_walls").value(s.explained_walls, 4);
        j.key("brokenness_injected").value(s.brokenness_injected);
        j.key("brokenness_found").value(s.brokenness_found);
        j.key("break_offsets_m").beginArray(true);
        for (const double o : s.break_offsets_m) j.value(o, 3);
        j.endArray();
        j.key("parts_with_3_pairs").value(s.parts_with_3_pairs);
        j.key("parts_with_5_pairs").value(s.parts_with_5_pairs);
        j.key("parts_with_5_counterparts").value(s.parts_with_5_counterparts);
        j.key("parts_with_3_counterparts").value(s.parts_with_3_counterparts);
        j.key("parts_with_3_kept").value(s.parts_with_3_kept);
        j.key("false_core").value(s.false_core);
        j.key("false_grown").value(s.false_grown);
        j.key("max_group_rotation_error_deg").value(s.max_group_rotation_error_deg, 2);
        if (s.lost.vertices) lostJson(j, s.lost);
        if (!s.parts.empty())
        {
            j.key("broken_cause").value(brokenCause(s));
            j.key("parts").beginArray();
            for (const auto& p : s.parts)
            {
                j.beginObject();
                j.key("part").value(p.part);
                j.key("yaw_deg").value(p.yaw_deg, 2);
                j.key("counterparts").value(static_cast<std::uint64_t>(p.counterparts));
                j.key("true_pairs").value(static_cast<std::uint64_t>(p.true_pairs));
                j.endObject();
            }
            j.endArray();
            j.key("groups").beginArray();
            for (const auto& g : s.groups)
            {
                j.beginObject();
                j.key("yaw_deg").value(g.yaw_deg, 2);
                j.key("part").value(g.part);
                j.key("offset_m").value(g.offset_m, 3);
                j.key("true_offset_m").value(g.true_offset_m, 3);
                j.key("vertices_per_part").beginObject();
                for (const auto& [part, n] : g.vertices_per_part)
                    j.key(std::to_string(part)).value(static_cast<std::uint64_t>(n));
                j.endObject();
                j.endObject();
            }
            j.endArray();
        }
        j.key("messages").beginArray();
        for (const auto& m : s.messages) j.value(m);
        j.endArray();
        j.key("error").value(r.error);
        j.key("time_ms").value(r.time_ms, 1);
        j.endObject();
    }
    j.endArray();
    j.endObject();
    return j.str();
}

template <typename F>
void parallelFor(std::size_t n, int threads, F&& f)
{
    std::atomic<std::size_t> next{0};
    auto worker = [&]
    {
        for (std::size_t i = next++; i < n; i = next++) f(i);
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
}

double msSince(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

/** Builds the case's map and scores it; the graphs and report are returned for pictures. */
CaseResult runCase(const Corpus& corpus, const CaseSpec& spec, const TopologyGraph* gt_graph_in,
                   const Parameters& params, TopologyGraph* gt_graph_out = nullptr,
                   TopologyGraph* map_graph_out = nullptr, QualityReport* report_out = nullptr,
                   mrpt::maps::COccupancyGridMap2D* map_out = nullptr)
{
    CaseResult r;
    r.spec = spec;
    try
    {
        Variant v = makeCaseMap(corpus, spec);
        const auto& gt_grid = groundTruthOf(corpus, spec);
        r.truth_source = v.truth.source;
        r.wall_tolerance_m = v.truth.wall_tolerance_m;
        r.truth_check = checkTruth(gt_grid, v.map, v.truth);
        r.distortion_m = mapDistortion(v.map, v.truth);
        TopologyGraph gt_graph =
            gt_graph_in ? *gt_graph_in : buildTopologyGraph(gt_grid, params.graph);
        TopologyGraph map_graph;
        const auto t0 = std::chrono::steady_clock::now();
        QualityReport report = evaluate(gt_graph, gt_grid, v.map, params, &map_graph);
        r.time_ms = msSince(t0);
        r.score = scoreCase(gt_graph, map_graph, report, v.truth);
        if (gt_graph_out) *gt_graph_out = std::move(gt_graph);
        if (map_graph_out) *map_graph_out = std::move(map_graph);
        if (report_out) *report_out = std::move(report);
        if (map_out) *map_out = std::move(v.map);
    }
    catch (const std::exception& e)
    {
        r.error = e.what();
    }
    return r;
}

std::string safeName(const std::string& id)
{
    std::string s = id;
    for (char& c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-'))
            c = '_';
    return s;
}
}  // namespace

int main(int argc, char** argv)
{
    Options opt;
    Parameters params;
    std::string floors_text;
    try
    {
        opt = parse(argc, argv);
        if (!opt.ini.empty()) params = Parameters::fromIniFile(opt.ini);
        if (!opt.floors.empty())
        {
            std::ifstream f(opt.floors);
            if (!f) throw InputError(opt.floors + ": cannot read the floors file");
            floors_text.assign(std::istreambuf_iterator<char>(f), {});
        }
        if (fs::exists(fs::path(opt.out) / "cases.csv") && !opt.force)
            throw InputError(opt.out + "/cases.csv exists: use --force to replace it, or --out");
    }
    catch (const std::exception& e)
    {
        std::cerr << "topoeval_validate: " << e.what() << "\n" << kUsage;
        return 2;
    }
    params.similarity.threads = 1;  // cases run in parallel instead
    const int threads = opt.threads > 0
                            ? opt.threads
                            : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    try
    {
        const auto t_start = std::chrono::steady_clock::now();
        Corpus corpus = buildCorpus(opt.corpus);
        if (!opt.only.empty())
            corpus.cases.erase(std::remove_if(corpus.cases.begin(), corpus.cases.end(),
                                              [&](const CaseSpec& c)
                                              { return c.id.find(opt.only) == std::string::npos; }),
                               corpus.cases.end());
        std::cerr << "validate: " << corpus.ground_truths.size() << " ground truths, "
                  << corpus.real_pairs.size() << " real pairs, " << corpus.cases.size()
                  << " cases, " << threads << " threads (corpus ready in "
                  << numText(msSince(t_start) / 1000.0, 1) << " s)\n";
        for (const auto& n : corpus.notes) std::cerr << "validate: " << n << "\n";

        std::vector<TopologyGraph> gt_graphs(corpus.ground_truths.size());
        parallelFor(
            gt_graphs.size(), threads,
            [&](std::size_t i)
            { gt_graphs[i] = buildTopologyGraph(corpus.ground_truths[i].grid, params.graph); });

        if (opt.draw_ground_truths)
        {
            fs::create_directories(fs::path(opt.out) / "pictures");
            for (std::size_t i = 0; i < gt_graphs.size(); ++i)
            {
                DrawOptions d;
                d.scale = 1;
                const fs::path png = fs::path(opt.out) / "pictures" /
                                     ("gt_" + safeName(corpus.ground_truths[i].name) + ".png");
                drawTopologyGraph(corpus.ground_truths[i].grid, gt_graphs[i], d)
                    .saveToFile(png.string());
            }
        }

        std::vector<CaseResult> results(corpus.cases.size());
        std::atomic<std::size_t> done{0};
        std::mutex print;
        parallelFor(
            corpus.cases.size(), threads,
            [&](std::size_t i)
            {
                const CaseSpec& c = corpus.cases[i];
                results[i] =
                    runCase(corpus, c, c.real_pair >= 0 ? nullptr : &gt_graphs[c.gt], params);
                const std::size_t k = ++done;
                std::lock_guard<std::mutex> lock(print);
                const auto& r = results[i];
                std::fprintf(stderr, "[%3zu/%zu] %-40s matched %3zu true %3zu%s\n", k,
                             results.size(), c.id.c_str(), r.score.matched, r.score.true_pairs,
                             r.error.empty() ? "" : ("  ERROR " + r.error).c_str());
            });
        const Summary sum = summarize(results);
        const std::string table = formatSummary(sum, results);
        std::cout << table;

        fs::create_directories(opt.out);
        writeFileAtomically(fs::path(opt.out) / "cases.csv", casesCsv(results));
        writeFileAtomically(fs::path(opt.out) / "cases.json",
                            casesJson(results, sum, opt, corpus.notes));
        writeFileAtomically(fs::path(opt.out) / "summary.txt", table);

        if (opt.pictures > 0)
        {
            std::vector<std::size_t> order(results.size());
            for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
            auto badness = [&](std::size_t i)
            {
                const auto& s = results[i].score;
                const double recall = std::isfinite(s.recall) ? s.recall : 1.0;
                return std::make_pair(static_cast<double>(s.matched - s.true_pairs), 1.0 - recall);
            };
            std::stable_sort(order.begin(), order.end(),
                             [&](auto a, auto b) { return badness(a) > badness(b); });
            fs::create_directories(fs::path(opt.out) / "pictures");
            for (int k = 0; k < opt.pictures && k < static_cast<int>(order.size()); ++k)
            {
                const CaseSpec& c = corpus.cases[order[static_cast<std::size_t>(k)]];
                TopologyGraph g, m;
                QualityReport rep;
                mrpt::maps::COccupancyGridMap2D map;
                const CaseResult r = runCase(corpus, c, nullptr, params, &g, &m, &rep, &map);
                if (!r.error.empty())
                {
                    std::cerr << "validate: cannot draw " << c.id << ": " << r.error << "\n";
                    continue;
                }
                DrawOptions d;
                d.scale = 1;
                const auto img = drawQualityReport(groundTruthOf(corpus, c), g, map, m, rep, d);
                char prefix[16];
                std::snprintf(prefix, sizeof prefix, "%02d_", k + 1);
                const fs::path png =
                    fs::path(opt.out) / "pictures" / (prefix + safeName(c.id) + ".png");
                img.saveToFile(png.string());
                // The case's ground truth and map beside its picture, so that the case can be
                // re-run alone (`topoeval compare NN_case.gt.gridmap NN_case.map.gridmap`).
                auto writeGrid =
                    [&](const mrpt::maps::COccupancyGridMap2D& grid, const char* suffix)
                {
                    const fs::path file = fs::path(png).replace_extension(suffix);
                    const fs::path tmp = fs::path(file).concat(".tmp");
                    {
                        mrpt::io::CFileGZOutputStream f(tmp.string());
                        auto arch = mrpt::serialization::archiveFrom(f);
                        arch << grid;
                    }
                    fs::rename(tmp, file);
                };
                writeGrid(groundTruthOf(corpus, c), ".gt.gridmap");
                writeGrid(map, ".map.gridmap");
                if (!r.score.counterpart_lines.empty())
                {
                    std::string text;
                    for (const auto& line : r.score.counterpart_lines) text += line + "\n";
                    writeFileAtomically(fs::path(png).replace_extension(".counterparts.txt"), text);
                }
                if (!r.score.false_pairs.empty())
                {
                    std::string text;
                    for (const auto& line : r.score.false_pairs) text += line + "\n";
                    writeFileAtomically(fs::path(png).replace_extension(".false_pairs.txt"), text);
                }
                std::cerr << "validate: wrote " << png.string() << " ("
                          << r.score.matched - r.score.true_pairs << " false of " << r.score.matched
                          << ", recall " << numText(r.score.recall, 2) << ")\n";
            }
        }
        std::cerr << "validate: wrote " << opt.out << "/cases.csv, cases.json, summary.txt in "
                  << numText(msSince(t_start) / 1000.0, 1) << " s\n";

        int rc = 0;
        if (sum.truth_failures > 0)
        {
            std::cerr << "validate: the truth check failed for " << sum.truth_failures
                      << " corpus case(s) (a generator bug; see truth_share in cases.csv)\n";
            rc = 3;
        }
        if (!opt.floors.empty())
            for (const auto& f : checkFloors(sum, floors_text, opt.floors))
            {
                std::cerr << "validate: FLOOR " << f << "\n";
                rc = 3;
            }
        return rc;
    }
    catch (const InputError& e)
    {
        std::cerr << "topoeval_validate: " << e.what() << "\n";
        return 2;
    }
    catch (const std::exception& e)
    {
        std::cerr << "topoeval_validate: internal error: " << e.what() << "\n";
        return 1;
    }
}
