// G90 (turning) and G94 (facing) single cycles, A codes; G77/G79 in B, G20/G24 in C
// (reference/cycles.md §8.1, §8.3): four moves from the start point A, taper by R.
#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/cycles/context.hpp"

namespace kerf::interpreter::cycles {

namespace {
namespace fn = dialects::functions;
}

SingleCycleBlock single_cycle_block(Context& ctx) {
    SingleCycleModal& modal = ctx.single_cycle();
    Position end = ctx.end_point();
    double r = ctx.mm('R').value_or(0);
    if (ctx.repeat()) {
        for (const std::size_t a : {std::size_t{0}, std::size_t{2}})
            if (!ctx.names_axis(a == 0 ? 'X' : 'Z')) end[a] = modal.end[a];
        if (!ctx.has('R')) r = modal.r;
    }
    modal = {end, r};
    return {end, r};
}

void lathe_single(Context& ctx) {
    const Position a = ctx.position();
    const auto [end, r] = single_cycle_block(ctx);
    const bool turning = ctx.function() == fn::turning_cycle;
    // The first axis of the cycle moves by rapid to the taper start (R a radius on X: 2R on the
    // diameter, §8.1), the other axis feeds the cut, then the first feeds back and the second
    // returns by rapid.
    const std::size_t first = turning ? 0 : 2;
    const double taper = turning && ctx.diameter_x() ? 2 * r : r;
    Position p1 = a;
    p1[first] = end[first] + taper;
    if (!ctx.rapid(p1)) return;
    if (!ctx.feed(end)) return;
    Position p3 = end;
    p3[first] = a[first];
    if (!ctx.feed(p3)) return;
    ctx.rapid(a);
}

}  // namespace kerf::interpreter::cycles
