// The number primitive: [+-] digits [. digits] | [+-] . digits, read as an exact decimal.
// Written as an X3 primitive parser because it is the hottest path of the grammar (bench/).
#pragma once

#include <boost/spirit/home/x3.hpp>
#include <charconv>
#include <string>

#include "grammar/builder.hpp"

namespace kerf::grammar {

namespace x3 = boost::spirit::x3;

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Reads a number at [first, last). `allow_sign`: a leading + or -. `allow_comma`: a decimal comma
// between digits when the dialect is lenient (F0,25); never inside macro expressions, where ','
// separates function arguments.
template <typename It>
bool scan_number(It& first, It last, bool allow_sign, bool allow_comma, NumberLit& out) {
    It p = first;
    NumberLit n;
    n.begin = &*first;
    if (allow_sign && p != last && (*p == '-' || *p == '+')) {
        n.negative = *p == '-';
        ++p;
    }
    // Leading zeros add nothing to the mantissa, so counting all digits is a safe overflow guard:
    // 18 decimal digits always fit in 63 bits.
    std::uint64_t mantissa = 0;
    int digits = 0;
    It digits_begin = p;
    while (p != last && is_digit(*p)) {
        mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
        ++p;
    }
    digits = static_cast<int>(p - digits_begin);
    const bool integer_digits = digits > 0;
    int scale = 0;
    if (p != last && (*p == '.' || (allow_comma && *p == ',' && integer_digits && std::next(p) != last &&
                                    is_digit(*std::next(p))))) {
        n.comma = *p == ',';
        n.point = true;
        ++p;
        It fraction_begin = p;
        while (p != last && is_digit(*p)) {
            mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
            ++p;
        }
        scale = static_cast<int>(p - fraction_begin);
        digits += scale;
    }
    if (digits == 0) return false;   // "-", ".", "+." are not numbers
    n.end = &*first + (p - first);
    if (digits > 18 || scale > 15 || mantissa > 2147483647u) {
        n.big = true;
        std::string spelled(n.begin, n.end);
        for (char& c : spelled) if (c == ',') c = '.';
        const char* s = spelled.c_str();
        if (*s == '+') ++s;
        std::from_chars(s, spelled.c_str() + spelled.size(), n.big_value);
    } else {
        n.mantissa = static_cast<std::int64_t>(mantissa);
        n.scale = scale;
    }
    out = n;
    first = p;
    return true;
}

struct number_parser : x3::parser<number_parser> {
    using attribute_type = NumberLit;
    static bool const has_attribute = true;
    bool allow_sign = false;
    bool word_value = false;   // decimal comma allowed when the dialect is lenient

    constexpr number_parser(bool sign, bool word) : allow_sign(sign), word_value(word) {}

    template <typename It, typename Ctx, typename RCtx, typename Attr>
    bool parse(It& first, It const& last, Ctx const& ctx, RCtx&, Attr& attr) const {
        // Decimal commas are always recognised in word values so that they can be diagnosed;
        // the dialect decides whether the diagnostic is a warning (lenient) or an error.
        NumberLit n;
        if (!scan_number(first, last, allow_sign, word_value, n)) return false;
        if constexpr (!std::is_same_v<Attr, x3::unused_type>) attr = n;
        return true;
    }
};

}  // namespace kerf::grammar
