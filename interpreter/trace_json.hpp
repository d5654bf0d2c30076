// The trace as JSON lines and the run summary as JSON (docs/trace.md). Text in, text out: the
// caller writes it where it wants.
#pragma once

#include <fmt/format.h>

#include <boost/json/value.hpp>
#include <string>
#include <vector>

#include "interpreter/event_fields.hpp"
#include "interpreter/interpreter.hpp"

namespace kerf::interpreter {

// One JSON object per event: the fields of event_fields() that the event has, in that order (kind,
// file, line, end as axis letter → number in work coordinates with lathe X as diameter, ...).
//
// The writer of `kerf run --trace`: millions of lines, so what is the same for every line (the
// quoted file names, the axes of the machine) is prepared once, and numbers take a fast path.
class TraceWriter {
public:
    TraceWriter(const ProgramSet& programs, std::string_view axes);
    // Appends the event as one line of JSON text (no newline).
    void append(fmt::memory_buffer& line, const Event& e);

private:
    void write_position(fmt::memory_buffer& out, const Position& p) const;
    void write_value(fmt::memory_buffer& out, const EventField& field, const Event& e) const;
    const ProgramSet& programs_;
    std::vector<std::size_t> axes_;          // indices into kAxisLetters, in order
    std::vector<std::string> quoted_names_;  // per file of `programs_`, grown as files are loaded
};

// The same for one event (tests, the language server): a writer made for the call.
void append_event_json(fmt::memory_buffer& line, const Event& e, const ProgramSet& programs, std::string_view axes);
void append_event_json(std::string& line, const Event& e, const ProgramSet& programs, std::string_view axes);
// The same as a JSON object (parsed from that text, so both always agree).
boost::json::object event_to_json(const Event& e, const ProgramSet& programs, std::string_view axes);
boost::json::object summary_to_json(const RunResult& r, std::string_view axes);

}  // namespace kerf::interpreter
