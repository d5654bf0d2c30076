// kerf check PATH... [--dialect D] [--machine M] [--format human|json|sarif] [--fix] [--verbose]
//                    [--baseline FILE] [--write-baseline FILE] [--list-rules [--format markdown]]
// The analyzer over files and folders, on all cores. Finding the files, resolving each one's
// project, dialect and machine, checking and fixing it is the project layer's
// (project/walk.hpp, project/check.hpp); this file parses the arguments and prints.
#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "analyzer/baseline.hpp"
#include "analyzer/output.hpp"
#include "cli/commands.hpp"
#include "cli/dry_run.hpp"
#include "cli/progress.hpp"
#include "project/check.hpp"
#include "project/parallel.hpp"
#include "project/walk.hpp"
#include "project/writer.hpp"

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
    bool verbose = false;
    std::string baseline;
    std::string write_baseline;
    unsigned jobs = 0;
    std::size_t max_findings_per_rule = 100;
    project::LimitSettings limits;
};

int list_rules(const CheckOptions& o) {
    const an::Registry& rules = an::builtin_rules();
    std::cout << (o.format == "markdown" ? an::format_rules_markdown(rules) : an::format_rule_list(rules));
    return kExitClean;
}

std::optional<std::vector<an::BaselineEntry>> load_baseline(const std::string& path) {
    const project::ReadResult read = project::DiskFileSystem().read(path);
    if (!read.text) {
        std::cerr << "kerf: " << read.error << "\n";
        return std::nullopt;
    }
    std::string error;
    auto entries = an::read_baseline(*read.text, error);
    if (!entries) std::cerr << fmt::format("kerf: {}: {}\n", path, error);
    return entries;
}

// Drops the findings the baseline accepts (in file order, so the result does not depend on threads).
void apply_baseline(std::vector<project::CheckedFile>& checked, const std::vector<an::BaselineEntry>& entries) {
    an::BaselineFilter filter(entries);
    for (project::CheckedFile& c : checked) {
        an::FileReport& r = c.report;
        an::FileReport kept;
        kept.name = r.name;
        for (std::size_t i = 0; i < r.findings.size(); ++i) {
            if (filter.accepts(c.keys[i])) continue;
            kept.findings.push_back(std::move(r.findings[i]));
            kept.locations.push_back(r.locations[i]);
            kept.utf16.push_back(r.utf16[i]);
            kept.excerpts.push_back(std::move(r.excerpts[i]));
        }
        r = std::move(kept);
    }
}

// The files a walk left out, with the reason, on stderr (--verbose).
void print_skipped(const std::vector<project::SkippedFile>& skipped) {
    for (const project::SkippedFile& s : skipped) std::cerr << fmt::format("{}: skipped: {}\n", s.path.string(), s.reason);
}

void print(const std::vector<an::FileReport>& reports, const CheckOptions& o, std::size_t files, std::size_t fixed,
           std::size_t skipped) {
    if (o.format == "json") std::cout << an::format_json(reports, files);
    else if (o.format == "sarif") std::cout << an::format_sarif(reports, an::builtin_rules());
    else {
        const bool color = ::isatty(STDOUT_FILENO) && !std::getenv("NO_COLOR");
        std::cout << an::format_human(reports, color);
        const an::Counts c = an::count(reports);
        std::cout << fmt::format("{} error(s), {} warning(s), {} info, {} hint(s) in {} file(s) checked{}{}\n", c.error,
                                 c.warning, c.info, c.hint, files, fixed ? fmt::format("; {} fix(es) applied", fixed) : "",
                                 skipped ? fmt::format("; {} file(s) skipped{}", skipped, o.verbose ? " (listed on stderr)" : " (--verbose lists them)") : "");
    }
}

int run_check(const CheckOptions& o) {
    if (o.list_rules) return list_rules(o);
    if (o.paths.empty()) {
        std::cerr << "kerf: check needs a file or folder (or --list-rules)\n";
        return kExitUsage;
    }
    std::optional<std::vector<an::BaselineEntry>> baseline;
    if (!o.baseline.empty() && !(baseline = load_baseline(o.baseline))) return kExitUsage;
    project::Workspace workspace(std::make_shared<project::DiskFileSystem>(),
                                 overrides_of(o.dialect, o.dialect_files, o.machine_file, o.limits));
    const project::WalkResult sources =
        project::collect_program_files({o.paths.begin(), o.paths.end()}, workspace.files(), workspace.check_selector());
    int code = kExitClean;
    for (const std::string& e : sources.errors) std::cerr << "kerf: " << e << "\n", code = kExitUsage;
    if (o.verbose) print_skipped(sources.skipped);
    std::vector<project::CheckedFile> checked(sources.files.size());
    ProblemPrinter problems;
    ProgressBar bar("kerf check");
    project::CheckSettings settings;
    settings.fix = o.fix;
    // A baseline records every finding: no cap then.
    settings.max_findings_per_rule = o.write_baseline.empty() ? o.max_findings_per_rule : 0;
    project::run_parallel(sources.files.size(), o.jobs, [&](std::size_t i) {
        checked[i] = project::check_file(workspace, sources.files[i], settings);
        problems.print(checked[i].problems);
    }, [&](std::size_t done, std::size_t total) { bar.update(done, total); });
    std::vector<an::BaselineEntry> all_keys;
    for (const project::CheckedFile& c : checked) all_keys.insert(all_keys.end(), c.keys.begin(), c.keys.end());
    if (baseline) apply_baseline(checked, *baseline);
    std::vector<an::FileReport> reports;
    std::size_t files = 0, fixed = 0;
    for (project::CheckedFile& c : checked) {
        if (project::has_errors(c.problems)) code = kExitUsage;
        if (!c.checked) continue;   // a file checked whose fixes could not be written keeps its report
        ++files;
        fixed += c.fixed;
        if (!c.report.findings.empty()) reports.push_back(std::move(c.report));
    }
    print(reports, o, files, fixed, sources.skipped.size());
    if (!o.write_baseline.empty())
        if (const auto error = project::write_atomically(o.write_baseline, an::write_baseline(all_keys)))
            std::cerr << fmt::format("{}: error: {}\n", o.write_baseline, *error), code = kExitUsage;
    if (code == kExitClean && an::count(reports).error > 0) code = kExitFindings;
    return code;
}

}  // namespace

Command add_check_command(CLI::App& app) {
    auto o = std::make_shared<CheckOptions>();
    CLI::App* cmd = app.add_subcommand("check", "lint programs: rules with stable ids (kerf check --list-rules)");
    cmd->add_option("paths", o->paths, "files and folders (folders recursively; programs recognised by content)");
    cmd->add_option("--dialect", o->dialect, "dialect id, or auto (default: .kerf.toml, then the header, then detection)");
    cmd->add_option("--dialect-file", o->dialect_files, "load a dialect data file (TOML)");
    cmd->add_option("--machine", o->machine_file, "machine configuration file (TOML, machine/SCHEMA.md)");
    cmd->add_option("--format", o->format, "human (default), json, sarif; with --list-rules also markdown")
        ->check(CLI::IsMember({"human", "json", "sarif", "markdown"}));
    cmd->add_flag("--fix", o->fix, "apply the safe fixes in place (atomically), then report what is left");
    cmd->add_flag("--verbose,-v", o->verbose, "list the files a folder walk skipped, with the reason (stderr)");
    cmd->add_option("--baseline", o->baseline, "accept the findings listed in this baseline file");
    cmd->add_option("--write-baseline", o->write_baseline, "write all findings of this run as a baseline file");
    cmd->add_flag("--list-rules", o->list_rules, "print the rules: id, name, default severity, category");
    cmd->add_option("--jobs,-j", o->jobs, "threads (default: all cores)");
    cmd->add_option("--max-findings-per-rule", o->max_findings_per_rule,
                    "show at most this many findings of a rule per file, then 'and N more' (default 100; 0 = all)");
    add_limit_options(*cmd, o->limits);
    return [o] { return run_check(*o); };
}

}  // namespace kerf::cli
