// [Haas] M97 P: the local subprogram call (Haas Mill Operator's Manual 96-8000, "M97 Local
// Sub-Program Call": P is an N of the same program, L repeats it, the subroutine ends with M99).
// The called label runs as a subprogram frame of the running program, so M99 returns to the block
// after M97 (executor_motion.cpp) and the call nests like M98. Found by its function id,
// local-subprogram-call, as the reference resolver finds the same P (references/references.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interpreter/executor.hpp"

namespace kerf::interpreter {

void Executor::call_local_subprogram(const BlockContext& ctx) {
    const Frame& frame = ctx.frame;
    const BlockWords& words = ctx.words;
    const auto* p = words.get('P');
    if (!p) {
        alarm(ctx, 76, "M97 without a sequence number P (alarm 076)");
        return;
    }
    const auto label = find_label(frame, p->value);
    if (!label) {
        alarm(ctx, 78, fmt::format("M97 P{}: no block N{} in this program (alarm 078)", p->value, p->value));
        return;
    }
    if (static_cast<int>(frames_.size()) > setup_.max_call_depth) {
        alarm(ctx, 77, fmt::format("subprogram nesting deeper than {} (alarm 077)", setup_.max_call_depth));
        return;
    }
    Frame sub;
    sub.program = frame.program;
    sub.block = *label;
    sub.start_block = *label;
    const auto* l = words.get('L');
    sub.repeats_left = l ? std::max<std::int64_t>(1, std::lround(l->value)) : 1;
    Event e = event_at(EventKind::call, ctx);
    e.code = 0;
    e.text = fmt::format("M97 P{}", p->value);
    emit(e);
    frames_.push_back(sub);
}

bool Executor::skip_resident_call(const BlockContext& ctx, std::int64_t program, std::string_view how) {
    if (!options_.resident || !options_.resident(program)) return false;
    Event e = event_at(EventKind::message, ctx);
    e.text = fmt::format("{} O{:04}: a program resident in the machine (.kerf.toml [programs] resident), not available to "
                         "the dry run: skipped", how, program);
    emit(e);
    return true;
}

}  // namespace kerf::interpreter
