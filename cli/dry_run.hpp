// What `kerf run` and `kerf plot` share: the options, reading the program, choosing the dialect
// (--dialect, then .kerf.toml, then detection) and the machine (--machine, then .kerf.toml, then
// the dialect's built-in one), the folder loader for subprograms, running the interpreter and
// reporting its alarms. Problems are printed to stderr here, as `kerf run` always did.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string_view>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "cli/config.hpp"
#include "cli/mapped_file.hpp"
#include "interpreter/interpreter.hpp"

namespace kerf::cli {

struct DryRunOptions {
    std::string file;
    std::string dialect = "auto";
    std::vector<std::string> dialect_files;
    std::string machine_file;   // "" = .kerf.toml's `machine`, else the dialect's built-in machine
    bool lenient = false;
};

// The pieces `kerf fmt --verify` shares with the dry run:
// subprograms not in the file, from its folder (O1000, O1000.nc, 1000.nc);
std::optional<std::pair<std::string, std::string>> load_from_folder(const std::filesystem::path& folder, std::int64_t number);
// the dialect id: the flag unless "auto", else .kerf.toml's, else detection from the text;
std::string choose_dialect(const std::string& flag, const ProjectConfig& config, std::string_view text);
// the Setup of a machine file, or of the dialect's built-in machine for an empty path (errors on stderr).
std::optional<interpreter::Setup> setup_for(const std::filesystem::path& machine_file, const dialects::Dialect& dialect);

// FILE, --dialect, --dialect-file, --machine, --lenient.
void add_dry_run_options(CLI::App& command, DryRunOptions& options);

// Everything a run needs. Held by pointer: `dialect` and the program set's loader point into it.
struct DryRun {
    RegistryResult dialects;
    const dialects::Dialect* dialect = nullptr;
    std::string dialect_id;
    std::unique_ptr<MappedFile> source;   // the main file, read in pieces by the run (outlives `programs`)
    interpreter::ProgramSet programs;
    interpreter::ProgramRef main;
    interpreter::Setup setup;
    bool lenient = false;
};

// The prepared run, or the exit code to return (the reason is already on stderr): 2 for a file
// that cannot be read, an unknown dialect or a bad machine file; 1 for a file without a program.
std::variant<std::unique_ptr<DryRun>, int> prepare_dry_run(const DryRunOptions& options);

// emit_state: a `state` event after every block (RunOptions::emit_state).
interpreter::RunResult execute(DryRun& run, interpreter::EventSink& sink, bool emit_state = false);

// Alarms on stderr as `file:line: error: alarm N: text`; the exit code: 0 without alarms, 1 with.
int report_alarms(const DryRun& run, const interpreter::RunResult& result);

}  // namespace kerf::cli
