// Reference points, rotation, modal macro calls, argument specification II, system variables,
// soft limits and acceleration in the trace (issue 3). Written against the reference (semantics.md §2.8 G28/G29/G30, §2.9 G68; dialects.md §3.7
// G65/G66) and the FANUC 0i/16i/18i/30i manuals where the reference is silent (argument
// specification II, system variables, stored stroke check, the exact-stop time model of
// motion/time.hpp in events).
//
// Setups come from the built-in machine of the dialect (machine::default_machine_for) changed
// through the machine configuration, not through Setup fields, so that this file compiles with
// the current headers whatever fields the Setup gains: base_machine() zeroes the work offsets,
// external offset, work shift and reference points, removes the soft limits and the
// accelerations; each test then sets what it needs. Every expected number is derived by hand next
// to it.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "interpreter/default_setup.hpp"
#include "machine/machine.hpp"
#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf;
using interpreter::Event;
using interpreter::EventKind;
using interpreter::Setup;
// The shared helpers, but not their `run`: runs here start from the machine configuration (below).
using test::alarm_list;
using test::dialect;
using test::moves;
using test::moves_on_line;
using test::require_clean;
using test::Run;
using test::x_at;
using test::X;
using test::Y;
using test::Z;

namespace {

machine::Machine base_machine(const char* id) {
    machine::Machine m = machine::default_machine_for(dialect(id));
    for (machine::Axis& a : m.axes) {
        a.min.reset();
        a.max.reset();
        a.acceleration = 0;
    }
    for (machine::AxisValues& w : m.work_offsets) w.clear();
    m.external_offset.clear();
    m.work_shift.clear();
    for (machine::AxisValues& r : m.reference_points) r.clear();
    return m;
}

machine::Axis& axis(machine::Machine& m, char letter) {
    for (machine::Axis& a : m.axes)
        if (a.letter == letter) return a;
    FAIL("the machine has no axis " << letter);
    return m.axes.front();
}

// Under dialect `id`: base_machine(id) changed by `adjust`, made a Setup; step limit 100 000.
Run run(const std::string& text, const char* id, const std::function<void(machine::Machine&)>& adjust = {}) {
    const dialects::Dialect& d = dialect(id);
    machine::Machine m = base_machine(id);
    if (adjust) adjust(m);
    Setup setup = interpreter::make_setup(m);
    setup.step_limit = 100'000;
    return test::run_with(text, d, setup);
}

// "G0 X#<first+i> Z<i+1>." for each variable: shows common variables as tagged moves (after the
// values were stored, so the showing moves do not change them).
std::string show(int first, int count) {
    std::string s = "G90 G0\n";
    for (int i = 0; i < count; ++i)
        s += "G0 X#" + std::to_string(first + i) + " Z" + std::to_string(i + 1) + ".\n";
    return s;
}

void check_shown(const Run& r, const std::vector<double>& expected) {
    for (std::size_t i = 0; i < expected.size(); ++i) {
        INFO("tag Z" << i + 1);
        const auto x = x_at(r, static_cast<double>(i + 1));
        REQUIRE(x.has_value());
        CHECK(*x == Approx(expected[i]).margin(1e-9));
    }
}

bool near(const interpreter::Position& p, double x, double y, double z) {
    return std::fabs(p[X] - x) < 1e-6 && std::fabs(p[Y] - y) < 1e-6 && std::fabs(p[Z] - z) < 1e-6;
}

}  // namespace

// --- G30 P2–P4 and G29 (semantics.md §2.8) ------------------------------------------------------------

// FANUC mill, work = machine (offsets zero); reference points 2 (−100, −50, 0), 3 (−200, −60, −10),
// 4 (−300, −70, −20):
//   G0 X-10. Y-10. Z-10.
//   G30 P3 X-20. Y-20.   → intermediate (−20, −20, −10), then X Y to point 3: (−200, −60, −10)
//   G30 P4 Z-15.         → intermediate Z −15, then Z to point 4: (−200, −60, −20)
//   G30 X-5.             → P omitted = 2 [FANUC]: intermediate X −5, then X to −100: (−100, −60, −20)
TEST_CASE("G30 P2-P4: via the intermediate point to reference points 2, 3, 4", "[machine-state]") {
    const Run r = run("O1\nG90 G0 X-10. Y-10. Z-10.\nG30 P3 X-20. Y-20.\nG30 P4 Z-15.\nG30 X-5.\nM30\n", "fanuc-mill",
                      [](machine::Machine& m) {
                          m.reference_points[1] = {{'X', -100}, {'Y', -50}, {'Z', 0}};
                          m.reference_points[2] = {{'X', -200}, {'Y', -60}, {'Z', -10}};
                          m.reference_points[3] = {{'X', -300}, {'Y', -70}, {'Z', -20}};
                      });
    require_clean(r);
    const auto p3 = moves_on_line(r, 3);
    REQUIRE(p3.size() == 2);
    CHECK(near(p3[0].machine_end, -20, -20, -10));
    CHECK(near(p3[1].machine_end, -200, -60, -10));
    const auto p4 = moves_on_line(r, 4);
    REQUIRE(p4.size() == 2);
    CHECK(near(p4[0].machine_end, -200, -60, -15));
    CHECK(near(p4[1].machine_end, -200, -60, -20));
    const auto p2 = moves_on_line(r, 5);
    REQUIRE(p2.size() == 2);
    CHECK(near(p2[0].machine_end, -5, -60, -20));
    CHECK(near(p2[1].machine_end, -100, -60, -20));
    for (const Event& e : moves(r)) CHECK(e.kind == EventKind::rapid);
}

// The seed 002 example of semantics.md §2.8 (pcnc-mill), reference point 1 at machine (0, 0, 0):
//   F500 / G1 X-10 Y-10 / X-40 Y-10 / G28 X50 Y100 (rapid to B = (50, 100), then to (0, 0)) / M0 /
//   G29 X-30 Y-5: rapid from the reference point to B (50, 100), then to C (−30, −5) /
//   G1 X-50 Y-30.
TEST_CASE("G29 returns through the G28 intermediate point (seed 002 example)", "[machine-state]") {
    const Run r = run("F500\nG1 X-10 Y-10\nX-40 Y-10\nG28 X50 Y100\nM0\nG29 X-30 Y-5\nG1 X-50 Y-30\nM2\n", "pcnc-mill");
    require_clean(r);
    const auto g29 = moves_on_line(r, 6);
    REQUIRE(g29.size() == 2);
    CHECK(g29[0].kind == EventKind::rapid);
    CHECK(near(g29[0].start, 0, 0, 0));
    CHECK(near(g29[0].end, 50, 100, 0));
    CHECK(near(g29[1].end, -30, -5, 0));
    const auto last = moves_on_line(r, 7);
    REQUIRE(last.size() == 1);
    CHECK(last[0].kind == EventKind::linear);
    CHECK(near(last[0].end, -50, -30, 0));
}

// Seed 003 (semantics.md §2.8 point 4): the intermediate point is kept per axis.
//   N1 G90 X100. Y200. Z300. / N2 G28 X400. Y500. (B = 400, 500, —) / N3 G28 Z600. (B = 400, 500, 600)
//   N4 G29 X0. Y0. Z0.: rapid to B (400, 500, 600), then to (0, 0, 0). Reference point 1 at the
//   machine origin, offsets zero.
TEST_CASE("G28 keeps the intermediate point per axis for G29 (seed 003 example)", "[machine-state]") {
    const Run r = run("O1\nN1 G90 G0 X100. Y200. Z300.\nN2 G28 X400. Y500.\nN3 G28 Z600.\nN4 G29 X0. Y0. Z0.\nM30\n",
                      "fanuc-mill");
    require_clean(r);
    const auto g29 = moves_on_line(r, 5);
    REQUIRE(g29.size() == 2);
    CHECK(near(g29[0].end, 400, 500, 600));
    CHECK(near(g29[1].end, 0, 0, 0));
}

// pcnc-mill accepts G30 P1 = the G28 point (semantics.md §2.8): reference point 1 at (5, 6, 7):
// G30 P1 X10 Y10 → intermediate (10, 10, 0), then X Y to (5, 6).
TEST_CASE("G30 P1 (pcnc-mill) is the G28 point", "[machine-state]") {
    const Run r = run("G90 G0 X0 Y0 Z0\nG30 P1 X10 Y10\nM2\n", "pcnc-mill",
                      [](machine::Machine& m) { m.reference_points[0] = {{'X', 5}, {'Y', 6}, {'Z', 7}}; });
    require_clean(r);
    const auto g30 = moves_on_line(r, 2);
    REQUIRE(g30.size() == 2);
    CHECK(near(g30[0].machine_end, 10, 10, 0));
    CHECK(near(g30[1].machine_end, 5, 6, 0));
}

// --- G68 / G69 (semantics.md §2.9) ---------------------------------------------------------------------

// FANUC: positive R is counter-clockwise, centre in the plane's two axes. Offsets zero, so the
// machine position is the rotated work position.
//   G68 X0. Y0. R90.  then G0 X10. Y0. → (10, 0) turned +90° about (0, 0) = (0, 10)
//   G69, G68 X10. Y0. R90. then G0 X20. Y0. → (20, 0) about (10, 0): offset (10, 0) → (0, 10): (10, 10)
//   G69, G0 X20. Y0. → (20, 0)
TEST_CASE("G68 FANUC: rotation counter-clockwise about the given centre; G69 cancels", "[machine-state]") {
    const Run r = run("O1\nG17 G90 G0 X0. Y0.\nG68 X0. Y0. R90.\nG0 X10. Y0.\nG69\nG68 X10. Y0. R90.\nG0 X20. Y0.\n"
                      "G69\nG0 X20. Y0.\nM30\n",
                      "fanuc-mill");
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 4);
    CHECK(near(m[1].machine_end, 0, 10, 0));
    CHECK(near(m[2].machine_end, 10, 10, 0));
    CHECK(near(m[3].machine_end, 20, 0, 0));
}

// Incremental moves are rotated too: G68 R45 about the origin, G91 G1 X10. → machine
// (10·cos 45°, 10·sin 45°) = (7.0711, 7.0711).
TEST_CASE("G68: incremental moves are rotated", "[machine-state]") {
    const Run r = run("O1\nG17 G90 G0 X0. Y0.\nG68 X0. Y0. R45.\nG91 G1 X10. F100.\nM30\n", "fanuc-mill");
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 2);
    CHECK(m[1].machine_end[X] == Approx(7.0710678));
    CHECK(m[1].machine_end[Y] == Approx(7.0710678));
    CHECK(m[1].length_mm == Approx(10));
}

// ADV400: "+" = clockwise (semantics.md §2.9): G68 X0 Y0 R90, G0 X10 Y0 → (10, 0) turned −90° =
// (0, −10).
TEST_CASE("G68 ADV400: positive R turns clockwise", "[machine-state]") {
    const Run r = run("G17 G90 G0 X0 Y0\nG68 X0 Y0 R90\nG0 X10 Y0\nG69\nM30\n", "adv400-mill");
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 2);
    CHECK(near(m[1].machine_end, 0, -10, 0));
}

// --- G66 / G67 (dialects.md §3.7) ---------------------------------------------------------------------

// G66 calls the macro after every following move block until G67; the G66 block itself does not
// call, the macro's own moves do not call again. O9010 lowers Z by #1 (= A1.):
//   X10 → call (Z −1), X20 → call (Z −2), G67, X30 → no call. Two call events; final (30, 0, −2).
TEST_CASE("G66 calls the macro after each move until G67", "[machine-state]") {
    const Run r = run("O1\nG90 G0 X0. Y0. Z0.\nG66 P9010 A1.\nG0 X10.\nG0 X20.\nG67\nG0 X30.\nM30\n"
                      "O9010\nG91 G0 Z-#1\nG90\nM99\n",
                      "fanuc-mill");
    require_clean(r);
    std::size_t calls = 0;
    for (const Event& e : r.events)
        if (e.kind == EventKind::call && e.code == 9010) ++calls;
    CHECK(calls == 2);
    const auto m = moves(r);
    REQUIRE(m.size() == 6);   // start, X10, Z−1, X20, Z−2, X30
    CHECK(m[2].end[Z] == Approx(-1));
    CHECK(m[4].end[Z] == Approx(-2));
    CHECK(near(r.result.final_position, 30, 0, -2));
}

// --- G65 argument specification II (FANUC) -------------------------------------------------------------

// A B C → #1 #2 #3, then I J K in sets: set 1 → #4 #5 #6, set 2 → #7 #8 #9, set 3 → #10 #11 #12, …
// set 10 → #31 #32 #33. A repeated I starts a new set. O9020 shows #1..#13 (−1 when vacant):
//   A1. B2. C3. I4. J5. K6. I7. J8. K9. I10. J11. K12. → #n = n for n = 1..12, #13 vacant.
// Second call I4. I7.: the second I is I2 → #4 = 4, #7 = 7, #5 vacant.
TEST_CASE("G65 argument specification II", "[machine-state]") {
    std::string body;
    for (int n = 1; n <= 13; ++n)
        body += "#100=-1\nIF [#" + std::to_string(n) + " NE #0] THEN #100=#" + std::to_string(n) + "\nG0 X#100 Z" +
                std::to_string(n) + ".\n";
    const Run r = run("O1\nG90 G0 X0. Y0. Z0.\nG65 P9020 A1. B2. C3. I4. J5. K6. I7. J8. K9. I10. J11. K12.\nM30\nO9020\n" +
                          body + "M99\n",
                      "fanuc-mill");
    require_clean(r);
    for (int n = 1; n <= 13; ++n) {
        INFO("#" << n);
        const auto x = x_at(r, n);
        REQUIRE(x);
        CHECK(*x == Approx(n <= 12 ? n : -1));
    }
    const Run two = run("O1\nG90 G0 X0. Y0. Z0.\nG65 P9021 I4. I7.\nM30\nO9021\n#100=-1\nIF [#5 NE #0] THEN #100=#5\n"
                        "G0 X#4 Z1.\nG0 X#7 Z2.\nG0 X#100 Z3.\nM99\n",
                        "fanuc-mill");
    require_clean(two);
    check_shown(two, {4, 7, -1});
}

// --- system variables (FANUC "System variables") ------------------------------------------------------

// #3000 = n (message): the program stops with macro alarm 3000 + n and the message.
TEST_CASE("#3000 raises a macro alarm", "[machine-state]") {
    const Run r = run("O1\nG90 G0 X0. Y0.\n#3000=12(TOOL BROKEN)\nG0 X5.\nM30\n", "fanuc-mill");
    INFO(alarm_list(r));
    REQUIRE(r.result.alarms.size() == 1);
    CHECK(r.result.alarms[0].code == 3012);
    CHECK(r.result.alarms[0].text.find("TOOL BROKEN") != std::string::npos);
    CHECK_FALSE(r.result.completed);
    CHECK(moves(r).size() == 1);
}

// #3006 = 1 (message): a stop with a message, like M00 (a dry run goes on past it).
TEST_CASE("#3006 stops with a message", "[machine-state]") {
    const Run r = run("O1\nG90 G0 X0. Y0.\n#3006=1(CHECK PART)\nG0 X5.\nM30\n", "fanuc-mill");
    require_clean(r);
    bool stop = false;
    for (const Event& e : r.events)
        if (e.kind == EventKind::stop && e.text.find("CHECK PART") != std::string::npos) stop = true;
    CHECK(stop);
    CHECK(moves(r).size() == 2);
}

// #3001 counts milliseconds of (simulated) run time and can be preset: #3001 = 500, G4 P2000
// (2000 ms on FANUC) → #3001 = 500 + 2000 = 2500.
TEST_CASE("#3001 timer follows the run time", "[machine-state]") {
    const Run r = run("O1\n#3001=500\nG4 P2000\n#100=#3001\n" + show(100, 1) + "M30\n", "fanuc-mill");
    require_clean(r);
    check_shown(r, {2500});
}

// Modal information (FANUC M): #4001 group 01 (G01 → 1), #4002 plane (17), #4003 G90/G91 (91),
// #4005 G94/G95 (95), #4014 work system (55), #4109 F (0.25), #4119 S (1200), #4120 T (5).
TEST_CASE("#4001-#4130 modal information", "[machine-state]") {
    const Run r = run("O1\nG91 G01 G17 G55 G95 X0 F0.25 S1200 M3\nT5 M6\n"
                      "#100=#4001\n#101=#4002\n#102=#4003\n#103=#4005\n#104=#4014\n#105=#4109\n#106=#4119\n#107=#4120\n" +
                          show(100, 8) + "M30\n",
                      "fanuc-mill");
    require_clean(r);
    check_shown(r, {1, 17, 91, 95, 55, 0.25, 1200, 5});
}

// Positions (FANUC M): #5001- end point of the last block (work), #5021- machine position, #5041-
// current position (work). G54 zero at machine (−500, −300, −500); after G0 X10. Y20. Z30.:
//   #5001..3 = (10, 20, 30), #5021..3 = (−490, −280, −470), #5041..3 = (10, 20, 30).
TEST_CASE("#5001 #5021 #5041 positions", "[machine-state]") {
    const Run r = run("O1\nG90 G0 X10. Y20. Z30.\n#100=#5001\n#101=#5002\n#102=#5003\n#103=#5021\n#104=#5022\n"
                      "#105=#5023\n#106=#5041\n#107=#5042\n#108=#5043\n" +
                          show(100, 9) + "M30\n",
                      "fanuc-mill", [](machine::Machine& m) { m.work_offsets[0] = {{'X', -500}, {'Y', -300}, {'Z', -500}}; });
    require_clean(r);
    check_shown(r, {10, 20, 30, -490, -280, -470, 10, 20, 30});
}

// A lathe's axes are X, Z, ...: #5001 is X (diameter), #5002 is Z. After G0 X40. Z-5.: (40, −5).
TEST_CASE("#5001 #5002 on a lathe are X and Z", "[machine-state]") {
    const Run r = run("O1\nG0 X40. Z-5.\n#100=#5001\n#101=#5002\nG0 X#100 Z1.\nG0 X#101 Z2.\nM30\n", "fanuc-lathe-a");
    require_clean(r);
    check_shown(r, {40, -5});
}

// Work offsets (FANUC M): G54 axis n = #5220 + n, G55 = #5240 + n, …: read G54 (−500, −300, −500);
// write G55 = (−100, 0, 0) and move there: G55 G0 X0. Y0. Z0. → machine (−100, 0, 0).
TEST_CASE("#5221- work offsets, read and write", "[machine-state]") {
    const Run r = run("O1\n#100=#5221\n#101=#5222\n#102=#5223\n#5241=-100.\n#5242=0\n#5243=0\n" + show(100, 3) +
                          "G55 G0 X0. Y0. Z0.\nM30\n",
                      "fanuc-mill", [](machine::Machine& m) { m.work_offsets[0] = {{'X', -500}, {'Y', -300}, {'Z', -500}}; });
    require_clean(r);
    check_shown(r, {-500, -300, -500});
    const auto m = moves(r);
    REQUIRE_FALSE(m.empty());
    CHECK(near(m.back().machine_end, -100, 0, 0));
}

// Tool offsets (FANUC M, up to 200 offsets): #2001 and #10001 are the same register (offset 1):
// #10001 = 12.5 reads back as #2001; #2002 = 3 reads back as #10002.
TEST_CASE("#2001 / #10001 tool offsets", "[machine-state]") {
    const Run r = run("O1\n#10001=12.5\n#2002=3.\n#100=#2001\n#101=#10002\n" + show(100, 2) + "M30\n", "fanuc-mill");
    require_clean(r);
    check_shown(r, {12.5, 3});
}

// --- time with acceleration in events (motion/time.hpp exact-stop model) ----------------------------------

// Machine X: rapid 6000 mm/min (100 mm/s), acceleration 500 mm/s²; offsets zero.
//   G1 X100. F6000.: 100 mm at 100 mm/s; v²/a = 20 ≤ 100 → 1 + 0.2 = 1.2 s (1.0 s without)
//   G0 X0.:          100 mm at the rapid rate 100 mm/s, same profile → 1.2 s
//   G1 X10. F6000.:  10 mm, triangle 2·√(10/500) = 0.2828427 s
// Total 2.6828427 s.
TEST_CASE("feed and rapid times include acceleration", "[machine-state]") {
    const Run r = run("O1\nG90 G1 X100. F6000.\nG0 X0.\nG1 X10. F6000.\nM30\n", "fanuc-mill", [](machine::Machine& m) {
        axis(m, 'X').rapid = 6000;
        axis(m, 'X').acceleration = 500;
    });
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 3);
    CHECK(m[0].time_s == Approx(1.2));
    CHECK(m[1].time_s == Approx(1.2));
    CHECK(m[2].time_s == Approx(0.2828427));
    CHECK(r.result.total_time_s == Approx(2.6828427));
}

// --- soft limits (stored stroke check 1: FANUC OT500 + side, OT501 − side) ------------------------------

// Machine X limits [−100, 100], offsets zero. X100. exactly on the limit is allowed; X150. passes
// the + limit (alarm 500), X−150. the − limit (alarm 501); the run stops.
TEST_CASE("soft limits: OT500 and OT501", "[machine-state]") {
    auto limits = [](machine::Machine& m) {
        axis(m, 'X').min = -100;
        axis(m, 'X').max = 100;
    };
    const Run ok = run("O1\nG90 G0 X100.\nX-100.\nM30\n", "fanuc-mill", limits);
    require_clean(ok);
    const Run plus = run("O1\nG90 G0 X150.\nM30\n", "fanuc-mill", limits);
    INFO(alarm_list(plus));
    REQUIRE(plus.result.alarms.size() == 1);
    CHECK(plus.result.alarms[0].code == 500);
    CHECK_FALSE(plus.result.completed);
    const Run minus = run("O1\nG90 G0 X-150.\nM30\n", "fanuc-mill", limits);
    INFO(alarm_list(minus));
    REQUIRE(minus.result.alarms.size() == 1);
    CHECK(minus.result.alarms[0].code == 501);
}

// An arc whose end points are inside but whose bulge passes the limit: from (95, −10) to (95, 10)
// with G03 J10 (centre (95, 0), radius 10, CCW from −90° through 0°) reaches X105 > 100: alarm 500.
TEST_CASE("soft limits check the whole arc, not only its end", "[machine-state]") {
    const Run r = run("O1\nG17 G90 G0 X95. Y-10.\nG03 X95. Y10. I0. J10. F100.\nM30\n", "fanuc-mill", [](machine::Machine& m) {
        axis(m, 'X').min = -100;
        axis(m, 'X').max = 100;
    });
    INFO(alarm_list(r));
    REQUIRE(r.result.alarms.size() == 1);
    CHECK(r.result.alarms[0].code == 500);
}

// A block that sets a frame does not move, but its M codes run: the coolant of `G68 ... M08`
// (and of G52 and G51.1 blocks, same path in executor.cpp apply_block_words) comes on.
TEST_CASE("M codes in a G68, G52 or G51.1 block still run", "[machine-state]") {
    for (const char* frame : {"G68 X0. Y0. R45.", "G52 X10. Y0.", "G51.1 X0."}) {
        INFO(frame);
        const Run r = run(std::string("O1\nG17 G90 G0 X0. Y0.\n") + frame + " M08\nG1 X10. F100.\nM09\nM30\n", "fanuc-mill");
        require_clean(r);
        const auto coolant = of_kind(r, EventKind::coolant);
        REQUIRE(coolant.size() == 2);
        CHECK(coolant[0].source.line == 3);
        CHECK(coolant[0].code == 8);
        CHECK(moves_on_line(r, 3).empty());
    }
}
