// Tool words per dialect and lathe tool offsets, G20/G21 switching, DPRNT formatting and the
// numbers of the JSON trace. Expected numbers are worked out by hand next to each check.
#include <catch2/catch.hpp>

#include "interpreter/trace_json.hpp"
#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf::test;
using kerf::interpreter::Position;

TEST_CASE("fanuc-mill: T selects a tool number, M06 changes it (tool_word = number)") {
    const Run r = run("O1\nT101\nG0 X10.\nM06\nG0 X20.\nM30\n", "fanuc-mill");
    require_clean(r);
    const auto changes = of_kind(r, EventKind::tool_change);
    REQUIRE(changes.size() == 1);
    CHECK(changes[0].source.line == 4);   // at M06, not at T101
    CHECK(changes[0].tool == 101);        // T101 is tool 101, not tool 1 offset 1
    CHECK(r.result.tools == std::vector<int>{101});
}

TEST_CASE("lathe: T0101 applies offset 1 to the machine position at once; T0100 cancels it") {
    // Offset 1: geometry X-100 (diameter) Z-50, wear X0.2 Z0.1 → machine = work + (-99.8, -49.9).
    const Run r = run("O1\nT0101\nG0 X50. Z10.\nT0100\nG0 X60.\nM30\n", "fanuc-lathe-a", [](Setup& s) {
        kerf::interpreter::ToolOffset t;
        t.geometry[X] = -100;
        t.geometry[Z] = -50;
        t.wear[X] = 0.2;
        t.wear[Z] = 0.1;
        s.tools[1] = t;
    });
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 2);
    CHECK(m[0].end[X] == Approx(50));              // work coordinates are as programmed
    CHECK(m[0].machine_end[X] == Approx(50 - 99.8));
    CHECK(m[0].machine_end[Z] == Approx(10 - 49.9));
    CHECK(m[1].machine_end[X] == Approx(60));      // T0100: no offset
    CHECK(m[1].machine_end[Z] == Approx(10));
    const auto changes = of_kind(r, EventKind::tool_change);
    REQUIRE(changes.size() == 1);                  // T0100 keeps station 1: no second change
    CHECK(changes[0].tool == 1);
    CHECK(changes[0].code == 1);                   // the offset number
}

TEST_CASE("G20/G21: the same place is read in the new unit; lengths and machine positions stay metric") {
    // G21 X25.4 is 1 inch; after G20 the tool reads X1. G0 Y1. moves 1 inch = 25.4 mm.
    const Run r = run_bare("O1\nG21 G90 G0 X25.4 Y0\nG20\nG0 Y1.\nG21\nG0 Z5.\nM30\n");
    require_clean(r);
    const auto m = moves(r);
    REQUIRE(m.size() == 3);
    CHECK(m[1].start[X] == Approx(1));
    CHECK(m[1].end[Y] == Approx(1));
    CHECK(m[1].machine_end[X] == Approx(25.4));
    CHECK(m[1].machine_end[Y] == Approx(25.4));
    CHECK(m[1].length_mm == Approx(25.4));
    CHECK(m[2].start[Y] == Approx(25.4));   // back in mm
    CHECK(m[2].end[Z] == Approx(5));
}

TEST_CASE("DPRNT prints #n[ab] with b decimals, * as a space, and drops blanks") {
    const Run r = run_bare("O1\n#1=1.5\n#2=-2.25\nDPRNT[X#1[53]*Y#2[30] Z#3[31]]\nM30\n");
    require_clean(r);
    const auto messages = of_kind(r, EventKind::message);
    REQUIRE(messages.size() == 1);
    // #1 = 1.5 with 3 decimals; #2 = -2.25 with 0 decimals is -2; #3 vacant
    // prints as 0 with 1 decimal; the blank before Z is not printed.
    CHECK(messages[0].text == "X1.500 Y-2Z0.0");
}

// fuzz_formatter (UBSan, signed overflow): a variable number of thirteen digits in DPRNT is no
// variable; it prints as a vacant one, 0.
TEST_CASE("DPRNT with a variable number past every variable prints 0 and does not overflow") {
    const Run r = run_bare("O1\nDPRNT[A#2025555555555[31]]\nM30\n");
    require_clean(r);
    const auto messages = of_kind(r, EventKind::message);
    REQUIRE(messages.size() == 1);
    CHECK(messages[0].text == "A0.0");
}

TEST_CASE("trace JSON: numbers shortest, snapped to 1e-9, only the given axes") {
    kerf::interpreter::ProgramSet programs;
    programs.add("t.nc", "O1\nM30\n", dialect("fanuc-mill"));
    Event e;
    e.kind = EventKind::rapid;
    e.source.line = 7;
    e.end = Position{6.123233995736766e-16, -1.0156, 150, 0, 0, 0};   // a rotated 0, and exact values
    std::string line;
    kerf::interpreter::append_event_json(line, e, programs, "XYZ");
    CHECK(line.find(R"("end":{"X":0,"Y":-1.0156,"Z":150})") != std::string::npos);
    CHECK(line.find("\"A\"") == std::string::npos);
    CHECK(line.find("\"line\":7") != std::string::npos);
    CHECK(line.find("e-") == std::string::npos);
    CHECK(line.front() == '{');
    CHECK(line.back() == '}');
}
