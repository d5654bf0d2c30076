// A thread whose axis speed (lead × rpm) is over the machine's maximum cutting feed gives a warning
// message event with its own code (interpreter/events.hpp kerf_warning, cycles.md §9), after the
// thread move and without stopping the run.
#include <catch2/catch.hpp>

#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf;

namespace {

int warnings(const test::Run& r) {
    int n = 0;
    for (const auto& e : r.events)
        n += e.kind == test::EventKind::message && e.code == interpreter::kerf_warning::thread_speed_over_limit;
    return n;
}

const auto limit_10000 = [](test::Setup& s) { s.max_cutting_feed = 10000; };

}  // namespace

TEST_CASE("lead times rpm over the maximum cutting feed is a warning event") {
    // G32 Z-20 F2 at S6000: 2 mm × 6000 rpm = 12000 mm/min > 10000.
    const auto fast = test::run("O1\nG97 S6000 M03\nG00 X20. Z2.\nG32 Z-20. F2.\nG00 X30.\nM30\n", "fanuc-lathe-a", limit_10000);
    CHECK(warnings(fast) == 1);
    CHECK(fast.result.completed);   // a warning, not an alarm
    // S4000: 8000 mm/min, under the limit.
    CHECK(warnings(test::run("O1\nG97 S4000 M03\nG00 X20. Z2.\nG32 Z-20. F2.\nM30\n", "fanuc-lathe-a", limit_10000)) == 0);
    // No limit configured: nothing to check.
    CHECK(warnings(test::run("O1\nG97 S6000 M03\nG00 X20. Z2.\nG32 Z-20. F2.\nM30\n", "fanuc-lathe-a",
                             [](test::Setup& s) { s.max_cutting_feed = 0; })) == 0);
    // G34 F2 K0.1 over 40 mm: the lead grows to sqrt(4 + 8) = 3.464 mm; at S3000 that is 10392 mm/min
    // at the end (6000 at the start): the larger lead counts.
    CHECK(warnings(test::run("O1\nG97 S3000 M03\nG00 X20. Z2.\nG34 Z-38. F2. K0.1\nM30\n", "fanuc-lathe-a", limit_10000)) == 1);
}
