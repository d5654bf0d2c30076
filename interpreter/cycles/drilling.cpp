// Drilling cycles (reference/cycles.md §10, §11; [FANUC] canned cycles where the reference gives
// only the table): mill G73/G74/G76/G81/G82/G83/G84/G85/G86/G89 (fanuc-mill), ADV400 G81/G84 (mill)
// and G83 (lathe), and the lathe live-tool cycles G83/G84/G86 (face) and G87/G88/G89 (side).
//
// fanuc-mill G87 (back boring) and G88 (boring, manual retract) follow [FANUC] M-series (the
// reference lists them in its tables only).
// Two forms share one hole expansion (drill_hole):
// * the mill form (R and Z are levels: absolute under G90; under G91 R counts from the initial
//   level and Z from the R level), drilling along Z, holes at the block's X/Y, G98/G99 return;
// * the lathe live-tool form (§10: R counts from the initial level, signed, omitted = 0; W from the
//   R level), drilling along Z (face) or X (side, radius distances), C indexing by H, the clamp
//   M code of the block before each hole and M+1 after it.
// Which word is the peck and which the repeat count comes from the code's word list (a code that
// takes Q pecks by Q and repeats by K/L; ADV400 G83 has no Q: K is its peck, cycles.md §11.3).
#include <fmt/format.h>

#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/cycles/context.hpp"

namespace kerf::interpreter::cycles {

namespace {

namespace fn = dialects::functions;
constexpr double kEps = 1e-7;
constexpr std::size_t kX = 0, kZ = 2, kC = 5;

enum class Kind {
    drill,            // feed in, rapid out (G81, G82 with P, lathe G83 without Q)
    peck,             // full retract to R after each peck (G83, §10 "withdrawn every time")
    high_speed_peck,  // retract d after each peck (G73)
    tap,              // feed in, dwell, spindle reverses, feed out (G84, G74 left hand, G88)
    bore,             // feed in, dwell, feed out (G85, G89, lathe G86/G89)
    bore_stop,        // feed in, spindle stop, rapid out (mill G86)
    fine_bore,        // feed in, dwell, oriented stop, shift Q, rapid out (G76)
    back_bore,        // oriented stop, shift Q, rapid to R below the part, shift back, feed up to Z (G87)
    bore_manual,      // feed in, dwell, spindle stop, the operator retracts (G88)
};

struct Form {
    Kind kind;
    bool lathe;                 // the live-tool form of §10
    std::size_t axis;           // the drilling axis (index into Position)
    bool left_hand = false;     // G74: the spindle turns the other way
};

std::optional<Form> form_of(dialects::FunctionId f) {
    if (f == fn::drilling_cycle || f == fn::drilling_dwell_cycle) return Form{Kind::drill, false, kZ};
    if (f == fn::peck_drilling_cycle) return Form{Kind::peck, false, kZ};
    if (f == fn::high_speed_peck_drilling_cycle) return Form{Kind::high_speed_peck, false, kZ};
    if (f == fn::tapping_cycle) return Form{Kind::tap, false, kZ};
    if (f == fn::left_hand_tapping_cycle) return Form{Kind::tap, false, kZ, true};
    if (f == fn::boring_cycle || f == fn::boring_dwell_cycle) return Form{Kind::bore, false, kZ};
    if (f == fn::boring_spindle_stop_cycle) return Form{Kind::bore_stop, false, kZ};
    if (f == fn::fine_boring_cycle) return Form{Kind::fine_bore, false, kZ};
    if (f == fn::back_boring_cycle) return Form{Kind::back_bore, false, kZ};
    if (f == fn::boring_manual_retract_cycle) return Form{Kind::bore_manual, false, kZ};
    if (f == fn::face_drilling_cycle) return Form{Kind::peck, true, kZ};
    if (f == fn::face_tapping_cycle) return Form{Kind::tap, true, kZ};
    if (f == fn::face_boring_cycle) return Form{Kind::bore, true, kZ};
    if (f == fn::side_drilling_cycle) return Form{Kind::peck, true, kX};
    if (f == fn::side_tapping_cycle) return Form{Kind::tap, true, kX};
    if (f == fn::side_boring_cycle) return Form{Kind::bore, true, kX};
    return std::nullopt;
}

double sign(double v) { return v > kEps ? 1.0 : v < -kEps ? -1.0 : 0.0; }

// One hole, from the hole position at the current level (cycles.md §10 expansion, §11.1–§11.3).
struct Hole {
    Form form;
    double initial, r_level, bottom;   // levels on the drilling axis, program units
    double peck, first_peck_only;      // program units along the axis; 0 = one feed
    double retract, clearance;         // G73 d, G83 re-approach (program units)
    double dwell_s, r_dwell_s, shift;
    bool return_r;
    bool tap_reverses;
    std::optional<int> clamp;
};

Position at(const Context& ctx, std::size_t axis, double level) {
    Position p = ctx.position();
    p[axis] = level;
    return p;
}

// The depths of the pecks from R to the bottom, the last one clipped at the bottom.
bool peck_in(Context& ctx, const Hole& h) {
    const double dir = sign(h.bottom - h.r_level);
    double depth = h.r_level;
    bool first = true;
    while (dir != 0) {
        const double step = first || !h.first_peck_only ? h.peck : 0;
        double next = step > 0 ? depth + dir * step : h.bottom;
        if (dir * (next - h.bottom) >= -kEps) next = h.bottom;
        if (!first && h.form.kind == Kind::peck) {
            // G83: back down at rapid to just above the last depth (§10, §11.3), then feed on; a
            // clearance larger than the hole so far leaves the tool at R.
            const double above = dir * (depth - dir * h.clearance - h.r_level) > 0 ? depth - dir * h.clearance : h.r_level;
            if (!ctx.rapid(at(ctx, h.form.axis, above))) return false;
        }
        if (!ctx.feed(at(ctx, h.form.axis, next))) return false;
        if (next == h.bottom) return true;
        const double out = h.form.kind == Kind::peck ? h.r_level : next - dir * h.retract;
        if (!ctx.rapid(at(ctx, h.form.axis, out))) return false;
        depth = next;
        first = false;
    }
    return true;
}

// Shift the tool by `dx` in X (the oriented-stop shift of G76/G87: +X, [FANUC] parameter RD1/RD2 = 0).
bool shift_x(Context& ctx, double dx) {
    Position p = ctx.position();
    p[kX] += dx;
    return ctx.rapid(p);
}

// G87 back boring [FANUC]: at the initial level an oriented stop and the shift Q, rapid down to the
// R level under the part, shift back, spindle on, feed up to Z, dwell P, oriented stop, shift Q,
// rapid up to the initial level (G87 always returns there: R lies below the part), shift back,
// spindle on.
bool back_bore(Context& ctx, const Hole& h) {
    ctx.message(fmt::format("{}: oriented spindle stop, shift {:g} in +X", ctx.spelling(), h.shift));
    if (!shift_x(ctx, h.shift) || !ctx.rapid(at(ctx, h.form.axis, h.r_level)) || !shift_x(ctx, -h.shift)) return false;
    ctx.message(fmt::format("{}: spindle on (M03), boring upward", ctx.spelling()));
    if (!ctx.feed(at(ctx, h.form.axis, h.bottom))) return false;
    if (h.dwell_s > 0) ctx.dwell(h.dwell_s);
    ctx.message(fmt::format("{}: oriented spindle stop, shift {:g} in +X", ctx.spelling(), h.shift));
    if (!shift_x(ctx, h.shift) || !ctx.rapid(at(ctx, h.form.axis, h.initial)) || !shift_x(ctx, -h.shift)) return false;
    ctx.message(fmt::format("{}: spindle on (M03)", ctx.spelling()));
    return true;
}

bool drill_hole(Context& ctx, const Hole& h) {
    if (h.form.kind == Kind::back_bore) return back_bore(ctx, h);
    const std::size_t axis = h.form.axis;
    const double out_level = h.return_r ? h.r_level : h.initial;
    if (h.clamp) ctx.m_code(*h.clamp);
    if (!ctx.rapid(at(ctx, axis, h.r_level))) return false;
    const bool pecks = (h.form.kind == Kind::peck || h.form.kind == Kind::high_speed_peck) && h.peck > 0;
    if (pecks ? !peck_in(ctx, h) : !ctx.feed(at(ctx, axis, h.bottom))) return false;
    if (h.dwell_s > 0) ctx.dwell(h.dwell_s);
    switch (h.form.kind) {
        case Kind::tap:
            if (h.tap_reverses) {
                ctx.message(fmt::format("{}: spindle reverses at the bottom ({})", ctx.spelling(),
                                        h.form.left_hand ? "M03 direction out" : "M04 direction out"));
                if (!ctx.feed(at(ctx, axis, h.r_level))) return false;
                if (h.r_dwell_s > 0) ctx.dwell(h.r_dwell_s);
                ctx.message(fmt::format("{}: spindle turns forward again", ctx.spelling()));
            }
            break;
        case Kind::bore:
            if (!ctx.feed(at(ctx, axis, h.r_level))) return false;
            break;
        case Kind::bore_stop:
            ctx.message(fmt::format("{}: spindle stops at the bottom, rapid out, spindle restarts", ctx.spelling()));
            break;
        case Kind::bore_manual:
            // [FANUC] G88: the machine stops with the spindle stopped; the operator retracts in a
            // manual mode, and the cycle start rapids to the return level: the dry run takes that rapid.
            ctx.message(fmt::format("{}: spindle stops at the bottom; the operator retracts by hand (manual mode), "
                                    "then cycle start returns at rapid and restarts the spindle", ctx.spelling()));
            break;
        case Kind::fine_bore:
            // [FANUC] oriented stop, shift Q away from the wall, rapid out, shift back, spindle on.
            ctx.message(fmt::format("{}: oriented spindle stop, shift {:g} in +X", ctx.spelling(), h.shift));
            if (!shift_x(ctx, h.shift) || !ctx.rapid(at(ctx, axis, out_level)) || !shift_x(ctx, -h.shift)) return false;
            break;
        default: break;
    }
    if (!ctx.rapid(at(ctx, axis, out_level))) return false;
    if (h.clamp) ctx.m_code(*h.clamp + 1);
    return true;
}

double dwell_seconds(const Context& ctx, std::optional<double> p) {
    if (!p) return 0;
    return ctx.dwell_seconds(*p);
}

// Program units per mm along the axis: X diameters move twice a radius distance (§10 G87).
double axis_scale(const Context& ctx, std::size_t axis) { return axis == kX && ctx.diameter_x() ? 2.0 : 1.0; }

// The levels and words of this block, the modal ones where it omits them.
void update_modal(Context& ctx, const Form& form, DrillModal& m) {
    const std::size_t axis = form.axis;
    const char letter = axis == kX ? 'X' : 'Z';
    const double k = axis_scale(ctx, axis);
    const double initial = m.start[axis];
    if (const auto r = ctx.mm('R')) {
        // Mill form: R is the level (G90) or counts from the initial level (G91); lathe form:
        // always from the initial level (§10 "[FANUC] distance from the initial level").
        m.r_level = form.lathe || ctx.incremental() ? initial + *r * k : *r;
    } else if (!m.has_bottom) {
        m.r_level = initial;   // §10: "omitted = 0"
    }
    const auto inc = ctx.increment(letter);
    if (inc) {
        m.bottom = m.r_level + *inc;
        m.has_bottom = true;
    } else if (const auto b = ctx.mm(letter); b && ctx.names_axis(letter)) {
        m.bottom = ctx.incremental() ? m.r_level + *b : *b;
        m.has_bottom = true;
    }
    // The peck: Q where the code takes it (P/Q units of §0 on the lathe form), else ADV400 K.
    if (ctx.takes('Q') && ctx.has('Q') && (form.kind == Kind::peck || form.kind == Kind::high_speed_peck))
        m.peck = (form.lathe ? *ctx.pq('Q') : *ctx.mm('Q')) * k;
    else if (!ctx.takes('Q') && form.kind == Kind::peck && ctx.has('K'))
        m.peck = *ctx.mm('K') * k;
    if ((form.kind == Kind::fine_bore || form.kind == Kind::back_bore) && ctx.has('Q')) m.shift = *ctx.mm('Q');
    // P dwells only where the code takes it (G82, G89, ...): [FANUC] G81 has no dwell, and a P in
    // its block is said, not run (a Haas habit: `G81 G99 Z-0.05 P0.5`).
    if (ctx.has('P') && ctx.takes('P')) m.dwell_s = dwell_seconds(ctx, ctx.raw('P'));
    else if (ctx.has('P') && !ctx.repeat())
        ctx.message(fmt::format("{}: P is not a word of this cycle (no dwell at the bottom; {} has none)", ctx.spelling(),
                                ctx.spelling()));
    if (form.kind == Kind::tap && ctx.takes('Q') && ctx.has('Q')) m.r_dwell_s = dwell_seconds(ctx, ctx.raw('Q'));
}

// K (or L) holes; K is the peck on a code without Q (ADV400 G83). L obeys drill_repeat_l.
long repeats(const Context& ctx, const Form& form) {
    const bool k_is_peck = form.kind == Kind::peck && !ctx.takes('Q');
    if (!k_is_peck && ctx.has('K')) return std::lround(*ctx.raw('K'));
    if (ctx.has('L')) return ctx.settings().repeat_l ? std::lround(*ctx.raw('L')) : 1;
    return 1;
}

// Where each hole is: the block's position words; incremental words (G91, U/H) step again for
// every repeat (cycles.md §11.1 [FANUC]); H indexes C before every hole, the first one included
// (§10 "the first position is also shifted by the angle H").
struct Positions {
    Position first, step;
};

Positions positions(const Context& ctx, const Form& form) {
    const Position start = ctx.position();
    const Position end = ctx.end_point();
    Positions p{start, {}};
    for (std::size_t a = 0; a < kAxisCount; ++a) {
        // An axis the block does not name moves too when the programmed point is transformed
        // (G16 polar angle, G68, G51, G51.1: executor_transforms.cpp); otherwise end = start there.
        if (a == form.axis || (!ctx.names_axis(kAxisLetters[a]) && end[a] == start[a])) continue;
        p.first[a] = end[a];
        const bool inc = ctx.incremental() || ctx.increment(kAxisLetters[a]).has_value();
        if (inc) p.step[a] = end[a] - start[a];
    }
    if (form.lathe && !ctx.increment('C') && ctx.has('H') && ctx.takes('H')) {
        p.first[kC] = start[kC] + *ctx.raw('H');   // systems B/C: H is the cycle's pitch word
        p.step[kC] = *ctx.raw('H');
    }
    return p;
}

}  // namespace

bool drilling(Context& ctx) {
    const auto form = form_of(ctx.function());
    if (!form) return false;
    DrillModal& m = ctx.drill();
    if (!m.active) {
        m = DrillModal{};
        m.active = true;
        m.start = ctx.position();
    }
    update_modal(ctx, *form, m);
    if (!m.has_bottom) {
        ctx.message(fmt::format("{}: no hole bottom ({}) given yet: no hole", ctx.spelling(), form->axis == kX ? 'X' : 'Z'));
        return true;
    }
    const Settings& s = ctx.settings();
    const double k = axis_scale(ctx, form->axis);
    // The switches are mm (machine/SCHEMA.md); a G20 program moves in inches.
    const double retract = s.high_speed_retract * ctx.per_mm() * k, clearance = s.peck_clearance * ctx.per_mm() * k;
    Hole h{*form,    m.start[form->axis], m.r_level,   m.bottom, m.peck, 0, retract, clearance, m.dwell_s, m.r_dwell_s,
           m.shift, ctx.return_to_r_level(), s.tapping_reverses, std::nullopt};
    h.first_peck_only = !ctx.takes('Q') && s.adv400_k_first_peck_only;
    // The clamp M of the first block holds for the holes of later C-only blocks too (§10 alternative
    // program: "G83 ... M20" then "C90" [inference]; FANUC issues M and M+1 per hole).
    if (form->lathe) {
        if (const auto clamp = ctx.m_word()) m.clamp = clamp;
        h.clamp = m.clamp;
    }
    const Positions where = positions(ctx, *form);
    const long count = repeats(ctx, *form);
    for (long i = 0; i < count; ++i) {
        Position to = ctx.position();
        for (std::size_t a = 0; a < kAxisCount; ++a)
            if (a != form->axis) to[a] = i == 0 ? where.first[a] : to[a] + where.step[a];
        if (!ctx.rapid(to)) return true;
        if (!drill_hole(ctx, h)) return true;
    }
    return true;
}

}  // namespace kerf::interpreter::cycles
