// A long text parsed on two threads (grammar/parse.cpp: the second half from the middle of a
// program, appended with its indices moved) must give the tree the one-thread parse gives, field
// for field: blocks, tokens, expression nodes, statements, big numbers and diagnostics, whatever
// the first half ends in (inside a program, before any code, after the closing '%').
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cstring>
#include <string>

#include "ast/printer.hpp"
#include "grammar/parse.hpp"

using namespace kerf;

namespace {

// Past the size from which parse() uses a second thread (8 MiB).
constexpr std::size_t kLong = std::size_t{9} << 20;

const dialects::LexicalRules& rules_of(const char* id) { return dialects::builtin_registry().find(id)->lexical; }

// `body(i)` repeated until the text is long enough, between `head` and `tail`.
template <typename Body>
std::string long_text(const std::string& head, Body body, const std::string& tail, std::size_t size = kLong) {
    std::string text = head;
    for (int i = 0; text.size() < size; ++i) text += body(i);
    text += tail;
    return text;
}

// The index of the first element where the arrays differ, or -1 (one assertion per array: a
// mismatch in millions of tokens is reported by its place, not one line per token).
template <typename A, typename Same>
long first_difference(const A& a, const A& b, Same same) {
    if (a.size() != b.size()) return static_cast<long>(std::min(a.size(), b.size()));
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!same(a[i], b[i])) return static_cast<long>(i);
    return -1;
}

bool same_bytes(const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof(x)) == 0; }

bool same_expr(const ast::Expr& x, const ast::Expr& y) {
    return x.begin == y.begin && x.end == y.end && x.kind == y.kind && x.op == y.op && x.flags == y.flags &&
           x.scale == y.scale && x.a == y.a && x.b == y.b;
}

bool same_statement(const ast::Statement& x, const ast::Statement& y) {
    return x.range.begin == y.range.begin && x.range.end == y.range.end && x.kind == y.kind && x.target == y.target &&
           x.value == y.value && x.label == y.label && x.then_statement == y.then_statement &&
           x.text.begin == y.text.begin && x.text.end == y.text.end;
}

bool same_diagnostic(const ast::Diagnostic& x, const ast::Diagnostic& y) {
    return x.range.begin == y.range.begin && x.range.end == y.range.end && x.code == y.code && x.severity == y.severity && x.message == y.message && x.hint == y.hint;
}

void require_same_tree(const std::string& text, const char* dialect) {
    const ast::SyntaxTree one = grammar::parse(text, rules_of(dialect), 1);
    const ast::SyntaxTree two = grammar::parse(text, rules_of(dialect), 2);
    REQUIRE(ast::print(two) == text);
    CHECK(first_difference(one.blocks, two.blocks, [](const ast::Block& x, const ast::Block& y) {
              return x.begin == y.begin && x.first_token == y.first_token && x.kind == y.kind && x.flags == y.flags;
          }) == -1);
    CHECK(first_difference(one.tokens, two.tokens, [](const ast::Token& x, const ast::Token& y) { return same_bytes(x, y); }) == -1);
    CHECK(first_difference(one.exprs, two.exprs, same_expr) == -1);
    CHECK(first_difference(one.statements, two.statements, same_statement) == -1);
    CHECK(first_difference(one.big_numbers, two.big_numbers, [](double x, double y) { return same_bytes(x, y); }) == -1);
    CHECK(first_difference(one.diagnostics, two.diagnostics, same_diagnostic) == -1);
    CHECK(first_difference(one.long_tokens, two.long_tokens, [](const ast::LongToken& x, const ast::LongToken& y) {
              return x.begin == y.begin && x.length == y.length;
          }) == -1);
}

}  // namespace

TEST_CASE("two threads: CAM output inside one program, in three kinds of line ends") {
    const auto body = [](const char* brk) {
        return [brk](int i) { return fmt::format("N{} G01 X{}.{} Y-{}.5 F1200.{}", i, i % 300, i % 10, i % 77, brk); };
    };
    require_same_tree(long_text("%\nO1000 (CAM)\nG90 G54 G00 X0. Y0.\n", body("\n"), "M30\n%\n"), "fanuc-mill");
    require_same_tree(long_text("%\r\nO1000\r\n", body("\r\n"), "M30\r\n%\r\n"), "fanuc-mill");
    require_same_tree(long_text("%\rO1000\r", body("\r"), "M30\r%\r"), "fanuc-mill");
}

TEST_CASE("two threads: macro statements, expressions, big numbers, comments and errors move their indices") {
    const auto body = [](int i) {
        return fmt::format(
            "#{}=[#1+{}.5]*SIN[30.]/2 (STEP {})\n"
            "IF [#{} GT 10.] GOTO {}\n"
            "WHILE [#100 LT {}] DO1\n"
            "G01 X123456789012345678.{} Z-1.000000000000000000001 ; G00 X#[#101+1]\n"
            "END1\n"
            "N{} G01 X1.2.3 Y&{}\n",
            100 + i % 50, i, i, 100 + i % 50, i % 9000 + 1, i, i % 10, i % 9000 + 1, i);
    };
    require_same_tree(long_text("%\nO2000\n", body, "M30\n%\n"), "fanuc-lathe-a");
}

TEST_CASE("two threads: long tokens keep their lengths in both halves; mantissas past 28 bits are big numbers") {
    const auto body = [](int i) {
        return fmt::format("({}{})\nG01 X[{}+#1] Y13.4217728 Z-134217.727 ; #{}=[{}]\n", std::string(250 + i % 20, 'C'), i,
                           std::string(260 + i % 7, '1'), 100 + i % 50, std::string(300, '2'));
    };
    const std::string text = long_text("%\nO3000\n", body, "M30\n%\n");
    require_same_tree(text, "fanuc-mill");
    const ast::SyntaxTree tree = grammar::parse(text, rules_of("fanuc-mill"), 2);
    CHECK(tree.long_tokens.size() > 3 * 10000);
}

TEST_CASE("two threads: no code before the middle, so the second half is read again after the first") {
    // The first half is comments only: the assumed state (code seen) is wrong there.
    const std::string comments = long_text("%\n", [](int i) { return fmt::format("(NOTE {})\n", i); }, "", kLong / 2 + 4096);
    const std::string text = long_text(comments, [](int i) { return fmt::format("G01 X{}. Y1.\n", i % 500); }, "M30\n%\n");
    require_same_tree(text, "fanuc-mill");
    // And the second half begins with a '%' line: after code it would close the tape (the rest a
    // tail); after comments only it opens it again. The text is sized so the split falls before it.
    std::string percent = comments + "%\n";
    const std::size_t size = 2 * comments.size() + 2;
    while (percent.size() + 16 < size) percent += "G01 X1. Y1.\n";
    percent += "(" + std::string(size - percent.size() - 3, 'P') + ")\n";
    REQUIRE(percent.size() == size);
    require_same_tree(percent, "fanuc-mill");
}

TEST_CASE("two threads: the tape closes in the first half; the rest is its tail") {
    // The closing '%' well before the middle: everything after it is one tail block.
    const std::string program = long_text("%\nO3000\n", [](int i) { return fmt::format("G01 X{}. Y2.\n", i % 500); },
                                          "M30\n%\n", kLong / 3);
    require_same_tree(long_text(program, [](int i) { return fmt::format("G00 X{}. (after the tape)\n", i); }, ""), "fanuc-mill");
    // The closing '%' as the last line before the split: a text of twice the program and a little,
    // whose middle falls inside the line after the '%', so the last line end before it is the '%'s.
    const std::string closed = long_text("%\nO3001\n", [](int i) { return fmt::format("G01 X{}. Y2.\n", i % 500); },
                                         "M30\n%\n", kLong / 2);
    std::string exact = closed + "(" + std::string(98, 'T') + ")\n";
    while (exact.size() < 2 * closed.size() + 50) exact += "G00 X1.\n";
    REQUIRE(exact.size() / 2 > closed.size());
    REQUIRE(exact.size() / 2 < closed.size() + 101);
    require_same_tree(exact, "fanuc-mill");
}

TEST_CASE("two threads: a text without a program number or '%' frame") {
    require_same_tree(long_text("", [](int i) { return fmt::format("G1X{}Y{}\n", i % 100, i % 37); }, ""), "fanuc-mill");
}
