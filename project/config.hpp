// The one model of a .kerf.toml (docs/config.md): every key of the file, parsed from its text.
// Pure: it takes the text and the file's path (relative paths in the file are relative to its
// folder); finding and reading the file is the workspace's business (project/workspace.hpp).
//
// Strict, like the dialect and machine files: an unknown key, a value of the wrong type or a bad
// value is a Problem with file:line:col that names what is allowed; a misspelt key must not
// silently keep a default. Each table is read by the module that owns its meaning: [check] and
// [rules] by analyzer/config.hpp, [format] by formatter/style.hpp; the rest here.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "analyzer/config.hpp"
#include "ast/input.hpp"
#include "formatter/style.hpp"
#include "project/problem.hpp"

namespace kerf::project {

// A range of program numbers, "O9000-O9999" (or one number, "O9010").
struct ProgramRange {
    std::int64_t first = 0;
    std::int64_t last = 0;
    bool contains(std::int64_t number) const { return number >= first && number <= last; }
};

// "O9000-O9999", "9000-9999", "O9010", "o9000 - o9999"; nullopt for anything else (first > last,
// negative or over 99999999 too).
std::optional<ProgramRange> parse_program_range(std::string_view text);

// "#100=5", "#500 = -1.5": a variable and the value `kerf run --set` / [run] set gives it before the
// run; nullopt for anything else (an expression, a variable number outside 1..99999).
std::optional<std::pair<int, double>> parse_assignment(std::string_view text);

// [run]: how a dry run of the project's programs starts (`kerf run --call/--set/--passes` win).
struct RunSettings {
    std::optional<std::string> call;   // the caller's block, "G65 P9010 A1.": a macro run as it is used
    std::vector<std::string> set;      // common variables before the run, "#100=5"
    std::optional<int> passes;         // passes of a main program that ends in M99 (bar-feed loop)
    // The command line's --call: every file run starts with it (a .kerf.toml's call only runs the
    // files that hold the program it calls: project/start.hpp).
    bool call_everywhere = false;
};

// [programs]: where the program index looks beyond a file's own folder, and what the machine holds.
struct ProgramSettings {
    std::vector<std::filesystem::path> library;   // folders (absolute) whose programs calls can reach
    std::vector<ProgramRange> resident;           // programs kept in the machine's memory (issue 15's lint)
    bool resident_contains(std::int64_t number) const;
};

// [limits]: the bounds of every command on a file (ARCHITECTURE.md "Bounded resources"); the
// command line's --max-file-bytes, --max-line-bytes and --time-limit (Overrides::limits) win.
// nullopt = not set here.
struct LimitSettings {
    std::optional<std::uint64_t> max_file_bytes;   // refuse larger files (0 = no limit)
    std::optional<std::uint64_t> max_line_bytes;   // refuse files with a longer line (0 = no limit)
    std::optional<double> time_limit_s;            // stop a dry run after this many seconds (0 = none)
};

// A run still going after this many seconds stops with alarm 90005: far above any real program's
// dry run (a 100 MB CAM program runs in about a second), and below the patience of an editor or a
// CI job.
inline constexpr double kDefaultTimeLimitS = 10;

// The bounds in force: the decoder's input limits (ast/input.hpp) and the dry run's wall clock.
struct Limits {
    ast::InputLimits input;
    std::chrono::milliseconds time_limit{0};   // 0 = none
};

// `over` (the command line) over `under` (.kerf.toml) over the defaults.
Limits resolve_limits(const LimitSettings& over, const LimitSettings& under);

struct Config {
    std::filesystem::path file;    // the .kerf.toml; empty for the defaults (no file found)
    std::string dialect;           // "" when not set (or "auto"): the header, then detection
    std::vector<std::filesystem::path> dialect_files;   // absolute
    std::optional<std::filesystem::path> machine;        // absolute
    analyzer::CheckConfig check;
    formatter::Style format;
    RunSettings run;
    ProgramSettings programs;
    LimitSettings limits;

    // The folder of the .kerf.toml: relative paths and [check] globs start there.
    std::filesystem::path folder() const { return file.parent_path(); }
};

struct ConfigResult {
    Config config;                   // whatever could be read (bad values keep their defaults)
    std::vector<Problem> problems;   // in the order of the file
};

// `file` names the problems and anchors relative paths; it is not read.
ConfigResult parse_config(std::string_view toml_text, const std::filesystem::path& file);

// Every key of the file, for the unknown-key message and the documentation test (docs/config.md).
struct KeyInfo {
    std::string_view table;   // "" for the top level, "run", "programs", "limits", "check", "format"
    std::string_view key;
    std::string_view type;    // "string", "array of strings", "integer", "number", "table"
    std::string_view description;
};
std::span<const KeyInfo> config_keys();

}  // namespace kerf::project
