// The Custom Macro B expression evaluator: a syntax-tree expression (ast::Expr) and the variables
// in, a value or a FANUC alarm out. Pure: no I/O; the only side effects are the reads the
// SystemVariables object makes of its own state.
//
// Sources of the rules (each function in evaluate.cpp names the one it implements):
//   [M-16i]  FANUC Series 16i/18i operator manual (B-63534EN, B-63684EN), chapter "Custom macro":
//            table "Arithmetic and logic operation", explanations, alarms 111-119.
//   [M-0i]   FANUC Series 0i-D/0i-F operator manual (B-64304EN, B-64604EN), same chapter, and
//   [M-30i]  FANUC Series 30i/31i/32i operator manual (B-63944EN, B-64484EN): ATAN[a,b], POW, ADP,
//            MOD, one-argument ATAN, logical AND/OR in conditions, NAT (parameter 6004#0).
//   [M-15i]  FANUC Series 15i operator manual (B-63324EN) "Limitation": precision remarks.
// Alarm numbers are those of the 16i/18i list (the 0i-D/30i "PS0xxx" alarms have the same numbers):
//   111 calculated data overflow, 112 division by zero (including TAN[90]), 114 format error in
//   macro, 115 illegal variable number, 116 write-protected variable, 118 bracket nesting
//   (more than five levels), 119 illegal argument (SQRT of a negative, BCD/BIN, ASIN/ACOS/LN domain).
//
// Precision: FANUC 0i/16i keep about 8 significant decimal digits in variables ([M-16i] "the
// precision of variable values is about 8 decimal digits"), the 15i/30i IEEE doubles. We compute
// and store in double and never round intermediate results, so results agree with a control to
// its own precision but not bit for bit; programs that compare computed values with EQ are as
// fragile here as on the control ([M-15i] "Relational operators").
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ast/diagnostic.hpp"
#include "ast/diagnostic_ids.hpp"
#include "ast/syntax.hpp"
#include "interpreter/macro/value.hpp"
#include "interpreter/macro/variables.hpp"

namespace kerf::interpreter::macro {

// Solution range of ASIN and two-argument ATAN: bit 0 (NAT) of parameter 6004.
enum class AngleRange : std::uint8_t {
    zero_to_360,       // NAT = 0 (default of 0/16/18/0i/30i): ATAN 0..360, ASIN 270..360 and 0..90
    minus_180_to_180,  // NAT = 1: ATAN -180..180, ASIN -90..90
};

struct Options {
    AngleRange angle_range = AngleRange::zero_to_360;
    // |result| above this is alarm 111. 1e47 is the range of 0i/16i/18i ("-10^47 to -10^-29, 0,
    // 10^-29 to 10^47"); a 30i uses doubles (about 1e308). Non-finite results are always 111.
    double max_magnitude = 1e47;
    // Bracket nesting limit, function brackets included ([M-16i]: five levels, alarm 118);
    // 0 = unlimited.
    int max_nesting = 5;
    // ROUND in an NC address rounds to the address's least input increment ([M-16i] "when the
    // ROUND function is used in NC statement addresses ..."): the interpreter sets the increment
    // (e.g. 0.001) when it evaluates an address; 0 = macro statements: round to an integer.
    double round_increment = 0.0;
    // ADP[x] = x * adp_factor when x is an argument written without a point (Value::increments),
    // else x. FANUC passes G65 arguments written without a decimal point in
    // least-input-increment units (X10 -> #24 = 0.010 on IS-B mm) and ADP gives back the value
    // "as if written with a point" (10.). Only the interpreter knows the increment; with the
    // default 1 ADP returns its argument unchanged.
    double adp_factor = 1.0;
    // AND/OR/XOR of two conditions inside IF/WHILE (30i, IF [[#1 EQ 1] AND [#2 EQ 2]]).
    bool logical_conditions = true;
};

// Stable error codes: "M0" + the FANUC alarm number; M09xx are kerf's own.
namespace codes {
inline constexpr const char* overflow = ast::diagnostic_id::macro_overflow;          // alarm 111
inline constexpr const char* division_by_zero = ast::diagnostic_id::macro_division_by_zero;  // alarm 112
inline constexpr const char* format = ast::diagnostic_id::macro_format;            // alarm 114
inline constexpr const char* variable_number = ast::diagnostic_id::macro_variable_number;   // alarm 115
inline constexpr const char* write_protected = ast::diagnostic_id::macro_write_protected;   // alarm 116
inline constexpr const char* nesting = ast::diagnostic_id::macro_bracket_nesting;           // alarm 118
inline constexpr const char* argument = ast::diagnostic_id::macro_argument;          // alarm 119
inline constexpr const char* bad_tree = ast::diagnostic_id::macro_bad_tree;          // not an expression the grammar makes
}  // namespace codes

struct Error {
    ast::Range range;     // the offending node (operator, function call, variable)
    std::string code;     // codes::...
    int alarm = 0;        // FANUC alarm number; kerf_alarm::internal for M0901 (events.hpp)
    std::string message;  // what is wrong, quoting the text
};

// As a diagnostic (severity error; hint empty) for reports and the LSP.
ast::Diagnostic to_diagnostic(const Error& error);

struct Result {
    Value value;
    std::optional<Error> error;   // when set, value is vacant and meaningless
    bool ok() const { return !error; }
};

struct ConditionResult {
    std::optional<bool> value;    // a value or an error: nullopt exactly when error is set
    std::optional<Error> error;
    bool ok() const { return !error; }
};

struct NumberResult {
    int number = 0;
    std::optional<Error> error;
    bool ok() const { return !error; }
};

// Expressions only read variables: every evaluation takes them const, so no expression can change
// one (only `assign` writes). The variables #1000 and up are answered by a SystemVariables object:
// the one the Variables were built with, or the one given (the interpreter reads a block ahead with
// the system variables of its copy of the machine state, and writes with those of the block being
// run).

// The value of expression `expr_index` (an index into tree.exprs). A comparison is not a value
// (FANUC: "#2=[1 LT 2]" is a format error): it is alarm 114 here; use evaluate_condition.
Result evaluate(const ast::SyntaxTree& tree, std::int32_t expr_index, const Variables& variables,
                SystemVariables& system, const Options& options = {});
inline Result evaluate(const ast::SyntaxTree& tree, std::int32_t expr_index, const Variables& variables,
                       const Options& options = {}) {
    return evaluate(tree, expr_index, variables, variables.system(), options);
}

// The condition of IF [..] GOTO/THEN and WHILE [..] DO: a comparison (EQ NE GT LT GE LE), in
// brackets or not, or (Options::logical_conditions) AND/OR/XOR of two conditions. Anything
// else is alarm 114.
ConditionResult evaluate_condition(const ast::SyntaxTree& tree, std::int32_t expr_index, const Variables& variables,
                                   SystemVariables& system, const Options& options = {});
inline ConditionResult evaluate_condition(const ast::SyntaxTree& tree, std::int32_t expr_index,
                                          const Variables& variables, const Options& options = {}) {
    return evaluate_condition(tree, expr_index, variables, variables.system(), options);
}

// The number a variable node (#1, #[#2+1]) designates: its index expression rounded half away
// from zero (#[1.4] is #1, #[1.5] is #2; a vacant index is #0). Alarm 115 when the index is
// negative or too large. Does not check that the variable exists.
NumberResult variable_number(const ast::SyntaxTree& tree, std::int32_t variable_expr, const Variables& variables,
                             const Options& options = {});

// Executes `#target = value` (a statement of kind assign): evaluates the value, then the target
// number, then writes (#1000 and up through `system`). Replacement keeps vacancy (#1=#0 makes #1
// vacant). Errors: those of the expressions, 115 (no such variable), 116 (#0 or a read-only
// variable), 119 (value refused).
std::optional<Error> assign(const ast::SyntaxTree& tree, const ast::Statement& statement, Variables& variables,
                            SystemVariables& system, const Options& options = {});
inline std::optional<Error> assign(const ast::SyntaxTree& tree, const ast::Statement& statement, Variables& variables,
                                   const Options& options = {}) {
    return assign(tree, statement, variables, variables.system(), options);
}

// The classic two-argument arc tangent ATAN[a]/[b]: the grammar reads it as a division whose left
// side is ATAN with one argument and whose right side is a bracket. Returns the indices of a and
// of the bracket [b] when `expr_index` is exactly that division. (The evaluator also recognises
// the form when it ends a product, as in 2*ATAN[a]/[b] or -ATAN[a]/[b].)
struct Atan2Operands {
    std::int32_t y = -1;   // a
    std::int32_t x = -1;   // [b]
};
std::optional<Atan2Operands> atan2_operands(const ast::SyntaxTree& tree, std::int32_t expr_index);

}  // namespace kerf::interpreter::macro
