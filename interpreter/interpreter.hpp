// The reference interpreter: dry-runs a program as the control would and emits the trace to a sink.
// Dialect differences come from the dialect tables (codes are dispatched by function id) and
// machine differences from the Setup; the interpreter does no I/O.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "dialects/dialect.hpp"
#include "interpreter/macro/evaluate.hpp"
#include "interpreter/program_set.hpp"
#include "interpreter/setup.hpp"
#include "interpreter/sink.hpp"

namespace kerf::interpreter {

struct RunOptions {
    bool block_delete = true;   // the block-delete switch: '/' blocks are skipped
    bool stop_at_m00 = false;   // a dry run goes on past M00/M01 (they are events)
    // A block with syntax errors stops the control (an alarm). Lenient: run it without its defective
    // words and say so in a message event — for reading damaged listings like the seeds.
    bool lenient = false;
    bool emit_state = false;    // a `state` event after every executed block (hovers, debugging)
    // Called after every executed block that ran to its end (no call, jump or alarm in it) with the
    // macro variables as they are then and the options the block's addresses were evaluated with:
    // the language server shows a variable's value and an expression's value at their block. It
    // reads only (evaluate takes the variables by reference for the system variables' sake).
    std::function<void(const SourceRef& block, macro::Variables& variables, const macro::Options& options)> after_block;
    // Wall-clock bound of the run (interpreter/run_guard.hpp): past it the run stops with alarm
    // kerf_alarm::time_limit. 0 = none (the library default: runs stay deterministic; the CLI sets one).
    std::chrono::milliseconds time_limit{0};
    // Programs the machine keeps in its memory (.kerf.toml [programs] resident): a call to one the
    // run cannot find is skipped with a message instead of alarm 078 (issue 15). Empty: none.
    std::function<bool(std::int64_t)> resident;
    // M99 in the main program is the bar-feeder loop: the control starts the program again
    // (dialects.md §3.6). A dry run runs this many passes and ends with a note (RunResult::repeats);
    // times are for the passes run. At least 1.
    std::int64_t passes = 1;
    // Macro variables set before the first block (`kerf run --set "#100=5"`, .kerf.toml [run] set):
    // the values a shop's common variables hold when the program is started.
    std::vector<std::pair<int, double>> preset;
    // Cancellation: once another thread sets the flag, the run stops before its next block
    // (RunResult::cancelled). The language server cancels the run of an older version of a document.
    const std::atomic<bool>* cancel = nullptr;
    // Run to a block: the run stops after the first execution of the block of file `file` (an index
    // of the ProgramSet) that starts at byte `begin` (RunResult::reached_block). A block that
    // calls stops after the call is made, a jump after it jumps.
    struct BlockAt {
        std::uint32_t file = 0;
        std::uint32_t begin = 0;
    };
    std::optional<BlockAt> run_to;
};

struct RunResult {
    Position final_position{};          // work coordinates, lathe X as diameter
    double total_time_s = 0;
    double feed_distance_mm = 0;
    double rapid_distance_mm = 0;
    std::map<int, double> time_per_tool_s;
    std::vector<int> tools;             // in the order they were first used
    std::vector<Event> alarms;
    std::uint64_t blocks = 0;           // blocks executed (the step count)
    bool completed = false;             // reached M30/M02 (or the end) without an alarm
    // The main program ended its last pass with M99: the control would start it again
    // (RunOptions::passes). `completed` is true too.
    bool repeats = false;
    std::int64_t passes = 1;            // passes of the main program run (M99 loops)
    // Work positions (final_position) are in the program's unit at the end: inches when this is
    // set (G20, C: G70); distances and times are always mm and s.
    bool inch = false;
    bool cancelled = false;             // RunOptions::cancel stopped the run (the result is partial)
    bool reached_block = false;         // RunOptions::run_to: the run stopped after that block
};

RunResult run(ProgramSet& programs, ProgramRef main, const dialects::Dialect& dialect, const Setup& setup,
              EventSink& sink, const RunOptions& options = {});

}  // namespace kerf::interpreter
