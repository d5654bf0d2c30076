// Formatting a program text in a test: parse, bind, format, and the checks the sweep and the
// golden tests share (comment texts, idempotence, trace equality through formatter::verify).
#pragma once

#include <catch2/catch.hpp>

#include <optional>
#include <string>
#include <vector>

#include "ast/typed.hpp"
#include "dialects/dialect.hpp"
#include "formatter/format.hpp"
#include "formatter/verify.hpp"
#include "grammar/parse.hpp"
#include "interpreter/default_setup.hpp"

namespace kerf::test {

// The dialect `id`; REQUIREs that it exists.
inline const dialects::Dialect& fmt_dialect(const std::string& id) {
    const dialects::Dialect* d = dialects::builtin_registry().find(id);
    INFO(id);
    REQUIRE(d != nullptr);
    return *d;
}

// `text` formatted in `style`, with the decimal mode of the dialect's built-in machine unless given.
inline formatter::FormatResult format_text(const std::string& text, const dialects::Dialect& d,
                                           const formatter::Style& style, std::optional<bool> calculator = std::nullopt) {
    ast::SyntaxTree tree = grammar::parse(text, d.lexical);
    const ast::TypedFile typed = ast::TypedFile::bind(tree, d);
    const bool calc = calculator.value_or(interpreter::default_setup(d).calculator_decimal);
    return formatter::format(typed, style, {calc});
}

// The formatted text; REQUIREs that the formatter did not refuse.
inline std::string formatted(const std::string& text, const dialects::Dialect& d, const formatter::Style& style,
                             std::optional<bool> calculator = std::nullopt) {
    formatter::FormatResult r = format_text(text, d, style, calculator);
    INFO((r.diagnostics.empty() ? std::string() : r.diagnostics.front().message));
    REQUIRE(r.text.has_value());
    return *r.text;
}

// The comment texts of a program in order, with the blanks just inside the parentheses dropped
// when `trim` (comment_inside tight/padded changes only those).
inline std::vector<std::string> comment_texts(const std::string& text, const dialects::Dialect& d, bool trim) {
    const ast::SyntaxTree tree = grammar::parse(text, d.lexical);
    std::vector<std::string> out;
    for (const ast::Token& t : tree.tokens) {
        if (t.kind != ast::TokenKind::comment) continue;
        std::string s(tree.spelling(t));
        if (trim && s.size() >= 2 && s.front() == '(' && s.back() == ')' && !t.has(ast::token_flags::unclosed)) {
            std::string inner = s.substr(1, s.size() - 2);
            const auto first = inner.find_first_not_of(" \t\f\v\r");
            inner = first == std::string::npos ? std::string() : inner.substr(first, inner.find_last_not_of(" \t\f\v\r") - first + 1);
            s = "(" + inner + ")";
        }
        out.push_back(s);
    }
    return out;
}

// The traces of `before` and `after` under the dialect's built-in machine (step limit 200 000).
inline std::optional<formatter::Difference> trace_difference(const std::string& before, const std::string& after,
                                                             const dialects::Dialect& d) {
    formatter::VerifyOptions o;
    o.dialect = &d;
    o.setup = interpreter::default_setup(d);
    o.setup.step_limit = 200'000;
    return formatter::verify("test.nc", before, after, o).difference;
}

}  // namespace kerf::test
