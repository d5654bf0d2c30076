#include "project/convert.hpp"

#include <fmt/format.h>

#include <memory>

#include "ast/display.hpp"
#include "ast/typed.hpp"
#include "grammar/parse.hpp"
#include "interpreter/trace_compare.hpp"

namespace kerf::project {

namespace fs = std::filesystem;

namespace {

// A parsed and bound text: the tree must outlive the typed file that points into it.
struct Bound {
    ast::SyntaxTree tree;
    std::optional<ast::TypedFile> typed;
};

std::unique_ptr<Bound> bind(std::string text, const dialects::Dialect& dialect) {
    auto b = std::make_unique<Bound>();
    b->tree = grammar::parse(std::move(text), dialect.lexical, grammar::parse_threads());
    b->typed.emplace(ast::TypedFile::bind(b->tree, dialect, false, grammar::parse_threads()));
    return b;
}

// The subprograms a converted program calls: found as the source's are, converted on the way, so
// the output runs against the converted library (what `kerf convert` of the folder writes).
interpreter::ProgramSet::Loader converted_loader(interpreter::ProgramSet::Loader source, const dialects::Dialect& from,
                                                 const dialects::Dialect& to, converter::Options options) {
    if (!source) return {};
    return [source = std::move(source), &from, &to, options](std::int64_t number) -> std::optional<std::pair<std::string, std::string>> {
        auto found = source(number);
        if (!found) return found;
        const auto b = bind(found->second, from);
        converter::Options o = options;
        o.name = found->first;
        o.loader = {};
        const converter::Conversion c = converter::convert(*b->typed, to, o);
        found->second = converter::apply(b->tree.text, c.edits);
        return found;
    };
}

// The block of a 1-based line, shortened and printable, for a --verify failure.
std::string line_text(std::string_view text, int line) {
    if (line <= 0) return {};
    std::size_t at = 0;
    for (int l = 1; l < line && at != std::string_view::npos; ++l) {
        at = text.find('\n', at);
        if (at != std::string_view::npos) ++at;
    }
    if (at == std::string_view::npos || at >= text.size()) return {};
    std::size_t end = text.find_first_of("\r\n", at);
    if (end == std::string_view::npos) end = text.size();
    return ast::printable(ast::shorten(text.substr(at, end - at), 100));
}

void verify(Workspace& workspace, const fs::path& file, const std::string& input, const Resolved& resolved,
            const dialects::Dialect& to, const interpreter::Setup& target_setup, const converter::Options& options,
            ConvertOutcome& r) {
    interpreter::ProgramSet::Loader loader = workspace.loader_for(file);
    interpreter::TraceSide before{file.string(), input, resolved.dialect, *resolved.setup, loader};
    interpreter::TraceSide after{file.string(), *r.converted, &to, target_setup,
                                 converted_loader(loader, *resolved.dialect, to, options)};
    interpreter::CompareOptions compare;
    compare.profile = interpreter::CompareProfile::motion;
    compare.tolerance = 0.001;   // issue 16: within 0.001 mm (program units)
    interpreter::RunOptions run;
    run.time_limit = resolved.project->limits().time_limit;
    const interpreter::TraceComparison c = interpreter::compare_runs(std::move(before), std::move(after), compare, run);
    r.verified_events = c.events;
    if (const std::optional<interpreter::Event>& a = c.stopped_at)
        r.verify_stopped = VerifyStop{static_cast<int>(a->source.line), a->control_alarm ? a->control_alarm : a->code, a->text};
    if (!c.difference) {
        r.verified = true;
        return;
    }
    const interpreter::TraceDifference& d = *c.difference;
    // A block of the file itself is shown from its text; one of a subprogram's file is named.
    const bool own_input = d.input_file == file.string(), own_output = d.output_file == file.string();
    r.verify_failure = VerifyFailure{d.event,
                                     own_input ? file.string() : d.input_file,
                                     own_output ? std::string("converted") : "converted " + d.output_file,
                                     static_cast<int>(d.input_line),
                                     static_cast<int>(d.output_line),
                                     own_input ? line_text(input, static_cast<int>(d.input_line)) : std::string(),
                                     own_output ? line_text(*r.converted, static_cast<int>(d.output_line)) : std::string(),
                                     d.what};
}

}  // namespace

ConvertOutcome convert_text(Workspace& workspace, const fs::path& file, std::string text, const ConvertSettings& settings) {
    ConvertOutcome r;
    const Resolved resolved = workspace.resolve(file, text);
    r.problems = resolved.problems;
    if (!resolved.ok() || has_errors(r.problems)) return r;
    const dialects::Dialect* to = resolved.project->dialects().find(settings.target);
    if (!to) {
        const std::vector<std::string> ids = resolved.project->dialects().ids();
        r.problems.push_back({Level::error, "", 0, 0,
                              fmt::format("--to: unknown dialect '{}' (known: {})", settings.target, fmt::join(ids, ", "))});
        return r;
    }
    r.from = resolved.dialect->id;
    r.to = to->id;
    const Project::SetupEntry& target = resolved.project->setup(*to, *resolved.dialect);
    for (const Problem& p : target.problems) r.problems.push_back(p);
    if (!target.setup) return r;
    converter::Options options;
    options.incremental = settings.incremental;
    options.expand = settings.expand;
    options.from = converter::reading_of(*resolved.dialect, *resolved.setup);
    options.to = converter::reading_of(*to, *target.setup);
    options.setup = *resolved.setup;
    options.loader = workspace.loader_for(file);
    options.name = file.string();
    options.time_limit_ms = resolved.project->limits().time_limit.count();
    const std::string input = settings.verify ? text : std::string();
    const auto bound = bind(std::move(text), *resolved.dialect);
    const converter::Conversion c = converter::convert(*bound->typed, *to, options);
    std::optional<ast::LineIndex> lines;   // only when there is something to place
    if (!c.reports.empty()) lines.emplace(bound->tree.text);
    for (const converter::Report& rep : c.reports) {
        const ast::Position at = lines->utf8(rep.range.begin);
        r.reports.push_back({static_cast<int>(at.line) + 1, static_cast<int>(at.column) + 1, rep.kind, rep.construct, rep.reason});
    }
    r.clean = c.clean();
    r.converted = converter::apply(bound->tree.text, c.edits);
    if (settings.verify) verify(workspace, file, input, resolved, *to, *target.setup, options, r);
    return r;
}

std::vector<std::string> describe(const std::string& file, const ConvertOutcome& o) {
    std::vector<std::string> lines;
    for (const ConvertReport& r : o.reports)
        lines.push_back(fmt::format("{}:{}:{}: {}: {}: {}", file, r.line, r.column, converter::to_string(r.kind),
                                    ast::printable(ast::shorten(r.construct, 80)), ast::printable(r.reason)));
    // As kerf fmt --verify says it (project/format.cpp): equal up to the alarm proves nothing after it.
    if (o.verify_stopped && !o.verify_failure)
        lines.push_back(fmt::format("{}:{}: note: --verify compared the runs up to alarm {} ({}); the blocks after it are not "
                                    "verified",
                                    file, o.verify_stopped->line, o.verify_stopped->number, ast::printable(o.verify_stopped->text)));
    if (o.verify_failure) {
        const VerifyFailure& f = *o.verify_failure;
        const std::string at = f.input_file == file && f.input_line > 0 ? fmt::format("{}:{}", file, f.input_line) : file;
        lines.push_back(fmt::format("{}: error: --verify: the converted program runs differently at motion event {}: {}", at,
                                    f.event, f.what));
        lines.push_back(fmt::format("  {} ({}) line {}: {}", ast::printable(f.input_file), o.from, f.input_line, f.input_block));
        lines.push_back(fmt::format("  {} ({}) line {}: {}", ast::printable(f.output_file), o.to, f.output_line, f.output_block));
    }
    return lines;
}

}  // namespace kerf::project
