// Running a program text through the interpreter in a test, and reading the events back: the
// helpers the per-feature interpreter tests share (tests/interpreter/test_*.cpp).
//
// Setups, from the barest up:
//   bare_setup   built by hand, no machine file: the Setup's defaults (zero work offsets, external
//                offset and reference points, no rapid rates, accelerations or limits), IS-B
//                increment, diameter X on lathes and the dialect's decimal-point rule; step limit
//                100 000.
//   plain_setup  bare_setup plus the G52 readings of the dialect's built-in machine (pcnc/ADV400:
//                G52 makes the current point take the values; semantics.md §2.4).
// A test that wants the built-in machine (interpreter::default_setup) or a machine configuration
// (interpreter::make_setup) builds that Setup itself and hands it to run_with.
//
// Assertions the helpers make (they count in Catch's totals): dialect() one REQUIRE, run_with one
// REQUIRE (the text has a program); run/run_bare make both.
#pragma once

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dialects/dialect.hpp"
#include "grammar/detect.hpp"
#include "interpreter/default_setup.hpp"
#include "interpreter/interpreter.hpp"
#include "tests/shared_files.hpp"

namespace kerf::test {

using interpreter::Event;
using interpreter::EventKind;
using interpreter::Setup;

// Indices into positions (interpreter::Position).
constexpr std::size_t X = 0, Y = 1, Z = 2;

// The built-in dialect `id`; REQUIREs that it exists.
inline const dialects::Dialect& dialect(const char* id) {
    const dialects::Dialect* d = dialects::builtin_registry().find(id);
    INFO(id);
    REQUIRE(d != nullptr);
    return *d;
}

// --- setups ------------------------------------------------------------------------------------------

inline Setup bare_setup(const dialects::Dialect& d) {
    Setup s;
    s.diameter_x = d.machine == dialects::MachineKind::lathe;
    s.calculator_decimal = d.lexical.calculator_decimal;   // fanuc-mill: X10 = 0.010 mm (IS-B)
    s.increment_mm = 0.001;
    s.step_limit = 100'000;
    return s;
}

inline Setup plain_setup(const dialects::Dialect& d) {
    Setup s = bare_setup(d);
    // The G52 reading is a machine switch resolved from the dialect (pcnc/ADV400: current point).
    const Setup from_machine = interpreter::default_setup(d);
    s.g52_current_point = from_machine.g52_current_point;
    s.g52_zeros_cancel = from_machine.g52_zeros_cancel;
    s.g54_cancels_g52 = from_machine.g54_cancels_g52;
    return s;
}

// --- runs ---------------------------------------------------------------------------------------------

struct Run {
    interpreter::RunResult result;
    std::vector<Event> events;
};

using SetupChange = std::function<void(Setup&)>;

// The first program of `text` (one file, "test.nc") under `d` with `setup`.
inline Run run_with(const std::string& text, const dialects::Dialect& d, const Setup& setup,
                    const interpreter::RunOptions& options = {}) {
    interpreter::ProgramSet programs;
    const auto file = programs.add("test.nc", text, d);
    interpreter::VectorSink sink;
    Run r;
    const auto main = programs.first_program(file);
    REQUIRE(main);
    r.result = interpreter::run(programs, *main, d, setup, sink, options);
    r.events = std::move(sink.events);
    return r;
}

// Under dialect `id` with its plain_setup, changed by `change`.
inline Run run(const std::string& text, const char* id, const SetupChange& change = {}) {
    const dialects::Dialect& d = dialect(id);
    Setup setup = plain_setup(d);
    if (change) change(setup);
    return run_with(text, d, setup);
}

// Under dialect `id` with its bare_setup, changed by `change`.
inline Run run_bare(const std::string& text, const char* id = "fanuc-mill", const SetupChange& change = {}) {
    const dialects::Dialect& d = dialect(id);
    Setup setup = bare_setup(d);
    if (change) change(setup);
    return run_with(text, d, setup);
}

// A file of ../shared (tests/shared_files.hpp) run as the sweeps run it: under the dialect detected
// from its text (REQUIREd: one assertion), on that dialect's built-in machine, step limit 200 000
// (M99 at the end of a main program loops until there). nullopt when the file holds no program.
struct SharedFileRun {
    const dialects::Dialect* dialect = nullptr;
    interpreter::ProgramSet programs;
    Setup setup;
    interpreter::RunResult result;
    std::vector<Event> events;
};

inline std::optional<SharedFileRun> run_shared_file(const std::filesystem::path& path,
                                                    const interpreter::RunOptions& options = {}) {
    const std::string text = read_text(path);
    SharedFileRun r;
    r.dialect = dialects::builtin_registry().find(grammar::detect_dialect(text).dialect);
    REQUIRE(r.dialect);
    const auto file = r.programs.add(path.string(), text, *r.dialect);
    const auto main = r.programs.first_program(file);
    if (!main) return std::nullopt;
    r.setup = interpreter::default_setup(*r.dialect);
    r.setup.step_limit = 200'000;
    interpreter::VectorSink sink;
    r.result = interpreter::run(r.programs, *main, *r.dialect, r.setup, sink, options);
    r.events = std::move(sink.events);
    return r;
}

// --- events -------------------------------------------------------------------------------------------

// Rapid, linear and circular moves (not threads).
inline bool is_move(EventKind k) {
    return k == EventKind::rapid || k == EventKind::linear || k == EventKind::arc_cw || k == EventKind::arc_ccw;
}

inline std::vector<Event> moves(const Run& r) {
    std::vector<Event> out;
    for (const Event& e : r.events)
        if (is_move(e.kind)) out.push_back(e);
    return out;
}

// The moves and the thread cuts (G32 and the threading cycles).
inline std::vector<Event> moves_with_threads(const Run& r) {
    std::vector<Event> out;
    for (const Event& e : r.events)
        if (is_move(e.kind) || e.kind == EventKind::thread) out.push_back(e);
    return out;
}

inline std::vector<Event> arcs(const Run& r) {
    std::vector<Event> out;
    for (const Event& e : r.events)
        if (e.kind == EventKind::arc_cw || e.kind == EventKind::arc_ccw) out.push_back(e);
    return out;
}

inline std::vector<Event> of_kind(const Run& r, EventKind kind) {
    std::vector<Event> out;
    for (const Event& e : r.events)
        if (e.kind == kind) out.push_back(e);
    return out;
}

inline std::size_t count(const Run& r, EventKind kind) {
    std::size_t n = 0;
    for (const Event& e : r.events) n += e.kind == kind;
    return n;
}

// The moves of source line `line` (1-based), and how many there are.
inline std::vector<Event> moves_on_line(const Run& r, std::uint32_t line) {
    std::vector<Event> out;
    for (const Event& e : moves(r))
        if (e.source.line == line) out.push_back(e);
    return out;
}

inline std::size_t count_moves_on_line(const Run& r, std::uint32_t line) { return moves_on_line(r, line).size(); }

// The X of the last move that ends at Z = tag (tags are unique per program), or nullopt.
inline std::optional<double> x_at(const Run& r, double tag) {
    std::optional<double> x;
    for (const Event& e : moves(r))
        if (std::fabs(e.end[Z] - tag) < 1e-9) x = e.end[X];
    return x;
}

// A point of a plane: X and the second axis (Y on mills, Z with check_path's `second`).
struct Pt {
    double x, y;
};

// The end points of the moves `m`, in order, to 0.001 (REQUIRE the count, two CHECKs a move).
inline void check_path(const std::vector<Event>& m, std::initializer_list<Pt> expected, std::size_t second = Y) {
    REQUIRE(m.size() == expected.size());
    std::size_t i = 0;
    for (const Pt& p : expected) {
        INFO("move " << i << " on line " << m[i].source.line << ": " << m[i].end[X] << " " << m[i].end[second]);
        CHECK(m[i].end[X] == Approx(p.x).margin(0.001));
        CHECK(m[i].end[second] == Approx(p.y).margin(0.001));
        ++i;
    }
}

// --- outcome ------------------------------------------------------------------------------------------

inline std::string alarm_list(const Run& r) {
    std::string s;
    for (const Event& a : r.result.alarms) s += "alarm " + std::to_string(a.code) + ": " + a.text + "\n";
    return s;
}

// A clean run: no alarm, reached its end (two CHECKs).
inline void require_clean(const Run& r) {
    INFO(alarm_list(r));
    CHECK(r.result.alarms.empty());
    CHECK(r.result.completed);
}

// Exactly one alarm, `number`, and the run stopped (REQUIRE, CHECK, CHECK_FALSE).
inline void require_alarm(const Run& r, int number) {
    INFO(alarm_list(r));
    REQUIRE(r.result.alarms.size() == 1);
    CHECK(r.result.alarms[0].code == number);
    CHECK_FALSE(r.result.completed);
}

}  // namespace kerf::test
