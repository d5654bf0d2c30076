#include "interpreter/executor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dialects/alarms.hpp"
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
        case EventKind::state: return "state";
    }
    return "?";
}

Executor::Executor(ProgramSet& programs, const dialects::Dialect& dialect, const Setup& setup, EventSink& sink,
                   const RunOptions& options)
    : programs_(programs), dialect_(dialect), setup_(setup), sink_(sink), options_(options),
      guard_(setup.step_limit, setup.move_limit, options.time_limit) {
    memory_.additional_offsets = setup.additional_work_offsets;
    memory_.tools = setup.tools;
    update_flags();
    for (const SoftLimit& limit : setup_.soft_limits) any_soft_limit_ |= limit.min.has_value() || limit.max.has_value();
    for (char letter = 'A'; letter <= 'Z'; ++letter) {
        const auto axis = axis_of_letter(letter);
        const std::size_t i = static_cast<std::size_t>(letter - 'A');
        axis_of_[i] = axis ? static_cast<std::int8_t>(*axis) : std::int8_t{-1};
        if (axis && dialect_.lexical.is_axis(letter)) axis_letters_ |= 1u << i;
        if (dialect_.lexical.is_axis(letter)) dialect_axes_ |= 1u << i;
    }
}

void Executor::update_flags() {
    const bool was_inch = state_.flags.inch;
    ModalFlags f;
    f.plane = dialect_.machine == dialects::MachineKind::lathe ? motion::Plane::zx : motion::Plane::xy;
    for (const dialects::CodeInfo* code : state_.modal) {
        if (!code) continue;
        const std::uint32_t c = code_class_of(*code);
        const bool motion_group = code->has(dialects::traits::motion_group);
        if (motion_group) {
            f.motion = code->function;
            if (c & kCycleCode) f.motion_cycle = code;
        }
        if (code->modal && (c & kCycleCode) && !motion_group) f.modal_cycle = code;   // G81.., lathe G83..
        f.incremental |= (c & kIncrementalCode) != 0;
        f.per_revolution |= (c & kPerRevolutionCode) != 0;
        f.css |= (c & kCssCode) != 0;
        f.inch |= (c & kInchCode) != 0;
        switch (c & kPlaneYZCode) {
            case kPlaneXYCode: f.plane = motion::Plane::xy; break;
            case kPlaneZXCode: f.plane = motion::Plane::zx; break;
            case kPlaneYZCode: f.plane = motion::Plane::yz; break;
            default: break;
        }
    }
    state_.flags = f;
    if (was_inch != state_.flags.inch) {
        // G20/G21 switch: the same place in the other unit (positions are kept as programmed).
        const double factor = state_.flags.inch ? 1.0 / 25.4 : 25.4;
        for (std::size_t a = 0; a < 3; ++a) {
            state_.position[a] *= factor;
            if (state_.intermediate[a]) *state_.intermediate[a] *= factor;
        }
    }
}

bool Executor::modal_active(dialects::FunctionId function) const {
    for (const dialects::CodeInfo* code : state_.modal)
        if (code && code->function == function) return true;
    return false;
}

std::string Executor::block_comment(const ast::BlockView& view) const {
    const ast::SyntaxTree& tree = view.tree();
    for (const std::uint32_t ti : view.comments()) {
        std::string_view text = tree.spelling(tree.tokens[ti]);
        if (!text.empty() && text.front() == '(') text.remove_prefix(1);
        if (!text.empty() && text.back() == ')') text.remove_suffix(1);
        return std::string(text);
    }
    return {};
}

ast::Program Executor::program_of(const Frame& f) const { return file_of(f).program(f.program.program); }

SourceRef Executor::source(const Frame& f, const ast::BlockView& view) const {
    const LoadedFile& file = file_of(f);
    const ast::Range r = file.file_range(view);
    const bool same_file = line_hint_file_ == f.program.file;
    const std::uint32_t line = file.line_of(view, same_file ? line_hint_ : 0);
    line_hint_file_ = f.program.file;
    line_hint_ = line;
    return {f.program.file, r, line + 1};
}

bool Executor::has_function(const BlockContext& ctx, dialects::FunctionId function) const {
    for (const ast::CodeRef& c : ctx.scan.g)
        if (c.info && c.info->function == function) return true;
    for (const ast::CodeRef& c : ctx.scan.m)
        if (c.info && c.info->function == function) return true;
    return false;
}

Event Executor::event_at(EventKind kind, const SourceRef& where) const {
    Event e;
    e.kind = kind;
    e.source = where;
    e.start = e.end = state_.position;
    return e;
}

void Executor::emit(Event&& e, const Position& machine_end) {
    const bool motion = e.kind == EventKind::rapid || e.kind == EventKind::linear || e.kind == EventKind::arc_cw ||
                        e.kind == EventKind::arc_ccw || e.kind == EventKind::thread;
    if (motion && !stopped_) {
        // The move over the limit is not made: the alarm stands where the tool is.
        if (auto limit = guard_.move()) return limit_alarm(e.source, e.start, std::move(*limit));
    }
    e.tool = e.kind == EventKind::tool_change ? e.tool : state_.tool;
    e.inch = state_.flags.inch;
    e.machine_end = machine_end;
    if (motion) state_.machine_at = e.machine_end;
    if (e.kind == EventKind::alarm) result_.alarms.push_back(e);
    result_.total_time_s += e.time_s;
    if (e.time_s > 0) {
        if (timed_tool_ != state_.tool || !tool_time_) {
            tool_time_ = &result_.time_per_tool_s[state_.tool];
            timed_tool_ = state_.tool;
        }
        *tool_time_ += e.time_s;
    }
    sink_.on_event(e);
    if (stopped_ || e.kind == EventKind::alarm) return;
    if (auto limit = guard_.tick()) limit_alarm(e.source, state_.position, std::move(*limit));
}

Position Executor::machine_position_of(const Position& work) const {
    const Position offset = machine_offset(state_);
    Position m{};
    for (std::size_t a = 0; a < kAxisCount; ++a) m[a] = work[a] * state_.axis_scale(a) + offset[a];
    return m;
}

void Executor::limit_alarm(const SourceRef& where, const Position& at, LimitAlarm limit) {
    Event e;
    e.kind = EventKind::alarm;
    e.source = where;
    e.start = e.end = at;
    e.code = limit.number;
    e.text = std::move(limit.text);
    emit(std::move(e));
    stopped_ = true;
}

bool Executor::count_idle_move(const BlockContext& ctx) {
    if (auto limit = guard_.move()) limit_alarm(ctx.source(), state_.position, std::move(*limit));
    return !stopped_;
}

void Executor::alarm(const SourceRef& where, int number, std::string text) {
    raise(Alarm{where, state_.position, number, std::move(text)});
}

// The number stays kerf's (the alarm's identity); a dialect that numbers the alarm itself
// ([alarms], Haas NGC) gives the number and text the user reads (dialects/dialect.hpp AlarmTable).
void Executor::raise(Alarm alarm) {
    Event e = event_at(EventKind::alarm, alarm.where);
    e.start = e.end = alarm.at;
    e.code = alarm.number;
    if (const std::optional<dialects::AlarmTable::Shown> shown = dialect_.alarms.shown(alarm.number)) e.control_alarm = shown->number;
    e.text = dialect_.alarms.message(alarm.number, alarm.text);
    emit(std::move(e));
    stopped_ = true;
}

void Executor::pop_frame() {
    if (frames_.back().macro) variables_.pop_level();   // a G65 call's locals end with it
    frames_.pop_back();
}

void Executor::change_offsets(const std::function<void()>& change) {
    // The tool does not move when an offset changes: its work coordinates do (semantics.md §2.7).
    const Position before = machine_offset(state_);
    change();
    const Position after = machine_offset(state_);
    for (std::size_t a = 0; a < kAxisCount; ++a) state_.position[a] += (before[a] - after[a]) / state_.axis_scale(a);
}

// --- the loop ------------------------------------------------------------------------------------

RunResult Executor::run(ProgramRef main) {
    Frame first;
    first.program = main;
    first.block = program_of(first).first_block;
    frames_.push_back(first);
    for (const auto& [number, value] : options_.preset) variables_.write(number, macro::Value::of(value));
    // The machine has been homed: the program starts at reference point 1 (semantics.md §2.8).
    const Position offset = machine_offset(state_);
    for (std::size_t a = 0; a < kAxisCount; ++a)
        state_.position[a] = setup_.start_at_reference ? (setup_.reference_points[0][a] - offset[a]) / state_.axis_scale(a) : 0.0;
    state_.machine_at = machine_position_of(state_.position);
    while (!frames_.empty() && !stopped_) {
        Frame& f = frames_.back();
        if (!file_of(f).in_program(f.program.program, f.block)) {
            // Running off the end of a program: a subprogram returns, a main program ends.
            if (frames_.size() == 1) {
                result_.completed = true;
                break;
            }
            pop_frame();
            continue;
        }
        if (options_.cancel && options_.cancel->load(std::memory_order_relaxed)) {
            result_.cancelled = true;
            break;
        }
        if (auto limit = guard_.block(++result_.blocks)) {
            const ast::BlockView view = file_of(f).block(f.block);
            // check3: kerf's own numbers, so K4004 sees only these (events.hpp kerf_alarm)
            alarm(source(f, view), limit->number, std::move(limit->text));
            break;
        }
        const std::uint32_t file = f.program.file, block = f.block;
        execute_block(f);   // `f` may be gone: a call pushes a frame
        if (options_.run_to && file == options_.run_to->file && reached(file, block)) {
            result_.reached_block = true;
            break;
        }
    }
    result_.final_position = state_.position;
    result_.inch = state_.flags.inch;
    return result_;
}

// Whether block `block` of file `file` is RunOptions::run_to's (by its start in the file's text).
bool Executor::reached(std::uint32_t file, std::uint32_t block) const {
    const LoadedFile& loaded = programs_.file(file);
    return loaded.file_range(loaded.block(block)).begin == options_.run_to->begin;
}

void Executor::execute_block(Frame& frame) {
    const LoadedFile& file = file_of(frame);
    const std::uint32_t index = frame.block++;
    file.pin(index);
    const ast::BlockView view = file.block(index);
    const ast::Block& block = view.block();
    if (block.kind != ast::BlockKind::code) return;
    if (block.has(ast::block_flags::deleted) && options_.block_delete) return;
    BlockScan& scan = scan_buffer_;
    scan_block(frame, view, scan);
    scan.block = index;
    BlockWords& words = words_buffer_;
    words.clear();
    const BlockContext ctx{frame, view, scan, words};
    if (block.has(ast::block_flags::has_error)) {
        if (!options_.lenient) {
            alarm(ctx, kerf_alarm::syntax_error, "the block has syntax errors (see the diagnostics of kerf parse)");
            return;
        }
        Event e = event_at(EventKind::message, ctx);
        e.text = "block with syntax errors run without its defective words (lenient)";
        emit(e);
    }
    if (refuse_unknown_g_code(ctx)) return;
    const std::size_t depth = frames_.size();
    if (execute_statements(frame, ctx) != Outcome::not_mine) return;   // a jump, a loop, a call, an alarm
    if (frames_.size() != depth || stopped_) return;   // a call or an alarm
    if (const auto call = scan.macro_call ? view.macro_call() : std::nullopt; call && call->modal) {
        // G66 P L args: remembers the call; its words are arguments, not moves (dialects.md §3.7).
        if (const auto arguments = macro_arguments(ctx, *call)) {
            if (!call->program) alarm(ctx, 76, "G66 without a program number P (alarm 076)");
            else state_.modal_call = ModalCall{*call->program, call->repeats, *arguments};
        }
        return;
    }
    if (!evaluate_words(ctx, words)) return;
    const SourceRef where = ctx.source();
    const bool moved = apply_block_words(frame, ctx) == Outcome::moved;
    if (options_.emit_state && !stopped_) emit_state(where);
    if (options_.after_block && !stopped_) options_.after_block(where, variables_, macro_options(state_, true));
    // G66: the macro runs after each move block, not inside the macro it calls (dialects.md §3.7).
    if (moved && state_.modal_call && !stopped_ && frames_.size() == depth && !frame.modal_macro)
        push_macro_frame(ctx, state_.modal_call->program, state_.modal_call->repeats, state_.modal_call->arguments, true);
}

// A G code the dialect does not have stops the control with alarm 010 (gcode-tables.md; the
// analyzer's K2001 says so before the run). Lenient: said, and the block runs without it. A
// computed code (G#1) is looked up when its value is known (apply_modal_codes).
bool Executor::refuse_unknown_g_code(const BlockContext& ctx) {
    for (const ast::CodeRef& c : ctx.scan.g) {
        if (c.info || !c.key) continue;
        const std::string_view code = ctx.view.tree().spelling(ctx.view.tree().tokens[c.token]);
        if (!options_.lenient) {
            alarm(ctx, alarms::improper_command, fmt::format("{} is not a code of {} (alarm 010)", code, dialect_.id));
            return true;
        }
        Event e = event_at(EventKind::message, ctx);
        e.text = fmt::format("{} is not a code of {}: the block runs without it (lenient; the control stops with alarm 010)",
                             code, dialect_.id);
        emit(e);
    }
    return false;
}

// Steps 2-9 of semantics.md §1.2 for the evaluated words.
Outcome Executor::apply_block_words(Frame& frame, const BlockContext& ctx) {
    remember_words(ctx);
    apply_feed_speed_tool(ctx);
    if (ctx.scan.classes & dialects::traits::not_modelled) note_not_modelled(ctx);
    apply_modal_codes(ctx);
    // M codes that act before motion (M03, M08, clamps ...) start the spindle for the block's own
    // cut: `G99 G01 Z-5. F0.2 S800 M03` cuts with the spindle turning (semantics.md §1.2 step 3).
    // They run after the block's modal codes (step 4) so that `G96 S200 M03` starts at the surface
    // speed: nothing an M code of step 3 does depends on the other modes.
    apply_m_codes(frame, ctx, MPhase::before_motion);
    if (stopped_) return Outcome::stopped;
    const std::uint32_t classes = ctx.scan.classes;
    if ((classes & kLengthCompCode) || state_.length_sign != 0) apply_length_offset(ctx);   // [length offsets]
    if (state_.pending_length_event || state_.length_applied_mm != state_.length_mm) take_up_length_offset_with_z(ctx);
    if (classes & kCornerSlowdownCode) apply_corner_slowdown(ctx);   // [seed 004 G28/G29]
    // [transforms] G15/G16, G50/G51, G50.1/G51.1 (executor_transforms.cpp): G51/G51.1 words are centres, no motion.
    // A block that sets a frame (G10, G50/G92 X Z, G52, G68, G51, G51.1) does not move; its M
    // codes still run (G68 X0 Y0 R45 M08 turns the coolant on).
    const bool frame_only = ((classes & kProgramTransformCode) && apply_program_transforms(ctx) != Outcome::not_mine) ||
                            apply_coordinate_operations(ctx) != Outcome::not_mine;
    if (stopped_) return Outcome::stopped;
    const Outcome motion = frame_only ? Outcome::done : apply_motion(ctx);
    if (stopped_) return Outcome::stopped;
    if (classes & kOneShotCode) apply_dwell(ctx);   // G04 is group 00
    apply_m_codes(frame, ctx, MPhase::after_motion);   // may end the program: `frame` is gone after M30
    return unless_stopped(motion);
}

// A code whose motion the dry run does not reproduce (traits::not_modelled: G31 skip, G36/G37
// automatic tool measurement, G39 corner arcs, G68/G69 double-turret mirror, G30.1, G50.2/G51.2
// polygon turning, G60, ADV400 G74 homing) is said, never quietly run as something else: a
// warning event the analyzer reports as K5009, saying what the trace does instead.
void Executor::note_not_modelled(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    const bool axis_words = (words.words.mask() & axis_letters_) != 0 || words.incremental.mask() != 0;
    for (const ast::CodeRef& c : ctx.scan.g) {
        if (!c.info || !c.info->has(dialects::traits::not_modelled)) continue;
        Event e = event_at(EventKind::message, ctx);
        e.code = kerf_warning::not_modelled;
        const std::string what = c.info->function == fn::skip_function
                                     ? "the move runs to its end point (a dry run has no skip signal)"
                                 : axis_words ? "the block's axis words run as an ordinary move of the active motion mode"
                                              : "the trace shows no motion for it";
        e.text = fmt::format("{} ({}) is not modelled by the dry run: {}", c.info->spelling, c.info->function.def().meaning, what);
        emit(std::move(e));
    }
}

void Executor::scan_block(const Frame& frame, const ast::BlockView& view, BlockScan& scan) const {
    // A piece of a streamed file brings its blocks scanned by the thread that parsed it.
    if (file_of(frame).scanned(view, scan)) {
        scan.source.file = frame.program.file;
        line_hint_file_ = frame.program.file;
        line_hint_ = scan.source.line - 1;
        return;
    }
    scan_tokens(view, scan);
    scan.source = source(frame, view);
}

void Executor::emit_state(const SourceRef& where) {
    Event e;
    e.kind = EventKind::state;
    e.source = where;
    e.start = e.end = state_.position;
    // Structured (issue 13): the modal codes in `text`, one per group; F, S and T in fields of their own.
    std::string text;
    for (const dialects::CodeInfo* code : state_.modal)
        if (code) text += (text.empty() ? "" : " ") + code->spelling;
    e.text = std::move(text);
    e.feed = state_.feed;
    e.spindle_rpm = state_.flags.css ? state_.css : state_.spindle_rpm;   // the S in force: rpm, or the surface speed under G96
    e.tool = state_.tool;
    e.code = state_.tool_offset;
    emit(std::move(e));
}

}  // namespace kerf::interpreter
