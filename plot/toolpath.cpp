#include "plot/toolpath.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "motion/arc.hpp"

namespace kerf::plot {

namespace {

using interpreter::Event;
using interpreter::EventKind;

// An arc out of the view plane is drawn as a polyline with a point every 5° (smooth at any scale
// the plot uses; a full circle is 72 segments).
constexpr double kPolylineStep = std::numbers::pi / 36;

motion::Plane view_plane(const ViewOptions& o) {
    return o.kind == dialects::MachineKind::lathe ? motion::Plane::zx : motion::Plane::xy;
}

// Geometric coordinates: lathe X from the diameter to the radius, as the interpreter hands them to
// the motion kernel (motion/vec.hpp "Units").
motion::Vec3 geometric(const interpreter::Position& p, const ViewOptions& o) {
    const bool diameter = o.kind == dialects::MachineKind::lathe && o.diameter_x;
    return {diameter ? p[0] / 2 : p[0], p[1], p[2]};
}

// The view plane's frame is (right, up): see toolpath.hpp.
Point project(motion::Vec3 p, const ViewOptions& o) {
    const motion::PlanePoint q = motion::to_plane(p, view_plane(o));
    return {q.first, q.second};
}

bool finite(const interpreter::Position& p) {
    return std::all_of(p.begin(), p.end(), [](double v) { return std::isfinite(v); });
}

bool finite(const Event& e) {
    return finite(e.start) && finite(e.end) && (!e.center || finite(*e.center)) && std::isfinite(e.radius);
}

std::optional<Stroke> stroke_of(EventKind kind) {
    switch (kind) {
    case EventKind::rapid: return Stroke::rapid;
    case EventKind::linear:
    case EventKind::arc_cw:
    case EventKind::arc_ccw: return Stroke::feed;
    case EventKind::thread: return Stroke::thread;
    default: return std::nullopt;
    }
}

// The view plane first, then the other two.
std::vector<motion::Plane> planes_to_try(const ViewOptions& o) {
    std::vector<motion::Plane> planes{view_plane(o)};
    for (const motion::Plane p : {motion::Plane::xy, motion::Plane::zx, motion::Plane::yz})
        if (p != planes.front()) planes.push_back(p);
    return planes;
}

// The arc of an event, rebuilt by the motion kernel from start, end and centre. Events do not
// carry the plane; it is the plane in which the centre has the start's normal coordinate (the
// kernel's convention, motion/arc.hpp "Arc::center") and start and end are equally far from the
// centre. The view plane is tried first. (Event::radius is not used: it is in mm, the positions
// are in program units.)
std::optional<motion::Arc> rebuild_arc(const Event& e, const ViewOptions& o) {
    if (!e.center) return std::nullopt;
    const motion::Vec3 s = geometric(e.start, o);
    const motion::Vec3 t = geometric(e.end, o);
    const motion::Vec3 c = geometric(*e.center, o);
    const double size = motion::distance(s, c);
    const double eps = 1e-6 * std::max(1.0, size);
    motion::ArcOptions options;
    // The end may be off the circle by the machine's arc tolerance (the kernel's spiral): a
    // generous bound here, the normal coordinate decides the plane.
    options.radius_tolerance = 0.1 * size + 0.05;
    const motion::ArcDirection dir = e.kind == EventKind::arc_cw ? motion::ArcDirection::cw : motion::ArcDirection::ccw;
    for (const motion::Plane plane : planes_to_try(o)) {
        if (std::fabs(motion::to_plane(s, plane).normal - motion::to_plane(c, plane).normal) > eps) continue;
        const motion::ArcResult r = motion::arc_from_center(s, t, plane, dir, c - s, options);
        if (r) return r.arc();
    }
    return std::nullopt;
}

// Positions are as programmed (inches after G20) and lengths in mm (docs/trace.md), so the ratio
// of a feed line's length to its programmed length tells the unit of the drawing.
bool programmed_in_inches(const std::vector<Event>& events, const ViewOptions& o) {
    int inch = 0;
    int metric = 0;
    for (const Event& e : events) {
        if (e.kind != EventKind::linear || !finite(e)) continue;
        const double programmed = motion::distance(geometric(e.start, o), geometric(e.end, o));
        if (programmed < 1e-6 || e.length_mm <= 0) continue;
        const double ratio = e.length_mm / programmed;
        if (std::fabs(ratio - 25.4) < 0.254) ++inch;
        else if (std::fabs(ratio - 1) < 0.01) ++metric;
    }
    return inch > metric;
}

Piece line_piece(Stroke stroke, const Event& e, const ViewOptions& o, Box2& bounds) {
    Piece p;
    p.stroke = stroke;
    p.from = project(geometric(e.start, o), o);
    p.to = project(geometric(e.end, o), o);
    bounds.extend(p.from);
    bounds.extend(p.to);
    return p;
}

Piece arc_piece(const motion::Arc& arc, const ViewOptions& o, Box2& bounds) {
    Piece p;
    p.from = project(arc.start, o);
    p.to = project(arc.end, o);
    if (arc.plane == view_plane(o)) {
        // A helix about the view normal projects onto its circle: the third axis drops out.
        p.arc = true;
        p.radius = arc.radius;
        p.sweep = arc.sweep;
        p.mid = project(motion::point_at(arc, 0.5), o);
    } else {
        const int n = std::clamp(static_cast<int>(std::ceil(std::fabs(arc.sweep) / kPolylineStep)), 2, 72);
        for (int i = 1; i <= n; ++i) p.polyline.push_back(project(motion::point_at(arc, static_cast<double>(i) / n), o));
    }
    const motion::Box box = motion::bounds(arc);   // exact: includes the quadrant points passed
    bounds.extend(project(box.min, o));
    bounds.extend(project(box.max, o));
    return p;
}

Piece piece_of(const Event& e, Stroke stroke, const ViewOptions& o, Box2& bounds) {
    if (e.kind == EventKind::arc_cw || e.kind == EventKind::arc_ccw) {
        if (const std::optional<motion::Arc> arc = rebuild_arc(e, o)) {
            Piece p = arc_piece(*arc, o, bounds);
            p.stroke = stroke;
            return p;
        }
        // Not a circle in any plane (should not come from the interpreter): the chord at least.
    }
    return line_piece(stroke, e, o, bounds);
}

void add_length(Toolpath& t, Stroke stroke, double mm) {
    switch (stroke) {
    case Stroke::rapid: t.rapid_mm += mm; break;
    case Stroke::feed: t.feed_mm += mm; break;
    case Stroke::thread: t.thread_mm += mm; break;
    }
}

}  // namespace

void Box2::extend(Point p) {
    if (empty) {
        h_min = h_max = p.h;
        v_min = v_max = p.v;
        empty = false;
        return;
    }
    h_min = std::min(h_min, p.h);
    h_max = std::max(h_max, p.h);
    v_min = std::min(v_min, p.v);
    v_max = std::max(v_max, p.v);
}

Toolpath build_toolpath(const std::vector<interpreter::Event>& events, const ViewOptions& options) {
    Toolpath t;
    t.inch = programmed_in_inches(events, options);
    for (const Event& e : events) {
        if (e.kind == EventKind::alarm) {
            if (!finite(e.end)) continue;
            t.alarms.push_back(project(geometric(e.end, options), options));
            t.bounds.extend(t.alarms.back());
            continue;
        }
        const std::optional<Stroke> stroke = stroke_of(e.kind);
        if (!stroke || !finite(e)) continue;
        add_length(t, *stroke, e.length_mm);
        t.pieces.push_back(piece_of(e, *stroke, options, t.bounds));
    }
    return t;
}

}  // namespace kerf::plot
