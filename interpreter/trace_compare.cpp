#include "interpreter/trace_compare.hpp"

#include "interpreter/event_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <tuple>
#include <vector>

namespace kerf::interpreter {

namespace {

bool near_relative(double a, double b, double tolerance) {
    if (a == b) return true;   // also equal infinities
    return std::fabs(a - b) <= tolerance * std::max(1.0, std::max(std::fabs(a), std::fabs(b)));
}

bool near(double a, double b, const CompareOptions& o) {
    if (o.profile == CompareProfile::everything) return near_relative(a, b, o.tolerance);
    return a == b || std::fabs(a - b) <= o.tolerance;
}

std::optional<std::string> compare_position(std::string_view what, const Position& a, const Position& b,
                                            const CompareOptions& o) {
    for (std::size_t i = 0; i < kAxisCount; ++i)
        if (!near(a[i], b[i], o)) return fmt::format("{} {}: {} vs {}", what, kAxisLetters[i], a[i], b[i]);
    return std::nullopt;
}

// The step-limit alarm (interpreter/run_guard.hpp) ends an endless program wherever the count of
// blocks runs out, and formatting or conversion changes that count (blank and comment lines are
// blocks); the time limit ends a run wherever the clock runs out: two runs are compared up to the
// first alarm of a run bound (kerf's own numbers, interpreter/events.hpp kerf_alarm, docs/trace.md).
bool is_run_limit(const Event& e) { return e.kind == EventKind::alarm && kerf_alarm::is_run_limit(e.code); }

std::optional<std::string> compare_field(const EventField& f, const Event& a, const Event& b, const CompareOptions& o) {
    switch (f.type) {
        case FieldType::position: return compare_position(f.key, position_of(a, f.member), position_of(b, f.member), o);
        case FieldType::number: {
            const double x = number_of(a, f.member), y = number_of(b, f.member);
            if (!near(x, y, o)) return fmt::format("{}: {} vs {}", f.key, x, y);
            return std::nullopt;
        }
        case FieldType::integer: {
            const long long x = integer_of(a, f.member), y = integer_of(b, f.member);
            if (x != y) return fmt::format("{}: {} vs {}", f.key, x, y);
            return std::nullopt;
        }
        case FieldType::flag:
            if (flag_of(a, f.member) != flag_of(b, f.member)) return fmt::format("{}: {} vs {}", f.key, flag_of(a, f.member), flag_of(b, f.member));
            return std::nullopt;
        case FieldType::text:
            if (f.member == EventMember::text && a.text != b.text) return fmt::format("text: '{}' vs '{}'", a.text, b.text);
            return std::nullopt;   // kind: compared before; units: a flag of its own (inch)
    }
    return std::nullopt;
}

// Every field of the trace that --verify compares (event_fields(): what the trace shows is what is
// compared, lead_end of a G34 thread included).
std::optional<std::string> compare_everything(const Event& a, const Event& b, const CompareOptions& o) {
    for (const EventField& f : event_fields()) {
        if (!f.compared) continue;
        const bool in_a = f.compared(a), in_b = f.compared(b);
        if (in_a != in_b) return fmt::format("{}: {} vs {}", f.key, in_a ? "present" : "absent", in_b ? "present" : "absent");
        if (!in_a) continue;
        if (auto d = compare_field(f, a, b, o)) return d;
    }
    return std::nullopt;
}

// issue 16: kind, end, centre, feed and feed mode, dwell time, machine position, alarms.
std::optional<std::string> compare_motion(const Event& a, const Event& b, const CompareOptions& o) {
    if (a.kind == EventKind::alarm) {
        if (a.code != b.code) return fmt::format("alarm: {} vs {}", a.code, b.code);
        return std::nullopt;
    }
    if (a.kind == EventKind::dwell) {
        if (!near_relative(a.time_s, b.time_s, 1e-6)) return fmt::format("dwell time: {} s vs {} s", a.time_s, b.time_s);
        return std::nullopt;
    }
    if (a.center.has_value() != b.center.has_value()) return std::string("one arc has a centre, the other not");
    for (const auto& [what, x, y] : {std::tuple{"end", &a.end, &b.end}, std::tuple{"machine end", &a.machine_end, &b.machine_end}})
        if (auto d = compare_position(what, *x, *y, o)) return d;
    if (a.center)
        if (auto d = compare_position("centre", *a.center, *b.center, o)) return d;
    if (a.feed_per_rev != b.feed_per_rev)
        return fmt::format("feed mode: {} vs {}", a.feed_per_rev ? "per revolution" : "per minute",
                           b.feed_per_rev ? "per revolution" : "per minute");
    // A rapid's F is the modal feed, which a rapid does not use.
    if (a.kind != EventKind::rapid && !near_relative(a.feed, b.feed, 1e-6)) return fmt::format("feed: {} vs {}", a.feed, b.feed);
    return std::nullopt;
}

// The input's events, handed from its run (on a thread of its own) to the output's run in batches,
// so that memory stays bounded however long the trace is.
class Channel {
public:
    using Batch = std::vector<Event>;
    void push(Batch batch) {
        std::unique_lock lock(mutex_);
        space_.wait(lock, [&] { return queue_.size() < kMaxBatches; });
        queue_.push_back(std::move(batch));
        ready_.notify_one();
    }
    void close() {
        std::lock_guard lock(mutex_);
        closed_ = true;
        ready_.notify_one();
    }
    // The next batch; empty once the producer has closed the channel and everything is taken.
    Batch pop() {
        std::unique_lock lock(mutex_);
        ready_.wait(lock, [&] { return !queue_.empty() || closed_; });
        if (queue_.empty()) return {};
        Batch b = std::move(queue_.front());
        queue_.pop_front();
        space_.notify_one();
        return b;
    }

private:
    static constexpr std::size_t kMaxBatches = 16;
    std::mutex mutex_;
    std::condition_variable ready_, space_;
    std::deque<Batch> queue_;
    bool closed_ = false;
};

class ProducingSink : public EventSink {
public:
    ProducingSink(Channel& channel, CompareProfile profile) : channel_(channel), profile_(profile) {}
    void on_event(const Event& e) override {
        if (!compared_kind(e.kind, profile_)) return;
        batch_.push_back(e);
        if (batch_.size() == kBatch) flush();
    }
    void flush() {
        if (!batch_.empty()) channel_.push(std::move(batch_));
        batch_ = {};
    }

private:
    static constexpr std::size_t kBatch = 1024;
    Channel& channel_;
    CompareProfile profile_;
    std::vector<Event> batch_;
};

// Compares the output's events with the input's as they come.
class ComparingSink : public EventSink {
public:
    ComparingSink(Channel& channel, const CompareOptions& options) : channel_(channel), options_(options) {}
    void on_event(const Event& e) override {
        if (!compared_kind(e.kind, options_.profile)) return;
        const std::size_t i = count_++;
        const Event* expected = next();
        if (difference_ || stopped_) return;
        if (!expected) {
            difference_ = TraceDifference{i, 0, e.source.line, "the output has more events than the input", {}, {}, 0, e.source.file};
            return;
        }
        if (is_run_limit(e) || is_run_limit(*expected)) {
            stopped_ = true;
            return;
        }
        if (auto what = compare_events(*expected, e, options_))
            difference_ = TraceDifference{i, expected->source.line, e.source.line, *what, {}, {}, expected->source.file, e.source.file};
        else if (e.kind == EventKind::alarm)
            stopped_at_ = *expected;   // an alarm ends the run: both stop here
    }
    // After the output's run: the input's events it did not match.
    void finish() {
        const std::size_t matched = count_;
        while (const Event* expected = next()) {
            if (!difference_ && !stopped_ && !is_run_limit(*expected))
                difference_ = TraceDifference{matched, expected->source.line, 0, "the output has fewer events than the input", {}, {},
                                              expected->source.file, 0};
        }
    }
    std::size_t expected_count() const { return taken_; }
    std::optional<TraceDifference>& difference() { return difference_; }
    std::optional<Event>& stopped_at() { return stopped_at_; }

private:
    Channel& channel_;
    const CompareOptions& options_;
    Channel::Batch batch_;
    std::size_t at_ = 0;
    std::size_t count_ = 0;
    std::size_t taken_ = 0;
    bool drained_ = false;
    bool stopped_ = false;   // a run bound was reached: the rest is not compared
    std::optional<TraceDifference> difference_;
    std::optional<Event> stopped_at_;

    const Event* next() {
        if (at_ == batch_.size() && !drained_) {
            batch_ = channel_.pop();
            at_ = 0;
            drained_ = batch_.empty();
        }
        if (at_ == batch_.size()) return nullptr;
        ++taken_;
        return &batch_[at_++];
    }
};

struct Run {
    ProgramSet programs;
    std::optional<ProgramRef> main;
};

// The first event of a run that the comparison looks at.
class FirstComparedEvent : public EventSink {
public:
    explicit FirstComparedEvent(CompareProfile profile) : profile_(profile) {}
    void on_event(const Event& e) override {
        if (!first && compared_kind(e.kind, profile_)) first = e;
    }
    std::optional<Event> first;

private:
    CompareProfile profile_;
};

// A text of blanks and line breaks only runs nothing: the empty text "" splits into one empty
// program while "\n\n" splits into none, and formatting turns the second into the first
// (blank_lines = 0; found by fuzz_formatter, fuzz/regressions/formatter/).
bool only_blanks(std::string_view text) {
    return std::all_of(text.begin(), text.end(), [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; });
}

void load(Run& run, TraceSide& side) {
    const bool blank = only_blanks(side.text);
    const std::uint32_t file = run.programs.add(side.name, std::move(side.text), *side.dialect);
    if (side.loader) run.programs.set_loader(side.loader, side.dialect);
    if (!blank) run.main = run.programs.first_program(file);
}

}  // namespace

bool compared_kind(EventKind kind, CompareProfile profile) {
    if (profile == CompareProfile::everything) return true;
    return is_motion(kind) || kind == EventKind::dwell || kind == EventKind::alarm;
}

std::optional<std::string> compare_events(const Event& a, const Event& b, const CompareOptions& o) {
    if (a.kind != b.kind) return fmt::format("kind: {} vs {}", to_string(a.kind), to_string(b.kind));
    return o.profile == CompareProfile::everything ? compare_everything(a, b, o) : compare_motion(a, b, o);
}

TraceComparison compare_runs(TraceSide input, TraceSide output, const CompareOptions& options, const RunOptions& run_options) {
    TraceComparison result;
    Run before, after;
    const dialects::Dialect& input_dialect = *input.dialect;
    const dialects::Dialect& output_dialect = *output.dialect;
    load(before, input);
    load(after, output);
    if (before.main.has_value() != after.main.has_value()) {
        // No program runs nothing: the other side must run nothing either (a program of comments and
        // an N word whose N the formatter removed is no program any more: fuzz_formatter).
        Run& ran = before.main ? before : after;
        const TraceSide& side = before.main ? input : output;
        FirstComparedEvent sink(options.profile);
        interpreter::run(ran.programs, *ran.main, *side.dialect, side.setup, sink, run_options);
        const std::optional<Event>& first = sink.first;
        if (first)
            result.difference = TraceDifference{0,
                                                before.main ? first->source.line : 0,
                                                before.main ? 0 : first->source.line,
                                                before.main ? "the output has no program" : "the input has no program",
                                                {}, {}, 0, 0};
        return result;
    }
    if (!before.main) return result;   // nothing runs in either
    Channel channel;
    std::thread input_run([&] {
        ProducingSink sink(channel, options.profile);
        interpreter::run(before.programs, *before.main, input_dialect, input.setup, sink, run_options);
        sink.flush();
        channel.close();
    });
    ComparingSink actual(channel, options);
    interpreter::run(after.programs, *after.main, output_dialect, output.setup, actual, run_options);
    actual.finish();
    input_run.join();
    result.events = actual.expected_count();
    result.difference = std::move(actual.difference());
    if (!result.difference) result.stopped_at = std::move(actual.stopped_at());
    // Both runs are over: the file tables no longer grow.
    if (result.difference) {
        TraceDifference& d = *result.difference;
        if (d.input_file_index < before.programs.file_count()) d.input_file = before.programs.file(d.input_file_index).name();
        if (d.output_file_index < after.programs.file_count()) d.output_file = after.programs.file(d.output_file_index).name();
    }
    return result;
}

}  // namespace kerf::interpreter
