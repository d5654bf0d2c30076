// G74 face peck drilling / face grooving and G75 OD/ID grooving (reference/cycles.md §5, §6):
// the same expansion with X and Z exchanged. Geometry in the Z–X plane with X as a radius.
#include <fmt/format.h>

#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/cycles/contour.hpp"

namespace kerf::interpreter::cycles {

namespace {

namespace fn = dialects::functions;
constexpr double kEps = 1e-7;

double sign(double v) { return v > kEps ? 1.0 : v < -kEps ? -1.0 : 0.0; }

struct Peck {
    Coord axis;        // the pecking axis: Z for G74, X for G75
    double peck;       // depth per peck (Q of G74, P of G75), 0 = one feed to the bottom
    double shift;      // step between columns (P of G74, Q of G75)
    double retract;    // e, after each peck (first block)
    double relief;     // Δd at the bottom, away from the next column (second R)
    char shift_word;   // the word that gives the step, for the alarm
};

// One column: pecks of `peck` with rapid retracts by e; the last peck clipped at the bottom
// (cycles.md §5 worked O0009: feed −17, rapid −16.5, feed −37, ...).
bool pecks(Context& ctx, const Peck& p, Pt a, double column, double bottom, const Position& like) {
    const bool dia = ctx.diameter_x();
    const double dir = sign(bottom - get(a, p.axis));
    double depth = get(a, p.axis);
    while (dir != 0) {
        double next = p.peck > 0 ? depth + dir * p.peck : bottom;
        if (dir * (next - bottom) >= -kEps) next = bottom;
        if (!ctx.feed(to_position(make(p.axis, next, column), like, dia))) return false;
        if (next == bottom) break;
        if (!ctx.rapid(to_position(make(p.axis, next - dir * p.retract, column), like, dia))) return false;
        depth = next;
    }
    return true;
}

void peck_cycle(Context& ctx, const Peck& p) {
    const bool dia = ctx.diameter_x();
    const Position like = ctx.position();
    const Pt a = to_pt(like, dia);
    const Pt end = to_pt(ctx.end_point(), dia);
    const Coord across = other(p.axis);
    const double step_dir = sign(get(end, across) - get(a, across));
    if (step_dir != 0 && p.shift <= 0) {
        ctx.alarm(62, fmt::format("{}: the end point moves in {} but the step {} is missing or zero (FANUC alarm 062)",
                                  ctx.spelling(), across == Coord::x ? 'X' : 'Z', p.shift_word));
        return;
    }
    double column = get(a, across);
    for (;;) {
        if (!pecks(ctx, p, a, column, get(end, p.axis), like)) return;
        const bool last = step_dir == 0 || step_dir * (get(end, across) - column) <= kEps;
        // Relief Δd at the bottom, away from the next column (§5 step 2), then back out.
        double out_column = column;
        if (p.relief > 0 && step_dir != 0) {
            out_column = column - step_dir * p.relief;
            if (!ctx.rapid(to_position(make(p.axis, get(end, p.axis), out_column), like, dia))) return;
        }
        if (!ctx.rapid(to_position(make(p.axis, get(a, p.axis), out_column), like, dia))) return;
        if (last) break;
        column += step_dir * p.shift;
        if (step_dir * (column - get(end, across)) > 0) column = get(end, across);
        if (!ctx.rapid(to_position(make(p.axis, get(a, p.axis), column), like, dia))) return;
    }
    if (ctx.position() != like) ctx.rapid(like);
}

}  // namespace

void peck_cycle(Context& ctx, const PeckCycle& p) {
    // The Haas one-block forms name the step I (G74: X step) or K (G75: Z step).
    peck_cycle(ctx, Peck{p.face ? Coord::z : Coord::x, p.peck, p.shift, p.retract, p.relief, p.face ? 'I' : 'K'});
}

void lathe_peck(Context& ctx) {
    const bool face = ctx.function() == fn::face_peck_drilling_cycle;
    Parameters& params = ctx.parameters();
    double& retract = face ? params.g74_retract : params.g75_retract;
    if (!ctx.has_end_point()) {
        // First block `G74 R(e)`: e persists (§0, "changes P722").
        retract = ctx.mm('R').value_or(retract);
        return;
    }
    // P and Q count least input increments (§0): G74 P = X step, Q = peck; G75 P = peck, Q = Z step.
    const double p = ctx.pq('P').value_or(0), q = ctx.pq('Q').value_or(0);
    Peck peck{face ? Coord::z : Coord::x, face ? q : p, face ? p : q, retract, ctx.mm('R').value_or(0), face ? 'P' : 'Q'};
    peck_cycle(ctx, peck);
}

}  // namespace kerf::interpreter::cycles
