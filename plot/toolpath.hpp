// The trace seen in the plane of the drawing: every move of the interpreter's events as a line,
// an arc of the view plane, or (an arc in another plane) projected line pieces, simplified to the
// drawing's resolution, with the box that holds them. The SVG writer (plot/svg.hpp) only scales
// and prints what this gives.
//
// Views (the issue: "XZ with the part axis for lathes, XY for mills"):
// * lathe: Z to the right, X up, X at the radius (events carry the diameter when diameter_x).
//   This is the view of reference/semantics.md §3 ("Z to the right and X (radius) upwards – the
//   view used in all SPINNER figures"), where G02 appears clockwise.
// * mill: X to the right, Y up, seen from +Z, where G02 is clockwise (semantics.md §3).
// In both views the view plane's frame (motion/vec.hpp: G18 = (Z, X), G17 = (X, Y)) is
// (right, up), so a motion::Arc's signed sweep is the sweep as seen: > 0 counter-clockwise.
#pragma once

#include <cstdint>
#include <unordered_set>
#include <vector>

#include "dialects/dialect.hpp"
#include "interpreter/events.hpp"
#include "interpreter/sink.hpp"

namespace kerf::plot {

// What the picture frames: the part (the cutting moves: feeds, arcs, threads, and where alarms
// stopped the run), so that the home returns of a lathe program (G28/G53 far from the part) do not
// shrink it to a corner of the picture; or the whole path (`kerf plot --frame all`).
enum class Frame { part, all };

struct ViewOptions {
    dialects::MachineKind kind = dialects::MachineKind::mill;
    bool diameter_x = false;   // lathe: event X is a diameter; it is drawn at the radius
    Frame frame = Frame::part;
};

// A point of the drawing in its unit (mm, or inches when most moves were in G20: Toolpath::inch),
// h to the right, v up.
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
    // Arcs in other planes are projected into line pieces.
    bool arc = false;
    double radius = 0;
    double sweep = 0;
    Point mid;
};

struct Toolpath {
    std::vector<Piece> pieces;     // in execution order, simplified (below)
    std::vector<Point> alarms;     // where alarms stopped the run (at most kMaxAlarms)
    Box2 bounds;                   // every point the path reaches, arc extremes included
    Box2 part_bounds;              // the cutting moves (arc extremes included) and the alarms; empty without them
    Point start, end;              // where the first move starts and the last one ends
    bool inch = false;             // the points are in inches (most moves ran under G20)
    double rapid_mm = 0;           // path lengths from the events (the interpreter's, in mm)
    double feed_mm = 0;
    double thread_mm = 0;
    std::uint64_t moves = 0;       // motion events seen
    std::uint64_t not_drawn = 0;   // moves left out because the picture was full (kMaxPieces)
    double resolution = 0;         // the grid of the simplification, in the drawing's unit
};

// The toolpath of a run, built one event at a time with memory bounded whatever the run
// (ARCHITECTURE.md "Bounded resources"; issue 17): the pieces are simplified on a grid of at least
// kGridCells cells across what the picture frames (Frame: the part once a cutting move came, else
// the whole drawing; a fraction of a pixel of the SVG):
// * consecutive lines of one stroke that continue along one line (within half a cell) become one,
//   and a line shorter than a cell takes the next one in (points closer than the resolution go);
// * a piece that repeats one already drawn (same stroke, same cells: an endless loop's second
//   turn) is dropped;
// * arcs in the view plane stay arcs.
// The grid coarsens (doubles) as the drawing grows, and when the pieces pass kMaxPieces, down to
// kCoarsestCells across; past that, moves are counted in `not_drawn` instead of drawn. Bounds,
// lengths, start and end always cover every move.
class ToolpathBuilder {
public:
    static constexpr double kGridCells = 4096;
    static constexpr double kCoarsestCells = 256;
    static constexpr std::size_t kMaxPieces = 100'000;
    static constexpr std::size_t kMaxAlarms = 100;

    explicit ToolpathBuilder(const ViewOptions& options) : options_(options) {}
    // Events that are not motion (tool change, spindle, ...) are skipped; alarms become markers.
    void add(const interpreter::Event& e);
    Toolpath finish() &&;

private:
    struct Key {
        std::int64_t a = 0, b = 0, c = 0, d = 0, e = 0, f = 0;
        std::uint8_t kind = 0;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const;
    };

    bool add_piece(Piece p);
    bool extend_open_line(const Piece& p);
    void set_direction(const Piece& line);
    void close_open();
    void finalize_last();
    void fit_grid();               // the grid for the framed extent; re-simplifies when it changes
    void resimplify(double grid);
    Key key_of(const Piece& p) const;
    std::int64_t cell(double v) const;

    ViewOptions options_;
    Toolpath t_;
    std::vector<Piece> move_pieces_;   // the pieces of the move being added (reused)
    int inch_votes_ = 0, metric_votes_ = 0;
    double grid_ = 0;              // cell size, a power of two; 0 until the drawing has an extent
    bool open_ = false;            // t_.pieces.back() is a line that may still grow
    Point direction_;              // the open line's direction (unit), once it is longer than a cell
    bool has_direction_ = false;
    bool full_ = false;            // kMaxPieces at the coarsest grid: moves are counted, not drawn
    bool resimplifying_ = false;
    bool grid_on_part_ = false;    // the grid follows the part's extent (Frame::part, after the first cut)
    std::unordered_set<Key, KeyHash> drawn_;
};

// All the events at once (tests, small runs): a ToolpathBuilder fed in order.
Toolpath build_toolpath(const std::vector<interpreter::Event>& events, const ViewOptions& options);

// A sink that builds the toolpath while the interpreter runs (kerf plot): no event is kept.
class ToolpathSink : public interpreter::EventSink {
public:
    explicit ToolpathSink(const ViewOptions& options) : builder_(options) {}
    void on_event(const interpreter::Event& e) override { builder_.add(e); }
    Toolpath finish() && { return std::move(builder_).finish(); }

private:
    ToolpathBuilder builder_;
};

}  // namespace kerf::plot
