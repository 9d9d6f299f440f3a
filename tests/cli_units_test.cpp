/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// The app logic behind `topoeval rawlog`, `series` and `rank`, in-process: report.json, score
// rows and scores.csv, which files of a folder are maps, and rank's worker pool and ranks.
#include <gtest/gtest.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/maps/load_map.h>
#include <mrpt_topoeval/scores/scores.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "rank_maps.h"
#include "rawlog_report.h"
#include "test_paths.h"

using namespace mrpt_topoeval;

namespace
{
ScoreRow sampleRow()
{
    ScoreRow r;
    r.step = 3;
    r.entry = 697;
    r.time_s = 34.8;
    r.scans = 349;
    r.vertices = 24;
    r.coverage = 0.875;
    r.relative_accuracy = 0.8347697770123;
    r.consistency_short = 1.0;
    r.brokenness = 1;
    r.quality = 0.9149639396;
    r.scoring_ms = 26.5;
    r.explained_walls = 0.96123456789;
    return r;
}
}  // namespace

TEST(ScoreRows, JsonHasTheCsvColumnsWithTenSignificantDigits)
{
    JsonWriter w;
    writeScoreRow(w, sampleRow());
    EXPECT_EQ(w.str(),
              "{\"step\": 3, \"entry\": 697, \"time_s\": 34.8, \"scans\": 349, \"vertices\": 24, "
              "\"coverage\": 0.875, \"relative_accuracy\": 0.834769777, \"consistency_short\": "
              "1, \"consistency_medium\": 0, \"consistency_long\": 0, \"brokenness\": 1, "
              "\"quality\": 0.9149639396, \"scoring_ms\": 26.5, \"explained_walls\": "
              "0.9612345679}\n");
    ScoreRow no_time = sampleRow();
    no_time.time_s = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(scoreCsvLine(no_time).substr(0, 8), "3,697,,3");
}

TEST(ScoreRows, CsvIsWrittenUnderATemporaryNameAndRenamedOnCommit)
{
    const auto dir = std::filesystem::temp_directory_path() / "topoeval_cli_units_csv";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "scores.csv").string();
    {
        ScoresCsv csv(path);
        csv.append(sampleRow());
        EXPECT_TRUE(std::filesystem::exists(path + ".part"));
        EXPECT_FALSE(std::filesystem::exists(path));
        csv.commit();
        EXPECT_EQ(csv.rows(), 1u);
    }
    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(text, scoreCsvHeader() + "\n" + scoreCsvLine(sampleRow()) + "\n");
    std::filesystem::remove_all(dir);
}

TEST(RawlogReport, ErrorReportHasNullsForWhatTheScorerDidNotReturn)
{
    cli::RawlogRun run;
    run.rawlog = "log.rawlog";
    run.ground_truth = "gt.yaml";
    run.topoeval_ini = "[MapLoad]\n";
    RawlogProbe probe;
    probe.messages = {"a note"};
    const std::string js =
        cli::rawlogErrorReportJson(run, "log.rawlog: entry 5 is corrupt", 2, probe, sampleRow());
    EXPECT_EQ(js.rfind("{\n  \"rawlog\": \"log.rawlog\",\n  \"ground_truth\": \"gt.yaml\",\n"
                       "  \"stop\": \"error\",\n  \"stop_entry\": null,\n",
                       0),
              0u)
        << js;
    EXPECT_NE(js.find("\"snapshots\": 2,\n  \"messages\": [\"a note\"],"), std::string::npos);
    EXPECT_NE(js.find("\"topoeval_ini\": \"[MapLoad]\\n\"}"), std::string::npos);
    EXPECT_NE(js.find("\"final_report\": null,\n  \"timing_ms\": null\n}\n"), std::string::npos);
}

TEST(RawlogReport, FinalReportIsNestedAndTimesComeLast)
{
    cli::RawlogRun run;
    RawlogScoreResult res;
    res.slam_ms = 1.5;
    const std::string js = cli::rawlogReportJson(run, res, Parameters{});
    EXPECT_NE(js.find("\"final_scores\": null,\n  \"final_report\": {\n    \""), std::string::npos)
        << js;
    EXPECT_NE(
        js.find("\n  },\n  \"timing_ms\": {\"slam\": 1.5, \"scoring\": 0, \"total\": 0}\n}\n"),
        std::string::npos)
        << js;
}

TEST(MapFiles, EveryVerbKnowsAMapByTheSameNames)
{
    for (const char* name : {"a.yaml", "b.YML", "c.png", "d.pgm", "e.gridmap.gz", "f.simplemap"})
        EXPECT_TRUE(isMapFile(name)) << name;
    for (const char* name : {".yaml", "notes.txt", "map.gz", "scores.csv"})
        EXPECT_FALSE(isMapFile(name)) << name;
    EXPECT_EQ(mapFormatFromName("x/house.GRIDMAP.gz"), MapFormat::Gridmap);
    EXPECT_EQ(mapFormatFromName("house.jpeg"), MapFormat::Image);
    EXPECT_FALSE(mapFormatFromName("house.tif").has_value());
}

// ---------------------------------------------------------------- rank

// The pool scores every map in the order given whatever the thread count; a missing map is an
// error in its row and the others are still ranked.
TEST(Rank, ScoresMapsInTheOrderGivenWhateverTheThreads)
{
    const std::string maps = mrpt_topoeval::testing::shareDir() + "/maps/";
    const std::string gt_file = maps + "map_2333d24.yaml";
    if (!std::filesystem::exists(gt_file)) GTEST_SKIP() << gt_file << " is not there";
    const std::vector<std::string> files = {maps + "map_2333d24.yaml", maps + "missing.yaml",
                                            maps + "map_6ccdcaa.yaml"};
    Parameters params;
    const LoadedMap gt = loadMap(gt_file, params.map_load);
    const TopologyGraph gt_graph = buildTopologyGraph(gt.grid, params.graph);

    std::string csv[2];
    for (const int threads : {1, 3})
    {
        params.similarity.threads = threads;
        std::size_t workers = 0;
        const std::vector<cli::MapResult> results =
            cli::scoreMaps(gt_graph, gt.grid, files, params, false, &workers);
        EXPECT_EQ(workers, static_cast<std::size_t>(threads));
        ASSERT_EQ(results.size(), files.size());
        for (std::size_t i = 0; i < files.size(); ++i) EXPECT_EQ(results[i].file, files[i]);
        EXPECT_TRUE(results[0].ok && results[2].ok);
        EXPECT_FALSE(results[1].ok);
        EXPECT_FALSE(results[1].internal_error);
        EXPECT_NE(results[1].error.find("missing.yaml"), std::string::npos) << results[1].error;
        EXPECT_DOUBLE_EQ(results[0].report.coverage, 1.0) << "the ground truth against itself";

        const cli::Ranking rk = cli::rankMaps(results);
        EXPECT_EQ(rk.overall, (std::vector<std::string>{"1", "", "2"}));
        csv[threads == 1 ? 0 : 1] = cli::rankCsv(results, rk);
    }
    EXPECT_EQ(csv[0], csv[1]);
}
