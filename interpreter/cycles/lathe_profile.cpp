// G70–G73, the lathe cycles over a finishing profile N P .. N Q (reference/cycles.md §1–§4).
// Geometry runs in the Z–X plane with X as a radius (contour.hpp); moves go out as diameters.
#include <fmt/format.h>

#include <cmath>

#include "dialects/alarms.hpp"
#include "interpreter/cycles/contour.hpp"

namespace kerf::interpreter::cycles {

namespace fn = dialects::functions;

namespace {

constexpr double kEps = 1e-7;

double sign(double v) { return v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0; }

// Emits one contour segment as its kind (rapid, feed, arc); `feed` overrides the modal F (G70).
bool emit(Context& ctx, const Seg& s, const Position& like, std::optional<double> feed = std::nullopt) {
    const bool dia = ctx.diameter_x();
    const Position to = to_position(s.b, like, dia);
    if (s.kind == EventKind::rapid) return ctx.rapid(to);
    if (s.is_arc()) return ctx.arc(s.kind == EventKind::arc_cw, to, to_position(s.c, like, dia), feed);
    return ctx.feed(to, feed);
}

// Rapid back to the start point A: both axes, or one after the other (machine switch
// rough_return, cycles.md §21.3).
bool return_to(Context& ctx, const Position& a) {
    Position p = ctx.position();
    if (ctx.settings().rough_return == Return::x_then_z) p[0] = a[0];
    if (ctx.settings().rough_return == Return::z_then_x) p[2] = a[2];
    if (p != ctx.position() && !ctx.rapid(p)) return false;
    return ctx.rapid(a);
}

// The second-block allowance Δu/2 (radius) and Δw; Δu is a diameter unless the machine says
// radius (cycles.md §2, §21.2; machine switch finish_allowance_u).
Pt allowance(Context& ctx) {
    const double u = ctx.mm('U').value_or(0);
    const double half = ctx.settings().allowance_u_radius || !ctx.diameter_x() ? u : u / 2;
    return {half, ctx.mm('W').value_or(0)};
}

// --- G70 (§1) ------------------------------------------------------------------------------------

// The profile as written, F of the profile blocks in effect, then rapid back to A; under G41/G42
// the executor offsets the whole path, the return included (semantics.md §5).
void finishing(Context& ctx, const Profile& profile) {
    const bool dia = ctx.diameter_x();
    std::vector<ProfileMove> path;
    for (const Seg& s : contour_of(profile, 0, dia)) {
        ProfileMove m;
        m.kind = s.kind;
        m.end = to_position(s.b, profile.start, dia);
        if (s.is_arc()) m.center = to_position(s.c, profile.start, dia);
        m.feed = profile.moves[s.move].feed;
        path.push_back(m);
    }
    ProfileMove back;
    back.kind = EventKind::rapid;
    back.end = profile.start;
    path.push_back(back);
    ctx.finishing_path(path);
}

// --- G71 / G72 type I (§2, §3) -------------------------------------------------------------------

// Roughing in levels of `level` (X for G71, Z for G72), passes along the other axis, 45° relief
// by e, then one pass along the allowance contour (cycles.md §2 "Expansion, type I").
struct Rough {
    Coord level;                        // the axis the depth of cut steps in
    double depth;                       // Δd
    double retract;                     // e
    bool q_block_may_return = false;    // type II: the Q block is exempt from the monotonic check
};

bool rough_levels(Context& ctx, const Profile& profile, const Rough& r, const Contour& allowance_contour, Pt a, Pt a_allow) {
    const Coord pass = other(r.level);
    const bool dia = ctx.diameter_x();
    const bool rapid_infeed = profile.moves[0].kind == EventKind::rapid;   // G00/G01 in block ns (§2)
    const double s = sign(get(a, r.level) - get(a_allow, r.level));
    for (int k = 1;; ++k) {
        const double level = get(a, r.level) - k * r.depth * s;
        if (s * (level - get(a_allow, r.level)) <= kEps) break;
        const auto cut = first_crossing(allowance_contour, r.level, level);
        const double end = cut ? get(cut->p, pass) : get(allowance_contour.back().b, pass);
        const Pt in = make(r.level, level, get(a, pass));
        const Position in_pos = to_position(in, profile.start, dia);
        if (!(rapid_infeed ? ctx.rapid(in_pos) : ctx.feed(in_pos))) return false;
        if (!ctx.feed(to_position(make(r.level, level, end), profile.start, dia))) return false;
        const double back = sign(get(a, pass) - end);
        const Position relief = to_position(make(r.level, level + s * r.retract, end + back * r.retract), profile.start, dia);
        if (!(ctx.settings().relief == Relief::rapid ? ctx.rapid(relief) : ctx.feed(relief))) return false;
        if (!ctx.rapid(to_position(make(r.level, level + s * r.retract, get(a, pass)), profile.start, dia))) return false;
    }
    return true;
}

// The semi-finishing pass along the allowance contour, clipped where it crosses the pass start
// (O0071: the contour starts at Z3, the pass at Z1).
bool allowance_pass(Context& ctx, const Profile& profile, Coord level, const Contour& contour, Pt a) {
    const Coord pass = other(level);
    const bool dia = ctx.diameter_x();
    Contour path = contour;
    if (const auto clip = first_crossing(contour, pass, get(a, pass))) path = after(contour, *clip);
    if (path.empty()) return true;
    const Pt start = path.front().a;
    const Position in = to_position(make(level, get(start, level), get(a, pass)), profile.start, dia);
    const bool rapid_infeed = profile.moves[0].kind == EventKind::rapid;
    if (!(rapid_infeed ? ctx.rapid(in) : ctx.feed(in))) return false;
    if (std::fabs(get(start, pass) - get(a, pass)) > kEps && !ctx.feed(to_position(start, profile.start, dia))) return false;
    for (const Seg& s : path)
        if (!emit(ctx, s, profile.start)) return false;
    return true;
}

// --- G71 / G72 type II (§2 "Type II differences") ------------------------------------------------
//
// Levels step by Δd while any part of the allowance contour lies deeper than the level (pockets
// included), not only down to A′. At each level the tool walks from the pass start along the level
// and, where the contour rises above it, along the contour (over a hump and down into the next
// pocket: "follows the contour down to the next level"); after the last place where the contour
// is deeper than the level it follows the contour up to the previous level ("the tool following
// the profile where it rises" instead of the 45° relief), steps out by e along the level axis and
// returns at that height, or first out to A's level when a hump stands in the way [inference: the
// seeds show no type II pass table].

struct TypeTwo {
    Coord level, pass;
    double s;              // +1 when the levels step toward smaller values of `level` (OD for G71)
    Pt a;                  // the start point A (radius)
    Contour contour;       // the allowance contour, starting at A's pass coordinate
};

// The allowance contour from A's pass coordinate on: clipped where it crosses it (O0071: Z3 → Z1),
// or led in along its start level when it starts beyond it.
Contour from_pass_start(const Contour& contour, Coord pass, Pt a) {
    if (contour.empty()) return contour;
    if (const auto clip = first_crossing(contour, pass, get(a, pass))) return after(contour, *clip);
    const Pt start = contour.front().a;
    Seg lead;
    lead.a = make(other(pass), get(start, other(pass)), get(a, pass));
    lead.b = start;
    Contour out{lead};
    out.insert(out.end(), contour.begin(), contour.end());
    return out;
}

// A piece of a split contour lies deeper than the level: inside the material the level removes.
bool deeper(const TypeTwo& t, const Seg& piece, double level) {
    return t.s * (level - get(point_at(piece, 0.5), t.level)) > kEps;
}

bool follow(Context& ctx, const Profile& profile, Seg piece) {
    if (piece.kind == EventKind::rapid) piece.kind = EventKind::linear;   // roughing cuts at F
    return emit(ctx, piece, profile.start);
}

// One level: the walk, the climb to the previous level, the step out and the return to the pass start.
bool level_two(Context& ctx, const Profile& profile, const TypeTwo& t, const Rough& r, double level, double previous) {
    const bool dia = ctx.diameter_x();
    const auto at = [&](Pt p) { return to_position(p, profile.start, dia); };
    const Contour pieces = split_at(t.contour, t.level, level);
    std::size_t last = pieces.size();
    for (std::size_t i = 0; i < pieces.size(); ++i)
        if (deeper(t, pieces[i], level)) last = i;
    if (last == pieces.size()) return true;   // the level only touches the contour
    const Pt in = deeper(t, pieces[0], level) ? make(t.level, level, get(t.a, t.pass)) : pieces[0].a;
    const bool rapid_infeed = profile.moves[0].kind == EventKind::rapid;   // G00/G01 in block ns (§2)
    if (!(rapid_infeed ? ctx.rapid(at(in)) : ctx.feed(at(in)))) return false;
    for (std::size_t i = 0; i <= last; ++i) {
        if (!deeper(t, pieces[i], level)) {
            if (!follow(ctx, profile, pieces[i])) return false;
        } else if (i == last || !deeper(t, pieces[i + 1], level)) {
            if (!ctx.feed(at(make(t.level, level, get(pieces[i].b, t.pass))))) return false;
        }
    }
    const Contour rest(pieces.begin() + static_cast<std::ptrdiff_t>(last) + 1, pieces.end());
    const auto top = first_crossing(rest, t.level, previous);
    // Where the tool stands, kept here: ctx.position() is the programmed point while G41/G42 is
    // on (O0016 programs G42 before G71, and roughing ignores it, cycles.md §2).
    Pt p = make(t.level, level, get(pieces[last].b, t.pass));
    for (const Seg& s : top ? until(rest, *top) : rest) {
        if (!follow(ctx, profile, s)) return false;
        p = s.b;
    }
    const double out = get(p, t.level) + t.s * r.retract;
    const Pt relief = make(t.level, out, get(p, t.pass));
    if (!(ctx.settings().relief == Relief::rapid ? ctx.rapid(at(relief)) : ctx.feed(at(relief)))) return false;
    // The way back at the relief height crosses the contour already passed when a hump reaches it.
    const Contour passed(pieces.begin(), pieces.begin() + static_cast<std::ptrdiff_t>(last) + 1);
    double back = out;
    if (t.s * (extreme(passed, t.level, t.s) - out) > -kEps) {
        back = get(t.a, t.level);
        if (!ctx.rapid(at(make(t.level, back, get(p, t.pass))))) return false;
    }
    return ctx.rapid(at(make(t.level, back, get(t.a, t.pass))));
}

bool rough_levels_two(Context& ctx, const Profile& profile, const Rough& r, const Contour& allowance_contour, Pt a, Pt a_allow) {
    TypeTwo t{r.level, other(r.level), sign(get(a, r.level) - get(a_allow, r.level)), a, {}};
    t.contour = from_pass_start(allowance_contour, t.pass, a);
    if (t.s == 0 || t.contour.empty()) return true;
    const double deepest = extreme(t.contour, t.level, -t.s);
    double previous = get(a, r.level);
    for (int k = 1;; ++k) {
        const double level = get(a, r.level) - k * r.depth * t.s;
        if (t.s * (level - deepest) <= kEps) break;
        if (!level_two(ctx, profile, t, r, level, previous)) return false;
        previous = level;
    }
    return true;
}

// The contour without the trailing segments of block `block` (a prefix of `contour`).
Contour before_block(const Contour& contour, const Profile& profile, std::uint32_t block) {
    Contour out = contour;
    while (!out.empty() && profile.moves[out.back().move].block == block) out.pop_back();
    return out;
}

void rough(Context& ctx, const Profile& profile, const Rough& r) {
    const bool dia = ctx.diameter_x();
    if (r.depth <= 0) {
        ctx.alarm(62, fmt::format("{}: depth of cut {} must be positive (FANUC alarm 062)", ctx.spelling(), r.depth));
        return;
    }
    const ProfileMove& first = profile.moves[0];
    // Type II: the first block names both axes (`N1000 G0 X60 W0`, cycles.md §2).
    const bool type2 = first.x_word && first.z_word;
    const Contour finish = contour_of(profile, 1, dia);
    // [Haas] "The Z Axis PQ path must not exceed the original starting location. The only
    // exception is on the Q block." (Haas G71 "Type 2 details", staging-diy.haascnc.com/type-2-details-0):
    // a Haas type II profile may end with its Q block going back, `N20 G00 G40 Z0.1` (corpus
    // enier290188 lathe_hp_2, round_head_plug, valve, weld_pin). The Q block is then left out of the
    // check only; roughing and the semi-finishing pass keep it (it lies outside the stock).
    const Contour checked = r.q_block_may_return && type2 ? before_block(finish, profile, profile.q_block) : finish;
    // The alarm stands at the profile block whose move reverses (an integer `Z-8` read as 0.008 is
    // the usual cause), where the programmer has to look.
    const auto reversal = [&](Coord c) { return first_reversal(checked, c); };
    const Coord axis = type2 ? other(r.level) : reversal(Coord::x) ? Coord::x : Coord::z;
    if (const std::optional<std::size_t> bad = reversal(axis)) {
        ctx.alarm_at(profile.moves[checked[*bad].move].block, alarms::profile_not_monotonic,
                     fmt::format("{}: this move reverses {} in the type {} profile, which must be monotonic (cycles.md §2; "
                                 "FANUC alarm 064)",
                                 ctx.spelling(), axis == Coord::x ? 'X' : 'Z', type2 ? "II" : "I"));
        return;
    }
    const Pt shift = allowance(ctx);
    const Contour allow = shifted(finish, shift.x, shift.z);
    const Pt a = to_pt(profile.start, dia);
    const Pt a_prime = to_pt(first.end, dia);
    const Pt a_allow{a_prime.x + shift.x, a_prime.z + shift.z};
    const auto levels = type2 ? rough_levels_two : rough_levels;
    if (!allow.empty() && !levels(ctx, profile, r, allow, a, a_allow)) return;
    // The semi-finishing pass along the allowance contour, both types ([FANUC] parameter 5105
    // RF1/RF2 = 0: the rough finishing cut is made).
    if (!allowance_pass(ctx, profile, r.level, allow, a)) return;
    return_to(ctx, profile.start);
}

// --- G73 (§4) ------------------------------------------------------------------------------------

// The profile d times, shifted by Δi·(d−j)/(d−1) + Δu/2 and Δk·(d−j)/(d−1) + Δw; each pass
// starts with a rapid from A to the shifted start, ends with a rapid back to A.
void pattern(Context& ctx, const Profile& profile, const Parameters& p) {
    const bool dia = ctx.diameter_x();
    const Pt finish = allowance(ctx);
    const Contour contour = contour_of(profile, 0, dia);
    const int d = std::max(1, p.g73_divisions);
    for (int j = 1; j <= d; ++j) {
        const double share = d == 1 ? 0.0 : static_cast<double>(d - j) / (d - 1);
        const Contour pass = shifted(contour, p.g73_relief_x * share + finish.x, p.g73_relief_z * share + finish.z);
        if (!ctx.rapid(to_position(pass.front().a, profile.start, dia))) return;
        for (const Seg& s : pass)
            if (!emit(ctx, s, profile.start)) return;
        if (!return_to(ctx, profile.start)) return;
    }
}

// The first block of G71–G73 sets the persistent parameters (§0); the block with P and Q runs.
bool first_block(Context& ctx, dialects::FunctionId f) {
    if (ctx.has('P') && ctx.has('Q')) return false;
    Parameters& p = ctx.parameters();
    if (f == fn::rough_turning_cycle) {
        p.g71_depth = ctx.mm('U').value_or(p.g71_depth);
        p.g71_retract = ctx.mm('R').value_or(p.g71_retract);
    } else if (f == fn::rough_facing_cycle) {
        p.g72_depth = ctx.mm('W').value_or(p.g72_depth);
        p.g72_retract = ctx.mm('R').value_or(p.g72_retract);
    } else if (f == fn::pattern_repeating_cycle) {
        p.g73_relief_x = ctx.mm('U').value_or(p.g73_relief_x);
        p.g73_relief_z = ctx.mm('W').value_or(p.g73_relief_z);
        if (const auto r = ctx.raw('R')) p.g73_divisions = static_cast<int>(std::lround(*r));
    }
    return true;
}

}  // namespace

void rough_profile(Context& ctx, const Profile& profile, const RoughCycle& r) {
    rough(ctx, profile, {r.facing ? Coord::z : Coord::x, r.depth, r.retract, r.q_block_may_return});
}

void repeat_pattern(Context& ctx, const Profile& profile, double relief_x, double relief_z, int divisions) {
    Parameters p;
    p.g73_relief_x = relief_x;
    p.g73_relief_z = relief_z;
    p.g73_divisions = divisions;
    pattern(ctx, profile, p);
}

std::optional<Profile> profile_of_block(Context& ctx) {
    const auto p = ctx.raw('P'), q = ctx.raw('Q');
    if (!p || !q) {
        ctx.alarm(62, fmt::format("{} without P and Q: no profile to run (FANUC alarm 062)", ctx.spelling()));
        return std::nullopt;
    }
    auto profile = ctx.profile(*p, *q);
    if (!profile) return std::nullopt;
    if (profile->moves.empty()) {
        ctx.alarm(65, fmt::format("{} P{} Q{}: the profile has no move (FANUC alarm 065)", ctx.spelling(), *p, *q));
        return std::nullopt;
    }
    return profile;
}

void lathe_profile(Context& ctx) {
    const dialects::FunctionId f = ctx.function();
    if (f != fn::finishing_cycle && first_block(ctx, f)) return;
    const auto profile = profile_of_block(ctx);
    if (!profile) return;
    const Parameters& params = ctx.parameters();
    if (f == fn::finishing_cycle) finishing(ctx, *profile);
    else if (f == fn::rough_turning_cycle) rough(ctx, *profile, {Coord::x, params.g71_depth, params.g71_retract, false});
    else if (f == fn::rough_facing_cycle) rough(ctx, *profile, {Coord::z, params.g72_depth, params.g72_retract, false});
    else pattern(ctx, *profile, params);
}

}  // namespace kerf::interpreter::cycles
