// kerf fmt PATH... [--check | --diff | --write] [--verify] [--dialect D] [--machine M] [--<style option> V]...
//
// Formats programs (formatter/format.hpp) in the style of .kerf.toml's [format] table, overridden by
// a flag per option (formatter/style.hpp, docs/fmt.md). One file: the result on stdout; `-`: stdin
// to stdout; folders are walked as by every batch command (project/walk.hpp) and run on all
// cores. A file that cannot be formatted (syntax errors, a reference renumbering cannot follow, a
// --verify difference) is never touched; it is reported and the exit code is 1. Exit codes as in
// design.md: 0 clean, 1 would change / not formatted, 2 usage or I/O error.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <map>

#include "ast/input.hpp"
#include "cli/commands.hpp"
#include "cli/dry_run.hpp"
#include "cli/progress.hpp"
#include "formatter/diff.hpp"
#include "project/format.hpp"
#include "project/parallel.hpp"
#include "project/walk.hpp"
#include "project/writer.hpp"

namespace kerf::cli {

namespace {

namespace fs = std::filesystem;

struct FmtOptions {
    std::vector<std::string> paths;
    bool check = false;
    bool diff = false;
    bool write = false;
    bool verify = false;
    std::string dialect = "auto";
    std::vector<std::string> dialect_files;
    std::string machine_file;
    std::map<std::string, std::string> style_flags;    // option key → value given on the command line
    std::map<std::string, CLI::Option*> style_options;
    project::LimitSettings limits;
};

// The style of a file: its project's [format] table, then the flags over it (a bad flag is a problem).
formatter::Style style_for(const project::Project& p, const FmtOptions& o, std::vector<project::Problem>& problems) {
    formatter::Style style = p.config().format;
    for (const auto& [key, option] : o.style_options)
        if (option->count() > 0)
            if (const auto error = formatter::set_option(style, key, o.style_flags.at(key)))
                problems.push_back({project::Level::error, "", 0, 0, fmt::format("--{}: {}", option->get_name().substr(2), *error)});
    return style;
}

// One file's outcome; printed by the main thread in file order.
struct FileResult {
    project::FormatOutcome outcome;
    int usage_error = 0;   // kExitUsage when the file could not be read or resolved
    ast::Encoding encoding = ast::Encoding::utf8;   // of the input: the output is written in it
    bool bom = false;
};

// The file's project problems (once each), its style and its formatting.
FileResult format_file(project::Workspace& w, const fs::path& path, std::string text, const FmtOptions& o,
                       ProblemPrinter& problems) {
    FileResult r;
    const std::shared_ptr<const project::Project> p = w.project_for(path);
    std::vector<project::Problem> setup = p->problems();
    const formatter::Style style = style_for(*p, o, setup);
    if (problems.print(setup)) {
        r.usage_error = kExitUsage;
        return r;
    }
    r.outcome = project::format_text(w, path, std::move(text), style, o.verify);
    if (problems.print(r.outcome.problems)) r.usage_error = kExitUsage;
    return r;
}

void print_messages(const FileResult& r) {
    for (const std::string& m : r.outcome.messages) std::cerr << m << "\n";
}

int run_stdin(const FmtOptions& o) {
    std::string bytes(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>{});
    project::Workspace workspace(std::make_shared<project::DiskFileSystem>(),
                                 overrides_of(o.dialect, o.dialect_files, o.machine_file, o.limits));
    ProblemPrinter problems;
    // Named "<stdin>", found in the current folder: its .kerf.toml and its subprograms apply.
    project::ReadResult read = project::decode_file("<stdin>", bytes, workspace.project_for("<stdin>")->limits().input);
    problems.print(project::input_problems("<stdin>", read.problems));
    if (!read.text) {
        std::cout << bytes;   // an editor gets its text back either way
        return kExitUsage;
    }
    const std::string& text = *read.text;
    FileResult r = format_file(workspace, "<stdin>", text, o, problems);
    print_messages(r);
    if (r.usage_error) return r.usage_error;
    const project::FormatOutcome& f = r.outcome;
    if (o.diff || o.check) {
        if (o.diff && f.formatted) std::cout << formatter::unified_diff(text, *f.formatted, "<stdin>", "<stdin> (formatted)");
        if (o.check && f.changed) std::cout << "<stdin>\n";
        return f.changed || !f.formatted ? kExitFindings : kExitClean;
    }
    // An editor gets its text back either way, in its encoding.
    std::cout << (f.formatted ? ast::encode_output(*f.formatted, read.encoding, read.bom) : bytes);
    return f.formatted ? kExitClean : kExitFindings;
}

// The result of one file in the chosen mode: stdout, and the exit code it asks for.
int finish_file(const fs::path& path, FileResult& r, const FmtOptions& o, std::string& original) {
    print_messages(r);
    if (r.usage_error) return r.usage_error;
    const project::FormatOutcome& f = r.outcome;
    if (!f.formatted) return kExitFindings;
    if (o.check) {
        if (f.changed) std::cout << path.string() << "\n";
        return f.changed ? kExitFindings : kExitClean;
    }
    if (o.diff) {
        std::cout << formatter::unified_diff(original, *f.formatted, path.string(), path.string() + " (formatted)");
        return f.changed ? kExitFindings : kExitClean;
    }
    // The program keeps its encoding (a UTF-16 file stays UTF-16).
    if (o.write) {
        if (!f.changed) return kExitClean;
        if (const auto error = project::write_atomically(path, ast::encode_output(*f.formatted, r.encoding, r.bom))) {
            std::cerr << fmt::format("{}: error: {}\n", path.string(), *error);
            return kExitUsage;
        }
        return kExitClean;
    }
    std::cout << ast::encode_output(*f.formatted, r.encoding, r.bom);
    return kExitClean;
}

int run_fmt(const FmtOptions& o) {
    if (o.paths.size() == 1 && o.paths.front() == "-") return run_stdin(o);
    project::Workspace workspace(std::make_shared<project::DiskFileSystem>(),
                                 overrides_of(o.dialect, o.dialect_files, o.machine_file, o.limits));
    const project::WalkResult sources = project::collect_program_files({o.paths.begin(), o.paths.end()}, workspace.files());
    for (const std::string& e : sources.errors) std::cerr << "kerf: " << e << "\n";
    const bool to_stdout = !o.check && !o.diff && !o.write;
    if (to_stdout && sources.files.size() > 1) {
        std::cerr << "kerf: fmt prints one file; for several use --check, --diff or --write\n";
        return kExitUsage;
    }
    int code = sources.errors.empty() ? kExitClean : kExitUsage;
    std::vector<FileResult> results(sources.files.size());
    std::vector<std::string> originals(sources.files.size());
    ProblemPrinter problems;
    ProgressBar bar("fmt");
    project::run_parallel(
        sources.files.size(), 0,
        [&](std::size_t i) {
            project::ReadResult read = workspace.read(sources.files[i]);
            std::vector<project::Problem> input = project::input_problems(sources.files[i].string(), read.problems);
            if (!read.text && !project::has_errors(input))
                input.push_back({project::Level::error, sources.files[i].string(), 0, 0, "cannot open file"});
            problems.print(input);
            if (!read.text) {
                results[i].usage_error = kExitUsage;
                return;
            }
            if (o.diff) originals[i] = *read.text;
            results[i] = format_file(workspace, sources.files[i], std::move(*read.text), o, problems);
            results[i].encoding = read.encoding;
            results[i].bom = read.bom;
        },
        [&](std::size_t done, std::size_t total) { bar.update(done, total); });
    for (std::size_t i = 0; i < sources.files.size(); ++i) {
        code = std::max(code, finish_file(sources.files[i], results[i], o, originals[i]));
        results[i] = {};
    }
    return code;
}

}  // namespace

Command add_fmt_command(CLI::App& app) {
    auto o = std::make_shared<FmtOptions>();
    CLI::App* cmd = app.add_subcommand("fmt", "format programs (style from .kerf.toml [format] and the flags; docs/fmt.md)");
    cmd->add_option("paths", o->paths, "files or folders; - reads standard input and writes standard output")->required();
    auto* check = cmd->add_flag("--check", o->check, "list the files that would change; exit 1 if any");
    auto* diff = cmd->add_flag("--diff", o->diff, "print a unified diff of what would change; exit 1 if anything would");
    cmd->add_flag("--write", o->write, "rewrite the files in place (atomically, permissions kept)")->excludes(check)->excludes(diff);
    cmd->add_flag("--verify", o->verify, "run the interpreter on each file before and after and refuse any difference");
    cmd->add_option("--dialect", o->dialect, "dialect id, or auto (default)");
    cmd->add_option("--dialect-file", o->dialect_files, "load a dialect data file (TOML)");
    cmd->add_option("--machine", o->machine_file, "machine configuration file (TOML): its decimal-point mode decides decimal_point = add");
    add_limit_options(*cmd, o->limits);
    for (const formatter::OptionInfo& info : formatter::options()) {
        std::string flag = "--" + std::string(info.key);
        std::replace(flag.begin(), flag.end(), '_', '-');
        const std::string key(info.key);
        o->style_options[key] =
            cmd->add_option(flag, o->style_flags[key], fmt::format("{} ({})", info.description, info.values));
    }
    return [o] { return run_fmt(*o); };
}

}  // namespace kerf::cli
