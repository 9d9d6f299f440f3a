/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <exception>
#include <string>

namespace mrpt_topoeval::internal
{
/** MRPT exceptions carry a banner, the message, a source location and a backtrace over many
 * lines; our errors are one line, so keep only the message (the last one of stacked MRPT
 * exceptions: the cause) and join its lines; at most 300 characters. */
std::string oneLine(const std::exception& e);

}  // namespace mrpt_topoeval::internal
