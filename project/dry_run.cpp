#include "project/dry_run.hpp"

#include <fmt/format.h>

namespace kerf::project {

namespace fs = std::filesystem;

namespace {

// Hooks the mapped program up as a stream (the run parses it piece by piece and the pages of
// parsed pieces are dropped: memory stays flat however long the file), the loader of the program
// index, and finds the main program: the file's first, or the caller's block of [run] call /
// --call (project/start.hpp), with the run's passes and preset variables.
bool load_program(DryRun& run, Workspace& workspace, const fs::path& file, std::vector<Problem>& problems) {
    interpreter::StreamOptions stream;
    stream.read_ahead = true;   // the grammar on the second core (bench/RESULTS.md)
    stream.release = [source = run.source.get()](std::size_t begin, std::size_t end) { source->release(begin, end); };
    const std::uint32_t main_file = run.programs.add_stream(file.string(), run.source->text(), *run.dialect, stream);
    run.programs.set_loader(workspace.loader_for(file), run.dialect);
    RunStart start = run_start(run.project->run_settings(), run.programs, main_file, *run.dialect, file.string());
    problems.insert(problems.end(), start.problems.begin(), start.problems.end());
    if (!start.main) return false;
    run.main = *start.main;
    run.options = std::move(start.options);
    run.options.resident = resident_programs(run.project->config().programs);
    return true;
}

}  // namespace

PreparedRun prepare_dry_run(std::shared_ptr<Workspace> workspace, const fs::path& file) {
    PreparedRun prepared;
    // The project's limits decide which files the decoder refuses (ast/input.hpp).
    const ast::InputLimits limits = workspace->project_for(file)->limits().input;
    ReadResult failure;
    std::optional<MappedFile> source = MappedFile::open(file, limits, failure);
    if (!source) {
        prepared.problems = input_problems(file.string(), failure.problems);
        if (!has_errors(prepared.problems)) prepared.problems.push_back({Level::error, file.string(), 0, 0, "cannot open file"});
        return prepared;
    }
    std::vector<Problem> notes = input_problems(file.string(), source->input().problems);
    auto run = std::make_unique<DryRun>();
    run->source = std::make_unique<MappedFile>(std::move(*source));
    run->workspace = std::move(workspace);
    Resolved resolved = run->workspace->resolve(file, run->source->text());
    prepared.problems = std::move(notes);
    prepared.problems.insert(prepared.problems.end(), resolved.problems.begin(), resolved.problems.end());
    if (!resolved.ok() || has_errors(prepared.problems)) return prepared;
    run->project = resolved.project;
    run->dialect = resolved.dialect;
    run->choice = std::move(resolved.choice);
    run->setup = *resolved.setup;
    const bool loaded = load_program(*run, *run->workspace, file, prepared.problems);
    if (has_errors(prepared.problems)) return prepared;
    if (!loaded) {
        prepared.problems.push_back({Level::error, file.string(), 0, 0, "no program to run"});
        prepared.outcome = PreparedRun::Outcome::no_program;
        return prepared;
    }
    prepared.run = std::move(run);
    prepared.outcome = PreparedRun::Outcome::ready;
    return prepared;
}

interpreter::RunResult execute(DryRun& run, interpreter::EventSink& sink, bool lenient, bool emit_state) {
    interpreter::RunOptions options = run.options;
    options.lenient = lenient;
    options.emit_state = emit_state;
    options.time_limit = run.project->limits().time_limit;
    return interpreter::run(run.programs, run.main, *run.dialect, run.setup, sink, options);
}

}  // namespace kerf::project
