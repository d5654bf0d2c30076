// The formatter: a bound syntax tree and a style in, text out. It works from the lossless tree, so
// what it does not mean to change comes out as it went in: comment text byte for byte, macro
// statements as written (but for renumbered GOTO labels), a block with a syntax error exactly as it
// was (only its line break follows the style), the text after the closing '%' untouched.
// Formatting its own output again changes nothing (tests/formatter/test_sweep.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ast/diagnostic.hpp"
#include "ast/source.hpp"
#include "ast/typed.hpp"
#include "formatter/style.hpp"

namespace kerf::formatter {

// What the formatter must know about the machine the program is for.
struct FormatContext {
    // An axis value without a decimal point is millimetres (calculator-type input), so X10 and X10.
    // mean the same; otherwise X10 counts least input increments and no point may be added
    // (reference/dialects.md §2 "Numbers", machine/SCHEMA.md `calculator_decimal`).
    bool calculator_decimal = false;
};

struct FormatResult {
    std::optional<std::string> text;              // nullopt: not formatted, the diagnostics say why
    std::vector<ast::Diagnostic> diagnostics;
};

// The whole file in `style`. Refuses (no text) only when renumbering cannot follow a reference.
FormatResult format(const ast::TypedFile& file, const Style& style, const FormatContext& context);

// A replacement of `range` of the original text by `text` (the language server's TextEdit).
struct TextEdit {
    ast::Range range;
    std::string text;
};

// The blocks that touch lines [first_line, last_line] (0-based, `lines` built on the tree's text)
// formatted alone, for the language server's range formatting: block numbers and '%' framing are
// whole-file matters and stay as they are; blank lines are counted inside the range only.
TextEdit format_range(const ast::TypedFile& file, const ast::LineIndex& lines, std::uint32_t first_line,
                      std::uint32_t last_line, const Style& style, const FormatContext& context);

}  // namespace kerf::formatter
