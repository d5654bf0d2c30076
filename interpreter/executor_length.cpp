// G43/G44/G49 tool length offsets (reference semantics.md §7; the dry-run formula of §2.7: "for
// mills add G43/G44 length (H) on Z"). G43 adds the H register (length + length wear) to the Z
// machine position, G44 subtracts it, G49 (and H0) cancel; an H word alone changes the register
// while G43/G44 is in force ([FANUC]). The programmed (work) coordinates stay what they are: the
// next block with a Z word moves to its Z with the new offset (take_up_length_offset), or Z moves
// at once (machine switch length_offset_motion); a move's length counts the offset it takes up. The block's event says so; its `code` is the H number and `tool` the
// spindle tool, so a rule can compare them (an H of another tool: analyzer K5019).
#include <fmt/format.h>

#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

namespace {

// +1 / −1 for the codes that set a direction, 0 for a cancel.
int length_sign_of(dialects::FunctionId f) {
    if (f == fn::tool_length_comp_plus || f == fn::axial_offset_plus) return 1;
    if (f == fn::tool_length_comp_minus || f == fn::axial_offset_minus) return -1;
    return 0;
}

}  // namespace

// seed 004 (iso-legacy-mill): "G43 and G44 define the directions of the axial offset" (semantics.md
// §7), the offset's registers addressed by H; G43 without H in a move is the approach of §9.4
// (executor_iso_specials.cpp). So G43/G44 are a length offset when the block has H, or always
// with the machine switch iso_g43 = "length-offset" (semantics.md §12.9).
bool Executor::axial_offset_is_length(const dialects::CodeInfo& code, const BlockWords& words) const {
    if (code.function != fn::axial_offset_plus && code.function != fn::axial_offset_minus) return true;
    return !setup_.iso_g43_approach || words.get('H') != nullptr;
}

void Executor::apply_length_offset(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    int sign = state_.length_sign;
    const dialects::CodeInfo* code = nullptr;
    for (const ast::CodeRef& c : ctx.scan.g) {
        if (!c.info || !(code_class_of(*c.info) & kLengthCompCode) || !axial_offset_is_length(*c.info, words)) continue;
        code = c.info;   // several in one block: the last one wins (semantics.md §1.1)
        sign = length_sign_of(c.info->function);
    }
    const auto* h_word = words.get('H');
    if (!code && !h_word) return;   // G43/G44 in force, nothing new in this block
    // The block's H, else the last H written (FANUC modal H; remember_words keeps it).
    const auto& modal_h = state_.last_words[static_cast<std::size_t>('H' - 'A')];
    const int h = sign == 0 ? 0 : h_word ? static_cast<int>(std::lround(h_word->value))
                                         : modal_h ? static_cast<int>(std::lround(*modal_h)) : 0;
    double length = 0;
    if (h != 0) {
        const auto it = memory_.tools.find(h);
        if (it == memory_.tools.end() && h > setup_.tool_offset_count) {
            Event m = event_at(EventKind::message, ctx);
            m.text = fmt::format("H{}: the machine has offset numbers 1..{} only: length 0", h, setup_.tool_offset_count);
            emit(m);
        }
        if (it != memory_.tools.end()) length = it->second.length + it->second.length_wear;
    }
    state_.length_sign = sign;
    state_.length_h = h;
    state_.length_mm = sign * length;
    Event e = event_at(EventKind::coordinate_change, ctx);
    e.code = h;
    e.text = sign == 0 ? "tool length offset cancelled (G49): machine Z = programmed Z"
                       : fmt::format("tool length offset {} H{}: machine Z = programmed Z {} {:.3f} mm",
                                     code ? code->spelling : std::string(sign > 0 ? "G43" : "G44"), h,
                                     sign > 0 ? "+" : "-", length);
    state_.pending_length_event = std::move(e);
    // With the axis-movement reading of the parameter a block without axis words moves Z by the
    // change at once; else (the default) the next block that moves Z takes it up, this one too.
    if (setup_.length_offset_at_once && !(words.words.mask() & axis_letters_) && !words.incremental.mask()) {
        take_up_length_offset(ctx);
        move(state_.flags.motion == fn::linear ? EventKind::linear : EventKind::rapid, state_.position, ctx);
    }
}

// The offset is taken up by the next block with a Z word ([FANUC]: the offset vector is executed
// with the movement of the offset axis; LinuxCNC's coordinate shift gives the same path): the Z
// of that block is measured with the new offset, a block that moves only X and Y keeps the axis
// where it stands (differential B2: `G28 G91 Z0. / G49 / G28 G91 X0. Y0.` does not drop the tool).
// The `coordinate_change` event says so where the machine position starts to follow the new offset
// (the block that takes it up), so that machine minus the offset of the events is the tool tip
// throughout the trace.
void Executor::take_up_length_offset_with_z(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    const auto* z = words.get('Z');
    if ((z && !z->data) || words.incremental.count('Z')) take_up_length_offset(ctx);
}

void Executor::take_up_length_offset(const BlockContext& ctx) {
    state_.length_applied_mm = state_.length_mm;
    if (!state_.pending_length_event) return;
    Event e = std::move(*state_.pending_length_event);
    state_.pending_length_event.reset();
    if (e.source.line != ctx.source().line) {
        e.text += ", given before and taken up by this block's Z";   // no line number: formatting moves lines
        e.source = ctx.source();
    }
    e.start = e.end = state_.position;
    emit(std::move(e));
}

}  // namespace kerf::interpreter
