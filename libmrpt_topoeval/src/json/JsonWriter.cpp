/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#include <mrpt_topoeval/json/JsonWriter.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace mrpt_topoeval
{
namespace
{
// Length of the valid UTF-8 sequence starting at s[i], or 0 if it is not valid (overlong
// forms, surrogates and code points above U+10FFFF are invalid, as RFC 3629 says).
std::size_t utf8SequenceLength(std::string_view s, std::size_t i)
{
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char b0 = byte(i);
    std::size_t len = 0;
    unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
    if (b0 >= 0xC2 && b0 <= 0xDF)
        len = 2;
    else if (b0 >= 0xE0 && b0 <= 0xEF)
    {
        len = 3;
        if (b0 == 0xE0) lo = 0xA0;  // overlong
        if (b0 == 0xED) hi = 0x9F;  // UTF-16 surrogates
    }
    else if (b0 >= 0xF0 && b0 <= 0xF4)
    {
        len = 4;
        if (b0 == 0xF0) lo = 0x90;  // overlong
        if (b0 == 0xF4) hi = 0x8F;  // above U+10FFFF
    }
    else
        return 0;
    if (i + len > s.size()) return 0;
    if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
    for (std::size_t k = 2; k < len; ++k)
        if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
    return len;
}
}  // namespace

std::string JsonWriter::formatDouble(double v, int decimals)
{
    if (!std::isfinite(v)) return "null";
    decimals = std::clamp(decimals, 0, 17);
    // Fixed notation of the largest double needs ~310 digits before the point.
    char buf[400];
    const auto res = std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::fixed, decimals);
    if (res.ec != std::errc()) throw std::logic_error("JsonWriter: cannot format a number");
    std::string s(buf, res.ptr);
    if (s.find('.') != std::string::npos)
    {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    if (s == "-0") s = "0";
    return s;
}

std::string JsonWriter::formatSignificant(double v, int significant)
{
    if (!std::isfinite(v)) return "null";
    char buf[40];
    std::snprintf(buf, sizeof(buf), "%.*g", std::clamp(significant, 1, 17), v);
    return buf;
}

std::string JsonWriter::quote(std::string_view s)
{
    static const char* const kHex = "0123456789abcdef";
    std::string out;
    out.reserve(s.size() + 2);
    out.push_back('"');
    for (std::size_t i = 0; i < s.size();)
    {
        const auto c = static_cast<unsigned char>(s[i]);
        if (c < 0x80)
        {
            switch (c)
            {
                case '"':
                    out += "\\\"";
                    break;
                case '\\':
                    out += "\\\\";
                    break;
                case '\b':
                    out += "\\b";
                    break;
                case '\f':
                    out += "\\f";
                    break;
                case '\n':
                    out += "\\n";
                    break;
                case '\r':
                    out += "\\r";
                    break;
                case '\t':
                    out += "\\t";
                    break;
                default:
                    if (c < 0x20)
                    {
                        out += "\\u00";
                        out.push_back(kHex[c >> 4]);
                        out.push_back(kHex[c & 0xF]);
                    }
                    else
                        out.push_back(static_cast<char>(c));
            }
            ++i;
            continue;
        }
        const std::size_t len = utf8SequenceLength(s, i);
        if (len == 0)
        {
            // A JSON text must be UTF-8: replace the stray byte (U+FFFD) rather than emit an
            // invalid document (file names on Linux are arbitrary bytes).
            out += "\xEF\xBF\xBD";
            ++i;
        }
        else
        {
            out.append(s.substr(i, len));
            i += len;
        }
    }
    out.push_back('"');
    return out;
}

bool JsonWriter::singleLineHere() const { return !m_stack.empty() && m_stack.back().single_line; }

void JsonWriter::newline(std::size_t depth)
{
    m_out.push_back('\n');
    m_out.append(2 * depth, ' ');
}

void JsonWriter::beforeValue()
{
    if (m_stack.empty())
    {
        if (m_done) throw std::logic_error("JsonWriter: a second top-level value");
        return;
    }
    Level& top = m_stack.back();
    if (top.is_object)
    {
        if (!top.have_key) throw std::logic_error("JsonWriter: object member without a key");
        top.have_key = false;  // key() already wrote the separator and indentation
        return;
    }
    if (top.count > 0) m_out.push_back(',');
    if (top.single_line)
    {
        if (top.count > 0) m_out.push_back(' ');
    }
    else
        newline(m_stack.size());
    ++top.count;
}

JsonWriter& JsonWriter::key(std::string_view k)
{
    if (m_stack.empty() || !m_stack.back().is_object)
        throw std::logic_error("JsonWriter: key outside an object");
    Level& top = m_stack.back();
    if (top.have_key) throw std::logic_error("JsonWriter: two keys in a row");
    if (top.count > 0) m_out.push_back(',');
    if (top.single_line)
    {
        if (top.count > 0) m_out.push_back(' ');
    }
    else
        newline(m_stack.size());
    m_out += quote(k);
    m_out += ": ";
    ++top.count;
    top.have_key = true;
    return *this;
}

JsonWriter& JsonWriter::begin(bool is_object, bool single_line)
{
    beforeValue();
    Level lvl;
    lvl.is_object = is_object;
    lvl.single_line = single_line || singleLineHere();
    m_stack.push_back(lvl);
    m_out.push_back(is_object ? '{' : '[');
    return *this;
}

JsonWriter& JsonWriter::end(bool is_object)
{
    if (m_stack.empty() || m_stack.back().is_object != is_object)
        throw std::logic_error("JsonWriter: unbalanced end of a container");
    const Level top = m_stack.back();
    if (top.have_key) throw std::logic_error("JsonWriter: key without a value");
    m_stack.pop_back();
    if (top.count > 0 && !top.single_line) newline(m_stack.size());
    m_out.push_back(is_object ? '}' : ']');
    if (m_stack.empty()) m_done = true;
    return *this;
}

JsonWriter& JsonWriter::beginObject(bool single_line) { return begin(true, single_line); }
JsonWriter& JsonWriter::endObject() { return end(true); }
JsonWriter& JsonWriter::beginArray(bool single_line) { return begin(false, single_line); }
JsonWriter& JsonWriter::endArray() { return end(false); }

JsonWriter& JsonWriter::value(double v, int decimals)
{
    beforeValue();
    m_out += formatDouble(v, decimals);
    if (m_stack.empty()) m_done = true;
    return *this;
}

JsonWriter& JsonWriter::value(std::int64_t v)
{
    beforeValue();
    m_out += std::to_string(v);
    if (m_stack.empty()) m_done = true;
    return *this;
}

JsonWriter& JsonWriter::value(std::uint64_t v)
{
    beforeValue();
    m_out += std::to_string(v);
    if (m_stack.empty()) m_done = true;
    return *this;
}

JsonWriter& JsonWriter::value(bool v)
{
    beforeValue();
    m_out += v ? "true" : "false";
    if (m_stack.empty()) m_done = true;
    return *this;
}

JsonWriter& JsonWriter::value(std::string_view v)
{
    beforeValue();
    m_out += quote(v);
    if (m_stack.empty()) m_done = true;
    return *this;
}

JsonWriter& JsonWriter::null()
{
    beforeValue();
    m_out += "null";
    if (m_stack.empty()) m_done = true;
    return *this;
}

JsonWriter& JsonWriter::valueSignificant(double v, int significant)
{
    beforeValue();
    m_out += formatSignificant(v, significant);
    if (m_stack.empty()) m_done = true;
    return *this;
}

JsonWriter& JsonWriter::embed(std::string_view document)
{
    while (!document.empty() && document.back() == '\n') document.remove_suffix(1);
    if (document.empty()) throw std::logic_error("JsonWriter: embedding an empty document");
    beforeValue();
    // On a single line the document's line breaks and their indentation are dropped (strings
    // hold no raw line breaks: quote() escapes them).
    const bool one_line = singleLineHere();
    bool line_start = false;
    for (const char ch : document)
    {
        if (ch == '\n')
        {
            line_start = true;
            if (!one_line) newline(m_stack.size());
            continue;
        }
        if (one_line && line_start && ch == ' ') continue;
        line_start = false;
        m_out.push_back(ch);
    }
    if (m_stack.empty()) m_done = true;
    return *this;
}

JsonWriter& JsonWriter::pair(double a, double b, int decimals)
{
    beginArray(true);
    value(a, decimals);
    value(b, decimals);
    return endArray();
}

std::string JsonWriter::str() const
{
    if (!m_done || !m_stack.empty()) throw std::logic_error("JsonWriter: document is incomplete");
    return m_out + "\n";
}

void writeTiming(JsonWriter& w, const std::map<std::string, double>& timing_ms)
{
    constexpr int kMillisecondDecimals = 3;
    w.key("timing_ms").beginObject();
    for (const auto& [step, ms] : timing_ms) w.key(step).value(ms, kMillisecondDecimals);
    w.endObject();
}

}  // namespace mrpt_topoeval
