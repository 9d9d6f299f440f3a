/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt_topoeval/evaluation/evaluate_match.h>
#include <mrpt_topoeval/graph/build_graph.h>
#include <mrpt_topoeval/maps/MapLoadOptions.h>
#include <mrpt_topoeval/matching/match_graphs.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <string>

namespace mrpt_topoeval
{
/** Every stage's parameters; one INI section per stage. Missing keys keep their defaults. */
struct Parameters : public mrpt::config::CLoadableOptions
{
    MapLoadOptions map_load;                //!< `[MapLoad]` (command line options override it)
    GraphBuilderParameters graph;           //!< `[GraphBuilder]`
    VertexSimilarityParameters similarity;  //!< `[VertexSimilarity]`
    GraphMatcherParameters matcher;         //!< `[GraphMatcher]`
    QualityParameters quality;              //!< `[QualityEvaluator]`

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                            const std::string& s = {}) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c,
                          const std::string& s = {}) const override;
    /** \throws InputError naming the section, field and value. */
    void validate() const;

    /** Reads an INI file: missing file, unknown section keys (typos) and out-of-range values
     * are errors naming the file, section, key and value.
     * \throws InputError */
    static Parameters fromIniFile(const std::string& path);
    /** fromIniFile() on INI text held in memory (the Python `Config.from_dict`): the same
     * checks and messages, with `source` where the file's path would be.
     * \throws InputError */
    static Parameters fromIniText(std::string text, const std::string& source);
    /** The documented default configuration as INI text (what `topoeval config --write`
     * writes), every key with its unit and meaning. */
    static std::string defaultIniText();
};

}  // namespace mrpt_topoeval
