/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// `topoeval VERB ...`: a thin dispatcher; each verb lives in its own file.

#include <iostream>
#include <string>
#include <vector>

#include "cli_common.h"

namespace mrpt_topoeval::cli
{
/** `topoeval match GT MAP [options]`: the match of two maps' Topology Graphs (verb_match.cpp). */
int verbMatch(int argc, char** argv);

namespace
{
struct Verb
{
    const char* name;
    const char* summary;
    int (*run)(int, char**);
};

const std::vector<Verb>& verbs()
{
    static const std::vector<Verb> kVerbs = {
        {"graph", "Build a map's Topology Graph: summary, --json graph, --image picture.",
         verbGraph},
        {"match", "Match a map's graph against the ground truth's: counts, --json, --image.",
         verbMatch},
        {"compare", "Quality of a map against the ground truth: report, --json, --image.",
         verbCompare},
        {"rank", "Score several maps against one ground truth and rank them: table, --csv.",
         verbRank},
        {"rawlog", "ICP-SLAM on a rawlog, the map scored every N scans: CSV, plot, report.",
         verbRawlog},
        {"series", "Score a sequence of saved maps over time: the same CSV and plot.", verbSeries},
        {"config", "Print, --write or --check the INI configuration.", verbConfig},
    };
    return kVerbs;
}

void printHelp(std::ostream& os)
{
    os << "topoeval: evaluates 2D occupancy grid maps with the Topology Graph method of\n"
          "Schwertfeger & Birk (2013).\n\n"
          "Usage: topoeval VERB [options]      (topoeval VERB --help for a verb's options)\n\n"
          "Verbs:\n";
    for (const Verb& v : verbs())
    {
        std::string name = v.name;
        name.resize(10, ' ');
        os << "  " << name << v.summary << "\n";
    }
    os << "\nOptions:\n"
          "  --help      This list.\n"
          "  --version   The version.\n\n"
          "Exit codes: 0 ok, 1 internal error, 2 bad input or usage, 3 output error,\n"
          "4 stopped early (rawlog: Ctrl-C or truncated/corrupt rawlog; outputs written).\n";
}

int dispatch(int argc, char** argv)
{
    if (argc < 2)
    {
        printHelp(std::cerr);
        return kExitBadInput;
    }
    const std::string first = argv[1];
    if (first == "--help" || first == "-h" || first == "help")
    {
        // `topoeval help VERB` is `topoeval VERB --help`.
        if (first == "help" && argc >= 3)
        {
            for (const Verb& v : verbs())
                if (argv[2] == std::string(v.name))
                {
                    char help_flag[] = "--help";
                    char* args[] = {argv[0], help_flag};
                    return v.run(2, args);
                }
            throw UsageError(std::string("unknown verb '") + argv[2] +
                             "'; run 'topoeval --help' for the list");
        }
        printHelp(std::cout);
        flushStdout();
        return kExitOk;
    }
    if (first == "--version")
    {
        std::cout << versionLine() << "\n";
        flushStdout();
        return kExitOk;
    }
    for (const Verb& v : verbs())
        if (first == v.name) return v.run(argc - 1, argv + 1);
    if (!first.empty() && first[0] == '-')
        throw UsageError("unknown option '" + first + "'; run 'topoeval --help'");
    throw UsageError("unknown verb '" + first + "'; run 'topoeval --help' for the list");
}
}  // namespace
}  // namespace mrpt_topoeval::cli

int main(int argc, char** argv)
{
    using namespace mrpt_topoeval::cli;
    return runGuarded([&] { return dispatch(argc, argv); });
}
