// What `kerf run` and `kerf plot` share on the command line: the options (FILE, --dialect,
// --dialect-file, --machine, --lenient), preparing the run through the project layer
// (project/dry_run.hpp) with its problems printed, and the alarms printed after it.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "cli/limits.hpp"
#include "project/dry_run.hpp"

namespace kerf::cli {

struct DryRunOptions {
    std::string file;
    std::string dialect = "auto";
    std::vector<std::string> dialect_files;
    std::string machine_file;   // "" = .kerf.toml's `machine`, else the dialect's built-in machine
    bool lenient = false;
    project::LimitSettings limits;   // --max-file-bytes, --max-line-bytes, --time-limit
    std::string call;                // --call "G65 P9010 A1.": the caller's block (project/start.hpp)
    std::vector<std::string> set;    // --set "#100=5"
    int passes = 0;                  // --passes N (0: [run] passes, else 1)
};

// FILE, --dialect, --dialect-file, --machine, --lenient, --call, --set, --passes and the limits
// (cli/limits.hpp).
void add_dry_run_options(CLI::App& command, DryRunOptions& options);

// The flags as the workspace's overrides.
project::Overrides overrides_of(const std::string& dialect, const std::vector<std::string>& dialect_files,
                                const std::string& machine_file, const project::LimitSettings& limits = {});

// The prepared run, or the exit code to return (the reasons are on stderr already): 2 for a file
// that cannot be read, an unknown dialect or a bad .kerf.toml or machine file; 1 for a file
// without a program.
std::variant<std::unique_ptr<project::DryRun>, int> prepare(const DryRunOptions& options);

// Alarms on stderr as `file:line: error: alarm N: text`; the exit code: 0 without alarms, 1 with.
// A strict run that stopped where a lenient one goes on (a code the dialect does not have, a block
// with syntax errors) says how to go past it.
int report_alarms(const project::DryRun& run, const interpreter::RunResult& result, bool lenient);

}  // namespace kerf::cli
