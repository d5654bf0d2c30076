#include "interpreter/executor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dialects/functions.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

std::optional<Axis> axis_of_letter(char letter) {
    for (std::size_t i = 0; i < kAxisCount; ++i)
        if (kAxisLetters[i] == letter) return static_cast<Axis>(i);
    return std::nullopt;
}

const char* to_string(EventKind k) {
    switch (k) {
        case EventKind::rapid: return "rapid";
        case EventKind::linear: return "linear";
        case EventKind::arc_cw: return "arc_cw";
        case EventKind::arc_ccw: return "arc_ccw";
        case EventKind::thread: return "thread";
        case EventKind::dwell: return "dwell";
        case EventKind::tool_change: return "tool_change";
        case EventKind::spindle: return "spindle";
        case EventKind::coolant: return "coolant";
        case EventKind::coordinate_change: return "coordinate_change";
        case EventKind::feed_mode: return "feed_mode";
        case EventKind::stop: return "stop";
        case EventKind::optional_stop: return "optional_stop";
        case EventKind::end: return "end";
        case EventKind::alarm: return "alarm";
        case EventKind::message: return "message";
        case EventKind::call: return "call";
        case EventKind::return_: return "return";
    }
    return "?";
}

Executor::Executor(ProgramSet& programs, const dialects::Dialect& dialect, const Setup& setup, EventSink& sink,
                   const RunOptions& options)
    : programs_(programs), dialect_(dialect), setup_(setup), sink_(sink), options_(options) {
    // Power-on state: the codes marked as defaults in the dialect table (semantics.md §1.3).
    for (const dialects::CodeInfo& c : dialect_.codes())
        if (c.letter == 'G' && c.power_on_default && c.group != "00") modal_[c.group] = &c;
}

const ast::Program& Executor::program_of(const Frame& f) const {
    return file_of(f).typed->programs()[f.program.program];
}

SourceRef Executor::source(const Frame& f, const ast::BlockView& view) const {
    const ast::Range r = view.range();
    return {f.program.file, r, file_of(f).lines->utf8(r.begin).line + 1};
}

bool Executor::has_function(const ast::BlockView& view, std::string_view function) const {
    for (const ast::CodeRef& c : view.g_codes())
        if (c.info && c.info->function == function) return true;
    for (const ast::CodeRef& c : view.m_codes())
        if (c.info && c.info->function == function) return true;
    return false;
}

std::string_view Executor::modal_function(const std::string& group) const {
    const auto it = modal_.find(group);
    return it == modal_.end() || !it->second ? std::string_view() : std::string_view(it->second->function);
}

Event Executor::event_at(EventKind kind, const Frame& f, const ast::BlockView& view) const {
    Event e;
    e.kind = kind;
    e.source = source(f, view);
    e.start = e.end = position_;
    return e;
}

void Executor::emit(Event e) {
    e.tool = e.kind == EventKind::tool_change ? e.tool : tool_;
    const Position offset = machine_offset();
    for (std::size_t a = 0; a < kAxisCount; ++a) e.machine_end[a] = e.end[a] + offset[a];
    if (e.kind == EventKind::alarm) result_.alarms.push_back(e);
    result_.total_time_s += e.time_s;
    if (e.time_s > 0) result_.time_per_tool_s[tool_] += e.time_s;
    sink_.on_event(e);
}

void Executor::alarm(const Frame& f, const ast::BlockView& view, int number, std::string text) {
    Event e = event_at(EventKind::alarm, f, view);
    e.code = number;
    e.text = std::move(text);
    emit(std::move(e));
    stopped_ = true;
}

void Executor::pop_frame() {
    if (frames_.back().macro) variables_.pop_level();   // a G65 call's locals end with it
    frames_.pop_back();
}

void Executor::change_offsets(const std::function<void()>& change) {
    // The tool does not move when an offset changes: its work coordinates do (semantics.md §2.7).
    const Position before = machine_offset();
    change();
    const Position after = machine_offset();
    for (std::size_t a = 0; a < kAxisCount; ++a) position_[a] += before[a] - after[a];
}

// --- the loop ------------------------------------------------------------------------------------

RunResult Executor::run(ProgramRef main) {
    Frame first;
    first.program = main;
    first.block = program_of(first).first_block;
    frames_.push_back(first);
    while (!frames_.empty() && !stopped_) {
        Frame& f = frames_.back();
        const ast::Program& p = program_of(f);
        if (f.block >= p.end_block) {
            // Running off the end of a program: a subprogram returns, a main program ends.
            if (frames_.size() == 1) {
                result_.completed = true;
                break;
            }
            pop_frame();
            continue;
        }
        if (++result_.blocks > setup_.step_limit) {
            const ast::BlockView view = file_of(f).typed->block(f.block);
            alarm(f, view, 0, fmt::format("step limit of {} blocks reached: endless loop?", setup_.step_limit));
            break;
        }
        execute_block(f);
    }
    result_.final_position = position_;
    return result_;
}

void Executor::execute_block(Frame& frame) {
    const LoadedFile& file = file_of(frame);
    const std::uint32_t index = frame.block++;
    const ast::BlockView view = file.typed->block(index);
    const ast::Block& block = view.block();
    if (block.kind != ast::BlockKind::code) return;
    if (block.has(ast::block_flags::deleted) && options_.block_delete) return;
    if (block.has(ast::block_flags::has_error)) {
        if (!options_.lenient) {
            alarm(frame, view, 0, "the block has syntax errors (see the diagnostics of kerf parse)");
            return;
        }
        Event e = event_at(EventKind::message, frame, view);
        e.text = "block with syntax errors run without its defective words (lenient)";
        emit(e);
    }
    view_ = &view;
    frame_ = &frame;
    const std::size_t depth = frames_.size();
    if (!execute_statements(frame, view)) return;
    if (frames_.size() != depth || stopped_) return;   // a call or an alarm
    BlockWords words;
    if (!evaluate_words(view, words)) return;
    apply_feed_speed_tool(view, words);
    apply_modal_codes(view);
    if (!apply_coordinate_operations(view, words)) return;
    apply_motion(view, words);
    apply_dwell(view, words);
    apply_m_codes(frame, view, words);
}

}  // namespace kerf::interpreter
