// Codes whose motion the next issue expands (canned cycles, compensation, polar and cylindrical
// interpolation, position offsets, direct drawing: reference/cycles.md, semantics.md §5–§10).
// Until an expander exists for a code, the interpreter must not pretend: a cycle block does not
// run its words as a plain move (the tool would cut through the part), it says so in a message
// and keeps the tool where it is; G71–G73 skip their profile blocks as the control does and check
// that P and Q exist (alarm 060); codes that change the path (G41/G42, G112, G45–G48, ,C ,R) let
// the programmed path run and say that it is not the compensated one.
#include <fmt/format.h>

#include <algorithm>
#include <iterator>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

namespace {

// Cycles whose function id does not say "-cycle" (SPINNER, cycles.md §15, §17).
constexpr std::string_view kOtherCycles[] = {"live-tool-rigid-tapping", "tailstock-coupling-carry",
                                             "tailstock-coupling-position"};

// Function ids (docs/functions.md) whose path the trace does not model yet.
constexpr std::string_view kPathChangers[] = {
    "axial-offset-direction-plus", "axial-offset-direction-minus",
    "radius-comp-left", "radius-comp-right", "polar-interpolation-on", "cylindrical-interpolation",
    "position-offset-increase", "position-offset-decrease", "position-offset-double-increase",
    "position-offset-double-decrease", "corner-slowdown", "arc-approach", "arc-exit",
    "tool-length-comp-plus", "tool-length-comp-minus", "polar-coordinate-command", "scaling", "mirror",
};

// G71/G72/G73 run the profile N P..N Q and go on after N Q (cycles.md §2–§4); G70 runs it and
// goes on after its own block (§1).
constexpr std::string_view kProfileCycles[] = {"rough-turning-cycle", "rough-facing-cycle", "pattern-repeating-cycle"};
constexpr std::string_view kFinishingCycle = "finishing-cycle";

}  // namespace

bool Executor::is_cycle_function(std::string_view f) {
    const bool cancel = f.size() >= 7 && f.substr(f.size() - 7) == "-cancel";   // G80 canned-cycle-cancel
    return (f.find("-cycle") != std::string_view::npos && !cancel) ||
           std::find(std::begin(kOtherCycles), std::end(kOtherCycles), f) != std::end(kOtherCycles);
}

// True when the block belongs to a cycle (then it does not move here).
// Per code of the dialect, computed once: the per-block checks compare bits, not strings.
void Executor::classify_codes() {
    const auto codes = dialect_.codes();
    code_class_.assign(codes.size(), 0);
    for (std::size_t i = 0; i < codes.size(); ++i) {
        const std::string_view f = codes[i].function;
        if (is_cycle_function(f)) code_class_[i] |= kCycleCode;
        if (std::find(std::begin(kPathChangers), std::end(kPathChangers), f) != std::end(kPathChangers))
            code_class_[i] |= kPathChangerCode;
        // The modal flags update_flags() derives (executor.cpp).
        if (f == fn::incremental_programming) code_class_[i] |= kIncrementalCode;
        if (f == fn::feed_per_revolution) code_class_[i] |= kPerRevolutionCode;
        if (f == fn::css_on) code_class_[i] |= kCssCode;
        if (f == fn::inch_input) code_class_[i] |= kInchCode;
        if (f == fn::plane_xy) code_class_[i] |= kPlaneXYCode;
        if (f == fn::plane_zx) code_class_[i] |= kPlaneZXCode;
        if (f == fn::plane_yz) code_class_[i] |= kPlaneYZCode;
    }
}

bool Executor::is_cycle(const dialects::CodeInfo& code) const { return code_class_of(code) & kCycleCode; }

std::uint8_t Executor::code_class_of(const dialects::CodeInfo& code) const {
    const auto codes = dialect_.codes();
    const std::size_t i = static_cast<std::size_t>(&code - codes.data());
    return i < code_class_.size() ? code_class_[i] : (is_cycle_function(code.function) ? kCycleCode : 0);
}

bool Executor::apply_cycle_placeholder(const ast::BlockView& view, const BlockWords& words, bool has_axis_words) {
    const dialects::CodeInfo* cycle = nullptr;
    for (const ast::CodeRef& c : scan_.g)
        if (c.info && is_cycle(*c.info)) cycle = c.info;
    for (const ast::CodeRef& c : scan_.m)
        if (c.info && is_cycle(*c.info)) cycle = c.info;
    if (!cycle && flags_.modal_cycle && has_axis_words) cycle = flags_.modal_cycle;   // G81 ... X Y: a new hole
    if (!cycle) return false;
    const auto* p = words.get('P');
    const auto* q = words.get('Q');
    const bool profile = std::find(std::begin(kProfileCycles), std::end(kProfileCycles), cycle->function) !=
                         std::end(kProfileCycles);
    if ((profile || cycle->function == kFinishingCycle) && p && q) {
        const auto first = find_label(*frame_, p->value);
        const auto last = find_label(*frame_, q->value);
        if (!first || !last) {
            const double missing = first ? q->value : p->value;
            alarm(*frame_, view, 60, fmt::format("{} P{} Q{}: sequence number N{} not found in this program (alarm 060)",
                                                 cycle->spelling, p->value, q->value, missing));
            return true;
        }
        // The control goes on after the profile (G71–G73), which the cycle has used.
        if (profile) current_frame()->block = *last + 1;
    }
    Event e = event_at(EventKind::message, *frame_, view);
    e.text = fmt::format("{} ({}) is not expanded yet (cycles: next issue): the tool stays at its start point",
                         cycle->spelling, cycle->function);
    emit(e);
    return true;
}

void Executor::note_path_changers(const ast::BlockView& view) {
    for (const ast::CodeRef& c : scan_.g) {
        if (c.info && (code_class_of(*c.info) & kPathChangerCode)) {
            Event e = event_at(EventKind::message, *frame_, view);
            e.text = fmt::format("{} ({}) is not applied yet (next issue): the trace follows the programmed path",
                                 c.info->spelling, c.info->function);
            emit(e);
        }
    }
    if (scan_.comma_words || scan_.direct_drawing) {
        Event e = event_at(EventKind::message, *frame_, view);
        e.text = "direct drawing (,A ,C ,R or plain A R) is not expanded yet (next issue): the block runs to its programmed end point";
        emit(e);
    }
}

}  // namespace kerf::interpreter
