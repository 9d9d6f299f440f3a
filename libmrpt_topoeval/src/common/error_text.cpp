/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include "common/error_text.h"

#include <mrpt_topoeval/errors.h>

#include <cctype>

namespace mrpt_topoeval::internal
{
std::string oneLine(const std::exception& e)
{
    std::string s = e.what();
    // Stacked MRPT exceptions repeat the banner per level: the last message is the cause.
    if (const auto m = s.rfind("Message:"); m != std::string::npos)
    {
        s = s.substr(m + 8);
        for (const char* end_mark : {"\nLocation:", "\nCall stack"})
            if (const auto k = s.find(end_mark); k != std::string::npos) s = s.substr(0, k);
    }
    std::string out;
    bool space = false;
    for (const char c : s)
    {
        if (std::isspace(static_cast<unsigned char>(c)))
        {
            space = !out.empty();
            continue;
        }
        if (space) out += ' ';
        space = false;
        out += c;
    }
    if (out.size() > 300) out = out.substr(0, 297) + "...";
    return out.empty() ? std::string("unknown error") : out;
}

}  // namespace mrpt_topoeval::internal

namespace mrpt_topoeval
{
std::string messageOnOneLine(const std::string& msg)
{
    std::string out;
    bool pending_break = false;
    for (const char ch : msg)
    {
        if (ch == '\n' || ch == '\r')
        {
            pending_break = !out.empty();
            continue;
        }
        if (pending_break)
        {
            out += "; ";
            pending_break = false;
        }
        out.push_back(ch);
    }
    return out;
}

}  // namespace mrpt_topoeval
