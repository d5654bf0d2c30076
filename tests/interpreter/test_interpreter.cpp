// The interpreter core: positions, modes, subprograms, work shift, macros, loops, step limit.
// Expected numbers are derived by hand in the comments.
#include <catch2/catch.hpp>

#include "interpreter/default_setup.hpp"
#include "interpreter/interpreter.hpp"
#include "tests/interpreter/interpreter_fixture.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace kerf;
using interpreter::EventKind;
// The shared helpers, but not their `run`: runs here use the dialect's built-in machine (below).
using test::moves;
using test::Run;
using test::X;
using test::Y;
using test::Z;

namespace {

// The built-in machine of the dialect (interpreter::default_setup), with `step_limit`; without
// acceleration when `acceleration` is false.
Run run(const std::string& text, const char* dialect_id, std::uint64_t step_limit = 10'000'000,
        bool acceleration = true) {
    const dialects::Dialect* d = dialects::builtin_registry().find(dialect_id);
    if (!d) FAIL("no dialect " << dialect_id);
    interpreter::Setup setup = interpreter::default_setup(*d);
    setup.step_limit = step_limit;
    if (!acceleration) setup.accel_mm_s2 = {};
    return test::run_with(text, *d, setup);   // REQUIREs the program (the one assertion of a run)
}

}  // namespace

TEST_CASE("system A: absolute X/Z and incremental U/W") {
    const Run r = run("O1\nG0 X50. Z2.\nG1 U-10. W-5. F.2\nX20.\nM30\n", "fanuc-lathe-a");
    const auto m = moves(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].end[X] == Approx(40));   // 50 + U-10 (diameter)
    CHECK(m[1].end[Z] == Approx(-3));   // 2 + W-5
    CHECK(m[1].length_mm == Approx(std::sqrt(25.0 + 25.0)));   // radius 5 in X, 5 in Z
    CHECK(r.result.final_position[X] == Approx(20));
    CHECK(r.result.completed);
    CHECK(r.result.alarms.empty());
}

TEST_CASE("mill: G90/G91 decide absolute or incremental") {
    const Run r = run("O1\nG90 G0 X10. Y10.\nG91 G1 X5. Y-5. F100\nG90 X0.\nM30\n", "fanuc-mill", 10'000'000, false);
    const auto m = moves(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].end[X] == Approx(15));
    CHECK(m[1].end[Y] == Approx(5));
    CHECK(m[1].time_s == Approx(std::sqrt(50.0) / 100.0 * 60.0));   // 7.071 mm at 100 mm/min
    CHECK(m[2].end[X] == Approx(0));
}

TEST_CASE("M98 P41001 runs O1001 four times; M98 P12 L3 three times") {
    const Run packed = run("O1\nG0 X0. Z0.\nM98 P41001\nM30\nO1001\nG0 W-10.\nM99\n", "fanuc-lathe-a");
    CHECK(packed.result.final_position[Z] == Approx(-40));
    CHECK(packed.result.completed);
    const Run pl = run("O1\nG90 G0 X0 Y0\nM98 P12 L3\nM30\nO12\nG91 G0 X5\nG90\nM99\n", "adv400-mill");
    CHECK(pl.result.final_position[X] == Approx(15));
}

TEST_CASE("M99 P returns to a sequence number of the caller") {
    const Run r = run("O1\nG0 X0. Z0.\nM98 P2\nG0 Z100.\nN50 G0 Z7.\nM30\nO2\nG0 Z1.\nM99 P50\n", "fanuc-lathe-a");
    CHECK(r.result.final_position[Z] == Approx(7));
    for (const auto& m : moves(r)) CHECK(m.end[Z] != Approx(100));   // the block after M98 is skipped
}

TEST_CASE("G10 P0 work shift: X/Z replace, U/W add (semantics.md §2.6 example)") {
    // O0001 of seed 001 §7.8: G10 P0 Z-130, then O0002 three times, each adding W10: the register
    // ends at -100. machine = work + G54 - shift; on the built-in lathe G54 Z is -550 (the chuck
    // face, machine zero at home), so machine Z0 (G53 Z0, home) is work Z = 0 + 550 - 100 = 450.
    const Run r = run("O1\nG10 P0 Z-130\nM98 P30002\nG53 Z0\nM30\nO2\nG10 P0 W10\nM99\n", "spinner-lathe-a");
    CHECK(r.result.alarms.empty());
    CHECK(r.result.final_position[Z] == Approx(450));
}

TEST_CASE("arcs: G02 with R on a lathe (G18), full geometry through the motion kernel") {
    // From X20 Z0 to X40 Z-10 with R10: radius geometry (10,0) → (20,-10); centre (10,-10) for CW.
    const Run r = run("O1\nG0 X20. Z0.\nG2 X40. Z-10. R10. F.1\nM30\n", "fanuc-lathe-a");
    const auto m = moves(r);
    REQUIRE(m.size() == 2);
    REQUIRE(m[1].center);
    CHECK(m[1].radius == Approx(10));
    CHECK(m[1].length_mm == Approx(M_PI * 10 / 2));   // a quarter circle
    CHECK(r.result.alarms.empty());
}

TEST_CASE("arc radius mismatch is an alarm") {
    const Run r = run("O1\nG0 X0. Y0.\nG2 X10. Y0. I3. J0. F100\nM30\n", "fanuc-mill");
    REQUIRE(r.result.alarms.size() == 1);
    CHECK(r.result.alarms[0].code == 20);
}

TEST_CASE("macro: assignments, WHILE loop, IF GOTO, values in words") {
    const Run r = run("O1\n#1=0\nG90 G0 X0. Y0.\nWHILE [#1 LT 3] DO 1\n#1=#1+1\nG91 X10.\nEND 1\nG90\n"
                      "IF [#1 EQ 3] GOTO 20\nG0 Y99.\nN20 G0 Y[#1*2]\nM30\n", "fanuc-mill");
    CHECK(r.result.alarms.empty());
    CHECK(r.result.final_position[X] == Approx(30));
    CHECK(r.result.final_position[Y] == Approx(6));
}

TEST_CASE("G65 passes arguments as locals of a new level") {
    const Run r = run("O1\n#1=5\nG90 G0 X0.\nG65 P9000 X12.5 A2.\nG0 Y#1\nM30\nO9000\nG0 X[#24*#1]\nM99\n", "fanuc-mill");
    CHECK(r.result.alarms.empty());
    CHECK(r.result.final_position[X] == Approx(25));   // #24 = X12.5, #1 = A2. inside the call
    CHECK(r.result.final_position[Y] == Approx(5));    // the caller's #1 is untouched
}

TEST_CASE("an endless loop ends at the step limit with an alarm") {
    const Run r = run("O1\nN10 G0 X1.\nGOTO 10\n", "fanuc-mill", 1000);
    REQUIRE(r.result.alarms.size() == 1);
    CHECK(r.result.alarms[0].text.find("step limit") != std::string::npos);
    // kerf's own number, outside FANUC's ranges (docs/trace.md), so K4004 sees only this alarm.
    CHECK(r.result.alarms[0].code == interpreter::kerf_alarm::step_limit);
    CHECK_FALSE(r.result.completed);
}

TEST_CASE("spindle events say whether they start or stop the spindle") {
    // M03 without S (no speed), M04 with S, M05: spindle_running is what the M code does
    // (events.hpp), whatever the rpm; the analyzer's K5010 reads it.
    const Run r = run("O1\nM3\nS500 M4\nM5\nM30\n", "fanuc-lathe-a");
    std::vector<std::pair<bool, double>> spindle;
    for (const auto& e : r.events)
        if (e.kind == EventKind::spindle) spindle.emplace_back(e.spindle_running, e.spindle_rpm);
    REQUIRE(spindle.size() == 3);
    CHECK(spindle[0] == std::pair{true, 0.0});
    CHECK(spindle[1] == std::pair{true, 500.0});
    CHECK(spindle[2] == std::pair{false, 0.0});
}

TEST_CASE("G96 rpm follows X and is clamped by G50 S") {
    // Vc 200 m/min at X50 (diameter): n = 1000*200/(pi*50) = 1273.2 rpm; at X10: 6366 → clamp 2000.
    const Run r = run("O1\nG50 S2000\nG96 S200 M3\nG0 X50. Z0.\nG1 Z-1. F.1\nX10.\nM30\n", "fanuc-lathe-a");
    const auto m = moves(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].spindle_rpm == Approx(1000.0 * 200 / (M_PI * 50)));
    CHECK(m[2].spindle_rpm == Approx(2000));
}

TEST_CASE("dwell: X and U in seconds, P in milliseconds") {
    const Run r = run("O1\nG4 X1.5\nG4 P500\nG4 U2.\nM30\n", "fanuc-lathe-a");
    std::vector<double> dwells;
    for (const auto& e : r.events)
        if (e.kind == EventKind::dwell) dwells.push_back(e.time_s);
    REQUIRE(dwells.size() == 3);
    CHECK(dwells[0] == Approx(1.5));
    CHECK(dwells[1] == Approx(0.5));
    CHECK(dwells[2] == Approx(2));
}

TEST_CASE("seed 001 §7.8 O0001/O0002: three facing cuts 10 mm apart, as semantics.md §2.6 computes") {
    // The reference: shift -130, -120, -110 → the cut at program Z-10 is 120, 110, 100 mm in front
    // of the chuck face, which is machine Z-550 on the built-in lathe (G54; machine zero at home):
    // machine Z -430, -440, -450; afterwards the shift is -100 and G0 X150 Z150 is relative to it
    // (250 in front of the chuck face: machine Z -300). `50 G1 X-2` lacks its N (a seed defect): the
    // lenient run executes it without the bare number.
    const std::filesystem::path file =
        std::filesystem::path(KERF_SHARED_DIR) / "reference/examples/001_O0001_O0002_M98_P30002.nc";
    if (!std::filesystem::exists(file)) {
        WARN("../shared is not there: the §2.6 example was not run");
        return;
    }
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const dialects::Dialect* d = dialects::builtin_registry().find("spinner-lathe-a");
    interpreter::ProgramSet programs;
    const auto f = programs.add(file.string(), text.str(), *d);
    interpreter::VectorSink sink;
    interpreter::RunOptions options;
    options.lenient = true;
    const auto r = interpreter::run(programs, *programs.first_program(f), *d, interpreter::default_setup(*d), sink, options);
    std::vector<double> cut_z;
    for (const auto& e : sink.events)
        if (e.kind == EventKind::linear) cut_z.push_back(e.machine_end[Z]);
    REQUIRE(cut_z.size() == 3);
    constexpr double kChuckFace = -550;   // machine Z of G54 Z0 on the built-in lathe
    CHECK(cut_z[0] == Approx(kChuckFace + 120));
    CHECK(cut_z[1] == Approx(kChuckFace + 110));
    CHECK(cut_z[2] == Approx(kChuckFace + 100));
    CHECK(r.final_position[X] == Approx(150));
    CHECK(r.final_position[Z] == Approx(150));
    CHECK(sink.events.back().machine_end[Z] == Approx(kChuckFace + 250));
    CHECK(r.completed);
}

TEST_CASE("changing the work system changes the work coordinates, not the tool") {
    const dialects::Dialect* d = dialects::builtin_registry().find("fanuc-mill");
    interpreter::ProgramSet programs;
    const auto f = programs.add("t.nc", "O1\nG54 G90 G0 X0. Y0.\nG55\nG0 Z10.\nM30\n", *d);
    interpreter::Setup setup = interpreter::default_setup(*d);
    setup.work_offsets[0] = {100, 50, 0, 0, 0, 0};
    setup.work_offsets[1] = {200, 50, 0, 0, 0, 0};
    interpreter::VectorSink sink;
    const auto r = interpreter::run(programs, *programs.first_program(f), *d, setup, sink);
    // At G54 X0 the tool is at machine X100; in G55 (zero at machine X200) that is X-100.
    CHECK(r.final_position[X] == Approx(-100));
    CHECK(sink.events.back().machine_end[X] == Approx(100));
}

TEST_CASE("G52 in its three readings (semantics.md §2.4)") {
    // pcnc-mill: tool at X200 Y160, G52 X100 Y100 → it reads X100 Y100 (A = (100, 60)); X20 is
    // then work X120; G152 restores the work system: the tool reads X120 Y100+60 = Y160.
    const Run pcnc = run("G90 G0 X200 Y160\nG52 X100 Y100\nG0 X20\nG152\nM2\n", "pcnc-mill");
    const auto m = moves(pcnc);
    REQUIRE(m.size() == 2);
    CHECK(m[1].end[X] == Approx(20));
    const double g54_x = m[0].machine_end[X] - 200;   // the built-in machine's G54 offset
    CHECK(m[1].machine_end[X] - g54_x == Approx(120));
    CHECK(pcnc.result.final_position[X] == Approx(120));
    CHECK(pcnc.result.final_position[Y] == Approx(160));
    // FANUC: the local origin is the work origin plus the vector; G52 X0 Y0 cancels.
    const Run fanuc = run("O1\nG90 G0 X0. Y0.\nG52 X10. Y5.\nG0 X0. Y0.\nG52 X0. Y0.\nM30\n", "fanuc-mill");
    const auto f = moves(fanuc);
    REQUIRE(f.size() == 2);
    CHECK(f[1].machine_end[X] - f[0].machine_end[X] == Approx(10));   // moves 0 and 1 both go to X0 Y0
    CHECK(f[1].machine_end[Y] - f[0].machine_end[Y] == Approx(5));
    CHECK(fanuc.result.final_position[X] == Approx(10));   // after the cancel the tool reads X10 Y5
    CHECK(fanuc.result.final_position[Y] == Approx(5));
}

// A G code the dialect does not have stops the control with alarm 010 (gcode-tables.md; K2001 says
// it before the run). Before, the dry run went past it as if it were not there: a system A → C
// conversion that left `G710` as it was compared equal although neither control runs it.
TEST_CASE("an unknown G code: alarm 010 at its block; lenient, a message and the block without it") {
    const std::string text = "G00 X10. Z5.\nG710 U1.\nG00 X20.\nM30\n";
    const dialects::Dialect& d = test::dialect("fanuc-lathe-a");
    const Run strict = test::run_with(text, d, test::plain_setup(d));
    REQUIRE(strict.result.alarms.size() == 1);
    CHECK(strict.result.alarms[0].code == 10);
    CHECK(strict.result.alarms[0].source.line == 2);
    CHECK(strict.result.alarms[0].text.find("G710 is not a code of fanuc-lathe-a") != std::string::npos);
    CHECK(moves(strict).size() == 1);   // the first block's rapid only
    CHECK_FALSE(strict.result.completed);

    interpreter::RunOptions lenient;
    lenient.lenient = true;
    const Run run = test::run_with(text, d, test::plain_setup(d), lenient);
    CHECK(run.result.completed);
    CHECK(run.result.alarms.empty());
    const auto said = std::find_if(run.events.begin(), run.events.end(), [](const interpreter::Event& e) {
        return e.kind == EventKind::message && e.text.find("G710 is not a code of fanuc-lathe-a") != std::string::npos;
    });
    CHECK(said != run.events.end());
    REQUIRE(moves(run).size() == 3);   // G710's U1. is a rapid from the modal G00, then X20.
    CHECK(run.result.final_position[X] == Approx(20));

    // A computed code (G#1) is no unknown code: it is looked up when its value is known.
    const Run computed = test::run_with("#1=1\nG#1 X5. Z1. F0.2\nM30\n", d, test::plain_setup(d));
    CHECK(computed.result.alarms.empty());
}
