// G43/G44/G49 tool length offsets through the interpreter (executor_length.cpp; reference
// semantics.md §7 and the dry-run formula of §2.7: machine Z = programmed Z ± H on mills). The
// work coordinates are kept, the machine position shifts. Expected values derived by hand below.
#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf::test;

namespace {

void registers(Setup& s) {
    s.tools[1].length = 120;        // H1: 120 − 0.5 wear = 119.5
    s.tools[1].length_wear = -0.5;
    s.tools[2].length = 30;         // H2: 30
}

}  // namespace

// bare_setup: no work offset, the run starts at machine zero, so machine = work + length offset.
// The offset is taken up by the next block with a Z word ([FANUC]; machine switch
// length_offset_motion = next-move, the default), where its coordinate_change event stands:
//   G0 X0 Y0 Z100       machine Z 100 (no offset yet)
//   G43 H1              no Z: nothing moves yet, no event
//   G0 Z50.             the event (code 1; work Z 100 with the new offset: machine 219.5), then
//                       the move: work 50, machine 50 + 119.5 = 169.5
//   G44 H2 Z10.         event code 2 (work 50: 50 − 30 = 20), then machine 10 − 30 = −20
//   H1                  an H alone under G44 changes the register, not taken up yet (no Z) ...
//   G49 Z0.             ... and replaced by the cancel before any Z move: event code 0 (work 10:
//                       machine 10), then machine 0
TEST_CASE("G43/G44/G49: machine Z = programmed Z ± H from the next Z move, the work coordinates stay") {
    const Run r = run_bare("O1\nG90 G0 X0. Y0. Z100.\nG43 H1\nG0 Z50.\nG44 H2 Z10.\nH1\nG49 Z0.\nM30\n", "fanuc-mill",
                           registers);
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 4);
    CHECK(m[0].machine_end[Z] == Approx(100));
    CHECK(m[1].end[Z] == Approx(50));
    CHECK(m[1].machine_end[Z] == Approx(169.5));
    CHECK(m[1].length_mm == Approx(169.5 - 100));   // the move takes the offset up
    CHECK(m[2].end[Z] == Approx(10));
    CHECK(m[2].machine_end[Z] == Approx(-20));
    CHECK(m[3].end[Z] == Approx(0));
    CHECK(m[3].machine_end[Z] == Approx(0));
    const auto changes = of_kind(r, EventKind::coordinate_change);
    REQUIRE(changes.size() == 3);   // G43 H1 (at G0 Z50.), G44 H2, G49 (the H1 before it never took effect)
    CHECK(changes[0].source.line == 4);
    CHECK(changes[0].code == 1);
    CHECK(changes[0].end[Z] == Approx(100));            // the work coordinate is kept
    CHECK(changes[0].machine_end[Z] == Approx(219.5));  // the machine position shifts by H1
    CHECK(changes[1].source.line == 5);
    CHECK(changes[1].machine_end[Z] == Approx(20));
    CHECK(changes[2].source.line == 7);
    CHECK(changes[2].code == 0);
    CHECK(changes[2].machine_end[Z] == Approx(10));
    CHECK(r.result.final_position[Z] == Approx(0));
}

// T1 M06 then G43 H2: the offset of H2 applies (30); the event names both, H2 in `code` and the
// spindle tool 1 in `tool`, so the length-offset-mismatch check can compare them.
TEST_CASE("G43 with the H of another tool: the event carries the H number and the tool") {
    const Run r = run_bare("O1\nT1 M06\nG90 G0 G43 Z5. H2\nM30\n", "fanuc-mill", registers);
    require_clean(r);
    const auto changes = of_kind(r, EventKind::coordinate_change);
    REQUIRE(changes.size() == 1);
    CHECK(changes[0].code == 2);
    CHECK(changes[0].tool == 1);
    const auto m = moves(r);
    REQUIRE(m.size() == 1);
    CHECK(m[0].machine_end[Z] == Approx(5 + 30));
}
