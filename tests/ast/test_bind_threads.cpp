// A long tree bound on two threads (ast/typed.cpp: two halves of the blocks side by side) must
// give what the one-thread bind gives: every token's role, the diagnostics in their order, the
// programs, the G01 reading at the end. A dialect with plain direct drawing (whose A/R roles
// depend on the blocks before) is bound on one thread and must agree too.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <string>

#include "ast/diagnostic_ids.hpp"
#include "ast/typed.hpp"
#include "grammar/parse.hpp"

using namespace kerf;

namespace {

const dialects::Dialect& dialect_of(const char* id) { return *dialects::builtin_registry().find(id); }

// Past the size from which bind() uses a second thread (200,000 blocks).
std::string long_program(const char* head, std::string (*block)(int), int blocks) {
    std::string text = head;
    for (int i = 0; i < blocks; ++i) text += block(i);
    return text + "M30\n%\n";
}

void require_same_binding(const std::string& text, const char* dialect) {
    ast::SyntaxTree one_tree = grammar::parse(text, dialect_of(dialect).lexical, 1);
    ast::SyntaxTree two_tree = grammar::parse(text, dialect_of(dialect).lexical, 1);
    REQUIRE(one_tree.block_count() >= 200000);
    const ast::TypedFile one = ast::TypedFile::bind(one_tree, dialect_of(dialect), false, 1);
    const ast::TypedFile two = ast::TypedFile::bind(two_tree, dialect_of(dialect), false, 2);
    long first_role_difference = -1;
    for (std::size_t i = 0; i < one_tree.tokens.size() && first_role_difference < 0; ++i)
        if (one_tree.tokens[i].role() != two_tree.tokens[i].role()) first_role_difference = static_cast<long>(i);
    CHECK(first_role_difference == -1);
    REQUIRE(one.diagnostics().size() == two.diagnostics().size());
    for (std::size_t i = 0; i < one.diagnostics().size(); ++i) {
        CHECK(one.diagnostics()[i].code == two.diagnostics()[i].code);
        CHECK(one.diagnostics()[i].range.begin == two.diagnostics()[i].range.begin);
        CHECK(one.diagnostics()[i].message == two.diagnostics()[i].message);
    }
    REQUIRE(one.programs().size() == two.programs().size());
    for (std::size_t i = 0; i < one.programs().size(); ++i) {
        CHECK(one.programs()[i].first_block == two.programs()[i].first_block);
        CHECK(one.programs()[i].end_block == two.programs()[i].end_block);
        CHECK(one.programs()[i].number == two.programs()[i].number);
    }
    CHECK(one.linear_at_end() == two.linear_at_end());
    // The second N words are reported in text order (as one walk of the blocks finds them).
    std::uint32_t last = 0;
    bool in_order = true;
    for (const ast::Diagnostic& d : two.diagnostics()) {
        if (d.code != ast::diagnostic_id::second_sequence_number) continue;
        in_order = in_order && d.range.begin >= last;
        last = d.range.begin;
    }
    CHECK(in_order);
}

}  // namespace

TEST_CASE("two-thread bind: roles, diagnostics and programs as on one thread") {
    // G65 blocks (every word an argument), M98 calls with and without a program (K-diagnostics of
    // check_call_forms), second N words (a diagnostic per block), G04 X (data), O words starting
    // programs on both halves, and a last motion code in the first half only (linear at the end).
    const auto block = [](int i) -> std::string {
        switch (i % 9) {
            case 0: return fmt::format("N{} G01 X{}. Y-{}. F500.\n", i, i % 300, i % 77);
            case 1: return fmt::format("N{} G65 P9010 A{}. M13 X1.\n", i, i % 5);
            case 2: return fmt::format("N{} M98 P{}\n", i, i % 7 == 0 ? 0 : 1000 + i % 5);
            case 3: return fmt::format("N{} N{} G00 Z5.\n", i, i + 1);
            case 4: return fmt::format("G04 X{}.\n", i % 3);
            case 5: return i % 45000 == 40001 ? fmt::format("M99\nO{}\n", 2000 + i / 45000) : std::string("G03 X1. Y1. R5.\n");
            case 6: return "A30. R2. X5.\n";
            case 7: return "M08\n";
            default: return fmt::format("T{} M06\n", i % 20);
        }
    };
    const std::string text = long_program("%\nO1000\n", +block, 240000);
    {   // the text has what the comparison is about: programs on both halves, diagnostics
        ast::SyntaxTree tree = grammar::parse(text, dialect_of("fanuc-mill").lexical, 1);
        const ast::TypedFile typed = ast::TypedFile::bind(tree, dialect_of("fanuc-mill"));
        CHECK(typed.programs().size() > 4);
        CHECK(typed.diagnostics().size() > 20000);
    }
    require_same_binding(text, "fanuc-mill");
    require_same_binding(text, "fanuc-lathe-a");
    require_same_binding(text, "spinner-lathe-a");
    // No motion code after the middle: the reading at the end is the first half's.
    const auto tail_without_motion = [](int i) -> std::string {
        return i < 1000 ? fmt::format("G01 X{}.\n", i) : fmt::format("M08 (block {})\n", i);
    };
    require_same_binding(long_program("%\nO1000\n", +tail_without_motion, 240000), "fanuc-mill");
}
