/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
// `topoeval config`: prints, writes or checks the INI configuration.

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt_topoeval/output.h>

#include <iostream>

#include "cli_common.h"

namespace mrpt_topoeval::cli
{
int verbConfig(int argc, char** argv)
{
    VerbCommandLine cl(
        "config",
        "Without options, prints the documented default configuration (INI) on stdout. --write "
        "saves it to a file (never replacing one without --force); --check reads a file, "
        "reports the first problem (unknown section or key, bad value) and prints the "
        "effective configuration. Exit codes: 0 ok, 1 internal error, 2 bad input or usage, 3 "
        "output error.");
    TCLAP::CmdLine& cmd = cl.cmd();
    TCLAP::SwitchArg force_arg("f", "force", "With --write: replace an existing file.", cmd);
    TCLAP::ValueArg<std::string> check_arg(
        "", "check", "Validate this INI file and print the configuration it gives.", false, "",
        "F.ini", cmd);
    TCLAP::ValueArg<std::string> write_arg(
        "w", "write", "Write the default configuration to this file.", false, "", "F.ini", cmd);
    if (const auto done = cl.parse(argc, argv)) return *done;

    if (write_arg.isSet() && check_arg.isSet())
        throw cl.usageError("--write and --check cannot be combined");
    if (force_arg.getValue() && !write_arg.isSet())
        throw cl.usageError("--force only applies to --write");

    if (write_arg.isSet())
    {
        if (write_arg.getValue().empty()) throw cl.usageError("--write needs a file name");
        writeFileAtomic(write_arg.getValue(), Parameters::defaultIniText(), force_arg.getValue());
        std::cout << "wrote " << write_arg.getValue() << "\n";
    }
    else if (check_arg.isSet())
    {
        if (check_arg.getValue().empty()) throw cl.usageError("--check needs a file name");
        const Parameters p = Parameters::fromIniFile(check_arg.getValue());
        mrpt::config::CConfigFileMemory effective;
        p.saveToConfigFile(effective);
        // The output is itself a valid INI file.
        std::cout << "# " << check_arg.getValue()
                  << " is valid. The configuration it gives (defaults for keys it omits):\n\n"
                  << effective.getContent();
    }
    else
        std::cout << Parameters::defaultIniText();
    flushStdout();
    return kExitOk;
}

}  // namespace mrpt_topoeval::cli
