// Code actions:
//   - quick fixes: the fix of each finding in the range that has one (the same fixes as
//     `kerf check --fix`), tied to its diagnostic;
//   - "fix all": every fix of the document at once (source.fixAll.kerf);
//   - "renumber blocks": the formatter's renumbering (number_start/number_step of .kerf.toml
//     [format]) with every reference moved, nothing else of the text changed; offered disabled,
//     with the planner's reason, when it refuses (a computed GOTO ...);
//   - conversions ("convert this program to FANUC lathe, G-code system B"): features/convert.cpp.
#include <fmt/format.h>

#include <algorithm>

#include "analyzer/fix.hpp"
#include "formatter/format.hpp"
#include "lsp/features/common.hpp"

namespace kerf::lsp {

namespace {

bool overlaps(ast::Range a, ast::Range b) { return a.begin <= b.end && b.begin <= a.end; }

json::object edit_of(const Document& doc, const std::vector<analyzer::TextEdit>& edits) {
    json::array list;
    for (const analyzer::TextEdit& e : edits) list.push_back(text_edit(doc, e.range, e.replacement));
    return json::object{{"changes", json::object{{doc.uri(), std::move(list)}}}};
}

void quick_fixes(const Snapshot& s, ast::Range range, json::array& out) {
    if (!s.analysis) return;
    const Document& doc = s.document();
    std::vector<analyzer::TextEdit> all;
    std::size_t fixes = 0;
    for (const analyzer::Finding& f : s.analysis->findings) {
        if (!f.fix) continue;
        ++fixes;
        all.insert(all.end(), f.fix->edits.begin(), f.fix->edits.end());
        if (!overlaps(f.range, range)) continue;
        out.push_back(json::object{{"title", fmt::format("{} ({})", f.fix->description, f.rule)},
                                   {"kind", "quickfix"},
                                   {"diagnostics", json::array{diagnostic_json(doc, f)}},
                                   {"isPreferred", true},
                                   {"edit", edit_of(doc, f.fix->edits)}});
    }
    if (fixes > 1) {
        // Edits of one fix-all must not overlap: keep the first of any two that do (as --fix).
        std::sort(all.begin(), all.end(), [](const analyzer::TextEdit& a, const analyzer::TextEdit& b) { return a.range.begin < b.range.begin; });
        std::vector<analyzer::TextEdit> kept;
        for (const analyzer::TextEdit& e : all)
            if (kept.empty() || kept.back().range.end <= e.range.begin) kept.push_back(e);
        out.push_back(json::object{{"title", fmt::format("Apply all {} kerf fixes", fixes)}, {"kind", "source.fixAll.kerf"}, {"edit", edit_of(doc, kept)}});
    }
}

// Renumbering alone: every other option of the style keeps the text as it is.
formatter::Style renumber_style(const formatter::Style& configured) {
    formatter::Style s;
    s.letter_case = formatter::LetterCase::keep;
    s.spacing = formatter::Spacing::keep;
    s.max_blank_lines = -1;
    s.block_numbers = formatter::BlockNumbers::renumber;
    s.number_start = configured.number_start;
    s.number_step = configured.number_step;
    return s;
}

void renumber_small(const Snapshot& s, json::array& out);

std::string renumber_title(const Document& doc) {
    return fmt::format("Renumber blocks (N{}, step {})", doc.settings().style.number_start, doc.settings().style.number_step);
}

// Clients ask for code actions at every cursor move: a long document gets the renumbering's
// edit only when the action is chosen (codeAction/resolve).
constexpr std::size_t kResolveFromBytes = std::size_t{1} << 20;

void renumber(const Snapshot& s, json::array& out) {
    const Document& doc = s.document();
    const std::string title = renumber_title(doc);
    if (doc.text().size() >= kResolveFromBytes) {
        out.push_back(json::object{{"title", title}, {"kind", "refactor.rewrite"},
                                   {"data", json::object{{"kerf", "renumber"}, {"uri", doc.uri()}, {"version", doc.version()}}}});
        return;
    }
    renumber_small(s, out);
}

void renumber_small(const Snapshot& s, json::array& out) {
    const Document& doc = s.document();
    const std::string title = renumber_title(doc);
    for (const ast::Diagnostic& d : doc.tree().diagnostics)
        if (d.severity == ast::Severity::error) {
            out.push_back(json::object{{"title", title}, {"kind", "refactor.rewrite"},
                                       {"disabled", json::object{{"reason", "the document has syntax errors (as kerf fmt, nothing is renumbered)"}}}});
            return;
        }
    const formatter::FormatResult r = formatter::format(doc.typed(), renumber_style(doc.settings().style), doc.settings().format_context);
    if (!r.text) {
        std::string why;
        for (const ast::Diagnostic& d : r.diagnostics) why += (why.empty() ? "" : "; ") + d.message;
        out.push_back(json::object{{"title", title}, {"kind", "refactor.rewrite"}, {"disabled", json::object{{"reason", why}}}});
        return;
    }
    json::array edits = edits_to(doc, *r.text);
    if (edits.empty()) return;
    out.push_back(json::object{{"title", title}, {"kind", "refactor.rewrite"}, {"edit", json::object{{"changes", json::object{{doc.uri(), std::move(edits)}}}}}});
}

bool wanted(const json::value& context, std::string_view kind) {
    const json::value* only = find_path(context, {"only"});
    if (!only || !only->is_array()) return true;
    for (const json::value& k : only->as_array())
        if (k.is_string() && (kind == k.as_string() || kind.starts_with(std::string(k.as_string()) + "."))) return true;
    return false;
}

}  // namespace

json::value resolve_code_action(const Snapshot& s, json::object action) {
    const Document& doc = s.document();
    const json::value* version = find_path(action, {"data", "version"});
    if (!version || !version->is_int64() || version->as_int64() != doc.version())
        throw RpcError(error_code::content_modified, "the document changed since the action was offered");
    const json::value* what = find_path(action, {"data", "kerf"});
    if (what && what->is_string() && what->as_string() == "convert") return resolve_conversion(s, std::move(action));
    json::array list;
    renumber_small(s, list);
    if (list.empty()) throw RpcError(error_code::request_failed, "nothing to renumber");
    const json::object& done = list.front().as_object();
    if (const json::value* disabled = done.if_contains("disabled"))
        throw RpcError(error_code::request_failed, std::string(disabled->as_object().at("reason").as_string()));
    action["edit"] = done.at("edit");
    return action;
}

json::value code_actions(const Snapshot& s, std::pair<ast::Position, ast::Position> range, const json::value& context) {
    json::array out;
    const Document& doc = s.document();
    if (!doc.refused().empty()) return out;
    const ast::Range bytes{doc.offset(range.first), doc.offset(range.second)};
    json::array fixes;
    if (wanted(context, "quickfix") || wanted(context, "source.fixAll.kerf")) quick_fixes(s, bytes, fixes);
    for (json::value& f : fixes)
        if (wanted(context, std::string(f.as_object().at("kind").as_string()))) out.push_back(std::move(f));
    if (wanted(context, "refactor.rewrite")) renumber(s, out);
    if (wanted(context, "source.convert.kerf")) conversion_actions(s, out);
    return out;
}

}  // namespace kerf::lsp
