// The output formats of `kerf check`: human (file:line:col, the source line with a caret
// underline, notes, hint, fix), JSON (docs/check-json.md, schema docs/check-json.schema.json) and
// SARIF 2.1.0; and the rule documentation (list, explain, docs/rules.md). Text out, no I/O.
#pragma once

#include <string>
#include <vector>

#include "analyzer/finding.hpp"
#include "analyzer/registry.hpp"
#include "ast/display.hpp"

namespace kerf::analyzer {

// One checked file, ready to print after its tree is gone.
struct FileReport {
    std::string name;                    // as given on the command line (or found in a folder)
    std::vector<Finding> findings;
    std::vector<Location> locations;     // 1-based, columns in UTF-8 bytes
    std::vector<Location> utf16;         // the same with UTF-16 columns (SARIF's default column kind)
    // Each finding's source line around it, escaped (ast/display.hpp excerpt), with its caret line.
    std::vector<ast::Excerpt> excerpts;
};

FileReport make_report(std::string name, const ast::SyntaxTree& tree, const ast::LineIndex& lines,
                       std::vector<Finding> findings);

struct Counts {
    std::size_t error = 0, warning = 0, info = 0, hint = 0;
};
Counts count(const std::vector<FileReport>& reports);

std::string format_human(const std::vector<FileReport>& reports, bool color);
std::string format_json(const std::vector<FileReport>& reports, std::size_t files_checked);
std::string format_sarif(const std::vector<FileReport>& reports, const Registry& registry);

std::string format_rule_list(const Registry& registry);       // id name severity category, one a line
std::string format_rules_markdown(const Registry& registry);  // docs/rules.md
std::string format_rule_docs(const Rule& rule);               // kerf explain K1001

// The id `kerf parse` and `kerf fmt` print for a parser diagnostic: the rule `kerf check` reports it
// as, which is the id a user suppresses (`(kerf: ignore K1003)`, `[check.rules] K1003 = "off"`),
// with the parser's code after it - "K1003 (S0103)"; the code alone when no rule reports it.
std::string diagnostic_id(std::string_view code, const Registry& registry);

}  // namespace kerf::analyzer
