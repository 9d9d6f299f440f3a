/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace mrpt_topoeval
{
/** A small streaming JSON writer whose output depends only on the calls made, so equal data
 * gives byte-identical files (the determinism our JSON outputs promise).
 *
 * Format:
 * - Pretty-printed with a 2-space indent; object keys keep the order they were written in.
 * - Containers opened with `single_line = true` are written on one line (`[1.5, 2]`); use it
 *   for short numeric tuples such as points. Anything nested inside one is single-line too.
 * - Empty containers are `{}` and `[]`.
 * - Doubles in fixed notation with at most `decimals` digits after the point, trailing zeros
 *   and a trailing point removed (`0.25`, `3`, never `1e-05`); a value that rounds to zero is
 *   `0` (no `-0`); NaN and infinities are `null` (JSON has no such numbers). Locale
 *   independent.
 * - Strings: `"` and `\` escaped, control characters as `\n`, `\t`, ... or `\u00XX`; valid
 *   UTF-8 passes through unchanged, each byte of an invalid sequence becomes U+FFFD.
 * - The document ends with a newline.
 *
 * Misuse (a value where a key is expected, unbalanced containers) is a programming error and
 * throws std::logic_error. */
class JsonWriter
{
public:
    /** Decimals used by value(double) when none are given. */
    static constexpr int kDefaultDecimals = 6;

    JsonWriter& beginObject(bool single_line = false);
    JsonWriter& endObject();
    JsonWriter& beginArray(bool single_line = false);
    JsonWriter& endArray();

    /** The key of the next member; only inside an object. */
    JsonWriter& key(std::string_view k);

    JsonWriter& value(double v, int decimals = kDefaultDecimals);
    JsonWriter& value(std::int64_t v);
    JsonWriter& value(std::uint64_t v);
    JsonWriter& value(int v) { return value(static_cast<std::int64_t>(v)); }
    JsonWriter& value(unsigned v) { return value(static_cast<std::uint64_t>(v)); }
    JsonWriter& value(bool v);
    JsonWriter& value(std::string_view v);
    JsonWriter& value(const char* v) { return value(std::string_view(v)); }
    JsonWriter& value(const std::string& v) { return value(std::string_view(v)); }
    JsonWriter& null();

    /** A number with `significant` significant digits (printf `%.Ng`: `0.8571428571`,
     * `1e-05`); null when not finite. For the run reports whose numbers keep full precision
     * (`topoeval rawlog` and `series`), where fixed decimals would round small scores. */
    JsonWriter& valueSignificant(double v, int significant = 10);

    /** A complete JSON document written by another JsonWriter (its str()), as this value:
     * re-indented to the current depth, its final newline dropped. Lets one document hold
     * another (a quality report inside a rawlog report) without writing it twice. */
    JsonWriter& embed(std::string_view document);

    /** Shorthand for a single-line array of two numbers, e.g. a point `[x, y]`. */
    JsonWriter& pair(double a, double b, int decimals = kDefaultDecimals);

    /** The finished document. \throws std::logic_error if containers are still open or
     * nothing was written. */
    std::string str() const;

    /** The number text value(double) writes, without the writer (null for NaN/inf). */
    static std::string formatDouble(double v, int decimals = kDefaultDecimals);
    /** The number text valueSignificant() writes (null for NaN/inf). */
    static std::string formatSignificant(double v, int significant = 10);
    /** `s` as a quoted JSON string. */
    static std::string quote(std::string_view s);

private:
    struct Level
    {
        bool is_object = false;
        bool single_line = false;
        std::size_t count = 0;  // members or elements written so far
        bool have_key = false;  // objects: a key was written, its value is due
    };

    void beforeValue();  // separators and indentation before a value or a container
    void newline(std::size_t depth);
    JsonWriter& begin(bool is_object, bool single_line);
    JsonWriter& end(bool is_object);
    bool singleLineHere() const;

    std::string m_out;
    std::vector<Level> m_stack;
    bool m_done = false;  // the top-level value is complete
};

/** Writes the member "timing_ms": {step: milliseconds} (3 decimals). Every writer puts it last,
 * so that a comparison of two runs can cut it off: it is the only part that varies. */
void writeTiming(JsonWriter& w, const std::map<std::string, double>& timing_ms);

}  // namespace mrpt_topoeval
