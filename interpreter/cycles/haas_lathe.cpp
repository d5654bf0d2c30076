// [Haas] The one-block forms of the lathe's multiple repetitive cycles (haas-lathe.toml): where
// FANUC system A writes two blocks (G71 U R / G71 P Q U W F), Haas writes one and names the depth,
// the thread height and the pecks with their own letters. The expansion is FANUC's (cycles.md
// §2–§7) with the values read from the one block; what Haas leaves to its settings comes from the
// machine's cycle parameters ([cycle_parameters], machine/SCHEMA.md) and is said where it is used.
//
//   G71/G72 P Q U W D (I K)   staging-diy.haascnc.com "G71 O.D./I.D. Stock Removal Cycle": D depth of
//                             cut per pass (radius); without D Setting 72 (the machine's g71/g72
//                             depth); retract Setting 73 (the machine's g71/g72 retract);
//                             "Type 2 details": the Q block may go back past the start in Z
//   G73 P Q U W I K D         I/K the stock to remove (radius X, Z), D the number of passes [unverified]
//   G74 X Z K I D             K the Z peck, I the X step, D the relief at the bottom [unverified]
//   G75 X Z I K D             I the X peck (radius), K the Z step, D the relief [unverified];
//                             corpus lathe_hp_2 'G75 X0.0 I0.005' (a cut-off in pecks)
//   G76 X Z K D A I P         "G76 Threading Cycle, Multiple Pass (Group 00) - Lathe" (Haas Technical
//                             Documentation): K thread height, D first pass depth, A tool nose angle,
//                             I taper (radius), P1–P4 cutting method; the chamfer out of the thread
//                             is on unless M24 turned it off (M23 on)
#include <fmt/format.h>

#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/cycles/context.hpp"

namespace kerf::interpreter::cycles {

namespace {

namespace fn = dialects::functions;

void rough(Context& ctx, bool facing) {
    const auto profile = profile_of_block(ctx);
    if (!profile) return;
    const Parameters& params = ctx.parameters();
    RoughCycle r;
    r.facing = facing;
    // What the block leaves to Settings 72/73 comes from the machine's [cycle_parameters], in mm
    // (machine/SCHEMA.md): to program units here, as no Haas block ever sets them (an inch
    // program would otherwise retract 1 in for 1 mm).
    r.depth = ctx.mm('D').value_or((facing ? params.g72_depth : params.g71_depth) * ctx.per_mm());
    r.retract = (facing ? params.g72_retract : params.g71_retract) * ctx.per_mm();
    // Haas G71/G72 "Type 2 details": the Q block is the one exception to the rule that the Z path
    // of P..Q does not go back past the start (lathe_profile.cpp, rough).
    r.q_block_may_return = true;
    rough_profile(ctx, *profile, r);
}

void pattern(Context& ctx) {
    const auto profile = profile_of_block(ctx);
    if (!profile) return;
    const auto d = ctx.raw('D');
    const int passes = d ? static_cast<int>(std::lround(*d)) : ctx.parameters().g73_divisions;
    if (passes < 1) {
        ctx.alarm(62, fmt::format("{}: the number of passes D{} must be at least 1 (FANUC alarm 062)", ctx.spelling(), *d));
        return;
    }
    repeat_pattern(ctx, *profile, ctx.mm('I').value_or(0), ctx.mm('K').value_or(0), passes);
}

void peck(Context& ctx, bool face) {
    if (!ctx.has_end_point()) {
        ctx.alarm(62, fmt::format("{} without an end point X/Z (FANUC alarm 062)", ctx.spelling()));
        return;
    }
    const Parameters& params = ctx.parameters();
    PeckCycle p;
    p.face = face;
    p.peck = ctx.mm(face ? 'K' : 'I').value_or(0);
    p.shift = ctx.mm(face ? 'I' : 'K').value_or(0);
    p.retract = (face ? params.g74_retract : params.g75_retract) * ctx.per_mm();   // machine mm, as rough()
    p.relief = ctx.mm('D').value_or(0);
    peck_cycle(ctx, p);
}

void threading(Context& ctx) {
    const double k = ctx.mm('K').value_or(0), d = ctx.mm('D').value_or(0);
    if (!ctx.has_end_point() || k <= 0 || d <= 0) {
        ctx.alarm(62, fmt::format("{}: the end point X/Z, the thread height K and the first cut D must be given and positive "
                                  "(FANUC alarm 062)", ctx.spelling()));
        return;
    }
    const Parameters& params = ctx.parameters();
    const double lead = ctx.raw('F').value_or(ctx.raw('E').value_or(ctx.modal_feed()));
    ThreadCycle t;
    t.height = k;
    t.first = d;
    t.min_step = params.g76_min_depth * ctx.per_mm();   // Setting 99, thread minimum cut (machine mm, as rough())
    t.allowance = params.g76_allowance * ctx.per_mm();  // Setting 86, thread finish allowance
    t.finishing_passes = 1;
    t.angle = ctx.raw('A').value_or(params.g76_angle);
    t.taper = ctx.mm('I').value_or(0);
    // Settings 95/96: the chamfer in leads; the machine's G92 run-out length stands in for them.
    t.chamfer = ctx.thread_chamfer() ? ctx.settings().thread_chamfer_leads * lead : 0;
    const int method = static_cast<int>(std::lround(ctx.raw('P').value_or(1)));
    // P1 single edge, amount constant; P2 double edge, amount constant; P3 single edge, depth
    // constant; P4 double edge, depth constant.
    if (method < 1 || method > 4) {
        ctx.alarm(62, fmt::format("{}: cutting method P{} is not P1–P4 (FANUC alarm 062)", ctx.spelling(), method));
        return;
    }
    t.constant_depth = method >= 3;
    t.infeed = method % 2 == 0 ? ThreadInfeed::alternating : ThreadInfeed::flank;
    thread_cycle(ctx, t, lead);
}

}  // namespace

bool haas_lathe(Context& ctx) {
    const dialects::FunctionId f = ctx.function();
    if (f == fn::one_block_rough_turning_cycle) rough(ctx, false);
    else if (f == fn::one_block_rough_facing_cycle) rough(ctx, true);
    else if (f == fn::one_block_pattern_repeating_cycle) pattern(ctx);
    else if (f == fn::one_block_face_peck_cycle) peck(ctx, true);
    else if (f == fn::one_block_grooving_cycle) peck(ctx, false);
    else if (f == fn::one_block_threading_cycle) threading(ctx);
    else return false;
    return true;
}

}  // namespace kerf::interpreter::cycles
