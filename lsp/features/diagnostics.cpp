// Diagnostics: every finding of `kerf check` (parser diagnostics as their K rules, static rules,
// the dry run's rules and alarms), after the same suppressions and .kerf.toml settings, as LSP
// diagnostics: code = the rule id, codeDescription = its section of docs/rules.md, source "kerf",
// related information, the Unnecessary tag on unreachable blocks. The static findings of a version
// are published first (`kerf.phase` "static"), the full list when the dry run has finished
// ("complete"); clients ignore the extra field.
#include <fmt/format.h>

#include <cctype>
#include <filesystem>

#include "lsp/features/common.hpp"

#ifndef KERF_DOCS_DIR
#define KERF_DOCS_DIR ""
#endif

namespace kerf::lsp {

namespace {

int severity(analyzer::Severity s) {
    switch (s) {
        case analyzer::Severity::error: return diagnostic_severity::error;
        case analyzer::Severity::warning: return diagnostic_severity::warning;
        case analyzer::Severity::info: return diagnostic_severity::information;
        case analyzer::Severity::hint: return diagnostic_severity::hint;
    }
    return diagnostic_severity::warning;
}

// docs/rules.md of the source tree, when it is there (an installed kerf has no documentation
// folder to link to): the anchor of "## K3001 label-not-found".
std::optional<std::string> rule_link(const analyzer::Finding& f) {
    static const std::string docs = [] {
        const std::filesystem::path p = std::filesystem::path(KERF_DOCS_DIR) / "rules.md";
        std::error_code ec;
        return std::string(KERF_DOCS_DIR).empty() || !std::filesystem::exists(p, ec) ? std::string() : path_to_uri(p);
    }();
    if (docs.empty()) return std::nullopt;
    std::string anchor = f.rule + "-" + f.name;
    for (char& c : anchor) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return docs + "#" + anchor;
}

}  // namespace

json::object diagnostic_json(const Document& doc, const analyzer::Finding& f) {
    std::string message = f.message;
    if (!f.hint.empty()) message += "\nhint: " + f.hint;
    json::object d{{"range", range_json(doc, f.range)},
                   {"severity", severity(f.severity)},
                   {"code", f.rule},
                   {"source", "kerf"},
                   {"message", message}};
    if (const auto link = rule_link(f)) d["codeDescription"] = json::object{{"href", *link}};
    if (!f.related.empty()) {
        json::array related;
        for (const analyzer::Related& r : f.related)
            related.push_back(json::object{{"location", location_json(doc, r.range)}, {"message", r.message}});
        d["relatedInformation"] = std::move(related);
    }
    if (f.rule == "K3007") d["tags"] = json::array{1};   // DiagnosticTag.Unnecessary: the client greys the dead blocks
    if (f.fix) d["data"] = json::object{{"fix", f.fix->description}};
    return d;
}

json::object publish_diagnostics(const Document& doc, const Analysis& analysis, bool final) {
    // A client shows a few thousand diagnostics usefully; a damaged 50 MB file may have millions.
    constexpr std::size_t kMaxDiagnostics = 2000;
    json::array list;
    for (const analyzer::Finding& f : analysis.findings) {
        if (list.size() == kMaxDiagnostics) {
            list.push_back(json::object{{"range", range_json(doc, {0, 0})},
                                        {"severity", diagnostic_severity::information},
                                        {"source", "kerf"},
                                        {"message", fmt::format("{} more findings are not shown here; `kerf check` lists them all",
                                                                analysis.findings.size() - kMaxDiagnostics)}});
            break;
        }
        list.push_back(diagnostic_json(doc, f));
    }
    return {{"uri", doc.uri()},
            {"version", doc.version()},
            {"diagnostics", std::move(list)},
            {"kerf", json::object{{"phase", final ? "complete" : "static"}}}};
}

}  // namespace kerf::lsp
