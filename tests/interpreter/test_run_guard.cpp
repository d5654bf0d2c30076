// interpreter/run_guard.hpp: the bounds of a run besides the step limit (issue 17). A block can
// expand into any number of moves, and the step limit counts blocks: the move limit ends such a
// run; the wall-clock limit ends any run that takes too long.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <thread>

#include "interpreter/events.hpp"
#include "interpreter/run_guard.hpp"
#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf;
using namespace kerf::test;
namespace ka = interpreter::kerf_alarm;

namespace {

std::size_t motion_events(const std::vector<Event>& events) {
    std::size_t n = 0;
    for (const Event& e : events)
        n += e.kind == EventKind::rapid || e.kind == EventKind::linear || e.kind == EventKind::thread ||
             e.kind == EventKind::arc_cw || e.kind == EventKind::arc_ccw;
    return n;
}

}  // namespace

// ../shared/findings/cli-mutation/hang-run-check-fmt.fanuc-lathe-c.nc in small: the system C G76
// (face peck drilling, cycles.md §5) with a peck of Q400 = 0.4 mm over 580 mm of Z and a step of
// P1200 = 1.2 mm over 280 mm of X expands into about 340,000 moves from one block, and an M99 main
// program runs it again and again: the step limit (blocks) never comes.
TEST_CASE("run guard: the move limit stops a cycle block that expands without end", "[run_guard]") {
    const std::string text = "O1\nG00 X300. Z550.\nG76 X20. Z-30. P1200 Q400 F2.\nM99\n";
    const Run r = run_bare(text, "fanuc-lathe-c", [](Setup& s) { s.move_limit = 1000; });
    REQUIRE(r.result.alarms.size() == 1);
    const Event& alarm = r.result.alarms[0];
    CHECK(alarm.code == ka::move_limit);
    CHECK(alarm.text == "move limit of 1000 moves reached: an endless loop, or a cycle with a step far smaller than its stroke?");
    CHECK(alarm.source.line == 3);   // the G76 block
    CHECK(motion_events(r.events) == 1000);
    CHECK(r.result.blocks == 3);     // the limit struck inside the first G76
    CHECK_FALSE(r.result.completed);
    CHECK(r.events.back().kind == EventKind::alarm);
}

TEST_CASE("run guard: the step limit still counts blocks, the move limit moves", "[run_guard]") {
    // A bar-feed loop asked to run a million passes (RunOptions::passes): the bounds end it.
    const std::string text = "O1\nG91 G01 X1. F100.\nM99\n";
    interpreter::RunOptions many;
    many.passes = 1'000'000;
    const auto run_limited = [&](std::uint64_t step_limit, std::uint64_t move_limit) {
        Setup s = bare_setup(dialect("fanuc-mill"));
        s.step_limit = step_limit;
        s.move_limit = move_limit;
        return run_with(text, dialect("fanuc-mill"), s, many);
    };
    const Run steps = run_limited(90, 1000);
    REQUIRE(steps.result.alarms.size() == 1);
    CHECK(steps.result.alarms[0].code == ka::step_limit);
    CHECK(steps.result.alarms[0].text == "step limit of 90 blocks reached: endless loop?");
    // Blocks: O1, G91 G01, M99 per turn: the 91st block is the alarm's, the 30th turn's move ran.
    CHECK(motion_events(steps.events) == 30);
    const Run moves = run_limited(1000, 20);
    REQUIRE(moves.result.alarms.size() == 1);
    CHECK(moves.result.alarms[0].code == ka::move_limit);
    CHECK(motion_events(moves.events) == 20);
}

TEST_CASE("run guard: the wall-clock limit stops an endless run", "[run_guard]") {
    const dialects::Dialect& d = dialect("fanuc-mill");
    Setup setup = bare_setup(d);
    setup.step_limit = std::uint64_t{1} << 62;   // never
    interpreter::RunOptions options;
    options.time_limit = std::chrono::milliseconds(200);
    const auto start = std::chrono::steady_clock::now();
    const Run r = run_with("O1\nN10 #1=#1+1\nGOTO 10\n", d, setup, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    REQUIRE(r.result.alarms.size() == 1);
    CHECK(r.result.alarms[0].code == ka::time_limit);
    CHECK(r.result.alarms[0].text.find("time limit of 0.2 s reached") == 0);
    CHECK(seconds >= 0.2);
    CHECK(seconds < 10);   // the clock is read every 1024 blocks: late by milliseconds, not seconds
    CHECK(r.result.blocks > 1000);
}

TEST_CASE("run guard: no time limit unless one is given; the bounds are kerf's run-limit alarms", "[run_guard]") {
    interpreter::RunGuard guard(5, 3, std::chrono::milliseconds(0));
    for (int i = 0; i < 100'000; ++i) REQUIRE_FALSE(guard.tick());
    CHECK_FALSE(guard.block(5));
    REQUIRE(guard.block(6));
    CHECK(guard.block(6)->number == ka::step_limit);
    CHECK_FALSE(guard.move());
    CHECK_FALSE(guard.move());
    CHECK_FALSE(guard.move());
    REQUIRE(guard.move());
    for (const int code : {ka::step_limit, ka::move_limit, ka::time_limit}) CHECK(ka::is_run_limit(code));
    CHECK_FALSE(ka::is_run_limit(ka::syntax_error));
    CHECK_FALSE(ka::is_run_limit(ka::internal));
}

// RunOptions::cancel (issue 13): the flag stops the run before its next block, also in a macro loop
// that emits no event at all (the analyzer once threw out of its sink, which such a loop never calls).
TEST_CASE("cancel: a flag set by another thread stops an endless eventless loop at once", "[run_guard]") {
    const std::string text = "O1\n#1=0\nWHILE [#1 GE 0] DO1\n#1=#1+1\nEND1\nM30\n";
    const dialects::Dialect& d = dialect("fanuc-mill");
    Setup setup = plain_setup(d);
    setup.step_limit = 4'000'000'000;   // far beyond what 100 ms runs: only the flag stops it
    std::atomic<bool> cancel{false};
    interpreter::RunOptions options;
    options.cancel = &cancel;
    std::thread canceller([&cancel] {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        cancel = true;
    });
    const Run r = run_with(text, d, setup, options);
    canceller.join();
    CHECK(r.result.cancelled);
    CHECK_FALSE(r.result.completed);
    CHECK(r.result.alarms.empty());   // not an alarm of the program
    CHECK(r.result.blocks > 1000);    // it ran until the flag came
}

TEST_CASE("cancel: a flag already set runs nothing", "[run_guard]") {
    std::atomic<bool> cancel{true};
    interpreter::RunOptions options;
    options.cancel = &cancel;
    const dialects::Dialect& d = dialect("fanuc-mill");
    const Run r = run_with("O1\nG00 X10. Y10.\nM30\n", d, plain_setup(d), options);
    CHECK(r.result.cancelled);
    CHECK(r.result.blocks == 0);
    CHECK(motion_events(r.events) == 0);
}

// RunOptions::run_to: stop after a block, where the tool then is (the language server's "run to here").
TEST_CASE("run to a block: the run stops after its first execution, also inside a subprogram", "[run_guard]") {
    const std::string text = "O1\nG00 X10. Y10.\nM98 P2 L3\nG00 X50. Y50.\nM30\nO2\nG91 G00 X1.\nG90 M99\n";
    const dialects::Dialect& d = dialect("fanuc-mill");
    interpreter::RunOptions options;
    // Line 3 of the main program (M98 P2 L3): the call is made, nothing of O2 runs yet.
    options.run_to = interpreter::RunOptions::BlockAt{0, static_cast<std::uint32_t>(text.find("M98"))};
    Run r = run_with(text, d, plain_setup(d), options);
    CHECK(r.result.reached_block);
    CHECK_FALSE(r.result.completed);
    CHECK(r.result.final_position[X] == Approx(10));
    // The G91 X1. block of O2: its first execution, after one step of X1.
    options.run_to = interpreter::RunOptions::BlockAt{0, static_cast<std::uint32_t>(text.find("G91"))};
    r = run_with(text, d, plain_setup(d), options);
    CHECK(r.result.reached_block);
    CHECK(r.result.final_position[X] == Approx(11));
    // A block that never runs: the run goes to its end.
    options.run_to = interpreter::RunOptions::BlockAt{0, 1};
    r = run_with(text, d, plain_setup(d), options);
    CHECK_FALSE(r.result.reached_block);
    CHECK(r.result.completed);
    CHECK(r.result.final_position[X] == Approx(50));
}

// A system variable outside kerf's tables (#3101 on FANUC, which O8200 of the corpus reads) is
// kerf's limit 90006, not the program's alarm 115, on a read and on a write, at the block that
// names it; the run stops there (the control may well have the variable), and --verify and the
// analyzer take it as the end of the run, like the other limits.
TEST_CASE("a system variable kerf does not model stops the run as kerf's alarm 90006") {
    CHECK(ka::is_run_limit(ka::unknown_variable));
    for (const char* block : {"#1=#3101", "#3101=5"}) {
        INFO(block);
        const Run r = run_bare(std::string("O1\n") + block + "\nG00 X1.\nM30\n", "fanuc-mill");
        require_alarm(r, ka::unknown_variable);
        CHECK(r.result.alarms[0].source.line == 2);
        CHECK(r.result.alarms[0].text.find("#3101 is not in kerf's tables") != std::string::npos);
        CHECK(count_moves_on_line(r, 3) == 0);
    }
}
