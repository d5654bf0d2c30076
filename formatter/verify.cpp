#include "formatter/verify.hpp"

#include <algorithm>
#include <fmt/format.h>

#include <cmath>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

namespace kerf::formatter {

namespace {

using interpreter::Event;
using interpreter::EventKind;

constexpr double kTolerance = 1e-9;

bool near(double a, double b) {
    if (a == b) return true;   // also equal infinities
    return std::fabs(a - b) <= kTolerance * std::max(1.0, std::max(std::fabs(a), std::fabs(b)));
}

std::optional<std::string> compare_number(std::string_view what, double a, double b) {
    if (near(a, b)) return std::nullopt;
    return fmt::format("{}: {} vs {}", what, a, b);
}

std::optional<std::string> compare_position(std::string_view what, const interpreter::Position& a,
                                            const interpreter::Position& b) {
    for (std::size_t i = 0; i < interpreter::kAxisCount; ++i)
        if (!near(a[i], b[i])) return fmt::format("{} {}: {} vs {}", what, interpreter::kAxisLetters[i], a[i], b[i]);
    return std::nullopt;
}

// Alarm texts and call texts quote sequence numbers ("GOTO 10: no N10", "M98 Q20"), which
// renumbering changes on purpose; their codes and the events around them carry the meaning.
bool compares_text(EventKind k) { return k != EventKind::alarm && k != EventKind::call; }

// The step-limit alarm (interpreter/run_guard.hpp) ends an endless program wherever the count of
// blocks runs out, and formatting changes that count (blank and comment lines are blocks); the
// time limit ends a run wherever the clock runs out: two runs are compared up to the first alarm
// of a run bound (kerf's own numbers, interpreter/events.hpp kerf_alarm, docs/trace.md).
bool is_run_limit(const Event& e) {
    return e.kind == EventKind::alarm && interpreter::kerf_alarm::is_run_limit(e.code);
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

class ProducingSink : public interpreter::EventSink {
public:
    explicit ProducingSink(Channel& channel) : channel_(channel) {}
    void on_event(const Event& e) override {
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
    std::vector<Event> batch_;
};

// Compares the output's events with the input's as they come.
class ComparingSink : public interpreter::EventSink {
public:
    explicit ComparingSink(Channel& channel) : channel_(channel) {}
    void on_event(const Event& e) override {
        const std::size_t i = count_++;
        const Event* expected = next();
        if (difference_ || stopped_) return;
        if (!expected) {
            difference_ = Difference{i, 0, e.source.line, "the output has more events than the input"};
            return;
        }
        if (is_run_limit(e) || is_run_limit(*expected)) {
            stopped_ = true;
            return;
        }
        if (auto what = compare_events(*expected, e)) difference_ = Difference{i, expected->source.line, e.source.line, *what};
    }
    // After the output's run: the input's events it did not match.
    void finish() {
        const std::size_t matched = count_;
        while (const Event* expected = next()) {
            if (!difference_ && !stopped_ && !is_run_limit(*expected))
                difference_ = Difference{matched, expected->source.line, 0, "the output has fewer events than the input"};
        }
    }
    std::size_t expected_count() const { return taken_; }
    std::optional<Difference>& difference() { return difference_; }

private:
    Channel& channel_;
    Channel::Batch batch_;
    std::size_t at_ = 0;
    std::size_t count_ = 0;
    std::size_t taken_ = 0;
    bool drained_ = false;
    bool stopped_ = false;   // a run bound was reached: the rest is not compared
    std::optional<Difference> difference_;

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
    interpreter::ProgramSet programs;
    std::optional<interpreter::ProgramRef> main;
};

// A text of blanks and line breaks only runs nothing: the empty text "" splits into one empty
// program while "\n\n" splits into none, and formatting turns the second into the first
// (blank_lines = 0; found by fuzz_formatter, fuzz/regressions/formatter/).
bool only_blanks(std::string_view text) {
    return std::all_of(text.begin(), text.end(), [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; });
}

void load(Run& run, const std::string& name, std::string text, const VerifyOptions& o) {
    const bool blank = only_blanks(text);
    const std::uint32_t file = run.programs.add(name, std::move(text), *o.dialect);
    if (o.loader) run.programs.set_loader(o.loader, o.dialect);
    if (!blank) run.main = run.programs.first_program(file);
}

}  // namespace

std::optional<std::string> compare_events(const Event& a, const Event& b) {
    if (a.kind != b.kind) return fmt::format("kind: {} vs {}", interpreter::to_string(a.kind), interpreter::to_string(b.kind));
    if (a.code != b.code) return fmt::format("code: {} vs {}", a.code, b.code);
    if (a.tool != b.tool) return fmt::format("tool: {} vs {}", a.tool, b.tool);
    if (a.feed_per_rev != b.feed_per_rev || a.spindle_running != b.spindle_running) return std::string("feed mode or spindle state");
    if (compares_text(a.kind) && a.text != b.text) return fmt::format("text: '{}' vs '{}'", a.text, b.text);
    if (a.center.has_value() != b.center.has_value()) return std::string("one arc has a centre, the other not");
    for (const auto& [what, x, y] : {std::tuple{"start", &a.start, &b.start}, std::tuple{"end", &a.end, &b.end},
                                      std::tuple{"machine end", &a.machine_end, &b.machine_end}})
        if (auto d = compare_position(what, *x, *y)) return d;
    if (a.center)
        if (auto d = compare_position("centre", *a.center, *b.center)) return d;
    for (const auto& [what, x, y] : {std::tuple{"radius", a.radius, b.radius}, std::tuple{"length", a.length_mm, b.length_mm},
                                      std::tuple{"time", a.time_s, b.time_s}, std::tuple{"feed", a.feed, b.feed},
                                      std::tuple{"spindle rpm", a.spindle_rpm, b.spindle_rpm}})
        if (auto d = compare_number(what, x, y)) return d;
    return std::nullopt;
}

VerifyResult verify(const std::string& name, std::string input, std::string output, const VerifyOptions& o) {
    VerifyResult result;
    Run before, after;
    load(before, name, std::move(input), o);
    load(after, name, std::move(output), o);
    if (before.main.has_value() != after.main.has_value()) {
        result.difference = Difference{0, 0, 0, before.main ? "the output has no program" : "the input has no program"};
        return result;
    }
    if (!before.main) return result;   // nothing runs in either
    Channel channel;
    std::thread input_run([&] {
        ProducingSink sink(channel);
        interpreter::run(before.programs, *before.main, *o.dialect, o.setup, sink, o.run);
        sink.flush();
        channel.close();
    });
    ComparingSink actual(channel);
    interpreter::run(after.programs, *after.main, *o.dialect, o.setup, actual, o.run);
    actual.finish();
    input_run.join();
    result.events = actual.expected_count();
    result.difference = std::move(actual.difference());
    return result;
}

}  // namespace kerf::formatter
