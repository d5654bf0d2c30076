// How a dry run starts (project/start.hpp, issue 12 "Programs that loop and programs with no
// caller"): a macro run as its caller's block calls it, variables set before the run, passes of a
// bar-feed loop, and the [run] call of a .kerf.toml that only runs the files holding its program.
#include <catch2/catch.hpp>

#include "interpreter/interpreter.hpp"
#include "interpreter/sink.hpp"
#include "project/config.hpp"
#include "project/start.hpp"

using namespace kerf;
using namespace kerf::project;


namespace {

const dialects::Dialect& mill() { return *dialects::builtin_registry().find("fanuc-mill"); }

// A macro that stops on its own argument guard when it is run alone (#1 vacant), and moves to
// X#1 Y#2 when it is called with A and B.
const char* kMacro = "O9010 (MOVE TO A B)\nIF [#1 EQ #0] THEN #3000=1 (A MISSING)\nG90 G0 X#1 Y#2\nM99\n";

struct Started {
    interpreter::RunResult result;
    std::vector<interpreter::Event> events;
    RunStart start;
};

Started run_started(const RunSettings& settings, const std::string& text) {
    interpreter::ProgramSet programs;
    const std::uint32_t file = programs.add("O9010.nc", text, mill());
    Started s;
    s.start = run_start(settings, programs, file, mill(), "O9010.nc");
    REQUIRE(s.start.main);
    interpreter::VectorSink sink;
    interpreter::Setup setup;
    s.result = interpreter::run(programs, *s.start.main, mill(), setup, sink, s.start.options);
    s.events = std::move(sink.events);
    return s;
}

std::vector<interpreter::Event> rapids(const Started& s) {
    std::vector<interpreter::Event> out;
    for (const auto& e : s.events)
        if (e.kind == interpreter::EventKind::rapid) out.push_back(e);
    return out;
}

}  // namespace

TEST_CASE("run start: a macro alone stops on its own guard; with its caller it runs") {
    const Started alone = run_started({}, kMacro);
    REQUIRE(alone.result.alarms.size() == 1);
    CHECK(alone.result.alarms[0].code == 3001);   // #3000=1: its own check, no caller
    RunSettings call;
    call.call = "G65 P9010 A12.5 B-4.";
    const Started called = run_started(call, kMacro);
    CHECK(called.start.called == 9010);
    CHECK(called.result.alarms.empty());
    CHECK(called.result.completed);
    CHECK_FALSE(called.result.repeats);   // the M99 returns to the caller, whose M30 ends the run
    REQUIRE(rapids(called).size() == 1);
    CHECK(rapids(called)[0].end[0] == Approx(12.5));
    CHECK(rapids(called)[0].end[1] == Approx(-4.0));
}

TEST_CASE("run start: a .kerf.toml call runs only the files that hold its program") {
    RunSettings call;
    call.call = "G65 P9999 A1.";   // another macro of the library
    const Started other = run_started(call, kMacro);
    CHECK_FALSE(other.start.called);
    CHECK(other.result.alarms.size() == 1);   // run alone: its guard
    call.call_everywhere = true;             // the command line's --call applies whatever the file
    const Started forced = run_started(call, kMacro);
    CHECK(forced.start.called == 9999);
    REQUIRE(forced.result.alarms.size() == 1);
    CHECK(forced.result.alarms[0].code == 78);   // O9999 is nowhere: alarm 078 at the caller's block
}

TEST_CASE("run start: --set and [run] set preset variables; --passes the bar-feed loop") {
    RunSettings settings;
    settings.set = {"#1=3.", "#2 = -1.5"};
    const Started preset = run_started(settings, kMacro);
    CHECK(preset.result.alarms.empty());
    REQUIRE(rapids(preset).size() == 1);
    CHECK(rapids(preset)[0].end[0] == Approx(3.0));
    CHECK(rapids(preset)[0].end[1] == Approx(-1.5));
    CHECK(preset.result.repeats);   // run as a main program, its M99 starts it again
    settings.passes = 2;
    const Started twice = run_started(settings, kMacro);
    CHECK(twice.result.passes == 2);
}

TEST_CASE("run start: a bad --set or --call is a problem, not a silent default") {
    RunSettings bad;
    bad.set = {"#100=[1/3]"};
    interpreter::ProgramSet programs;
    const std::uint32_t file = programs.add("a.nc", kMacro, mill());
    const RunStart s = run_start(bad, programs, file, mill(), "a.nc");
    REQUIRE(s.problems.size() == 1);
    CHECK(s.problems[0].message.find("#100=[1/3]") != std::string::npos);
    RunSettings no_call;
    no_call.call = "G0 X1.";
    const RunStart t = run_start(no_call, programs, file, mill(), "a.nc");
    REQUIRE(t.problems.size() == 1);
    CHECK(t.problems[0].message.find("calls a program") != std::string::npos);
}

TEST_CASE("parse_assignment reads a variable and a number") {
    CHECK(parse_assignment("#100=5") == std::pair<int, double>{100, 5.0});
    CHECK(parse_assignment(" #500 = -1.5 ") == std::pair<int, double>{500, -1.5});
    CHECK(parse_assignment("#1=.25") == std::pair<int, double>{1, 0.25});
    CHECK_FALSE(parse_assignment("#100"));
    CHECK_FALSE(parse_assignment("100=5"));
    CHECK_FALSE(parse_assignment("#0=5"));
    CHECK_FALSE(parse_assignment("#100=#101"));
    CHECK_FALSE(parse_assignment("#100=5x"));
}
