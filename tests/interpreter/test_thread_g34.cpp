// G34 variable-lead threading (reference/cycles.md §9, [FANUC] `G34 X(U) Z(W) F(L0) K(ΔL/rev)`):
// the lead after n revolutions is L0 + K·n, so the tool has gone ∫0^n (L0 + K·m) dm =
// L0·n + K·n²/2 after n revolutions. Expected values derived by hand in the comments.
#include "tests/interpreter/cycle_steps.hpp"

#include "motion/time.hpp"

using namespace kerf::test;

// From Z0 to Z-40 (length 40) with F2 K0.1 at S600: K/2·n² + 2n − 40 = 0 →
// n = (√(4 + 8) − 2) / 0.1 = (3.464102 − 2) / 0.1 = 14.641016 revolutions; the end lead
// 2 + 0.1·14.641016 = √12 = 3.464102; time 14.641016 / 600 min = 1.464102 s (a constant lead of 2
// would take 20 revolutions, 2 s).
TEST_CASE("G34 times the thread by the integral of the lead and gives the lead at the end (cycles.md §9)") {
    for (const char* dialect : {"fanuc-lathe-a", "fanuc-lathe-b", "fanuc-lathe-c"}) {
        INFO(dialect);
        const Run r = run_bare("O1\nG97 S600 M3\nG0 X30. Z0\nG34 Z-40. F2. K0.1\nG0 X40.\nM30\n", dialect);
        require_clean(r);
        check_path(r, 4, {thread(30, -40)});
        const auto cuts = of_kind(r, EventKind::thread);
        REQUIRE(cuts.size() == 1);
        CHECK(cuts[0].feed == Approx(2));
        CHECK(cuts[0].lead_end == Approx(3.464102).margin(1e-6));
        CHECK(cuts[0].time_s == Approx(1.464102).margin(1e-6));
    }
}

// A decreasing lead: F4 K-0.1 over 40: n = (√(16 − 8) − 4) / −0.1 = (2.828427 − 4) / −0.1 =
// 11.715729 revolutions, end lead √8 = 2.828427, at S300: 11.715729 / 300 · 60 = 2.343146 s.
// K0 is G32: 40 / 4 = 10 revolutions, 2 s, the lead stays 4.
TEST_CASE("G34 with a decreasing lead, and K0 like G32") {
    const Run r = run_bare("O1\nG97 S300 M3\nG0 X30. Z0\nG34 Z-40. F4. K-0.1\nG0 X40.\nZ0\nX30.\nG34 Z-40. F4. K0\nM30\n",
                           "fanuc-lathe-a");
    require_clean(r);
    const auto cuts = of_kind(r, EventKind::thread);
    REQUIRE(cuts.size() == 2);
    CHECK(cuts[0].lead_end == Approx(2.828427).margin(1e-6));
    CHECK(cuts[0].time_s == Approx(2.343146).margin(1e-6));
    CHECK(cuts[1].lead_end == Approx(4));
    CHECK(cuts[1].time_s == Approx(2));
}

// F2 K-0.1 over 40: 4 − 8 < 0, the lead reaches zero after 20 revolutions and 20 mm: alarm 313.
TEST_CASE("G34 whose lead reaches zero before the end: alarm 313") {
    require_alarm(run_bare("O1\nG97 S300 M3\nG0 X30. Z0\nG34 Z-40. F2. K-0.1\nM30\n", "fanuc-lathe-a"), 313);
}

TEST_CASE("variable_lead: the closed form against the integral summed in small steps") {
    const auto v = kerf::motion::variable_lead(40, 2, 0.1);
    REQUIRE(v);
    // Walk the revolutions in steps of 1e-4: the distance covered reaches 40 at n.
    double n = 0, distance = 0;
    const double dn = 1e-4;
    while (distance < 40) {
        distance += (2 + 0.1 * (n + dn / 2)) * dn;
        n += dn;
    }
    CHECK(v->revolutions == Approx(n).margin(2e-4));
    CHECK(v->lead_end == Approx(2 + 0.1 * n).margin(1e-4));
    CHECK_FALSE(kerf::motion::variable_lead(40, 2, -0.1));
    CHECK_FALSE(kerf::motion::variable_lead(40, 0, 0.1));
}
