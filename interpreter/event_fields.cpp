#include "interpreter/event_fields.hpp"

#include <array>

namespace kerf::interpreter {

bool is_motion(EventKind k) {
    return k == EventKind::rapid || k == EventKind::linear || k == EventKind::arc_cw || k == EventKind::arc_ccw ||
           k == EventKind::thread;
}

namespace {

bool always(const Event&) { return true; }
bool inch(const Event& e) { return e.inch; }
bool motion(const Event& e) { return is_motion(e.kind); }
bool cutting(const Event& e) { return is_motion(e.kind) && e.kind != EventKind::rapid; }
// The state after a block (RunOptions::emit_state): its F and S (`text` holds the modal codes,
// `tool` the tool and `code` its offset number).
bool state(const Event& e) { return e.kind == EventKind::state; }
// The lead at a thread's end differs from its start only in G34 (cycles.md §9).
bool variable_lead(const Event& e) { return e.kind == EventKind::thread && e.lead_end != e.feed; }
bool arc(const Event& e) { return e.center.has_value(); }
bool dwell(const Event& e) { return e.kind == EventKind::dwell; }
bool spindle(const Event& e) { return e.kind == EventKind::spindle; }
bool has_code(const Event& e) { return e.code != 0; }
bool has_text(const Event& e) { return !e.text.empty(); }
bool control_numbered(const Event& e) { return e.control_alarm != 0; }
// Alarm and call texts quote sequence numbers ("GOTO 10: no N10", "M98 Q20"), which renumbering
// changes on purpose; their codes and the events around them carry the meaning.
bool compared_text(const Event& e) { return has_text(e) && e.kind != EventKind::alarm && e.kind != EventKind::call; }

using M = EventMember;
using T = FieldType;

constexpr std::array kFields{
    EventField{"kind", M::kind, T::text, always, always},
    EventField{"file", M::file, T::text, always, nullptr},
    EventField{"line", M::line, T::integer, always, nullptr},
    EventField{"end", M::end, T::position, always, always},
    EventField{"units", M::units, T::text, inch, inch},
    EventField{"machine", M::machine, T::position, always, always},
    EventField{"start", M::start, T::position, motion, motion},
    EventField{"length_mm", M::length_mm, T::number, motion, motion},
    EventField{"time_s", M::time_s, T::number, motion, motion},
    EventField{"feed", M::feed, T::number, cutting, cutting},
    EventField{"lead_end", M::lead_end, T::number, variable_lead, variable_lead},
    EventField{"feed_per_rev", M::feed_per_rev, T::flag, cutting, cutting},
    EventField{"spindle_rpm", M::spindle_rpm, T::number, cutting, cutting},
    EventField{"spindle_running", M::spindle_running, T::flag, cutting, cutting},
    EventField{"center", M::center, T::position, arc, arc},
    EventField{"radius", M::radius, T::number, arc, arc},
    EventField{"time_s", M::time_s, T::number, dwell, dwell},
    EventField{"spindle_rpm", M::spindle_rpm, T::number, spindle, spindle},
    EventField{"feed", M::feed, T::number, state, state},
    EventField{"spindle_rpm", M::spindle_rpm, T::number, state, state},
    EventField{"tool", M::tool, T::integer, always, always},
    EventField{"code", M::code, T::integer, has_code, has_code},
    EventField{"control_alarm", M::control_alarm, T::integer, control_numbered, control_numbered},
    EventField{"text", M::text, T::text, has_text, compared_text},
};

}  // namespace

std::span<const EventField> event_fields() { return kFields; }

const Position& position_of(const Event& e, EventMember member) {
    switch (member) {
        case M::start: return e.start;
        case M::machine: return e.machine_end;
        case M::center: return *e.center;
        default: return e.end;
    }
}

double number_of(const Event& e, EventMember member) {
    switch (member) {
        case M::length_mm: return e.length_mm;
        case M::time_s: return e.time_s;
        case M::feed: return e.feed;
        case M::lead_end: return e.lead_end;
        case M::spindle_rpm: return e.spindle_rpm;
        default: return e.radius;
    }
}

long long integer_of(const Event& e, EventMember member) {
    switch (member) {
        case M::line: return e.source.line;
        case M::tool: return e.tool;
        case M::control_alarm: return e.control_alarm;
        default: return e.code;
    }
}

bool flag_of(const Event& e, EventMember member) {
    switch (member) {
        case M::units: return e.inch;
        case M::feed_per_rev: return e.feed_per_rev;
        default: return e.spindle_running;
    }
}

}  // namespace kerf::interpreter
