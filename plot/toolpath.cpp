#include "plot/toolpath.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

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

// Geometric coordinates in mm: lathe X from the diameter to the radius, inches (an event of a G20
// stretch, Event::inch) times 25.4, as the interpreter hands them to the motion kernel
// (motion/vec.hpp "Units"). The drawing is built in mm and scaled to inches at the end when most
// moves were in inches, so a program that switches units mid-way still draws one part.
motion::Vec3 geometric(const interpreter::Position& p, const ViewOptions& o, bool inch) {
    const bool diameter = o.kind == dialects::MachineKind::lathe && o.diameter_x;
    const double k = inch ? 25.4 : 1.0;
    return {(diameter ? p[0] / 2 : p[0]) * k, p[1] * k, p[2] * k};
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
// centre. The view plane is tried first.
std::optional<motion::Arc> rebuild_arc(const Event& e, const ViewOptions& o) {
    if (!e.center) return std::nullopt;
    const motion::Vec3 s = geometric(e.start, o, e.inch);
    const motion::Vec3 t = geometric(e.end, o, e.inch);
    const motion::Vec3 c = geometric(*e.center, o, e.inch);
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

// Positions are as programmed, inches after G20 (Event::inch, docs/trace.md): each move votes for
// the unit of the drawing, +1 inch, -1 metric.
int inch_vote(const Event& e) { return e.inch ? 1 : -1; }

Piece line_piece(Stroke stroke, Point from, Point to) {
    Piece p;
    p.stroke = stroke;
    p.from = from;
    p.to = to;
    return p;
}

// A view-plane arc as one piece; an arc in another plane as the line pieces of its projection,
// a point every 5°.
void arc_pieces(const motion::Arc& arc, Stroke stroke, const ViewOptions& o, Box2& bounds, std::vector<Piece>& out) {
    const motion::Box box = motion::bounds(arc);   // exact: includes the quadrant points passed
    bounds.extend(project(box.min, o));
    bounds.extend(project(box.max, o));
    if (arc.plane == view_plane(o)) {
        // A helix about the view normal projects onto its circle: the third axis drops out.
        Piece p = line_piece(stroke, project(arc.start, o), project(arc.end, o));
        p.arc = true;
        p.radius = arc.radius;
        p.sweep = arc.sweep;
        p.mid = project(motion::point_at(arc, 0.5), o);
        out.push_back(p);
        return;
    }
    const int n = std::clamp(static_cast<int>(std::ceil(std::fabs(arc.sweep) / kPolylineStep)), 2, 72);
    Point from = project(arc.start, o);
    for (int i = 1; i <= n; ++i) {
        const Point to = project(motion::point_at(arc, static_cast<double>(i) / n), o);
        out.push_back(line_piece(stroke, from, to));
        from = to;
    }
}

bool cuts(Stroke s) { return s != Stroke::rapid; }

// The pieces of one move into `out` (cleared first; reused from move to move).
void pieces_of(const Event& e, Stroke stroke, const ViewOptions& o, Box2& bounds, std::vector<Piece>& out) {
    out.clear();
    if (e.kind == EventKind::arc_cw || e.kind == EventKind::arc_ccw)
        if (const std::optional<motion::Arc> arc = rebuild_arc(e, o)) return arc_pieces(*arc, stroke, o, bounds, out);
    // A line, or an arc that is not a circle in any plane (should not come from the interpreter):
    // the chord at least.
    const Piece p = line_piece(stroke, project(geometric(e.start, o, e.inch), o), project(geometric(e.end, o, e.inch), o));
    bounds.extend(p.from);
    bounds.extend(p.to);
    out.push_back(p);
}

void add_length(Toolpath& t, Stroke stroke, double mm) {
    switch (stroke) {
    case Stroke::rapid: t.rapid_mm += mm; break;
    case Stroke::feed: t.feed_mm += mm; break;
    case Stroke::thread: t.thread_mm += mm; break;
    }
}

double length(Point a, Point b) { return std::hypot(b.h - a.h, b.v - a.v); }

// The drawing, built in mm, in another unit (× k): points, arc radii, bounds, resolution.
void scale_to(Toolpath& t, double k) {
    const auto scaled = [k](Point p) { return Point{p.h * k, p.v * k}; };
    for (Piece& p : t.pieces) {
        p.from = scaled(p.from);
        p.to = scaled(p.to);
        p.mid = scaled(p.mid);
        p.radius *= k;
    }
    for (Point& a : t.alarms) a = scaled(a);
    t.start = scaled(t.start);
    t.end = scaled(t.end);
    const auto scaled_box = [k](const Box2& b) { return Box2{b.h_min * k, b.h_max * k, b.v_min * k, b.v_max * k, b.empty}; };
    t.bounds = scaled_box(t.bounds);
    t.part_bounds = scaled_box(t.part_bounds);
    t.resolution *= k;
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

// --- the builder ----------------------------------------------------------------------------------

std::size_t ToolpathBuilder::KeyHash::operator()(const Key& k) const {
    std::size_t h = k.kind;
    for (const std::int64_t v : {k.a, k.b, k.c, k.d, k.e, k.f}) h = h * 1000003u ^ std::hash<std::int64_t>{}(v);
    return h;
}

std::int64_t ToolpathBuilder::cell(double v) const {
    // Far outside any drawing (a 1e300 coordinate) the cells saturate: such pieces still compare.
    const double c = std::round(v / grid_);
    return static_cast<std::int64_t>(std::clamp(c, -9.0e18, 9.0e18));
}

ToolpathBuilder::Key ToolpathBuilder::key_of(const Piece& p) const {
    Key k{cell(p.from.h), cell(p.from.v), cell(p.to.h), cell(p.to.v), 0, 0,
          static_cast<std::uint8_t>(static_cast<int>(p.stroke) * 4 + (p.arc ? 1 + (p.sweep > 0) : 0))};
    if (p.arc) {
        k.e = cell(p.mid.h);
        k.f = cell(p.mid.v);
    }
    return k;
}

void ToolpathBuilder::add(const interpreter::Event& e) {
    if (e.kind == EventKind::alarm) {
        if (!finite(e.end) || t_.alarms.size() >= kMaxAlarms) return;
        t_.alarms.push_back(project(geometric(e.end, options_, e.inch), options_));
        t_.bounds.extend(t_.alarms.back());
        t_.part_bounds.extend(t_.alarms.back());   // where the run stopped belongs to the picture
        return;
    }
    const std::optional<Stroke> stroke = stroke_of(e.kind);
    if (!stroke || !finite(e)) return;
    const int vote = inch_vote(e);
    inch_votes_ += vote > 0;
    metric_votes_ += vote < 0;
    add_length(t_, *stroke, e.length_mm);
    ++t_.moves;
    Box2 box;   // the move's own
    pieces_of(e, *stroke, options_, box, move_pieces_);
    for (const Point corner : {Point{box.h_min, box.v_min}, Point{box.h_max, box.v_max}}) {
        t_.bounds.extend(corner);
        if (cuts(*stroke)) t_.part_bounds.extend(corner);
    }
    if (t_.moves == 1) t_.start = move_pieces_.front().from;
    t_.end = move_pieces_.back().to;
    fit_grid();
    bool drawn = true;
    for (const Piece& p : move_pieces_) drawn = add_piece(p) && drawn;
    if (!drawn) ++t_.not_drawn;
}

// The grid is the power of two at least 1/kGridCells of the framed extent, so it changes only when
// that doubles. Framing the part, the grid follows the whole drawing until the first cutting move
// and then the part (once finer, for the rapids from home that came first): a part far from home
// is drawn as finely as one alone.
void ToolpathBuilder::fit_grid() {
    const bool on_part = options_.frame == Frame::part && !t_.part_bounds.empty;
    const Box2& framed = on_part ? t_.part_bounds : t_.bounds;
    const double extent = std::max(framed.h_max - framed.h_min, framed.v_max - framed.v_min);
    if (!(extent > 0) || !std::isfinite(extent)) {
        if (grid_ == 0) grid_ = 1e-9;   // one point so far: exact
        return;
    }
    const bool to_part = on_part && !grid_on_part_;
    grid_on_part_ = on_part;
    if (extent <= grid_ * kGridCells && !to_part) return;   // the common case: the grid still fits
    const double wanted = std::exp2(std::ceil(std::log2(extent / kGridCells)));
    if (wanted > grid_ || (to_part && wanted < grid_)) resimplify(wanted);
}

void ToolpathBuilder::resimplify(double grid) {
    grid_ = grid;
    std::vector<Piece> pieces = std::move(t_.pieces);
    t_.pieces.clear();
    drawn_.clear();
    open_ = false;
    has_direction_ = false;
    resimplifying_ = true;
    for (Piece& p : pieces) add_piece(std::move(p));   // the last one stays open
    resimplifying_ = false;
}

// A line continuing the open one (the same stroke, from where it ends) joins it while the open line
// is shorter than a cell, or while the new end stays within half a cell of the open line's
// direction and goes on forward (Reumann–Witkam): every point merged away lies within about a cell
// of the line drawn, so a curve made of tiny moves stays a curve.
bool ToolpathBuilder::extend_open_line(const Piece& p) {
    if (!open_ || p.arc || t_.pieces.empty()) return false;
    Piece& last = t_.pieces.back();
    if (last.stroke != p.stroke || length(last.to, p.from) > grid_ * 1e-6) return false;
    if (has_direction_) {
        const double dh = p.to.h - last.from.h, dv = p.to.v - last.from.v;
        const double across = std::fabs(dh * direction_.v - dv * direction_.h);
        const double along_new = dh * direction_.h + dv * direction_.v;
        const double along_old = (last.to.h - last.from.h) * direction_.h + (last.to.v - last.from.v) * direction_.v;
        if (across > grid_ / 2 || along_new < along_old - grid_ / 2) return false;
    }
    last.to = p.to;
    set_direction(last);
    return true;
}

// The open line's direction, once it is a cell long.
void ToolpathBuilder::set_direction(const Piece& line) {
    if (has_direction_) return;
    const double l = length(line.from, line.to);
    if (!(l >= grid_)) return;
    direction_ = {(line.to.h - line.from.h) / l, (line.to.v - line.from.v) / l};
    has_direction_ = true;
}

// False when the picture is full and the piece is not drawn.
bool ToolpathBuilder::add_piece(Piece p) {
    if (p.arc && std::fabs(p.sweep) * p.radius < grid_) p.arc = false;   // an arc smaller than a cell is a line
    if (extend_open_line(p)) return true;
    close_open();
    if (full_) return false;
    t_.pieces.push_back(p);
    if (p.arc) {
        finalize_last();
        return true;
    }
    open_ = true;
    has_direction_ = false;
    set_direction(p);
    return true;
}

void ToolpathBuilder::close_open() {
    if (!open_) return;
    open_ = false;
    finalize_last();
}

// The last piece is final: dropped when it repeats one drawn before; when the picture is full,
// the grid coarsens, and at the coarsest one the picture stops growing.
void ToolpathBuilder::finalize_last() {
    if (!drawn_.insert(key_of(t_.pieces.back())).second) {
        t_.pieces.pop_back();
        return;
    }
    if (t_.pieces.size() < kMaxPieces || full_ || resimplifying_) return;
    const double extent = std::max(t_.bounds.h_max - t_.bounds.h_min, t_.bounds.v_max - t_.bounds.v_min);
    while (t_.pieces.size() > kMaxPieces / 2 && grid_ * 2 <= extent / kCoarsestCells) resimplify(grid_ * 2);
    full_ = t_.pieces.size() > kMaxPieces / 2;
}

Toolpath ToolpathBuilder::finish() && {
    close_open();
    t_.inch = inch_votes_ > metric_votes_;
    t_.resolution = grid_;
    if (t_.inch) scale_to(t_, 1 / 25.4);
    return std::move(t_);
}

Toolpath build_toolpath(const std::vector<interpreter::Event>& events, const ViewOptions& options) {
    ToolpathBuilder builder(options);
    for (const Event& e : events) builder.add(e);
    return std::move(builder).finish();
}

}  // namespace kerf::plot
