// Subprograms through the interpreter (reference/dialects.md §3.6, §6.2; mcodes.md M98/M99;
// FANUC 0i/16i/18i/30i "Subprogram" where the reference is silent): both M98 forms and their
// repeat counts (the dialect's `subprogram_call` lexical switch), M99 return, M99 P, M99 in a main
// program, nesting limit (alarm 077), program lookup in the same file, in other files and through
// the ProgramSet loader, and the alarms for missing programs (FANUC 076 "address P not defined",
// 078 "number not found").
//
// Every Setup is built by hand: zero offsets, no limits. Expected counts and positions are derived
// by hand in the comments.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf;
using namespace kerf::test;

// --- the packed form M98 P<repeats><program> (dialects.md §3.6) ---------------------------------

// Lines: 1 O1, 2 G0 X0. Z0., 3 M98 P41001, 4 G0 X100., 5 M30, 6 O1001, 7 G0 W-10., 8 M99.
// P41001: the last four digits are the program (O1001), the digits before them the repeats (4).
// One M98 block: one call event (code 1001); the subprogram runs four times: four passes of line 7
// (Z −10, −20, −30, −40) and four M99 returns; then line 4 runs at Z −40.
TEST_CASE("M98 P41001 runs O1001 four times", "[subprograms]") {
    const Run r = run("O1\nG0 X0. Z0.\nM98 P41001\nG0 X100.\nM30\nO1001\nG0 W-10.\nM99\n", "fanuc-lathe-a");
    require_clean(r);
    const auto calls = of_kind(r, EventKind::call);
    REQUIRE(calls.size() == 1);
    CHECK(calls[0].code == 1001);
    CHECK(of_kind(r, EventKind::return_).size() == 4);
    CHECK(count_moves_on_line(r, 7) == 4);
    std::vector<double> z;
    for (const Event& e : moves(r))
        if (e.source.line == 7) z.push_back(e.end[Z]);
    REQUIRE(z.size() == 4);
    CHECK(z[0] == Approx(-10));
    CHECK(z[1] == Approx(-20));
    CHECK(z[2] == Approx(-30));
    CHECK(z[3] == Approx(-40));
    const auto m = moves(r);
    REQUIRE(m.size() == 6);
    CHECK(m.back().source.line == 4);
    CHECK(m.back().end[Z] == Approx(-40));
    CHECK(m.back().end[X] == Approx(100));
}

// The reference's other examples: P1000 → O1000 once, P30002 → O0002 three times, P40020 → O0020
// four times. Each subprogram adds W-1., W-10., W-100. respectively:
//   Z = −1·1 − 10·3 − 100·4 = −431.
TEST_CASE("M98 packed forms: P1000 once, P30002 three times, P40020 four times", "[subprograms]") {
    const Run r = run("O1\nG0 X0. Z0.\nM98 P1000\nM98 P30002\nM98 P40020\nM30\n"
                      "O1000\nG0 W-1.\nM99\nO0002\nG0 W-10.\nM99\nO0020\nG0 W-100.\nM99\n",
                      "fanuc-lathe-a");
    require_clean(r);
    CHECK(of_kind(r, EventKind::call).size() == 3);
    CHECK(of_kind(r, EventKind::return_).size() == 1 + 3 + 4);
    CHECK(moves(r).size() == 1 + 1 + 3 + 4);
    CHECK(r.result.final_position[Z] == Approx(-431));
}

// "Maximum number of repetitions in one call is 9999": P99990003 → O0003 9999 times, each +1 in
// Z → Z 9999.
TEST_CASE("M98 P99990003 repeats 9999 times", "[subprograms]") {
    const Run r = run("O1\nG0 X0. Z0.\nM98 P99990003\nM30\nO0003\nG0 W1.\nM99\n", "fanuc-lathe-a");
    require_clean(r);
    CHECK(r.result.final_position[Z] == Approx(9999));
    CHECK(of_kind(r, EventKind::return_).size() == 9999);
}

// --- the P/L form (dialects.md §3.6 [FANUC], §6.2 ADV400) ----------------------------------------

// adv400-mill (`subprogram_call = "p-l"`): M98 P12 L100 runs O12 a hundred times; O12 moves +1 in
// X, so X = 100 and there are 100 passes of its move (line 6).
TEST_CASE("M98 P12 L100 (ADV400) runs O12 a hundred times", "[subprograms]") {
    const Run r = run("O1\nG90 G0 X0 Y0\nM98 P12 L100\nM30\nO12\nG91 G0 X1\nG90\nM99\n", "adv400-mill");
    require_clean(r);
    CHECK(r.result.final_position[X] == Approx(100));
    CHECK(count_moves_on_line(r, 6) == 100);
    CHECK(of_kind(r, EventKind::call).size() == 1);
    CHECK(of_kind(r, EventKind::return_).size() == 100);
}

// fanuc-mill (`both`): P of at most four digits with L is the P/L form (O12 three times); P30012
// without L is the packed form (O0012 three times) → X = 3 + 3 = 6.
// pcnc-mill (`p-l`): M98 P12 L2 → twice → X = 2.
TEST_CASE("M98 P/L and packed forms in the FANUC mill; P/L in pcnc-mill", "[subprograms]") {
    const Run fanuc = run("O1\nG90 G0 X0. Y0.\nM98 P12 L3\nM98 P30012\nM30\nO12\nG91 G0 X1.\nG90\nM99\n", "fanuc-mill");
    require_clean(fanuc);
    CHECK(fanuc.result.final_position[X] == Approx(6));
    CHECK(of_kind(fanuc, EventKind::return_).size() == 6);
    const Run pcnc = run("O1\nG90 G0 X0 Y0\nM98 P12 L2\nM2\nO12\nG91 G0 X1\nG90\nM99\n", "pcnc-mill");
    require_clean(pcnc);
    CHECK(pcnc.result.final_position[X] == Approx(2));
}

// In a P/L dialect P41001 is the program number 41001, not "O1001 four times": O1001 exists but
// O41001 does not → alarm 078 and O1001 never runs.
TEST_CASE("M98 P41001 in a P/L dialect names O41001", "[subprograms]") {
    const Run r = run("O1\nG90 G0 X0 Y0\nM98 P41001\nM30\nO1001\nG0 X5\nM99\n", "adv400-mill");
    require_alarm(r, 78);
    for (const Event& m : moves(r)) CHECK(m.end[X] != Approx(5));
}

// --- M98 Q (sequence number) ---------------------------------------------------------------------

// The reference is silent on Q with M98. FANUC 30i-B/0i-F: M98 Q<n> calls the blocks from N<n> of
// the program being executed as a subprogram (up to its M99), then returns after the M98.
//   lines: G0 X0. Y0. → M98 Q100 → N100 G0 X10. → M99 → G0 Y50. → M30
// Moves in order: (0, 0), X10 (N100), Y50 with X10; the run ends at M30.
TEST_CASE("M98 Q100 calls N100 of the same program as a subprogram", "[subprograms]") {
    const Run r = run("O1\nG90 G0 X0. Y0.\nM98 Q100\nG0 Y50.\nM30\nN100 G0 X10.\nM99\n", "fanuc-mill");
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].end[X] == Approx(10));
    CHECK(m[1].source.line == 6);
    CHECK(m[2].end[X] == Approx(10));
    CHECK(m[2].end[Y] == Approx(50));
}

// --- M99 ---------------------------------------------------------------------------------------------

// M99 returns to the block after the calling M98; subprograms share the modal state with the caller
// (dialects.md §3.6 "no save/restore"): O2 leaves G91 active, so the caller's G0 X1. is
// incremental: 1 (in O2) + 1 = 2.
TEST_CASE("M99 returns after the M98; modal state is shared", "[subprograms]") {
    const Run r = run("O1\nG90 G0 X0. Y0.\nM98 P2\nG0 X1.\nM30\nO2\nG91 G0 X1.\nM99\n", "fanuc-mill");
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].source.line == 7);   // O2's move comes before the caller's next block
    CHECK(m[2].source.line == 4);
    CHECK(r.result.final_position[X] == Approx(2));
}

// M99 P<n> returns to N<n> of the *caller*, not of the main program: O1 → O2 → O3; O3 ends with
// M99 P30 → N30 of O2 (X30), skipping O2's G0 X99.; O2 then returns normally to O1 (Z1.).
// Moves: X3 (O3), X30 (O2 N30), Z1 (O1).
TEST_CASE("M99 P returns to a sequence number of the calling program", "[subprograms]") {
    const Run r = run("O1\nG90 G0 X0. Y0. Z0.\nM98 P2\nG0 Z1.\nM30\n"
                      "O2\nM98 P3\nG0 X99.\nN30 G0 X30.\nM99\n"
                      "O3\nG0 X3.\nM99 P30\n",
                      "fanuc-mill");
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 4);
    CHECK(m[1].end[X] == Approx(3));
    CHECK(m[2].end[X] == Approx(30));
    CHECK(m[3].end[Z] == Approx(1));
    for (const Event& e : m) CHECK(e.end[X] != Approx(99));
}

// [FANUC] "M99 Pn in the main program: control returns to sequence number n instead of the start":
// X1, then M99 P20 → N20 G0 Y5. → M30. The block G0 X99. is never run, nothing loops.
TEST_CASE("M99 P in a main program jumps to that sequence number", "[subprograms]") {
    const Run r = run("O1\nG90 G0 X1.\nM99 P20\nG0 X99.\nN20 G0 Y5.\nM30\n", "fanuc-mill",
                      [](Setup& s) { s.step_limit = 1000; });
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 2);
    CHECK(m[1].end[Y] == Approx(5));
    CHECK(m[1].end[X] == Approx(1));
}

// M99 at the end of a main program goes back to its start (dialects.md §3.6): the control loops
// forever (a bar feeder). Asked for a million passes (RunOptions::passes; by default the dry run
// stops after one, tests/interpreter/test_shop_programs.cpp), the step limit ends it. Step limit
// 90; one pass executes three blocks (O1, G91 G0 X1., M99), so 90 blocks are 30 passes: 30 moves
// of +1 (X = 30) and 30 returns; the 91st block raises the alarm.
TEST_CASE("M99 at the end of a main program loops until the step limit when asked to", "[subprograms]") {
    const dialects::Dialect& d = dialect("fanuc-mill");
    Setup setup = plain_setup(d);
    setup.step_limit = 90;
    interpreter::RunOptions many;
    many.passes = 1'000'000;
    const Run r = run_with("O1\nG91 G0 X1.\nM99\n", d, setup, many);
    INFO(alarm_list(r));
    REQUIRE(r.result.alarms.size() == 1);
    CHECK(r.result.alarms[0].text.find("step limit") != std::string::npos);
    CHECK_FALSE(r.result.completed);
    CHECK(r.result.blocks <= 91);
    CHECK(moves(r).size() == 30);
    CHECK(r.result.final_position[X] == Approx(30));
    CHECK(of_kind(r, EventKind::return_).size() == 30);
}

// --- nesting (dialects.md §3.6: 4 levels [FANUC], configurable) -----------------------------------

namespace {
// A chain O1 → O1001 → … → O100<depth>; the last one moves to X<depth>.
std::string chain(int depth) {
    std::string text = "O1\nG90 G0 X0. Y0.\nM98 P1001\nM30\n";
    for (int level = 1; level <= depth; ++level) {
        text += "O" + std::to_string(1000 + level) + "\n";
        if (level < depth) text += "M98 P" + std::to_string(1001 + level) + "\n";
        else text += "G0 X" + std::to_string(level) + ".\n";
        text += "M99\n";
    }
    return text;
}
}  // namespace

// Four nested levels (main → 1001 → 1002 → 1003 → 1004) run: the innermost moves to X4.
// A fifth level (→ 1005) is alarm 077 and its move never happens.
TEST_CASE("subprogram nesting: four levels run, a fifth is alarm 077", "[subprograms]") {
    const Run four = run(chain(4), "fanuc-mill");
    require_clean(four);
    CHECK(four.result.final_position[X] == Approx(4));
    CHECK(of_kind(four, EventKind::call).size() == 4);

    const Run five = run(chain(5), "fanuc-mill");
    require_alarm(five, 77);
    CHECK(of_kind(five, EventKind::call).size() == 4);
    for (const Event& m : moves(five)) CHECK(m.end[X] != Approx(5));
}

// Setup::max_call_depth = 2: main → 1001 → 1002 runs, → 1003 (third level) is alarm 077.
TEST_CASE("subprogram nesting limit comes from the Setup", "[subprograms]") {
    const Run two = run(chain(2), "fanuc-mill", [](Setup& s) { s.max_call_depth = 2; });
    require_clean(two);
    CHECK(two.result.final_position[X] == Approx(2));
    const Run three = run(chain(3), "fanuc-mill", [](Setup& s) { s.max_call_depth = 2; });
    require_alarm(three, 77);
}

// --- where programs are found (program_set.hpp) ----------------------------------------------------

// The loader callback is asked only for programs the set lacks, once each (a loaded file joins the
// set): M98 P22000 (twice) and M98 P2000 (once) → O2000 runs three times (X = 3) with one loader
// call; O3000 is in the main file and is never asked for. Events of O2000 point into file 1.
TEST_CASE("programs come from the same file first, then through the loader", "[subprograms]") {
    const dialects::Dialect& d = dialect("fanuc-mill");
    interpreter::ProgramSet programs;
    const auto main_file =
        programs.add("main.nc", "O1\nG90 G0 X0. Y0. Z0.\nM98 P22000\nM98 P2000\nM98 P3000\nM30\nO3000\nG0 Z7.\nM99\n", d);
    std::map<std::int64_t, int> asked;
    programs.set_loader(
        [&](std::int64_t number) -> std::optional<std::pair<std::string, std::string>> {
            ++asked[number];
            if (number == 2000) return std::make_pair(std::string("O2000.nc"), std::string("O2000\nG91 G0 X1.\nG90\nM99\n"));
            return std::nullopt;
        },
        &d);
    interpreter::VectorSink sink;
    const auto r = interpreter::run(programs, *programs.first_program(main_file), d, plain_setup(d), sink);
    CHECK(r.alarms.empty());
    CHECK(r.completed);
    CHECK(r.final_position[X] == Approx(3));
    CHECK(r.final_position[Z] == Approx(7));
    CHECK(asked.size() == 1);
    CHECK(asked[2000] == 1);
    REQUIRE(programs.file_count() == 2);
    std::size_t from_loaded = 0;
    for (const Event& e : sink.events)
        if ((e.kind == EventKind::rapid) && e.source.file == 1) ++from_loaded;
    CHECK(from_loaded == 3);
}

// The calling file wins over other files holding the same number; a number only another file holds
// is found there. lib.nc (file 0): O5000 → X1., O6000 → Y6.; main.nc (file 1): O5000 → X2.
// Running main.nc: M98 P5000 runs its own O5000 (X2), M98 P6000 runs lib's O6000 (Y6).
TEST_CASE("the calling file's program wins over another file's", "[subprograms]") {
    const dialects::Dialect& d = dialect("fanuc-mill");
    interpreter::ProgramSet programs;
    programs.add("lib.nc", "O5000\nG0 X1.\nM99\nO6000\nG0 Y6.\nM99\n", d);
    const auto main_file = programs.add("main.nc", "O1\nG90 G0 X0. Y0.\nM98 P5000\nM98 P6000\nM30\nO5000\nG0 X2.\nM99\n", d);
    interpreter::VectorSink sink;
    const auto r = interpreter::run(programs, *programs.first_program(main_file), d, plain_setup(d), sink);
    CHECK(r.alarms.empty());
    CHECK(r.completed);
    CHECK(r.final_position[X] == Approx(2));
    CHECK(r.final_position[Y] == Approx(6));
}

// --- alarms ------------------------------------------------------------------------------------------

// FANUC alarm 078 "number not found": no O9999 in the file and no loader (or a loader that has
// nothing) → alarm 078; the block after the M98 is not run.
TEST_CASE("M98 to a missing program is alarm 078", "[subprograms]") {
    const Run r = run("O1\nG90 G0 X0. Y0.\nM98 P9999\nG0 X5.\nM30\n", "fanuc-mill");
    require_alarm(r, 78);
    CHECK(moves(r).size() == 1);

    const dialects::Dialect& d = dialect("fanuc-mill");
    interpreter::ProgramSet programs;
    const auto f = programs.add("main.nc", "O1\nM98 P9999\nM30\n", d);
    int asked = 0;
    programs.set_loader(
        [&](std::int64_t) -> std::optional<std::pair<std::string, std::string>> {
            ++asked;
            return std::nullopt;
        },
        &d);
    interpreter::VectorSink sink;
    const auto lr = interpreter::run(programs, *programs.first_program(f), d, plain_setup(d), sink);
    REQUIRE(lr.alarms.size() == 1);
    CHECK(lr.alarms[0].code == 78);
    CHECK(asked == 1);
}

// FANUC alarm 078 also covers G65 P (and M99 P) numbers that are not found ("a program number or a
// sequence number which was specified by address P in the block which includes an M98, M99, G65
// or G66 was not found").
TEST_CASE("G65 to a missing program is alarm 078", "[subprograms]") {
    const Run r = run("O1\nG65 P9999 A1.\nM30\n", "fanuc-mill");
    require_alarm(r, 78);
}

TEST_CASE("M99 P to a sequence number the caller lacks is alarm 078", "[subprograms]") {
    const Run r = run("O1\nM98 P2\nM30\nO2\nM99 P77\n", "fanuc-mill");
    require_alarm(r, 78);
}

// FANUC alarm 076 "address P not defined": M98 without P (and without Q).
TEST_CASE("M98 without P is alarm 076", "[subprograms]") {
    const Run r = run("O1\nM98\nM30\n", "fanuc-mill");
    require_alarm(r, 76);
}
