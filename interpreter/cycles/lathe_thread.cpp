// Threading cycles: G76 multiple threading (two blocks, reference/cycles.md §7) and the single
// thread cycle G92 (A; G78 in B, G21 in C; §8.2). Each pass cuts with the thread event, timed at
// lead × rpm by the executor (§9).
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "dialects/functions.hpp"
#include "interpreter/cycles/context.hpp"

namespace kerf::interpreter::cycles {

namespace {

namespace fn = dialects::functions;
constexpr double kEps = 1e-9;

double sign(double v) { return v > kEps ? 1.0 : v < -kEps ? -1.0 : 0.0; }

// The cut of one pass from the current point to `end` (X a diameter when `dia`): with a run-out
// of `chamfer` (Z length) the thread leaves at 45° before the end point (§7 step 3, §8.2), never
// past the start diameter `limit_x` [inference: the pull-out ends where the X retract would].
bool cut(Context& ctx, const Position& end, double lead, double chamfer, double limit_x) {
    if (chamfer <= kEps) return ctx.thread(end, lead);
    const Position from = ctx.position();
    const double length = end[2] - from[2];
    const double dir = sign(length);
    const double run_out = std::min(chamfer, std::fabs(length));
    const double t = std::fabs(length) > kEps ? (std::fabs(length) - run_out) / std::fabs(length) : 0;
    Position before = end;
    before[0] = from[0] + (end[0] - from[0]) * t;
    before[2] = end[2] - dir * run_out;
    if (!ctx.thread(before, lead)) return false;
    const double out_x = sign(limit_x - end[0]);
    Position pulled = end;
    pulled[0] = before[0] + out_x * (ctx.diameter_x() ? 2 : 1) * run_out;
    if (out_x * (pulled[0] - limit_x) > 0) pulled[0] = limit_x;
    return ctx.thread(pulled, lead);
}

// One pass: rapid in to (x_start, z_start), thread to (x_end, Z end), rapid X back to A, rapid Z
// back to A.
bool pass(Context& ctx, const Position& a, double x_start, double z_start, Position end, double lead, double chamfer) {
    Position in = a;
    in[0] = x_start;
    in[2] = z_start;
    if (!ctx.rapid(in)) return false;
    if (!cut(ctx, end, lead, chamfer, a[0])) return false;
    Position back = ctx.position();
    back[0] = a[0];
    if (!ctx.rapid(back)) return false;
    return ctx.rapid(a);
}

// Cumulative radial depths of the roughing passes (§7 step 1): Δd·√n, at least Δdmin more than
// the last, the last one exactly k − d.
std::vector<double> rough_depths(double k, double first, double min_step, double allowance) {
    std::vector<double> depths;
    const double target = k - allowance;
    double last = 0;
    for (int n = 1; n < 10000; ++n) {
        double d = first * std::sqrt(static_cast<double>(n));
        if (d - last < min_step) d = last + min_step;
        if (d >= target - kEps) {
            depths.push_back(target);
            break;
        }
        depths.push_back(d);
        last = d;
    }
    return depths;
}

double thread_lead(Context& ctx) { return ctx.raw('F').value_or(ctx.modal_feed()); }

void multiple_threading(Context& ctx) {
    Parameters& params = ctx.parameters();
    if (!ctx.has_end_point()) {
        // First block: P(m)(r)(a) packed two digits each, Q Δdmin, R d; persistent (§0, §7).
        if (const auto p = ctx.raw('P')) {
            const long v = std::lround(*p);
            params.g76_finishing_passes = static_cast<int>(v / 10000);
            params.g76_chamfer = static_cast<int>(v / 100 % 100);
            params.g76_angle = static_cast<int>(v % 100);
        }
        params.g76_min_depth = ctx.pq('Q').value_or(params.g76_min_depth);
        params.g76_allowance = ctx.mm('R').value_or(params.g76_allowance);
        return;
    }
    const double k = ctx.pq('P').value_or(0), first = ctx.pq('Q').value_or(0);
    if (k <= 0 || first <= 0) {
        ctx.alarm(62, fmt::format("{}: thread height P and first depth Q must be positive (FANUC alarm 062)", ctx.spelling()));
        return;
    }
    const double lead = thread_lead(ctx);
    ThreadCycle t;
    t.height = k;
    t.first = first;
    t.min_step = params.g76_min_depth;
    t.allowance = params.g76_allowance;
    t.finishing_passes = params.g76_finishing_passes;
    t.angle = params.g76_angle;
    t.taper = ctx.mm('R').value_or(0);   // i, radius: start − end
    t.chamfer = params.g76_chamfer * lead / 10.0;
    thread_cycle(ctx, t, lead);
}

// G92: rapid to X + 2R, thread to (X, Z) with the run-out of the machine, rapid X, rapid Z (§8.2).
void single_threading(Context& ctx) {
    const Position a = ctx.position();
    const auto [end, r] = single_cycle_block(ctx);
    const double lead = thread_lead(ctx);
    const double taper = r * (ctx.diameter_x() ? 2 : 1);
    pass(ctx, a, end[0] + taper, a[2], end, lead, ctx.settings().thread_chamfer_leads * lead);
}

}  // namespace

void thread_cycle(Context& ctx, const ThreadCycle& t, double lead) {
    const Position a = ctx.position();
    const Position end = ctx.end_point();
    const double taper = t.taper * (ctx.diameter_x() ? 2 : 1);
    const double side = sign(a[0] - end[0]);                                      // + outside (OD)
    const double toward_end = sign(end[2] - a[2]);
    const double flank = std::tan(t.angle * std::numbers::pi / 360.0);
    const Infeed machine = ctx.settings().infeed;
    const bool on_flank = t.infeed == ThreadInfeed::flank || t.infeed == ThreadInfeed::alternating ||
                          (t.infeed == ThreadInfeed::machine && machine != Infeed::radial);
    const double flank_dir = !on_flank                                                         ? 0.0
                             : t.infeed == ThreadInfeed::machine && machine == Infeed::opposite_flank ? -toward_end
                                                                                                      : toward_end;
    const double dia = ctx.diameter_x() ? 2 : 1;
    std::vector<double> depths;
    if (t.constant_depth) {
        for (double d = t.first; d < t.height - t.allowance - kEps && depths.size() < 10000; d += t.first) depths.push_back(d);
        depths.push_back(t.height - t.allowance);
    } else {
        depths = rough_depths(t.height, t.first, t.min_step, t.allowance);
    }
    for (int m = 0; m < std::max(1, t.finishing_passes); ++m) depths.push_back(t.height);
    for (std::size_t i = 0; i < depths.size(); ++i) {
        const double d = depths[i];
        Position to = end;
        to[0] = end[0] + side * dia * (t.height - d);
        // Alternating flanks (Haas P2/P4, double edge cutting): every second pass on the other flank.
        const double dir = t.infeed == ThreadInfeed::alternating && i % 2 == 1 ? -flank_dir : flank_dir;
        const double z_start = a[2] + dir * (d - depths.front()) * flank;
        if (!pass(ctx, a, to[0] + taper, z_start, to, lead, t.chamfer)) return;
    }
}

void lathe_thread(Context& ctx) {
    if (ctx.function() == fn::multiple_threading_cycle) multiple_threading(ctx);
    else single_threading(ctx);
}

}  // namespace kerf::interpreter::cycles
