// G70 under G41/G42 (cycles.md §1: "tool-nose radius compensation active before G70 is applied to
// the profile"; semantics.md §5 "G70 does"): the finishing path through the same compensation as
// programmed blocks, for every imaginary tip number (executor_compensation.cpp compensate_path).
#include <cmath>
#include <tuple>

#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf::test;

// fanuc-lathe-a, T0101 nose radius r = 0.8, G42 given without motion at A = X20 Z5, then
// G70 P10 Q70 over (Z, X as a radius):
//   N10 G1 Z0 F0.2   (5,10) → (0,10)   −Z: right normal +X
//   N20 Z-10         → (−10,10)
//   N30 X24 Z-12     → (−12,12)        45° chamfer, right normal (1,1)/√2: offset z + x = 0.8√2
//   N40 Z-20         → (−20,12)
//   N50 G2 X40 Z-28 R8 → (−28,20)      CW quarter about (−20,20), tangent to N40 and N60
//   N60 G1 X44       → (−28,22)        +X: right normal +Z
//   N70 Z5           → (5,22)          +Z: right normal −X
//   return to A      → (5,10)          −X: right normal −Z
// Nose centre path (FANUC compensation C, start-up type B):
//   start-up perpendicular at the end of N10: (0, 10.8)
//   N20/N30 inside corner: x = 10.8 on z + x = 0.8√2 → (0.8√2 − 10.8, 10.8) = (−9.669, 10.8)
//   N30/N40 outside 135°: the offset lines cross at x = 12.8 → (0.8√2 − 12.8, 12.8) = (−11.669, 12.8)
//   N40/N50 tangent: (−20, 12.8); the arc offset towards its centre (tool right of a CW arc): R7.2
//   to (−27.2, 20), centre (−20, 20)
//   N60/N70 inside: (−27.2, 21.2); N70/return inside: (4.2, 21.2); the return (rapid) ends
//   perpendicular, no element after it: (4.2, 10).
// The controlled point is the centre + the tip vector r·(dz, dx) of semantics.md §5 / the FANUC
// numbering in radius_compensation.hpp: 1 (+X +Z), 2 (+X −Z), 3 (−X −Z), 4 (−X +Z), 5 (+Z),
// 6 (+X), 7 (−Z), 8 (−X), 0 the centre. X printed as a diameter.
TEST_CASE("G70 under G42: the finishing profile with a chamfer and an arc, tips 0-8") {
    const double s = 0.8 * std::sqrt(2.0);
    struct P {
        double z, x;   // x as a radius
        EventKind kind;
    };
    const std::vector<P> centre = {{0, 10.8, EventKind::linear},      {s - 10.8, 10.8, EventKind::linear},
                                   {s - 12.8, 12.8, EventKind::linear}, {-20, 12.8, EventKind::linear},
                                   {-27.2, 20, EventKind::arc_cw},      {-27.2, 21.2, EventKind::linear},
                                   {4.2, 21.2, EventKind::linear},      {4.2, 10, EventKind::rapid}};
    for (const auto& [tip, dz, dx] :
         {std::tuple{0, 0, 0}, std::tuple{1, 1, 1}, std::tuple{2, -1, 1}, std::tuple{3, -1, -1}, std::tuple{4, 1, -1},
          std::tuple{5, 1, 0}, std::tuple{6, 0, 1}, std::tuple{7, -1, 0}, std::tuple{8, 0, -1}}) {
        const int tip_number = tip;
        // G42 alone (the start-up is the profile's first element), or engaged before the cycle by
        // `G0 G42 Z5.` along −Z from Z20 (the look-ahead stops at the cycle: the tool ends
        // perpendicular, centre (5, 10.8)); the G70 path is the same: N10 runs on in a straight line.
        for (const char* start : {"G0 X20. Z5.\nG42\n", "G0 X20. Z20.\nG0 G42 Z5.\n"}) {
        const Run r = run_bare(std::string("O1\nT0101\n") + start + "G70 P10 Q70\nG40 G0 X60.\nM30\n"
                               "N10 G1 Z0. F0.2\nN20 Z-10.\nN30 X24. Z-12.\nN40 Z-20.\nN50 G2 X40. Z-28. R8.\n"
                               "N60 G1 X44.\nN70 Z5.\n",
                               "fanuc-lathe-a", [&](Setup& st) {
                                   st.tools[1].nose_radius = 0.8;
                                   st.tools[1].tip = tip_number;
                               });
        require_clean(r);
        INFO("tip " << tip << ", start " << start);
        const auto m = moves_on_line(r, 5);
        REQUIRE(m.size() == centre.size());
        for (std::size_t i = 0; i < m.size(); ++i) {
            INFO("move " << i);
            CHECK(m[i].kind == centre[i].kind);
            CHECK(m[i].end[Z] == Approx(centre[i].z + 0.8 * dz).margin(0.001));
            CHECK(m[i].end[X] == Approx(2 * (centre[i].x + 0.8 * dx)).margin(0.001));
        }
        // The arc keeps its centre (X40 Z-20), shifted by the tip vector like every point.
        REQUIRE(m[4].center);
        CHECK((*m[4].center)[Z] == Approx(-20 + 0.8 * dz).margin(0.001));
        CHECK((*m[4].center)[X] == Approx(2 * (20 + 0.8 * dx)).margin(0.001));
        CHECK(m[4].radius == Approx(7.2).margin(0.001));
        CHECK(m[0].feed == Approx(0.2));
        }
    }
}

// Without G41/G42 the same G70 runs the programmed profile (the path of cycles.md §1).
TEST_CASE("G70 without compensation runs the profile as written") {
    const Run r = run_bare("O1\nT0101\nG0 X20. Z5.\nG70 P10 Q30\nM30\nN10 G1 Z0. F0.2\nN20 Z-10.\nN30 X24. Z-12.\n",
                           "fanuc-lathe-a", [](Setup& st) { st.tools[1].nose_radius = 0.8; });
    require_clean(r);
    const auto m = moves_on_line(r, 4);
    REQUIRE(m.size() == 4);
    CHECK(m[2].end[X] == Approx(24));
    CHECK(m[2].end[Z] == Approx(-12));
    CHECK(m[3].end[X] == Approx(20));
    CHECK(m[3].end[Z] == Approx(5));
}

// G71 under G42 (cycles.md §2 "Roughing ignores nose-radius compensation"; semantics.md §5 "Rough
// cycles G71–G73 do not apply the compensation; G70 does"): O0071 of cycles.md §2 after a G42
// start-up, tool 1 with r = 0.8 and tip 3 (imaginary tip at −X −Z of the centre), machine switch
// rough_return = x_then_z.
//   line 4 `G0 G42 Z1.` from X105 Z5 along −Z; the look-ahead stops at the cycle, so the centre
//          ends perpendicular, 0.8 to the right of −Z (+X): (Z1, x 53.3); the tip 3 point is
//          (Z1 − 0.8, x 53.3 − 0.8) = X105. Z0.2.
//   line 6 the roughing: O0071's pass table as in the uncompensated run (the first rapid from the
//          offset point), then the return to A = X105 Z1 X first: from X102 Z-88 to X105 Z-88, then
//          Z1 (the cycle reads where the tool stands, not the programmed start point).
//   line 12 G70: the offset is taken up again from A; its path is the one of a G42 given at A
//          without motion before G70 (the G70 test above derives that path by hand).
TEST_CASE("G71 under G42 roughs programmed points, returns X then Z, and G70 starts up from A") {
    const auto profile = std::string("N100 G0 X40.\nN110 G1 Z-30.\nN120 X60. Z-60.\nN130 Z-80.\nN140 X100. Z-90.\n");
    const auto setup = [](Setup& st) {
        st.tools[1].nose_radius = 0.8;
        st.tools[1].tip = 3;
        st.cycles.rough_return = kerf::interpreter::cycles::Return::x_then_z;
    };
    const Run r = run_bare("O1\nT0101\nG0 X105. Z5.\nG0 G42 Z1.\nG71 U3. R1.\nG71 P100 Q140 U2. W2. F0.3\n" + profile +
                               "N150 G70 P100 Q140\nG40 G0 X200. Z200.\nM30\n",
                           "fanuc-lathe-a", setup);
    require_clean(r);
    const auto start = moves_on_line(r, 4);
    REQUIRE(start.size() == 1);
    CHECK(start[0].end[X] == Approx(105).margin(0.001));
    CHECK(start[0].end[Z] == Approx(0.2).margin(0.001));
    const auto rough = moves_on_line(r, 6);
    REQUIRE(rough.size() == 10 * 4 + 5 + 2);
    CHECK(rough[0].kind == EventKind::rapid);   // O0071's first level: X99 at Z1, from the offset point
    CHECK(rough[0].end[X] == Approx(99).margin(0.001));
    CHECK(rough[0].end[Z] == Approx(1).margin(0.001));
    const Event& x_back = rough[rough.size() - 2];
    CHECK(x_back.kind == EventKind::rapid);
    CHECK(x_back.end[X] == Approx(105).margin(0.001));
    CHECK(x_back.end[Z] == Approx(-88).margin(0.001));
    CHECK(rough.back().end[X] == Approx(105).margin(0.001));
    CHECK(rough.back().end[Z] == Approx(1).margin(0.001));
    // F0.3 as the G71 gave it in `r` (G70 runs at the F in force: without one, alarm 011).
    const Run at_a = run_bare("O1\nT0101 F0.3\nG0 X105. Z1.\nG42\nG70 P100 Q140\nM30\n" + profile, "fanuc-lathe-a", setup);
    require_clean(at_a);
    const auto want = moves_on_line(at_a, 5);
    const auto got = moves_on_line(r, 12);
    REQUIRE(!want.empty());
    REQUIRE(got.size() == want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        INFO("G70 move " << i);
        CHECK(got[i].kind == want[i].kind);
        CHECK(got[i].end[X] == Approx(want[i].end[X]).margin(0.001));
        CHECK(got[i].end[Z] == Approx(want[i].end[Z]).margin(0.001));
    }
    // The G70 profile's first element from A is a start-up: the tool is not at a programmed point.
    CHECK(got[0].end[Z] != Approx(1).margin(0.01));
}
