// A file read in pieces (interpreter/loaded_file.hpp) runs exactly as the whole file: the same
// events, with the same source ranges and lines, for every reference example and corpus file, and
// for programs that jump back and forth across pieces (labels, loops, calls into later programs).
#include <catch2/catch.hpp>

#include <filesystem>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "tests/interpreter/interpreter_fixture.hpp"
#include "tests/shared_files.hpp"
#include "interpreter/trace_compare.hpp"

namespace fs = std::filesystem;
using namespace kerf;

namespace {

struct Outcome {
    interpreter::RunResult result;
    std::vector<interpreter::Event> events;
    std::vector<std::pair<std::size_t, std::size_t>> released;
};

// Runs `text` whole (piece_bytes 0) or in pieces of `piece_bytes`, `held` pieces kept.
Outcome run_text(const std::string& text, const dialects::Dialect& d, std::size_t piece_bytes, std::size_t held,
                 bool start_at_reference = true, bool read_ahead = false) {
    Outcome out;
    std::mutex released_mutex;
    interpreter::ProgramSet programs;
    std::uint32_t file = 0;
    if (piece_bytes == 0) {
        file = programs.add("f.nc", text, d);
    } else {
        interpreter::StreamOptions options;
        options.piece_bytes = piece_bytes;
        options.pieces_held = held;
        options.read_ahead = read_ahead;
        // Called from the read-ahead thread too.
        options.release = [&out, &released_mutex](std::size_t b, std::size_t e) {
            std::lock_guard lock(released_mutex);
            out.released.emplace_back(b, e);
        };
        file = programs.add_stream("f.nc", text, d, options);
    }
    const auto main = programs.first_program(file);
    if (!main) return out;
    interpreter::Setup setup = interpreter::default_setup(d);
    setup.step_limit = 200'000;
    setup.start_at_reference = start_at_reference;
    interpreter::VectorSink sink;
    out.result = interpreter::run(programs, *main, d, setup, sink);
    out.events = std::move(sink.events);
    return out;
}

void check_same(const Outcome& whole, const Outcome& pieces) {
    CHECK(pieces.result.blocks == whole.result.blocks);
    CHECK(pieces.result.completed == whole.result.completed);
    REQUIRE(pieces.events.size() == whole.events.size());
    for (std::size_t i = 0; i < whole.events.size(); ++i) {
        const interpreter::Event& a = whole.events[i];
        const interpreter::Event& b = pieces.events[i];
        INFO("event " << i << " line " << a.source.line << ": " << a.text);
        REQUIRE(b.kind == a.kind);
        REQUIRE(b.source.line == a.source.line);
        REQUIRE(b.source.range.begin == a.source.range.begin);
        REQUIRE(b.source.range.end == a.source.range.end);
        // Every field of the trace (interpreter/event_fields.hpp), exactly; texts of alarms and calls too.
        const std::optional<std::string> difference =
            interpreter::compare_events(a, b, {interpreter::CompareProfile::everything, 0.0});
        INFO(difference.value_or(""));
        REQUIRE_FALSE(difference.has_value());
        REQUIRE(b.text == a.text);
    }
}

const dialects::Dialect& fanuc_mill() { return test::dialect("fanuc-mill"); }

}  // namespace

TEST_CASE("every reference example and corpus file runs the same whole and in pieces") {
    const std::vector<fs::path> files = test::shared_files_or_warn("the pieces sweep was not run");
    if (files.empty()) return;
    for (const fs::path& path : files) {
        const std::string text = test::read_text(path);
        const dialects::Dialect* d = dialects::builtin_registry().find(grammar::detect_dialect(text).dialect);
        REQUIRE(d);
        INFO(path.string());
        const Outcome whole = run_text(text, *d, 0, 0);
        // One line a piece with nothing else held (every jump re-reads), and odd piece sizes.
        for (const auto& [bytes, held] : {std::pair<std::size_t, std::size_t>{1, 0}, {97, 1}, {4096, 4}}) {
            INFO("piece_bytes " << bytes << " held " << held);
            check_same(whole, run_text(text, *d, bytes, held));
        }
        INFO("read ahead on a second thread, 97-byte pieces");
        check_same(whole, run_text(text, *d, 97, 1, true, true));
    }
}

TEST_CASE("jumps, loops and calls across pieces") {
    // A label behind (GOTO back), a WHILE loop, M98 to a program after the main one, M98 Q to a
    // label ahead, M99 P back to the caller's label: each crosses a piece boundary at 1 byte a piece.
    const std::string text =
        "%\n"
        "O0001\n"
        "#1=0\n"
        "N10 #1=#1+1\n"
        "G91 G01 X1. F100.\n"
        "IF [#1 LT 3] GOTO 10\n"
        "#2=0\n"
        "WHILE [#2 LT 2] DO 1\n"
        "G01 Y1.\n"
        "#2=#2+1\n"
        "END 1\n"
        "M98 P0002\n"
        "M98 P0003\n"
        "N20 G01 Z-1.\n"
        "M30\n"
        "O0002\n"
        "G01 X-1.\n"
        "M99\n"
        "O0003\n"
        "G01 Y-1.\n"
        "M99 P20\n"
        "%\n"
        "text after the tape end is not read\n";
    const Outcome whole = run_text(text, fanuc_mill(), 0, 0, false);
    CHECK(whole.result.completed);
    CHECK(whole.result.alarms.empty());
    // 3 X moves, 2 Y moves, the calls' X-1 and Y-1, then Z-1 after the return to N20: +1 −1 each way.
    REQUIRE(whole.result.completed);
    CHECK(whole.result.final_position[test::X] == Approx(2.0));
    CHECK(whole.result.final_position[test::Y] == Approx(1.0));
    for (const std::size_t held : {0, 1, 3}) {
        INFO("held " << held);
        const Outcome pieces = run_text(text, fanuc_mill(), 1, held, false);
        check_same(whole, pieces);
        check_same(whole, run_text(text, fanuc_mill(), 1, held, false, true));
        // The text of every piece read is offered for release, and never past the tape end.
        REQUIRE_FALSE(pieces.released.empty());
        for (const auto& [b, e] : pieces.released) CHECK(e <= text.find("text after"));
    }
}

TEST_CASE("a call to a program far ahead reads ahead to it, and an unknown one reads to the end") {
    std::string text = "O0001\nM98 P0009\nM98 P0007\nM30\n";
    for (int i = 0; i < 200; ++i) text += "(filler line " + std::to_string(i) + ")\n";
    text += "O0009\nG91 G01 X5. F100.\nM99\n";
    const Outcome pieces = run_text(text, fanuc_mill(), 64, 1, false);
    REQUIRE(pieces.result.alarms.size() == 1);
    CHECK(pieces.result.alarms[0].code == 78);   // O0007 not found (alarm 078)
    CHECK(pieces.result.final_position[test::X] == Approx(5.0));
    check_same(run_text(text, fanuc_mill(), 0, 0, false), pieces);
}
