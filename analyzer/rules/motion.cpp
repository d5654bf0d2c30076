// Dynamic motion rules: they read the events of the dry run (docs/trace.md), so moves inside
// subprograms, macros and (once expanded) cycles are checked as they actually run.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "analyzer/analyze.hpp"
#include "analyzer/rules/common.hpp"
#include "dialects/alarms.hpp"

namespace kerf::analyzer::rules {

namespace {

using S = Severity;
using interpreter::Event;
using interpreter::EventKind;

bool is_feed_move(const Event& e) {
    return e.kind == EventKind::linear || e.kind == EventKind::arc_cw || e.kind == EventKind::arc_ccw;
}

ast::Range where(const RunContext& run, const Event& e) {
    return trim_range(*run.programs.file(e.source.file).whole_tree(), e.source.range);
}

// Reports the first event that `bad` accepts, once per run (one cause, usually many moves).
template <class Bad, class Say>
class FirstOnly : public DynamicCheck {
public:
    void event(const RunContext& run, const Event& e, Reporter& out) override {
        if (done_ || e.source.file != run.checked_file || !Bad{}(run, e)) return;
        done_ = true;
        const auto [message, hint] = Say{}(e);
        out.report(where(run, e), message, hint);
    }

private:
    bool done_ = false;
};

struct SpindleStopped {
    bool operator()(const RunContext&, const Event& e) const {
        return (is_feed_move(e) || e.kind == EventKind::thread) && e.feed_per_rev && !e.spindle_running && e.length_mm > 0;
    }
};
struct SpindleStoppedSay {
    std::pair<std::string, std::string> operator()(const Event& e) const {
        return {fmt::format("feed per revolution (F{:g}) with the spindle stopped: the axes wait forever", e.feed),
                "start the spindle (M03/M04) before the cut, or feed per minute for a stopped spindle"};
    }
};

struct PerRevHigh {
    bool operator()(const RunContext&, const Event& e) const { return is_feed_move(e) && e.feed_per_rev && e.feed > 2.0; }
};
struct PerRevHighSay {
    std::pair<std::string, std::string> operator()(const Event& e) const {
        return {fmt::format("F{:g} per revolution is a feed per minute value: the tool would feed {:g} per spindle turn", e.feed,
                            e.feed),
                "switch to feed per minute (G98/G94) first, or write the feed per revolution"};
    }
};

struct PerMinLow {
    bool operator()(const RunContext&, const Event& e) const {
        return is_feed_move(e) && !e.feed_per_rev && e.feed > 0 && e.feed < 1.0 && e.length_mm > 0;
    }
};
struct PerMinLowSay {
    std::pair<std::string, std::string> operator()(const Event& e) const {
        return {fmt::format("F{:g} per minute is a feed per revolution value: the cut crawls", e.feed),
                "switch to feed per revolution (G99/G95) first, or write the feed per minute"};
    }
};

// A feed move of axes that carry no cutting tool (the machine's `carries_tool = false`: the lathe
// tailstock / sub-spindle carriage B of G138 and G38, cycles.md §12, §16) cuts nothing.
bool moves_a_tool(const interpreter::Setup& setup, const Event& e) {
    for (std::size_t a = 0; a < interpreter::kAxisCount; ++a)
        if (setup.carries_tool[a] && std::abs(e.end[a] - e.start[a]) > 1e-9) return true;
    return false;
}

struct NoTool {
    bool operator()(const RunContext& run, const Event& e) const {
        return is_feed_move(e) && e.tool == 0 && e.length_mm > 0 && moves_a_tool(run.setup, e);
    }
};
struct NoToolSay {
    std::pair<std::string, std::string> operator()(const Event&) const {
        return {"feed move with no tool selected (T0 or no T word before it)", "select the tool before the first cut"};
    }
};

struct NoSpeed {
    bool operator()(const RunContext&, const Event& e) const {
        // A spindle event says whether it starts (M03/M04) or stops the spindle (events.hpp).
        return e.kind == EventKind::spindle && e.spindle_running && e.spindle_rpm <= 0;
    }
};
struct NoSpeedSay {
    std::pair<std::string, std::string> operator()(const Event&) const {
        return {"spindle started with no speed (no S word before it)", "program S with or before M03/M04"};
    }
};

// Thread lead × rpm is the Z feed: it must stay within what the axis can do (semantics.md §4.1,
// SPINNER: lead × rpm ≤ 4000; here the machine's Z rapid rate is the limit).
class ThreadTooFast : public DynamicCheck {
public:
    void event(const RunContext& run, const Event& e, Reporter& out) override {
        if (e.kind != EventKind::thread || e.source.file != run.checked_file) return;
        const double limit = run.setup.rapid_mm_min[static_cast<std::size_t>(interpreter::Axis::z)];
        const double speed = e.feed * e.spindle_rpm;
        if (limit <= 0 || speed <= limit) return;
        out.report(where(run, e),
                   fmt::format("thread lead {:g} × {:g} rpm = {:g} mm/min, over the Z axis limit of {:g} mm/min", e.feed,
                               e.spindle_rpm, speed, limit),
                   "lower the spindle speed for the thread");
    }
};

// Mills: a rapid that moves across the part at a depth where the program cut before. Feed moves
// before a tool goes down (G1 X Y at the change height after a tool change, 1006.nc N5895, or at
// the clearance height after a retract, N5670) cut nothing; a sideways rapid of at most 1 mm is a
// boring bar backing off the wall inside its bore (O0051 'G00 Y-.025 (BACK OFF SIDE OF BORE)'); a
// rapid back to a point where the tool plunged since it last went down, no deeper than it cut
// there, returns through its own pocket (O0057 N2102 'G00X1.4248Y-1.6769' after each pass, for
// the next step down). Not a move across the part (issue 15).
class RapidIntoCut : public DynamicCheck {
public:
    void event(const RunContext& run, const Event& e, Reporter& out) override {
        if (run.dialect.machine != dialects::MachineKind::mill) return;
        constexpr std::size_t z = 2;
        const bool down = e.end[z] < e.start[z] - kEps, up = e.end[z] > e.start[z] + kEps;
        if (e.kind == EventKind::tool_change || (e.kind == EventKind::rapid && up)) {
            approached_ = false;   // retracted: the next cut starts a new descent
            plunges_.clear();
            floor_ = 1e300;
            if (e.kind == EventKind::tool_change) return;
        }
        if (is_feed_move(e)) {
            if (approached_ || down) {
                whole_.add(e);
                floor_ = std::min(floor_, std::min(e.start[z], e.end[z]));
            }
            if (down && plunges_.size() < kMaxPlunges) plunges_.push_back({e.start[0], e.start[1]});
            approached_ = approached_ || down;
            return;
        }
        if (e.kind != EventKind::rapid) return;
        approached_ = approached_ || down;
        if (e.source.file != run.checked_file || reported_) return;
        const double level = std::max(e.start[z], e.end[z]);
        if (sideways(e) * mm_per_unit(e) <= kBackOffMm || !whole_.inside(e.end) || level > whole_.level + kEps) return;
        if (level >= floor_ - kEps && returns_to_plunge(e)) return;
        reported_ = true;
        out.report(where(run, e),
                   std::abs(level - whole_.level) <= kEps
                       ? fmt::format("rapid move across the part at Z{:g}, the depth where the program cut", e.end[z])
                       : fmt::format("rapid move across the part at Z{:g}, below the level Z{:g} where the program cut", e.end[z],
                                     whole_.level),
                   "retract Z above the part before the rapid move");
    }

private:
    static constexpr double kBackOffMm = 1.0, kEps = 1e-6;
    // A descent plunges at a handful of points (one per step down); more than this and the rapid is
    // judged by the whole cut alone (the bound on what the rule keeps per run).
    static constexpr std::size_t kMaxPlunges = 64;
    // Where feed moves cut: the box of their ends and the highest of their lowest points (`level`:
    // below it the program has cut somewhere).
    struct Area {
        double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
        double level = -1e300;
        void add(const Event& e) {
            constexpr std::size_t x = 0, y = 1, z = 2;
            level = std::max(level, std::min(e.start[z], e.end[z]));
            for (const auto& p : {e.start, e.end}) {
                lo_x = std::min(lo_x, p[x]), hi_x = std::max(hi_x, p[x]);
                lo_y = std::min(lo_y, p[y]), hi_y = std::max(hi_y, p[y]);
            }
        }
        bool inside(const interpreter::Position& p) const { return p[0] > lo_x && p[0] < hi_x && p[1] > lo_y && p[1] < hi_y; }
    };
    // The rapid ends (in X/Y, within 0.01 mm) where a feed move of this descent went down.
    bool returns_to_plunge(const Event& e) const {
        const double tolerance = 0.01 / mm_per_unit(e);
        return std::any_of(plunges_.begin(), plunges_.end(), [&](const std::array<double, 2>& p) {
            return std::hypot(e.end[0] - p[0], e.end[1] - p[1]) <= tolerance;
        });
    }
    static double sideways(const Event& e) { return std::hypot(e.end[0] - e.start[0], e.end[1] - e.start[1]); }
    // Positions are in program units (inch under G20): the move's length in mm over its length.
    static double mm_per_unit(const Event& e) {
        const double programmed = std::hypot(e.end[0] - e.start[0], e.end[1] - e.start[1], e.end[2] - e.start[2]);
        return programmed > 1e-9 && e.length_mm > 0 ? e.length_mm / programmed : 1.0;
    }
    Area whole_;                                  // every cut of the run
    std::vector<std::array<double, 2>> plunges_;   // X/Y where feed moves went down since the last retract
    double floor_ = 1e300;                         // the lowest point cut since the last retract
    bool reported_ = false;
    bool approached_ = false;   // the tool went down since the last tool change or retract (or the start)
};

// The interpreter says which codes it could not expand yet (cycles, compensation): those parts
// of the program are not checked by the dynamic rules.
class NotExpanded : public DynamicCheck {
public:
    void event(const RunContext& run, const Event& e, Reporter& out) override {
        if (e.kind != EventKind::message || e.source.file != run.checked_file) return;
        if (e.code != interpreter::kerf_warning::not_modelled) return;   // interpreter/events.hpp
        out.report(where(run, e), e.text, "the dry run does not check this motion yet");
    }
};

}  // namespace

void add_motion(Registry& r) {
    const auto rule = rule_maker(Category::motion);
    // The dry run raises alarm 011 itself (interpreter/executor_motion.cpp feed_commanded): `kerf run`
    // and `kerf check` report the same alarm at the same block.
    r.add(alarm_rule("K5001", "feed-move-without-feed", Category::motion, S::error, {{alarms::feed_zero, alarms::feed_zero}},
        {"A G01/G02/G03 move runs with no feed rate.", "The control stops with alarm 011 (feed rate zero).",
         "G01 X10.", "G01 X10. F0.2", "semantics.md §4"}));
    r.add(dynamic_rule<FirstOnly<SpindleStopped, SpindleStoppedSay>>(rule("K5002", "feed-with-spindle-stopped", S::warning,
        {"A move with feed per revolution while the spindle is stopped.",
         "The axes wait for spindle revolutions that never come: the program hangs, or the tool rubs when the spindle starts.",
         "M05\nG99 G01 Z-5. F0.2", "M03 S800\nG99 G01 Z-5. F0.2", "semantics.md §4"})));
    r.add(dynamic_rule<ThreadTooFast>(rule("K5003", "thread-lead-too-fast", S::error,
        {"Thread lead × spindle rpm is faster than the Z axis can feed.",
         "The thread is cut wrong (lead error) or the control alarms.", "G97 S3000\nG32 Z-20. F2.", "G97 S1000\nG32 Z-20. F2.",
         "semantics.md §4.1"})));
    r.add(dynamic_rule<FirstOnly<PerRevHigh, PerRevHighSay>>(rule("K5005", "feed-per-rev-too-high", S::warning,
        {"A feed per revolution above 2 per turn: most likely a feed per minute value in G99/G95 mode.",
         "F100 in G99 asks for 100 mm per spindle turn: the axis runs at its limit into the part.",
         "G99 G01 Z-5. F100.", "G98 G01 Z-5. F100.", "semantics.md §4"})));
    r.add(dynamic_rule<FirstOnly<PerMinLow, PerMinLowSay>>(rule("K5006", "feed-per-min-too-low", S::warning,
        {"A feed per minute below 1 per minute: most likely a feed per revolution value in G98/G94 mode.",
         "F0.2 in G98 is 0.2 mm/min: the cut takes hours and the tool rubs.", "G98 G01 Z-5. F0.2", "G99 G01 Z-5. F0.2",
         "semantics.md §4"})));
    r.add(dynamic_rule<RapidIntoCut>(rule("K5007", "rapid-at-cut-depth", S::warning,
        {"A rapid move across the part at or below a depth where the program cut before (mills).",
         "G00 at cutting depth crosses material: a crash.", "G01 Z-5. F100.\nG00 X50.", "G01 Z-5. F100.\nG00 Z5.\nX50.",
         "semantics.md §2; gcode-tables.md §5 G00"})));
    r.add(dynamic_rule<FirstOnly<NoTool, NoToolSay>>(rule("K5008", "cut-without-tool", S::warning,
        {"A feed move before any tool is selected.", "The control cuts with whatever tool is in the spindle or turret.",
         "G01 X10. F0.2", "T0101\nG01 X10. F0.2", "dialects.md §3.5"})));
    r.add(opt_in(with_alarms(dynamic_rule<NotExpanded>(rule("K5009", "not-checked-by-dry-run", S::info,
        {"A block whose motion the dry run does not model (a code the reference leaves open, such as seed 004's G44 "
         "without H, or a cycle no part of kerf expands), so its motion is not checked; or a system variable kerf's "
         "tables do not have, where the dry run stops (kerf's alarm 90006).",
         "Nothing on the machine: a note about kerf's coverage (opt-in).", "G44 X10. Y5.", "G43 H1 Z10.",
         "docs/trace.md"})), {{alarms::unknown_variable, alarms::unknown_variable}})));
    r.add(dynamic_rule<FirstOnly<NoSpeed, NoSpeedSay>>(rule("K5010", "spindle-without-speed", S::warning,
        {"M03/M04 with no spindle speed programmed.", "The spindle does not turn (S0) and the first cut breaks the tool.",
         "M03\nG01 X10. F0.2", "S800 M03\nG01 X10. F0.2", "semantics.md §4.1"})));
}

}  // namespace kerf::analyzer::rules
