// interpreter/compensation/radius_compensation.hpp: the state machine fed programmed elements,
// returning tool-centre moves; every expected point derived by hand (semantics.md §6, FANUC
// compensation C: intersections, acute corners extended by r, start-up/cancel type B).
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <vector>

#include "interpreter/compensation/radius_compensation.hpp"

using namespace kerf::interpreter::compensation;
using kerf::motion::Element;
using kerf::motion::P2;

namespace {

Programmed line(P2 a, P2 b, int side, double r) { return {Element{a, b, false, {}, true}, side, r}; }
Programmed arc(P2 a, P2 b, P2 c, bool ccw, int side, double r) { return {Element{a, b, true, c, ccw}, side, r}; }

// Runs the elements in order, each with the next one as its look-ahead; all moves in one list.
std::vector<ToolMove> run_all(RadiusCompensation& comp, const std::vector<Programmed>& path, std::optional<Alarm>* alarm = nullptr) {
    std::vector<ToolMove> out;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const std::optional<Programmed> next = i + 1 < path.size() ? std::optional<Programmed>(path[i + 1]) : std::nullopt;
        const Step s = comp.step(path[i], next);
        if (s.alarm) {
            if (alarm) *alarm = s.alarm;
            break;
        }
        out.insert(out.end(), s.moves.begin(), s.moves.end());
    }
    return out;
}

void check_points(const std::vector<ToolMove>& moves, const std::vector<P2>& expected) {
    REQUIRE(moves.size() == expected.size());
    for (std::size_t i = 0; i < moves.size(); ++i) {
        INFO("move " << i);
        CHECK(moves[i].end.a == Approx(expected[i].a).margin(1e-9));
        CHECK(moves[i].end.b == Approx(expected[i].b).margin(1e-9));
    }
}

// The 20 × 20 square (0,0) → (20,0) → (20,20) → (0,20) → (0,0), run counter-clockwise, entered
// along +a from (−10,0) and left along −b to (0,−10).
std::vector<Programmed> square(int side, double r) {
    return {line({-10, 0}, {0, 0}, side, r),   line({0, 0}, {20, 0}, side, r),  line({20, 0}, {20, 20}, side, r),
            line({20, 20}, {0, 20}, side, r), line({0, 20}, {0, 0}, side, r), line({0, 0}, {0, -10}, 0, r)};
}

}  // namespace

TEST_CASE("compensation: square, G42 outside, type B") {
    // Counter-clockwise travel with the tool on the right: outside. r = 5.
    // Start-up along +a into a straight run: perpendicular, (0,0) + 5·(0,−1) = (0,−5).
    // 90° outside corners (not acute): the offset lines cross at (25,−5), (25,25), (−5,25).
    // The last side (x = −5 going −b) continues straight into the cancel (−b): perpendicular
    // (−5,0), then the cancel to its programmed end (0,−10).
    RadiusCompensation comp;
    check_points(run_all(comp, square(-1, 5)), {{0, -5}, {25, -5}, {25, 25}, {-5, 25}, {-5, 0}, {0, -10}});
    CHECK_FALSE(comp.engaged());
}

TEST_CASE("compensation: square, G41 inside, type B") {
    // Tool on the left of counter-clockwise travel: inside, r = 5. Start-up ends at (0,5); the
    // inside corners are the crossings (15,5), (15,15), (5,15); the last side x = 5 runs
    // straight into the cancel: (5,0), then (0,−10).
    RadiusCompensation comp;
    check_points(run_all(comp, square(+1, 5)), {{0, 5}, {15, 5}, {15, 15}, {5, 15}, {5, 0}, {0, -10}});
}

TEST_CASE("compensation: circle, G41 inside and G42 outside") {
    // Full circle R20 counter-clockwise about the origin from (20,0), entered along +b from
    // (20,−10) (tangent to the circle there), left along +b to (20,10).
    // G41 r5: left is the centre side, R15: start-up to (15,0), circle back to (15,0) about the
    // origin, cancel to (20,10). G42: R25, (25,0).
    for (const auto& [side, x] : {std::pair{+1, 15.0}, std::pair{-1, 25.0}}) {
        RadiusCompensation comp;
        const auto moves = run_all(comp, {line({20, -10}, {20, 0}, side, 5), arc({20, 0}, {20, 0}, {0, 0}, true, side, 5),
                                          line({20, 0}, {20, 10}, 0, 5)});
        check_points(moves, {{x, 0}, {x, 0}, {20, 10}});
        CHECK(moves[1].arc);
        CHECK(moves[1].center.a == Approx(0));
        CHECK(moves[1].ccw);
    }
}

TEST_CASE("compensation: acute outside corner extended by the radius") {
    // (0,0) → (10,0) → (0,5), G42 r2: a left turn of 153.4°, outside for a right tool, acute.
    // First offset line b = −2 ends at (10,−2), extended by r along +a: (12,−2).
    // Second direction t = (−10,5)/√125 = (−0.8944, 0.4472); its right normal (0.4472, 0.8944),
    // offset start (10,0) + 2·(0.4472,0.8944) = (10.8944, 1.7889), backed off by r along t:
    // (10.8944 + 1.7889, 1.7889 − 0.8944) = (12.6833, 0.8944); then its end (0.8944, 6.7889).
    RadiusCompensation comp;
    const double s5 = std::sqrt(5.0);
    const auto moves = run_all(comp, {line({-5, 0}, {0, 0}, -1, 2), line({0, 0}, {10, 0}, -1, 2), line({10, 0}, {0, 5}, -1, 2)});
    check_points(moves, {{0, -2}, {12, -2}, {10 + 2 / s5 + 4 / s5, 4 / s5 - 2 / s5}, {2 / s5, 5 + 4 / s5}});
}

TEST_CASE("compensation: ADV400 inserts an arc about an outside corner") {
    // The G42 square with corner arcs: the first side ends perpendicular at (20,−5), an arc of
    // r5 about the corner (20,0) counter-clockwise (a left turn) to (25,0).
    RadiusCompensation comp({StartType::b, CornerStyle::arc});
    const auto moves = run_all(comp, {line({-10, 0}, {0, 0}, -1, 5), line({0, 0}, {20, 0}, -1, 5), line({20, 0}, {20, 20}, -1, 5)});
    check_points(moves, {{0, -5}, {20, -5}, {25, 0}, {25, 20}});
    CHECK(moves[2].arc);
    CHECK(moves[2].ccw);
    CHECK(moves[2].center.a == Approx(20));
}

TEST_CASE("compensation: a radius change in a straight run shifts the tool first") {
    // G42 r10 along +a to (10,0) (ends at (10,−10)), then r12 on to (20,0): the next block first
    // shifts to (10,−12), then runs to (20,−12) (seed 004 ex. 3 "shifts by 2 mm, then moves").
    RadiusCompensation comp;
    check_points(run_all(comp, {line({-5, 0}, {0, 0}, -1, 10), line({0, 0}, {10, 0}, -1, 10), line({10, 0}, {20, 0}, -1, 12)}),
                 {{0, -10}, {10, -10}, {10, -12}, {20, -12}});
}

TEST_CASE("compensation: type A start-up goes perpendicular to the next element") {
    // Start-up (0,−10) → (0,0) along +b, next along +a: a right (clockwise) turn, outside for
    // a left tool (G41) r5. Type A ends at (0,0) + 5·left(+a) = (0,5); type B at the crossing of x = −5 (left of +b)
    // and b = 5: (−5,5).
    const std::vector<Programmed> path{line({0, -10}, {0, 0}, +1, 5), line({0, 0}, {10, 0}, +1, 5)};
    RadiusCompensation a({StartType::a, CornerStyle::intersection});
    CHECK(a.step(path[0], path[1]).moves.back().end.b == Approx(5));
    CHECK(a.step(path[0], path[1]).moves.size() == 1);
    RadiusCompensation b;
    const Step sb = b.step(path[0], path[1]);
    REQUIRE(sb.moves.size() == 1);
    CHECK(sb.moves[0].end.a == Approx(-5));
    CHECK(sb.moves[0].end.b == Approx(5));
}

TEST_CASE("compensation: alarms for an arc start, an arc cancel and over-cut") {
    RadiusCompensation start;
    const Step s = start.step(arc({10, 0}, {0, 10}, {0, 0}, true, +1, 2), std::nullopt);
    REQUIRE(s.alarm);
    CHECK(s.alarm->number == 34);
    // An 8 × 8 pocket with r5 inside: the second side (x = 3 going +b) would have to start at
    // b = 5 and end at its crossing b = 3, behind the tool: alarm 041.
    RadiusCompensation small;
    std::optional<Alarm> alarm;
    run_all(small, {line({-5, 0}, {0, 0}, +1, 5), line({0, 0}, {8, 0}, +1, 5), line({8, 0}, {8, 8}, +1, 5),
                    line({8, 8}, {0, 8}, +1, 5)},
            &alarm);
    REQUIRE(alarm);
    CHECK(alarm->number == 41);
    // An inside arc R4 with r5: no offset arc.
    RadiusCompensation arc_small;
    std::optional<Alarm> a2;
    run_all(arc_small, {line({4, -5}, {4, 0}, +1, 5), arc({4, 0}, {-4, 0}, {0, 0}, true, +1, 5)}, &a2);
    REQUIRE(a2);
    CHECK(a2->number == 41);
    // Cancel on an arc.
    RadiusCompensation cancel;
    std::optional<Alarm> a3;
    run_all(cancel, {line({20, -10}, {20, 0}, +1, 5), arc({20, 0}, {0, 20}, {0, 0}, true, 0, 5)}, &a3);
    REQUIRE(a3);
    CHECK(a3->number == 34);
}

TEST_CASE("compensation: lathe tip vectors") {
    // Nose centre → imaginary tip, (Z, X radius), r = 0.8: tip 3 (outside turning) −Z −X.
    CHECK(tip_vector(3, 0.8).a == Approx(-0.8));
    CHECK(tip_vector(3, 0.8).b == Approx(-0.8));
    CHECK(tip_vector(2, 0.8).b == Approx(0.8));   // inside boring: +X −Z
    CHECK(tip_vector(2, 0.8).a == Approx(-0.8));
    CHECK(tip_vector(8, 0.4).b == Approx(-0.4));
    CHECK(tip_vector(8, 0.4).a == Approx(0));
    CHECK(tip_vector(0, 0.8).a == 0);
    CHECK(tip_vector(9, 0.8).b == 0);
}
