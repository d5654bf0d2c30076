#include "converter/numbers.hpp"

#include <fmt/format.h>

#include <cmath>

namespace kerf::converter {

std::optional<Decimal> parse_decimal(std::string_view text) {
    Decimal d;
    std::size_t i = 0;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) {
        d.negative = text[i] == '-';
        ++i;
    }
    bool any = false;
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (c >= '0' && c <= '9') {
            d.digits += c;
            if (d.point) ++d.scale;
            any = true;
        } else if ((c == '.' || c == ',') && !d.point) {   // ',' only in F0,25 (decimal_comma words)
            d.point = true;
        } else {
            return std::nullopt;
        }
    }
    if (!any) {
        if (!d.point) return std::nullopt;   // "-" alone
        d.digits.assign(1, '0');             // "." reads as 0 on FANUC
    }
    return d;
}

Decimal shifted(Decimal d, int shift) {
    d.scale -= shift;
    if (d.scale < 0) {
        d.digits.append(static_cast<std::size_t>(-d.scale), '0');
        d.scale = 0;
    }
    return d;
}

namespace {

// Integer and fraction digits, leading zeros of the integer part and trailing zeros of the
// fraction dropped.
std::pair<std::string, std::string> parts(const Decimal& d) {
    std::string digits = d.digits;
    if (static_cast<int>(digits.size()) < d.scale) digits.insert(0, static_cast<std::size_t>(d.scale) - digits.size(), '0');
    std::string whole = digits.substr(0, digits.size() - static_cast<std::size_t>(d.scale));
    std::string fraction = digits.substr(digits.size() - static_cast<std::size_t>(d.scale));
    while (!fraction.empty() && fraction.back() == '0') fraction.pop_back();
    const std::size_t first = whole.find_first_not_of('0');
    whole = first == std::string::npos ? std::string() : whole.substr(first);
    return {whole, fraction};
}

}  // namespace

bool is_zero(const Decimal& d) { return d.digits.find_first_not_of('0') == std::string::npos; }

std::string with_point(const Decimal& d) {
    const auto [whole, fraction] = parts(d);
    std::string s = d.negative && !is_zero(d) ? "-" : "";
    if (fraction.empty()) return s + (whole.empty() ? "0" : whole) + ".";
    return s + (whole.empty() ? "0" : whole) + "." + fraction;
}

std::string plain(const Decimal& d) {
    const auto [whole, fraction] = parts(d);
    if (!fraction.empty()) return with_point(d);
    return (d.negative && !is_zero(d) ? "-" : "") + (whole.empty() ? std::string("0") : whole);
}

Decimal negated(Decimal d) {
    d.negative = !d.negative && !is_zero(d);
    return d;
}

std::string format_value(double value, int digits) {
    const double unit = std::pow(10.0, digits);
    double rounded = std::round(value * unit) / unit;
    if (rounded == 0) rounded = 0;   // no "-0."
    std::string s = fmt::format("{:.{}f}", rounded, digits);
    while (!s.empty() && s.back() == '0') s.pop_back();
    return s;
}

}  // namespace kerf::converter
