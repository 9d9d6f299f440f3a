/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// What every verb of the `topoeval` command shares: exit codes, error reporting, command-line
// parsing, configuration loading and output checks. The library does the work; this only
// formats.

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_topoeval/Parameters.h>
#include <mrpt_topoeval/errors.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mrpt_topoeval::cli
{
/** Exit codes of every verb (documented in README, "Exit codes"). */
enum ExitCode : int
{
    kExitOk = 0,             //!< Done (warnings may have been printed).
    kExitInternalError = 1,  //!< A bug or resource failure (out of memory).
    kExitBadInput = 2,       //!< Bad input file, bad parameter, or command-line misuse.
    kExitOutputError = 3,    //!< An output could not be written or would overwrite a file.
    kExitStoppedEarly = 4,   //!< `rawlog` only: reading stopped before the end of the rawlog
                             //!< (Ctrl-C, truncated or corrupt rawlog); the outputs for the
                             //!< part done were written.
};

/** A command-line mistake (unknown option, missing argument): exit code 2 like bad input. */
class UsageError : public InputError
{
public:
    using InputError::InputError;
};

/** `topoeval 0.1.0 (MRPT 2.5.8)`. */
std::string versionLine();

/** Runs `body` and turns exceptions into one-line messages on stderr and exit codes:
 * InputError -> "topoeval: error: ..." and 2, OutputError -> 3, anything else -> 1. */
int runGuarded(const std::function<int()>& body);

/** The text of the exception being handled, on one line, as runGuarded() would print it
 * ("out of memory" for std::bad_alloc). Call it in a catch block only. */
std::string currentErrorText();

/** Prints "topoeval: warning: <msg>" on stderr. */
void printWarning(const std::string& msg);

/** Prints "topoeval: error: <msg>" on stderr, on one line, for errors a verb reports without
 * stopping (`rank`: a map that cannot be read). */
void printError(const std::string& msg);

/** A verb's TCLAP command line whose help, version and errors are ours: `--help` prints the
 * usage on stdout and the verb exits 0; a parse error becomes a one-line UsageError. */
class VerbCommandLine
{
public:
    /** `verb` is the verb's name ("graph"), `description` the paragraph under its usage. */
    VerbCommandLine(const std::string& verb, const std::string& description);

    TCLAP::CmdLine& cmd() { return m_cmd; }

    /** Parses `argv` (argv[0] is ignored). Returns an exit code if the verb is done
     * (`--help`, `--version`: 0), nothing if it should run.
     * \throws UsageError on unknown options, bad values, missing values. */
    std::optional<int> parse(int argc, char** argv);

    /** A UsageError ending in "; see 'topoeval VERB --help'". */
    UsageError usageError(const std::string& what) const;

private:
    class Output : public TCLAP::StdOutput
    {
    public:
        bool done = false;  // help or version was printed
        std::string error;  // the parse error, if any
        void usage(TCLAP::CmdLineInterface& c) override;
        void version(TCLAP::CmdLineInterface& c) override;
        void failure(TCLAP::CmdLineInterface& c, TCLAP::ArgException& e) override;
    };

    std::string m_verb;
    Output m_output;  // declared before m_cmd, which points to it
    TCLAP::CmdLine m_cmd;
};

/** Default parameters, or those of `config_path` (if not empty), with `--resolution`
 * overriding `[MapLoad] resolution_m` when given. \throws InputError, UsageError */
Parameters loadParameters(const std::string& config_path, std::optional<double> resolution_m);

/** Checks an output path before any work is done, so a run does not fail at its end:
 * refuses a path that is one of `inputs` (UsageError) and an existing file without `force`
 * (OutputError). writeFileAtomic() checks again when writing. */
void checkOutputPath(const std::string& out, bool force, const std::vector<std::string>& inputs);

/** Flushes stdout. \throws OutputError if it could not be written (full disk, closed pipe). */
void flushStdout();

// ---- Verbs: each takes argv with argv[0] = "topoeval VERB" and returns an exit code.

/** `topoeval graph MAP [options]`: Topology Graph summary, JSON and picture. */
int verbGraph(int argc, char** argv);
/** `topoeval config [--write F.ini [--force] | --check F.ini]`. */
int verbConfig(int argc, char** argv);
/** `topoeval compare GT MAP [options]`: quality report of one map (verb_compare.cpp). */
int verbCompare(int argc, char** argv);
/** `topoeval rank GT MAP... [options]`: several maps scored and ranked (verb_rank.cpp). */
int verbRank(int argc, char** argv);
/** `topoeval rawlog RAWLOG --ground-truth GT [options]`: ICP-SLAM on a rawlog, scores over
 * time (verb_rawlog.cpp). Exit code 4: stopped early, outputs for the part done written. */
int verbRawlog(int argc, char** argv);
/** `topoeval series GT MAP... [options]`: the same scores over saved maps (verb_series.cpp). */
int verbSeries(int argc, char** argv);

}  // namespace mrpt_topoeval::cli
