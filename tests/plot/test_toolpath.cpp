// plot/toolpath.hpp ToolpathBuilder: the simplification that keeps a plot small whatever the run
// (issue 17): collinear points merged, points closer than the grid dropped, repeated pieces
// dropped, arcs kept as arcs, a hard bound on the pieces; bounds, start and end exact.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "plot/toolpath.hpp"

using namespace kerf;
using interpreter::Event;
using interpreter::EventKind;
using interpreter::Position;
using plot::ToolpathBuilder;

namespace {

Position xy(double x, double y) { return {x, y, 0, 0, 0, 0}; }

Event move(EventKind kind, Position start, Position end) {
    Event e;
    e.kind = kind;
    e.start = start;
    e.end = end;
    e.length_mm = std::hypot(end[0] - start[0], end[1] - start[1]);
    return e;
}

const plot::ViewOptions kMill{dialects::MachineKind::mill, false, plot::Frame::part};

// The distance of point p from the segment a-b.
double distance_to_segment(plot::Point p, plot::Point a, plot::Point b) {
    const double dh = b.h - a.h, dv = b.v - a.v, l2 = dh * dh + dv * dv;
    const double t = l2 > 0 ? std::clamp(((p.h - a.h) * dh + (p.v - a.v) * dv) / l2, 0.0, 1.0) : 0.0;
    return std::hypot(p.h - a.h - t * dh, p.v - a.v - t * dv);
}

}  // namespace

TEST_CASE("toolpath: moves along one line become one piece") {
    ToolpathBuilder b(kMill);
    for (int i = 0; i < 100; ++i) b.add(move(EventKind::linear, xy(i, 0), xy(i + 1, 0)));
    const plot::Toolpath t = std::move(b).finish();
    REQUIRE(t.pieces.size() == 1);
    CHECK(t.pieces[0].from.h == 0);
    CHECK(t.pieces[0].to.h == 100);
    CHECK(t.moves == 100);
    CHECK(t.feed_mm == Approx(100));
}

TEST_CASE("toolpath: points closer than the grid go; a turn or another stroke starts a new piece") {
    ToolpathBuilder b(kMill);
    // 0 -> 100 along X with a wobble of 1e-6 (far below the grid of 100 / 4096 -> 1/32).
    for (int i = 0; i < 100; ++i) b.add(move(EventKind::linear, xy(i, i % 2 ? 1e-6 : 0), xy(i + 1, (i + 1) % 2 ? 1e-6 : 0)));
    b.add(move(EventKind::linear, xy(100, 0), xy(100, 50)));   // a turn
    b.add(move(EventKind::rapid, xy(100, 50), xy(100, 100)));  // along the same line, but a rapid
    const plot::Toolpath t = std::move(b).finish();
    REQUIRE(t.pieces.size() == 3);
    CHECK(t.pieces[0].to.h == Approx(100));
    CHECK(t.pieces[1].stroke == plot::Stroke::feed);
    CHECK(t.pieces[2].stroke == plot::Stroke::rapid);
    CHECK(t.resolution == 1.0 / 32);
}

TEST_CASE("toolpath: a circle of short lines stays a circle within a grid cell") {
    // 3600 chords of a circle of radius 50 (each 0.087 mm): the grid is 100 / 4096 -> 1/32.
    ToolpathBuilder b(kMill);
    auto at = [](int i) { const double a = 2 * std::numbers::pi * i / 3600; return xy(50 * std::cos(a), 50 * std::sin(a)); };
    for (int i = 0; i < 3600; ++i) b.add(move(EventKind::linear, at(i), at(i + 1)));
    const plot::Toolpath t = std::move(b).finish();
    CHECK(t.pieces.size() < 3600);
    CHECK(t.pieces.size() > 50);
    // Every original point lies within a grid cell of the pieces drawn.
    for (int i = 0; i <= 3600; i += 7) {
        const plot::Point p{at(i)[0], at(i)[1]};
        double nearest = 1e9;
        for (const plot::Piece& piece : t.pieces) nearest = std::min(nearest, distance_to_segment(p, piece.from, piece.to));
        CHECK(nearest <= t.resolution);
    }
}

TEST_CASE("toolpath: arcs stay arcs, and a path run again is drawn once") {
    ToolpathBuilder b(kMill);
    for (int turn = 0; turn < 1000; ++turn) {
        b.add(move(EventKind::linear, xy(0, 0), xy(40, 0)));
        Event arc = move(EventKind::arc_ccw, xy(40, 0), xy(40, 20));
        arc.center = xy(40, 10);
        b.add(arc);
        b.add(move(EventKind::linear, xy(40, 20), xy(0, 20)));
        b.add(move(EventKind::rapid, xy(0, 20), xy(0, 0)));
    }
    const plot::Toolpath t = std::move(b).finish();
    REQUIRE(t.pieces.size() == 4);
    CHECK(t.pieces[1].arc);
    CHECK(t.pieces[1].radius == Approx(10));
    CHECK(t.pieces[1].sweep == Approx(std::numbers::pi));
    CHECK(t.moves == 4000);
    // The bounds include the arc's extreme point X50.
    CHECK(t.bounds.h_max == Approx(50));
}

TEST_CASE("toolpath: a million moves that never repeat stay within the piece bound") {
    ToolpathBuilder b(kMill);
    std::mt19937 random(17);
    std::uniform_real_distribution<double> coordinate(0, 1000);
    Position from = xy(0, 0);
    for (int i = 0; i < 1'000'000; ++i) {
        const Position to = xy(coordinate(random), coordinate(random));
        b.add(move(i % 2 ? EventKind::rapid : EventKind::linear, from, to));
        from = to;
    }
    const plot::Toolpath t = std::move(b).finish();
    CHECK(t.pieces.size() <= ToolpathBuilder::kMaxPieces);
    CHECK(t.moves == 1'000'000);
    CHECK(t.not_drawn > 0);
    CHECK(t.not_drawn < t.moves);
    // Start, end and bounds still cover every move.
    CHECK(t.start.h == 0);
    CHECK(t.end.h == from[0]);
    CHECK(t.bounds.h_max <= 1000);
    CHECK(t.bounds.h_max > 999);
}
