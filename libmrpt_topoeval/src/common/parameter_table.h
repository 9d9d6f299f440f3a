/* mrpt_topoeval: map quality by Topology Graph matching (Schwertfeger & Birk 2013). BSD-3. */
#pragma once

// One table per parameters struct, each INI key written once in it (key and member, unit, help,
// valid range); loadFromConfigFile, saveToConfigFile and validate are derived from the table, so
// they cannot disagree about a key (doc/architecture.md, "Parameters"). A table reads:
//
//   TOPOEVAL_PARAMETER_TABLE(GraphBuilderParameters, NumberText::Stream,
//       real(TOPOEVAL_KEY(min_clearance_m), "m", "drop Voronoi edges nearer ...", above(0)),
//       relation(&P::wall_gap_close_radius_m, "wall_gap_close_radius_m < min_clearance_m",
//                [](const P& p) { return p.wall_gap_close_radius_m < p.min_clearance_m; }))
//
// Rows are saved, loaded and checked in their order: the order of the INI keys, and which
// violation validate() reports first.

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt_topoeval/errors.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

/** The INI key and the member it fills, written once: `"name", &P::name` (inside
 * TOPOEVAL_PARAMETER_TABLE, `P` is the parameters struct). */
#define TOPOEVAL_KEY(member) #member, &P::member

/** Defines `Type`'s table from the rows given and its loadFromConfigFile, saveToConfigFile and
 * validate from the table. Used in namespace mrpt_topoeval, once per parameters struct. */
#define TOPOEVAL_PARAMETER_TABLE(Type, numbers, ...)                                            \
    namespace                                                                                   \
    {                                                                                           \
    const ::mrpt_topoeval::internal::ParameterTable<Type>& tableOf##Type()                      \
    {                                                                                           \
        using P = Type;                                                                         \
        using namespace ::mrpt_topoeval::internal;                                              \
        static const ParameterTable<P> table(numbers, {__VA_ARGS__});                           \
        return table;                                                                           \
    }                                                                                           \
    }                                                                                           \
    void Type::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) \
    {                                                                                           \
        tableOf##Type().load(*this, c, s);                                                      \
    }                                                                                           \
    void Type::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const   \
    {                                                                                           \
        tableOf##Type().save(*this, c, s);                                                      \
    }                                                                                           \
    void Type::validate() const { tableOf##Type().validate(*this); }

namespace mrpt_topoeval::internal
{
// ---- strict reading of INI values: MRPT's reader takes "0.3x" as 0.3, "" as 0, "maybe" as false

std::string trim(const std::string& s);
std::string lower(std::string s);
/** Shortest text that reads back as `v` ("-1", "0.05"). */
std::string shortestNumber(double v);
/** The whole text is one finite number. */
bool parseReal(const std::string& text, double& out);
/** Optional sign, then digits only. */
bool isInteger(const std::string& text);
/** The spellings MRPT's read_bool() understands the way a user means them. */
bool isBool(const std::string& text);
/** The whole text is a count up to 2^64-1. */
bool parseCount(const std::string& text, std::uint64_t& out);

/** How validation messages write a real value: `Stream` as std::ostream does (6 significant
 * digits), `Shortest` as shortestNumber(). The stages' sections have always used the first and
 * [MapLoad] the second; kept so that no message changes. */
enum class NumberText
{
    Stream,
    Shortest
};

/** The valid values of a number: bounds, open or closed, finite unless orInfinity(). Renders
 * as the rule a message names: "key > 0", "0 <= key < 0.5". */
class Range
{
public:
    Range& atMost(double v) { return setHi(v, false); }
    Range& below(double v) { return setHi(v, true); }
    /** +infinity is valid too ("as large as you like"); NaN never is. */
    Range& orInfinity()
    {
        m_infinity_ok = true;
        return *this;
    }
    bool contains(double v) const;
    std::string rule(const std::string& key) const;

    friend Range atLeast(double v);
    friend Range above(double v);

private:
    Range& setHi(double v, bool open)
    {
        m_hi = v;
        m_hi_open = open;
        return *this;
    }
    std::optional<double> m_lo, m_hi;
    bool m_lo_open = false, m_hi_open = false, m_infinity_ok = false;
};

/** key >= v */
inline Range atLeast(double v)
{
    Range r;
    r.m_lo = v;
    return r;
}
/** key > v */
inline Range above(double v)
{
    Range r;
    r.m_lo = v;
    r.m_lo_open = true;
    return r;
}

template <class P>
using MemberOf = std::variant<std::monostate, double P::*, int P::*, bool P::*, std::uint64_t P::*,
                              std::string P::*>;

/** One row of a table: an INI key, or a rule between keys (`relation`), checked in its place. */
template <class P>
struct Field
{
    const char* key = nullptr;  //!< Set by the table for a relation (from `member`).
    MemberOf<P> member;
    bool is_key = true;
    std::string comment;  //!< "[unit] help", written after the value in the INI.
    std::function<void(P&, const mrpt::config::CConfigFileBase&, const std::string& section)> load;
    std::function<void(const P&, mrpt::config::CConfigFileBase&, const std::string& section)> save;
    std::function<std::string(const P&, NumberText)> value_text;  //!< As messages write it.
    std::function<bool(const P&)> valid;                          //!< Empty: any value.
    std::function<std::string(const P&)> rule;                    //!< What `valid` checks.
};

/** The rows of one parameters struct, for its INI section P::kIniSection. */
template <class P>
class ParameterTable
{
public:
    ParameterTable(NumberText numbers, std::vector<Field<P>> fields)
        : m_numbers(numbers), m_fields(std::move(fields))
    {
        for (Field<P>& f : m_fields)
        {
            if (f.is_key) continue;
            for (const Field<P>& k : m_fields)
                if (k.is_key && k.member == f.member)
                {
                    f.key = k.key;
                    f.value_text = k.value_text;
                }
            if (!f.key) throw std::logic_error("parameter table: a relation names no key");
        }
    }

    void load(P& p, const mrpt::config::CConfigFileBase& c, const std::string& section) const
    {
        for (const Field<P>& f : m_fields)
            if (f.load) f.load(p, c, section);
    }
    void save(const P& p, mrpt::config::CConfigFileBase& c, const std::string& section) const
    {
        for (const Field<P>& f : m_fields)
            if (f.save) f.save(p, c, section);
    }
    /** \throws InputError "[Section] key = value violates rule" for the first row violated. */
    void validate(const P& p) const
    {
        for (const Field<P>& f : m_fields)
            if (f.valid && !f.valid(p))
                throw InputError(std::string("[") + P::kIniSection + "] " + f.key + " = " +
                                 f.value_text(p, m_numbers) + " violates " + f.rule(p));
    }
    const std::vector<Field<P>>& fields() const { return m_fields; }

private:
    NumberText m_numbers;
    std::vector<Field<P>> m_fields;
};

// ---- rows

/** "[section] key = 'text' <problem>": a value that is not of its key's type. */
[[noreturn]] void throwBadValue(const std::string& section, const char* key,
                                const std::string& text, const char* problem);
/** The key's text, trimmed, if present. */
std::optional<std::string> readText(const mrpt::config::CConfigFileBase& c,
                                    const std::string& section, const char* key);
/** The INI comment of a key: "[unit] help". */
inline std::string comment(const std::string& unit, const char* help)
{
    return "[" + unit + "] " + help;
}
int savePadding(bool name);

template <class T>
std::string streamText(const T& v)
{
    std::ostringstream os;
    os << v;
    return os.str();
}

/** What every key row has: key, member, comment, saving with MRPT's padding, its value as
 * messages write it (as std::ostream does), and `range` if given. */
template <class P, class T>
Field<P> keyRow(const char* key, T P::*m, const std::string& unit, const char* help,
                const std::optional<Range>& range = {})
{
    Field<P> f;
    f.key = key;
    f.member = m;
    f.comment = comment(unit, help);
    f.save = [key, m, text = f.comment](const P& p, mrpt::config::CConfigFileBase& c,
                                        const std::string& s)
    { c.write(s, key, p.*m, savePadding(true), savePadding(false), text); };
    f.value_text = [m](const P& p, NumberText) { return streamText(p.*m); };
    if constexpr (std::is_arithmetic_v<T>)
        if (range)
        {
            f.valid = [m, r = *range](const P& p) { return r.contains(static_cast<double>(p.*m)); };
            f.rule = [key, r = *range](const P&) { return r.rule(key); };
        }
    return f;
}

/** Loading of a key present in the INI: `parse(text, value, section)` sets the value from the
 * trimmed text or throws naming it. */
template <class P, class T, class Parse>
void loadWith(const char* key, T P::*m, Field<P>& f, Parse parse)
{
    f.load = [key, m, parse](P& p, const mrpt::config::CConfigFileBase& c, const std::string& s)
    {
        if (const auto text = readText(c, s, key)) parse(c, s, *text, p.*m);
    };
}

/** A real number; read strictly (the whole text, finite). */
template <class P>
Field<P> real(const char* key, double P::*m, const char* unit, const char* help,
              std::optional<Range> range = {})
{
    Field<P> f = keyRow(key, m, unit, help, range);
    loadWith(key, m, f,
             [key](const auto&, const std::string& s, const std::string& text, double& v)
             {
                 if (!parseReal(text, v)) throwBadValue(s, key, text, "is not a finite number");
             });
    f.value_text = [m](const P& p, NumberText n)
    { return n == NumberText::Shortest ? shortestNumber(p.*m) : streamText(p.*m); };
    return f;
}

/** A whole number; read strictly (sign and digits), then as MRPT reads it. */
template <class P>
Field<P> integer(const char* key, int P::*m, const char* unit, const char* help,
                 std::optional<Range> range = {})
{
    Field<P> f = keyRow(key, m, unit, help, range);
    loadWith(key, m, f,
             [key](const mrpt::config::CConfigFileBase& c, const std::string& s,
                   const std::string& text, int& v)
             {
                 if (!isInteger(text)) throwBadValue(s, key, text, "is not a whole number");
                 v = c.read_int(s, key, v);
             });
    return f;
}

/** A count up to 2^64-1 (sizes in cells); a negative count violates the range. */
template <class P>
Field<P> count(const char* key, std::uint64_t P::*m, const char* unit, const char* help,
               Range range)
{
    Field<P> f = keyRow(key, m, unit, help, std::optional<Range>(range));
    loadWith(
        key, m, f,
        [key, range](const auto&, const std::string& s, const std::string& text, std::uint64_t& v)
        {
            if (!text.empty() && text[0] == '-' && isInteger(text))
                throw InputError("[" + s + "] " + key + " = " + text + " violates " +
                                 range.rule(key));
            if (!parseCount(text, v))
                throwBadValue(s, key, text, "is not a whole number (up to 2^64-1)");
        });
    return f;
}

/** true / false (also yes / no, 1 / 0), then as MRPT reads it. */
template <class P>
Field<P> flag(const char* key, bool P::*m, const char* help)
{
    Field<P> f = keyRow(key, m, "bool", help);
    loadWith(key, m, f,
             [key](const mrpt::config::CConfigFileBase& c, const std::string& s,
                   const std::string& text, bool& v)
             {
                 if (!isBool(text)) throwBadValue(s, key, text, "is not true or false");
                 v = c.read_bool(s, key, v);
             });
    return f;
}

/** One of a few words, kept as text. */
template <class P>
Field<P> word(const char* key, std::string P::*m, std::vector<std::string> allowed,
              const char* help)
{
    std::string unit, set;
    for (const auto& a : allowed)
    {
        unit += (unit.empty() ? "" : "|") + a;
        set += (set.empty() ? "" : ", ") + a;
    }
    Field<P> f = keyRow(key, m, unit, help);
    loadWith(key, m, f,
             [](const auto&, const std::string&, const std::string& text, std::string& v)
             { v = text; });
    f.value_text = [m](const P& p, NumberText) { return "'" + p.*m + "'"; };
    f.valid = [m, allowed](const P& p)
    {
        for (const auto& a : allowed)
            if (p.*m == a) return true;
        return false;
    };
    f.rule = [key, set](const P&) { return std::string(key) + " in {" + set + "}"; };
    return f;
}

/** An enumeration, written with toString(E) and read with `parse` (which names a bad value). */
template <class P, class E>
Field<P> choice(const char* key, E P::*m, E (*parse)(const std::string&), std::vector<E> values,
                const char* help)
{
    std::string unit;
    for (const E v : values) unit += (unit.empty() ? "" : "|") + toString(v);
    Field<P> f;
    f.key = key;
    f.comment = comment(unit, help);
    f.load = [key, m, parse](P& p, const mrpt::config::CConfigFileBase& c, const std::string& s)
    { p.*m = parse(c.read_string(s, key, toString(p.*m))); };
    f.save = [key, m, text = f.comment](const P& p, mrpt::config::CConfigFileBase& c,
                                        const std::string& s)
    { c.write(s, key, toString(p.*m), savePadding(true), savePadding(false), text); };
    f.value_text = [m](const P& p, NumberText) { return toString(p.*m); };
    return f;
}

/** `P` as written, not deduced from an argument (a lambda is no std::function). */
template <class T>
struct NotDeduced
{
    using type = T;
};

/** A rule between keys, reported as a violation by the key `member` fills. */
template <class P, class T>
Field<P> relation(T P::*member,
                  typename NotDeduced<std::function<std::string(const P&)>>::type rule,
                  typename NotDeduced<std::function<bool(const P&)>>::type valid)
{
    Field<P> f;
    f.member = member;
    f.is_key = false;
    f.rule = std::move(rule);
    f.valid = std::move(valid);
    return f;
}
template <class P, class T>
Field<P> relation(T P::*member, const char* rule,
                  typename NotDeduced<std::function<bool(const P&)>>::type valid)
{
    return relation<P, T>(
        member, [rule](const P&) { return std::string(rule); }, std::move(valid));
}

}  // namespace mrpt_topoeval::internal
