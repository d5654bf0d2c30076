// A finding: what a rule says about one place of one file. Positions are byte ranges into the
// checked file's text; the output turns them into 1-based line/column with ast::LineIndex.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ast/diagnostic.hpp"
#include "ast/source.hpp"

namespace kerf::analyzer {

using ast::Severity;

// Replace the bytes of `range` by `replacement` (an insertion has an empty range).
struct TextEdit {
    ast::Range range;
    std::string replacement;
};

// A fix the rule is sure of: applying it keeps the meaning the programmer evidently wanted.
struct Fix {
    std::string description;   // "replace the letter O by the digit 0"
    std::vector<TextEdit> edits;
};

// Another place of the same file that the finding is about (the first of two duplicated words, the
// blocks a label is on): the language server's relatedInformation.
struct Related {
    ast::Range range;
    std::string message;
};

struct Finding {
    ast::Range range;
    Severity severity = Severity::warning;
    std::string rule;           // stable id, "K1001"
    std::string name;           // short name, "address-without-value"
    std::string message;        // what is wrong, quoting the text
    std::string hint;           // how to fix it
    std::vector<std::string> notes;   // why it matters, where a value came from
    std::optional<Fix> fix;
    std::vector<Related> related;
};

// 1-based line and column (UTF-8 bytes) of a finding's range.
struct Location {
    std::uint32_t line = 1, column = 1, end_line = 1, end_column = 1;
};
Location locate(const ast::LineIndex& lines, ast::Range range);

}  // namespace kerf::analyzer
