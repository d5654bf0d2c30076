#include "interpreter/trace_json.hpp"

#include <fmt/format.h>

#include <boost/json.hpp>
#include <cmath>
#include <iterator>

namespace kerf::interpreter {

namespace json = boost::json;

namespace {

// Numbers are written shortest-exact after snapping to 1e-9, so 150 prints as 150 and a rotated
// 6.1e-16 as 0 (a trace reader compares to 1e-9 anyway, docs/trace.md).
double snap(double v) {
    const double s = std::round(v * 1e9) / 1e9;
    return s == 0 ? 0.0 : s;   // no "-0"
}

bool is_motion(EventKind k) {
    return k == EventKind::rapid || k == EventKind::linear || k == EventKind::arc_cw || k == EventKind::arc_ccw ||
           k == EventKind::thread;
}

using Out = std::back_insert_iterator<std::string>;

void write_string(Out out, std::string_view s) {
    *out++ = '"';
    for (const char c : s) {
        switch (c) {
            case '"': fmt::format_to(out, "\\\""); break;
            case '\\': fmt::format_to(out, "\\\\"); break;
            case '\n': fmt::format_to(out, "\\n"); break;
            case '\r': fmt::format_to(out, "\\r"); break;
            case '\t': fmt::format_to(out, "\\t"); break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) fmt::format_to(out, "\\u{:04x}", static_cast<int>(c));
                else *out++ = c;
        }
    }
    *out++ = '"';
}

void write_position(Out out, std::string_view key, const Position& p, std::string_view axes) {
    fmt::format_to(out, ",\"{}\":{{", key);
    bool first = true;
    for (std::size_t a = 0; a < kAxisCount; ++a) {
        if (axes.find(kAxisLetters[a]) == std::string_view::npos) continue;
        fmt::format_to(out, "{}\"{}\":{}", first ? "" : ",", kAxisLetters[a], snap(p[a]));
        first = false;
    }
    *out++ = '}';
}

}  // namespace

void append_event_json(std::string& line, const Event& e, const ProgramSet& programs, std::string_view axes) {
    Out out(line);
    fmt::format_to(out, "{{\"kind\":\"{}\",\"file\":", to_string(e.kind));
    write_string(out, programs.file(e.source.file).name);
    fmt::format_to(out, ",\"line\":{}", e.source.line);
    write_position(out, "end", e.end, axes);
    write_position(out, "machine", e.machine_end, axes);
    if (is_motion(e.kind)) {
        write_position(out, "start", e.start, axes);
        fmt::format_to(out, ",\"length_mm\":{},\"time_s\":{}", snap(e.length_mm), snap(e.time_s));
        if (e.kind != EventKind::rapid)
            fmt::format_to(out, ",\"feed\":{},\"feed_per_rev\":{},\"spindle_rpm\":{},\"spindle_running\":{}", snap(e.feed),
                           e.feed_per_rev, snap(e.spindle_rpm), e.spindle_running);
    }
    if (e.center) {
        write_position(out, "center", *e.center, axes);
        fmt::format_to(out, ",\"radius\":{}", snap(e.radius));
    }
    if (e.kind == EventKind::dwell) fmt::format_to(out, ",\"time_s\":{}", snap(e.time_s));
    if (e.kind == EventKind::spindle) fmt::format_to(out, ",\"spindle_rpm\":{}", snap(e.spindle_rpm));
    fmt::format_to(out, ",\"tool\":{}", e.tool);
    if (e.code) fmt::format_to(out, ",\"code\":{}", e.code);
    if (!e.text.empty()) {
        fmt::format_to(out, ",\"text\":");
        write_string(out, e.text);
    }
    *out++ = '}';
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
    for (const Event& a : r.alarms) alarms.push_back(json::object{{"line", a.source.line}, {"code", a.code}, {"text", a.text}});
    return json::object{{"final_position", position_json(r.final_position, axes)},
                        {"total_time_s", snap(r.total_time_s)},
                        {"feed_distance_mm", snap(r.feed_distance_mm)},
                        {"rapid_distance_mm", snap(r.rapid_distance_mm)},
                        {"time_per_tool_s", std::move(per_tool)},
                        {"tools", std::move(tools)},
                        {"alarms", std::move(alarms)},
                        {"blocks", r.blocks},
                        {"completed", r.completed}};
}

}  // namespace kerf::interpreter
