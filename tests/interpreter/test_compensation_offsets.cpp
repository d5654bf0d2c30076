// G45–G48 one-block position offsets (reference semantics.md §9.3): the worked example 5 of seed
// 004 reproduced block by block, and the rules one at a time.
#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf::test;

namespace {

// D registers of example 5: D08 = 10 (the cutter radius), D17 = 0.8 (semantics.md §12.7: +0.8,
// the allowance the text describes), D21 = 15.
void example_registers(Setup& s) {
    s.tools[8].radius = 10;
    s.tools[17].radius = 0.8;
    s.tools[21].radius = 15;
}

struct Centre {
    double x, y;
};

void check_end(const Event& e, double x, double y) {
    INFO(to_string(e.kind) << " on line " << e.source.line << " to X" << e.end[X] << " Y" << e.end[Y]);
    CHECK(e.end[X] == Approx(x).margin(0.001));
    CHECK(e.end[Y] == Approx(y).margin(0.001));
}

}  // namespace

// The table of semantics.md §9.3 ("Tool centre after block"), from point 0 = (0, 0): each value
// is the programmed move changed by the rule: N1 G46 both axes 90 − 10, 55 − 10; N2 G47 +75 + 20;
// N3 G46 D17 +45 − 0.8; N4 G48 +50 − 20; N5 G46 D17 −45 + 0.8 (the magnitude decreases); N6 G45
// +30 + 10; N7 G45 arc R40 → R50 about (245, 95): (245, 45) → (295, 95); N8 +65 + 10; N9 G46
// X0 → −10; N10 G46 arc R40 → R30 about (285, 200): (285, 170) → (255, 200); N11 G45 Y0 → +10;
// N12 G46 X0 → −10; N13 G45 D21 −155 − 15; N14 G46 Y0 D08 → −10; N15 back to (0, 0).
TEST_CASE("G45-G48: example 5 of seed 004 gives the tool centres of semantics.md §9.3") {
    const Run r = run_bare(
        "O5\n"
        "N1 G90 G46 G0 X90. Y55. D08\n"
        "N2 G91 G47 G1 X75. F60\n"
        "N3 G46 Y45. D17\n"
        "N4 G48 X50. D08\n"
        "N5 G46 Y-45. D17\n"
        "N6 G45 X30. D08\n"
        "N7 G45 G3 X40. Y40. J40.\n"
        "N8 G45 G1 Y65.\n"
        "N9 G46 X0.\n"
        "N10 G46 G2 X-40. Y40. J40.\n"
        "N11 G45 Y0.\n"
        "N12 G46 X0.\n"
        "N13 G45 X-155. D21\n"
        "N14 G46 Y0. D08\n"
        "N15 G90 G0 X0. Y0. M02\n",
        "iso-legacy-mill", example_registers);
    require_clean(r);
    const std::vector<Event> m = moves(r);
    const Centre table[] = {{80, 45},  {175, 45},  {175, 89.2}, {205, 89.2}, {205, 45},  {245, 45}, {295, 95}, {295, 170},
                            {285, 170}, {255, 200}, {255, 210}, {245, 210},  {75, 210}, {75, 200}, {0, 0}};
    REQUIRE(m.size() == std::size(table));
    for (std::size_t i = 0; i < m.size(); ++i) check_end(m[i], table[i].x, table[i].y);
    // The arcs: N7 counter-clockwise R50 about (245, 95), N10 clockwise R30 about (285, 200).
    CHECK(m[6].kind == EventKind::arc_ccw);
    REQUIRE(m[6].center);
    CHECK((*m[6].center)[X] == Approx(245));
    CHECK((*m[6].center)[Y] == Approx(95));
    CHECK(m[6].radius == Approx(50));
    CHECK(m[9].kind == EventKind::arc_cw);
    REQUIRE(m[9].center);
    CHECK((*m[9].center)[X] == Approx(285));
    CHECK((*m[9].center)[Y] == Approx(200));
    CHECK(m[9].radius == Approx(30));
}

// One block only (semantics.md §9.3): the block after G45 moves as programmed from where the tool
// stands: an axis it does not name stays (issue 12: it used to return to the programmed point).
TEST_CASE("G45-G48 act in their block only; the next block moves only the axes it names") {
    const Run r = run_bare("O1\nG90 G1 X0. Y0. F100.\nG45 X20. D08\nY10.\nG47 X30.\nM30\n", "iso-legacy-mill",
                           example_registers);
    require_clean(r);
    const std::vector<Event> m = moves(r);
    REQUIRE(m.size() == 4);
    check_end(m[1], 30, 0);    // +20 increased by D08 = 10
    check_end(m[2], 30, 10);   // no offset: Y10, X stays where the tool is
    check_end(m[3], 50, 10);   // G90 X30 from the tool's X30: a zero move, which G47 makes +2·10 = +20
}
