// [additional work offsets] FANUC G54.1 P (fanuc-mill) and Haas G154 P1–P99 / G110–G129: work
// coordinate systems beyond G54–G59, found by the function id work-coordinate-additional. G110–G129
// carry their number as data (`implied = ["P1"]` in haas-mill.toml: G110 is G154 P1, haas.co.uk
// "Programmable Offsets"). The registers start at 0 (an offset nobody set puts the work zero on
// machine zero) and are written through the dialect's work-offset variables (#14001.. on Haas NGC,
// executor_dialect_variables.cpp). Selecting one keeps the tool where it is: its work coordinates
// change (semantics.md §2.7), as with G54–G59.
#include <fmt/format.h>

#include <cmath>

#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace {
constexpr int kMaxAdditional = 300;   // FANUC G54.1 P1–P300, Haas G154 P1–P99
}

const Position& Executor::active_work_offset() const {
    if (additional_system_ > 0) {
        const auto it = additional_offsets_.find(additional_system_);
        static const Position zero{};
        return it == additional_offsets_.end() ? zero : it->second;
    }
    return work_offsets_[static_cast<std::size_t>(work_system_)];
}

Position& Executor::additional_offset(int number) { return additional_offsets_[number]; }

void Executor::select_additional_work_offset(const ast::BlockView& view, const BlockWords& words, const dialects::CodeInfo& code) {
    std::optional<double> p;
    if (const auto* w = words.get('P')) p = w->value;
    for (const auto& [letter, value] : code.implied)
        if (letter == 'P' && !p) p = value;
    if (!p) {
        alarm(*frame_, view, 10, fmt::format("{} without P: which additional work offset is meant (alarm 010)", code.spelling));
        return;
    }
    const long n = std::lround(*p);
    if (n < 1 || n > kMaxAdditional || *p != static_cast<double>(n)) {
        alarm(*frame_, view, 10, fmt::format("{} P{}: no additional work offset with that number (alarm 010)", code.spelling, *p));
        return;
    }
    change_offsets([&] { additional_system_ = static_cast<int>(n); });
    Event e = event_at(EventKind::coordinate_change, *frame_, view);
    e.text = fmt::format("additional work offset P{} ({})", n, code.spelling);
    emit(e);
}

}  // namespace kerf::interpreter
