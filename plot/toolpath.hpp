// The trace seen in the plane of the drawing: every move of the interpreter's events as a line,
// an arc of the view plane, or (an arc in another plane) a projected polyline, with the box that
// holds them. The SVG writer (plot/svg.hpp) only scales and prints what this gives.
//
// Views (the issue: "XZ with the part axis for lathes, XY for mills"):
// * lathe: Z to the right, X up, X at the radius (events carry the diameter when diameter_x).
//   This is the view of reference/semantics.md §3 ("Z to the right and X (radius) upwards – the
//   view used in all SPINNER figures"), where G02 appears clockwise.
// * mill: X to the right, Y up, seen from +Z, where G02 is clockwise (semantics.md §3).
// In both views the view plane's frame (motion/vec.hpp: G18 = (Z, X), G17 = (X, Y)) is
// (right, up), so a motion::Arc's signed sweep is the sweep as seen: > 0 counter-clockwise.
#pragma once

#include <vector>

#include "dialects/dialect.hpp"
#include "interpreter/events.hpp"

namespace kerf::plot {

struct ViewOptions {
    dialects::MachineKind kind = dialects::MachineKind::mill;
    bool diameter_x = false;   // lathe: event X is a diameter; it is drawn at the radius
};

// A point of the drawing in program units (mm, or inches after G20): h to the right, v up.
struct Point {
    double h = 0;
    double v = 0;
};

struct Box2 {
    double h_min = 0, h_max = 0, v_min = 0, v_max = 0;
    bool empty = true;
    void extend(Point p);
};

enum class Stroke { rapid, feed, thread };

struct Piece {
    Stroke stroke = Stroke::feed;
    Point from;
    Point to;
    // An arc in the view plane. sweep: signed radians as seen (> 0 counter-clockwise, v up);
    // ±2π is a full circle. mid: the point half-way along it (arcs over 180° are drawn in halves).
    bool arc = false;
    double radius = 0;
    double sweep = 0;
    Point mid;
    // An arc in another plane (or a helix around a horizontal axis), projected: the points after
    // `from`, the last one `to`. Empty for lines and view-plane arcs.
    std::vector<Point> polyline;
};

struct Toolpath {
    std::vector<Piece> pieces;     // in execution order
    std::vector<Point> alarms;     // where alarms stopped the run
    Box2 bounds;                   // every point the path reaches, arc extremes included
    bool inch = false;             // the points are in inches (G20): positions are as programmed
    double rapid_mm = 0;           // path lengths from the events (the interpreter's, in mm)
    double feed_mm = 0;
    double thread_mm = 0;
};

// Events that are not motion (tool change, spindle, ...) are skipped; alarms become markers.
Toolpath build_toolpath(const std::vector<interpreter::Event>& events, const ViewOptions& options);

}  // namespace kerf::plot
