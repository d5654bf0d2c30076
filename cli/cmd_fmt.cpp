// kerf fmt PATH... [--check | --diff | --write] [--verify] [--dialect D] [--machine M] [--<style option> V]...
//
// Formats programs (formatter/format.hpp) in the style of .kerf.toml's [format] table, overridden by
// a flag per option (formatter/style.hpp, docs/fmt.md). One file: the result on stdout; `-`: stdin
// to stdout; folders are walked as by every batch command (cli/source_files.hpp) and run on all
// cores. A file that cannot be formatted (syntax errors, a reference renumbering cannot follow, a
// --verify difference) is never touched; it is reported and the exit code is 1. Exit codes as in
// design.md: 0 clean, 1 would change / not formatted, 2 usage or I/O error.
#include <fmt/format.h>

#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <sys/stat.h>
#include <unistd.h>

#include "ast/typed.hpp"
#include "cli/commands.hpp"
#include "cli/config.hpp"
#include "cli/dry_run.hpp"
#include "cli/source_files.hpp"
#include "formatter/diff.hpp"
#include "formatter/format.hpp"
#include "formatter/verify.hpp"
#include "grammar/parse.hpp"

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
};

// What the files under one .kerf.toml (or none) share: the dialects, the style, the machine file.
struct Project {
    ProjectConfig config;
    RegistryResult dialects;
    formatter::Style style;
    fs::path machine_file;
    std::vector<std::string> errors;

    // The machine's Setup for a dialect, read once per dialect (a bad machine file is reported once).
    std::optional<interpreter::Setup> setup(const dialects::Dialect& dialect) const {
        std::lock_guard lock(setups_mutex);
        auto it = setups.find(dialect.id);
        if (it == setups.end()) it = setups.emplace(dialect.id, setup_for(machine_file, dialect)).first;
        return it->second;
    }
    mutable std::mutex setups_mutex;
    mutable std::map<std::string, std::optional<interpreter::Setup>> setups;
};

// [format] of the .kerf.toml (formatter::style_from_toml), then the flags over it.
void read_style(Project& p, const FmtOptions& o) {
    if (p.config.path) {
        std::string error;
        if (const auto text = read_file(*p.config.path, error)) {
            formatter::StyleResult r = formatter::style_from_toml(*text, p.config.path->string());
            p.style = r.style;
            for (const formatter::StyleError& e : r.errors)
                p.errors.push_back(e.line ? fmt::format("{} (line {}, column {})", e.message, e.line, e.column) : e.message);
        } else {
            p.errors.push_back(error);
        }
    }
    for (const auto& [key, option] : o.style_options)
        if (option->count() > 0)
            if (const auto error = formatter::set_option(p.style, key, o.style_flags.at(key)))
                p.errors.push_back(fmt::format("--{}: {}", option->get_name().substr(2), *error));
}

// Held by pointer: the workers share it, and its setup cache has a mutex.
std::unique_ptr<Project> make_project(const fs::path& start, const FmtOptions& o) {
    auto owned = std::make_unique<Project>();
    Project& p = *owned;
    p.config = find_config(start, p.errors);
    std::vector<fs::path> files(o.dialect_files.begin(), o.dialect_files.end());
    files.insert(files.end(), p.config.dialect_files.begin(), p.config.dialect_files.end());
    p.dialects = make_registry(files);
    p.errors.insert(p.errors.end(), p.dialects.errors.begin(), p.dialects.errors.end());
    p.machine_file = !o.machine_file.empty() ? fs::path(o.machine_file) : p.config.machine_file.value_or(fs::path{});
    read_style(p, o);
    return owned;
}

// One file's outcome; printed by the main thread in file order.
struct FileResult {
    std::optional<std::string> formatted;   // nullopt: not formatted (messages say why)
    bool changed = false;
    std::string messages;                   // for stderr
    int io_error = 0;                       // kExitUsage when the file could not be read
};

std::string diagnostic_line(const std::string& name, const ast::LineIndex& lines, const ast::Diagnostic& d) {
    const ast::Position at = lines.utf8(d.range.begin);
    std::string s = fmt::format("{}:{}:{}: {}: {} [{}]\n", name, at.line + 1, at.column + 1, ast::to_string(d.severity),
                                d.message, d.code);
    if (!d.hint.empty()) s += fmt::format("  hint: {}\n", d.hint);
    return s;
}

// Syntax errors make the file one kerf does not format: it is left as it is.
bool report_syntax_errors(const std::string& name, const ast::SyntaxTree& tree, const ast::LineIndex& lines, FileResult& r) {
    std::size_t errors = 0;
    for (const ast::Diagnostic& d : tree.diagnostics) {
        if (d.severity != ast::Severity::error) continue;
        if (errors++ == 0) r.messages += diagnostic_line(name, lines, d);
    }
    if (errors == 0) return false;
    r.messages += fmt::format("{}: not formatted: {} syntax error{} (the first above); the file is left as it is\n", name,
                              errors, errors == 1 ? "" : "s");
    return true;
}

void verify_result(const std::string& name, std::string text, const dialects::Dialect& dialect,
                   const interpreter::Setup& setup, FileResult& r) {
    formatter::VerifyOptions v;
    v.dialect = &dialect;
    v.setup = setup;
    const fs::path folder = fs::path(name).parent_path();
    v.loader = [folder](std::int64_t n) { return load_from_folder(folder, n); };
    const formatter::VerifyResult result = formatter::verify(name, std::move(text), *r.formatted, v);
    if (!result.difference) return;
    const formatter::Difference& d = *result.difference;
    r.messages += fmt::format(
        "{}:{}: error: --verify: the formatted program runs differently at event {} (formatted line {}): {}; "
        "the file is left as it is (a kerf bug: please report it with the file)\n",
        name, d.input_line, d.event, d.output_line, d.what);
    r.formatted.reset();
}

// Parses, refuses a text with syntax errors, formats; fills r.formatted and r.changed.
void format_tree(const std::string& name, std::string text, const dialects::Dialect& dialect, const formatter::Style& style,
                 const interpreter::Setup& setup, FileResult& r) {
    ast::SyntaxTree tree = grammar::parse(std::move(text), dialect.lexical);
    const ast::TypedFile typed = ast::TypedFile::bind(tree, dialect);
    const ast::LineIndex lines(tree.text);
    if (report_syntax_errors(name, tree, lines, r)) return;
    formatter::FormatResult f = formatter::format(typed, style, {setup.calculator_decimal});
    for (const ast::Diagnostic& d : f.diagnostics) r.messages += diagnostic_line(name, lines, d);
    if (!f.text) {
        r.messages += fmt::format("{}: not formatted; the file is left as it is\n", name);
        return;
    }
    r.changed = *f.text != tree.text;
    r.formatted = std::move(f.text);
}

FileResult format_text(const std::string& name, std::string text, const Project& p, const FmtOptions& o) {
    FileResult r;
    const std::string id = choose_dialect(o.dialect, p.config, text);
    const dialects::Dialect* dialect = p.dialects.registry.find(id);
    if (!dialect) {
        r.messages = fmt::format("kerf: unknown dialect '{}'; `kerf dialects` lists them\n", id);
        r.io_error = kExitUsage;
        return r;
    }
    const std::optional<interpreter::Setup> setup = p.setup(*dialect);
    if (!setup) {
        r.io_error = kExitUsage;
        return r;
    }
    std::string original = o.verify ? text : std::string();
    format_tree(name, std::move(text), *dialect, p.style, *setup, r);
    // The tree is gone by now: --verify parses both texts again, and a 100 MB file's tree is 360 MB.
    if (o.verify && r.changed) verify_result(name, std::move(original), *dialect, *setup, r);
    return r;
}

// Atomic replacement: a temp file in the same folder with the old permissions, then rename().
std::optional<std::string> write_atomic(const fs::path& path, const std::string& text) {
    struct stat st{};
    if (::stat(path.c_str(), &st) != 0) return fmt::format("{}: cannot stat", path.string());
    std::string temp = (path.parent_path() / ("." + path.filename().string() + ".kerf-fmt-XXXXXX")).string();
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) return fmt::format("{}: cannot create a temp file next to it", path.string());
    bool ok = ::fchmod(fd, st.st_mode & 07777) == 0;
    for (std::size_t at = 0; ok && at < text.size();) {
        const ssize_t n = ::write(fd, text.data() + at, text.size() - at);
        ok = n > 0;
        if (ok) at += static_cast<std::size_t>(n);
    }
    ok = ::fsync(fd) == 0 && ok;
    ok = ::close(fd) == 0 && ok;
    if (ok && ::rename(temp.c_str(), path.c_str()) == 0) return std::nullopt;
    ::unlink(temp.c_str());
    return fmt::format("{}: could not write the formatted file; it is left as it is", path.string());
}

int run_stdin(const FmtOptions& o) {
    std::string text(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>{});
    const std::unique_ptr<Project> project = make_project(fs::current_path(), o);
    const Project& p = *project;
    for (const std::string& e : p.errors) std::cerr << "kerf: " << e << "\n";
    if (!p.errors.empty()) return kExitUsage;
    FileResult r = format_text("<stdin>", text, p, o);
    std::cerr << r.messages;
    if (r.io_error) return r.io_error;
    if (o.diff || o.check) {
        if (o.diff && r.formatted) std::cout << formatter::unified_diff(text, *r.formatted, "<stdin>", "<stdin> (formatted)");
        if (o.check && r.changed) std::cout << "<stdin>\n";
        return r.changed || !r.formatted ? kExitFindings : kExitClean;
    }
    std::cout << (r.formatted ? *r.formatted : text);   // an editor gets its text back either way
    return r.formatted ? kExitClean : kExitFindings;
}

// The result of one file in the chosen mode: stdout, and the exit code it asks for.
int finish_file(const fs::path& path, FileResult& r, const FmtOptions& o, std::string& original) {
    std::cerr << r.messages;
    if (r.io_error) return r.io_error;
    if (!r.formatted) return kExitFindings;
    if (o.check) {
        if (r.changed) std::cout << path.string() << "\n";
        return r.changed ? kExitFindings : kExitClean;
    }
    if (o.diff) {
        std::cout << formatter::unified_diff(original, *r.formatted, path.string(), path.string() + " (formatted)");
        return r.changed ? kExitFindings : kExitClean;
    }
    if (o.write) {
        if (!r.changed) return kExitClean;
        if (const auto error = write_atomic(path, *r.formatted)) {
            std::cerr << "kerf: " << *error << "\n";
            return kExitUsage;
        }
        return kExitClean;
    }
    std::cout << *r.formatted;
    return kExitClean;
}

int run_fmt(const FmtOptions& o) {
    if (o.paths.size() == 1 && o.paths.front() == "-") return run_stdin(o);
    const SourceFiles sources = collect_source_files({o.paths.begin(), o.paths.end()});
    for (const std::string& e : sources.errors) std::cerr << "kerf: " << e << "\n";
    const bool to_stdout = !o.check && !o.diff && !o.write;
    if (to_stdout && sources.files.size() > 1) {
        std::cerr << "kerf: fmt prints one file; for several use --check, --diff or --write\n";
        return kExitUsage;
    }
    // One project per .kerf.toml, prepared here so the workers only read it.
    std::map<std::optional<fs::path>, std::unique_ptr<Project>> projects;
    std::vector<const Project*> project_of(sources.files.size());
    int code = sources.errors.empty() ? kExitClean : kExitUsage;
    for (std::size_t i = 0; i < sources.files.size(); ++i) {
        std::vector<std::string> ignored;
        const auto key = find_config(sources.files[i], ignored).path;
        auto& slot = projects[key];
        if (!slot) {
            slot = make_project(sources.files[i], o);
            for (const std::string& e : slot->errors) std::cerr << "kerf: " << e << "\n";
        }
        if (!slot->errors.empty()) return kExitUsage;
        project_of[i] = slot.get();
    }
    std::vector<FileResult> results(sources.files.size());
    std::vector<std::string> originals(sources.files.size());
    ProgressBar bar("fmt");
    run_parallel(
        sources.files.size(), 0,
        [&](std::size_t i) {
            std::string error;
            std::optional<std::string> text = read_file(sources.files[i], error);
            if (!text) {
                results[i].messages = "kerf: " + error + "\n";
                results[i].io_error = kExitUsage;
                return;
            }
            if (o.diff) originals[i] = *text;
            results[i] = format_text(sources.files[i].string(), std::move(*text), *project_of[i], o);
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
