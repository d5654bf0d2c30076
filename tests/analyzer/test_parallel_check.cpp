// kerf check runs the dry run beside the static rules on a second thread for long files
// (analyzer/analyze.cpp check_file): the findings must be the same as one after the other.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "analyzer/analyze.hpp"
#include "interpreter/default_setup.hpp"
#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf;

namespace {

std::vector<std::string> keys(const std::vector<analyzer::Finding>& findings) {
    std::vector<std::string> out;
    for (const analyzer::Finding& f : findings)
        out.push_back(f.rule + "@" + std::to_string(f.range.begin) + ":" + f.message);
    return out;
}

}  // namespace

TEST_CASE("the dry run beside the static rules finds what it finds after them") {
    // Static findings (letter O for zero, a missing subprogram), a dynamic one (the program's own
    // alarm #3000 at the end: K4006; the missing program's alarm 078 is K3003's, reported once) and
    // a long body between them.
    std::string text = "O0001\nT1 MO6\nG90 G01 X10. Y10.\n";
    for (int i = 0; i < 20000; ++i) text += "G01 X" + std::to_string(i % 97) + ". Y" + std::to_string(i % 89) + ". F500.\n";
    text += "#3000=1(END)\nM98 P4321\nM30\n";
    const dialects::Dialect& d = test::dialect("fanuc-mill");
    const interpreter::Setup setup = interpreter::default_setup(d);
    analyzer::CheckOptions sequential;
    sequential.parallel_from_bytes = std::size_t(-1);
    analyzer::CheckOptions parallel;
    parallel.parallel_from_bytes = 0;
    const auto one = analyzer::check_text("a.nc", text, d, setup, sequential);
    const auto two = analyzer::check_text("a.nc", text, d, setup, parallel);
    REQUIRE_FALSE(one.empty());
    CHECK(keys(one) == keys(two));
    bool has_static = false, has_dynamic = false;
    for (const auto& f : one) {
        has_static |= f.rule == "K1003";
        has_dynamic |= !f.notes.empty() && f.notes.front().starts_with("found by the dry run");
    }
    CHECK(has_static);
    CHECK(has_dynamic);
}

TEST_CASE("the program checks run on whichever thread is done first; their findings keep their place") {
    // Repeated N numbers (K3011, a program check over the label table) and a jump to a repeated
    // label (K3002, which asks the same table during the static walk). In the second text the dry
    // run ends at once (M30 first), so its thread takes the program checks while the static rules
    // still walk the blocks: both threads ask for the label table.
    const dialects::Dialect& d = test::dialect("fanuc-mill");
    const interpreter::Setup setup = interpreter::default_setup(d);
    std::string body;
    for (int i = 0; i < 20000; ++i) body += "N" + std::to_string(10 + 10 * (i % 500)) + " G01 X" + std::to_string(i % 97) + ". F500.\n";
    for (const std::string& text : {"O0001\nIF [#1 EQ 0] GOTO 20\n" + body + "M30\n",
                                    "O0001\nM30\nIF [#1 EQ 0] GOTO 20\n" + body + "M30\n"}) {
        analyzer::CheckOptions sequential;
        sequential.parallel_from_bytes = std::size_t(-1);
        analyzer::CheckOptions parallel;
        parallel.parallel_from_bytes = 0;
        const auto one = analyzer::check_text("a.nc", text, d, setup, sequential);
        for (int round = 0; round < 5; ++round) CHECK(keys(analyzer::check_text("a.nc", text, d, setup, parallel)) == keys(one));
        bool duplicate = false, ambiguous = false;
        for (const auto& f : one) {
            duplicate |= f.rule == "K3011";
            ambiguous |= f.rule == "K3002";
        }
        CHECK(duplicate);
        CHECK(ambiguous);
    }
}
