// Where the interpreter's events go. The interpreter never prints; a sink decides.
#pragma once

#include <vector>

#include "interpreter/events.hpp"

namespace kerf::interpreter {

class EventSink {
public:
    virtual ~EventSink() = default;
    virtual void on_event(const Event& event) = 0;
};

// Keeps every event (tests, small programs, the plot).
class VectorSink : public EventSink {
public:
    void on_event(const Event& event) override { events.push_back(event); }
    std::vector<Event> events;
};

}  // namespace kerf::interpreter
