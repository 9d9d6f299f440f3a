/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// Parameter checks with messages like "min_clearance_m = -1 violates min_clearance_m > 0".

#include <mrpt_topoeval/errors.h>

#include <cmath>
#include <sstream>
#include <string>

namespace mrpt_topoeval::internal
{
/** Throws InputError "<prefix><name> = <value> violates <rule>" unless `ok`. */
template <class T>
void require(bool ok, const char* name, const T& value, const char* rule,
             const std::string& prefix = {})
{
    if (ok) return;
    std::ostringstream os;
    os << prefix << name << " = " << value << " violates " << rule;
    throw InputError(os.str());
}

inline bool isPositive(double v) { return std::isfinite(v) && v > 0.0; }
inline bool isNonNegative(double v) { return std::isfinite(v) && v >= 0.0; }
inline bool isUnit(double v) { return std::isfinite(v) && v >= 0.0 && v <= 1.0; }

}  // namespace mrpt_topoeval::internal
