// The analyzer: every enabled rule over one file, static rules in one pass over its blocks, the
// parser's diagnostics mapped to rules, and one dry run (lenient: a block with a syntax error runs
// without its defective words, the syntax rules report it) whose events go to the dynamic rules
// and whose alarms become findings. Then inline suppressions, configured severities, one finding
// per rule and line, sorted by position, at most CheckOptions::max_findings_per_rule per rule. Pure: no I/O (the program set's loader is the caller's).
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <optional>
#include <vector>

#include "analyzer/config.hpp"
#include "analyzer/finding.hpp"
#include "analyzer/registry.hpp"
#include "interpreter/interpreter.hpp"
#include "interpreter/program_set.hpp"
#include "interpreter/setup.hpp"
#include "interpreter/sink.hpp"

namespace kerf::analyzer {

// A program of another control, as detection found it (grammar/detect.hpp Detection::Foreign): the
// check reports that once (K2009 foreign-control) instead of reading the file as FANUC.
struct ForeignControl {
    std::string id, name;
    std::uint32_t line = 0, column = 0;   // 1-based, where the evidence first shows (0: the whole file)
    std::string evidence;                 // what shows it there ("a line starting with '%@MACRO'")
    std::string proves;
};

struct CheckOptions {
    const Registry* registry = nullptr;   // nullptr: builtin_rules()
    CheckConfig config;
    bool dry_run = true;                  // run the interpreter for the dynamic rules
    // Files of this size or more run the dry run on a second thread beside the static rules.
    std::size_t parallel_from_bytes = std::size_t{1} << 20;
    // The other files that hold program O`number`, in the order a call reaches them (the program
    // index, project/index.hpp); empty or unset: not known (K3010 stays silent).
    std::function<std::vector<std::string>(std::int64_t number)> program_files;
    // At most this many findings per rule and file; the rest become one "and N more" finding of
    // severity info (0 = all). Bounds the output and the memory whatever the file.
    std::size_t max_findings_per_rule = 100;
    std::chrono::milliseconds time_limit{0};   // of the dry run (interpreter RunOptions::time_limit)
    std::optional<ForeignControl> foreign;     // detection found another control's program
    // Programs resident in the machine (.kerf.toml [programs] resident): no K3003 for calls into
    // them, and the dry run skips them with a message (interpreter RunOptions::resident).
    std::function<bool(std::int64_t)> resident;
    // The argument letters the callers found by the program index pass to program O`number` (as local
    // variable numbers, #1 A ... #26 Z); empty or unset: no caller known (K4001).
    std::function<std::vector<int>(std::int64_t number)> caller_arguments;
    // How the dry run starts (project/start.hpp): its passes and preset variables (the analyzer
    // sets lenient, time_limit and emit_state), and the main program when it is not the file's
    // first (a caller's block: a macro run as it is used).
    interpreter::RunOptions run;
    std::optional<interpreter::ProgramRef> main;
};

// Checks file `file` of `programs` (its first program is run as the main program).
std::vector<Finding> check_file(interpreter::ProgramSet& programs, std::uint32_t file, const dialects::Dialect& dialect,
                                const interpreter::Setup& setup, const CheckOptions& options = {});

// The phases of check_file, apart for the language server, which publishes the static findings at
// once and the dry run's when it has finished (issue 14). Raw findings: finish_findings makes them
// what check_file returns.

// When `options.foreign` says the file is another control's program: its one finding (K2009), and
// nothing else is checked (check_file returns it as it is). nullopt: check the file.
std::optional<std::vector<Finding>> check_foreign(const interpreter::ProgramSet& programs, std::uint32_t file,
                                                  const CheckOptions& options);

// The static rules and the parser's and binder's diagnostics. `program_exists` answers K3003
// (does a called program exist); empty: this file, then the program set's loader.
// `cancel`, once set, stops the walk at the next program or 4096 blocks (the result is then partial).
std::vector<Finding> check_static(const interpreter::ProgramSet& programs, std::uint32_t file, const dialects::Dialect& dialect,
                                  const interpreter::Setup& setup, const CheckOptions& options,
                                  std::function<bool(std::int64_t)> program_exists = {},
                                  const std::atomic<bool>* cancel = nullptr);

struct DryRunHooks {
    interpreter::EventSink* observer = nullptr;   // also sees every event of the run (with state events)
    bool emit_state = false;                       // RunOptions::emit_state, for the observer only
    decltype(interpreter::RunOptions::after_block) after_block;   // RunOptions::after_block
    const std::atomic<bool>* cancel = nullptr;     // once set, the run stops before its next block (RunOptions::cancel)
};
// The dry run's findings (dynamic rules and alarms); nullopt when `hooks.cancel` stopped it.
std::optional<std::vector<Finding>> check_dry_run(interpreter::ProgramSet& programs, std::uint32_t file,
                                                  const dialects::Dialect& dialect, const interpreter::Setup& setup,
                                                  const CheckOptions& options, const DryRunHooks& hooks = {});

// Inline suppressions, configured severities, one finding per rule and line, sorted by position.
void finish_findings(std::vector<Finding>& findings, const ast::SyntaxTree& tree, const ast::LineIndex& lines,
                     const CheckOptions& options);

// Convenience for tests and the language server: `text` alone (no other files).
std::vector<Finding> check_text(std::string name, std::string text, const dialects::Dialect& dialect,
                                const interpreter::Setup& setup, const CheckOptions& options = {});

// `range` without the trailing blanks and line break (a block's range ends after its newline).
ast::Range trim_range(const ast::SyntaxTree& tree, ast::Range range);

}  // namespace kerf::analyzer
