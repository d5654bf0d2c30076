// A dry run of a program file, prepared as `kerf run` and `kerf plot` need it: the file mapped and
// read in pieces as the run reaches them (interpreter/loaded_file.hpp), its project, dialect and
// Setup resolved by the workspace, subprograms and macros reached through the program index.
// Problems come back as values; the caller prints them.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "interpreter/interpreter.hpp"
#include "project/mapped_file.hpp"
#include "project/start.hpp"
#include "project/workspace.hpp"

namespace kerf::project {

// Everything a run needs. Held by pointer: `dialect` and the program set's loader point into it.
struct DryRun {
    std::shared_ptr<Workspace> workspace;   // the program set's loader reads through it
    std::shared_ptr<const Project> project;
    const dialects::Dialect* dialect = nullptr;
    DialectChoice choice;
    std::unique_ptr<MappedFile> source;   // the main file (outlives `programs`)
    interpreter::ProgramSet programs;
    interpreter::ProgramRef main;
    interpreter::Setup setup;
    interpreter::RunOptions options;   // passes and preset variables (project/start.hpp)
};

struct PreparedRun {
    enum class Outcome {
        ready,        // `run` is set
        unusable,     // the file cannot be read, the dialect is unknown, the machine file is bad (exit 2)
        no_program,   // the file holds no program to run (exit 1)
    };
    Outcome outcome = Outcome::unusable;
    std::unique_ptr<DryRun> run;
    std::vector<Problem> problems;   // warnings too, also when ready
};

PreparedRun prepare_dry_run(std::shared_ptr<Workspace> workspace, const std::filesystem::path& file);

// The run's options: `lenient` (run blocks with syntax errors without their defective words),
// `emit_state` (a state event after every block).
interpreter::RunResult execute(DryRun& run, interpreter::EventSink& sink, bool lenient, bool emit_state = false);

}  // namespace kerf::project
