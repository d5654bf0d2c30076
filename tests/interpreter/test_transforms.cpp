// [FANUC] programmable transforms of fanuc-mill through the interpreter (executor_transforms.cpp,
// transforms.hpp): G16 polar coordinate command, G51 scaling (one P, or I/J/K each axis with a
// negative one as mirror), G51.1 mirror image with G02/G03 and G41/G42 swapped, and their nesting
// with G68. Every expected point is derived by hand in the comment above its test.
#include <cmath>

#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf::test;

namespace {

void check_centre(const Event& arc, Pt c, double radius) {
    REQUIRE(arc.center);
    CHECK((*arc.center)[X] == Approx(c.x).margin(0.001));
    CHECK((*arc.center)[Y] == Approx(c.y).margin(0.001));
    CHECK(arc.radius == Approx(radius).margin(0.001));
}

// The texts of the coordinate_change events, in order.
std::vector<std::string> changes(const Run& r) {
    std::vector<std::string> out;
    for (const Event& e : of_kind(r, EventKind::coordinate_change)) out.push_back(e.text);
    return out;
}

bool says_not_applied(const Run& r) {
    for (const Event& e : of_kind(r, EventKind::message))
        if (e.text.find("not applied yet") != std::string::npos) return true;
    return false;
}

}  // namespace

// G90 G16, radius 50 from the work origin, absolute angles every 60°: the corners of a hexagon
// (50 cos 60° = 25, 50 sin 60° = 43.301). Y360. is back at (50, 0). After G15, X0. Y0. is Cartesian.
TEST_CASE("G16 G90: a hexagon of absolute angles about the work origin; G15 cancels", "[transforms]") {
    const Run r = run_bare("O1\nG90 G17 G0 X0. Y0.\nG16\nG1 X50. Y0. F100.\nY60.\nY120.\nY180.\nY240.\nY300.\nY360.\n"
                           "G15\nG0 X0. Y0.\nM30\n");
    require_clean(r);
    check_path(moves(r), {{0, 0}, {50, 0}, {25, 43.301}, {-25, 43.301}, {-50, 0}, {-25, -43.301}, {25, -43.301},
                          {50, 0}, {0, 0}});
    CHECK(changes(r) == std::vector<std::string>{"polar coordinate command (G16)", "polar coordinate command cancel (G15)"});
    CHECK_FALSE(says_not_applied(r));
}

// G91 under G16 ([FANUC] rules in executor_transforms.cpp polar_target):
//   G1 X40. Y45.  absolute: 40 at 45°                      → (28.284, 28.284)
//   G91 Y90.      no radius word: r = 40 about the origin, angle 45 + 90 = 135° → (−28.284, 28.284)
//   X10. Y0.      incremental radius: from the current point, 10 at 135 + 0 = 135°
//                 → (−28.284 − 7.071, 28.284 + 7.071) = (−35.355, 35.355)
//   G90 X20. Y-90.  absolute again: 20 at −90°            → (0, −20)
TEST_CASE("G16 G91: incremental angle about the origin, incremental radius from the current point", "[transforms]") {
    const Run r = run_bare("O1\nG90 G17 G0 X0. Y0.\nG16\nG1 X40. Y45. F100.\nG91 Y90.\nX10. Y0.\nG90 X20. Y-90.\nG15\nM30\n");
    require_clean(r);
    check_path(moves(r), {{0, 0}, {28.284, 28.284}, {-28.284, 28.284}, {-35.355, 35.355}, {0, -20}});
}

// FANUC's bolt-hole example with G81: radius 100 at 30°, 150°, 270° → (86.603, 50), (−86.603, 50),
// (0, −100); each hole is a rapid to the point, one to R, the feed to Z and the return (G98).
TEST_CASE("G16 with G81: a bolt circle of three holes", "[transforms]") {
    const Run r = run_bare("O1\nG90 G17 G0 X0. Y0. Z10.\nG16\nG98 G81 X100. Y30. Z-20. R5. F200.\nY150.\nY270.\nG80 G15\nM30\n");
    require_clean(r);
    const std::vector<Event> bottoms = of_kind(r, EventKind::linear);   // the feeds to the hole bottoms
    check_path(bottoms, {{86.603, 50}, {-86.603, 50}, {0, -100}});
    for (const Event& e : bottoms) CHECK(e.end[Z] == Approx(-20));
}

// G16 with an R arc: from (30, 0) to radius 30 at 90° = (0, 30), G03 R30: a quarter about (0, 0).
TEST_CASE("G16: an arc with R to a polar end point", "[transforms]") {
    const Run r = run_bare("O1\nG90 G17 G0 X0. Y0.\nG16\nG1 X30. Y0. F100.\nG3 X30. Y90. R30.\nG15\nM30\n");
    require_clean(r);
    const auto a = arcs(r);
    REQUIRE(a.size() == 1);
    CHECK(a[0].kind == EventKind::arc_ccw);
    check_path(a, {{0, 30}});
    check_centre(a[0], {0, 0}, 30);
}

// G51 X10. Y10. P: ×2 about (10, 10) (P2000 in units of 0.001, or P2. itself).
//   G1 X20. Y10.   → (10 + 2·10, 10) = (30, 10)
//   G3 X10. Y20. R10. (or I-10. J0.): programmed a quarter about (10, 10) from (20, 10) to (10, 20);
//                  scaled: end (10, 10 + 2·10) = (10, 30), R 20 (I −20), centre (10, 10) stays
//   G1 X10. Y10.   → (10, 10): the centre is a fixed point
//   G50, G0 X0. Y0. → (0, 0) unscaled
TEST_CASE("G51 P: scaling about a centre, an arc by R and by I/J; G50 cancels", "[transforms]") {
    for (const char* p : {"P2000", "P2."})
        for (const char* centre : {"R10.", "I-10. J0."}) {
            INFO(p << " " << centre);
            const Run r = run_bare(std::string("O1\nG90 G17 G0 X0. Y0.\nG51 X10. Y10. ") + p + "\nG1 X20. Y10. F100.\nG3 X10. Y20. " +
                                   centre + "\nG1 X10. Y10.\nG50\nG0 X0. Y0.\nM30\n");
            require_clean(r);
            const auto m = moves(r);
            check_path(m, {{0, 0}, {30, 10}, {10, 30}, {10, 10}, {0, 0}});
            CHECK(m[2].kind == EventKind::arc_ccw);
            check_centre(m[2], {10, 10}, 20);
            CHECK(changes(r) == std::vector<std::string>{"scaling (G51) about X10 Y10 Z0, magnification X2 Y2 Z2",
                                                         "scaling cancel (G50)"});
        }
}

// The machine's scaling_unit 0.00001: P200000 is ×2; G1 X20. about (0, 0) → (40, 0).
TEST_CASE("G51 P without a point in the machine's unit", "[transforms]") {
    const Run r = run_bare("O1\nG90 G17 G0 X0. Y0.\nG51 X0. Y0. P200000\nG1 X20. F100.\nG50\nM30\n", "fanuc-mill",
                           [](Setup& s) { s.scaling_unit = 0.00001; });
    require_clean(r);
    check_path(moves(r), {{0, 0}, {40, 0}});
}

// G51 I-1000 J1000 (each axis; I −1 mirrors X about the centre X0):
//   G1 X10. Y0.  → (−10, 0)
//   G3 X0. Y10. R10. (or I-10. J0.): programmed counter-clockwise about (0, 0) from (10, 0) to
//   (0, 10); mirrored it runs from (−10, 0) (180°) to (0, 10) (90°) about (0, 0): clockwise.
TEST_CASE("G51 with a negative I: the X axis mirrored, the arc reversed", "[transforms]") {
    for (const char* centre : {"R10.", "I-10. J0."}) {
        INFO(centre);
        const Run r = run_bare(std::string("O1\nG90 G17 G0 X0. Y0.\nG51 X0. Y0. I-1000 J1000\nG1 X10. Y0. F100.\nG3 X0. Y10. ") +
                               centre + "\nG50\nM30\n");
        require_clean(r);
        const auto m = moves(r);
        check_path(m, {{0, 0}, {-10, 0}, {0, 10}});
        CHECK(m[2].kind == EventKind::arc_cw);
        check_centre(m[2], {0, 0}, 10);
    }
}

// P0 is no magnification: FANUC alarm 142 (illegal scale rate), the run stops there.
TEST_CASE("G51 P0: alarm 142", "[transforms]") {
    const Run r = run_bare("O1\nG90 G17 G0 X0. Y0.\nG51 X0. Y0. P0\nG1 X10. F100.\nM30\n");
    require_alarm(r, 142);
}

// G51.1 Y5.: y → 10 − y. G1 X10. Y0. → (10, 10); G3 X0. Y10. R10. (counter-clockwise about
// (0, 0)) → end (0, 0), centre (0, 10); from (10, 10) (0° about the centre) to (0, 0) (−90°):
// clockwise. G50.1 Y0. cancels: G0 X0. Y0. → (0, 0).
TEST_CASE("G51.1: a mirrored arc runs the other way (G03 becomes clockwise)", "[transforms]") {
    const Run r = run_bare("O1\nG90 G17 G0 X0. Y10.\nG51.1 Y5.\nG1 X10. Y0. F100.\nG3 X0. Y10. R10.\nG50.1 Y0.\nG0 X0. Y0.\nM30\n");
    require_clean(r);
    const auto m = moves(r);
    check_path(m, {{0, 10}, {10, 10}, {0, 0}, {0, 0}});
    CHECK(m[2].kind == EventKind::arc_cw);
    check_centre(m[2], {0, 10}, 10);
    CHECK(changes(r) == std::vector<std::string>{"mirror image (G51.1) about Y5", "mirror image cancel (G50.1) Y"});
    CHECK_FALSE(says_not_applied(r));
}

// G50.1 cancels the axes it names; without axis words (kerf) all of them.
//   G51.1 X5. Y5.: G0 X0. Y0. → (10, 10); G50.1 X0.: only Y mirrored → (0, 10); G50.1 → (0, 0).
TEST_CASE("G50.1 cancels per axis", "[transforms]") {
    const Run r = run_bare("O1\nG90 G17\nG51.1 X5. Y5.\nG0 X0. Y0.\nG50.1 X0.\nG0 X0. Y0.\nG50.1\nG0 X0. Y0.\nM30\n");
    require_clean(r);
    check_path(moves(r), {{10, 10}, {0, 10}, {0, 0}});
}

// The 20 × 20 square of test_compensation_mill.cpp with G42 D1 (r 5, outside when run
// counter-clockwise): path (−10,0), (0,−5), (25,−5), (25,25), (−5,25), (−5,0), (0,−10). Under
// G51.1 X0. the programmed square runs clockwise from (10, 0) through (0,0), (−20,0), (−20,20),
// (0,20), and FANUC swaps G42 for G41, which keeps the tool outside: the compensated path is the
// mirror of the original, every X negated: (10,0), (0,−5), (−25,−5), (−25,25), (5,25), (5,0), (0,−10).
// Without the swap the tool would run inside, at X −5 / −15 instead of 5 / −25.
TEST_CASE("G51.1 with G42: the compensation side swaps and the path is the mirror image", "[transforms]") {
    const Run r = run_bare("O1\nG90 G17 G0 X0. Y0.\nG51.1 X0.\nG0 X-10. Y0.\nG42 D1 G1 X0. F100.\nX20.\nY20.\nX0.\nY0.\n"
                           "G40 Y-10.\nG50.1 X0.\nM30\n",
                           "fanuc-mill", [](Setup& s) { s.tools[1].radius = 5; });
    require_clean(r);
    check_path(moves(r), {{0, 0}, {10, 0}, {0, -5}, {-25, -5}, {-25, 25}, {5, 25}, {5, 0}, {0, -10}});
}

// FANUC: a G68 given in G51 mode has its centre scaled; scaling first, then rotation.
//   G51 X0. Y0. P2000, G68 X10. Y0. R90., G1 X20. Y0.: rotated about (10, 0): (20,0) − (10,0) =
//   (10, 0) → (0, 10) → (10, 10); scaled ×2 about (0, 0): (20, 20). (Seen the FANUC way: the
//   centre scaled to (20, 0), the point to (40, 0), turned 90° about (20, 0): (20, 20).)
TEST_CASE("G51 then G68: the rotation centre is scaled", "[transforms]") {
    const Run r = run_bare("O1\nG90 G17 G0 X0. Y0.\nG51 X0. Y0. P2000\nG68 X10. Y0. R90.\nG1 X20. Y0. F100.\nG69\nG50\nM30\n");
    require_clean(r);
    check_path(moves(r), {{0, 0}, {20, 20}});
}

// All three nested the FANUC way (G51.1 ⊃ G51 ⊃ G68): work = mirror(scale(rotate(p))).
//   G1 X10. Y5.: R90 about (0, 0) → (−5, 10); ×2 about (0, 0) → (−10, 20); X mirrored about 0 → (10, 20).
//   G3 X5. Y10. R5. from the programmed (10, 5): a quarter counter-clockwise about (5, 5) (from 0°
//   to 90°; the other centre (10, 10) would make it 270°, not the R > 0 arc). Rotated +90° about (0,0): centre (−5, 5), end (−10, 5); ×2: centre
//   (−10, 10), end (−20, 10), R 10; mirrored X: centre (10, 10), end (20, 10), and the arc runs
//   clockwise (one mirrored axis): from (10, 20) (90° about (10,10)) to (20, 10) (0°).
TEST_CASE("G51.1, G51 and G68 together", "[transforms]") {
    const Run r = run_bare("O1\nG90 G17 G0 X0. Y0.\nG51.1 X0.\nG51 X0. Y0. P2000\nG68 X0. Y0. R90.\nG1 X10. Y5. F100.\n"
                           "G3 X5. Y10. R5.\nG69\nG50\nG50.1 X0.\nM30\n");
    require_clean(r);
    const auto m = moves(r);
    check_path(m, {{0, 0}, {10, 20}, {20, 10}});
    CHECK(m[2].kind == EventKind::arc_cw);
    check_centre(m[2], {10, 10}, 10);
}

// A drilling cycle whose block names only X still drills at the transformed point: G68 R90. about
// (0, 0) turns the programmed (10, 0) to (0, 10), so Y moves although the block has no Y word
// (cycles/drilling.cpp takes every axis the transform moved). The bottom feed ends at (0, 10, −5).
TEST_CASE("G68 with G81 X only: the hole is at the rotated point", "[transforms]") {
    const Run r = run_bare("O1\nG90 G17 G0 X0. Y0. Z10.\nG68 X0. Y0. R90.\nG98 G81 X10. Z-5. R2. F100.\nG80 G69\nM30\n");
    require_clean(r);
    const std::vector<Event> bottoms = of_kind(r, EventKind::linear);   // the feeds to the hole bottoms
    check_path(bottoms, {{0, 10}});
    CHECK(bottoms[0].end[Z] == Approx(-5));
}

// G18 G16: the plane's first axis is Z (the radius), the second X (the angle). Z10. X90.: radius
// 10 at 90° from +Z towards +X → Z = 10·cos 90° = 0, X = 10·sin 90° = 10; Y untouched.
TEST_CASE("G16 in G18: Z is the radius, X the angle", "[transforms]") {
    const Run r = run_bare("O1\nG90 G18 G0 X0. Y5. Z0.\nG16\nG1 Z10. X90. F100.\nG15\nM30\n");
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 2);
    CHECK(m[1].end[Z] == Approx(0).margin(0.001));
    CHECK(m[1].end[X] == Approx(10).margin(0.001));
    CHECK(m[1].end[Y] == Approx(5));
}
