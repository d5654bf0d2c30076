// The trace writer's number fast path (interpreter/trace_json.cpp put_number) writes exactly what
// fmt's "{}" writes for the snapped value, on values across every range the fast path touches
// and its borders: the trace text must not depend on which path wrote a number.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>
#include <random>
#include <string>

#include "interpreter/trace_json.hpp"
#include "tests/interpreter/interpreter_fixture.hpp"

using namespace kerf;

namespace {

double snapped(double v) {
    if (!(std::fabs(v) < 1e15)) return v;
    const double s = std::round(v * 1e9) / 1e9;
    return s == 0 ? 0.0 : s;
}

// The text of end.X in the event's JSON line.
std::string written(interpreter::TraceWriter& writer, double x) {
    interpreter::Event e;
    e.kind = interpreter::EventKind::message;
    e.end[0] = x;
    fmt::memory_buffer line;
    writer.append(line, e);
    const std::string text(line.data(), line.size());
    const std::string key = "\"end\":{\"X\":";
    const std::size_t begin = text.find(key) + key.size();
    return text.substr(begin, text.find('}', begin) - begin);
}

}  // namespace

TEST_CASE("trace numbers are written as fmt writes the snapped value") {
    interpreter::ProgramSet programs;
    programs.add("f.nc", "O1\n", test::dialect("fanuc-mill"));
    interpreter::TraceWriter writer(programs, "X");
    const double fixed[] = {0, -0.0, 1, -1, 0.5, 150, 123.456, -0.001, 1e-4, 9.99999e-5, 0.0001234, 999999.999999999,
                            1e6, 1e6 - 1e-9, 12345.678901234, 1e-9, 4e-10, 6e-10, 1e15, 1e16, 1.5e300, 0.1 + 0.2,
                            2.0 / 3.0, -123456.000000001, 100000, 7.25e-3};
    for (const double v : fixed) {
        INFO(v);
        CHECK(written(writer, v) == fmt::format("{}", snapped(v)));
    }
    // JSON has no infinity or NaN: a value past the doubles (the length of a move between 1e193 mm
    // words) is null, and a huge finite value is not snapped into an infinity.
    CHECK(written(writer, INFINITY) == "null");
    CHECK(written(writer, -INFINITY) == "null");
    CHECK(written(writer, NAN) == "null");
    CHECK(written(writer, 1.5e300) == "1.5e+300");
    CHECK(written(writer, -4.2e193) == "-4.2e+193");
    std::mt19937_64 random(20261121);
    for (const double scale : {1e-5, 1e-3, 1.0, 1e3, 1e5, 1e7}) {
        std::uniform_real_distribution<double> value(-scale, scale);
        for (int i = 0; i < 20000; ++i) {
            const double v = value(random);
            const double rounded = std::round(v * 1000) / 1000;   // CAM-like: three decimals
            INFO(v);
            REQUIRE(written(writer, v) == fmt::format("{}", snapped(v)));
            REQUIRE(written(writer, rounded) == fmt::format("{}", snapped(rounded)));
        }
    }
}
