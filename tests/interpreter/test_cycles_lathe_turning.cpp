// G74/G75 peck cycles, G76 and G92 threading, G90/G94 single cycles (reference/cycles.md §5–§9)
// on small programs, in each G-code system where the number differs. Expected paths derived by
// hand in the comments; the worked examples O0009, O0010, O0011 of the reference reproduced.
#include <cmath>

#include "tests/interpreter/cycle_steps.hpp"

using namespace kerf::test;

namespace {

struct Codes {
    const char* dialect;
    const char* face_peck;    // G74 (A, B) / G76 (C)
    const char* grooving;     // G75 / G77
    const char* threading;    // G76 / G78
    const char* thread_one;   // G92 / G78 (B) / G21 (C)
    const char* turning;      // G90 / G77 / G20
    const char* facing;       // G94 / G79 / G24
};
constexpr Codes kSystems[] = {
    {"fanuc-lathe-a", "G74", "G75", "G76", "G92", "G90", "G94"},
    {"fanuc-lathe-b", "G74", "G75", "G76", "G78", "G77", "G79"},
    {"fanuc-lathe-c", "G76", "G77", "G78", "G21", "G20", "G24"},
};

}  // namespace

// cycles.md §5 worked O0009: A = X0 Z3, e = 0.5, Δk = Q20000 = 20 mm (IS-B increments, §0):
// feed Z−17, rapid Z−16.5, feed Z−37, rapid Z−36.5, feed Z−57, rapid Z−56.5, feed Z−60, rapid Z3.
TEST_CASE("G74 peck drilling reproduces O0009 (cycles.md §5)") {
    for (const Codes& c : kSystems) {
        INFO(c.dialect);
        const Run r = run_clean("O1\nG0 X0 Z3.\n{0} R0.5\n{0} Z-60. Q20000 F0.2\nM30\n", c.face_peck, c.dialect);
        check_path(r, 4, {feed(0, -17), rapid(0, -16.5), feed(0, -37), rapid(0, -36.5), feed(0, -57), rapid(0, -56.5),
                          feed(0, -60), rapid(0, 3)});
    }
}

// Face grooving (§5): A = X80 Z1 (radius 40), end X70 (radius 35) Z−3, P2500 = 2.5 mm X step
// (radius), Q2000 = 2 mm pecks, e = 0.5, Δd = R0.2 (radius: 0.4 on the diameter) away from the
// next column (+X). Columns X80, X75, X70: feed Z−1, rapid Z−0.5, feed Z−3, rapid X+0.4, rapid Z1,
// rapid to the next column; after the last, rapid to A.
TEST_CASE("G74 face grooving steps columns and relieves at the bottom (cycles.md §5)") {
    const Run r = run_bare("O1\nG0 X80. Z1.\nG74 R0.5\nG74 X70. Z-3. P2500 Q2000 R0.2 F0.1\nM30\n", "fanuc-lathe-a");
    require_clean(r);
    std::vector<Step> want;
    for (const double x : {80.0, 75.0, 70.0}) {
        if (x != 80.0) want.push_back(rapid(x, 1));
        for (const Step s : {feed(x, -1), rapid(x, -0.5), feed(x, -3), rapid(x + 0.4, -3), rapid(x + 0.4, 1)}) want.push_back(s);
    }
    want.push_back(rapid(80, 1));
    check_path(r, 4, want);
}

// cycles.md §6 worked O0010: A = X80 Z−55, X69 Z−28, P3000 = 3 mm pecks (radius: X 80 → 74),
// e = R.5 (radius: rapid back to X75), Q2500 = 2.5 mm Z steps: plunges at Z −55, −52.5, …, −30
// and the clipped −28 (12 plunges); each plunge: feed X74, rapid X75, feed X69, rapid X80.
TEST_CASE("G75 grooving reproduces O0010 (cycles.md §6)") {
    for (const Codes& c : kSystems) {
        INFO(c.dialect);
        const Run r = run_clean("O1\nG0 X80. Z-55.\n{0} R.5\n{0} X69. Z-28. P3000 Q2500 F.1\nM30\n", c.grooving, c.dialect);
        std::vector<Step> want;
        std::vector<double> plunges;
        for (int k = 0; k <= 10; ++k) plunges.push_back(-55 + 2.5 * k);
        plunges.push_back(-28);
        CHECK(plunges.size() == 12);
        for (std::size_t i = 0; i < plunges.size(); ++i) {
            const double z = plunges[i];
            if (i > 0) want.push_back(rapid(80, z));
            for (const Step s : {feed(74, z), rapid(75, z), feed(69, z), rapid(80, z)}) want.push_back(s);
        }
        want.push_back(rapid(80, -55));
        check_path(r, 4, want);
    }
}

// cycles.md §7 worked O0011: k = P1300 = 1.3, Δd = Q500 = 0.5, Δdmin = Q50 = 0.05, d = R0.03,
// m = 1, a = 60, root X57.4, Z−30, A = X62 Z4. Depths 0.5·√n for n = 1..6 (each step > Δdmin),
// n = 7 gives 1.3229 ≥ k − d = 1.27 → 1.27; then the finishing pass at 1.3. Diameters
// 57.4 + 2(1.3 − d): 59.000, 58.586, 58.268, 58.000, 57.764, 57.551, 57.460, 57.400 (the
// reference's list). Flank infeed toward the thread end: Z start = 4 − (d − 0.5)·tan 30°. Each
// pass: rapid in, thread to Z−30, rapid X62, rapid Z4. Time of a cut: lead 2 × 500 rpm =
// 1000 mm/min over its length.
TEST_CASE("G76 reproduces the O0011 pass depths (cycles.md §7)") {
    const double depths[] = {0.5,           0.5 * std::sqrt(2.0), 0.5 * std::sqrt(3.0), 1.0, 0.5 * std::sqrt(5.0),
                             0.5 * std::sqrt(6.0), 1.27, 1.3};
    const double listed[] = {59.000, 58.586, 58.268, 58.000, 57.764, 57.551, 57.460, 57.400};
    for (const Codes& c : kSystems) {
        INFO(c.dialect);
        const Run r = run_clean("O1\nG97 S500 M3\nG0 X62. Z4.\n{0} P010060 Q50 R0.03\n"
                                "{0} X57.4 Z-30. R0 P1300 Q500 F2.\nM30\n",
                                c.threading, c.dialect);
        std::vector<Step> want;
        for (std::size_t i = 0; i < 8; ++i) {
            const double x = 57.4 + 2 * (1.3 - depths[i]);
            CHECK(x == Approx(listed[i]).margin(0.0005));
            const double z = 4 - (depths[i] - 0.5) * std::tan(M_PI / 6);
            for (const Step s : {rapid(x, z), thread(x, -30), rapid(62, -30), rapid(62, 4)}) want.push_back(s);
        }
        check_path(r, 5, want);
        const auto cuts = of_kind(r, EventKind::thread);
        REQUIRE(cuts.size() == 8);
        CHECK(cuts[0].feed == Approx(2));
        CHECK(cuts[0].time_s == Approx(34.0 / 1000.0 * 60.0));   // Z4 → Z−30 at 1000 mm/min
    }
}

// G92 (§8.2) with the machine's run-out of 1 lead (thread_chamfer default): A = X35 Z5, X29.4
// Z−20 F1.5: rapid X29.4, thread to Z−18.5, 45° pull-out thread to X32.4 Z−20 (1.5 on the
// radius), rapid X35, rapid Z5. The next block `X28.8` repeats the cycle (modal group 01).
// Time of the first cut: 23.5 mm at 1.5 × 400 = 600 mm/min = 2.35 s.
TEST_CASE("G92 single thread cycle with run-out, repeated by X blocks (cycles.md §8.2)") {
    for (const Codes& c : kSystems) {
        INFO(c.dialect);
        const Run r =
            run_clean("O1\nG97 S400 M3\nG0 X35. Z5.\n{0} X29.4 Z-20. F1.5\nX28.8\nG0 X100.\nM30\n", c.thread_one, c.dialect);
        check_path(r, 4, {rapid(29.4, 5), thread(29.4, -18.5), thread(32.4, -20), rapid(35, -20), rapid(35, 5)});
        check_path(r, 5, {rapid(28.8, 5), thread(28.8, -18.5), thread(31.8, -20), rapid(35, -20), rapid(35, 5)});
        check_path(r, 6, {rapid(100, 5)});
        CHECK(of_kind(r, EventKind::thread)[0].time_s == Approx(2.35));
    }
    // Without run-out (thread_chamfer 0) the cut runs straight to the end point.
    const Run plain = run_bare("O1\nG97 S400 M3\nG0 X35. Z5.\nG92 X29.4 Z-20. F1.5\nM30\n", "fanuc-lathe-a",
                               [](Setup& s) { s.cycles.thread_chamfer_leads = 0; });
    check_path(plain, 4, {rapid(29.4, 5), thread(29.4, -20), rapid(35, -20), rapid(35, 5)});
}

// G90 (§8.1): rapid X to X + 2R, feed to (X, Z), feed X back to X_A, rapid Z back. A = X52 Z2.
// Taper R−2 (radius): start X 40 + 2·(−2) = 36.
TEST_CASE("G90 turning cycle, modal repeat and taper R (cycles.md §8.1)") {
    for (const Codes& c : kSystems) {
        INFO(c.dialect);
        const Run r = run_clean("O1\nG0 X52. Z2.\n{0} X45. Z-20. F0.2\nX40.\n{0} X40. Z-20. R-2.\nG0 X60.\nM30\n", c.turning, c.dialect);
        check_path(r, 3, {rapid(45, 2), feed(45, -20), feed(52, -20), rapid(52, 2)});
        check_path(r, 4, {rapid(40, 2), feed(40, -20), feed(52, -20), rapid(52, 2)});
        check_path(r, 5, {rapid(36, 2), feed(40, -20), feed(52, -20), rapid(52, 2)});
        check_path(r, 6, {rapid(60, 2)});
    }
}

// G94 (§8.3): rapid Z to Z + R, feed to (X, Z), feed Z back to Z_A, rapid X back. A = X52 Z2.
// Taper R−1 along Z: start Z −4 − 1 = −5.
TEST_CASE("G94 facing cycle and taper R (cycles.md §8.3)") {
    for (const Codes& c : kSystems) {
        INFO(c.dialect);
        const Run r = run_clean("O1\nG0 X52. Z2.\n{0} X20. Z-2. F0.2\n{0} X20. Z-4. R-1.\nM30\n", c.facing, c.dialect);
        check_path(r, 3, {rapid(52, -2), feed(20, -2), feed(20, 2), rapid(52, 2)});
        check_path(r, 4, {rapid(52, -5), feed(20, -4), feed(20, 2), rapid(52, 2)});
    }
}

// §0: with the 'tens of microns' machines (IS-C, 0.0001 mm) the same Q20000 is 2 mm.
TEST_CASE("G74 P/Q follow the machine's P/Q unit (cycles.md §0)") {
    const Run r = run_bare("O1\nG0 X0 Z3.\nG74 R0.5\nG74 Z-2. Q20000 F0.2\nM30\n", "fanuc-lathe-a",
                           [](Setup& s) { s.cycles.pq_unit_mm = 0.0001; });
    require_clean(r);
    check_path(r, 4, {feed(0, 1), rapid(0, 1.5), feed(0, -1), rapid(0, -0.5), feed(0, -2), rapid(0, 3)});
}
