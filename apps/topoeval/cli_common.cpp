/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "cli_common.h"

#include <mrpt/core/exceptions.h>
#include <mrpt/system/os.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <new>
#include <sstream>

namespace fs = std::filesystem;

namespace mrpt_topoeval::cli
{
namespace
{
/** Messages promise one line: fold any line breaks a lower layer put in. */
std::string oneLine(const std::string& msg) { return messageOnOneLine(msg); }
}  // namespace

void printError(const std::string& msg)
{
    std::cout.flush();  // keep stdout and stderr in order on a terminal
    std::cerr << "topoeval: error: " << oneLine(msg) << std::endl;
}

std::string versionLine()
{
    return std::string("topoeval ") + TOPOEVAL_VERSION + " (" + mrpt::system::MRPT_getVersion() +
           ")";
}

int runGuarded(const std::function<int()>& body)
{
    try
    {
        return body();
    }
    catch (const InputError& e)  // includes UsageError
    {
        printError(e.what());
        return kExitBadInput;
    }
    catch (const OutputError& e)
    {
        printError(e.what());
        return kExitOutputError;
    }
    catch (const std::bad_alloc&)
    {
        printError("out of memory");
        return kExitInternalError;
    }
    catch (const std::exception& e)
    {
        std::cout.flush();
        std::cerr << "topoeval: internal error: " << mrpt::exception_to_str(e) << std::endl;
        return kExitInternalError;
    }
    catch (...)
    {
        printError("internal error: unknown exception");
        return kExitInternalError;
    }
}

std::string currentErrorText()
{
    try
    {
        throw;
    }
    catch (const InputError& e)
    {
        return oneLine(e.what());
    }
    catch (const OutputError& e)
    {
        return oneLine(e.what());
    }
    catch (const std::bad_alloc&)
    {
        return "out of memory";
    }
    catch (const std::exception& e)
    {
        return oneLine(mrpt::exception_to_str(e));
    }
    catch (...)
    {
        return "unknown exception";
    }
}

void printWarning(const std::string& msg)
{
    std::cout.flush();
    std::cerr << "topoeval: warning: " << oneLine(msg) << std::endl;
}

// ---------------------------------------------------------------- command lines

void VerbCommandLine::Output::usage(TCLAP::CmdLineInterface& c)
{
    TCLAP::StdOutput::usage(c);
    done = true;
}

void VerbCommandLine::Output::version(TCLAP::CmdLineInterface&)
{
    std::cout << versionLine() << "\n";
    done = true;
}

void VerbCommandLine::Output::failure(TCLAP::CmdLineInterface&, TCLAP::ArgException& e)
{
    // TCLAP's own failure() prints a multi-line usage; we want one line naming the argument.
    std::string id = e.argId();
    const std::string prefix = "Argument: ";
    if (id.rfind(prefix, 0) == 0) id.erase(0, prefix.size());
    while (!id.empty() && id.back() == ' ') id.pop_back();
    error = e.error();
    while (!error.empty() && (error.back() == '!' || error.back() == '.')) error.pop_back();
    if (!id.empty()) error += ": " + id;
}

VerbCommandLine::VerbCommandLine(const std::string& verb, const std::string& description)
    : m_verb(verb), m_cmd(description, ' ', TOPOEVAL_VERSION)
{
    delete m_cmd.getOutput();  // TCLAP's default output, replaced (it is ours to free)
    m_cmd.setOutput(&m_output);
}

std::optional<int> VerbCommandLine::parse(int argc, char** argv)
{
    std::vector<const char*> args(argv, argv + argc);
    const std::string prog = "topoeval " + m_verb;
    if (!args.empty()) args[0] = prog.c_str();  // "USAGE: topoeval graph ..."
    if (m_cmd.parse(static_cast<int>(args.size()), args.data())) return std::nullopt;
    if (m_output.done) return kExitOk;
    throw usageError(m_output.error.empty() ? "cannot parse the command line" : m_output.error);
}

UsageError VerbCommandLine::usageError(const std::string& what) const
{
    return UsageError(m_verb + ": " + what + "; see 'topoeval " + m_verb + " --help'");
}

// ---------------------------------------------------------------- configuration and outputs

Parameters loadParameters(const std::string& config_path, std::optional<double> resolution_m)
{
    Parameters p = config_path.empty() ? Parameters() : Parameters::fromIniFile(config_path);
    if (resolution_m)
    {
        if (!(std::isfinite(*resolution_m) && *resolution_m > 0.0))
        {
            std::ostringstream os;
            os << "--resolution " << *resolution_m << " violates resolution > 0 (metres per cell)";
            throw UsageError(os.str());
        }
        p.map_load.resolution_m = *resolution_m;
    }
    p.validate();
    return p;
}

void checkOutputPath(const std::string& out, bool force, const std::vector<std::string>& inputs)
{
    std::error_code ec;
    for (const auto& in : inputs)
        if (!in.empty() && fs::exists(out, ec) && fs::equivalent(out, in, ec))
            throw UsageError(out + ": is an input of this run; choose another output file");
    if (fs::is_directory(out, ec)) throw OutputError(out + ": is a folder");
    if (!force && fs::exists(fs::symlink_status(out, ec)))
        throw OutputError(out + ": exists; pass --force to replace it");
}

void flushStdout()
{
    std::cout.flush();
    if (!std::cout) throw OutputError("standard output: write failed");
}

}  // namespace mrpt_topoeval::cli
