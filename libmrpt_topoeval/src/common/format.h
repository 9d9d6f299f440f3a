/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once
// One number formatted as printf does, for the text report and the pictures' legends.

#include <cstdio>
#include <string>

namespace mrpt_topoeval::internal
{
/** `v` formatted by `format` ("%.3f"). */
inline std::string fmt(const char* format, double v)
{
    char buf[64];
    std::snprintf(buf, sizeof(buf), format, v);
    return buf;
}
}  // namespace mrpt_topoeval::internal
