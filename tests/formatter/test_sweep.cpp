// Every reference example and corpus file formatted in the default style and three others (issue 6,
// point 2): the output formats to itself (idempotent), runs the same trace (formatter::verify: same
// events, positions to 1e-9), keeps every comment's text, and keeps every block with a syntax error
// byte for byte. Renumbering styles may refuse a file only with a diagnostic (computed GOTO,
// syntax errors), and then the file is not formatted at all.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

#include "grammar/detect.hpp"
#include "tests/formatter/format_fixture.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf;
using formatter::Style;

namespace {

Style compact_style() {
    Style s;
    s.spacing = formatter::Spacing::compact;
    s.word_order = formatter::WordOrder::canonical;
    s.code_digits = formatter::CodeDigits::two;
    s.decimal_point = formatter::DecimalPoint::add;
    s.block_end = formatter::BlockEnd::semicolon;
    s.line_ending = formatter::LineEnding::lf;
    s.percent = formatter::Percent::ensure;
    s.program_number = formatter::ProgramNumber::four_digits;
    s.max_blank_lines = 0;
    s.comment_inside = formatter::CommentInside::tight;
    s.comment_gap = formatter::CommentGap::none;
    s.block_numbers = formatter::BlockNumbers::renumber;
    s.number_start = 1;   // the CAM files have up to 99 999 blocks (dialects.md §2: N has 5 digits)
    s.number_step = 1;
    return s;
}

Style spread_style() {
    Style s;
    s.letter_case = formatter::LetterCase::lower;
    s.word_order = formatter::WordOrder::canonical;
    s.code_digits = formatter::CodeDigits::minimal;
    s.block_end = formatter::BlockEnd::none;
    s.line_ending = formatter::LineEnding::crlf;
    s.comment_inside = formatter::CommentInside::padded;
    s.comment_gap = formatter::CommentGap::one;
    s.block_numbers = formatter::BlockNumbers::referenced;
    s.number_start = 1;
    s.number_step = 1;
    s.max_blank_lines = 2;
    return s;
}

Style keep_style() {
    Style s;
    s.letter_case = formatter::LetterCase::keep;
    s.spacing = formatter::Spacing::keep;
    s.max_blank_lines = -1;
    s.block_numbers = formatter::BlockNumbers::remove;
    return s;
}

struct Named {
    const char* name;
    Style style;
};

bool has_syntax_error(const std::string& text, const dialects::Dialect& d) {
    const ast::SyntaxTree tree = grammar::parse(text, d.lexical);
    return std::any_of(tree.blocks.begin(), tree.blocks.end(),
                       [](const ast::Block& b) { return b.has(ast::block_flags::has_error); });
}

void check_file(const fs::path& path, const Named& named, std::size_t& refused) {
    const std::string text = test::read_text(path);
    const dialects::Dialect& d = test::fmt_dialect(grammar::detect_dialect(text).dialect);
    INFO(path.string() << " as " << d.id << " in the " << named.name << " style");
    const formatter::FormatResult r = test::format_text(text, d, named.style);
    if (!r.text) {
        // Only renumbering refuses, always with a reason: a block with a syntax error (it may hide a
        // reference) or a reference it cannot follow.
        REQUIRE(named.style.block_numbers != formatter::BlockNumbers::keep);
        REQUIRE_FALSE(r.diagnostics.empty());
        CHECK(r.diagnostics.front().code == "F0001");
        if (!has_syntax_error(text, d)) {
            INFO(r.diagnostics.front().message);
            const std::string& m = r.diagnostics.front().message;
            CHECK((m.find("computed") != std::string::npos || m.find("is over N99999") != std::string::npos ||
                   m.find("second N word") != std::string::npos));
        }
        ++refused;
        return;
    }
    const std::string& out = *r.text;
    CHECK(test::formatted(out, d, named.style) == out);
    const bool trim = named.style.comment_inside != formatter::CommentInside::keep;
    CHECK(test::comment_texts(out, d, trim) == test::comment_texts(text, d, trim));
    const auto difference = test::trace_difference(text, out, d);
    INFO((difference ? difference->what + " at event " + std::to_string(difference->event) : std::string()));
    CHECK_FALSE(difference.has_value());
    const ast::SyntaxTree tree = grammar::parse(text, d.lexical);
    for (std::size_t b = 0; b < tree.block_count(); ++b) {
        if (!tree.blocks[b].has(ast::block_flags::has_error)) continue;
        const auto tokens = tree.block_tokens(b);
        const std::string_view content = tree.slice({tree.blocks[b].begin, tokens.back().begin + tokens.back().length});
        CHECK(out.find(content) != std::string::npos);
    }
}

}  // namespace

TEST_CASE("formatting every reference example and corpus file: idempotent, same trace, same comments") {
    const auto files = test::shared_files_or_warn("the formatter sweep was not run");
    if (files.empty()) return;
    REQUIRE(files.size() >= 140);
    const Named styles[] = {{"default", Style{}}, {"compact", compact_style()}, {"spread", spread_style()}, {"keep", keep_style()}};
    for (const Named& named : styles) {
        std::size_t refused = 0;
        for (const fs::path& path : files) check_file(path, named, refused);
        // Refusals are the files with syntax errors or computed GOTOs, not the rule.
        INFO(named.name << ": " << refused << " of " << files.size() << " refused");
        CHECK(refused * 3 < files.size());
    }
}
