// Custom Macro B evaluation. Source tags ([M-16i], [M-0i], [M-30i], [M-15i]) are listed in
// evaluate.hpp; "kerf" marks a choice of ours where the manuals say nothing.
#include "interpreter/macro/evaluate.hpp"
#include "interpreter/events.hpp"   // kerf_alarm::internal (check3)

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>

namespace kerf::interpreter::macro {

using ast::BinaryOp;
using ast::Expr;
using ast::ExprKind;
using ast::Function;

ast::Diagnostic to_diagnostic(const Error& error) {
    ast::Diagnostic d;
    d.range = error.range;
    d.severity = ast::Severity::error;
    d.code = error.code;
    d.message = error.message;
    return d;
}

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadiansPerDegree = kPi / 180.0;

// Largest variable number accepted from an index expression; larger ones are alarm 115.
constexpr std::int64_t kMaxVariableNumber = 99999999;

// Operands of AND/OR/XOR ([M-16i]: "performed on binary numbers bit by bit", 32 bits wide).
constexpr double kMaxBits = 4294967296.0;   // 2^32: the widest PMC/system value read as bits

bool is_comparison(BinaryOp op) {
    return op == BinaryOp::eq || op == BinaryOp::ne || op == BinaryOp::gt || op == BinaryOp::lt ||
           op == BinaryOp::ge || op == BinaryOp::le;
}
bool is_logical(BinaryOp op) { return op == BinaryOp::and_ || op == BinaryOp::or_ || op == BinaryOp::xor_; }
bool is_multiplicative(BinaryOp op) {
    return op == BinaryOp::mul || op == BinaryOp::div || op == BinaryOp::and_ || op == BinaryOp::mod;
}

const char* op_name(BinaryOp op) {
    switch (op) {
        case BinaryOp::add: return "+";
        case BinaryOp::sub: return "-";
        case BinaryOp::mul: return "*";
        case BinaryOp::div: return "/";
        case BinaryOp::or_: return "OR";
        case BinaryOp::xor_: return "XOR";
        case BinaryOp::and_: return "AND";
        case BinaryOp::mod: return "MOD";
        case BinaryOp::eq: return "EQ";
        case BinaryOp::ne: return "NE";
        case BinaryOp::gt: return "GT";
        case BinaryOp::lt: return "LT";
        case BinaryOp::ge: return "GE";
        case BinaryOp::le: return "LE";
    }
    return "?";
}

const char* function_name(Function f) {
    switch (f) {
        case Function::sin: return "SIN";
        case Function::cos: return "COS";
        case Function::tan: return "TAN";
        case Function::asin: return "ASIN";
        case Function::acos: return "ACOS";
        case Function::atan: return "ATAN";
        case Function::sqrt: return "SQRT";
        case Function::abs: return "ABS";
        case Function::bin: return "BIN";
        case Function::bcd: return "BCD";
        case Function::round: return "ROUND";
        case Function::fix: return "FIX";
        case Function::fup: return "FUP";
        case Function::ln: return "LN";
        case Function::exp: return "EXP";
        case Function::pow: return "POW";
        case Function::adp: return "ADP";
    }
    return "?";
}

std::string number_text(double x) {
    if (x == std::floor(x) && std::fabs(x) < 1e15) return fmt::format("{:.0f}", x);
    return fmt::format("{}", x);
}

std::string value_text(Value v) { return v.vacant ? std::string("<vacant>") : number_text(v.number); }

// "variable #34 does not exist", quoting the text when it is an indirect #[...].
std::string no_such_variable(int number, const std::string& text) {
    if (text == fmt::format("#{}", number)) return fmt::format("variable #{} does not exist on this control", number);
    return fmt::format("variable #{} (`{}`) does not exist on this control", number, text);
}

// A system variable kerf's tables do not have: the control may have it; the run cannot go on.
std::string not_modelled(int number, const std::string& text) {
    const std::string name = text == fmt::format("#{}", number) ? text : fmt::format("#{} (`{}`)", number, text);
    return fmt::format("system variable {} is not in kerf's tables for this control: the dry run stops here "
                       "(kerf's limit, not an alarm of the program)", name);
}

// No negative zero in results: -0 would print as "-0." and FANUC has no such value.
double clean(double x) { return x == 0.0 ? 0.0 : x; }

// --- angles ---------------------------------------------------------------------------------------
// [M-16i] "The units of angles used with SIN, COS, TAN, ASIN, ACOS and ATAN are degrees" (90°30'
// is 90.5). kerf: the angle is reduced to a quadrant and a remainder in [-45°, 45°] before the
// radian conversion, so multiples of 90° are exact (COS[90] = 0, SIN[180] = 0, TAN[90] is a
// division by zero) and so are ±30° and ±45° remainders (SIN[30] = 0.5): the control's own error
// ([M-16i] table "Errors involved in operations": 1e-8 for SIN/COS) hides far larger differences.
struct SinCos {
    double sin = 0.0;
    double cos = 1.0;
    bool quadrant_boundary_odd = false;   // angle is an odd multiple of 90° (cos exactly 0)
};

SinCos sincos_degrees(double degrees) {
    const double quadrant = std::round(degrees / 90.0);
    const double rest = degrees - quadrant * 90.0;   // in [-45, 45]
    double s = 0.0;
    double c = 1.0;
    if (rest == 30.0 || rest == -30.0) {
        s = rest > 0 ? 0.5 : -0.5;
        c = std::sqrt(3.0) / 2.0;
    } else if (rest == 45.0 || rest == -45.0) {
        s = rest > 0 ? std::sqrt(0.5) : -std::sqrt(0.5);
        c = std::sqrt(0.5);
    } else if (rest != 0.0) {
        s = std::sin(rest * kRadiansPerDegree);
        c = std::cos(rest * kRadiansPerDegree);
    }
    double q = std::fmod(quadrant, 4.0);
    if (q < 0) q += 4.0;
    SinCos r;
    switch (static_cast<int>(q)) {
        case 0: r.sin = s; r.cos = c; break;
        case 1: r.sin = c; r.cos = -s; break;
        case 2: r.sin = -s; r.cos = -c; break;
        default: r.sin = -c; r.cos = s; break;
    }
    r.sin = clean(r.sin);
    r.cos = clean(r.cos);
    r.quadrant_boundary_odd = rest == 0.0 && (q == 1.0 || q == 3.0);
    return r;
}

// Results of the inverse functions in degrees; values within 1e-12° of an integer are taken as
// that integer (kerf: ATAN[1]/[1] is 45, not 44.99999999999999, so FIX of it is 45; far below the
// control's 1.8e-6° ATAN error of [M-16i]).
double to_degrees(double radians) {
    const double d = radians / kRadiansPerDegree;
    const double r = std::round(d);
    return std::fabs(d - r) <= 1e-12 * std::fmax(1.0, std::fabs(d)) ? clean(r) : d;
}

// The two-argument arc tangent ATAN[y]/[x] = ATAN[y,x] ([M-16i], [M-30i]): the angle of the point
// (x, y). NAT = 0 ([M-0i] parameter 6004#0, the default): 0° to 360° (ATAN[-1]/[-1] = 225);
// NAT = 1: -180° to 180° (ATAN[-1]/[-1] = -135). ATAN[0]/[0] is 0 (kerf; the manuals are silent).
double atan2_degrees(double y, double x, AngleRange range) {
    double d = to_degrees(std::atan2(y, x));
    if (range == AngleRange::zero_to_360 && d < 0) d += 360.0;
    if (range == AngleRange::minus_180_to_180 && d == -180.0) d = 180.0;
    return clean(d);
}

bool near_integer(double x, double& integer) {
    if (!std::isfinite(x)) return false;
    integer = std::round(x);
    return std::fabs(x - integer) <= 1e-9;
}

// --- the evaluator ---------------------------------------------------------------------------------

class Evaluator {
public:
    Evaluator(const ast::SyntaxTree& tree, const Variables& variables, SystemVariables& system, const Options& options)
        : tree_(tree), variables_(variables), system_(system), options_(options) {}

    std::optional<Error> error;

    // Each of these is a value or an error: nullopt (a vacant Value for `value`) exactly when
    // `error` has been set.
    Value value(std::int32_t index);
    std::optional<bool> condition(std::int32_t index);
    std::optional<int> variable_number(std::int32_t index);

    // A node of the tree, or nullptr with an error (an index the grammar never makes).
    const Expr* node(std::int32_t index, ast::Range where) {
        if (index < 0 || static_cast<std::size_t>(index) >= tree_.exprs.size()) {
            fail(where, codes::bad_tree, kerf_alarm::internal, fmt::format("expression index {} is not in the syntax tree", index));
            return nullptr;
        }
        return &tree_.exprs[static_cast<std::size_t>(index)];
    }

    void fail(ast::Range range, const char* code, int alarm, std::string message) {
        if (!error) error = Error{range, code, alarm, std::move(message)};
    }
    Value fail_value(ast::Range range, const char* code, int alarm, std::string message) {
        fail(range, code, alarm, std::move(message));
        return Value::vacant_value();
    }

private:
    const ast::SyntaxTree& tree_;
    const Variables& variables_;   // read only: an expression never writes a variable
    SystemVariables& system_;      // #1000 and up
    const Options& options_;
    int depth_ = 0;

    std::string quote(const Expr& e) const { return std::string(tree_.slice(e.range())); }

    // [M-16i] "Brackets can be used to a depth of five levels including the brackets used to
    // enclose a function. When a depth of five levels is exceeded, alarm No. 118 occurs."
    bool enter(const Expr& e) {
        ++depth_;
        if (options_.max_nesting > 0 && depth_ > options_.max_nesting) {
            fail(e.range(), codes::nesting, 118,
                 fmt::format("brackets nested deeper than {} levels in `{}`", options_.max_nesting, quote(e)));
            return false;
        }
        return true;
    }
    void leave() { --depth_; }

    // [M-16i] alarm 111: "the result of a calculation is out of the allowable range
    // (-10^47 to -10^-29, 0, and 10^-29 to 10^47)"; the bound is Options::max_magnitude.
    Value checked(const Expr& e, double result) {
        if (!std::isfinite(result) || std::fabs(result) > options_.max_magnitude)
            return fail_value(e.range(), codes::overflow, 111,
                              fmt::format("result of `{}` is out of range ({})", quote(e), number_text(result)));
        return Value::of(clean(result));
    }

    Value read_variable(const Expr& e);
    Value binary(const Expr& e);
    Value apply(const Expr& e, BinaryOp op, Value a, Value b);
    Value function(const Expr& e);
    Value function_of(const Expr& e, Value a, Value b);
    bool atan_slot(std::int32_t index);
    Value with_atan2(std::int32_t index, const Expr& divisor_bracket, const Expr& division);
    std::optional<std::int64_t> bits(const Expr& e, Value v, const char* what);
    bool is_condition(std::int32_t index);
    bool compare(BinaryOp op, Value a, Value b) const;
};

Value Evaluator::value(std::int32_t index) {
    const Expr* ep = node(index, {});
    if (!ep) return Value::vacant_value();
    const Expr& e = *ep;
    switch (e.kind) {
        case ExprKind::number: return Value::of(tree_.number_value(e));
        case ExprKind::variable: return read_variable(e);
        case ExprKind::plus: return value(e.a);   // unary plus changes nothing, vacancy included
        case ExprKind::negate: {
            // [M-16i] "To reverse the sign of a variable value, prefix '-' to #" (G00 X-#1): a
            // signed quotation. kerf: a quoted vacant variable stays vacant with its sign, so
            // X-#1 is omitted like X#1 and #2=-#1 copies vacancy; anywhere else it counts as 0.
            const Value v = value(e.a);
            if (error || v.vacant) return v;
            return Value::of(clean(-v.number));
        }
        case ExprKind::bracket: {
            // Brackets only group: [#1] is #1, vacancy included.
            if (!enter(e)) return Value::vacant_value();
            const Value v = value(e.a);
            leave();
            return v;
        }
        case ExprKind::binary: return binary(e);
        case ExprKind::function: return function(e);
    }
    return fail_value(e.range(), codes::bad_tree, kerf_alarm::internal, "unknown expression node");
}

// [M-16i] "Variable number: #[<expression>]"; real values where an integer is needed are rounded
// (see round_half_away). A vacant index is 0, i.e. #0 (vacant as 0, the arithmetic rule).
std::optional<int> Evaluator::variable_number(std::int32_t index) {
    const Expr* ep = node(index, {});
    if (!ep) return std::nullopt;
    const Expr& e = *ep;
    if (e.kind != ExprKind::variable) {
        fail(e.range(), codes::bad_tree, kerf_alarm::internal, fmt::format("`{}` is not a variable", quote(e)));
        return std::nullopt;
    }
    const Value index_value = value(e.a);
    if (error) return std::nullopt;
    const double x = index_value.or_zero();
    const auto number = round_to_integer(x, 0, kMaxVariableNumber);
    if (!number) {
        fail(e.range(), codes::variable_number, 115,
             fmt::format("`{}` designates variable number {}, which does not exist", quote(e), number_text(x)));
        return std::nullopt;
    }
    return static_cast<int>(*number);
}

// Reading an undefined number is alarm 115 ([M-16i] "illegal variable number").
Value Evaluator::read_variable(const Expr& e) {
    const auto number = variable_number(static_cast<std::int32_t>(&e - tree_.exprs.data()));
    if (!number) return Value::vacant_value();
    const std::optional<Value> v = variables_.read(*number, system_);
    if (!v && !system_.modelled(*number))
        return fail_value(e.range(), codes::variable_number, kerf_alarm::unknown_variable, not_modelled(*number, quote(e)));
    if (!v)
        return fail_value(e.range(), codes::variable_number, 115, no_such_variable(*number, quote(e)));
    return *v;
}

// ATAN with one argument, possibly signed, possibly ending a product: the place where a
// following "/[b]" turns it into the two-argument form.
bool Evaluator::atan_slot(std::int32_t index) {
    if (index < 0 || static_cast<std::size_t>(index) >= tree_.exprs.size()) return false;
    const Expr& e = tree_.exprs[static_cast<std::size_t>(index)];
    switch (e.kind) {
        case ExprKind::function: return e.function() == Function::atan && e.b < 0;
        case ExprKind::negate:
        case ExprKind::plus: return atan_slot(e.a);
        case ExprKind::binary: return is_multiplicative(e.binary_op()) && atan_slot(e.b);
        default: return false;
    }
}

// [M-16i] "#i = ATAN[#j]/[#k]": the slash belongs to the function, whose operand is the bracket
// after it. The grammar has made a division whose left side ends with ATAN[#j] (index), so the
// left side is rebuilt around the two-argument value: -ATAN[a]/[b] is -(ATAN[a]/[b]) and
// 2*ATAN[a]/[b] is 2*(ATAN[a]/[b]).
Value Evaluator::with_atan2(std::int32_t index, const Expr& divisor, const Expr& division) {
    const Expr& e = tree_.exprs[static_cast<std::size_t>(index)];
    switch (e.kind) {
        case ExprKind::function: {
            if (!enter(e)) return Value::vacant_value();
            const Value y = value(e.a);
            leave();
            if (error) return Value::vacant_value();
            const Value x = value(static_cast<std::int32_t>(&divisor - tree_.exprs.data()));   // counts its bracket
            if (error) return Value::vacant_value();
            // Vacant operands count as 0 (arithmetic rule).
            return checked(division, atan2_degrees(y.or_zero(), x.or_zero(), options_.angle_range));
        }
        case ExprKind::plus: return with_atan2(e.a, divisor, division);
        case ExprKind::negate: {
            const Value v = with_atan2(e.a, divisor, division);
            if (error) return v;
            return Value::of(clean(-v.number));
        }
        case ExprKind::binary: {
            const Value a = value(e.a);
            if (error) return a;
            const Value b = with_atan2(e.b, divisor, division);
            if (error) return b;
            return apply(e, e.binary_op(), a, b);
        }
        default: return fail_value(e.range(), codes::bad_tree, kerf_alarm::internal, "not an ATAN form");
    }
}

Value Evaluator::binary(const Expr& e) {
    const BinaryOp op = e.binary_op();
    if (is_comparison(op))
        // A conditional expression has no numeric value: "#2=[1 LT 2]" is illegal (alarm 114).
        return fail_value(e.range(), codes::format, 114,
                          fmt::format("`{}` is a comparison; it can only be the condition of IF or WHILE", quote(e)));
    if (op == BinaryOp::div) {
        const Expr* right = node(e.b, e.range());
        if (!right) return Value::vacant_value();
        if (right->kind == ExprKind::bracket && atan_slot(e.a)) return with_atan2(e.a, *right, e);
    }
    const Value a = value(e.a);
    if (error) return a;
    const Value b = value(e.b);
    if (error) return b;
    return apply(e, op, a, b);
}

// Bit operands: integers of up to 32 bits (negative values in two's complement).
std::optional<std::int64_t> Evaluator::bits(const Expr& e, Value v, const char* what) {
    double integer = 0.0;
    const double x = v.or_zero();
    if (!near_integer(x, integer) || std::fabs(integer) >= kMaxBits) {
        fail(e.range(), codes::argument, 119,
             fmt::format("{} needs integer operands below 2^32; `{}` has {}", what, quote(e), number_text(x)));
        return std::nullopt;
    }
    return static_cast<std::int64_t>(integer);
}

// Binary operators ([M-16i] table "Arithmetic and logic operation"). Vacant operands count as 0
// ([M-16i] "Undefined variables": #2=#1*5 and #2=#1+#1 give 0 when #1 is vacant).
Value Evaluator::apply(const Expr& e, BinaryOp op, Value va, Value vb) {
    const double a = va.or_zero();
    const double b = vb.or_zero();
    switch (op) {
        case BinaryOp::add: return checked(e, a + b);
        case BinaryOp::sub: return checked(e, a - b);
        case BinaryOp::mul: return checked(e, a * b);
        case BinaryOp::div:
            // [M-16i] alarm 112 "division by zero" (a vacant divisor is 0).
            if (b == 0.0)
                return fail_value(e.range(), codes::division_by_zero, 112,
                                  fmt::format("division by zero in `{}` (divisor {})", quote(e), value_text(vb)));
            return checked(e, a / b);
        case BinaryOp::mod: {
            // [M-30i] "#i = #j MOD #k: remainder": the fractions of #j and #k are rounded off
            // (half away from zero) first; the remainder has the sign of #j (-10 MOD 3 = -1);
            // #k rounding to 0 is a division by zero (alarm 112).
            const double j = round_half_away(a);
            const double k = round_half_away(b);
            if (k == 0.0)
                return fail_value(e.range(), codes::division_by_zero, 112,
                                  fmt::format("MOD by zero in `{}` (divisor {})", quote(e), value_text(vb)));
            return checked(e, std::fmod(j, k));
        }
        case BinaryOp::or_:
        case BinaryOp::xor_:
        case BinaryOp::and_: {
            // [M-16i] "#i = #j OR #k / XOR / AND: a logical operation is performed on binary
            // numbers bit by bit." kerf: the operands must be integers (within 1e-9) of fewer than
            // 32 bits, else alarm 119; negative values take part in two's complement.
            const auto x = bits(e, va, op_name(op));
            if (!x) return Value::vacant_value();
            const auto y = bits(e, vb, op_name(op));
            if (!y) return Value::vacant_value();
            std::int64_t r = 0;
            if (op == BinaryOp::or_) r = *x | *y;
            else if (op == BinaryOp::xor_) r = *x ^ *y;
            else r = *x & *y;
            return checked(e, static_cast<double>(r));
        }
        default: break;
    }
    return fail_value(e.range(), codes::format, 114,
                      fmt::format("`{}` is a comparison; it can only be the condition of IF or WHILE", quote(e)));
}

Value Evaluator::function(const Expr& e) {
    const Function f = e.function();
    const bool two = f == Function::pow;                 // POW[a,b]
    const bool either = f == Function::atan;             // ATAN[a] or ATAN[a,b]
    const bool has_b = e.b >= 0;
    if (!either && has_b != two)
        return fail_value(e.range(), codes::format, 114,
                          fmt::format("{} takes {} argument{} (`{}`)", function_name(f), two ? 2 : 1, two ? "s" : "",
                                      quote(e)));
    if (!enter(e)) return Value::vacant_value();
    const Value a = value(e.a);
    Value b = Value::vacant_value();
    if (!error && has_b) b = value(e.b);
    leave();
    if (error) return Value::vacant_value();
    return function_of(e, a, b);
}

// The functions ([M-16i] table "Arithmetic and logic operation"; ATAN[a,b], POW, ADP [M-30i]).
// A vacant argument counts as 0.
Value Evaluator::function_of(const Expr& e, Value va, Value vb) {
    const double x = va.or_zero();
    const double y = vb.or_zero();
    switch (e.function()) {
        case Function::sin: return checked(e, sincos_degrees(x).sin);
        case Function::cos: return checked(e, sincos_degrees(x).cos);
        case Function::tan: {
            // [M-16i] "TAN performs SIN/COS"; alarm 112 lists "tan 90°" among divisions by zero.
            const SinCos sc = sincos_degrees(x);
            if (sc.quadrant_boundary_odd)
                return fail_value(e.range(), codes::division_by_zero, 112,
                                  fmt::format("`{}`: the tangent of {}° is infinite", quote(e), number_text(x)));
            const double quadrant = std::round(x / 90.0);
            const double rest = x - quadrant * 90.0;
            double t = 0.0;
            if (rest == 45.0 || rest == -45.0) t = rest > 0 ? 1.0 : -1.0;
            else t = std::tan(rest * kRadiansPerDegree);
            if (std::fmod(std::fabs(quadrant), 2.0) == 1.0) t = -1.0 / t;   // tan(90°+r) = -1/tan(r)
            return checked(e, t);
        }
        case Function::asin: {
            // [M-0i] "ASIN: NAT = 0: 270° to 90°; NAT = 1: -90° to 90°. When #j is beyond the
            // range of -1 to 1, an alarm is issued" (alarm 119 in the 16i numbering).
            if (x < -1.0 || x > 1.0)
                return fail_value(e.range(), codes::argument, 119,
                                  fmt::format("ASIN of {} (`{}`): the argument must be within -1 to 1", number_text(x),
                                              quote(e)));
            double d = to_degrees(std::asin(x));
            if (options_.angle_range == AngleRange::zero_to_360 && d < 0) d += 360.0;
            return checked(e, d);
        }
        case Function::acos: {
            // [M-0i] "ACOS: the solution ranges from 180° to 0°"; beyond -1..1 alarm 119.
            if (x < -1.0 || x > 1.0)
                return fail_value(e.range(), codes::argument, 119,
                                  fmt::format("ACOS of {} (`{}`): the argument must be within -1 to 1", number_text(x),
                                              quote(e)));
            return checked(e, to_degrees(std::acos(x)));
        }
        case Function::atan:
            // ATAN[a,b] ([M-30i]) is ATAN[a]/[b]. ATAN[a] alone ([M-30i] one-argument form)
            // is the principal value, -90° to 90°, whatever NAT says.
            if (e.b >= 0) return checked(e, atan2_degrees(x, y, options_.angle_range));
            return checked(e, to_degrees(std::atan(x)));
        case Function::sqrt:
            // [M-16i] alarm 119: "the SQRT argument is negative".
            if (x < 0.0)
                return fail_value(e.range(), codes::argument, 119,
                                  fmt::format("square root of the negative number {} (`{}`)", number_text(x), quote(e)));
            return checked(e, std::sqrt(x));
        case Function::abs: return checked(e, std::fabs(x));
        case Function::bcd: {
            // [M-16i] "BCD: conversion from BIN to BCD" (BCD[123] = 0x123 = 291), for PMC signals;
            // alarm 119 "BCD argument is negative". kerf: the argument must be an integer
            // 0..99999999 (eight BCD digits, 32 bits).
            double n = 0.0;
            if (!near_integer(x, n) || n < 0 || n > 99999999.0)
                return fail_value(e.range(), codes::argument, 119,
                                  fmt::format("BCD of {} (`{}`): the argument must be an integer from 0 to 99999999",
                                              number_text(x), quote(e)));
            auto v = static_cast<std::uint64_t>(n);
            std::uint64_t out = 0;
            for (int shift = 0; v != 0; shift += 4, v /= 10) out |= (v % 10) << shift;
            return checked(e, static_cast<double>(out));
        }
        case Function::bin: {
            // [M-16i] "BIN: conversion from BCD to BIN" (BIN[291] = 123); alarm 119 when a
            // 4-bit digit is not 0..9.
            double n = 0.0;
            if (!near_integer(x, n) || n < 0 || n >= kMaxBits)
                return fail_value(e.range(), codes::argument, 119,
                                  fmt::format("BIN of {} (`{}`): the argument must be a BCD integer of up to 32 bits",
                                              number_text(x), quote(e)));
            auto v = static_cast<std::uint64_t>(n);
            std::uint64_t out = 0;
            std::uint64_t scale = 1;
            for (; v != 0; v >>= 4, scale *= 10) {
                const std::uint64_t digit = v & 0xF;
                if (digit > 9)
                    return fail_value(e.range(), codes::argument, 119,
                                      fmt::format("BIN of {} (`{}`): a 4-bit digit is {}, not a decimal digit",
                                                  number_text(x), quote(e), digit));
                out += digit * scale;
            }
            return checked(e, static_cast<double>(out));
        }
        case Function::round: {
            // [M-16i] "ROUND in an arithmetic/logic command or IF/WHILE rounds off at the first
            // decimal place" (ROUND[1.2345] = 1.0; half away from zero: ROUND[-1.5] = -2); in an
            // NC address it rounds to the address's least input increment (Options::round_increment).
            if (options_.round_increment > 0.0) {
                const double inc = options_.round_increment;
                return checked(e, round_half_away(x / inc) * inc);
            }
            return checked(e, round_half_away(x));
        }
        case Function::fix:
            // [M-16i] "Rounding down: the absolute value of the integer is less than the absolute
            // value of the original number": FIX[1.2] = 1, FIX[-1.2] = -1 (toward zero).
            return checked(e, std::trunc(x));
        case Function::fup:
            // [M-16i] "Rounding up: the absolute value of the integer is greater than the absolute
            // value of the original number": FUP[1.2] = 2, FUP[-1.2] = -2 (away from zero).
            return checked(e, x < 0 ? std::floor(x) : std::ceil(x));
        case Function::ln:
            // [M-0i] "LN: when the antilogarithm (#j) is zero or smaller, an alarm is issued" (119).
            if (x <= 0.0)
                return fail_value(e.range(), codes::argument, 119,
                                  fmt::format("LN of {} (`{}`): the argument must be greater than 0", number_text(x),
                                              quote(e)));
            return checked(e, std::log(x));
        case Function::exp:
            // [M-0i] "EXP: when the result exceeds 3.65e47 (#j about 110.0) an overflow occurs" (111).
            return checked(e, std::exp(x));
        case Function::pow: {
            // [M-30i] "POW[#j,#k]: #j to the power #k". kerf: a negative base needs an integer
            // exponent and 0 needs a positive one, else alarm 119 (the result is not a real number).
            double integer = 0.0;
            if (x < 0.0 && !near_integer(y, integer))
                return fail_value(e.range(), codes::argument, 119,
                                  fmt::format("POW of the negative base {} to the fractional power {} (`{}`)",
                                              number_text(x), number_text(y), quote(e)));
            if (x == 0.0 && y <= 0.0)
                return fail_value(e.range(), codes::argument, 119,
                                  fmt::format("POW of 0 to the power {} (`{}`)", number_text(y), quote(e)));
            if (x < 0.0) return checked(e, std::pow(x, integer));
            return checked(e, std::pow(x, y));
        }
        case Function::adp:
            // [M-30i] "ADP: add a decimal point": an argument passed without a point (in least
            // increments) is scaled back by Options::adp_factor; any other value is returned as is.
            return checked(e, va.increments ? x * options_.adp_factor : x);
    }
    return fail_value(e.range(), codes::bad_tree, kerf_alarm::internal, "unknown function");
}

// Comparisons ([M-16i] "Conditional expressions" and "Undefined variables"):
//   EQ and NE tell vacant from 0: with #1 vacant, [#1 EQ #0] holds and [#1 EQ 0] does not;
//   with #1 = 0, [#1 EQ #0] does not hold, [#1 NE 0] does not hold.
//   GT, LT, GE, LE take vacant as 0: [#1 GE #0] holds for #1 vacant or 0, [#1 GT 0] for neither.
// Numbers compare exactly ([M-15i]: "allow for the possible error ... IF [ABS[#1-#2] LT 0.1]").
bool Evaluator::compare(BinaryOp op, Value a, Value b) const {
    const auto equal = [&] { return (a.vacant || b.vacant) ? (a.vacant && b.vacant) : a.number == b.number; };
    switch (op) {
        case BinaryOp::eq: return equal();
        case BinaryOp::ne: return !equal();
        case BinaryOp::gt: return a.or_zero() > b.or_zero();
        case BinaryOp::lt: return a.or_zero() < b.or_zero();
        case BinaryOp::ge: return a.or_zero() >= b.or_zero();
        case BinaryOp::le: return a.or_zero() <= b.or_zero();
        default: return false;
    }
}

bool Evaluator::is_condition(std::int32_t index) {
    if (index < 0 || static_cast<std::size_t>(index) >= tree_.exprs.size()) return false;
    const Expr& e = tree_.exprs[static_cast<std::size_t>(index)];
    if (e.kind == ExprKind::bracket) return is_condition(e.a);
    if (e.kind != ExprKind::binary) return false;
    if (is_comparison(e.binary_op())) return true;
    return options_.logical_conditions && is_logical(e.binary_op()) && is_condition(e.a) && is_condition(e.b);
}

// IF [<conditional expression>] / WHILE [<conditional expression>] ([M-16i] "Conditional
// expressions": a relational operator between two expressions). [M-30i] also accepts AND, OR
// and XOR between bracketed conditions (IF [[#1 EQ 1] AND [#2 GT 0]]); both sides are evaluated.
std::optional<bool> Evaluator::condition(std::int32_t index) {
    const Expr* ep = node(index, {});
    if (!ep) return std::nullopt;
    const Expr& e = *ep;
    if (e.kind == ExprKind::bracket) {
        if (!enter(e)) return std::nullopt;
        const auto r = condition(e.a);
        leave();
        return r;
    }
    if (e.kind == ExprKind::binary && is_comparison(e.binary_op())) {
        const Value a = value(e.a);
        if (error) return std::nullopt;
        const Value b = value(e.b);
        if (error) return std::nullopt;
        return compare(e.binary_op(), a, b);
    }
    if (e.kind == ExprKind::binary && is_logical(e.binary_op()) && options_.logical_conditions && is_condition(e.a) &&
        is_condition(e.b)) {
        const auto a = condition(e.a);
        if (!a) return std::nullopt;
        const auto b = condition(e.b);
        if (!b) return std::nullopt;
        switch (e.binary_op()) {
            case BinaryOp::and_: return *a && *b;
            case BinaryOp::or_: return *a || *b;
            default: return *a != *b;
        }
    }
    fail(e.range(), codes::format, 114,
         fmt::format("`{}` is not a condition: IF and WHILE need a comparison (EQ NE GT LT GE LE)", quote(e)));
    return std::nullopt;
}

}  // namespace

Result evaluate(const ast::SyntaxTree& tree, std::int32_t expr_index, const Variables& variables, SystemVariables& system,
                const Options& options) {
    Evaluator ev(tree, variables, system, options);
    Value v = ev.value(expr_index);
    if (ev.error) return Result{Value::vacant_value(), std::move(ev.error)};
    return Result{v, std::nullopt};
}

ConditionResult evaluate_condition(const ast::SyntaxTree& tree, std::int32_t expr_index, const Variables& variables,
                                   SystemVariables& system, const Options& options) {
    Evaluator ev(tree, variables, system, options);
    const auto c = ev.condition(expr_index);
    if (ev.error) return ConditionResult{std::nullopt, std::move(ev.error)};
    return ConditionResult{c, std::nullopt};
}

NumberResult variable_number(const ast::SyntaxTree& tree, std::int32_t variable_expr, const Variables& variables,
                             const Options& options) {
    Evaluator ev(tree, variables, variables.system(), options);
    const auto n = ev.variable_number(variable_expr);
    if (ev.error) return NumberResult{0, std::move(ev.error)};
    return NumberResult{*n, std::nullopt};
}

// [M-16i] "Replacement #i = <expression>": a replacement copies vacancy (#2=#1 with #1 vacant
// leaves #2 vacant). "#0 cannot be assigned" and write-protected variables give alarm 116.
std::optional<Error> assign(const ast::SyntaxTree& tree, const ast::Statement& statement, Variables& variables,
                            SystemVariables& system, const Options& options) {
    Evaluator ev(tree, variables, system, options);
    if (statement.kind != ast::StatementKind::assign) {
        ev.fail(statement.range, codes::bad_tree, kerf_alarm::internal, "not an assignment statement");
        return ev.error;
    }
    const Value v = ev.value(statement.value);
    if (ev.error) return ev.error;
    const auto number = ev.variable_number(statement.target);
    if (ev.error) return ev.error;
    const Expr& target = tree.exprs[static_cast<std::size_t>(statement.target)];
    const std::string text(tree.slice(target.range()));
    switch (variables.write(*number, v, system)) {
        case WriteResult::ok: return std::nullopt;
        case WriteResult::undefined:
            if (!system.modelled(*number))
                return Error{target.range(), codes::variable_number, kerf_alarm::unknown_variable, not_modelled(*number, text)};
            return Error{target.range(), codes::variable_number, 115, no_such_variable(*number, text)};
        case WriteResult::read_only:
            return Error{target.range(), codes::write_protected, 116,
                         *number == numbers::vacant
                             ? fmt::format("#0 is always vacant and cannot be assigned (`{}`)", text)
                             : fmt::format("variable #{} (`{}`) is write-protected", *number, text)};
        case WriteResult::invalid_value:
            return Error{statement.range, codes::argument, 119,
                         fmt::format("variable #{} does not accept the value {}", *number, value_text(v))};
    }
    return std::nullopt;
}

std::optional<Atan2Operands> atan2_operands(const ast::SyntaxTree& tree, std::int32_t expr_index) {
    const auto at = [&](std::int32_t i) -> const Expr* {
        return i >= 0 && static_cast<std::size_t>(i) < tree.exprs.size() ? &tree.exprs[static_cast<std::size_t>(i)] : nullptr;
    };
    const Expr* e = at(expr_index);
    if (!e || e->kind != ExprKind::binary || e->binary_op() != BinaryOp::div) return std::nullopt;
    const Expr* left = at(e->a);
    const Expr* right = at(e->b);
    if (!left || !right || right->kind != ExprKind::bracket) return std::nullopt;
    if (left->kind != ExprKind::function || left->function() != Function::atan || left->b >= 0) return std::nullopt;
    return Atan2Operands{left->a, e->b};
}

}  // namespace kerf::interpreter::macro
