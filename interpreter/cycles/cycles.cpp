// Which family expands which cycle, by function id (docs/functions.md): the G numbers differ
// between systems A/B/C and come from the dialect tables.
#include "dialects/functions.hpp"
#include "interpreter/cycles/context.hpp"

namespace kerf::interpreter::cycles {

namespace fn = dialects::functions;

bool expand(Context& ctx) {
    const std::string_view f = ctx.function();
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
