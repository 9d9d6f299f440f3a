/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "common/parameter_table.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace mrpt_topoeval::internal
{
std::string trim(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return s;
}

std::string shortestNumber(double v)
{
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof(buf), v);
    return std::string(buf, r.ptr);
}

bool parseReal(const std::string& text, double& out)
{
    const std::string t = trim(text);
    if (t.empty()) return false;
    char* end = nullptr;
    out = std::strtod(t.c_str(), &end);
    return end == t.c_str() + t.size() && std::isfinite(out);
}

bool isInteger(const std::string& text)
{
    std::string t = trim(text);
    if (!t.empty() && (t[0] == '-' || t[0] == '+')) t.erase(0, 1);
    return !t.empty() &&
           std::all_of(t.begin(), t.end(), [](unsigned char ch) { return std::isdigit(ch) != 0; });
}

bool isBool(const std::string& text)
{
    const std::string t = lower(trim(text));
    return t == "true" || t == "false" || t == "yes" || t == "no" || t == "1" || t == "0";
}

bool parseCount(const std::string& text, std::uint64_t& out)
{
    std::uint64_t v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size()) return false;
    out = v;
    return true;
}

bool Range::contains(double v) const
{
    if (std::isnan(v) || (std::isinf(v) && !(m_infinity_ok && v > 0))) return false;
    if (m_lo && (m_lo_open ? !(v > *m_lo) : !(v >= *m_lo))) return false;
    if (m_hi && (m_hi_open ? !(v < *m_hi) : !(v <= *m_hi))) return false;
    return true;
}

std::string Range::rule(const std::string& key) const
{
    if (m_lo && m_hi)
        return shortestNumber(*m_lo) + (m_lo_open ? " < " : " <= ") + key +
               (m_hi_open ? " < " : " <= ") + shortestNumber(*m_hi);
    if (m_lo) return key + (m_lo_open ? " > " : " >= ") + shortestNumber(*m_lo);
    if (m_hi) return key + (m_hi_open ? " < " : " <= ") + shortestNumber(*m_hi);
    return key + " is finite";
}

void throwBadValue(const std::string& section, const char* key, const std::string& text,
                   const char* problem)
{
    throw InputError("[" + section + "] " + key + " = '" + text + "' " + problem);
}

std::optional<std::string> readText(const mrpt::config::CConfigFileBase& c,
                                    const std::string& section, const char* key)
{
    if (!c.keyExists(section, key)) return std::nullopt;
    return trim(c.read_string(section, key, ""));
}

int savePadding(bool name)
{
    return name ? mrpt::config::MRPT_SAVE_NAME_PADDING() : mrpt::config::MRPT_SAVE_VALUE_PADDING();
}

}  // namespace mrpt_topoeval::internal
