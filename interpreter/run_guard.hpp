// The bounds of one dry run (ARCHITECTURE.md "Bounded resources"): the blocks it executes
// (Setup::step_limit), the moves it emits (Setup::move_limit: one block may expand into any
// number of moves, a peck cycle with a tiny peck over a long stroke into millions) and the
// wall-clock time it takes (RunOptions::time_limit). Each ends the run with an alarm of kerf's own
// number (events.hpp kerf_alarm), so no input keeps a command busy however it loops.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace kerf::interpreter {

struct LimitAlarm {
    int number = 0;     // kerf_alarm::step_limit, move_limit or time_limit
    std::string text;
};

class RunGuard {
public:
    RunGuard(std::uint64_t step_limit, std::uint64_t move_limit, std::chrono::milliseconds time_limit);
    // Before a block runs; `blocks` counts it.
    std::optional<LimitAlarm> block(std::uint64_t blocks);
    // After a motion event.
    std::optional<LimitAlarm> move();
    // Work without events (any other event, a cycle step that did not move): the clock only.
    std::optional<LimitAlarm> tick();

private:
    std::uint64_t step_limit_;
    std::uint64_t move_limit_;
    std::chrono::milliseconds time_limit_;
    std::chrono::steady_clock::time_point deadline_;
    std::uint64_t moves_ = 0;
    std::uint32_t until_clock_ = 0;   // ticks until the clock is read again (it costs ~20 ns)
};

}  // namespace kerf::interpreter
