// A Custom Macro B value: a number or <vacant> (FANUC "null variable", written #0).
//
// FANUC rule (0i/16i/18i/30i operator manuals, "Custom macro" > "Variables" > "Undefined
// variables"): a variable that was never set, a local variable not given by a G65/G66 argument,
// and #0 hold no value at all; that is not the same as 0. How vacancy behaves in each place is
// documented where it is implemented (evaluate.cpp) and summarised here:
//   * replacement #i=#j copies vacancy (#1=#0 makes #1 vacant);
//   * in any other operation a vacant operand counts as 0 (#1=#0+0 is 0, #1=#0*5 is 0);
//   * EQ/NE tell vacant from 0, GT/LT/GE/LE treat vacant as 0;
//   * an NC address whose value is vacant is omitted (G90 X100 Y#1 with #1 vacant is G90 X100):
//     the interpreter tests `is_vacant` on the evaluated address value.
#pragma once

#include <cstdint>
#include <optional>

namespace kerf::interpreter::macro {

struct Value {
    bool vacant = true;
    double number = 0.0;   // meaningless (kept 0) when vacant
    // A G65/G66 argument written without a decimal point, stored in least input increments
    // (X10 → 0.010): ADP gives it back as 10. Any operation makes a plain value again.
    bool increments = false;

    static constexpr Value vacant_value() { return Value{true, 0.0, false}; }
    static constexpr Value of(double x) { return Value{false, x, false}; }
    static constexpr Value of_increments(double x) { return Value{false, x, true}; }

    constexpr bool is_vacant() const { return vacant; }
    // The operand value under FANUC's arithmetic rule: vacant counts as 0.
    constexpr double or_zero() const { return vacant ? 0.0 : number; }

    // Two vacant values are equal whatever `number` holds.
    friend constexpr bool operator==(const Value& a, const Value& b) {
        return a.vacant == b.vacant && (a.vacant || a.number == b.number);
    }
};

// True when an NC address given this value must be omitted (FANUC: "when an undefined variable
// is quoted, the address itself is ignored").
constexpr bool is_vacant(const Value& v) { return v.vacant; }

// FANUC rounding to an integer, half away from zero (ROUND[1.5] = 2, ROUND[-1.5] = -2). It is also
// the rule wherever a real value stands where an integer is needed: variable numbers (#[1.5] is
// #2), and NC addresses that take integers (M#1 with #1 = 3.5 is M4).
double round_half_away(double x);

// `round_half_away(x)` as an integer, or nullopt when x is not finite or outside [min, max].
std::optional<std::int64_t> round_to_integer(double x, std::int64_t min, std::int64_t max);

}  // namespace kerf::interpreter::macro
