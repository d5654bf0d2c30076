#include "interpreter/compensation/radius_compensation.hpp"

#include <cmath>

namespace kerf::interpreter::compensation {

using motion::CornerClass;
using motion::Element;
using motion::P2;

namespace {

constexpr double kClose = 1e-6;   // mm
// Elements meant to be tangent meet at a fraction of a degree in CAM output (arcs written with four
// decimals in inch): where their offsets do not meet ahead of the tool, FANUC joins them with a
// minute straight move instead of an alarm (differential A5: 1006.nc, O0057, CGIP11719, O0003).
constexpr double kNearlyTangent = 1.0 * 3.14159265358979323846 / 180;   // radians

P2 left_of(P2 tangent, int side, double r) { return motion::left_normal(tangent) * (side * r); }

ToolMove line_to(P2 p) { return {p, false, {}, true}; }

Alarm overcut(const char* what) {
    // FANUC alarm 041 "interference in cutter compensation" [FANUC]; semantics.md §6.
    return {41, std::string("interference in cutter / nose radius compensation: ") + what + " (over-cut, alarm 041)"};
}

Alarm arc_start_cancel(bool start) {
    // [FANUC] alarm 034: start-up or cancel in a G02/G03 block; semantics.md §5 (seed 003 "should
    // be commanded or cancelled with G00 or G01").
    return {34, start ? "compensation started in an arc block (G02/G03): start it on G00/G01 (alarm 034)"
                      : "compensation cancelled in an arc block (G02/G03): cancel it on G00/G01 (alarm 034)"};
}

bool nearly_tangent(const Programmed& a, const Programmed& b) {
    return std::fabs(motion::turn_angle(motion::end_tangent(a.path), motion::start_tangent(b.path))) < kNearlyTangent;
}

}  // namespace

P2 tip_vector(int tip, double r) {
    // {Z, X} unit components per tip number (see the header); 0 and 9: the nose centre.
    static constexpr double kDir[10][2] = {{0, 0},  {1, 1},  {-1, 1}, {-1, -1}, {1, -1},
                                           {1, 0},  {0, 1},  {-1, 0}, {0, -1},  {0, 0}};
    if (tip < 0 || tip > 9) return {};
    return {kDir[tip][0] * r, kDir[tip][1] * r};
}

Step RadiusCompensation::step(const Programmed& current, const std::optional<Programmed>& next) {
    if (!engaged_) {
        tool_ = current.path.start;
        if (current.side == 0) {
            Step s;
            run(s, {current.path.end, current.path.arc, current.path.center, current.path.ccw});
            return s;
        }
        return start_up(current, next);
    }
    return current.side == 0 ? cancel(current) : follow(current, next);
}

Step RadiusCompensation::start_up(const Programmed& current, const std::optional<Programmed>& next) {
    Step s;
    if (current.path.arc) {
        s.alarm = arc_start_cancel(true);
        return s;
    }
    const P2 e = current.path.end;
    const bool has_next = next && next->side != 0 && next->moves();
    if (!current.moves()) {
        // No motion in the block: the centre moves at once perpendicular to the next element
        // (seed 004 ex. 2 "G42 D02": point 1 → point 2); without a next element it stays.
        if (has_next) run(s, line_to(e + left_of(motion::start_tangent(next->path), current.side, current.radius)));
        engaged_ = true;
        return s;
    }
    const P2 t = motion::start_tangent(current.path);
    engaged_ = true;
    if (!has_next) {
        run(s, line_to(e + left_of(t, current.side, current.radius)));
        return s;
    }
    const P2 t_next = motion::start_tangent(next->path);
    const CornerClass c = motion::classify_corner(t, t_next, current.side);
    // Type A, an inside corner (both types) and a straight run: the centre ends perpendicular
    // to the next element at its start ([FANUC] start-up figures); ADV400 builds the offset up
    // along the first move the same way (semantics.md §6 "diagonal lead-in").
    if (settings_.start == StartType::a || c == CornerClass::inside || c == CornerClass::straight ||
        settings_.corners == CornerStyle::arc) {
        run(s, line_to(e + left_of(t_next, current.side, current.radius)));
        return s;
    }
    // Type B at an outside corner: the corner of the start-up block's offset and the next one's.
    const auto a = motion::offset_element(current.path, current.side * current.radius);
    const auto b = motion::offset_element(next->path, next->side * next->radius);
    const auto j = a && b ? join(*a, *b, current, *next, e, false) : std::nullopt;
    if (!j) {
        run(s, line_to(e + left_of(t_next, current.side, current.radius)));
        return s;
    }
    run(s, line_to(j->extension ? *j->extension : j->end));
    entry_ = j->entry;
    return s;
}

Step RadiusCompensation::cancel(const Programmed& current) {
    Step s;
    if (current.path.arc) {
        s.alarm = arc_start_cancel(false);
        return s;
    }
    for (const ToolMove& m : entry_) run(s, m);
    entry_.clear();
    if (motion::norm(current.path.end - tool_) > kClose) run(s, line_to(current.path.end));
    engaged_ = false;
    return s;
}

Step RadiusCompensation::follow(const Programmed& current, const std::optional<Programmed>& next) {
    Step s;
    const auto a = motion::offset_element(current.path, current.side * current.radius);
    if (!a) {
        s.alarm = overcut("an inside arc of smaller radius than the tool");
        return s;
    }
    for (const ToolMove& m : entry_) run(s, m);
    entry_.clear();
    // The element's end: perpendicular without a next element; the corner with the next one,
    // whose offset is the cancel block's own when it cancels (type B) or is its perpendicular (A).
    Join j{a->end, std::nullopt, {}};
    if (next && next->moves()) {
        const bool cancels = next->side == 0;
        const Programmed as_next = cancels ? Programmed{next->path, current.side, current.radius} : *next;
        const CornerClass c = motion::classify_corner(motion::end_tangent(current.path), motion::start_tangent(next->path),
                                                      current.side);
        const bool perpendicular = cancels && (settings_.start == StartType::a || c == CornerClass::inside);
        const auto b = motion::offset_element(as_next.path, as_next.side * as_next.radius);
        if (!perpendicular && b) {
            auto joined = join(*a, *b, current, as_next, current.path.end, cancels);
            // A nearly tangent corner whose offsets miss each other (or meet behind the tool): the
            // element runs to its own end and a minute move joins the next one.
            if ((!joined || !motion::ahead_on(*a, tool_, joined->end)) && nearly_tangent(current, as_next))
                joined = straight_join(*a, *b);
            if (!joined) {
                s.alarm = overcut("the offset paths of this block and the next do not meet");
                return s;
            }
            j = *joined;
        }
    }
    if (!motion::ahead_on(*a, tool_, j.end)) {
        s.alarm = overcut("the block is shorter than the radius allows");
        return s;
    }
    // A line's extension runs on along the line: one move.
    if (!(j.extension && !a->arc)) run(s, {j.end, a->arc, a->center, a->ccw});
    if (j.extension) run(s, line_to(*j.extension));
    entry_ = j.entry;
    return s;
}

RadiusCompensation::Join RadiusCompensation::straight_join(const Element& a, const Element& b) {
    Join j{a.end, std::nullopt, {}};
    if (motion::norm(b.start - a.end) > kClose) j.entry.push_back(line_to(b.start));
    return j;
}

std::optional<RadiusCompensation::Join> RadiusCompensation::join(const Element& a, const Element& b, const Programmed& pa,
                                                                const Programmed& pb, P2 corner, bool cancel_block) const {
    const P2 t_in = motion::end_tangent(pa.path), t_out = motion::start_tangent(pb.path);
    const CornerClass c = motion::classify_corner(t_in, t_out, pa.side);
    Join j{a.end, std::nullopt, {}};
    // The line of a cancel block ends at its programmed end: it starts where the corner leaves it.
    const auto connect_to_b = [&](Join& out) {
        if (b.arc || cancel_block) out.entry.push_back(line_to(b.start));
    };
    // Tangent arcs whose ends are rounded to the program's last digit (O0057 N2101: a 0.5 in arc
    // running into a 0.35 in one inside it; 1006.nc N6150: half circles whose centres differ by
    // 0.0001 in) turn by a hair: their offsets touch rather than cross, and where they "meet" is
    // noise. An inside corner whose offsets end within the end tolerance of each other is joined
    // by the shift between them: it errs by less than that tolerance (with no radius, not at all).
    const bool tangent = c == CornerClass::straight ||
                         (c == CornerClass::inside && motion::norm(b.start - a.end) <= settings_.end_tolerance);
    if (tangent || pa.side != pb.side) {
        // A tangent run (or a side change: seed 004 ex. 2 "the centre first shifts from point 3
        // to point 4"): where the offsets meet, else a straight shift between them at the start of
        // the next block (a D change, ex. 3 "the tool first shifts up by 2 mm").
        const auto p = tangent ? std::nullopt : motion::meet(a, b, corner);
        if (p && motion::norm(*p - corner) <= 2 * std::max(pa.radius, pb.radius) + kClose) j.end = *p;
        else if (motion::norm(b.start - a.end) > kClose) j.entry.push_back(line_to(b.start));
        return j;
    }
    if (c == CornerClass::inside) {
        const auto p = motion::meet(a, b, corner);
        if (!p) return std::nullopt;
        j.end = *p;
        return j;
    }
    if (settings_.corners == CornerStyle::arc) {
        // ADV400: an arc about the corner point with the cutter radius (semantics.md §6).
        j.entry.push_back({b.start, true, corner, motion::turn_angle(t_in, t_out) > 0});
        return j;
    }
    if (c == CornerClass::outside) {
        // 90° or more: the offset paths joined where they cross (a crossing of an arc's support
        // far from the corner is not the join: then the acute rule below).
        const auto p = motion::meet(a, b, corner);
        if (p && motion::norm(*p - corner) <= std::sqrt(2.0) * std::max(pa.radius, pb.radius) + kClose) {
            j.end = *p;
            return j;
        }
    }
    // Acute outside corner: both elements extended by the radius, joined by a straight move.
    j.extension = a.end + t_in * pa.radius;
    const P2 before_b = b.start - t_out * pb.radius;
    j.entry.push_back(line_to(before_b));
    connect_to_b(j);
    return j;
}

}  // namespace kerf::interpreter::compensation
