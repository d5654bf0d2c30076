// G40–G42 through the interpreter (executor_compensation.cpp): the tool-centre path of a square
// and a circle on a mill, seed 004 examples 2 and 3 (semantics.md §6, §9.2), a start on an arc,
// over-cut, and a lathe profile with a chamfer per tip-number family (semantics.md §5). Every
// expected point derived by hand in the comments.
#include <cmath>

#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf::test;

namespace {

void seed_registers(Setup& s) {
    s.tools[1].radius = 15;   // D1, ex. 2 finishing
    s.tools[2].radius = 20;   // D02, ex. 2 roughing
    s.tools[7].radius = 12;   // D07, ex. 3
    s.tools[8].radius = 10;   // D08, ex. 3
    s.comp_shift_without_motion = true;   // the iso-legacy-mill machine's switch (seed 004)
}

}  // namespace

// The 20 × 20 square run counter-clockwise from (0,0), D1 = 5, entered along +a from (−10,0),
// left along −Y to (0,−10). G42 (outside): start-up perpendicular (0,−5); 90° outside corners at
// the offset lines' crossings (25,−5), (25,25), (−5,25); the last side runs straight into the
// cancel: (−5,0), then (0,−10). G41 (inside): (0,5), (15,5), (15,15), (5,15), (5,0), (0,−10).
TEST_CASE("G41/G42 on a mill: a square outside and inside") {
    for (const auto& [code, path] :
         {std::pair{"G42", std::vector<Pt>{{-10, 0}, {0, -5}, {25, -5}, {25, 25}, {-5, 25}, {-5, 0}, {0, -10}}},
          std::pair{"G41", std::vector<Pt>{{-10, 0}, {0, 5}, {15, 5}, {15, 15}, {5, 15}, {5, 0}, {0, -10}}}}) {
        const Run r = run_bare(std::string("O1\nG90 G17 G0 X-10. Y0.\n") + code +
                                   " D1 G1 X0. F100.\nX20.\nY20.\nX0.\nY0.\nG40 Y-10.\nM30\n",
                               "fanuc-mill", [](Setup& s) { s.tools[1].radius = 5; });
        require_clean(r);
        const auto m = moves(r);
        REQUIRE(m.size() == path.size());
        for (std::size_t i = 0; i < m.size(); ++i) {
            INFO(code << " move " << i);
            CHECK(m[i].end[X] == Approx(path[i].x).margin(0.001));
            CHECK(m[i].end[Y] == Approx(path[i].y).margin(0.001));
        }
    }
}

// The look-ahead of compensation reads the next motion block through const functions of the live
// state (executor.hpp comp_look_ahead): an alarm there is the next block's, raised by the running
// block before it moves, with the tool where it stands. D1 = 5, G41: the start-up N3 ends at
// (0,5), perpendicular to N4's +X; N4 reads N5 ahead, whose Y[1/0] is alarm 112: the alarm is on
// line 5 at (0,5), and N4 makes no move.
TEST_CASE("G41 on a mill: an alarm in the block read ahead stops the run where the tool stands") {
    const Run r = run_bare("O1\nG90 G17 G0 X-10. Y0.\nG41 D1 G1 X0. F100.\nX20.\nY[1/0]\nM30\n", "fanuc-mill",
                           [](Setup& s) { s.tools[1].radius = 5; });
    require_alarm(r, 112);
    const Event& a = r.result.alarms[0];
    CHECK(a.source.line == 5);
    CHECK(a.end[X] == Approx(0).margin(1e-9));
    CHECK(a.end[Y] == Approx(5));
    const auto m = moves(r);
    REQUIRE(m.size() == 2);   // the rapid of N2 and the start-up of N3
    CHECK(m[1].end[X] == Approx(0).margin(1e-9));
    CHECK(m[1].end[Y] == Approx(5));
    CHECK(moves_on_line(r, 4).empty());
}

// A full circle R20 about the origin from (20,0), entered and left along +Y (tangent there):
// G41 (left of counter-clockwise travel = inside) r5 runs R15 from (15,0); G42 R25 from (25,0);
// the cancel ends on the programmed (20,10).
TEST_CASE("G41/G42 on a mill: a circle inside and outside") {
    for (const auto& [code, x] : {std::pair{"G41", 15.0}, std::pair{"G42", 25.0}}) {
        const Run r = run_bare(std::string("O1\nG90 G17 G0 X20. Y-10.\n") + code +
                                   " D1 G1 Y0. F100.\nG3 I-20.\nG40 G1 Y10.\nM30\n",
                               "fanuc-mill", [](Setup& s) { s.tools[1].radius = 5; });
        require_clean(r);
        const auto m = moves(r);
        check_path(m, {{20, -10}, {x, 0}, {x, 0}, {20, 10}});
        CHECK(m[2].kind == EventKind::arc_ccw);
        CHECK(m[2].radius == Approx(x));
    }
}

// Seed 004 ex. 2 (semantics.md §6): `G42 D02` alone moves the centre from point 1 (175,50) to
// point 2, right of the −X pass: (175,70); N20 to point 3 (25,70) leaving 5 mm (D02 − D1);
// N25 G41 D1: first the shift to point 4 (25,65), then point 5 (200,65); N30 G40 to (240,50).
TEST_CASE("seed 004 ex. 2: G42 D02 without motion, then G41 D1 without G40") {
    const Run r = run_bare("O2\nN10 G90 G0 X175. Y50.\nN15 G42 D02\nN20 G1 X25. F60.\nN25 G41 D1 X200. F40.\nN30 G40 X240.\n",
                           "iso-legacy-mill", seed_registers);
    require_clean(r);
    check_path(moves(r), {{175, 50}, {175, 70}, {25, 70}, {25, 65}, {200, 65}, {240, 50}});
}

// Seed 004 ex. 3: G42 D08 from (140,40) → (140,50). The line to X100 meets the arc (R10 + 10 =
// R20 about (90,40)) inside: b = 50, a = 90 + √(400 − 100) = 107.321. The arc ends at (90,60);
// `G1 X40 D07` first shifts up by D07 − D08 = 2 to (90,62), runs to (40,62); `G3 … D08` shifts
// back to (40,60) and runs R20 about (40,40) to its inside crossing with b = 50:
// a = 40 − √300 = 22.679; the line to X0 ends perpendicular (0,50); G0 G40 X-35 → (−35,40).
TEST_CASE("seed 004 ex. 3: a D change inside the contour leaves 2 mm") {
    const Run r = run_bare("O3\nN10 G90 G17\nG0 X140. Y40.\nG42 D08\nG1 X100. F60.\nG3 X90. Y50. I-10. J0.\n"
                           "G1 X40. D07\nG3 X30. Y40. I0. J-10. D08\nG1 X0.\nG0 G40 X-35. M02\n",
                           "iso-legacy-mill", seed_registers);
    require_clean(r);
    check_path(moves(r), {{140, 40}, {140, 50}, {90 + std::sqrt(300.0), 50}, {90, 60}, {90, 62}, {40, 62}, {40, 60},
                          {40 - std::sqrt(300.0), 50}, {0, 50}, {-35, 40}});
}

TEST_CASE("G41 started on an arc is alarm 034; an inside corner too tight is alarm 041") {
    const Run arc = run_bare("O1\nG90 G17 G0 X10. Y0.\nG41 D1 G3 X0. Y10. R10. F100.\nM30\n", "fanuc-mill",
                             [](Setup& s) { s.tools[1].radius = 2; });
    require_alarm(arc, 34);
    // An 8 × 8 pocket with r5 inside: the second side would end behind its start (over-cut).
    const Run tight = run_bare("O1\nG90 G17 G0 X-5. Y0.\nG41 D1 G1 X0. F100.\nX8.\nY8.\nX0.\nM30\n", "fanuc-mill",
                               [](Setup& s) { s.tools[1].radius = 5; });
    require_alarm(tight, 41);
}

// A lathe profile (X diameter, plane Z–X, X as a radius in the geometry): T0101 with nose radius
// 0.8, G42 along −Z at X20 from Z5: centre path (Z, X radius): start-up perpendicular (0, 10.8);
// the chamfer X24 Z-12 (45°, dir (−1,1)/√2, right normal (1,1)/√2) meets X = 10.8 inside at
// z + x = 0.8√2 → Z −9.669; the chamfer's offset meets X = 12.8 outside (45°) at Z −11.669; the
// last line ends perpendicular before the +X cancel (an inside turn): (−20, 12.8); then the
// cancel to the programmed X30 Z-20. The controlled point is the centre + the tip vector:
// tip 0 (0,0), tip 3 (−0.8 Z, −0.8 X), tip 8 (0 Z, −0.8 X); X printed as diameter.
TEST_CASE("G42 on a lathe: a chamfered profile for tip families 0, 3 and 8") {
    const double z1 = -10 + 0.8 * std::sqrt(2.0) - 10.8 + 10;   // z + x = 0.8√2 with x = 10.8 (radius)
    const double z2 = 0.8 * std::sqrt(2.0) - 12.8;
    for (const auto& [tip, dz, dx] : {std::tuple{0, 0.0, 0.0}, std::tuple{3, -0.8, -0.8}, std::tuple{8, 0.0, -0.8}}) {
        const int tip_number = tip;
        const Run r = run_bare("O1\nT0101\nG0 X20. Z5.\nG42 G1 Z0. F0.2\nZ-10.\nX24. Z-12.\nZ-20.\nG40 G0 X30.\nM30\n",
                               "fanuc-lathe-a", [&](Setup& s) {
                                   s.tools[1].nose_radius = 0.8;
                                   s.tools[1].tip = tip_number;
                               });
        require_clean(r);
        INFO("tip " << tip);
        const double ddx = 2 * dx;   // diameter
        check_path(moves(r),
                   {{20, 5}, {21.6 + ddx, 0 + dz}, {21.6 + ddx, z1 + dz}, {25.6 + ddx, z2 + dz}, {25.6 + ddx, -20 + dz}, {30, -20}},
                   Z);
    }
}

// The look-ahead carries the modal motion through the blocks it reads (executor_compensation.cpp
// comp_look_ahead). D1 = 5, G41, `G03` alone on a block before `X30. Y10. R10.`: N4 (X20, +X)
// meets the arc about (20,10), which leaves (20,0) along +X: tangent, so N4 ends at (20,5); the arc
// runs on radius 10 − 5 to (25,10); N7 (+Y) is tangent to the arc's end: (25,20) and the corner
// with the cancel's +X, (25,25). Before, the look-ahead read the arc as a line from the running
// block's G01: N4 stopped short at the inside corner (17.929,5) and the arc ran as a line.
TEST_CASE("G41 on a mill: a motion code alone on a block is the motion of the move read ahead after it") {
    const Run r = run_bare("O1\nG90 G17 G0 X-10. Y0.\nG41 D1 G1 X0. F100.\nX20.\nG03\nX30. Y10. R10.\nG1 Y20.\nG40 X40.\nM30\n",
                           "fanuc-mill", [](Setup& s) { s.tools[1].radius = 5; });
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 6);
    CHECK(m[2].end[X] == Approx(20));
    CHECK(m[2].end[Y] == Approx(5));
    CHECK(m[3].kind == EventKind::arc_ccw);
    CHECK(m[3].end[X] == Approx(25));
    CHECK(m[3].end[Y] == Approx(10));
    CHECK(m[4].end[X] == Approx(25));
    CHECK(m[4].end[Y] == Approx(25));
}
