// Helpers shared by the rule families (internal to analyzer/rules/).
#pragma once

#include <fmt/format.h>

#include <optional>
#include <string>

#include <array>
#include <cctype>
#include <map>
#include <type_traits>

#include "analyzer/registry.hpp"
#include "dialects/functions.hpp"

namespace kerf::analyzer::rules {

inline Rule make_rule(std::string id, std::string name, Category category, Severity severity, RuleDocs docs) {
    Rule r;
    r.id = std::move(id);
    r.name = std::move(name);
    r.category = category;
    r.severity = severity;
    r.docs = std::move(docs);
    return r;
}

// make_rule with the category of a family fixed: `const auto rule = rule_maker(Category::macro);`.
inline auto rule_maker(Category category) {
    return [category](std::string id, std::string name, Severity s, RuleDocs docs) {
        return make_rule(std::move(id), std::move(name), category, s, std::move(docs));
    };
}

// A rule whose findings are the parser's diagnostics with these codes (docs/diagnostics.md).
inline Rule diagnostic_rule(std::string id, std::string name, Severity severity, std::vector<std::string> codes,
                            RuleDocs docs) {
    Rule r = make_rule(std::move(id), std::move(name), Category::syntax, severity, std::move(docs));
    r.diagnostics = std::move(codes);
    return r;
}

// A rule whose findings are interpreter alarms with numbers in [first, last].
inline Rule alarm_rule(std::string id, std::string name, Category category, Severity severity,
                       std::vector<std::pair<int, int>> alarms, RuleDocs docs) {
    Rule r = make_rule(std::move(id), std::move(name), category, severity, std::move(docs));
    r.alarms = std::move(alarms);
    return r;
}

// Modifiers of a rule as it is registered: `r.add(fixable(opt_in(static_rule<C>(...))))`.
inline Rule fixable(Rule r) {   // its static check attaches text edits (docs: "fix")
    r.has_fix = true;
    return r;
}
inline Rule opt_in(Rule r) {   // off unless .kerf.toml turns it on
    r.enabled = false;
    return r;
}
// A diagnostic rule whose findings carry the fix `fix` makes from the diagnostic.
inline Rule with_diagnostic_fix(Rule r, decltype(Rule::diagnostic_fix) fix) {
    r.diagnostic_fix = std::move(fix);
    r.has_fix = true;
    return r;
}
// Also the findings of the dry run's alarms in these ranges (a static rule that the run confirms).
inline Rule with_alarms(Rule r, std::vector<std::pair<int, int>> alarms) {
    r.alarms = std::move(alarms);
    return r;
}

inline Rule explaining(Rule r, std::vector<std::pair<int, int>> alarms) {
    r.explains = std::move(alarms);
    return r;
}

// A check with data members writes them in state() (rule.hpp StateKey): incremental checking
// compares them. A check without members has no state.
template <class C>
constexpr bool writes_state = sizeof(C) == sizeof(StaticCheck) ||
                              !std::is_same_v<decltype(&C::state), void (StaticCheck::*)(StateKey&) const>;

// A static rule whose check is the class C (default-constructed per file, copied for checkpoints).
template <class C>
Rule static_rule(Rule r) {
    static_assert(writes_state<C>, "a static check with data members must override StaticCheck::state");
    r.make_static = [] { return std::make_unique<C>(); };
    r.clone_static = [](const StaticCheck& c) -> std::unique_ptr<StaticCheck> { return std::make_unique<C>(static_cast<const C&>(c)); };
    return r;
}

// A program rule: the stateless check C sees each program whole (rule.hpp ProgramCheck).
template <class C>
Rule program_rule(Rule r) {
    r.program_check = std::make_shared<const C>();
    return r;
}

template <class C>
Rule dynamic_rule(Rule r) {
    r.make_dynamic = [] { return std::make_unique<C>(); };
    return r;
}

// The token's integer value (P41001, T0101) or nullopt (expressions, fractions, no value).
inline std::optional<std::int64_t> integer_of(const ast::SyntaxTree& tree, const ast::Token& t) {
    return ast::integer_value(tree, t);
}

// The first word with `letter` in the block that has a plain number, with its value.
struct NumberWord {
    std::uint32_t token;
    double value;
};
inline std::optional<NumberWord> number_word(const BlockContext& b, char letter) {
    const std::uint32_t first = b.view.first_token();
    const auto tokens = b.view.tokens();
    for (std::uint32_t i = 0; i < tokens.size(); ++i)
        if (tokens[i].kind == ast::TokenKind::word && tokens[i].letter == letter && tokens[i].is_number())
            return NumberWord{first + i, b.tree().number_value(tokens[i])};
    return std::nullopt;
}

}  // namespace kerf::analyzer::rules

namespace kerf::analyzer::rules {

// The motion (group 01) function in force for the block: its own code, else the modal one.
inline dialects::FunctionId motion_function(const BlockContext& b) {
    for (const ast::CodeRef& c : b.g)
        if (c.info && c.info->has(dialects::traits::motion_group)) return c.info->function;
    for (const auto& [group, info] : b.modal)
        if (info && info->has(dialects::traits::motion_group)) return info->function;
    return {};
}
inline bool circular_motion(const BlockContext& b) {
    const dialects::FunctionId f = motion_function(b);
    return f == dialects::functions::circular_cw || f == dialects::functions::circular_ccw;
}

// True when a code of the block other than those `skip` accepts lists `letter` among its data
// words (parameter_words: G384 H D M T, G138 T, G28 K in iso-legacy-mill): the word is that code's
// value, not what its letter usually addresses.
template <class Skip>
bool code_parameter(const BlockContext& b, char letter, Skip skip) {
    const int bit = std::toupper(static_cast<unsigned char>(letter)) - 'A';
    if (bit < 0 || bit >= 26) return false;
    for (const auto* codes : {&b.g, &b.m})
        for (const ast::CodeRef& c : *codes)
            if (c.info && (c.info->parameter_mask >> bit & 1u) && !skip(*c.info)) return true;
    return false;
}
inline bool code_parameter(const BlockContext& b, char letter) {
    return code_parameter(b, letter, [](const dialects::CodeInfo&) { return false; });
}

// A block's words from the first to the last token (no trailing line break).
inline ast::Range block_text_range(const BlockContext& b) {
    const auto tokens = b.view.tokens();
    if (tokens.empty()) return b.view.range();
    return {tokens.front().begin, b.tree().end(tokens.back())};
}

// The constant value of an expression node (a number, or a bracket around one), if it is one.
inline std::optional<double> constant_of(const ast::SyntaxTree& tree, std::int32_t expr) {
    while (expr >= 0 && tree.exprs[static_cast<std::size_t>(expr)].kind == ast::ExprKind::bracket)
        expr = tree.exprs[static_cast<std::size_t>(expr)].a;
    if (expr < 0 || tree.exprs[static_cast<std::size_t>(expr)].kind != ast::ExprKind::number) return std::nullopt;
    return tree.number_value(tree.exprs[static_cast<std::size_t>(expr)]);
}

}  // namespace kerf::analyzer::rules
