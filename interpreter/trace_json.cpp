#include "interpreter/trace_json.hpp"

#include "ast/display.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <boost/json.hpp>
#include <cmath>
#include <cstdint>
#include <iterator>

namespace kerf::interpreter {

namespace json = boost::json;

namespace {

// Numbers are written shortest-exact after snapping to 1e-9, so 150 prints as 150 and a rotated
// 6.1e-16 as 0 (a trace reader compares to 1e-9 anyway, docs/trace.md).
// From 1e15 on a double has no digit at 1e-9 to snap, and v * 1e9 would overflow past 1.8e299
// (a 300-digit word made "inf", which is no JSON: fuzz_interpreter).
double snap(double v) {
    if (!(std::fabs(v) < 1e15)) return v;
    const double s = std::round(v * 1e9) / 1e9;
    return s == 0 ? 0.0 : s;   // no "-0"
}

// Written into an fmt::memory_buffer with literal pieces appended directly: the trace of a
// 100 MB program is millions of lines, and a format string per piece costs more than the numbers.
using Buffer = fmt::memory_buffer;

void put(Buffer& out, std::string_view text) { out.append(text.data(), text.data() + text.size()); }

void put_int(Buffer& out, long long v) { fmt::format_to(std::back_inserter(out), FMT_COMPILE("{}"), v); }

// The shortest text of snap(v), as fmt's "{}" writes it. Fast path: 1e-4 <= |v| < 1e6, where fmt
// writes fixed notation and the value is m / 1e9 for an integer m; at most 6 + 9 significant
// digits, so the decimal digits of m (trailing zeros dropped) are the shortest text that reads
// back as the same double (any decimal of 15 digits or fewer round-trips, DBL_DIG). Elsewhere fmt.
void put_number(Buffer& out, double v) {
    const double s = snap(v);
    const double a = std::fabs(s);
    if (!std::isfinite(s)) {
        // JSON has no infinity: the length of a move between 1e193-mm words overflows (fuzz_interpreter).
        put(out, "null");
        return;
    }
    if (s == 0) {
        out.push_back('0');
        return;
    }
    if (!(a >= 1e-4 && a < 1e6)) {
        fmt::format_to(std::back_inserter(out), FMT_COMPILE("{}"), s);
        return;
    }
    const std::int64_t m = std::llround(a * 1e9);
    const std::int64_t whole = m / 1'000'000'000;
    std::int64_t fraction = m % 1'000'000'000;
    if (s < 0) out.push_back('-');
    put_int(out, whole);
    if (fraction == 0) return;
    char digits[9];
    for (int i = 8; i >= 0; --i) {
        digits[i] = static_cast<char>('0' + fraction % 10);
        fraction /= 10;
    }
    int length = 9;
    while (digits[length - 1] == '0') --length;
    out.push_back('.');
    out.append(digits, digits + length);
}

void write_string(Buffer& out, std::string_view s) {
    // A message may quote the program's own bytes (#3006, DPRNT, comments in CP1251): JSON text
    // must be UTF-8, so bytes outside a valid sequence become U+FFFD (ast/display.hpp).
    std::string repaired;
    if (!ast::is_valid_utf8(s)) {
        repaired = ast::valid_utf8(s);
        s = repaired;
    }
    out.push_back('"');
    for (const char c : s) {
        switch (c) {
            case '"': put(out, "\\\""); break;
            case '\\': put(out, "\\\\"); break;
            case '\n': put(out, "\\n"); break;
            case '\r': put(out, "\\r"); break;
            case '\t': put(out, "\\t"); break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) fmt::format_to(std::back_inserter(out), "\\u{:04x}", static_cast<int>(c));
                else out.push_back(c);
        }
    }
    out.push_back('"');
}

}  // namespace

TraceWriter::TraceWriter(const ProgramSet& programs, std::string_view axes) : programs_(programs) {
    for (std::size_t a = 0; a < kAxisCount; ++a)
        if (axes.find(kAxisLetters[a]) != std::string_view::npos) axes_.push_back(a);
}

void TraceWriter::write_position(Buffer& out, const Position& p) const {
    out.push_back('{');
    bool first = true;
    for (const std::size_t a : axes_) {
        if (!first) out.push_back(',');
        out.push_back('"');
        out.push_back(kAxisLetters[a]);
        put(out, "\":");
        put_number(out, p[a]);
        first = false;
    }
    out.push_back('}');
}

void TraceWriter::write_value(Buffer& out, const EventField& field, const Event& e) const {
    switch (field.member) {
        case EventMember::kind:
            out.push_back('"');
            put(out, to_string(e.kind));
            out.push_back('"');
            return;
        case EventMember::file: put(out, quoted_names_[e.source.file]); return;
        case EventMember::units: put(out, "\"inch\""); return;   // absent: mm
        case EventMember::text: write_string(out, e.text); return;
        default: break;
    }
    switch (field.type) {
        case FieldType::position: write_position(out, position_of(e, field.member)); return;
        case FieldType::number: put_number(out, number_of(e, field.member)); return;
        case FieldType::integer: put_int(out, integer_of(e, field.member)); return;
        case FieldType::flag: put(out, flag_of(e, field.member) ? "true" : "false"); return;
        case FieldType::text: return;
    }
}

void TraceWriter::append(fmt::memory_buffer& out, const Event& e) {
    // Files join the set while the run goes on (subprograms from the folder).
    while (quoted_names_.size() < programs_.file_count()) {
        Buffer quoted;
        write_string(quoted, programs_.file(static_cast<std::uint32_t>(quoted_names_.size())).name());
        quoted_names_.emplace_back(quoted.data(), quoted.size());
    }
    out.push_back('{');
    bool first = true;
    for (const EventField& field : event_fields()) {
        if (!field.written(e)) continue;
        if (!first) out.push_back(',');
        first = false;
        out.push_back('"');
        put(out, field.key);
        put(out, "\":");
        write_value(out, field, e);
    }
    out.push_back('}');
}

void append_event_json(fmt::memory_buffer& out, const Event& e, const ProgramSet& programs, std::string_view axes) {
    TraceWriter(programs, axes).append(out, e);
}

void append_event_json(std::string& line, const Event& e, const ProgramSet& programs, std::string_view axes) {
    fmt::memory_buffer buffer;
    append_event_json(buffer, e, programs, axes);
    line.append(buffer.data(), buffer.size());
}

json::object event_to_json(const Event& e, const ProgramSet& programs, std::string_view axes) {
    std::string line;
    append_event_json(line, e, programs, axes);
    return json::parse(line).as_object();
}

namespace {
json::object position_json(const Position& p, std::string_view axes) {
    json::object o;
    for (std::size_t a = 0; a < kAxisCount; ++a)
        if (axes.find(kAxisLetters[a]) != std::string_view::npos) {
            const double v = snap(p[a]);
            if (v == std::round(v) && std::fabs(v) < 1e15) o[std::string(1, kAxisLetters[a])] = static_cast<std::int64_t>(v);
            else o[std::string(1, kAxisLetters[a])] = v;
        }
    return o;
}
}  // namespace

json::object summary_to_json(const RunResult& r, std::string_view axes) {
    json::array tools;
    for (const int t : r.tools) tools.push_back(t);
    json::object per_tool;
    for (const auto& [tool, seconds] : r.time_per_tool_s) per_tool[std::to_string(tool)] = snap(seconds);
    json::array alarms;
    for (const Event& a : r.alarms) {
        json::object alarm{{"line", a.source.line}, {"code", a.code}, {"text", a.text}};
        if (a.control_alarm != 0) alarm["control_alarm"] = a.control_alarm;   // the control numbers it itself ([alarms])
        alarms.push_back(std::move(alarm));
    }
    return json::object{{"final_position", position_json(r.final_position, axes)},
                        {"total_time_s", snap(r.total_time_s)},
                        {"feed_distance_mm", snap(r.feed_distance_mm)},
                        {"rapid_distance_mm", snap(r.rapid_distance_mm)},
                        {"time_per_tool_s", std::move(per_tool)},
                        {"tools", std::move(tools)},
                        {"alarms", std::move(alarms)},
                        {"blocks", r.blocks},
                        {"completed", r.completed},
                        {"repeats", r.repeats},
                        {"passes", r.passes},
                        {"units", r.inch ? "inch" : "mm"}};
}

}  // namespace kerf::interpreter
