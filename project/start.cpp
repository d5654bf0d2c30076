#include "project/start.hpp"

#include <fmt/format.h>

namespace kerf::project {

namespace {

// The program the caller's file calls: the first G65/G66 P or M98 P of its blocks.
std::optional<std::int64_t> called_program(const interpreter::LoadedFile& caller) {
    const ast::TypedFile* typed = caller.whole_typed();
    if (!typed) return std::nullopt;
    for (std::size_t b = 0; b < typed->tree().blocks.size(); ++b) {
        const ast::BlockView view = typed->block(b);
        if (const auto call = view.macro_call(); call && call->program) return call->program;
        if (const auto call = view.subprogram_call()) return call->program;
    }
    return std::nullopt;
}

bool holds_program(const interpreter::ProgramSet& programs, std::uint32_t file, std::int64_t number) {
    const auto found = programs.find(number, file);
    return found && found->file == file;
}

}  // namespace

RunStart run_start(const RunSettings& settings, interpreter::ProgramSet& programs, std::uint32_t file,
                   const dialects::Dialect& dialect, const std::string& name) {
    RunStart start;
    start.main = programs.first_program(file);
    start.options.passes = settings.passes.value_or(1);
    for (const std::string& s : settings.set) {
        if (const auto assignment = parse_assignment(s)) start.options.preset.push_back(*assignment);
        else start.problems.push_back({Level::error, name, 0, 0, fmt::format("--set '{}': expected a variable and a number, such as \"#100=5\"", s)});
    }
    if (!settings.call) return start;
    // The caller is a program of its own: its block, then M30 (the run ends when the call returns).
    const std::string caller_name = fmt::format("(caller: {})", *settings.call);
    const std::uint32_t caller = programs.add(caller_name, *settings.call + "\nM30\n", dialect);
    const std::optional<std::int64_t> called = called_program(programs.file(caller));
    const interpreter::LoadedFile& loaded = programs.file(caller);
    if (!called || loaded.whole_tree()->diagnostics.size() > 0) {
        start.problems.push_back({Level::error, name, 0, 0,
                                  fmt::format("--call '{}': expected a block that calls a program, such as \"G65 P9010 A1. B2.\" "
                                              "(G65/G66 P, M98 P)", *settings.call)});
        return start;
    }
    if (!settings.call_everywhere && !holds_program(programs, file, *called)) return start;   // another program's caller
    start.main = programs.first_program(caller);
    start.called = called;
    return start;
}

std::function<bool(std::int64_t)> resident_programs(const ProgramSettings& programs) {
    if (programs.resident.empty()) return {};
    return [programs](std::int64_t n) { return programs.resident_contains(n); };
}

}  // namespace kerf::project
