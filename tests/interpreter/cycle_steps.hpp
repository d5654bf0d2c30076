// Expected cycle paths in tests: a list of (kind, X, Z) steps compared with the moves and thread
// cuts of one source line (tests/interpreter/test_cycles_*.cpp).
#pragma once

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <array>
#include <string>
#include <vector>

#include "tests/interpreter/interpreter_fixture.hpp"

namespace kerf::test {

struct Step {
    EventKind kind;
    double x;
    double z;
};

inline Step rapid(double x, double z) { return {EventKind::rapid, x, z}; }
inline Step feed(double x, double z) { return {EventKind::linear, x, z}; }
inline Step thread(double x, double z) { return {EventKind::thread, x, z}; }
inline Step cw(double x, double z) { return {EventKind::arc_cw, x, z}; }
inline Step ccw(double x, double z) { return {EventKind::arc_ccw, x, z}; }

// `program` with {0} the cycle's code in a G-code system, run under run_bare without alarms
// (REQUIREd): the cycle tests run one program in each system where the number differs.
inline Run run_clean(std::string_view program, const char* code, const char* dialect) {
    const Run r = run_bare(fmt::format(fmt::runtime(program), code), dialect);
    require_clean(r);
    return r;
}

inline std::string describe(const Event& e) {
    return fmt::format("{} X{:.4f} Z{:.4f}", interpreter::to_string(e.kind), e.end[X], e.end[Z]);
}

// The moves and threads of `line`, each to 0.001 mm, in order (one CHECK per step and the count).
inline void check_path(const Run& r, std::uint32_t line, const std::vector<Step>& want) {
    std::vector<Event> got;
    for (const Event& e : moves_with_threads(r))
        if (e.source.line == line) got.push_back(e);
    std::string listing;
    for (const Event& e : got) listing += describe(e) + "\n";
    INFO("moves of line " << line << ":\n" << listing);
    CHECK(got.size() == want.size());
    for (std::size_t i = 0; i < std::min(got.size(), want.size()); ++i) {
        INFO("step " << i << ": " << describe(got[i]));
        CHECK(got[i].kind == want[i].kind);
        CHECK(got[i].end[X] == Approx(want[i].x).margin(0.001));
        CHECK(got[i].end[Z] == Approx(want[i].z).margin(0.001));
    }
}

}  // namespace kerf::test

namespace kerf::test {

// Paths on three axes (mill X Y Z, live-tool lathe X Z C): (kind, a, b, c) against the axes
// `axes` of the events' end points, and the non-motion events in between ignored.
struct Step3 {
    EventKind kind;
    double a, b, c;
};
inline Step3 rapid3(double a, double b, double c) { return {EventKind::rapid, a, b, c}; }
inline Step3 feed3(double a, double b, double c) { return {EventKind::linear, a, b, c}; }

inline void check_path3(const Run& r, std::uint32_t line, std::array<std::size_t, 3> axes, const std::vector<Step3>& want) {
    std::vector<Event> got;
    for (const Event& e : moves(r))
        if (e.source.line == line) got.push_back(e);
    std::string listing;
    for (const Event& e : got)
        listing += fmt::format("{} {:.4f} {:.4f} {:.4f}\n", interpreter::to_string(e.kind), e.end[axes[0]], e.end[axes[1]],
                               e.end[axes[2]]);
    INFO("moves of line " << line << ":\n" << listing);
    CHECK(got.size() == want.size());
    for (std::size_t i = 0; i < std::min(got.size(), want.size()); ++i) {
        INFO("step " << i);
        CHECK(got[i].kind == want[i].kind);
        CHECK(got[i].end[axes[0]] == Approx(want[i].a).margin(0.001));
        CHECK(got[i].end[axes[1]] == Approx(want[i].b).margin(0.001));
        CHECK(got[i].end[axes[2]] == Approx(want[i].c).margin(0.001));
    }
}

}  // namespace kerf::test
