// kerf parse FILE [--dialect D|auto] [--json | --print] [--explain-dialect]
#include <fmt/format.h>

#include <boost/json/serialize.hpp>
#include <chrono>
#include <iostream>

#include "analyzer/output.hpp"
#include "ast/display.hpp"
#include "ast/dump.hpp"
#include "ast/printer.hpp"
#include "cli/commands.hpp"
#include "cli/dry_run.hpp"
#include "cli/progress.hpp"
#include "grammar/parse.hpp"
#include "project/workspace.hpp"

namespace kerf::cli {

namespace {

struct ParseOptions {
    std::string file;
    std::string dialect = "auto";
    std::vector<std::string> dialect_files;
    bool json = false;
    bool print = false;
    bool explain_dialect = false;
    bool stats = false;
    project::LimitSettings limits;
};

void print_diagnostic(const std::string& file, const ast::LineIndex& lines, const ast::Diagnostic& d) {
    const ast::Position p = lines.utf8(d.range.begin);
    std::cerr << fmt::format("{}:{}:{}: {}: {} [{}]\n", file, p.line + 1, p.column + 1, ast::to_string(d.severity),
                             ast::printable(d.message), analyzer::diagnostic_id(d.code, analyzer::builtin_rules()));
    if (!d.hint.empty()) std::cerr << fmt::format("  hint: {}\n", ast::printable(d.hint));
}

// The file (or standard input) through the input decoder under the project's limits; nullopt
// after printing why not. Notes (an empty file, UTF-16 read) are printed too.
std::optional<project::ReadResult> read_program(project::Workspace& workspace, const ParseOptions& o) {
    project::ReadResult read;
    const std::string name = o.file == "-" ? "<stdin>" : o.file;
    if (o.file == "-") {
        std::string bytes{std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>()};
        read = project::decode_file(name, std::move(bytes), workspace.project_for(name)->limits().input);
    } else {
        read = workspace.read(o.file);
    }
    std::vector<project::Problem> problems = project::input_problems(name, read.problems);
    if (!read.text && !project::has_errors(problems)) problems.push_back({project::Level::error, name, 0, 0, "cannot open file"});
    ProblemPrinter().print(problems);
    if (!read.text) return std::nullopt;
    return read;
}

int run_parse(const ParseOptions& o) {
    const bool from_stdin = o.file == "-";
    // The flag wins over the config, the config over the header and detection (project/workspace.hpp).
    project::Workspace workspace(std::make_shared<project::DiskFileSystem>(),
                                 overrides_of(o.dialect, o.dialect_files, "", o.limits));
    std::optional<project::ReadResult> read = read_program(workspace, o);
    if (!read) return kExitUsage;
    std::optional<std::string>& text = read->text;
    const project::Resolved resolved = workspace.resolve(from_stdin ? "<stdin>" : o.file, *text);
    const bool bad_project = ProblemPrinter().print(resolved.project->problems());
    if (bad_project) return kExitUsage;
    const std::string& id = resolved.choice.id;
    std::string why = resolved.choice.why;
    for (const std::string& r : resolved.choice.evidence) why += "\n  " + r;
    const dialects::Dialect* dialect = resolved.dialect;
    if (!dialect) {
        std::cerr << fmt::format("kerf: unknown dialect '{}'; `kerf dialects` lists them\n", id);
        return kExitUsage;
    }
    if (o.explain_dialect) std::cerr << why << "\n";

    const auto start = std::chrono::steady_clock::now();
    ast::SyntaxTree tree = grammar::parse(std::move(*text), dialect->lexical, grammar::parse_threads());
    const ast::TypedFile typed = ast::TypedFile::bind(tree, *dialect, false, grammar::parse_threads());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (o.stats) {
        std::size_t errors = 0;
        for (const ast::Diagnostic& d : tree.diagnostics) errors += d.severity == ast::Severity::error;
        std::cout << fmt::format(
            "bytes {}\nblocks {}\ntokens {}\nexpressions {}\nstatements {}\nprograms {}\ndiagnostics {} ({} errors)\n"
            "parse+bind {:.3f} s, {:.1f} MB/s\n",
            tree.text.size(), tree.blocks.size(), tree.tokens.size(), tree.exprs.size(), tree.statements.size(),
            typed.programs().size(), tree.diagnostics.size() + typed.diagnostics().size(), errors, seconds,
            static_cast<double>(tree.text.size()) / 1e6 / seconds);
        return errors ? kExitFindings : kExitClean;
    }
    // Only what prints positions needs the line index (--stats does not: 24 MB for 100 MB of short lines).
    const ast::LineIndex lines(tree.text);
    if (o.print) {
        std::cout << ast::encode_output(ast::print(tree), read->encoding, read->bom);   // the file's bytes
    } else if (o.json) {
        std::cout << boost::json::serialize(ast::to_json(typed, lines)) << "\n";
    } else {
        std::cout << ast::printable(ast::to_text(typed, lines), true);   // the file's bytes never reach the terminal raw
    }
    bool errors = false;
    const std::string name = from_stdin ? "<stdin>" : o.file;
    for (const ast::Diagnostic& d : tree.diagnostics) {
        if (!o.json) print_diagnostic(name, lines, d);
        errors |= d.severity == ast::Severity::error;
    }
    for (const ast::Diagnostic& d : typed.diagnostics()) {
        if (!o.json) print_diagnostic(name, lines, d);
        errors |= d.severity == ast::Severity::error;
    }
    return errors ? kExitFindings : kExitClean;
}

}  // namespace

Command add_parse_command(CLI::App& app) {
    auto o = std::make_shared<ParseOptions>();
    CLI::App* cmd = app.add_subcommand("parse", "print the typed syntax tree of a program (or the file back, --print)");
    cmd->add_option("file", o->file, "program file, or - for standard input")->required();
    cmd->add_option("--dialect", o->dialect, "dialect id, or auto (default) to detect it");
    cmd->add_option("--dialect-file", o->dialect_files, "load a dialect data file (TOML)");
    auto* json = cmd->add_flag("--json", o->json, "typed AST as JSON with source ranges");
    cmd->add_flag("--print", o->print, "print the file back from the syntax tree (byte for byte)")->excludes(json);
    cmd->add_flag("--stats", o->stats, "print counts and parse throughput instead of the tree");
    cmd->add_flag("--explain-dialect", o->explain_dialect, "say which dialect was chosen and why (stderr)");
    add_limit_options(*cmd, o->limits, false);
    return [o] { return run_parse(*o); };
}

}  // namespace kerf::cli
