// Renumbering (issue 6, point 3): the targets of G70 P/Q, GOTO, M98 Q and M99 P move with their
// blocks; a reference kerf cannot follow makes it refuse, naming the block.
#include <catch2/catch.hpp>

#include <string>

#include "formatter/renumber.hpp"
#include "tests/formatter/format_fixture.hpp"

using namespace kerf;
using formatter::BlockNumbers;
using formatter::Style;

namespace {

Style renumbering(int start, int step, BlockNumbers mode = BlockNumbers::renumber) {
    Style s;
    s.block_numbers = mode;
    s.number_start = start;
    s.number_step = step;
    return s;
}

// The one refusal of formatting `text`; REQUIREs that there is one.
ast::Diagnostic refusal(const std::string& text, const char* dialect, const Style& style) {
    const formatter::FormatResult r = test::format_text(text, test::fmt_dialect(dialect), style);
    REQUIRE_FALSE(r.text.has_value());
    REQUIRE(r.diagnostics.size() == 1);
    CHECK(r.diagnostics.front().code == "F0001");
    CHECK(r.diagnostics.front().severity == ast::Severity::error);
    CHECK_FALSE(r.diagnostics.front().hint.empty());
    return r.diagnostics.front();
}

}  // namespace

TEST_CASE("renumbering moves the targets of G70 P/Q, GOTO, M98 Q and M99 P") {
    const std::string text =
        "O0001\nN1 G0 X50 Z2\nN2 G71 U1 R.5\nN3 G71 P7 Q8 U.4 W.1 F.2\nN7 G0 X20\nN8 G1 Z-10\nN9 G70 P7 Q8\n"
        "#1=0\nN4 #1=#1+1\nIF [#1 LT 3] GOTO 4\nM98 P1000 Q6\nN5 M30\nO1000\nN6 G0 U1\nM99 P5\n";
    const dialects::Dialect& d = test::fmt_dialect("fanuc-lathe-a");
    const std::string out = test::formatted(text, d, renumbering(100, 5));
    // O0001: N1→100 N2→105 N3→110 N7→115 N8→120 N9→125 #1=0→130 N4→135 IF→140 M98→145 N5→150.
    CHECK(out.find("N110 G71 P115 Q120 U.4 W.1 F.2\n") != std::string::npos);
    CHECK(out.find("N125 G70 P115 Q120\n") != std::string::npos);
    CHECK(out.find("N140 IF [#1 LT 3] GOTO 135\n") != std::string::npos);
    // O1000 starts again: N6→100, M99→105; M98 Q6 names O1000's N6, M99 P5 the caller's N5.
    CHECK(out.find("N145 M98 P1000 Q100\n") != std::string::npos);
    CHECK(out.find("N100 G0 U1\nN105 M99 P150\n") != std::string::npos);
    CHECK_FALSE(test::trace_difference(text, out, d).has_value());
}

TEST_CASE("M98 Q without P names a label of the program itself") {
    const std::string text = "O0001\nN30 M98 Q70\nM30\nN70 G0 X1\nM99\n";
    const std::string out = test::formatted(text, test::fmt_dialect("fanuc-lathe-a"), renumbering(1, 1));
    // N30→1, M30→2, N70→3, M99→4.
    CHECK(out == "O0001\nN1 M98 Q3\nN2 M30\nN3 G0 X1\nN4 M99\n");
}

TEST_CASE("a computed GOTO makes renumbering refuse, naming the block") {
    const std::string text = "O0001\nN10 #5=20\nN20 GOTO #5\nN30 G0 X1\nM30\n";
    const ast::Diagnostic d = refusal(text, "fanuc-mill", renumbering(10, 10));
    CHECK(d.message == "cannot renumber: GOTO '#5' is computed, so the block it jumps to is known only at run time "
                       "in block 'N20 GOTO #5'");
    CHECK(text.substr(d.range.begin, d.range.size()) == "#5");
    // The other modes that move or drop numbers refuse too; keep leaves the program alone.
    refusal(text, "fanuc-mill", renumbering(10, 10, BlockNumbers::remove));
    refusal("O1\nN1 IF [#1 GT 0] GOTO [#2+10]\nM30\n", "fanuc-mill", renumbering(10, 10, BlockNumbers::referenced));
    CHECK(test::format_text(text, test::fmt_dialect("fanuc-mill"), Style{}).text.has_value());
}

TEST_CASE("renumbering refuses what it cannot follow") {
    SECTION("a reference to no block, when renumbering would create that number") {
        const ast::Diagnostic d = refusal("O1\nG0 X1\nGOTO 20\nM30\n", "fanuc-mill", renumbering(10, 10));
        CHECK(d.message.find("refers to N20, which no block has, and renumbering would create N20") != std::string::npos);
    }
    SECTION("M99 P of a subprogram whose callers number that label differently") {
        const ast::Diagnostic d = refusal("O0001\nN50 M98 P2000\nM30\nO0002\nG0 X1\nN50 M98 P2000\nM30\nO2000\nM99 P50\n",
                                          "fanuc-mill", renumbering(10, 10));
        CHECK(d.message.find("N50 is in several programs") != std::string::npos);
    }
    SECTION("a cycle's P written as an expression") {
        const ast::Diagnostic d = refusal("O1\nN10 G70 P#1 Q20\nN20 G0 X1\nM30\n", "fanuc-lathe-a", renumbering(10, 10));
        CHECK(d.message.find("G70 P 'P#1' is not a plain sequence number") != std::string::npos);
    }
    SECTION("a block with a syntax error") {
        const ast::Diagnostic d = refusal("O1\nN10 G0 X1.2.3\nM30\n", "fanuc-mill", renumbering(10, 10));
        CHECK(d.message.find("syntax error") != std::string::npos);
    }
    SECTION("a block with an O word after its words, which a reprint could make a program start") {
        // `D 2` is no plain word, so `O 3` is a word of the block; renumbered, `D2O3` would start O0003
        // (fuzz/regressions/formatter/inner-o-word-becomes-program-start.nc).
        const ast::Diagnostic d = refusal("O1\nN10 X9 D 2O 3\nM30\n", "fanuc-mill", renumbering(10, 10));
        CHECK(d.message.find("an O word after its first word") != std::string::npos);
        CHECK(d.hint == "put the O word on a line of its own, or remove it");
        // A '%' before the O (`%O0003(...)`) is not such a block: no reading starts a program there.
        const formatter::FormatResult framed =
            test::format_text("%O0003(FIXTURE)\nN5 G0 X1\nM30\n%\n", test::fmt_dialect("fanuc-mill"), renumbering(10, 10));
        REQUIRE(framed.text.has_value());
        CHECK(*framed.text == "% O0003 (FIXTURE)\nN10 G0 X1\nN20 M30\n%\n");
    }
    SECTION("a block with a second N word") {
        const ast::Diagnostic d = refusal("O1\nN10 G0 N30 X1\nM30\n", "fanuc-mill", renumbering(10, 10));
        CHECK(d.message.find("second N word") != std::string::npos);
    }
    SECTION("a reference word given twice in its block") {
        // G70 P100 Q1 P1: the dry run takes the last P, the references the first; renumbering one of
        // them changed the cycle's profile (fuzz/regressions/formatter/verify-alarm-65-vs-60.nc).
        const ast::Diagnostic d = refusal("O1\nN1 G0 X1\nN100 G1 X2\nN101 G0 X3\nG70 P100 Q101 P1\nM30\n", "fanuc-lathe-a",
                                          renumbering(10, 10));
        CHECK(d.message == "cannot renumber: G70 P is given twice ('P100' and 'P1') in block 'G70 P100 Q101 P1'");
        CHECK(d.hint == "keep one P word in the block (K1021)");
    }
    SECTION("numbers past N99999") {
        const ast::Diagnostic d = refusal("O1\nG0 X1\nG0 X2\nM30\n", "fanuc-mill", renumbering(99990, 10));
        CHECK(d.message.find("the new number N100000 is over N99999") != std::string::npos);
    }
}

TEST_CASE("a reference to no block keeps its value when no new number takes it") {
    // reference/examples 001_12-1: the profile N1000-N1100 is missing; the alarm stays the same.
    const std::string text = "O1\nN10 G0 X28 Z1\nN20 G72 P1000 Q1100 U-1 W.1 F.2\nN30 M30\n";
    const dialects::Dialect& d = test::fmt_dialect("fanuc-lathe-a");
    const std::string out = test::formatted(text, d, renumbering(1, 1));
    CHECK(out == "O1\nN1 G0 X28 Z1\nN2 G72 P1000 Q1100 U-1 W.1 F.2\nN3 M30\n");
    CHECK_FALSE(test::trace_difference(text, out, d).has_value());
}

TEST_CASE("keep plans nothing") {
    ast::SyntaxTree tree = grammar::parse("O1\nN10 GOTO 10\n", test::fmt_dialect("fanuc-mill").lexical);
    const ast::TypedFile typed = ast::TypedFile::bind(tree, test::fmt_dialect("fanuc-mill"));
    const auto plan = formatter::plan_renumbering(typed, Style{});
    REQUIRE(std::holds_alternative<formatter::Renumbering>(plan));
    CHECK(std::get<formatter::Renumbering>(plan).empty());
}
