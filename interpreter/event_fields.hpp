// The one list of an event's fields (issue 13): what the trace JSON writes, in its order, for
// which events, and which fields `kerf fmt --verify` compares. The trace writer
// (trace_json.cpp), the comparison (trace_compare.cpp), the streamed-run test, the trace's JSON
// schema (docs/trace.schema.json) and the table of docs/trace.md all follow it, and a test holds
// the schema, the docs and the golden renderer to it: a field added here is written, compared and
// documented, or a test says which of them is missing.
#pragma once

#include <span>
#include <string_view>

#include "interpreter/events.hpp"

namespace kerf::interpreter {

// Which member of Event a field shows (a key may be written at two places of the line for two
// kinds of events: `time_s` of a motion after its length, of a dwell after the centre).
enum class EventMember : std::uint8_t {
    kind, file, line, end, units, machine, start, length_mm, time_s, feed, lead_end, feed_per_rev,
    spindle_rpm, spindle_running, center, radius, tool, code, control_alarm, text,
};

// How a field's value is written: a position is an object of the machine's axis letters.
enum class FieldType : std::uint8_t { position, number, integer, flag, text };

struct EventField {
    std::string_view key;               // the JSON key (docs/trace.md)
    EventMember member;
    FieldType type;
    bool (*written)(const Event&);      // whether the trace has the field for this event
    // Whether `kerf fmt --verify` (CompareProfile::everything) compares it for this event; null:
    // never (file and line move when a program is formatted).
    bool (*compared)(const Event&);
};

// Every field in the order of the trace's JSON line.
std::span<const EventField> event_fields();

bool is_motion(EventKind kind);

// A field's value (the member's type must match: positions for position fields, and so on).
const Position& position_of(const Event& e, EventMember member);   // a center field only when written
double number_of(const Event& e, EventMember member);
long long integer_of(const Event& e, EventMember member);           // line, tool, code, control_alarm
bool flag_of(const Event& e, EventMember member);                   // units (inch), feed_per_rev, spindle_running

}  // namespace kerf::interpreter
