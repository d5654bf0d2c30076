// The Haas one-block G71 (haas-lathe.toml, interpreter/cycles/haas_lathe.cpp) where it differs from
// FANUC's two-block G71: the Q block of a type II profile may go back in Z past the start ("The Z
// Axis PQ path must not exceed the original starting location. The only exception is on the Q
// block.", Haas G71 "Type 2 details", staging-diy.haascnc.com/type-2-details-0). Expected paths are
// derived by hand in the comments.
#include "tests/interpreter/cycle_steps.hpp"

using namespace kerf::test;

namespace {

// The smallest program of the corpus's shape (enier290188 weld_pin: `N20 G00 G40 Z0.1` after the
// last cut): A = X50 Z2, D5 (radius), no allowance; type II (N10 names X and Z). On the radius
// the contour is (10, 2) → (10, −10) → (25, −10), then the Q block rapids back to (25, 2).
std::string haas_q_return(const char* extra_profile_block = "") {
    return fmt::format("O1\n"                                  // 1
                       "G0 X50. Z2.\n"                         // 2
                       "G71 P10 Q30 D5. U0 W0 F0.2\n"          // 3
                       "N10 G0 X20. Z2.\n"                     // 4
                       "N20 G1 Z-10.\n"                        // 5
                       "{}"                                    //
                       "N25 X50.\n"                            // 6 (7 with the extra block)
                       "N30 G0 Z2.\n"                          //
                       "M30\n",
                       extra_profile_block);
}

void retract_half_mm(Setup& s) { s.cycles.initial.g71_retract = 0.5; }

}  // namespace

// Levels on the radius 25 − 5k deeper than the deepest point 10: 20, 15 (10 touches it).
//  20 (X40): in at Z2, along the level to the face at Z-10, up the face to the previous level 25
//      (X50), out by e = 0.5 (X51), back to Z2 (nothing passed stands above 25.5).
//  15 (X30): in, to Z-10, up the face to 20 (X40), out to X41, back to Z2.
// Then the semi-finishing pass along the whole profile, the Q block's rapid back to Z2 included
// (it lies on the stock's outside, X50); the return to A is no move, the tool already stands there.
TEST_CASE("Haas G71: the Q block of a type II profile may go back past the start in Z") {
    const Run r = run_bare(haas_q_return(), "haas-lathe", retract_half_mm);
    require_clean(r);
    check_path(r, 3,
               {rapid(40, 2), feed(40, -10), feed(50, -10), feed(51, -10), rapid(51, 2),   // 20
                rapid(30, 2), feed(30, -10), feed(40, -10), feed(41, -10), rapid(41, 2),   // 15
                rapid(20, 2), feed(20, -10), feed(50, -10), rapid(50, 2)});
}

// The exception is the Q block's alone: a reversal before it is still alarm 064, at its block.
TEST_CASE("Haas G71: a Z reversal before the Q block is still alarm 064") {
    const Run r = run_bare(haas_q_return("N22 Z-5.\n"), "haas-lathe", retract_half_mm);
    require_alarm(r, 64);
    CHECK(r.result.alarms[0].source.line == 6);
}

// FANUC's G71 has no such exception (cycles.md §2: Z monotonic in type II): the same profile in
// the two-block form stops at the Q block with alarm 064.
TEST_CASE("FANUC G71: the same profile going back in its Q block is alarm 064") {
    const Run r = run_bare("O1\nG0 X50. Z2.\nG71 U5. R0.5\nG71 P10 Q30 U0 W0 F0.2\nN10 G0 X20. Z2.\nN20 G1 Z-10.\n"
                           "N25 X50.\nN30 G0 Z2.\nM30\n",
                           "fanuc-lathe-a");
    require_alarm(r, 64);
    CHECK(r.result.alarms[0].source.line == 8);
}

// The machine's cycle parameters are mm (machine/SCHEMA.md): an inch program retracts by
// e = 0.5 mm = 0.019685 in on the radius, 0.03937 on the diameter. The same profile in inch
// (A = X5 Z0.2, D0.5: levels 2.0, 1.5 on the radius): the first level steps out from X5 to
// X5.03937.
TEST_CASE("Haas G71 in inch: Setting 73 (the machine's retract, mm) in program units") {
    const Run r = run_bare("O1\nG20\nG0 X5. Z0.2\nG71 P10 Q30 D0.5 U0 W0 F0.01\nN10 G0 X2. Z0.2\nN20 G1 Z-1.\n"
                           "N25 X5.\nN30 G0 Z0.2\nM30\n",
                           "haas-lathe", retract_half_mm);
    require_clean(r);
    const auto m = moves_on_line(r, 4);
    REQUIRE(m.size() >= 4);
    CHECK(m[3].end[X] == Approx(5.03937).margin(1e-5));
    CHECK(m[3].end[Z] == Approx(-1).margin(1e-6));
}
