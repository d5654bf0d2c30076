// Numbers as the converter writes them: exact decimal text, never a round trip through a double
// where the value is a written one (a word's value moves its decimal point, changes sign, or gets
// the point the target needs to read it the same), and computed values (G52 from the dry run,
// --expand) with the least digits that hold them to the input increment.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace kerf::converter {

// A written number: sign, digits without the point, and how many of them follow the point.
struct Decimal {
    bool negative = false;
    std::string digits;   // no sign, no point; may have leading zeros ("0055")
    int scale = 0;        // digits after the point
    bool point = false;   // written with a point ("10." has point and scale 0)
};

// Parses "-12.5", "+.5", "10.", "0055"; nullopt for anything else (expressions, exponents).
std::optional<Decimal> parse_decimal(std::string_view text);

// The value times 10^shift, exactly (shift > 0 moves the point right).
Decimal shifted(Decimal d, int shift);

// Text with a point: "0.1", "-12.5", "100." (no exponent, no trailing zeros after the point, a
// leading zero before a bare fraction).
std::string with_point(const Decimal& d);
// Text without a point when the value is whole ("100", "-3"), else as with_point.
std::string plain(const Decimal& d);
// Negated (a leading '-' added or removed); zero stays unsigned.
Decimal negated(Decimal d);
bool is_zero(const Decimal& d);

// A computed value (mm, degrees, seconds) written with a point and at most `digits` decimals,
// trailing zeros dropped: 45 → "45.", 12.50 → "12.5", -0.0004 at 3 digits → "0.".
std::string format_value(double value, int digits);

}  // namespace kerf::converter
