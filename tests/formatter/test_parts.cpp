// The formatter's smaller parts: style options from TOML and by name, the unified diff, the trace
// comparison (it must catch a changed program), and range formatting for the language server.
#include <catch2/catch.hpp>

#include <string>

#include "formatter/diff.hpp"
#include "tests/formatter/format_fixture.hpp"

using namespace kerf;

TEST_CASE("style from the [format] table of .kerf.toml") {
    const auto r = formatter::style_from_toml(
        "dialect = \"fanuc-mill\"\n[check]\nx = 1\n[format]\nletter_case = \"lower\"\nblank_lines = 0\n"
        "block_numbers = \"renumber\"\nnumber_step = 5\n",
        ".kerf.toml");
    CHECK(r.errors.empty());
    CHECK(r.style.letter_case == formatter::LetterCase::lower);
    CHECK(r.style.max_blank_lines == 0);
    CHECK(r.style.block_numbers == formatter::BlockNumbers::renumber);
    CHECK(r.style.number_step == 5);
    CHECK(r.style.spacing == formatter::Spacing::spaced);   // the default where the table is silent
}

TEST_CASE("a misspelt key or a bad value in [format] is an error with its line") {
    const auto r = formatter::style_from_toml("[format]\nletter_cse = \"lower\"\nspacing = \"wide\"\nnumber_step = 0\n", "p.toml");
    REQUIRE(r.errors.size() == 3);
    // An unknown key names the valid ones (the first and the last of formatter::options()).
    CHECK(r.errors[0].message.starts_with("p.toml: format.letter_cse: unknown key; the keys of [format] are letter_case, "));
    CHECK(r.errors[0].message.ends_with(", number_step"));
    CHECK(r.errors[0].line == 2);
    CHECK(r.errors[1].message == "p.toml: format.spacing: 'wide' is not one of keep|spaced|compact");
    CHECK(r.errors[2].message == "p.toml: format.number_step: '0' is not a whole number from 1 to 99999");
    const auto broken = formatter::style_from_toml("[format\n", "p.toml");
    CHECK(broken.errors.size() == 1);
}

TEST_CASE("every option can be set by name") {
    formatter::Style s;
    for (const formatter::OptionInfo& o : formatter::options()) {
        INFO(o.key);
        const std::string_view values = o.values;
        const std::string first = values == "integer" ? "1" : std::string(values.substr(0, values.find('|')));
        CHECK_FALSE(formatter::set_option(s, o.key, first).has_value());
    }
    CHECK(formatter::options().size() == 15);
    CHECK(formatter::set_option(s, "nope", "x") == std::optional<std::string>("unknown option 'nope'"));
}

TEST_CASE("unified diff") {
    CHECK(formatter::unified_diff("a\nb\n", "a\nb\n", "x", "y").empty());
    CHECK(formatter::unified_diff("1\n2\n3\n4\n5\n6\n7\n8\n9\n", "1\n2\n3\n4\nV\n6\n7\n8\n9\n", "a.nc", "b.nc") ==
          "--- a.nc\n+++ b.nc\n@@ -2,7 +2,7 @@\n 2\n 3\n 4\n-5\n+V\n 6\n 7\n 8\n");
    CHECK(formatter::unified_diff("a\nb", "a\nc\n", "x", "y") == "--- x\n+++ y\n@@ -1,2 +1,2 @@\n a\n-b\n\\ No newline at end of file\n+c\n");
    CHECK(formatter::unified_diff("", "new\n", "x", "y") == "--- x\n+++ y\n@@ -0,0 +1,1 @@\n+new\n");
    // Two changes far apart are two hunks.
    std::string a, b;
    for (int i = 0; i < 20; ++i) {
        a += std::to_string(i) + "\n";
        b += (i == 2 || i == 17 ? "x" : std::to_string(i)) + "\n";
    }
    const std::string d = formatter::unified_diff(a, b, "a", "b");
    CHECK(d.find("@@ -1,6 +1,6 @@") != std::string::npos);
    CHECK(d.find("@@ -15,6 +15,6 @@") != std::string::npos);
}

TEST_CASE("the trace comparison catches a program that moves differently") {
    const dialects::Dialect& d = test::fmt_dialect("fanuc-mill");
    const auto moved = test::trace_difference("G0 X10. Y0\nG1 X20. F100\nM30\n", "G0 X10. Y0\nG1 X20.000000001 F100\nM30\n", d);
    CHECK_FALSE(moved.has_value());   // within 1e-9
    const auto other = test::trace_difference("G0 X10. Y0\nG1 X20. F100\nM30\n", "G0 X10. Y0\nG1 X20.1 F100\nM30\n", d);
    REQUIRE(other.has_value());
    CHECK(other->what.find("X: 20 vs 20.1") != std::string::npos);
    CHECK(other->input_line == 2);
    const auto fewer = test::trace_difference("G0 X10.\nG0 X20.\nM30\n", "G0 X10.\nM30\n", d);
    REQUIRE(fewer.has_value());
    // On fanuc-mill X10 is 10 increments (0.010 mm): a point there would change the program.
    CHECK(test::trace_difference("G0 X10\nM30\n", "G0 X10.\nM30\n", d).has_value());
    CHECK(test::formatted("G0 X10\n", d, [] { formatter::Style s; s.decimal_point = formatter::DecimalPoint::add; return s; }()) ==
          "G0 X10\n");
}

// A program that runs nothing and no program at all run the same: `N4 (NOTE)` is a program of one
// code block; with its N removed it is a comment, and the file has no program (fuzz_formatter).
// A program that moves is not "the same" as no program.
TEST_CASE("the trace comparison: no program equals a program that does nothing, not one that moves") {
    const dialects::Dialect& d = test::fmt_dialect("fanuc-mill");
    CHECK_FALSE(test::trace_difference("(HEAD)\nN4 (NOTE)\n", "(HEAD)\n(NOTE)\n", d).has_value());
    CHECK_FALSE(test::trace_difference("(HEAD)\n(NOTE)\n", "(HEAD)\nN4 (NOTE)\n", d).has_value());
    const auto moves = test::trace_difference("(HEAD)\nG0 X10.\n", "(HEAD)\n(G0 X10.)\n", d);
    REQUIRE(moves.has_value());
    CHECK(moves->what == "the output has no program");
    CHECK(moves->input_line == 2);
}

TEST_CASE("range formatting for the language server touches only the blocks of those lines") {
    const dialects::Dialect& d = test::fmt_dialect("fanuc-mill");
    ast::SyntaxTree tree = grammar::parse("o1\ng0  x1\ng1 x2 (a)\n\n\ng0 x3\n", d.lexical);
    const ast::TypedFile typed = ast::TypedFile::bind(tree, d);
    const ast::LineIndex lines(tree.text);
    formatter::Style style;
    style.block_numbers = formatter::BlockNumbers::renumber;   // a whole-file matter: not in a range
    const formatter::TextEdit edit = formatter::format_range(typed, lines, 1, 2, style, {});
    CHECK(tree.slice(edit.range) == "g0  x1\ng1 x2 (a)\n");
    CHECK(edit.text == "G0 X1\nG1 X2 (a)\n");
    const formatter::TextEdit blanks = formatter::format_range(typed, lines, 3, 4, style, {});
    CHECK(tree.slice(blanks.range) == "\n\n");
    CHECK(blanks.text == "\n");
}
