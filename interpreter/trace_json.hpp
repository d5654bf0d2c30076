// The trace as JSON lines and the run summary as JSON (docs/trace.md). Text in, text out: the
// caller writes it where it wants.
#pragma once

#include <fmt/format.h>

#include <boost/json/value.hpp>
#include <string>
#include <vector>

#include "interpreter/interpreter.hpp"

namespace kerf::interpreter {

// One JSON object per event: kind, file, line, end (axis letter → number, work coordinates, lathe X
// as diameter), and per kind: start, center, radius, length_mm, time_s, feed, tool, code, text.
//
// The writer of `kerf run --trace`: millions of lines, so what is the same for every line (the
// quoted file names, the axes of the machine) is prepared once, and numbers take a fast path.
class TraceWriter {
public:
    TraceWriter(const ProgramSet& programs, std::string_view axes);
    // Appends the event as one line of JSON text (no newline).
    void append(fmt::memory_buffer& line, const Event& e);

private:
    void write_position(fmt::memory_buffer& out, std::string_view key, const Position& p) const;
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
