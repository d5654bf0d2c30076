// Every reference example and corpus file formatted in the default style and three others (issue 6,
// point 2): the output formats to itself (idempotent), runs the same trace (formatter::verify: same
// events, positions to 1e-9), keeps every comment's text, and keeps every block with a syntax error
// byte for byte. Renumbering styles may refuse a file only with a diagnostic (computed GOTO,
// syntax errors), and then the file is not formatted at all.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <utility>
#include <string>

#include "grammar/detect.hpp"
#include "tests/formatter/format_fixture.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf;
using formatter::Style;

namespace {

// A style from option names and values (formatter::set_option, as .kerf.toml and the flags set them).
Style style_of(std::initializer_list<std::pair<const char*, const char*>> settings) {
    Style s;
    for (const auto& [key, value] : settings) {
        INFO(key << " = " << value);
        REQUIRE_FALSE(formatter::set_option(s, key, value).has_value());
    }
    return s;
}

// Everything changed that can be: the CAM files have up to 99 999 blocks, hence 1/1 numbering
// (dialects.md §2: N has 5 digits).
Style compact_style() {
    return style_of({{"spacing", "compact"}, {"word_order", "canonical"}, {"code_digits", "two"}, {"decimal_point", "add"},
                     {"block_end", "semicolon"}, {"line_ending", "lf"}, {"percent", "ensure"},
                     {"program_number", "four_digits"}, {"blank_lines", "0"}, {"comment_inside", "tight"},
                     {"comment_gap", "none"}, {"block_numbers", "renumber"}, {"number_start", "1"}, {"number_step", "1"}});
}

Style spread_style() {
    return style_of({{"letter_case", "lower"}, {"word_order", "canonical"}, {"code_digits", "minimal"},
                     {"block_end", "none"}, {"line_ending", "crlf"}, {"comment_inside", "padded"}, {"comment_gap", "one"},
                     {"block_numbers", "referenced"}, {"number_start", "1"}, {"number_step", "1"}, {"blank_lines", "2"}});
}

Style keep_style() {
    return style_of({{"letter_case", "keep"}, {"spacing", "keep"}, {"blank_lines", "-1"}, {"block_numbers", "remove"}});
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
        const std::string_view content = tree.slice({tree.blocks[b].begin, tree.end(tokens.back())});
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
