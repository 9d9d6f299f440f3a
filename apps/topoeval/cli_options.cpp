/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "cli_options.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt_topoeval/output.h>
#include <mrpt_topoeval/similarity/vertex_similarity.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <tuple>

namespace fs = std::filesystem;

namespace mrpt_topoeval::cli
{
double msSince(Clock::time_point t0)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

std::string fmt(const char* format, double v)
{
    char buf[64];
    std::snprintf(buf, sizeof(buf), format, v);
    return buf;
}

namespace
{
std::string lowerExtension(const std::string& path)
{
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return ext;
}
}  // namespace

bool endsWithPng(const std::string& path) { return lowerExtension(path) == ".png"; }

bool endsWithHtml(const std::string& path)
{
    const std::string ext = lowerExtension(path);
    return ext == ".html" || ext == ".htm";
}

std::string iniText(const Parameters& params)
{
    mrpt::config::CConfigFileMemory ini;
    params.saveToConfigFile(ini);
    return ini.getContent();
}

LoadedMap loadMapWarning(const std::string& path, const MapLoadOptions& opts)
{
    LoadedMap m = loadMap(path, opts);
    for (const auto& note : m.notes) printWarning(m.file + ": " + note);
    return m;
}

LoadedMap loadMapTimed(const std::string& path, const MapLoadOptions& opts, double& ms)
{
    const auto t0 = Clock::now();
    LoadedMap m = loadMapWarning(path, opts);
    ms = msSince(t0);
    return m;
}

std::vector<std::pair<std::string, double>> orderedTimings(const std::map<std::string, double>& t,
                                                           const std::vector<std::string>& order)
{
    std::vector<std::pair<std::string, double>> out;
    for (const auto& name : order)
        if (const auto it = t.find(name); it != t.end()) out.emplace_back(*it);
    for (const auto& kv : t)
        if (std::find(order.begin(), order.end(), kv.first) == order.end()) out.emplace_back(kv);
    return out;
}

std::string timingList(const std::vector<std::pair<std::string, double>>& steps)
{
    std::string out;
    bool first = true;
    for (const auto& [step, ms] : steps)
    {
        out += (first ? "" : ", ") + step + " " + fmt("%.1f", ms);
        first = false;
    }
    return out;
}

void checkDistinctOutputs(const VerbCommandLine& cl, const OutputList& outputs)
{
    for (std::size_t i = 0; i < outputs.size(); ++i)
        for (std::size_t k = i + 1; k < outputs.size(); ++k)
            if (fs::absolute(outputs[i].second).lexically_normal() ==
                fs::absolute(outputs[k].second).lexically_normal())
                throw cl.usageError(outputs[i].first + " and " + outputs[k].first +
                                    " name the same file " + outputs[i].second);
}

// ---------------------------------------------------------------- standard options

void StandardOptions::addForce(const std::string& help)
{
    m_force = std::make_unique<TCLAP::SwitchArg>("f", "force", help, m_cl.cmd());
}

void StandardOptions::addImage(const std::string& help)
{
    m_image = std::make_unique<TCLAP::ValueArg<std::string>>("i", "image", help, false, "",
                                                             "OUT.png", m_cl.cmd());
}

void StandardOptions::addJson(const std::string& help)
{
    m_json = std::make_unique<TCLAP::ValueArg<std::string>>("j", "json", help, false, "",
                                                            "OUT.json", m_cl.cmd());
}

void StandardOptions::addHtml(const std::string& help)
{
    m_html = std::make_unique<TCLAP::ValueArg<std::string>>("", "html", help, false, "", "OUT.html",
                                                            m_cl.cmd());
}

void StandardOptions::addThreads(const std::string& help)
{
    m_threads =
        std::make_unique<TCLAP::ValueArg<int>>("", "threads", help, false, 0, "N", m_cl.cmd());
}

void StandardOptions::addSimilarity()
{
    m_similarity = std::make_unique<TCLAP::ValueArg<std::string>>(
        "s", "similarity",
        "Vertex similarity: 'attributes' (fast) or 'icp' (obstacles around each vertex aligned "
        "by ICP); overrides [VertexSimilarity] mode (default attributes).",
        false, "", "attributes|icp", m_cl.cmd());
}

void StandardOptions::addResolution()
{
    m_resolution = std::make_unique<TCLAP::ValueArg<double>>(
        "r", "resolution",
        "Cell size for plain images and .simplemap files [m/cell]; overrides [MapLoad] "
        "resolution_m (default 0.05).",
        false, 0.0, "R", m_cl.cmd());
}

void StandardOptions::addConfig(const std::string& help)
{
    m_config = std::make_unique<TCLAP::ValueArg<std::string>>("c", "config", help, false, "",
                                                              "F.ini", m_cl.cmd());
}

void StandardOptions::addGtAndMap()
{
    // One argument for both files: TCLAP allows a single optional unlabeled argument, and
    // checking the count ourselves names what is missing.
    m_maps = std::make_unique<TCLAP::UnlabeledMultiArg<std::string>>(
        "GT_MAP",
        "Exactly two maps: the ground truth, then the map to evaluate. ROS map_server .yaml, "
        "image (.png .pgm .bmp .jpg), MRPT .gridmap[.gz] or .simplemap[.gz].",
        false, "GT MAP", m_cl.cmd());
}

std::pair<std::string, std::string> StandardOptions::gtAndMap(
    const std::string& too_many_hint) const
{
    const std::vector<std::string> maps = m_maps ? m_maps->getValue() : std::vector<std::string>();
    if (maps.empty()) throw m_cl.usageError("missing the GT and MAP arguments");
    if (maps.size() == 1) throw m_cl.usageError("missing the MAP argument");
    if (maps.size() > 2)
        throw m_cl.usageError("expected two maps (GT MAP), got " + std::to_string(maps.size()) +
                              "; unexpected '" + maps[2] + "'" + too_many_hint);
    if (maps[0].empty()) throw m_cl.usageError("the GT argument is empty");
    if (maps[1].empty()) throw m_cl.usageError("the MAP argument is empty");
    return {maps[0], maps[1]};
}

std::vector<std::string> StandardOptions::writeOutputs(const std::string& json_text,
                                                       const mrpt::img::CImage& picture,
                                                       const std::string& html_text) const
{
    std::vector<std::string> written;
    if (!json().empty())
    {
        writeFileAtomic(json(), json_text, force());
        written.push_back(json());
    }
    if (!image().empty())
    {
        writePngAtomic(image(), picture, force());
        written.push_back(image());
    }
    if (!html().empty())
    {
        writeFileAtomic(html(), html_text, force());
        written.push_back(html());
    }
    return written;
}

bool StandardOptions::force() const { return m_force && m_force->getValue(); }
std::string StandardOptions::json() const { return m_json ? m_json->getValue() : ""; }
std::string StandardOptions::image() const { return m_image ? m_image->getValue() : ""; }
std::string StandardOptions::config() const { return m_config ? m_config->getValue() : ""; }
std::string StandardOptions::html() const { return m_html ? m_html->getValue() : ""; }

void StandardOptions::checkJsonImage() const
{
    if (m_json && m_json->isSet() && json().empty())
        throw m_cl.usageError("--json needs a file name");
    if (m_image && m_image->isSet() && image().empty())
        throw m_cl.usageError("--image needs a file name");
    if (!image().empty() && !endsWithPng(image()))
        throw m_cl.usageError("--image " + image() + ": pictures are PNG; use a .png file name");
    if (m_html && m_html->isSet() && html().empty())
        throw m_cl.usageError("--html needs a file name");
    if (!html().empty() && !endsWithHtml(html()))
        throw m_cl.usageError("--html " + html() +
                              ": the report is a web page; use a .html file name");
}

OutputList StandardOptions::outputs() const
{
    OutputList out;
    if (!json().empty()) out.emplace_back("--json", json());
    if (!image().empty()) out.emplace_back("--image", image());
    if (!html().empty()) out.emplace_back("--html", html());
    return out;
}

Parameters StandardOptions::parameters() const
{
    const bool threads_set = m_threads && m_threads->isSet();
    const bool similarity_set = m_similarity && m_similarity->isSet();
    // The same bounds as [VertexSimilarity] threads, reported as the option the user typed.
    if (threads_set && (m_threads->getValue() < 0 || m_threads->getValue() > 256))
        throw m_cl.usageError("--threads " + std::to_string(m_threads->getValue()) +
                              " violates 0 <= N <= 256");
    const std::string similarity_mode = similarity_set ? m_similarity->getValue() : "";
    if (similarity_set && similarity_mode != "attributes" && similarity_mode != "icp")
        throw m_cl.usageError("--similarity '" + similarity_mode +
                              "' is not one of: attributes, icp");

    Parameters params =
        loadParameters(config(), m_resolution && m_resolution->isSet()
                                     ? std::optional<double>(m_resolution->getValue())
                                     : std::nullopt);
    // Verbs without --similarity and --threads take loadParameters()'s validation as it is.
    if (!m_similarity && !m_threads) return params;
    if (similarity_set) params.similarity.mode = similarityModeFromString(similarity_mode);
    if (threads_set) params.similarity.threads = m_threads->getValue();
    params.validate();
    return params;
}

void StandardOptions::checkOutputPaths(const std::vector<std::string>& inputs) const
{
    for (const auto& out : outputs()) checkOutputPath(out.second, force(), inputs);
}

GtAndMapRun StandardOptions::gtAndMapRun(const std::string& too_many_hint) const
{
    GtAndMapRun run;
    std::tie(run.gt_path, run.map_path) = gtAndMap(too_many_hint);
    checkJsonImage();
    checkDistinctOutputs(m_cl, outputs());
    run.params = parameters();
    // Refuse unwritable outputs now rather than after the work.
    checkOutputPaths({run.gt_path, run.map_path, config()});
    return run;
}

}  // namespace mrpt_topoeval::cli
