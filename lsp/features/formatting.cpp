// Formatting and range formatting: exactly `kerf fmt` (formatter/format.hpp) in the style of the
// document's .kerf.toml [format] table and its machine's decimal mode; a document with syntax
// errors is not formatted (as `kerf fmt` refuses it), and a renumbering the planner refuses is not
// done: both answer with an error that says why.
#include <fmt/format.h>

#include "formatter/format.hpp"
#include "lsp/features/common.hpp"

namespace kerf::lsp {

namespace {

void refuse_syntax_errors(const Document& doc) {
    std::size_t errors = 0;
    const ast::Diagnostic* first = nullptr;
    for (const ast::Diagnostic& d : doc.tree().diagnostics)
        if (d.severity == ast::Severity::error && errors++ == 0) first = &d;
    if (!first) return;
    const ast::Position p = doc.lines().utf8(first->range.begin);
    throw RpcError(error_code::request_failed,
                   fmt::format("not formatted: {} syntax error{} (the first at line {}: {}), as kerf fmt", errors, errors == 1 ? "" : "s",
                               p.line + 1, first->message));
}

}  // namespace

json::value formatting(const Snapshot& s) {
    const Document& doc = s.document();
    if (!doc.refused().empty()) throw RpcError(error_code::request_failed, doc.refused());
    refuse_syntax_errors(doc);
    const formatter::FormatResult r = formatter::format(doc.typed(), doc.settings().style, doc.settings().format_context);
    if (!r.text) {
        std::string why;
        for (const ast::Diagnostic& d : r.diagnostics) why += (why.empty() ? "" : "; ") + d.message;
        throw RpcError(error_code::request_failed, "not formatted: " + why);
    }
    return edits_to(doc, *r.text);
}

json::value range_formatting(const Snapshot& s, std::pair<ast::Position, ast::Position> range) {
    const Document& doc = s.document();
    if (!doc.refused().empty()) throw RpcError(error_code::request_failed, doc.refused());
    refuse_syntax_errors(doc);
    std::uint32_t last_line = range.second.line;
    if (range.second.column == 0 && last_line > range.first.line) --last_line;   // a selection that ends at a line start
    const formatter::TextEdit e = formatter::format_range(doc.typed(), doc.lines(), range.first.line, last_line, doc.settings().style,
                                                          doc.settings().format_context);
    if (doc.tree().slice(e.range) == e.text) return json::array{};
    return json::array{text_edit(doc, e.range, e.text)};
}

}  // namespace kerf::lsp
