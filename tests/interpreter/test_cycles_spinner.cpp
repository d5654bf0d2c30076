// SPINNER cycles (reference/cycles.md §12–§17, mcodes.md §3.2–§3.3) on small programs. bare_setup of
// spinner-lathe-a: the run starts at X0 Z0 C0 B0 with zero offsets, calculator decimal input
// (B-400 = −400 mm), no accelerations; the machine switches at their machine/SCHEMA.md defaults
// (g38_stop target, clamp_contact half-tolerance, g238_a_timing start, g384_radial_h radius,
// g384_bottom_dwell 0.1 s). Expected paths derived by hand in the comments.
#include "tests/interpreter/cycle_steps.hpp"

using namespace kerf::test;

namespace {

constexpr std::size_t B = 4, C = 5;
constexpr std::array<std::size_t, 3> kXZB{X, Z, B};
constexpr std::array<std::size_t, 3> kXZC{X, Z, C};
constexpr const char* kSpinner = "spinner-lathe-a";

Run spinner(const std::string& text, const SetupChange& change = {}) { return run_bare(text, kSpinner, change); }

std::vector<Event> on_line(const Run& r, std::uint32_t line, EventKind kind) {
    std::vector<Event> out;
    for (const Event& e : r.events)
        if (e.kind == kind && e.source.line == line) out.push_back(e);
    return out;
}

bool has_text(const Run& r, std::uint32_t line, const std::string& part) {
    for (const Event& e : on_line(r, line, EventKind::message))
        if (e.text.find(part) != std::string::npos) return true;
    return false;
}

// The feed moves of a line: their programmed feed in mm/min, whatever G99 says.
void check_feeds_per_minute(const Run& r, std::uint32_t line, const std::vector<double>& want) {
    std::vector<Event> feeds = on_line(r, line, EventKind::linear);
    REQUIRE(feeds.size() == want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        CHECK_FALSE(feeds[i].feed_per_rev);
        CHECK(feeds[i].feed == Approx(want[i]));
    }
}

}  // namespace

// §12: G38 B-472 F10 from B-400 (G99 in effect): one torque-limited feed of B to the commanded B
// (g38_stop target) at 10 mm/min (72 mm: 72 / 10 · 60 = 432 s), then the chuck closes. The G99 mode
// and the modal F stay: the next G1 B-480 F0.1 is 0.1 mm/rev.
TEST_CASE("G38 feeds B to the transfer position at F mm/min and closes the sub-spindle chuck") {
    const std::string program = "O1\nG0 B-400\nG99 G38 B-472 F10\nG1 B-480 F0.1\nM30\n";
    const Run r = spinner(program);
    require_clean(r);
    check_path3(r, 3, kXZB, {feed3(0, 0, -472)});
    check_feeds_per_minute(r, 3, {10});
    CHECK(on_line(r, 3, EventKind::linear)[0].time_s == Approx(432));
    CHECK(has_text(r, 3, "sub-spindle chuck closed"));
    const auto next = on_line(r, 4, EventKind::linear);
    REQUIRE(next.size() == 1);
    CHECK(next[0].feed_per_rev);
    CHECK(next[0].feed == Approx(0.1));
    // g38_stop half-tolerance, Q2: B + Q/2 = −472 + 1 = −471.
    const Run half = spinner("O1\nG0 B-400\nG38 B-472 F10 Q2\nM30\n",
                             [](Setup& s) { s.cycles.spinner.g38_stop_half_tolerance = true; });
    require_clean(half);
    check_path3(half, 3, kXZB, {feed3(0, 0, -471)});
}

// mcodes.md §3.3: 3012 for a wrong argument: no F, or a positive B (§12 "all B are negative").
TEST_CASE("G38 without F or with a positive B is alarm 3012") {
    require_alarm(spinner("O1\nG38 B-472\nM30\n"), 3012);
    require_alarm(spinner("O1\nG38 B10 F10\nM30\n"), 3012);
}

// §13 example: G138 B-425.8 Q1 S700 T300 J10 E1 from B0: G0 to J before B on the retract side
// (−425.8 + 10 = −415.8), G1 at 700 mm/min to the contact B + Q/2 = −425.3, inside the window
// −425.8 < B ≤ −424.8. G138 D1500 J10 E2: 10 mm back at 1500 mm/min, −425.3 + 10 = −415.3.
TEST_CASE("G138 clamps with the tailstock inside the window and releases by J") {
    const Run r = spinner("O1\nG138 B-425.8 Q1 S700 T300 J10 E1\nG138 D1500 J10 E2\nM30\n");
    require_clean(r);
    check_path3(r, 2, kXZB, {rapid3(0, 0, -415.8), feed3(0, 0, -425.3)});
    check_feeds_per_minute(r, 2, {700});
    CHECK(has_text(r, 2, "workpiece clamped"));
    check_path3(r, 3, kXZB, {feed3(0, 0, -415.3)});
    check_feeds_per_minute(r, 3, {1500});
    // Defaults (§13 table): J5, S200, Q1; release J5 at D1500.
    const Run d = spinner("O1\nG138 B-100 T50 E1\nG138 E2\nM30\n");
    require_clean(d);
    check_path3(d, 2, kXZB, {rapid3(0, 0, -95), feed3(0, 0, -99.5)});
    check_feeds_per_minute(d, 2, {200});
    check_path3(d, 3, kXZB, {feed3(0, 0, -94.5)});
    check_feeds_per_minute(d, 3, {1500});
}

// clamp_contact = target puts the contact at B itself, which the window (B, B − Q] excludes:
// 3011 PART NOT CLAMPED. No E (or E3) is 3012.
TEST_CASE("G138 contact outside the window is 3011, a missing E is 3012") {
    const Run r = spinner("O1\nG138 B-425.8 Q1 S700 T300 J10 E1\nM30\n",
                          [](Setup& s) { s.cycles.spinner.clamp_contact_target = true; });
    require_alarm(r, 3011);
    check_path3(r, 2, kXZB, {rapid3(0, 0, -415.8), feed3(0, 0, -425.8)});
    require_alarm(spinner("O1\nG138 B-425.8 T300\nM30\n"), 3012);
    require_alarm(spinner("O1\nG138 B-425.8 T300 E3\nM30\n"), 3012);
    require_alarm(spinner("O1\nG138 B-425.8 E1\nM30\n"), 3012);   // no thrust limit T
}

// §14 example: G238 X100 Z50 B-425.8 K5 Q1 S700 T250 A501 E1: T0501 at the start (g238_a_timing
// start), G0 X100 Z50 B(−425.8 + 5 = −420.8) together, G1 at 700 to −425.3. Release
// G238 X250 Z250 B100 D1200 J10 E2: 10 mm at 1200 (−415.3), then G0 X250 Z250 B100.
TEST_CASE("G238 positions X Z B together, clamps, and releases by J then G0") {
    const std::string program =
        "O1\nG238 X100 Z50 B-425.8 K5 Q1 S700 T250 A501 E1\nG238 X250 Z250 B100 D1200 J10 E2\nM30\n";
    const Run r = spinner(program);
    require_clean(r);
    const auto tools = on_line(r, 2, EventKind::tool_change);
    REQUIRE(tools.size() == 1);
    CHECK(tools[0].tool == 5);
    check_path3(r, 2, kXZB, {rapid3(100, 50, -420.8), feed3(100, 50, -425.3)});
    check_feeds_per_minute(r, 2, {700});
    check_path3(r, 3, kXZB, {feed3(100, 50, -415.3), rapid3(250, 250, 100)});
    check_feeds_per_minute(r, 3, {1200});
    // g238_a_timing after-clamp: the tool change is the last event of the clamping block.
    const Run after = spinner(program, [](Setup& s) { s.cycles.spinner.g238_a_after_clamp = true; });
    std::vector<Event> line2;
    for (const Event& e : after.events)
        if (e.source.line == 2 && e.kind != EventKind::message) line2.push_back(e);
    REQUIRE(line2.size() == 3);
    CHECK(line2[2].kind == EventKind::tool_change);
    // Release without B and J (§14 item 8): straight G0 to B0.
    const Run b0 = spinner("O1\nG238 B-100 T50 E1\nG238 E2\nM30\n");
    require_clean(b0);
    check_path3(b0, 2, kXZB, {rapid3(0, 0, -90), feed3(0, 0, -99.5)});
    check_path3(b0, 3, kXZB, {rapid3(0, 0, 0)});
}

// §15 example (O0001 G384/G380): at X150 Z5 C30, G384 H20 F2 S300 D300 M20 T2: brake M20, R = 0
// (no R word: the R point is the positioning point), synchronised feed F·S = 2 · 300 = 600 mm/min
// to Z5 − 20 = −15, dwell 0.1 s, reverse at F·D = 600 back to Z5, brake off M21. G384 C90: G0 to
// C90, the same hole. G380 ends it; the G0 after it is a plain rapid.
TEST_CASE("G384 taps each hole synchronised, G380 cancels") {
    const Run r = spinner("O1\nG98\nG0 X150 Z5 C30\nG384 H20.0 F2.0 S300. D300. M20. T2\nG384 C90.0\nG380\n"
                          "G0 X200 Z100\nM30\n");
    require_clean(r);
    check_path3(r, 4, kXZC, {feed3(150, -15, 30), feed3(150, 5, 30)});
    check_feeds_per_minute(r, 4, {600, 600});
    const auto dwells = on_line(r, 4, EventKind::dwell);
    REQUIRE(dwells.size() == 1);
    CHECK(dwells[0].time_s == Approx(0.1));
    std::vector<int> codes;
    for (const Event& e : on_line(r, 4, EventKind::message))
        if (e.code) codes.push_back(e.code);
    CHECK(codes == std::vector<int>{20, 21});
    check_path3(r, 5, kXZC, {rapid3(150, 5, 90), feed3(150, -15, 90), feed3(150, 5, 90)});
    CHECK(moves_on_line(r, 6).empty());
    check_path3(r, 7, kXZC, {rapid3(200, 100, 90)});
}

// R−3 from Z5: G0 to Z2, feed 10 deep to Z−8 at 1.5 · 300 = 450 (D omitted = S), back to Z2,
// G0 to the positioning point Z5. T3 (sub-spindle) taps toward +Z: from Z−5, H10 → Z5.
TEST_CASE("G384 R point, D default and the T3 direction") {
    const Run r = spinner("O1\nG0 X0 Z5\nG384 H10 R-3 F1.5 S300 T2\nG380\nG0 Z-5\nG384 H10 F1 S100 T3\nG380\nM30\n");
    require_clean(r);
    check_path3(r, 3, kXZC, {rapid3(0, 2, 0), feed3(0, -8, 0), feed3(0, 2, 0), rapid3(0, 5, 0)});
    check_feeds_per_minute(r, 3, {450, 450});
    check_path3(r, 6, kXZC, {feed3(0, 5, 0), feed3(0, -5, 0)});
}

// T1 radial: X is a diameter, H5 a radius depth (g384_radial_h radius): X60 − 2·5 = X50; in at
// F·S = 800, out at F·D = 400. With g384_radial_h diameter: X60 − 5 = X55.
TEST_CASE("G384 T1 taps along X with H as a radius or diameter depth") {
    const std::string program = "O1\nG0 X60 Z-10 C0\nG384 H5 F1 S800 D400 T1\nG384 C180\nG380\nM30\n";
    const Run r = spinner(program);
    require_clean(r);
    check_path3(r, 3, kXZC, {feed3(50, -10, 0), feed3(60, -10, 0)});
    check_feeds_per_minute(r, 3, {800, 400});
    check_path3(r, 4, kXZC, {rapid3(60, -10, 180), feed3(50, -10, 180), feed3(60, -10, 180)});
    const Run d = spinner(program, [](Setup& s) { s.cycles.spinner.g384_radial_h_diameter = true; });
    check_path3(d, 3, kXZC, {feed3(55, -10, 0), feed3(60, -10, 0)});
}

// §15 notes: another canned cycle before G380 is 3011; a missing H, a repeated F in a later
// block, a brake M220 without T3 are 3012.
TEST_CASE("G384 alarms 3011 and 3012") {
    const Run other = spinner("O1\nG0 X90 Z5\nG384 H10 F1 S300 T2\nG83 Z-10 F80\nM30\n");
    require_alarm(other, 3011);
    CHECK(on_line(other, 4, EventKind::alarm).size() == 1);
    require_alarm(spinner("O1\nG384 F1 S800 D800 M20 T1\nM30\n"), 3012);   // §15 seed: "G384 N30" has no H
    require_alarm(spinner("O1\nG384 H10 F1 S300 T2\nG384 C90 F2\nM30\n"), 3012);
    require_alarm(spinner("O1\nG384 H10 F1 S300 M220 T2\nM30\n"), 3012);
    require_alarm(spinner("O1\nG384 H10 F1 S300 T4\nM30\n"), 3012);
}

// §16: M329 X0 Z5 H-30 R-2 F2.5 S400 T2 A303 I0 from X0 Z0: T3 (offset 3), G0 Z5, G0 to R Z3,
// feed to the absolute H Z−30 at 2.5 · 400 = 1000 mm/min, back to Z3 at 1000, G0 to Z5.
TEST_CASE("M329 taps with the work spindle to the absolute H") {
    const Run r = spinner("O1\nM329 X0 Z5 H-30.0 R-2 F2.5 S400 T2 A303 I0\nM30\n");
    require_clean(r);
    const auto tools = on_line(r, 2, EventKind::tool_change);
    REQUIRE(tools.size() == 1);
    CHECK(tools[0].tool == 3);
    check_path3(r, 2, kXZC, {rapid3(0, 5, 0), rapid3(0, 3, 0), feed3(0, -30, 0), feed3(0, 3, 0), rapid3(0, 5, 0)});
    check_feeds_per_minute(r, 2, {1000, 1000});
    CHECK(has_text(r, 2, "right-hand"));
    require_alarm(spinner("O1\nM329 X0 Z5 F2.5 S400\nM30\n"), 3012);   // no H
}

// §17: G100 Z300. with the coupling position at machine Z450 (bare setup: machine = work): G0 to
// Z450, then carry the tailstock to Z300. G100 I1: only the coupling move. G101: G0 to the second
// coupling hole Z350. Without a [tailstock] entry the carriage stays and a message says why.
TEST_CASE("G100 and G101 move the carriage to the tailstock coupling positions") {
    const auto machine = [](Setup& s) {
        s.cycles.spinner.coupling_z = 450.0;
        s.cycles.spinner.coupling_z_second = 350.0;
    };
    const Run r = spinner("O1\nG100 Z300.\nG100 I1\nG101\nM30\n", machine);
    require_clean(r);
    check_path3(r, 2, kXZC, {rapid3(0, 450, 0), rapid3(0, 300, 0)});
    check_path3(r, 3, kXZC, {rapid3(0, 450, 0)});
    check_path3(r, 4, kXZC, {rapid3(0, 350, 0)});
    CHECK(has_text(r, 4, "until M56"));
    const Run none = spinner("O1\nG101\nM30\n");
    require_clean(none);
    CHECK(moves_on_line(none, 2).empty());
    CHECK(has_text(none, 2, "coupling_z_second"));
    // G100 without Z or I1 (the template's `G100 Z_` read leniently) is 3012 before any move.
    const Run bare = spinner("O1\nG100\nM30\n", machine);
    require_alarm(bare, 3012);
    CHECK(moves(bare).empty());
}

// mcodes.md §3.2: M432 moves no axis; the run says what the cycle does.
TEST_CASE("M432 is the parts catcher cycle without axis motion") {
    const Run r = spinner("O1\nG0 X50 Z20\nM432\nM30\n");
    require_clean(r);
    CHECK(moves_on_line(r, 3).empty());
    CHECK(has_text(r, 3, "parts catcher"));
}
