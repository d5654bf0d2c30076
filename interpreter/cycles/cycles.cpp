// Which family expands which cycle, by function id (docs/functions.md): the G numbers differ
// between systems A/B/C and come from the dialect tables.
#include <fmt/format.h>

#include "dialects/functions.hpp"
#include "interpreter/cycles/context.hpp"

namespace kerf::interpreter::cycles {

namespace fn = dialects::functions;

namespace {

// SPINNER §15 note 10: another canned cycle between G384 and G380 is alarm 3011.
bool inside_rigid_tapping(Context& ctx, dialects::FunctionId f) {
    if (!ctx.rigid_tap().active || f == fn::live_tool_rigid_tapping || f == fn::live_tool_rigid_tapping_cancel ||
        f == fn::parts_catcher_cycle)
        return false;
    ctx.alarm(3011, fmt::format("3011: {} programmed while G384 rigid tapping is active: cancel it with G380 first "
                                "(cycles.md §15)",
                                ctx.spelling()));
    return true;
}

}  // namespace

bool expand(Context& ctx) {
    const dialects::FunctionId f = ctx.function();
    if (inside_rigid_tapping(ctx, f)) return true;
    if (spinner(ctx)) return true;
    if (haas_lathe(ctx)) return true;   // [Haas] one-block G71–G76 (haas_lathe.cpp)
    if (f == fn::finishing_cycle || f == fn::rough_turning_cycle || f == fn::rough_facing_cycle ||
        f == fn::pattern_repeating_cycle)
        lathe_profile(ctx);
    else if (f == fn::face_peck_drilling_cycle || f == fn::grooving_cycle)
        lathe_peck(ctx);
    else if (f == fn::multiple_threading_cycle || f == fn::thread_cutting_cycle)
        lathe_thread(ctx);
    else if (f == fn::turning_cycle || f == fn::facing_cycle)
        lathe_single(ctx);
    else
        return drilling(ctx);
    return true;
}

}  // namespace kerf::interpreter::cycles
