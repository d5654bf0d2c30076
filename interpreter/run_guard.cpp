#include "interpreter/run_guard.hpp"

#include <fmt/format.h>

#include "interpreter/events.hpp"

namespace kerf::interpreter {

namespace {
// The clock is read every this many ticks: a block or a move costs 0.1–5 µs, so the guard is
// late by a few milliseconds at most.
constexpr std::uint32_t kTicksPerClock = 1024;
}  // namespace

RunGuard::RunGuard(std::uint64_t step_limit, std::uint64_t move_limit, std::chrono::milliseconds time_limit)
    : step_limit_(step_limit), move_limit_(move_limit), time_limit_(time_limit),
      deadline_(std::chrono::steady_clock::now() + time_limit) {}

std::optional<LimitAlarm> RunGuard::block(std::uint64_t blocks) {
    if (blocks > step_limit_)
        return LimitAlarm{kerf_alarm::step_limit, fmt::format("step limit of {} blocks reached: endless loop?", step_limit_)};
    return tick();
}

std::optional<LimitAlarm> RunGuard::move() {
    if (++moves_ > move_limit_)
        return LimitAlarm{kerf_alarm::move_limit,
                          fmt::format("move limit of {} moves reached: an endless loop, or a cycle with a step far "
                                      "smaller than its stroke?",
                                      move_limit_)};
    return tick();
}

std::optional<LimitAlarm> RunGuard::tick() {
    if (time_limit_.count() <= 0 || ++until_clock_ < kTicksPerClock) return std::nullopt;
    until_clock_ = 0;
    if (std::chrono::steady_clock::now() < deadline_) return std::nullopt;
    return LimitAlarm{kerf_alarm::time_limit,
                      fmt::format("time limit of {:g} s reached: the dry run stopped here (an endless loop? "
                                  "--time-limit raises it)",
                                  static_cast<double>(time_limit_.count()) / 1000)};
}

}  // namespace kerf::interpreter
