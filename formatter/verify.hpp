// The formatter's proof: the interpreter runs the program before and after formatting and the two
// traces must be the same event for event (the comparison is interpreter/trace_compare.hpp, which
// `kerf convert --verify` shares) — same kinds, codes, tools and texts, positions, centres,
// lengths, times, feeds and speeds equal to 1e-9 (issue 6, "meaning-preserving"). Events carry
// source lines, which formatting may move, so sources are not compared; alarm and call texts quote
// sequence numbers, which renumbering changes, so their codes are compared instead. Two endless
// programs are compared up to the first alarm of a run bound (step, move or time limit: blank lines
// count as steps, and the clock runs differently in two runs).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "dialects/dialect.hpp"
#include "interpreter/interpreter.hpp"

namespace kerf::formatter {

struct VerifyOptions {
    const dialects::Dialect* dialect = nullptr;
    interpreter::Setup setup;
    interpreter::RunOptions run;
    interpreter::ProgramSet::Loader loader;   // subprograms from elsewhere (the CLI: the file's folder); may be empty
};

struct Difference {
    std::size_t event = 0;          // index of the first event that differs (or the shorter count)
    std::uint32_t input_line = 0;   // 1-based source lines of that event, 0 when there is none
    std::uint32_t output_line = 0;
    std::string what;               // "end X: 10 vs 10.5", "kind: linear vs rapid", "event count: 12 vs 11"
};

// The program's alarm both runs stopped at: the blocks after it were not run, so not verified.
struct AlarmStop {
    std::uint32_t line = 0;   // 1-based, in the input
    int number = 0;           // as the control shows it (Event::control_alarm, else the code)
    std::string text;
};

struct VerifyResult {
    std::size_t events = 0;                 // events of the input's run that were read
    std::optional<Difference> difference;   // nullopt: the traces are equal
    std::optional<AlarmStop> stopped_at;    // equal traces that end at an alarm of the program
};

// Runs `input` and `output` (the same program before and after formatting) from their first
// program and compares the traces.
VerifyResult verify(const std::string& name, std::string input, std::string output, const VerifyOptions& options);

// The first difference between two events, or nullopt. Exposed for the tests.
std::optional<std::string> compare_events(const interpreter::Event& a, const interpreter::Event& b);

}  // namespace kerf::formatter
