// Direct drawing (reference semantics.md §10): angles, chamfers and fillets as the moves the
// control makes, in a running program and inside a G70 profile, and the alarms of §10.1. The
// expected points are the reference's worked numbers (§10.2, §10.3), derived again in the comments
// with radius geometry (X is a diameter in the program, a radius in the geometry).
#include <cmath>

#include "tests/interpreter/cycle_steps.hpp"

using namespace kerf::test;

namespace {

// An arc's centre, to 0.001 mm (X a diameter).
void check_center(const Event& e, double x, double z) {
    INFO(describe(e));
    REQUIRE(e.center);
    CHECK((*e.center)[X] == Approx(x).margin(0.001));
    CHECK((*e.center)[Z] == Approx(z).margin(0.001));
}

// A mill's G17 fillet from +X travel into +Y travel (a G03 quarter): the line to (x_in, 0), the
// arc to (x_corner, r) about (x_in, r), to 0.001 mm (the G17 moves of `line`).
void check_xy_fillet(const Run& r, std::uint32_t line, double x_in, double x_corner, double radius) {
    const std::vector<Event> m = moves_on_line(r, line);
    REQUIRE(m.size() == 2);
    CHECK(m[0].end[X] == Approx(x_in));
    CHECK(m[0].end[Y] == Approx(0).margin(1e-9));
    CHECK(m[1].kind == EventKind::arc_ccw);
    CHECK(m[1].end[X] == Approx(x_corner));
    CHECK(m[1].end[Y] == Approx(radius));
    REQUIRE(m[1].center);
    CHECK((*m[1].center)[X] == Approx(x_in));
    CHECK((*m[1].center)[Y] == Approx(radius));
}

}  // namespace

// semantics.md §10.2, O0012 (program exact but for the G10/T/spindle lines, which do not change
// the path). Lines: 1 O0012, 2 G0, 3 G1 Z0, 4 N70, 5 N80, ... 13 N150, 14 N160.
//   N70 ,A90 R6 + N80 X50 Z-25 ,A165: the line at 90° from P1 (Z0 r0) meets the line at 165°
//   through (Z-25, r25): r = 25 + (Z − (−25))·tan(165°)·… → the corner Z0 r18.3013 (X36.603).
//   Turn 90° → 165° = +75° (G03); setback 6·tan 37.5° = 4.6039: in at r18.3013 − 4.6039 =
//   13.6974 (X27.395 Z0); centre 6 to the left of +X travel, i.e. Z−6 (X27.395 Z−6); out along
//   165°: Z 0 + 4.6039·cos165 = −4.4470, r 18.3013 + 4.6039·sin165 = 19.4929 (X38.986).
//   N90 ,A180 + N100 X75 Z-49 ,A90: r25 line meets Z−49 → X50 Z−49 (sharp corner).
//   N100 ,C1: 1 mm back along 90° (r36.5, X73) and 1 mm on along 180° (Z−50).
//   N120 ,A150 R50 + N130 X185 Z-100 ,A110: from (Z−60, r37.5) at 150° and through (Z−100,
//   r92.5) at 110°: corner Z−85.298 r52.105 (X104.211); turn −40° (G02); setback 50·tan 20° =
//   18.199: in at Z−85.298 + 18.199·0.8660 = −69.537, r 52.105 − 18.199·0.5 = 43.006 (X86.013);
//   out at Z −85.298 + 18.199·cos110 = −91.522, r 52.105 + 18.199·sin110 = 69.207 (X138.413).
//   N140 ,A90 ,C2 + N150 X200 Z-150 ,A180: corner X200 Z−100; C2 → X196 Z−100, X200 Z−102.
TEST_CASE("direct drawing: the O0012 contour of semantics.md §10.2") {
    const Run r = run(
        "O0012\n"                                  // 1
        "G99 F0.12 G0 X0 Z3\n"                     // 2
        "N60 G1 Z0\n"                              // 3
        "N70 ,A90 R6\n"                            // 4
        "N80 X50 Z-25 ,A165\n"                     // 5
        "N90 ,A180\n"                              // 6
        "N100 X75 Z-49 ,A90 ,C1\n"                 // 7
        "N110 Z-60\n"                              // 8
        "N120 ,A150 R50\n"                         // 9
        "N130 X185 Z-100 ,A110\n"                  // 10
        "N140 ,A90 ,C2\n"                          // 11
        "N150 X200 Z-150 ,A180\n"                  // 12
        "N160 G0 X250 Z200 M30\n",                 // 13
        "spinner-lathe-a");
    require_clean(r);
    check_path(r, 4, {feed(27.395, 0), ccw(38.986, -4.447)});
    check_center(moves_on_line(r, 4).at(1), 27.395, -6);
    check_path(r, 5, {feed(50, -25)});
    check_path(r, 6, {feed(50, -49)});
    check_path(r, 7, {feed(73, -49), feed(75, -50)});
    check_path(r, 8, {feed(75, -60)});
    check_path(r, 9, {feed(86.013, -69.537), cw(138.413, -91.522)});
    check_path(r, 10, {feed(185, -100)});
    check_path(r, 11, {feed(196, -100), feed(200, -102)});
    check_path(r, 12, {feed(200, -150)});
    check_path(r, 13, {rapid(250, 200)});
    // The fillet of N120 has the radius 50 about X172.615 Z−44.537 (the reference's centre:
    // 50 to the right of the 150° line at the in point: Z −69.537 + 50·sin150·… = −44.537,
    // r 43.006 + 50·cos30 = 86.308, X172.615).
    check_center(moves_on_line(r, 9).at(1), 172.615, -44.537);
}

// semantics.md §10.3, O0013: from X97 Z−15 a line at 150° to the level of X102 (r51): rises 2.5,
// so Z −15 − 2.5/tan30° = −19.330; then Z−45.
TEST_CASE("direct drawing: the O0013 corner (plain A in SPINNER) of semantics.md §10.3") {
    const Run r = run("O0013\nG99 F0.2 G0 X97 Z-10\nG1 Z-15\nN140 A150\nN150 X102 Z-45 A180\nG0 X200 M30\n",
                      "spinner-lathe-a");
    require_clean(r);
    check_path(r, 4, {feed(102, -19.330)});
    check_path(r, 5, {feed(102, -45)});
}

// semantics.md §10.3, O0014's profile N1000–N1100 run by G70 (and G71 before it): the points
// the reference computes. N1040 A170 from X60 Z−22 meets N1050's 140° line through X95 Z−50 at
// X63.190 Z−31.045; R20, turn 170°→140° = −30° (G02), setback 20·tan15° = 5.359: X61.329
// Z−25.767 → X70.079 Z−35.150 about X100.721 Z−22.294; R5 at X95 Z−50, turn 140°→180° = +40°
// (G03), setback 5·tan20° = 1.820: X92.660 Z−48.606 → X95 Z−51.820 about X85 Z−51.820; N1060
// A180 meets N1070's 135° line through X110 Z−64 at X95 Z−56.5.
TEST_CASE("direct drawing inside a G70 profile gives the O0014 corners of semantics.md §10.3") {
    const std::string profile =
        "N1000 G0 X56\n"
        "N1010 G1 Z0\n"
        "N1020 X60 Z-2\n"
        "N1030 Z-22\n"
        "N1040 A170 R20\n"
        "N1050 X95 Z-50 A140 R5\n"
        "N1060 A180\n"
        "N1070 X110 Z-64 A135\n"
        "N1100 X111\n";
    // The profile after M30 (G70 goes on after its own block, cycles.md §1): only G70 runs it.
    const Run r = run("O0014\nG99 F0.15\nG0 X111 Z2\nG70 P1000 Q1100\nM30\n" + profile, "spinner-lathe-a");
    require_clean(r);
    check_path(r, 4, {rapid(56, 2), feed(56, 0), feed(60, -2), feed(60, -22), feed(61.329, -25.767), cw(70.079, -35.150),
                      feed(92.660, -48.606), ccw(95, -51.820), feed(95, -56.5), feed(110, -64), feed(111, -64), rapid(111, 2)});
    const std::vector<Event> arcs_of_g70 = arcs(r);
    REQUIRE(arcs_of_g70.size() == 2);
    check_center(arcs_of_g70[0], 100.721, -22.294);
    check_center(arcs_of_g70[1], 85, -51.820);
    // G71 over the same profile runs without an alarm and ends at its start point.
    const Run rough = run("O0014\nG99 F0.25\nG0 X111 Z2\nG71 U3 R1\nG71 P1000 Q1100 U0.3 W0.1\n" + profile + "M30\n",
                          "spinner-lathe-a");
    require_clean(rough);
    CHECK(rough.result.final_position[X] == Approx(111));
    CHECK(rough.result.final_position[Z] == Approx(2));
}

// semantics.md §10.3, O0017's internal profile: the 180° line at r19 (X38) meets N2040's 195°
// line through X25 Z−30 where r falls 6.5: Z −30 + 6.5/tan15° = −5.742. R15, turn 180°→195° =
// +15° (G03), setback 15·tan7.5° = 1.975: X38 Z−3.767 → r 19 − 1.975·sin15 = 18.489 (X36.978)
// Z −5.742 − 1.975·cos15 = −7.649, about r4 (X8) Z−3.767; then X25 Z−30. Live and in G70.
TEST_CASE("direct drawing: the O0017 internal corner of semantics.md §10.3, live and as a G70 profile") {
    const std::string blocks = "N2020 G1 X38 Z-1.5\nN2030 A180 R15\nN2040 X25 Z-30 A195\n";
    const Run live = run("O0017\nG99 F0.12\nG0 X41 Z0\n" + blocks + "G0 X20 M30\n", "spinner-lathe-a");
    require_clean(live);
    check_path(live, 4, {feed(38, -1.5)});
    check_path(live, 5, {feed(38, -3.767), ccw(36.978, -7.649)});
    check_path(live, 6, {feed(25, -30)});
    check_center(arcs(live).at(0), 8, -3.767);
    const Run profile = run("O0017\nG99 F0.12\nG0 X18 Z2\nG70 P2020 Q2040\nM30\n" + blocks, "spinner-lathe-a");
    require_clean(profile);
    check_path(profile, 4, {feed(38, -1.5), feed(38, -3.767), ccw(36.978, -7.649), feed(25, -30), rapid(18, 2)});
}

// FANUC comma words on a lathe (fanuc-lathe-a): ,C and ,R at the end of a block; an angle with
// one coordinate (X given, Z computed: from X20 Z0 at 135° r rises 5 while Z falls 5 → Z−5).
TEST_CASE("direct drawing: FANUC ,A with one coordinate, ,C and ,R on fanuc-lathe-a") {
    const Run r = run(
        "O1\nG99 F0.1\nG0 X20. Z0.\n"
        "G1 X30. ,A135\n"          // 4: r10 → r15 at 135°: Z −5
        "Z-20. ,C2.\n"              // 5: chamfer 2: stop at Z−18, then to X34. Z−20
        "X50. ,R3.\n"               // 6: up to the corner X50. Z−20, then line 7 goes −Z
        "Z-40.\n"                  // 7
        "M30\n",
        "fanuc-lathe-a");
    require_clean(r);
    check_path(r, 4, {feed(30, -5)});
    check_path(r, 5, {feed(30, -18), feed(34, -20)});
    // Line 6 goes +X (90°) then line 7 −Z (180°): turn +90° (G03), setback 3: r25 − 3 = 22 (X44),
    // out at Z−23 r25; centre 3 to the left of +X travel: Z−23, r22 (X44).
    check_path(r, 6, {feed(44, -20), ccw(50, -23)});
    check_center(arcs(r).at(0), 44, -23);
    check_path(r, 7, {feed(50, -40)});
}

// A mill in G17: ,A from +X counter-clockwise, a fillet between +X and +Y travel.
TEST_CASE("direct drawing on a mill (fanuc-mill G17): ,R between two lines") {
    const Run r = run("O1\nG17 G90 G0 X0 Y0\nG1 X50. ,R10. F100.\nY40.\nM30\n", "fanuc-mill");
    require_clean(r);
    // +X then +Y: turn +90° (G03), setback 10: X40 Y0 → X50 Y10 about X40 Y10.
    check_xy_fillet(r, 3, 40, 50, 10);
}

// The next block is read ahead from the point the running block is programmed to (semantics.md
// §10.1 (c)): the executor reads it through const functions of the live state (executor.hpp
// look_ahead), the tool taken to stand at that point. So #5001 in the block
// read ahead is X10, the end of N3: the corner is +X → +Y, a 90° turn, setback 2: X8 Y0, then
// the fillet about X8 Y2 to X10 Y2; N4 then runs from there to X10 Y10 (its #5001 is the tool's
// X10). Read with the tool where it stood before N3 (X0) the next block would run to X0 Y10, a
// 135° turn with setback 2·tan 67.5° = 4.828, and N3 would end at X5.172.
TEST_CASE("direct drawing: the block read ahead reads #5001 at the end of the running block") {
    const Run r = run("O1\nG17 G90 G0 X0 Y0\nG1 X10. Y0 ,R2. F100.\nX[#5001] Y10.\nM30\n", "fanuc-mill");
    require_clean(r);
    check_xy_fillet(r, 3, 8, 10, 2);
    const std::vector<Event> next = moves_on_line(r, 4);
    REQUIRE(next.size() == 1);
    CHECK(next[0].end[X] == Approx(10));
    CHECK(next[0].end[Y] == Approx(10));
}

// An alarm in the block read ahead is that block's, standing where the reading stood (the end of
// the running block, X50 Y0), and the running block makes no move: N3's corner needs N4, whose
// Y[1/0] is alarm 112 (division by zero).
TEST_CASE("direct drawing: an alarm of the block read ahead stops the run before the corner") {
    const Run r = run("O1\nG17 G90 G0 X0 Y0\nG1 X50. ,R10. F100.\nY[1/0]\nM30\n", "fanuc-mill");
    require_alarm(r, 112);
    const Event& a = r.result.alarms[0];
    CHECK(a.source.line == 4);
    CHECK(a.end[X] == Approx(50));
    CHECK(a.end[Y] == Approx(0).margin(1e-9));
    CHECK(moves_on_line(r, 3).empty());
}

// The alarms of §10.1 ("a missing intersection or a corner larger than the adjacent segments is
// an error"), with FANUC's numbers.
TEST_CASE("direct drawing alarms: parallel lines, corners that do not fit, a bad next block") {
    struct Case {
        const char* what;
        const char* blocks;   // after G0 X20. Z0. (r10 Z0)
        int alarm;
    };
    const Case cases[] = {
        {"parallel: an angle-only line at 180° and a next line at 180° never meet", "G1 ,A180\nX30. Z-20. ,A180\n", 57},
        {"a chamfer of 5 on a line of 2", "G1 Z-2. ,C5.\nX40.\n", 55},
        {"a fillet of 5 (setback 5 at 90°) before a line of 1 (X20 -> X22 is r10 -> r11)", "G1 Z-20. ,R5.\nX22.\n", 55},
        {"an angle-only block followed by a block without an angle", "G1 ,A150\nX30. Z-20.\n", 56},
        {"a corner followed by a rapid", "G1 Z-20. ,C1.\nG0 X40.\n", 52},
        {"a corner followed by a block without a move (M30)", "G1 Z-20. ,C1.\n", 51},
    };
    for (const Case& c : cases) {
        INFO(c.what);
        require_alarm(run(std::string("O1\nG99 F0.1\nG0 X20. Z0.\n") + c.blocks + "M30\n", "fanuc-lathe-a"), c.alarm);
    }
}
