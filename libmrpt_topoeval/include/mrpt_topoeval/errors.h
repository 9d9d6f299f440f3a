/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <stdexcept>
#include <string>

namespace mrpt_topoeval
{
/** Thrown for bad user input: a file that is missing, unreadable or malformed, a parameter
 * out of range. The message names the file (when there is one), the field and the value, on
 * one line. The `topoeval` command maps it to exit code 2 (see README, "Exit codes"). */
class InputError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

/** Thrown when an output cannot be written, or would overwrite an existing file without the
 * caller allowing it. The `topoeval` command maps it to exit code 3. */
class OutputError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

/** `msg` on one line as the `topoeval` command prints errors and warnings: each run of line
 * breaks becomes "; " (none at either end). The Python package gives its exceptions the same
 * text, so that a message reads the same in both. */
std::string messageOnOneLine(const std::string& msg);

}  // namespace mrpt_topoeval
