// G70–G73 expansion (reference/cycles.md §1–§4) on small programs, in the G-code systems where
// the numbers differ (A/B: G70 G71 G72 G73; C: G72 G73 G74 G75). Expected paths are derived by
// hand in the comments from the reference's rules.
#include "tests/interpreter/cycle_steps.hpp"

using namespace kerf::test;

namespace {

struct System {
    const char* dialect;
    const char* finishing;   // G70 (A, B) / G72 (C)
    const char* turning;     // G71 / G73
    const char* facing;      // G72 / G74
    const char* pattern;     // G73 / G75
};
constexpr System kSystems[] = {
    {"fanuc-lathe-a", "G70", "G71", "G72", "G73"},
    {"fanuc-lathe-b", "G70", "G71", "G72", "G73"},
    {"fanuc-lathe-c", "G72", "G73", "G74", "G75"},
};

std::string o0071(const System& s) {
    // cycles.md §2 worked example O0071 (lines 1-13).
    return fmt::format(
        "O0071\n"                                 // 1
        "G0 X105. Z1.\n"                          // 2
        "{1} U3. R1.\n"                           // 3
        "{1} P100 Q140 U2. W2. F0.3\n"            // 4
        "N100 G0 X40.\n"                          // 5
        "N110 G1 Z-30.\n"                         // 6
        "N120 X60. Z-60.\n"                       // 7
        "N130 Z-80.\n"                            // 8
        "N140 X100. Z-90.\n"                      // 9
        "N150 {0} P100 Q140\n"                    // 10
        "G0 X200. Z200.\n"                        // 11
        "M30\n",                                  // 12
        s.finishing, s.turning);
}

}  // namespace

// The pass table of cycles.md §2 "Worked example – O0071": each level is a rapid infeed to X_k at
// Z1 (N100 is G00), a feed to the allowance contour, the 45° relief (+2 on the diameter, +1 in Z)
// and a rapid back to Z1; then the allowance contour (X42 Z1 → Z-28 → X62 Z-58 → Z-78 → X102
// Z-88) and the rapid back to A. G70 runs the profile itself and returns to X105 Z1.
TEST_CASE("G71 type I reproduces the O0071 pass table of cycles.md §2; G70 runs the profile (A, B, C)") {
    struct Level {
        double x, z, relief_x, relief_z;
    };
    const Level table[] = {{99, -87.25, 101, -86.25}, {93, -85.75, 95, -84.75}, {87, -84.25, 89, -83.25},
                           {81, -82.75, 83, -81.75},  {75, -81.25, 77, -80.25}, {69, -79.75, 71, -78.75},
                           {63, -78.25, 65, -77.25},  {57, -50.5, 59, -49.5},   {51, -41.5, 53, -40.5},
                           {45, -32.5, 47, -31.5}};
    std::vector<Step> rough;
    for (const Level& l : table) {
        rough.push_back(rapid(l.x, 1));
        rough.push_back(feed(l.x, l.z));
        rough.push_back(feed(l.relief_x, l.relief_z));   // machine switch rough_relief = feed (default)
        rough.push_back(rapid(l.relief_x, 1));
    }
    for (const Step s : {rapid(42, 1), feed(42, -28), feed(62, -58), feed(62, -78), feed(102, -88), rapid(105, 1)})
        rough.push_back(s);
    const std::vector<Step> finish = {rapid(40, 1), feed(40, -30), feed(60, -60), feed(60, -80), feed(100, -90), rapid(105, 1)};
    for (const System& s : kSystems) {
        INFO(s.dialect);
        const Run r = run_bare(o0071(s), s.dialect);
        require_clean(r);
        check_path(r, 4, rough);
        check_path(r, 10, finish);
        // The profile blocks do not run on their own: the control goes on after N140 (§2).
        for (std::uint32_t line = 5; line <= 9; ++line) CHECK(count_moves_on_line(r, line) == 0);
        // The roughing feed is the F of the cycle block.
        CHECK(moves_on_line(r, 4)[1].feed == Approx(0.3));
        CHECK(r.result.final_position[X] == Approx(200));
    }
}

// A profile with an arc: A = X62 Z2, Δd = 3, e = 0.5, no allowance; profile N10 G0 X20, G1 Z-10,
// G2 X40 Z-20 R10 (centre X40 Z-10: radius 10 about (x 20, z -10) on the radius), G1 X60.
// Levels on the radius 31 − 3k: 28, 25, 22 meet the face X40..X60 at Z-20; 19, 16, 13 meet the
// arc where x = 20 + 10 sin θ, z = −10 + 10 cos θ with θ in the third quadrant:
// z = −10 − √(100 − (x − 20)²): x 19 → −10 − √99 = −19.94987, x 16 → −10 − √84 = −19.16515,
// x 13 → −10 − √51 = −17.14143. Level 10 is the contour start itself: no pass.
TEST_CASE("G71 levels meet an arc of the profile where the circle says (cycles.md §2)") {
    for (const System& s : kSystems) {
        INFO(s.dialect);
        const Run r = run_clean(
            "O1\nG0 X62. Z2.\n{0} U3. R0.5\n{0} P10 Q40 U0 W0 F0.25\nN10 G0 X20.\nN20 G1 Z-10.\n"
            "N30 G2 X40. Z-20. R10.\nN40 G1 X60.\nM30\n",
            s.turning, s.dialect);
        std::vector<Step> want;
        const double levels[][2] = {{56, -20}, {50, -20}, {44, -20}, {38, -19.94987}, {32, -19.16515}, {26, -17.14143}};
        for (const auto& [x, z] : levels) {
            for (const Step st : {rapid(x, 2), feed(x, z), feed(x + 1, z + 0.5), rapid(x + 1, 2)}) want.push_back(st);
        }
        for (const Step st : {rapid(20, 2), feed(20, -10), cw(40, -20), feed(60, -20), rapid(62, 2)}) want.push_back(st);
        check_path(r, 4, want);
        const auto arcs_of_cycle = arcs(r);
        REQUIRE(arcs_of_cycle.size() == 1);
        REQUIRE(arcs_of_cycle[0].center);
        CHECK((*arcs_of_cycle[0].center)[X] == Approx(40).margin(0.001));
        CHECK((*arcs_of_cycle[0].center)[Z] == Approx(-10).margin(0.001));
    }
}

// G72 (§3): A = X82 Z2, W2 R0.5, profile N10 G0 Z-6 (type I: Z only), G1 X60, X40 Z-2, X20;
// U0.4 (diameter: 0.2 on the radius) W0.2 shift the contour to X82.4 Z-5.8 → X60.4 Z-5.8 →
// X40.4 Z-1.8 → X20.4 Z-1.8. Levels Z 2 − 2k: 0, −2, −4 (−6 is past the contour start −5.8).
// Z0 lies above the contour: the pass runs to its end X20.4. Z−2 crosses the taper at
// t = (−2 + 5.8)/4 = 0.95 → X 60.4 − 20·0.95 = 41.4; Z−4: t = 0.45 → X51.4. Relief +0.5 in Z,
// +1 on the diameter (0.5 radius, back toward A). The allowance pass is clipped at X82 (A's X).
TEST_CASE("G72 facing levels, relief and allowance pass derived by hand (cycles.md §3)") {
    for (const System& s : kSystems) {
        INFO(s.dialect);
        const Run r = run_clean(
            "O1\nG0 X82. Z2.\n{0} W2. R0.5\n{0} P10 Q40 U0.4 W0.2 F0.2\nN10 G0 Z-6.\nN20 G1 X60.\n"
            "N30 X40. Z-2.\nN40 X20.\nM30\n",
            s.facing, s.dialect);
        check_path(r, 4,
                   {rapid(82, 0), feed(20.4, 0), feed(21.4, 0.5), rapid(82, 0.5),          //
                    rapid(82, -2), feed(41.4, -2), feed(42.4, -1.5), rapid(82, -1.5),      //
                    rapid(82, -4), feed(51.4, -4), feed(52.4, -3.5), rapid(82, -3.5),      //
                    rapid(82, -5.8), feed(60.4, -5.8), feed(40.4, -1.8), feed(20.4, -1.8), //
                    rapid(82, 2)});
    }
}

// G73 (§4): A = X60 Z5, U2 W1 R2 (Δi 2 radius, Δk 1, two passes), U0.4 W0.1. Pass j is shifted
// by X = 2·Δi·(d−j)/(d−1) + Δu on the diameter and Z = Δk·(d−j)/(d−1) + Δw:
// pass 1: X +4.4, Z +1.1; pass 2: X +0.4, Z +0.1. Each pass: rapid to the shifted A, the shifted
// profile (N10 rapid, then feeds), rapid back to A.
TEST_CASE("G73 repeats the shifted profile d times (cycles.md §4)") {
    for (const System& s : kSystems) {
        INFO(s.dialect);
        const Run r = run_clean(
            "O1\nG0 X60. Z5.\n{0} U2. W1. R2\n{0} P10 Q30 U0.4 W0.1 F0.2\nN10 G0 X20. Z1.\nN20 G1 Z-10.\n"
            "N30 X40. Z-20.\nM30\n",
            s.pattern, s.dialect);
        check_path(r, 4,
                   {rapid(64.4, 6.1), rapid(24.4, 2.1), feed(24.4, -8.9), feed(44.4, -18.9), rapid(60, 5),
                    rapid(60.4, 5.1), rapid(20.4, 1.1), feed(20.4, -9.9), feed(40.4, -19.9), rapid(60, 5)});
    }
}

// G70 (§1): F in the profile blocks is in effect; an arc keeps its centre. From X62 Z2:
// N10 G0 X20 (rapid), N20 G1 Z-10 F0.1, N30 G2 X40 Z-20 R10 (at F0.1, centre X40 Z-10),
// N40 G1 X60 F0.2; rapid back to X62 Z2.
TEST_CASE("G70 runs the profile with its own F and arcs, then returns to the start (cycles.md §1)") {
    const Run r = run_bare("O1\nG99 G0 X62. Z2. F0.3\nG70 P10 Q40\nN10 G0 X20.\nN20 G1 Z-10. F0.1\n"
                           "N30 G2 X40. Z-20. R10.\nN40 G1 X60. F0.2\nM30\n",
                           "fanuc-lathe-a");
    require_clean(r);
    check_path(r, 3, {rapid(20, 2), feed(20, -10), cw(40, -20), feed(60, -20), rapid(62, 2)});
    const auto m = moves_on_line(r, 3);
    REQUIRE(m.size() == 5);
    CHECK(m[1].feed == Approx(0.1));
    CHECK(m[2].feed == Approx(0.1));
    CHECK(m[3].feed == Approx(0.2));
    // G70 goes on after its own block: the profile blocks then run as ordinary blocks.
    CHECK(count_moves_on_line(r, 4) == 1);
}

// cycles.md §0: the first-block values persist until changed; before any program sets them they
// are the machine's [cycle_parameters]. A second G71 without a first block uses U3 R1 again. Its
// profile lies before it, so the run goes on after the second G71 block itself (only a profile
// that follows the cycle block is skipped).
TEST_CASE("G71 depth and retract persist across cycles and start from the machine (cycles.md §0)") {
    const std::string profile = "N10 G0 X40.\nN20 G1 Z-10.\n";
    const std::string text = "O1\nG0 X50. Z1.\nG71 U3. R1.\nG71 P10 Q20 U0 W0 F0.2\n" + profile +
                             "G0 X50. Z1.\nG71 P10 Q20 U0 W0 F0.2\nM30\n";
    const Run r = run_bare(text, "fanuc-lathe-a");
    require_clean(r);
    // Levels on the radius 25 − 3k above 20: 22, 19 → X44, X38 ... X38 < 40: only X44 (22 > 20),
    // then 19 is inside. Both cycles: rapid X44 Z1, feed Z-10, relief X46 Z-9, rapid Z1, allowance
    // pass X40 Z1 → Z-10, rapid X50 Z1.
    const std::vector<Step> want = {rapid(44, 1), feed(44, -10), feed(46, -9), rapid(46, 1),
                                    rapid(40, 1), feed(40, -10), rapid(50, 1)};
    check_path(r, 4, want);
    check_path(r, 8, want);
    // Never set: the machine's initial Δd = 6, e = 1 give one level at radius 25 − 6 = 19 < 20: none.
    const Run initial = run_bare("O1\nG0 X50. Z1.\nG71 P10 Q20 U0 W0 F0.2\n" + profile + "M30\n", "fanuc-lathe-a",
                                 [](Setup& s) { s.cycles.initial.g71_depth = 6; });
    require_clean(initial);
    check_path(initial, 3, {rapid(40, 1), feed(40, -10), rapid(50, 1)});
}

// G71 type II (cycles.md §2: the first block names both axes, `N10 G0 X20 W0`), a pocket.
// A = X50 Z2 (radius 25), U2 R0.5 (Δd 2, e 0.5 on the radius), no allowance. Profile on the
// radius: (10, 2) → s1 (10, −10) → s2 (20, −20) → s3 (14, −25) → s4 (14, −30) → s5 (23, −38).
// Lines: s2 x = 10 + 10t, z = −10 − 10t (z = −x); s3 x = 20 − 6t, z = −20 − 5t; s5 x = 14 + 9t,
// z = −30 − 8t. Levels 25 − 2k while deeper than the deepest point 10: 23 21 19 17 15 13 11.
// Each level: along the level, over the hump along the contour where it stands above the level,
// after the last deeper stretch up the contour to the previous level, out by e, back to Z2 at
// that height, or first out to X50 when the hump (radius 20) reaches that height.
//  23 (X46): the whole contour lies below (its end touches 23): X46 to Z-38; out X47; back Z2.
//  21 (X42): s5 at t = 7/9, z = −36.2222; up s5 to 23 at Z-38 (X46); out X47; back.
//  19 (X38): s2 z = −19, s3 t = 1/6 z = −20.8333, s5 t = 5/9 z = −34.4444: X38 Z-19, over the
//      hump X40 Z-20, X38 Z-20.8333, X38 Z-34.4444, up to 21 at Z-36.2222 (X42), out X43, back
//      at 21.5 (hump 20 below it).
//  17 (X34): z −17, s3 t = 0.5 z = −22.5, s5 t = 1/3 z = −32.6667; up to 19 at Z-34.4444 (X38);
//      out X39 (19.5): the hump (20) stands higher: out to X50, then Z2.
//  15 (X30): z −15, s3 t = 5/6 z = −24.1667, s5 t = 1/9 z = −30.8889; up to 17 at Z-32.6667
//      (X34); out X35 (17.5 < 20): out to X50, then Z2.
//  13 (X26): only s1/s2 lie deeper (the pocket floor is 14): X26 Z-13, up s2 to 15 at Z-15
//      (X30), out X31, back (15.5 above everything passed).
//  11 (X22): X22 Z-11, up to 13 at Z-13 (X26), out X27, back.
// Then the semi-finishing pass along the contour (the profile itself, U0 W0) and rapid to A.
TEST_CASE("G71 type II roughs a pocket level by level, following the profile (cycles.md §2)") {
    const std::vector<Step> want = {
        rapid(46, 2), feed(46, -38), feed(47, -38), rapid(47, 2),                                        // 23
        rapid(42, 2), feed(42, -36.2222), feed(46, -38), feed(47, -38), rapid(47, 2),                    // 21
        rapid(38, 2), feed(38, -19), feed(40, -20), feed(38, -20.8333), feed(38, -34.4444),              // 19
        feed(42, -36.2222), feed(43, -36.2222), rapid(43, 2),                                            //
        rapid(34, 2), feed(34, -17), feed(40, -20), feed(34, -22.5), feed(34, -32.6667),                 // 17
        feed(38, -34.4444), feed(39, -34.4444), rapid(50, -34.4444), rapid(50, 2),                       //
        rapid(30, 2), feed(30, -15), feed(40, -20), feed(30, -24.1667), feed(30, -30.8889),              // 15
        feed(34, -32.6667), feed(35, -32.6667), rapid(50, -32.6667), rapid(50, 2),                       //
        rapid(26, 2), feed(26, -13), feed(30, -15), feed(31, -15), rapid(31, 2),                         // 13
        rapid(22, 2), feed(22, -11), feed(26, -13), feed(27, -13), rapid(27, 2),                         // 11
        rapid(20, 2), feed(20, -10), feed(40, -20), feed(28, -25), feed(28, -30), feed(46, -38),         // semi-finish
        rapid(50, 2)};
    for (const System& s : kSystems) {
        INFO(s.dialect);
        const Run r = run_clean(
            "O1\nG0 X50. Z2.\n{0} U2. R0.5\n{0} P10 Q50 U0 W0 F0.2\nN10 G0 X20. W0\nN20 G1 Z-10.\n"
            "N30 X40. Z-20.\nN40 X28. Z-25.\nN45 Z-30.\nN50 X46. Z-38.\nM30\n",
            s.turning, s.dialect);
        check_path(r, 4, want);
    }
}

// G72 type II (§3: "as G71 with X and Z exchanged"; a first block naming both axes): the same
// walk with levels in Z. A = X60 Z2, W2 R0.5, no allowance; profile N10 G0 X60 Z-4 (A′ on the
// radius (30, −4)), G1 X40 (radius 20), X30 Z-1 (radius 15, a rise toward A: the hump),
// X20 Z-3 (radius 10, the pocket), X10 Z0 (radius 5). On the radius the contour is
// (30, −4) → (20, −4) → (15, −1) → (10, −3) → (5, 0): Z reverses (the pocket), the pass axis X
// (30 20 15 10 5) is monotonic as type II asks. Levels Z 2 − 2k deeper than −4: 0, −2.
//  Z0: the contour end (5, 0) touches it; the rest lies deeper: the pass X60 → X10 at Z0, out
//      by e in Z (Z0.5), back to X60 (0.5 is above everything passed).
//  Z−2: pieces: (30,−4)→(20,−4) deeper; (20,−4)→(15,−1) crosses −2 at t = 2/3: X radius
//      20 − 5·2/3 = 16.6667 (X33.3333); above −2 up to the hump (15, −1) and down to
//      (10,−3) crossing −2 at t = 1/2: radius 12.5 (X25); deeper to (10, −3) and up (10,−3)→(5,0)
//      crossing −2 at t = 1/3: radius 8.3333 (X16.6667). Walk: X33.3333 Z-2, over the hump
//      X30 Z-1, X25 Z-2, X16.6667 Z-2; up to the previous level Z0 at (5, 0) = X10 Z0; out by e
//      in Z to Z0.5; back to X60 (the hump Z-1 is below 0.5).
// Then the semi-finishing pass: in at Z-4 from X60 (rapid: N10 is G0), the contour, back to A.
TEST_CASE("G72 type II walks the levels in Z over a pocket (cycles.md §2, §3)") {
    const Run r = run_bare("O1\nG0 X60. Z2.\nG72 W2. R0.5\nG72 P10 Q50 U0 W0 F0.2\nN10 G0 X60. Z-4.\n"
                           "N20 G1 X40.\nN30 X30. Z-1.\nN40 X20. Z-3.\nN50 X10. Z0\nM30\n",
                           "fanuc-lathe-a");
    require_clean(r);
    check_path(r, 4,
               {rapid(60, 0), feed(10, 0), feed(10, 0.5), rapid(60, 0.5),                                     // Z0
                rapid(60, -2), feed(33.3333, -2), feed(30, -1), feed(25, -2), feed(16.6667, -2),            // Z-2
                feed(10, 0), feed(10, 0.5), rapid(60, 0.5),                                                  //
                rapid(60, -4), feed(40, -4), feed(30, -1), feed(20, -3), feed(10, 0), rapid(60, 2)});
}

// Type II keeps the pass axis monotonic (cycles.md §2 "[FANUC] Z must be monotonic"): a profile
// that turns back in Z is alarm 064.
TEST_CASE("G71 type II profile reversing in Z: alarm 064") {
    require_alarm(run_bare("O1\nG0 X50. Z1.\nG71 U1. R1.\nG71 P10 Q30 F0.2\nN10 G0 X30. W0\nN20 G1 X40. Z-5.\n"
                           "N30 X45. Z-2.\nM30\n",
                           "fanuc-lathe-a"),
                  64);
}

TEST_CASE("G71–G73 profile errors are alarms with the FANUC numbers") {
    SECTION("N Q not in the program: alarm 060") {
        require_alarm(run_bare("O1\nG0 X50. Z1.\nG71 U1. R1.\nG71 P10 Q99 F0.2\nN10 G0 X40.\nM30\n", "fanuc-lathe-a"), 60);
    }
    SECTION("type I profile reversing in X: alarm 064") {
        require_alarm(run_bare("O1\nG0 X50. Z1.\nG71 U1. R1.\nG71 P10 Q30 F0.2\nN10 G0 X30.\nN20 G1 X40. Z-5.\n"
                               "N30 X35. Z-10.\nM30\n",
                               "fanuc-lathe-a"),
                      64);
    }
    SECTION("zero depth of cut: alarm 062") {
        require_alarm(run_bare("O1\nG0 X50. Z1.\nG71 U0 R1.\nG71 P10 Q20 F0.2\nN10 G0 X40.\nN20 G1 Z-5.\nM30\n",
                               "fanuc-lathe-a"),
                      62);
    }
}
