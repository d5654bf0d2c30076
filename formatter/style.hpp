// The formatter's style: every option of `kerf fmt` (docs/fmt.md), with one table of option names
// and values that both the `[format]` table of .kerf.toml and the command-line flags go through,
// so the two can never disagree about a name or a value.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::formatter {

enum class LetterCase { keep, upper, lower };          // address letters only; comments never change
enum class Spacing { keep, spaced, compact };          // between the words of a block
enum class WordOrder { keep, canonical };              // N, G, axes, I/J/K/R, others, ",", F, S, T, M
enum class CodeDigits { keep, two, minimal };          // G/M codes: G01 (two) or G1 (minimal)
enum class DecimalPoint { keep, add };                 // add: X10 → X10. where that means the same
enum class BlockEnd { keep, semicolon, none };         // ';' after every block, or none at line ends
enum class LineEnding { keep, lf, crlf };
enum class Percent { keep, ensure };                   // ensure: '%' lines before and after the program
enum class ProgramNumber { keep, four_digits };        // O1 → O0001
enum class CommentInside { keep, tight, padded };      // (TEXT) / ( TEXT ): the text itself is kept
enum class CommentGap { spacing, one, none };          // blank before a comment that follows a word
enum class BlockNumbers { keep, remove, renumber, referenced };

struct Style {
    LetterCase letter_case = LetterCase::upper;
    Spacing spacing = Spacing::spaced;
    WordOrder word_order = WordOrder::keep;
    CodeDigits code_digits = CodeDigits::keep;
    DecimalPoint decimal_point = DecimalPoint::keep;
    BlockEnd block_end = BlockEnd::keep;
    LineEnding line_ending = LineEnding::keep;
    Percent percent = Percent::keep;
    ProgramNumber program_number = ProgramNumber::keep;
    int max_blank_lines = 1;                             // -1: keep every blank line
    CommentInside comment_inside = CommentInside::keep;
    CommentGap comment_gap = CommentGap::spacing;
    BlockNumbers block_numbers = BlockNumbers::keep;
    int number_start = 10;
    int number_step = 10;
};

// One option: its key (TOML key; the flag is `--` + key with '_' as '-'), what it takes, what it does.
struct OptionInfo {
    std::string_view key;
    std::string_view values;        // "keep|upper|lower", or "integer"
    std::string_view description;
};
std::span<const OptionInfo> options();

// Sets `key` to `value` (the spelling of options()); an error message saying what is allowed
// when the key or the value is unknown.
std::optional<std::string> set_option(Style& style, std::string_view key, std::string_view value);

struct StyleError {
    std::string message;   // "<source>: format.<key>: what is wrong; allowed: ..."
    int line = 0;          // 1-based in the TOML text, 0 when unknown
    int column = 0;
};

struct StyleResult {
    Style style;
    std::vector<StyleError> errors;
};

// The `[format]` table of a .kerf.toml text over `base`; a text without the table gives `base`.
// Unknown keys and bad values are errors (a misspelt key must not silently format another way).
StyleResult style_from_toml(std::string_view toml_text, std::string_view source_name, const Style& base = {});

}  // namespace kerf::formatter
