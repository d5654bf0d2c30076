// How a dry run of a file starts, as `.kerf.toml [run]` and `kerf run --call/--set/--passes` say
// (docs/config.md): the passes of a bar-feed M99 loop, the variables set before the first block,
// and for a macro run as it is used, a caller's block as the main program. Pure: the program set
// is given; nothing is read.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dialects/dialect.hpp"
#include "interpreter/interpreter.hpp"
#include "project/config.hpp"
#include "project/problem.hpp"

namespace kerf::project {

struct RunStart {
    std::optional<interpreter::ProgramRef> main;   // nullopt: the file holds no program to run
    interpreter::RunOptions options;               // passes and preset variables (the rest: defaults)
    std::optional<std::int64_t> called;            // the program the caller's block calls, when one is used
    std::vector<Problem> problems;
};

// The start of a run of file `file` (its index in `programs`; `name` its path for problems). The
// caller's block (`settings.call`) becomes the main program, a file of its own added to
// `programs`, when the program it calls is in this file, or always when `settings.call_everywhere`
// (the command line's --call); else the file's first program is the main program.
RunStart run_start(const RunSettings& settings, interpreter::ProgramSet& programs, std::uint32_t file,
                   const dialects::Dialect& dialect, const std::string& name);

// The programs the machine keeps in memory ([programs] resident) as the interpreter asks for them
// (RunOptions::resident: a call to one the run cannot find is said and skipped); empty when the
// project lists none. kerf run, plot, check and fmt --verify take the same (issue 15).
std::function<bool(std::int64_t)> resident_programs(const ProgramSettings& programs);

}  // namespace kerf::project
