#include "cli/dry_run.hpp"

#include <fmt/format.h>

#include <iostream>

#include "ast/display.hpp"
#include "dialects/alarms.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"

namespace kerf::cli {

void add_dry_run_options(CLI::App& command, DryRunOptions& o) {
    command.add_option("file", o.file, "program file")->required();
    command.add_option("--dialect", o.dialect, "dialect id, or auto (default: .kerf.toml, then the header, then detection)");
    command.add_option("--dialect-file", o.dialect_files, "load a dialect data file (TOML)");
    command.add_option("--machine", o.machine_file, "machine configuration file (TOML, machine/SCHEMA.md)");
    command.add_flag("--lenient", o.lenient, "run blocks with syntax errors without their defective words");
    command.add_option("--call", o.call,
                       "run the program as this block calls it: --call \"G65 P9010 A1. B2.\" (a macro with its arguments)");
    command.add_option("--set", o.set, "set a macro variable before the run: --set \"#100=5\" (repeatable)");
    command.add_option("--passes", o.passes,
                       "passes of a main program that ends in M99 (a bar-feed loop; default 1, or .kerf.toml [run] passes)")
        ->check(CLI::Range(1, 1000000));
    add_limit_options(command, o.limits);
}

project::Overrides overrides_of(const std::string& dialect, const std::vector<std::string>& dialect_files,
                                const std::string& machine_file, const project::LimitSettings& limits) {
    project::Overrides o;
    o.limits = limits;
    o.dialect = dialect;
    o.dialect_files.assign(dialect_files.begin(), dialect_files.end());
    o.machine = machine_file;
    return o;
}

std::variant<std::unique_ptr<project::DryRun>, int> prepare(const DryRunOptions& o) {
    project::Overrides overrides = overrides_of(o.dialect, o.dialect_files, o.machine_file, o.limits);
    if (!o.call.empty()) overrides.run.call = o.call;
    overrides.run.call_everywhere = true;
    overrides.run.set = o.set;
    if (o.passes > 0) overrides.run.passes = o.passes;
    auto workspace = std::make_shared<project::Workspace>(std::make_shared<project::DiskFileSystem>(), std::move(overrides));
    project::PreparedRun prepared = project::prepare_dry_run(std::move(workspace), o.file);
    ProblemPrinter().print(prepared.problems);
    switch (prepared.outcome) {
        case project::PreparedRun::Outcome::ready: return std::move(prepared.run);
        case project::PreparedRun::Outcome::no_program: return kExitFindings;
        case project::PreparedRun::Outcome::unusable: break;
    }
    return kExitUsage;
}

namespace {

// Alarms a lenient run does not stop at (interpreter/executor.cpp: refuse_unknown_g_code, and the
// strict run's refusal of a block with syntax errors).
bool lenient_goes_past(const interpreter::Event& alarm) {
    return alarm.code == alarms::improper_command || alarm.code == alarms::syntax_error;
}

}  // namespace

int report_alarms(const project::DryRun& run, const interpreter::RunResult& result, bool lenient) {
    // The number the control shows: its own when the dialect numbers the alarm ([alarms]), else kerf's.
    for (const interpreter::Event& a : result.alarms) {
        std::cerr << fmt::format("{}:{}: error: alarm {}: {}\n", run.programs.file(a.source.file).name(), a.source.line,
                                 a.control_alarm ? a.control_alarm : a.code,
                                 ast::printable(a.text));   // alarm texts quote the program (#3000, comments)
        if (!lenient && lenient_goes_past(a))
            std::cerr << "  = hint: if the program is for another control, name its dialect (--dialect; `kerf dialects` "
                         "lists them), or run past the block with --lenient\n";
    }
    return result.alarms.empty() ? kExitClean : kExitFindings;
}

}  // namespace kerf::cli
