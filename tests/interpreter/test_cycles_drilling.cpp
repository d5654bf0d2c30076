// Drilling cycles (reference/cycles.md §10, §11; [FANUC] canned cycles for the fanuc-mill codes
// the reference lists only in its tables) on small programs. Expected paths derived by hand in
// the comments. bare_setup: the run starts at 0 0 0, peck clearance 0.5 mm, G73 retract 0.1 mm
// (cycles::Settings defaults = machine/SCHEMA.md defaults).
#include "tests/interpreter/cycle_steps.hpp"

using namespace kerf::test;

namespace {

constexpr std::array<std::size_t, 3> kXYZ{X, Y, Z};
constexpr std::size_t C = 5;
constexpr std::array<std::size_t, 3> kXZC{X, Z, C};

std::vector<Event> texts_of_line(const Run& r, std::uint32_t line, EventKind kind) {
    std::vector<Event> out;
    for (const Event& e : r.events)
        if (e.kind == kind && e.source.line == line) out.push_back(e);
    return out;
}

}  // namespace

// G81 (FANUC form): rapid to X Y at the current level, rapid to R, feed to Z, rapid to the return
// level: G99 = R (Z2), G98 = the initial level (Z50, where the cycle mode began). Every later block
// with X/Y drills a new hole with the modal Z and R; G80 ends it.
TEST_CASE("G81 drills at every X/Y block and returns to R (G99) or the initial level (G98)") {
    const Run r = run_bare("O1\nG0 G90 X0 Y0 Z50.\nG99 G81 X10. Y20. Z-5. R2. F100\nX30.\nG98 X40.\nG80\nG0 Z100.\nM30\n");
    require_clean(r);
    check_path3(r, 3, kXYZ, {rapid3(10, 20, 50), rapid3(10, 20, 2), feed3(10, 20, -5), rapid3(10, 20, 2)});
    // Already at R: no move to R, the hole, back to R.
    check_path3(r, 4, kXYZ, {rapid3(30, 20, 2), feed3(30, 20, -5), rapid3(30, 20, 2)});
    check_path3(r, 5, kXYZ, {rapid3(40, 20, 2), feed3(40, 20, -5), rapid3(40, 20, 50)});
    CHECK(moves_on_line(r, 6).empty());
    check_path3(r, 7, kXYZ, {rapid3(40, 20, 100)});
}

// cycles.md §10 "until G80 or a group-01 code": G00 X50. after a G81 hole is a plain rapid.
TEST_CASE("a group-01 code cancels the drilling cycle") {
    const Run r = run_bare("O1\nG0 X0 Y0 Z10.\nG81 X5. Y5. Z-2. R1. F100\nG0 X50.\nY20.\nM30\n");
    require_clean(r);
    check_path3(r, 3, kXYZ, {rapid3(5, 5, 10), rapid3(5, 5, 1), feed3(5, 5, -2), rapid3(5, 5, 10)});
    check_path3(r, 4, kXYZ, {rapid3(50, 5, 10)});
    check_path3(r, 5, kXYZ, {rapid3(50, 20, 10)});
}

// G91 [FANUC]: R counts from the initial level (50 − 48 = 2), Z from R (2 − 7 = −5); K3 repeats the
// incremental X10 Y5 three times: holes at (10,5), (20,10), (30,15), each back to R (G99).
TEST_CASE("G81 under G91 with K repeats steps the hole position") {
    const Run r = run_bare("O1\nG0 G90 X0 Y0 Z50.\nG91 G99 G81 X10. Y5. Z-7. R-48. K3 F100\nM30\n");
    require_clean(r);
    check_path3(r, 3, kXYZ,
                {rapid3(10, 5, 50), rapid3(10, 5, 2), feed3(10, 5, -5), rapid3(10, 5, 2),   //
                 rapid3(20, 10, 2), feed3(20, 10, -5), rapid3(20, 10, 2),                    //
                 rapid3(30, 15, 2), feed3(30, 15, -5), rapid3(30, 15, 2)});
}

// G83: pecks of Q5 from R1: feed −4, rapid to R, rapid to −4 + 0.5 = −3.5, feed −9, rapid R,
// rapid −8.5, feed −12 (bottom), rapid to the initial level Z10 (G98).
TEST_CASE("G83 peck drilling retracts to R after every peck") {
    const Run r = run_bare("O1\nG0 X0 Y0 Z10.\nG98 G83 X5. Y5. Z-12. R1. Q5. F100\nM30\n");
    require_clean(r);
    check_path3(r, 3, kXYZ,
                {rapid3(5, 5, 10), rapid3(5, 5, 1), feed3(5, 5, -4), rapid3(5, 5, 1), rapid3(5, 5, -3.5),
                 feed3(5, 5, -9), rapid3(5, 5, 1), rapid3(5, 5, -8.5), feed3(5, 5, -12), rapid3(5, 5, 10)});
}

// G73: pecks of Q5, retract d = 0.1 (machine switch high_speed_retract) after each: feed −4,
// rapid −3.9, feed −9, rapid −8.9, feed −12, rapid R1 (G99). With d = 1: rapid −3, −8.
TEST_CASE("G73 high-speed peck retracts by the machine's d") {
    const std::string program = "O1\nG0 X0 Y0 Z10.\nG99 G73 X5. Y5. Z-12. R1. Q5. F100\nM30\n";
    const Run r = run_bare(program);
    require_clean(r);
    check_path3(r, 3, kXYZ,
                {rapid3(5, 5, 10), rapid3(5, 5, 1), feed3(5, 5, -4), rapid3(5, 5, -3.9), feed3(5, 5, -9),
                 rapid3(5, 5, -8.9), feed3(5, 5, -12), rapid3(5, 5, 1)});
    const Run d1 = run_bare(program, "fanuc-mill", [](Setup& s) { s.cycles.high_speed_retract = 1.0; });
    check_path3(d1, 3, kXYZ,
                {rapid3(5, 5, 10), rapid3(5, 5, 1), feed3(5, 5, -4), rapid3(5, 5, -3), feed3(5, 5, -9),
                 rapid3(5, 5, -8), feed3(5, 5, -12), rapid3(5, 5, 1)});
    CHECK(kerf::interpreter::default_setup(dialect("fanuc-mill")).cycles.high_speed_retract == Approx(0.1));
}

// G82: P500 = 0.5 s at the bottom (FANUC P in ms, semantics.md §8.2), rapid out to Z10 (G98).
TEST_CASE("G82 dwells P at the bottom") {
    const Run r = run_bare("O1\nG0 X0 Y0 Z10.\nG98 G82 Z-3. R1. P500 F50\nM30\n");
    require_clean(r);
    check_path3(r, 3, kXYZ, {rapid3(0, 0, 1), feed3(0, 0, -3), rapid3(0, 0, 10)});
    const auto dwells = texts_of_line(r, 3, EventKind::dwell);
    REQUIRE(dwells.size() == 1);
    CHECK(dwells[0].time_s == Approx(0.5));
    CHECK(dwells[0].end[Z] == Approx(-3));
}

// G84 / G74 tapping: feed to the bottom, dwell P, the spindle reverses (a message), feed out to R,
// then the return level: G99 stays at R3, G98 goes up to Z10.
TEST_CASE("G84 and G74 tap: feed in, reverse, feed out") {
    for (const char* code : {"G84", "G74"}) {
        INFO(code);
        const Run r = run_bare(fmt::format("O1\nG0 X0 Y0 Z10.\nG99 {} Z-8. R3. P200 F125\nG98 X10.\nM30\n", code));
        require_clean(r);
        check_path3(r, 3, kXYZ, {rapid3(0, 0, 3), feed3(0, 0, -8), feed3(0, 0, 3)});
        check_path3(r, 4, kXYZ, {rapid3(10, 0, 3), feed3(10, 0, -8), feed3(10, 0, 3), rapid3(10, 0, 10)});
        CHECK(texts_of_line(r, 3, EventKind::dwell).size() == 1);
        CHECK(texts_of_line(r, 3, EventKind::message).size() == 2);   // reverse, forward again
    }
}

// Boring: G85 feeds out to R; G89 the same with a dwell; G86 rapids out (spindle stop message);
// G76 dwells, shifts Q2 in +X at the bottom, rapids out, shifts back.
TEST_CASE("G85 G86 G89 G76 boring cycles") {
    const Run r = run_bare(
        "O1\nG0 X0 Y0 Z10.\nG98 G85 Z-5. R1. F50\nG80\nG89 X10. Z-5. R1. P100 F50\nG80\nG86 X20. Z-5. R1. F50\nG80\n"
        "G76 X30. Z-5. R1. Q2. P100 F50\nM30\n");
    require_clean(r);
    check_path3(r, 3, kXYZ, {rapid3(0, 0, 1), feed3(0, 0, -5), feed3(0, 0, 1), rapid3(0, 0, 10)});
    check_path3(r, 5, kXYZ, {rapid3(10, 0, 10), rapid3(10, 0, 1), feed3(10, 0, -5), feed3(10, 0, 1), rapid3(10, 0, 10)});
    CHECK(texts_of_line(r, 5, EventKind::dwell).size() == 1);
    check_path3(r, 7, kXYZ, {rapid3(20, 0, 10), rapid3(20, 0, 1), feed3(20, 0, -5), rapid3(20, 0, 10)});
    check_path3(r, 9, kXYZ,
                {rapid3(30, 0, 10), rapid3(30, 0, 1), feed3(30, 0, -5), rapid3(32, 0, -5), rapid3(32, 0, 10),
                 rapid3(30, 0, 10)});
}

// fanuc-mill G87 back boring [FANUC]: from Z50 at X10 Y10: oriented stop, shift Q2 to X12, rapid
// down to the R level Z−20 under the part, shift back to X10, feed up to Z−5, dwell P500 (0.5 s),
// shift to X12, rapid up to the initial Z50 (G87 always returns there), shift back to X10.
// G88 [FANUC]: feed to Z−5, dwell P1000 (1 s), spindle stop and manual retract (a message), then
// the rapid to the return level R2 (G99).
TEST_CASE("G87 back boring and G88 boring with manual retract") {
    const Run r = run_bare("O1\nG0 X0 Y0 Z50.\nG98 G87 X10. Y10. Z-5. R-20. Q2. P500 F100\nG80\n"
                           "G99 G88 X10. Y10. Z-5. R2. P1000 F100\nG80\nM30\n");
    require_clean(r);
    check_path3(r, 3, kXYZ,
                {rapid3(10, 10, 50), rapid3(12, 10, 50), rapid3(12, 10, -20), rapid3(10, 10, -20), feed3(10, 10, -5),
                 rapid3(12, 10, -5), rapid3(12, 10, 50), rapid3(10, 10, 50)});
    const auto dwell87 = texts_of_line(r, 3, EventKind::dwell);
    REQUIRE(dwell87.size() == 1);
    CHECK(dwell87[0].time_s == Approx(0.5));
    check_path3(r, 5, kXYZ, {rapid3(10, 10, 2), feed3(10, 10, -5), rapid3(10, 10, 2)});
    const auto dwell88 = texts_of_line(r, 5, EventKind::dwell);
    REQUIRE(dwell88.size() == 1);
    CHECK(dwell88[0].time_s == Approx(1.0));
    bool manual = false;
    for (const Event& e : texts_of_line(r, 5, EventKind::message)) manual |= e.text.find("by hand") != std::string::npos;
    CHECK(manual);
}

// ADV400 G81 (cycles.md §11.1) with L2 [FANUC: G90 drills the same hole again]: hole at X−3
// Y−2.75 twice, back to R0.1 (G99); with drill_repeat_l = ignore once.
TEST_CASE("ADV400 G81 repeats by L") {
    const std::string program = "O1\nG0 X0 Y0 Z1.\nG99 G81 X-3. Y-2.75 Z-0.05 R0.1 F250 L2\nM30\n";
    const Run r = run_bare(program, "adv400-mill");
    require_clean(r);
    check_path3(r, 3, kXYZ,
                {rapid3(-3, -2.75, 1), rapid3(-3, -2.75, 0.1), feed3(-3, -2.75, -0.05), rapid3(-3, -2.75, 0.1),
                 feed3(-3, -2.75, -0.05), rapid3(-3, -2.75, 0.1)});
    const Run once = run_bare(program, "adv400-mill", [](Setup& s) { s.cycles.repeat_l = false; });
    check_path3(once, 3, kXYZ,
                {rapid3(-3, -2.75, 1), rapid3(-3, -2.75, 0.1), feed3(-3, -2.75, -0.05), rapid3(-3, -2.75, 0.1)});
    CHECK(kerf::interpreter::default_setup(dialect("adv400-mill")).cycles.repeat_l);
}

// ADV400 G84 (cycles.md §11.2): P.5 = 0.5 s at the bottom (ADV400 P in seconds), feed out to R,
// Q1 = 1 s at R, G98 back to Z1. With adv400_g84 = drill-dwell no reverse: rapid out.
TEST_CASE("ADV400 G84 dwells P at the bottom and Q at R") {
    const std::string program = "O1\nG0 X0 Y0 Z1.\nG98 G84 X-2. Y-1. Z-0.5 Q1 R0.1 F15.625 P.5\nM30\n";
    const Run r = run_bare(program, "adv400-mill", [](Setup& s) { s.dwell_p_in_seconds = true; });
    require_clean(r);
    check_path3(r, 3, kXYZ,
                {rapid3(-2, -1, 1), rapid3(-2, -1, 0.1), feed3(-2, -1, -0.5), feed3(-2, -1, 0.1), rapid3(-2, -1, 1)});
    const auto dwells = texts_of_line(r, 3, EventKind::dwell);
    REQUIRE(dwells.size() == 2);
    CHECK(dwells[0].time_s == Approx(0.5));
    CHECK(dwells[1].time_s == Approx(1.0));
    CHECK(kerf::interpreter::default_setup(dialect("adv400-mill")).dwell_p_in_seconds);
    const Run dd = run_bare(program, "adv400-mill", [](Setup& s) {
        s.dwell_p_in_seconds = true;
        s.cycles.tapping_reverses = false;
    });
    check_path3(dd, 3, kXYZ, {rapid3(-2, -1, 1), rapid3(-2, -1, 0.1), feed3(-2, -1, -0.5), rapid3(-2, -1, 1)});
}

// ADV400 lathe G83 (cycles.md §11.3): R1 is the Z level, K6 the depth of every peck, re-approach
// 0.5 above the last depth: feed −5, rapid 1, rapid −4.5, feed −11, rapid 1, rapid −10.5, feed −17,
// rapid 1, rapid −16.5, feed −20, rapid to the initial Z5 (adv400-lathe G98/G99 are feed codes).
// adv400_g83_k = initial-depth: one peck of K, then the rest: feed −5, rapid 1, rapid −4.5, feed −20.
TEST_CASE("ADV400 lathe G83 pecks by K") {
    const std::string program = "O1\nG0 X0 Z5.\nG83 X0 Z-20. K6. R1. F25\nG80\nM30\n";
    const Run r = run_bare(program, "adv400-lathe");
    require_clean(r);
    check_path(r, 3,
               {rapid(0, 1), feed(0, -5), rapid(0, 1), rapid(0, -4.5), feed(0, -11), rapid(0, 1), rapid(0, -10.5),
                feed(0, -17), rapid(0, 1), rapid(0, -16.5), feed(0, -20), rapid(0, 5)});
    const Run first = run_bare(program, "adv400-lathe", [](Setup& s) { s.cycles.adv400_k_first_peck_only = true; });
    check_path(first, 3, {rapid(0, 1), feed(0, -5), rapid(0, 1), rapid(0, -4.5), feed(0, -20), rapid(0, 5)});
}

// Lathe live-tool G83 (cycles.md §10, seed O0004): from X90 Z2 C0, H90 K4: holes at C90, C180,
// C270, C360 (= 0°; "the first hole is shifted by H"); M20 before each hole, M21 after; Q5000 =
// 5 mm pecks (§0), R omitted = the initial level Z2: feed −3, rapid 2, rapid −2.5, feed −8, rapid 2,
// rapid −7.5, feed −10, rapid 2 (already there: no move).
TEST_CASE("lathe G83 face drilling indexes C by H, K holes, clamp M codes") {
    const Run r = run_bare("O1\nG98 F80\nG0 C0\nX90. Z2.\nG83 Z-10. Q5000 H90. K4 M20 F80\nG0 G80 X150. Z150.\nM30\n",
                           "fanuc-lathe-a");
    require_clean(r);
    std::vector<Step3> want;
    for (const double c : {90.0, 180.0, 270.0, 360.0})
        for (const Step3 s : {rapid3(90, 2, c), feed3(90, -3, c), rapid3(90, 2, c), rapid3(90, -2.5, c), feed3(90, -8, c),
                              rapid3(90, 2, c), rapid3(90, -7.5, c), feed3(90, -10, c), rapid3(90, 2, c)})
            want.push_back(s);
    check_path3(r, 5, kXZC, want);
    std::vector<int> m_codes;
    for (const Event& e : texts_of_line(r, 5, EventKind::message)) m_codes.push_back(e.code);
    CHECK(m_codes == std::vector<int>{20, 21, 20, 21, 20, 21, 20, 21});
    check_path3(r, 6, kXZC, {rapid3(150, 150, 360)});
}

// Lathe G87 side drilling (seed O0005): from X125 Z−15, X96, Q4500 = 4.5 mm radius pecks = 9 on
// the diameter, clearance 0.5 radius = 1 on the diameter: feed X116, rapid 125, rapid 117, feed 107,
// rapid 125, rapid 108, feed 98, rapid 125, rapid 99, feed 96, rapid 125; at C120, C240, C360.
TEST_CASE("lathe G87 side drilling pecks along X in radius steps") {
    const Run r = run_bare("O1\nG98\nG0 C0\nX125. Z-15.\nG87 X96. Q4500 H120. K3 M20 F100\nG80\nM30\n", "fanuc-lathe-a");
    require_clean(r);
    std::vector<Step3> want;
    for (const double c : {120.0, 240.0, 360.0}) {
        want.push_back(rapid3(125, -15, c));
        for (const double x : {116.0, 107.0, 98.0}) {
            want.push_back(feed3(x, -15, c));
            want.push_back(rapid3(125, -15, c));
            want.push_back(rapid3(x + 1, -15, c));
        }
        want.push_back(feed3(96, -15, c));
        want.push_back(rapid3(125, -15, c));
    }
    check_path3(r, 5, kXZC, want);
}

// Lathe G83 without H: a block with only C repeats the cycle at that C (§10 alternative program);
// no Q: one feed to the bottom. R−1 from the initial Z2 → R level Z1. The clamp M20 of the cycle
// block clamps the repeat hole too (M20 before, M21 after) [inference, cycles.md §10].
TEST_CASE("lathe G83 repeats on a C block; no Q is one feed") {
    const Run r = run_bare("O1\nG98\nG0 X90. Z2. C0\nG83 Z-10. R-1. M20 F80\nC90.\nG80\nM30\n", "fanuc-lathe-a");
    require_clean(r);
    check_path3(r, 4, kXZC, {rapid3(90, 1, 0), feed3(90, -10, 0), rapid3(90, 2, 0)});
    check_path3(r, 5, kXZC, {rapid3(90, 2, 90), rapid3(90, 1, 90), feed3(90, -10, 90), rapid3(90, 2, 90)});
    for (const std::uint32_t line : {4u, 5u}) {
        std::vector<int> m_codes;
        for (const Event& e : texts_of_line(r, line, EventKind::message)) m_codes.push_back(e.code);
        CHECK(m_codes == std::vector<int>{20, 21});
    }
}

// System B/C: G98/G99 are the return levels (gcode-tables.md §3): G99 stays at R1; system A has no
// return-level code and always goes back to the initial level Z2 (§10 "system A").
TEST_CASE("lathe drilling return level under each G-code system") {
    for (const char* id : {"fanuc-lathe-b", "fanuc-lathe-c"}) {
        INFO(id);
        const Run r = run_bare("O1\nG0 X0 Z2.\nG99 G83 Z-4. R-1. F80\nG80\nM30\n", id);
        require_clean(r);
        check_path(r, 3, {rapid(0, 1), feed(0, -4), rapid(0, 1)});
    }
    const Run a = run_bare("O1\nG0 X0 Z2.\nG83 Z-4. R-1. F80\nG80\nM30\n", "fanuc-lathe-a");
    require_clean(a);
    check_path(a, 3, {rapid(0, 1), feed(0, -4), rapid(0, 2)});
}

// Lathe G84 face tapping and G86 face boring: feed in, dwell P (ms), feed out to R, rapid to the
// initial level. R−3 from Z5 → Z2.
TEST_CASE("lathe G84 and G86 feed out to R") {
    for (const char* code : {"G84", "G86"}) {
        INFO(code);
        const Run r = run_bare(fmt::format("O1\nG98\nG0 X0 Z5.\n{} Z-10. R-3. P100 F100\nG80\nM30\n", code), "fanuc-lathe-a");
        require_clean(r);
        check_path(r, 4, {rapid(0, 2), feed(0, -10), feed(0, 2), rapid(0, 5)});
        const auto dwells = texts_of_line(r, 4, EventKind::dwell);
        REQUIRE(dwells.size() == 1);
        CHECK(dwells[0].time_s == Approx(0.1));
    }
}
