// Two dry runs compared event for event: the proof behind `kerf fmt --verify` (the same program
// before and after formatting, one dialect) and `kerf convert --verify` (a program in one dialect
// and its conversion in another, each on its own dialect's reading of one machine description).
// The input runs on a thread of its own and hands its events over in batches through a bounded
// queue, so memory stays flat whatever the length of the trace (ARCHITECTURE.md "Bounded
// resources"). Two endless programs are compared up to the first alarm of a run bound (step, move
// or time limit): where a bound strikes depends on the block count and the clock, not the program.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "dialects/dialect.hpp"
#include "interpreter/interpreter.hpp"

namespace kerf::interpreter {

// What the comparison looks at.
enum class CompareProfile {
    // Every event: kinds, codes, tools, texts (but alarm and call texts, which quote sequence
    // numbers), start, end, machine position, centre, radius, length, time, feed and feed mode,
    // spindle speed; relative tolerance (the formatter: nothing but the text changes).
    everything,
    // What a conversion keeps (issue 16): only motion (rapid, linear, arcs, threads), dwells and
    // alarms; per motion its kind, end, centre, machine position (absolute tolerance), feed
    // (relative 1e-6) and feed mode; per dwell its time; per alarm its number. Codes and texts name
    // codes in each dialect's spelling and M-code events differ by number between controls.
    motion,
};

struct CompareOptions {
    CompareProfile profile = CompareProfile::everything;
    double tolerance = 1e-9;   // everything: relative; motion: absolute, in program units (mm or inch)
};

// One side of the comparison: a program text and how to run it.
struct TraceSide {
    std::string name;
    std::string text;
    const dialects::Dialect* dialect = nullptr;
    Setup setup;
    ProgramSet::Loader loader;   // subprograms from elsewhere; may be empty
};

struct TraceDifference {
    std::size_t event = 0;          // index of the first compared event that differs (or the shorter count)
    std::uint32_t input_line = 0;   // 1-based source lines of that event, 0 when there is none
    std::uint32_t output_line = 0;
    std::string what;               // "end X: 10 vs 10.5", "kind: linear vs rapid", "the output has fewer events ..."
    std::string input_file;         // the file of each side's event (a subprogram's file when it came from one)
    std::string output_file;
    std::uint32_t input_file_index = 0, output_file_index = 0;   // in each side's ProgramSet
};

struct TraceComparison {
    std::size_t events = 0;                     // compared events of the input's run
    std::optional<TraceDifference> difference;  // nullopt: the traces agree
    // The program's alarm both runs stopped at, equal in both (the input's event): what follows it
    // in the program was not run, so not compared. nullopt when the runs ended otherwise (M30, the
    // end of the program, a run bound) or differ.
    std::optional<Event> stopped_at;
};

// Runs both sides from their first program and compares the traces.
TraceComparison compare_runs(TraceSide input, TraceSide output, const CompareOptions& options,
                             const RunOptions& run = {});

// The first difference between two events under `options`, or nullopt.
std::optional<std::string> compare_events(const Event& a, const Event& b, const CompareOptions& options);

// Whether `options` compares events of this kind at all.
bool compared_kind(EventKind kind, CompareProfile profile);

}  // namespace kerf::interpreter
