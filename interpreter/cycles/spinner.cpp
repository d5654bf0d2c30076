// SPINNER cycles (reference/cycles.md §12–§17, mcodes.md §3.2–§3.3): the G38 transfer, the G138 and
// G238 tailstock clamping, G384/G380 live-tool rigid tapping, M329 spindle rigid tapping, G100/G101
// tailstock coupling and the M432 parts catcher, as the axis moves they make plus messages for the
// machine states a dry run cannot observe (chuck closed, part clamped, spindle reversing). The
// sensor outcomes are modelled by the machine switches of machine/SCHEMA.md "Cycles" (g38_stop,
// clamp_contact, ...). Wrong arguments are alarm 3012 ILLEGAL COMMAND, a part outside its clamping
// window and another cycle inside G384 mode are 3011 (mcodes.md §3.3).
//
// Every word of these blocks is cycle data (the dialect's parameter_words): B, X, Z, C are read as
// distances with the dialect's decimal rule (Context::mm), F, S, D, T, E, A, I, M as written.
#include <fmt/format.h>

#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/cycles/context.hpp"

namespace kerf::interpreter::cycles {

namespace {

namespace fn = dialects::functions;
constexpr std::size_t kX = 0, kZ = 2, kB = 4, kC = 5;
constexpr double kEps = 1e-7;
// §12 "all B coordinates are negative" (B0 = home, seed 001 §8.1 `G28 B0`): the sub-spindle and the
// tailstock move toward the part in −B, and retract in +B.
constexpr double kTowardPart = -1;

Position with(Position p, std::size_t axis, double value) {
    p[axis] = value;
    return p;
}

void illegal(Context& ctx, const std::string& why) {
    ctx.alarm(3012, fmt::format("3012 ILLEGAL COMMAND: {} {} (mcodes.md §3.3)", ctx.spelling(), why));
}

int as_int(double v) { return static_cast<int>(std::lround(v)); }

// --- G38 (§12) ------------------------------------------------------------------------------------

// Torque-limited feed of B toward the commanded B at F mm/min; the part stops at B (or B + Q/2 by
// g38_stop), inside the tolerance window [B, B + Q] the program waits for; then the cycle closes
// the sub-spindle chuck ("G38 includes the clamping operation").
void transfer(Context& ctx) {
    const auto b = ctx.mm('B');
    const auto f = ctx.raw('F');
    const double q = ctx.mm('Q').value_or(1.0);
    if (!b || *b >= 0) return illegal(ctx, "needs B, negative (cycles.md §12: all B coordinates are negative)");
    if (!f || *f <= 0) return illegal(ctx, "needs F, the transfer speed in mm/min (cycles.md §12)");
    if (q <= 0) return illegal(ctx, "Q (tolerance) must be positive (cycles.md §12)");
    const double stop = ctx.settings().spinner.g38_stop_half_tolerance ? *b - kTowardPart * q / 2 : *b;
    if (!ctx.feed_at(with(ctx.position(), kB, stop), *f)) return;
    ctx.message(fmt::format("{}: part transferred, B{:g} within the tolerance B{:g}..B{:g}; sub-spindle chuck closed "
                            "(as M48, cycles.md §12)",
                            ctx.spelling(), stop, *b, *b - kTowardPart * q));
}

// --- G138 / G238 (§13, §14) -----------------------------------------------------------------------

// The final approach at S until the thrust T: the contact is modelled at B + Q/2 (or B, by
// clamp_contact) and checked against the window (B, B − Q] of §13, "B − Q" being Q back from B on
// the retract side (the example's −425.8 < B ≤ −424.8).
void clamp_at_contact(Context& ctx, double b, double q, double feed, double thrust) {
    const double contact = ctx.settings().spinner.clamp_contact_target ? b : b - kTowardPart * q / 2;
    if (!ctx.feed_at(with(ctx.position(), kB, contact), feed)) return;
    const double back = (contact - b) * -kTowardPart;   // how far short of B, toward the retract side
    const double edge = b - kTowardPart * q;
    if (back <= kEps || back > q + kEps) {
        ctx.alarm(3011, fmt::format("3011 PART NOT CLAMPED: {} contact at B{:g} is outside the window B{:g} (excl.) .. "
                                    "B{:g} (cycles.md §13)",
                                    ctx.spelling(), contact, b, edge));
        return;
    }
    ctx.message(fmt::format("{}: workpiece clamped at B{:g} (thrust limit T{:g}, window B{:g} excl. .. B{:g})",
                            ctx.spelling(), contact, thrust, b, edge));
}

struct ClampWords {
    double b, q, feed, thrust;
};

// B and T for a clamp (E1), Q and S with their defaults (§13 table: Q1, S200).
std::optional<ClampWords> clamp_words(Context& ctx) {
    const auto b = ctx.mm('B');
    const auto t = ctx.raw('T');
    const double q = ctx.mm('Q').value_or(1.0);
    const double s = ctx.raw('S').value_or(200.0);
    if (!b || !t) {
        illegal(ctx, "E1 needs B (clamping position) and T (thrust limit) (cycles.md §13, §14)");
        return std::nullopt;
    }
    if (q <= 0 || s <= 0) {
        illegal(ctx, "Q and S must be positive (cycles.md §13, §14)");
        return std::nullopt;
    }
    return ClampWords{*b, q, s, *t};
}

std::optional<int> clamp_mode(Context& ctx) {
    const int e = as_int(ctx.raw('E').value_or(0));
    if (e == 1 || e == 2) return e;
    illegal(ctx, "needs E1 (clamp) or E2 (release) (cycles.md §13, §14)");
    return std::nullopt;
}

// Release: J back toward the retract side at D (default 1500 mm/min).
bool release_travel(Context& ctx, double j) {
    const double d = ctx.raw('D').value_or(1500.0);
    if (d <= 0) {
        illegal(ctx, "D (release feed) must be positive (cycles.md §13, §14)");
        return false;
    }
    const Position p = ctx.position();
    return ctx.feed_at(with(p, kB, p[kB] - kTowardPart * j), d);
}

// G138: E1 rapid to J before B on the retract side ("approach 10 mm by G0"), then the clamping
// feed; E2 retract J (default 5) at D.
void tailstock_clamp_1(Context& ctx) {
    const auto mode = clamp_mode(ctx);
    if (!mode) return;
    const double j = ctx.mm('J').value_or(5.0);
    if (*mode == 2) {
        if (release_travel(ctx, j)) ctx.message(fmt::format("{}: tailstock released", ctx.spelling()));
        return;
    }
    const auto w = clamp_words(ctx);
    if (!w) return;
    if (!ctx.rapid(with(ctx.position(), kB, w->b - kTowardPart * j))) return;
    clamp_at_contact(ctx, w->b, w->q, w->feed, w->thrust);
}

// X and Z of a G238 block (absolute, optional) with B: one simultaneous G0.
Position g238_point(Context& ctx, double b) {
    Position p = ctx.position();
    if (const auto x = ctx.mm('X')) p[kX] = *x;
    if (const auto z = ctx.mm('Z')) p[kZ] = *z;
    p[kB] = b;
    return p;
}

// G238: E1 rapid X, Z, B together to B + K (default 10), the clamping feed, the A tool at the
// start or after clamping (g238_a_timing); E2 J back at D if J is given, then G0 to X, Z and B
// (default 0, §14 items 8–10).
void tailstock_clamp_2(Context& ctx) {
    const auto mode = clamp_mode(ctx);
    if (!mode) return;
    if (*mode == 2) {
        if (const auto j = ctx.mm('J'); j && !release_travel(ctx, *j)) return;
        if (ctx.rapid(g238_point(ctx, ctx.mm('B').value_or(0.0))))
            ctx.message(fmt::format("{}: tailstock released", ctx.spelling()));
        return;
    }
    const auto w = clamp_words(ctx);
    if (!w) return;
    const auto a = ctx.raw('A');
    const bool after = ctx.settings().spinner.g238_a_after_clamp;
    if (a && !after) ctx.tool(as_int(*a));
    const double k = ctx.mm('K').value_or(10.0);
    if (!ctx.rapid(g238_point(ctx, w->b - kTowardPart * k))) return;
    clamp_at_contact(ctx, w->b, w->q, w->feed, w->thrust);
    if (a && after) ctx.tool(as_int(*a));
}

// --- G384 / G380 (§15) ----------------------------------------------------------------------------

// The first G384 block: T1 radial (X, toward −X), T2 face on the main spindle (−Z), T3 face on the
// sub-spindle (+Z [inference]); H a positive depth from the R point (along X a radius unless
// g384_radial_h says diameter); R signed, from the positioning point [inference, as the lathe
// drilling R of §10]; F the pitch, S / D the live-tool speeds in and out; M20 / M220 the brake
// (M220 only with T3).
bool start_rigid_tap(Context& ctx, RigidTapModal& m) {
    const auto t = ctx.raw('T');
    const auto h = ctx.mm('H');
    const auto f = ctx.raw('F');
    const auto s = ctx.raw('S');
    const int dir = t ? as_int(*t) : 0;
    if (dir < 1 || dir > 3) return illegal(ctx, "needs T1 (radial), T2 or T3 (face) (cycles.md §15)"), false;
    if (!h || *h <= 0) return illegal(ctx, "needs H, the positive hole depth from the R point (cycles.md §15)"), false;
    if (!f || *f <= 0 || !s || *s <= 0) return illegal(ctx, "needs F (pitch) and S (live-tool speed) (cycles.md §15)"), false;
    const auto brake = ctx.m_word();
    if (brake && *brake != 20 && !(*brake == 220 && dir == 3))
        return illegal(ctx, fmt::format("M{} is no brake code here: M20 spindle 1, M220 spindle 2 with T3 (cycles.md §15)", *brake)),
               false;
    const bool radial = dir == 1;
    const double x_scale = ctx.diameter_x() ? 2.0 : 1.0;
    m.active = true;
    m.axis = radial ? kX : kZ;
    m.toward = dir == 3 ? 1.0 : -1.0;
    m.r = ctx.mm('R').value_or(0.0) * (radial ? x_scale : 1.0);
    m.depth = *h * (radial && !ctx.settings().spinner.g384_radial_h_diameter ? x_scale : 1.0);
    m.pitch = *f;
    m.rpm_in = *s;
    m.rpm_out = ctx.raw('D').value_or(*s);
    m.brake = brake;
    return true;
}

// One hole from the positioning point: brake, G0 to R, synchronised feed F × S to the bottom, the
// bottom dwell, reverse, F × D back to R, G0 to the positioning point, brake off (§15 steps 2–8).
void tap_hole(Context& ctx, const RigidTapModal& m) {
    const double initial = ctx.position()[m.axis];
    const double r_level = initial + m.r;
    const double bottom = r_level + m.toward * m.depth;
    if (m.brake) ctx.m_code(*m.brake);
    if (!ctx.rapid(with(ctx.position(), m.axis, r_level))) return;
    if (!ctx.feed_at(with(ctx.position(), m.axis, bottom), m.pitch * m.rpm_in)) return;
    ctx.dwell(ctx.settings().spinner.g384_bottom_dwell_s);
    ctx.message(fmt::format("{}: live tool reverses ({:g} min-1), synchronised retract to R", ctx.spelling(), m.rpm_out));
    if (!ctx.feed_at(with(ctx.position(), m.axis, r_level), m.pitch * m.rpm_out)) return;
    ctx.message(fmt::format("{}: live tool stops after leaving the R point", ctx.spelling()));
    if (!ctx.rapid(with(ctx.position(), m.axis, initial))) return;
    if (m.brake) ctx.m_code(*m.brake + 1);
}

// "G384 must be written in every block that taps": the first block sets the data (and runs the A
// tool), later blocks give only X, Z or C; repeating H R F S D M E Q A T there is 3012.
void live_tool_rigid_tapping(Context& ctx) {
    RigidTapModal& m = ctx.rigid_tap();
    if (!m.active) {
        if (!start_rigid_tap(ctx, m)) return;
        if (const auto a = ctx.raw('A')) ctx.tool(as_int(*a));
    } else {
        for (const char letter : {'H', 'R', 'F', 'S', 'D', 'M', 'E', 'Q', 'A', 'T'})
            if (ctx.has(letter))
                return illegal(ctx, fmt::format("{} repeated after the first G384 block: later blocks give only the hole "
                                                "position (cycles.md §15)", letter));
    }
    Position p = ctx.position();
    for (const std::size_t a : {kX, kZ, kC})
        if (const auto v = ctx.mm(kAxisLetters[a])) p[a] = *v;
    if (!ctx.rapid(p)) return;
    tap_hole(ctx, m);
}

// --- M329 (§16) -----------------------------------------------------------------------------------

// The work spindle taps: A tool, G0 X Z, G0 to R (incremental, Z), synchronised feed F × S to the
// absolute Z = H, reverse, feed back to R, G0 to the start point, spindle stop. I1 left hand (M4
// direction in), any other value right hand (M3) [inference].
void spindle_rigid_tapping(Context& ctx) {
    const auto h = ctx.mm('H');
    const auto f = ctx.raw('F');
    const auto s = ctx.raw('S');
    const int spindle = as_int(ctx.raw('T').value_or(2));
    if (!h) return illegal(ctx, "needs H, the absolute Z of the hole bottom (cycles.md §16)");
    if (!f || *f <= 0 || !s || *s <= 0) return illegal(ctx, "needs F (pitch) and S (spindle speed) (cycles.md §16)");
    if (spindle != 2 && spindle != 3) return illegal(ctx, "T must be T2 (spindle 1) or T3 (spindle 2) (cycles.md §16)");
    if (const auto a = ctx.raw('A')) ctx.tool(as_int(*a));
    Position start = ctx.position();
    if (const auto x = ctx.mm('X')) start[kX] = *x;
    if (const auto z = ctx.mm('Z')) start[kZ] = *z;
    if (!ctx.rapid(start)) return;
    const double r_level = start[kZ] + ctx.mm('R').value_or(0.0);
    const bool left = as_int(ctx.raw('I').value_or(0)) == 1;
    if (!ctx.rapid(with(start, kZ, r_level))) return;
    ctx.message(fmt::format("{}: spindle {} turns {} at {:g} min-1 ({}-hand thread, pitch {:g})", ctx.spelling(),
                            spindle == 2 ? 1 : 2, left ? "M4" : "M3", *s, left ? "left" : "right", *f));
    if (!ctx.feed_at(with(start, kZ, *h), *f * *s)) return;
    ctx.message(fmt::format("{}: spindle reverses, synchronised retract to R", ctx.spelling()));
    if (!ctx.feed_at(with(start, kZ, r_level), *f * *s)) return;
    if (!ctx.rapid(start)) return;
    ctx.message(fmt::format("{}: spindle stops", ctx.spelling()));
}

// --- G100 / G101 (§17) ----------------------------------------------------------------------------

// The carriage Z of a machine coordinate, in work coordinates.
Position carriage_at(const Context& ctx, double machine_z) {
    return with(ctx.position(), kZ, machine_z - ctx.machine_offset()[kZ]);
}

// G100: G0 to the coupling position, couple, carry the tailstock to the machine Z of the block
// (or home with I1) [inference: at rapid], decouple. G101: G0 to the second coupling hole; the
// program's own Z moves then carry the tailstock until M56 (not modelled as a second axis).
void tailstock_coupling(Context& ctx, bool carry) {
    const SpinnerSettings& s = ctx.settings().spinner;
    const auto z = ctx.raw('Z');
    const bool home = ctx.raw('I').value_or(0) == 1;
    if (carry && !z && !home) return illegal(ctx, "needs Z (machine position, with a decimal point) or I1 (cycles.md §17)");
    const std::optional<double> coupling = carry ? s.coupling_z : s.coupling_z_second;
    if (!coupling) {
        ctx.message(fmt::format("{}: the machine sets no [tailstock] {}: the carriage stays (machine/SCHEMA.md)",
                                ctx.spelling(), carry ? "coupling_z" : "coupling_z_second"));
        return;
    }
    if (!ctx.rapid(carriage_at(ctx, *coupling))) return;
    if (!carry) {
        ctx.message(fmt::format("{}: tailstock coupled to the carriage; the next Z moves carry it until M56", ctx.spelling()));
        return;
    }
    if (home) {
        ctx.message(fmt::format("{}: tailstock coupled, carried to its home position{} and decoupled", ctx.spelling(),
                                s.home_b ? fmt::format(" B{:g}", *s.home_b) : std::string()));
        return;
    }
    if (!ctx.rapid(carriage_at(ctx, *z))) return;
    ctx.message(fmt::format("{}: tailstock carried to machine Z{:g} and decoupled", ctx.spelling(), *z));
}

// M432 (mcodes.md §3.2): no axis moves; the next block waits for spindle stop, part release and
// unloading.
void parts_catcher(Context& ctx) {
    ctx.message(fmt::format("{}: parts catcher cycle: sub-spindle stop, part release, unload; the next block waits "
                            "(mcodes.md §3.2)",
                            ctx.spelling()));
}

}  // namespace

bool spinner(Context& ctx) {
    const dialects::FunctionId f = ctx.function();
    if (f == fn::workpiece_transfer_cycle) transfer(ctx);
    else if (f == fn::tailstock_clamping_cycle_1) tailstock_clamp_1(ctx);
    else if (f == fn::tailstock_clamping_cycle_2) tailstock_clamp_2(ctx);
    else if (f == fn::live_tool_rigid_tapping) live_tool_rigid_tapping(ctx);
    else if (f == fn::live_tool_rigid_tapping_cancel) ctx.rigid_tap().active = false;
    else if (f == fn::spindle_rigid_tapping_cycle) spindle_rigid_tapping(ctx);
    else if (f == fn::tailstock_coupling_carry) tailstock_coupling(ctx, true);
    else if (f == fn::tailstock_coupling_position) tailstock_coupling(ctx, false);
    else if (f == fn::parts_catcher_cycle) parts_catcher(ctx);
    else return false;
    return true;
}

}  // namespace kerf::interpreter::cycles
