#include "interpreter/trace_json.hpp"

#include <boost/json.hpp>

namespace kerf::interpreter {

namespace json = boost::json;

namespace {
json::object position_json(const Position& p, std::string_view axes) {
    json::object o;
    for (std::size_t a = 0; a < kAxisCount; ++a)
        if (axes.find(kAxisLetters[a]) != std::string_view::npos) o[std::string(1, kAxisLetters[a])] = p[a];
    return o;
}
bool is_motion(EventKind k) {
    return k == EventKind::rapid || k == EventKind::linear || k == EventKind::arc_cw || k == EventKind::arc_ccw ||
           k == EventKind::thread;
}
}  // namespace

json::object event_to_json(const Event& e, const ProgramSet& programs, std::string_view axes) {
    json::object o{{"kind", to_string(e.kind)},
                   {"file", programs.file(e.source.file).name},
                   {"line", e.source.line},
                   {"end", position_json(e.end, axes)},
                   {"machine", position_json(e.machine_end, axes)}};
    if (is_motion(e.kind)) {
        o["start"] = position_json(e.start, axes);
        o["length_mm"] = e.length_mm;
        o["time_s"] = e.time_s;
        if (e.kind != EventKind::rapid) {
            o["feed"] = e.feed;
            o["feed_per_rev"] = e.feed_per_rev;
            o["spindle_rpm"] = e.spindle_rpm;
        }
    }
    if (e.center) {
        o["center"] = position_json(*e.center, axes);
        o["radius"] = e.radius;
    }
    if (e.kind == EventKind::dwell) o["time_s"] = e.time_s;
    if (e.kind == EventKind::spindle) o["spindle_rpm"] = e.spindle_rpm;
    o["tool"] = e.tool;
    if (e.code) o["code"] = e.code;
    if (!e.text.empty()) o["text"] = e.text;
    return o;
}

json::object summary_to_json(const RunResult& r, std::string_view axes) {
    json::array tools;
    for (const int t : r.tools) tools.push_back(t);
    json::object per_tool;
    for (const auto& [tool, seconds] : r.time_per_tool_s) per_tool[std::to_string(tool)] = seconds;
    json::array alarms;
    for (const Event& a : r.alarms) alarms.push_back(json::object{{"line", a.source.line}, {"code", a.code}, {"text", a.text}});
    return json::object{{"final_position", position_json(r.final_position, axes)},
                        {"total_time_s", r.total_time_s},
                        {"feed_distance_mm", r.feed_distance_mm},
                        {"rapid_distance_mm", r.rapid_distance_mm},
                        {"time_per_tool_s", std::move(per_tool)},
                        {"tools", std::move(tools)},
                        {"alarms", std::move(alarms)},
                        {"blocks", r.blocks},
                        {"completed", r.completed}};
}

}  // namespace kerf::interpreter
