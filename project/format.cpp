#include "project/format.hpp"

#include <fmt/format.h>

#include "analyzer/output.hpp"
#include "ast/display.hpp"
#include "ast/typed.hpp"
#include "formatter/format.hpp"
#include "formatter/verify.hpp"
#include "project/start.hpp"
#include "grammar/parse.hpp"

namespace kerf::project {

namespace fs = std::filesystem;

namespace {

std::string diagnostic_line(const std::string& name, const ast::LineIndex& lines, const ast::Diagnostic& d) {
    const ast::Position at = lines.utf8(d.range.begin);
    std::string s = fmt::format("{}:{}:{}: {}: {} [{}]", name, at.line + 1, at.column + 1, ast::to_string(d.severity),
                                ast::printable(d.message), analyzer::diagnostic_id(d.code, analyzer::builtin_rules()));
    if (!d.hint.empty()) s += fmt::format("\n  hint: {}", ast::printable(d.hint));
    return s;
}

// Syntax errors make the file one kerf does not format: it is left as it is.
bool refuse_syntax_errors(const std::string& name, const ast::SyntaxTree& tree, const ast::LineIndex& lines, FormatOutcome& r) {
    std::size_t errors = 0;
    for (const ast::Diagnostic& d : tree.diagnostics) {
        if (d.severity != ast::Severity::error) continue;
        if (errors++ == 0) r.messages.push_back(diagnostic_line(name, lines, d));
    }
    if (errors == 0) return false;
    r.messages.push_back(fmt::format("{}: not formatted: {} syntax error{} (the first above); the file is left as it is",
                                     name, errors, errors == 1 ? "" : "s"));
    return true;
}

void verify_result(Workspace& workspace, const fs::path& file, std::string text, const Resolved& resolved, FormatOutcome& r) {
    formatter::VerifyOptions v;
    v.dialect = resolved.dialect;
    v.setup = *resolved.setup;
    v.loader = workspace.loader_for(file);
    v.run.time_limit = resolved.project->limits().time_limit;
    v.run.resident = resident_programs(resolved.project->config().programs);
    const std::string name = file.string();
    const formatter::VerifyResult result = formatter::verify(name, std::move(text), *r.formatted, v);
    // Equal runs that stop at the program's alarm (a call to a program that is nowhere: .kerf.toml
    // [programs] library and resident say where such programs are) prove nothing after it.
    if (const std::optional<formatter::AlarmStop>& a = result.stopped_at)
        r.messages.push_back(fmt::format("{}:{}: note: --verify compared the runs up to alarm {} ({}); the blocks after it "
                                         "are not verified",
                                         name, a->line, a->number, ast::printable(a->text)));
    if (!result.difference) return;
    const formatter::Difference& d = *result.difference;
    r.messages.push_back(fmt::format(
        "{}:{}: error: --verify: the formatted program runs differently at event {} (formatted line {}): {}; "
        "the file is left as it is (a kerf bug: please report it with the file)",
        name, d.input_line, d.event, d.output_line, d.what));
    r.formatted.reset();
}

// Parses, refuses a text with syntax errors, formats; fills r.formatted and r.changed.
void format_tree(const std::string& name, std::string text, const Resolved& resolved, const formatter::Style& style,
                 FormatOutcome& r) {
    ast::SyntaxTree tree = grammar::parse(std::move(text), resolved.dialect->lexical, grammar::parse_threads());
    const ast::TypedFile typed = ast::TypedFile::bind(tree, *resolved.dialect, false, grammar::parse_threads());
    const ast::LineIndex lines(tree.text);
    if (refuse_syntax_errors(name, tree, lines, r)) return;
    formatter::FormatResult f = formatter::format(typed, style, {resolved.setup->calculator_decimal});
    for (const ast::Diagnostic& d : f.diagnostics) r.messages.push_back(diagnostic_line(name, lines, d));
    if (!f.text) {
        r.messages.push_back(fmt::format("{}: not formatted; the file is left as it is", name));
        return;
    }
    r.changed = *f.text != tree.text;
    r.formatted = std::move(f.text);
}

}  // namespace

FormatOutcome format_text(Workspace& workspace, const fs::path& file, std::string text, const formatter::Style& style,
                          bool verify) {
    FormatOutcome r;
    const Resolved resolved = workspace.resolve(file, text);
    r.problems = resolved.problems;
    if (!resolved.ok() || has_errors(r.problems)) return r;
    std::string original = verify ? text : std::string();
    format_tree(file.string(), std::move(text), resolved, style, r);
    // The tree is gone by now: --verify parses both texts again, and a 100 MB file's tree is 360 MB.
    if (verify && r.changed) verify_result(workspace, file, std::move(original), resolved, r);
    return r;
}

}  // namespace kerf::project
