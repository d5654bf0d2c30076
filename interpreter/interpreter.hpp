// The reference interpreter: dry-runs a program as the control would and emits the trace to a sink.
// Dialect differences come from the dialect tables (codes are dispatched by function id) and
// machine differences from the Setup; the interpreter does no I/O.
#pragma once

#include <chrono>
#include <functional>
#include <cstdint>
#include <map>
#include <vector>

#include "dialects/dialect.hpp"
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
    // Wall-clock bound of the run (interpreter/run_guard.hpp): past it the run stops with alarm
    // kerf_alarm::time_limit. 0 = none (the library default: runs stay deterministic; the CLI sets one).
    std::chrono::milliseconds time_limit{0};
    // Programs the machine keeps in its memory (.kerf.toml [programs] resident): a call to one the
    // run cannot find is skipped with a message instead of alarm 078 (issue 15). Empty: none.
    std::function<bool(std::int64_t)> resident;
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
};

RunResult run(ProgramSet& programs, ProgramRef main, const dialects::Dialect& dialect, const Setup& setup,
              EventSink& sink, const RunOptions& options = {});

}  // namespace kerf::interpreter
