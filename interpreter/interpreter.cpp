// The block loop and the order of actions inside a block (reference/semantics.md §1.2):
//   1. statements (macro B), 2. F S T, 3. M codes before motion, 4. modal G codes,
//   5. coordinate-system operations, 6. (compensation: issue 4), 7. motion, 8. dwell,
//   9. M codes after motion, calls and returns.
#include "interpreter/interpreter.hpp"

#include <fmt/format.h>

#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

RunResult run(ProgramSet& programs, ProgramRef main, const dialects::Dialect& dialect, const Setup& setup,
              EventSink& sink, const RunOptions& options) {
    Executor executor(programs, dialect, setup, sink, options);
    return executor.run(main);
}

}  // namespace kerf::interpreter
