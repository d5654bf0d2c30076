#include "analyzer/output.hpp"

#include <fmt/format.h>

#include <boost/json.hpp>

namespace kerf::analyzer {

namespace json = boost::json;

namespace {

const char* severity_name(Severity s) { return ast::to_string(s); }

const char* sarif_level(Severity s) {
    switch (s) {
        case Severity::error: return "error";
        case Severity::warning: return "warning";
        default: return "note";
    }
}

const char* color_of(Severity s) {
    switch (s) {
        case Severity::error: return "\x1b[1;31m";
        case Severity::warning: return "\x1b[1;33m";
        case Severity::info: return "\x1b[1;34m";
        case Severity::hint: return "\x1b[1;36m";
    }
    return "";
}

void human_finding(std::string& out, const FileReport& r, std::size_t i, bool color) {
    const Finding& f = r.findings[i];
    const Location& l = r.locations[i];
    const char* on = color ? color_of(f.severity) : "";
    const char* bold = color ? "\x1b[1m" : "";
    const char* off = color ? "\x1b[0m" : "";
    // Everything that comes from the file is escaped: its bytes never reach the terminal raw.
    out += fmt::format("{}{}:{}:{}:{} {}{}{} {} {}: {}{}{}\n", bold, ast::printable(r.name), l.line, l.column, off, on,
                       severity_name(f.severity), off, f.rule, f.name, bold, ast::printable(f.message), off);
    const ast::Excerpt& e = r.excerpts[i];
    out += fmt::format("{:>6} | {}\n", l.line, e.text);
    out += fmt::format("{:>6} | {}{}{}\n", "", on, e.caret, off);
    for (const std::string& n : f.notes) out += fmt::format("       = note: {}\n", ast::printable(n));
    if (!f.hint.empty()) out += fmt::format("       = hint: {}\n", ast::printable(f.hint));
    if (f.fix) out += fmt::format("       = fix (kerf check --fix): {}\n", ast::printable(f.fix->description));
}

json::object location_json(const Location& l) {
    return {{"line", l.line}, {"column", l.column}, {"end_line", l.end_line}, {"end_column", l.end_column}};
}

// SARIF artifact URIs are URI references: relative paths with '/' and percent-encoding.
std::string uri_of(const std::string& path) {
    std::string out;
    for (const unsigned char c : path) {
        if (std::isalnum(c) || std::string_view("-._~/").find(static_cast<char>(c)) != std::string_view::npos) out += static_cast<char>(c);
        else out += fmt::format("%{:02X}", c);
    }
    return out;
}

json::object region(const Location& l) {
    return {{"startLine", l.line}, {"startColumn", l.column}, {"endLine", l.end_line}, {"endColumn", l.end_column}};
}

json::object sarif_rule(const Rule& r) {
    return {{"id", r.id},
            {"name", r.name},
            {"shortDescription", {{"text", r.docs.what}}},
            {"fullDescription", {{"text", r.docs.what + " " + r.docs.why}}},
            {"help", {{"text", fmt::format("{}\nBad: {}\nGood: {}\nReference: {}", r.docs.why, r.docs.bad, r.docs.good,
                                           r.docs.reference)}}},
            {"defaultConfiguration", {{"level", sarif_level(r.severity)}, {"enabled", r.enabled}}},
            {"properties", {{"category", to_string(r.category)}}}};
}

}  // namespace

FileReport make_report(std::string name, const ast::SyntaxTree& tree, const ast::LineIndex& lines,
                       std::vector<Finding> findings) {
    FileReport r;
    r.name = std::move(name);
    for (const Finding& f : findings) {
        r.locations.push_back(locate(lines, f.range));
        const ast::Position b = lines.utf16(f.range.begin), e = lines.utf16(f.range.end);
        r.utf16.push_back({b.line + 1, b.column + 1, e.line + 1, e.column + 1});
        const Location& l = r.locations.back();
        const std::uint32_t start = lines.line_start(l.line - 1);
        const std::uint32_t end = l.line < lines.line_count() ? lines.line_start(l.line)
                                                              : static_cast<std::uint32_t>(tree.text.size());
        std::string_view text = tree.slice({start, end});
        while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
        // One line is underlined: a range that goes on to later lines is underlined to the line's end.
        const bool one_line = l.end_line == l.line && l.end_column > l.column;
        r.excerpts.push_back(ast::excerpt(text, l.column - 1, l.end_column - 1, !one_line));
    }
    r.findings = std::move(findings);
    return r;
}

Counts count(const std::vector<FileReport>& reports) {
    Counts c;
    for (const FileReport& r : reports)
        for (const Finding& f : r.findings) {
            switch (f.severity) {
                case Severity::error: ++c.error; break;
                case Severity::warning: ++c.warning; break;
                case Severity::info: ++c.info; break;
                case Severity::hint: ++c.hint; break;
            }
        }
    return c;
}

std::string format_human(const std::vector<FileReport>& reports, bool color) {
    std::string out;
    for (const FileReport& r : reports)
        for (std::size_t i = 0; i < r.findings.size(); ++i) human_finding(out, r, i, color);
    return out;
}

std::string format_json(const std::vector<FileReport>& reports, std::size_t files_checked) {
    json::array findings;
    for (const FileReport& r : reports)
        for (std::size_t i = 0; i < r.findings.size(); ++i) {
            const Finding& f = r.findings[i];
            // JSON is UTF-8; text quoted from a file may not be (ast::valid_utf8).
            json::object o = location_json(r.locations[i]);
            o["file"] = ast::valid_utf8(r.name);
            o["severity"] = severity_name(f.severity);
            o["rule"] = f.rule;
            o["name"] = f.name;
            o["message"] = ast::valid_utf8(f.message);
            if (!f.hint.empty()) o["hint"] = ast::valid_utf8(f.hint);
            json::array notes;
            for (const std::string& n : f.notes) notes.push_back(json::string(ast::valid_utf8(n)));
            o["notes"] = std::move(notes);
            if (f.fix) {
                json::array edits;
                for (const TextEdit& e : f.fix->edits)
                    edits.push_back({{"offset", e.range.begin}, {"length", e.range.size()}, {"text", ast::valid_utf8(e.replacement)}});
                o["fix"] = {{"description", ast::valid_utf8(f.fix->description)}, {"edits", std::move(edits)}};
            }
            findings.push_back(std::move(o));
        }
    const Counts c = count(reports);
    const json::object root{{"version", 1},
                            {"tool", "kerf"},
                            {"files_checked", files_checked},
                            {"summary", {{"error", c.error}, {"warning", c.warning}, {"info", c.info}, {"hint", c.hint}}},
                            {"findings", std::move(findings)}};
    return json::serialize(root) + "\n";
}

std::string format_sarif(const std::vector<FileReport>& reports, const Registry& registry) {
    json::array rules;
    std::map<std::string, std::size_t> index;
    for (const Rule& r : registry.rules()) {
        index[r.id] = rules.size();
        rules.push_back(sarif_rule(r));
    }
    json::array results;
    for (const FileReport& r : reports)
        for (std::size_t i = 0; i < r.findings.size(); ++i) {
            const Finding& f = r.findings[i];
            const json::object artifact{{"uri", uri_of(r.name)}};
            json::object result{
                {"ruleId", f.rule},
                {"level", sarif_level(f.severity)},
                {"message", {{"text", ast::valid_utf8(f.hint.empty() ? f.message : f.message + " (" + f.hint + ")")}}},
                {"locations", json::array{{{"physicalLocation", {{"artifactLocation", artifact}, {"region", region(r.utf16[i])}}}}}}};
            if (const auto it = index.find(f.rule); it != index.end()) result["ruleIndex"] = it->second;
            results.push_back(std::move(result));
        }
    const json::object run{{"tool", {{"driver", {{"name", "kerf"},
                                                 {"version", "0.1.0"},
                                                 {"informationUri", "https://example.invalid/kerf"},
                                                 {"rules", std::move(rules)}}}}},
                           {"columnKind", "utf16CodeUnits"},
                           {"results", std::move(results)}};
    const json::object root{{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
                            {"version", "2.1.0"},
                            {"runs", json::array{run}}};
    return json::serialize(root) + "\n";
}

std::string format_rule_list(const Registry& registry) {
    std::string out;
    for (const Rule& r : registry.rules())
        out += fmt::format("{} {:<36} {:<8} {}{}\n", r.id, r.name, severity_name(r.severity), to_string(r.category),
                           r.enabled ? "" : " (off by default)");
    return out;
}

std::string format_rule_docs(const Rule& r) {
    std::string out = fmt::format("{} {} — {}\n", r.id, r.name, r.docs.what);
    out += fmt::format("  category: {}; default severity: {}{}{}\n", to_string(r.category), severity_name(r.severity),
                       r.enabled ? "" : "; off by default", r.has_fix ? "; kerf check --fix repairs it" : "");
    out += fmt::format("  why: {}\n", r.docs.why);
    auto block = [&](const char* label, const std::string& text) {
        if (text.empty()) return;
        out += fmt::format("  {}:\n", label);
        std::size_t at = 0;
        while (at <= text.size()) {
            const std::size_t nl = text.find('\n', at);
            out += "    " + text.substr(at, nl == std::string::npos ? std::string::npos : nl - at) + "\n";
            if (nl == std::string::npos) break;
            at = nl + 1;
        }
    };
    block("bad", r.docs.bad);
    block("good", r.docs.good);
    if (!r.diagnostics.empty()) {
        std::string codes;
        for (const std::string& c : r.diagnostics) codes += (codes.empty() ? "" : ", ") + c;
        out += fmt::format("  reports the parser diagnostics: {}\n", codes);
    }
    if (!r.alarms.empty()) out += "  reports the alarms of the dry run with these numbers\n";
    out += fmt::format("  reference: {}\n", r.docs.reference);
    return out;
}

std::string format_rules_markdown(const Registry& registry) {
    std::string out =
        "# kerf check rules\n\n"
        "Generated from the rule registry (`kerf check --list-rules --format markdown`); do not edit by hand.\n"
        "`kerf explain ID` prints the same text. Severities and on/off are set in `.kerf.toml` (`[check.rules]`).\n\n"
        "| id | name | category | default | fix |\n|---|---|---|---|---|\n";
    for (const Rule& r : registry.rules())
        out += fmt::format("| [{}](#{}) | {} | {} | {}{} | {} |\n", r.id, r.id == "" ? "" : fmt::format("{}-{}", 
                           [&] { std::string s = r.id; for (char& c : s) c = static_cast<char>(std::tolower(c)); return s; }(), r.name),
                           r.name, to_string(r.category), severity_name(r.severity), r.enabled ? "" : " (off)",
                           r.has_fix ? "yes" : "");
    for (const Rule& r : registry.rules()) {
        out += fmt::format("\n## {} {}\n\n{}\n\n**Why:** {}\n\n", r.id, r.name, r.docs.what, r.docs.why);
        if (!r.docs.bad.empty()) out += fmt::format("Bad:\n\n```\n{}\n```\n\n", r.docs.bad);
        if (!r.docs.good.empty()) out += fmt::format("Good:\n\n```\n{}\n```\n\n", r.docs.good);
        out += fmt::format("Category {}, default severity {}{}{}. Reference: {}.\n", to_string(r.category),
                           severity_name(r.severity), r.enabled ? "" : ", off by default",
                           r.has_fix ? ", fixed by `--fix`" : "", r.docs.reference);
    }
    return out;
}

std::string diagnostic_id(std::string_view code, const Registry& registry) {
    if (const Rule* rule = registry.for_diagnostic(code)) return fmt::format("{} ({})", rule->id, code);
    return std::string(code);
}

}  // namespace kerf::analyzer
