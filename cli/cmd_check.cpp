// kerf check PATH... [--dialect D] [--machine M] [--format human|json|sarif] [--fix]
//                    [--baseline FILE] [--write-baseline FILE] [--list-rules [--format markdown]]
// The analyzer (analyzer/) over files and folders, on all cores. All file I/O is here.
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>

#include "analyzer/analyze.hpp"
#include "analyzer/baseline.hpp"
#include "analyzer/fix.hpp"
#include "analyzer/output.hpp"
#include "cli/commands.hpp"
#include "cli/config.hpp"
#include "cli/dry_run.hpp"
#include "cli/source_files.hpp"

namespace kerf::cli {

namespace {

namespace fs = std::filesystem;
namespace an = analyzer;

struct CheckOptions {
    std::vector<std::string> paths;
    std::string dialect = "auto";
    std::vector<std::string> dialect_files;
    std::string machine_file;
    std::string format = "human";
    bool fix = false;
    bool list_rules = false;
    std::string baseline;
    std::string write_baseline;
    unsigned jobs = 0;
};

// What the files of one folder share: .kerf.toml, its [check] table, the dialects, the setups.
struct FolderContext {
    ProjectConfig project;
    an::CheckConfig check;
    RegistryResult dialects;
    std::mutex mutex;   // guards setups (filled on first use by the worker threads)
    std::map<std::string, std::optional<interpreter::Setup>> setups;
};

struct Checked {
    an::FileReport report;
    std::vector<an::BaselineEntry> keys;   // per finding
    std::string error;                     // I/O or setup problem (exit 2)
    bool skipped = false;                  // excluded by [check] include/exclude
    std::size_t fixed = 0;
};

std::unique_ptr<FolderContext> load_folder(const fs::path& folder, const CheckOptions& o, std::vector<std::string>& errors) {
    auto c = std::make_unique<FolderContext>();
    c->project = find_config(folder / "x", errors);
    std::vector<fs::path> files(o.dialect_files.begin(), o.dialect_files.end());
    files.insert(files.end(), c->project.dialect_files.begin(), c->project.dialect_files.end());
    c->dialects = make_registry(files);
    errors.insert(errors.end(), c->dialects.errors.begin(), c->dialects.errors.end());
    if (c->project.path) {
        std::string error;
        if (const auto text = read_file(*c->project.path, error)) {
            an::ConfigResult parsed = an::parse_check_config(*text, c->project.path->string());
            c->check = std::move(parsed.config);
            errors.insert(errors.end(), parsed.errors.begin(), parsed.errors.end());
        }
    }
    return c;
}

const interpreter::Setup* setup_of(FolderContext& c, const CheckOptions& o, const dialects::Dialect& dialect) {
    const std::lock_guard lock(c.mutex);
    auto it = c.setups.find(dialect.id);
    if (it == c.setups.end()) {
        const fs::path machine = !o.machine_file.empty() ? fs::path(o.machine_file) : c.project.machine_file.value_or(fs::path{});
        it = c.setups.emplace(dialect.id, setup_for(machine, dialect)).first;
    }
    return it->second ? &*it->second : nullptr;
}

// Writes `text` next to `path` and renames it over `path`, keeping the permissions: a reader
// never sees half a file, and a failure leaves the original untouched.
bool write_atomically(const fs::path& path, const std::string& text, std::string& error) {
    const fs::path temp = path.string() + ".kerf-tmp";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out << text;
        if (!out.flush()) {
            error = fmt::format("{}: cannot write {}", path.string(), temp.string());
            return false;
        }
    }
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) ::chmod(temp.c_str(), st.st_mode & 07777);
    std::error_code ec;
    fs::rename(temp, path, ec);
    if (ec) {
        fs::remove(temp, ec);
        error = fmt::format("{}: cannot replace the file: {}", path.string(), ec.message());
        return false;
    }
    return true;
}

std::vector<an::Finding> analyze(const std::string& name, std::string text, const dialects::Dialect& dialect,
                                 const interpreter::Setup& setup, const an::CheckConfig& config,
                                 interpreter::ProgramSet& programs, std::uint32_t& file) {
    file = programs.add(name, std::move(text), dialect);
    const fs::path folder = fs::path(name).parent_path();
    programs.set_loader([folder](std::int64_t n) { return load_from_folder(folder, n); }, &dialect);
    an::CheckOptions options;
    options.config = config;
    return an::check_file(programs, file, dialect, setup, options);
}

void check_one(const fs::path& path, FolderContext& folder, const CheckOptions& o, Checked& out) {
    const std::string name = path.string();
    std::string error;
    std::optional<std::string> text = read_file(path, error);
    if (!text) {
        out.error = error;
        return;
    }
    const std::string id = choose_dialect(o.dialect, folder.project, *text);
    const dialects::Dialect* dialect = folder.dialects.registry.find(id);
    if (!dialect) {
        out.error = fmt::format("{}: unknown dialect '{}'; `kerf dialects` lists them", name, id);
        return;
    }
    const interpreter::Setup* setup = setup_of(folder, o, *dialect);
    if (!setup) {
        out.error = fmt::format("{}: the machine file could not be loaded", name);
        return;
    }
    auto programs = std::make_unique<interpreter::ProgramSet>();
    std::uint32_t file = 0;
    std::vector<an::Finding> findings = analyze(name, *text, *dialect, *setup, folder.check, *programs, file);
    if (o.fix) {
        const an::FixResult fixed = an::apply_fixes(*text, findings);
        if (fixed.applied > 0) {
            if (!write_atomically(path, fixed.text, out.error)) return;
            out.fixed = fixed.applied;
            programs = std::make_unique<interpreter::ProgramSet>();
            findings = analyze(name, fixed.text, *dialect, *setup, folder.check, *programs, file);
        }
    }
    const interpreter::LoadedFile& loaded = programs->file(file);
    for (const an::Finding& f : findings) out.keys.push_back({name, f.rule, an::block_text(*loaded.whole_tree(), f.range.begin)});
    out.report = an::make_report(name, *loaded.whole_tree(), *loaded.whole_lines(), std::move(findings));
}

// [check] include/exclude apply to files found in folders, relative to the .kerf.toml's folder.
bool selected(const fs::path& file, const FolderContext& folder, const std::vector<fs::path>& named) {
    if (!folder.project.path || std::find(named.begin(), named.end(), file) != named.end()) return true;
    const fs::path relative = fs::relative(fs::absolute(file), fs::absolute(*folder.project.path).parent_path());
    return folder.check.selects(relative.generic_string());
}

int list_rules(const CheckOptions& o) {
    const an::Registry& rules = an::builtin_rules();
    std::cout << (o.format == "markdown" ? an::format_rules_markdown(rules) : an::format_rule_list(rules));
    return kExitClean;
}

std::optional<std::vector<an::BaselineEntry>> load_baseline(const std::string& path) {
    std::string error;
    const std::optional<std::string> text = read_file(path, error);
    if (!text) {
        std::cerr << "kerf: " << error << "\n";
        return std::nullopt;
    }
    auto entries = an::read_baseline(*text, error);
    if (!entries) std::cerr << fmt::format("kerf: {}: {}\n", path, error);
    return entries;
}

// Drops the findings the baseline accepts (in file order, so the result does not depend on threads).
void apply_baseline(std::vector<Checked>& checked, const std::vector<an::BaselineEntry>& entries) {
    an::BaselineFilter filter(entries);
    for (Checked& c : checked) {
        an::FileReport& r = c.report;
        std::vector<std::size_t> keep;
        for (std::size_t i = 0; i < r.findings.size(); ++i)
            if (!filter.accepts(c.keys[i])) keep.push_back(i);
        an::FileReport kept;
        kept.name = r.name;
        for (const std::size_t i : keep) {
            kept.findings.push_back(std::move(r.findings[i]));
            kept.locations.push_back(r.locations[i]);
            kept.utf16.push_back(r.utf16[i]);
            kept.lines.push_back(std::move(r.lines[i]));
        }
        r = std::move(kept);
    }
}

void print(const std::vector<an::FileReport>& reports, const CheckOptions& o, std::size_t files, std::size_t fixed) {
    if (o.format == "json") std::cout << an::format_json(reports, files);
    else if (o.format == "sarif") std::cout << an::format_sarif(reports, an::builtin_rules());
    else {
        const bool color = ::isatty(STDOUT_FILENO) && !std::getenv("NO_COLOR");
        std::cout << an::format_human(reports, color);
        const an::Counts c = an::count(reports);
        std::cout << fmt::format("{} error(s), {} warning(s), {} info, {} hint(s) in {} file(s) checked{}\n", c.error, c.warning,
                                 c.info, c.hint, files, fixed ? fmt::format("; {} fix(es) applied", fixed) : "");
    }
}

int run_check(const CheckOptions& o) {
    if (o.list_rules) return list_rules(o);
    if (o.paths.empty()) {
        std::cerr << "kerf: check needs a file or folder (or --list-rules)\n";
        return kExitUsage;
    }
    const std::vector<fs::path> named(o.paths.begin(), o.paths.end());
    SourceFiles sources = collect_source_files(named);
    int code = kExitClean;
    for (const std::string& e : sources.errors) std::cerr << "kerf: " << e << "\n", code = kExitUsage;
    std::optional<std::vector<an::BaselineEntry>> baseline;
    if (!o.baseline.empty() && !(baseline = load_baseline(o.baseline))) return kExitUsage;
    // Folder contexts first (sequentially: they print their configuration errors), then the files.
    std::map<fs::path, std::unique_ptr<FolderContext>> folders;
    std::vector<FolderContext*> folder_of;
    std::vector<std::string> config_errors;
    for (const fs::path& f : sources.files) {
        auto& c = folders[f.parent_path()];
        if (!c) c = load_folder(f.parent_path(), o, config_errors);
        folder_of.push_back(c.get());
    }
    for (const std::string& e : config_errors) std::cerr << "kerf: " << e << "\n";
    std::vector<Checked> checked(sources.files.size());
    ProgressBar bar("kerf check");
    run_parallel(sources.files.size(), o.jobs, [&](std::size_t i) {
        if (!selected(sources.files[i], *folder_of[i], named)) checked[i].skipped = true;
        else check_one(sources.files[i], *folder_of[i], o, checked[i]);
    }, [&](std::size_t done, std::size_t total) { bar.update(done, total); });
    std::vector<an::BaselineEntry> all_keys;
    for (const Checked& c : checked) all_keys.insert(all_keys.end(), c.keys.begin(), c.keys.end());
    if (baseline) apply_baseline(checked, *baseline);
    std::vector<an::FileReport> reports;
    std::size_t files = 0, fixed = 0;
    for (Checked& c : checked) {
        if (!c.error.empty()) std::cerr << "kerf: " << c.error << "\n", code = kExitUsage;
        if (c.skipped || !c.error.empty()) continue;
        ++files;
        fixed += c.fixed;
        if (!c.report.findings.empty()) reports.push_back(std::move(c.report));
    }
    print(reports, o, files, fixed);
    if (!o.write_baseline.empty()) {
        std::string error;
        if (!write_atomically(o.write_baseline, an::write_baseline(all_keys), error)) std::cerr << "kerf: " << error << "\n", code = kExitUsage;
    }
    if (code == kExitClean && an::count(reports).error > 0) code = kExitFindings;
    return code;
}

}  // namespace

Command add_check_command(CLI::App& app) {
    auto o = std::make_shared<CheckOptions>();
    CLI::App* cmd = app.add_subcommand("check", "lint programs: rules with stable ids (kerf check --list-rules)");
    cmd->add_option("paths", o->paths, "files and folders (folders recursively)");
    cmd->add_option("--dialect", o->dialect, "dialect id, or auto (default: .kerf.toml, then detection)");
    cmd->add_option("--dialect-file", o->dialect_files, "load a dialect data file (TOML)");
    cmd->add_option("--machine", o->machine_file, "machine configuration file (TOML, machine/SCHEMA.md)");
    cmd->add_option("--format", o->format, "human (default), json, sarif; with --list-rules also markdown")
        ->check(CLI::IsMember({"human", "json", "sarif", "markdown"}));
    cmd->add_flag("--fix", o->fix, "apply the safe fixes in place (atomically), then report what is left");
    cmd->add_option("--baseline", o->baseline, "accept the findings listed in this baseline file");
    cmd->add_option("--write-baseline", o->write_baseline, "write all findings of this run as a baseline file");
    cmd->add_flag("--list-rules", o->list_rules, "print the rules: id, name, default severity, category");
    cmd->add_option("--jobs,-j", o->jobs, "threads (default: all cores)");
    return [o] { return run_check(*o); };
}

}  // namespace kerf::cli
