// Canned cycles: the executor's side of interpreter/cycles/ (reference/cycles.md). CycleContext
// gives a cycle function the block's words, the profile blocks N P..N Q, the persistent
// parameters and moves through the executor's move()/emit_arc() (times, soft limits, machine
// positions as for any block). A cycle no family of cycles/ expands does not run its words as a
// plain move (the tool would cut through the part): it says so in a message and keeps the tool
// where it is (a message with kerf_warning::not_modelled).
#include <fmt/format.h>

#include <algorithm>
#include <iterator>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

bool Executor::is_cycle(const dialects::CodeInfo& code) const { return code_class_of(code) & kCycleCode; }

// --- the context a cycle runs in ------------------------------------------------------------------

class CycleContext final : public cycles::Context {
public:
    CycleContext(Executor& ex, const dialects::CodeInfo& code, const BlockContext& block, bool has_end, const Position& end)
        : ex_(ex), code_(code), block_(block), words_(block.words), has_end_(has_end), end_(end) {}

    // The profile blocks N P .. N Q the cycle read, if it read one: G71–G73 go on after N Q.
    const std::optional<Executor::ProfileBlocks>& profile_blocks() const { return profile_blocks_; }

    dialects::FunctionId function() const override { return code_.function; }
    bool thread_chamfer() const override { return ex_.state_.thread_chamfer; }
    std::string spelling() const override { return code_.spelling; }
    bool has(char letter) const override { return words_.get(letter) != nullptr; }
    bool takes(char letter) const override { return code_.takes_word(std::string_view(&letter, 1)); }
    std::optional<double> increment(char axis) const override {
        if (!words_.incremental.count(axis)) return std::nullopt;
        return ex_.axis_value(ex_.state_, words_.incremental.at(axis), axis);
    }
    std::optional<int> m_word() const override {
        if (const auto* w = words_.get('M')) return static_cast<int>(std::lround(w->value));   // a parameter M (G384)
        for (const ast::CodeRef& c : block_.scan.m)
            if (c.key) return static_cast<int>(*c.key / 10);
        return std::nullopt;
    }
    std::optional<double> raw(char letter) const override {
        const auto* w = words_.get(letter);
        return w ? std::optional<double>(w->value) : std::nullopt;
    }
    std::optional<double> mm(char letter) const override {
        const auto* w = words_.get(letter);
        return w ? std::optional<double>(ex_.axis_value(ex_.state_, *w, letter)) : std::nullopt;
    }
    // cycles.md §0: integers in least-input increments (or the machine's fixed unit); a decimal
    // point is an alarm on most controls: read as mm and said.
    std::optional<double> pq(char letter) const override {
        const auto* w = words_.get(letter);
        if (!w) return std::nullopt;
        if (w->has_point) {
            const_cast<CycleContext*>(this)->message(
                fmt::format("{}{} has a decimal point: read as mm (cycles.md §0: P/Q are integers in least input "
                            "increments; most controls alarm)", letter, w->value));
            return w->value;
        }
        // A fixed unit (micron, tenth micron) has its inch counterpart a tenth of it, as the
        // increments do (0.001 mm ↔ 0.0001 in): `G76 ... P645 Q180` in G20 is 0.0645 / 0.0180 in.
        const double metric = ex_.setup_.cycles.pq_unit_mm > 0 ? ex_.setup_.cycles.pq_unit_mm : ex_.setup_.increment_mm;
        return w->value * (ex_.state_.flags.inch ? metric / 10.0 : metric);
    }
    bool repeat() const override {
        for (const std::vector<ast::CodeRef>* codes : {&block_.scan.g, &block_.scan.m})
            for (const ast::CodeRef& c : *codes)
                if (c.info == &code_) return false;
        return true;
    }
    bool names_axis(char axis) const override {
        const auto* w = words_.get(axis);
        return (w && !w->data) || words_.incremental.count(axis);
    }
    bool has_end_point() const override { return has_end_; }
    Position end_point() const override { return end_; }
    bool incremental() const override { return ex_.state_.flags.incremental; }
    bool return_to_r_level() const override { return ex_.modal_active(fn::return_r_level); }
    double modal_feed() const override { return ex_.state_.feed; }

    // Under G41/G42 the tool stands at an offset point: the cycle starts from the programmed one
    // (the start point A of G70–G73 is the point of the block before, cycles.md §1); after the
    // cycle's first move (leave_offset_for_cycle) the tool runs on programmed points.
    Position position() const override { return ex_.state_.comp_path.value_or(ex_.state_.position); }
    bool diameter_x() const override { return ex_.setup_.diameter_x; }
    double per_mm() const override { return 1.0 / ex_.state_.unit_scale(); }
    const cycles::Settings& settings() const override { return ex_.setup_.cycles; }
    double dwell_seconds(double p) const override { return ex_.dwell_p_seconds(p); }
    cycles::Parameters& parameters() override { return ex_.state_.cycle_parameters; }
    cycles::SingleCycleModal& single_cycle() override { return ex_.state_.single_cycle; }
    cycles::DrillModal& drill() override { return ex_.state_.drill; }
    cycles::RigidTapModal& rigid_tap() override { return ex_.state_.rigid_tap; }
    Position machine_offset() const override { return ex_.machine_offset(ex_.state_); }
    std::optional<cycles::Profile> profile(double p, double q) override {
        return ex_.cycle_profile(block_, code_.spelling, p, q, profile_blocks_);
    }

    bool rapid(const Position& to) override { return move(EventKind::rapid, to); }
    bool feed(const Position& to, std::optional<double> f) override {
        if (f) ex_.state_.feed = *f;
        return move(EventKind::linear, to);
    }
    bool arc(bool cw, const Position& to, const Position& center, std::optional<double> f) override {
        if (f) ex_.state_.feed = *f;
        const bool ok = ex_.cycle_arc(cw, to, center, block_);
        ex_.leave_offset_for_cycle();
        return ok;
    }
    bool finishing_path(const std::vector<cycles::ProfileMove>& path) override {
        if (ex_.compensating()) return ex_.compensate_path(path, block_);   // executor_compensation.cpp
        for (const cycles::ProfileMove& m : path) {
            const bool ok = m.kind == EventKind::rapid ? rapid(m.end)
                            : (m.kind == EventKind::arc_cw || m.kind == EventKind::arc_ccw)
                                ? arc(m.kind == EventKind::arc_cw, m.end, m.center, m.feed)
                                : feed(m.end, m.feed);
            if (!ok) return false;
        }
        return true;
    }
    bool thread(const Position& to, double lead) override {
        ex_.state_.thread_lead = lead;
        ex_.state_.thread_lead_change = 0;   // cycle threads have a constant lead (a G34 before does not carry over)
        return move(EventKind::thread, to);
    }
    bool feed_at(const Position& to, double mm_per_min) override {
        // The cycle's own feed for this move; the modal F and feed mode stay as they are.
        return move(EventKind::linear, to, Executor::FeedRate{mm_per_min / ex_.state_.unit_scale(), false, 1.0});
    }
    void tool(int code) override { ex_.apply_tool_word(block_, code); }
    void dwell(double seconds) override {
        Event e = ex_.event_at(EventKind::dwell, block_);
        e.time_s = std::max(0.0, seconds);
        ex_.emit(e);
    }
    void m_code(int number) override {
        Event e = ex_.event_at(EventKind::message, block_);
        e.code = number;
        e.text = fmt::format("M{} (issued by {})", number, code_.spelling);
        ex_.emit(e);
    }
    void message(std::string text) override {
        Event e = ex_.event_at(EventKind::message, block_);
        e.text = std::move(text);
        ex_.emit(e);
    }
    void alarm(int number, std::string text) override { ex_.alarm(block_, number, std::move(text)); }
    void alarm_at(std::uint32_t block, int number, std::string text) override {
        const ast::BlockView at = ex_.file_of(block_.frame).block(block);
        ex_.alarm(ex_.source(block_.frame, at), number, std::move(text));
    }

private:
    bool move(EventKind kind, const Position& to) { return move(kind, to, ex_.modal_feed()); }
    bool move(EventKind kind, const Position& to, const Executor::FeedRate& feed) {
        if (ex_.stopped_) return false;
        // Nothing to move; it still counts as a move, so that a cycle whose step vanishes (a peck
        // below the resolution of a double far from zero) cannot loop without end.
        if (to == ex_.state_.position && kind != EventKind::thread) return ex_.count_idle_move(block_);
        ex_.move(kind, to, block_, feed);
        ex_.leave_offset_for_cycle();
        return !ex_.stopped_;
    }

    Executor& ex_;
    const dialects::CodeInfo& code_;
    const BlockContext& block_;
    const BlockWords& words_;
    bool has_end_;
    Position end_;
    std::optional<Executor::ProfileBlocks> profile_blocks_;
};

const dialects::CodeInfo* Executor::cycle_of_block(const BlockContext& ctx, bool has_axis_words) const {
    const dialects::CodeInfo* cycle = nullptr;
    if (ctx.scan.classes & kCycleCode) {   // the block names a cycle (most blocks do not)
        for (const std::vector<ast::CodeRef>* codes : {&ctx.scan.g, &ctx.scan.m})
            for (const ast::CodeRef& c : *codes)
                if (c.info && is_cycle(*c.info)) cycle = c.info;
    }
    if (cycle || !has_axis_words) return cycle;
    // A block with axis words repeats the modal cycle: G81 X Y a new hole, G90 X a new pass.
    return state_.flags.motion_cycle ? state_.flags.motion_cycle : state_.flags.modal_cycle;
}

Outcome Executor::apply_cycle(const BlockContext& ctx, bool has_axis_words, const Position& to) {
    const dialects::CodeInfo* cycle = cycle_of_block(ctx, has_axis_words);
    if (!cycle) return Outcome::not_mine;
    CycleContext context(*this, *cycle, ctx, has_axis_words, to);
    if (!cycles::expand(context)) {
        Event e = event_at(EventKind::message, ctx);
        e.code = kerf_warning::not_modelled;
        e.text = fmt::format("{} ({}) is not expanded by kerf: the tool stays at its start point",
                             cycle->spelling, cycle->function);
        emit(e);
        return Outcome::done;
    }
    // G71–G73: the control goes on after the profile that follows the cycle block (cycles.md
    // §2–§4); G70, or a profile written elsewhere, goes on after the cycle block (§1).
    Frame* frame = current_frame();
    const auto& blocks = context.profile_blocks();
    if (blocks && cycle->function != fn::finishing_cycle && !stopped_ && frame && blocks->first >= frame->block)
        frame->block = blocks->last + 1;
    return unless_stopped(Outcome::done);
}

// Rough cycles do not apply the compensation (cycles.md §2 "Roughing ignores nose-radius
// compensation", semantics.md §5): the cycle's first move leaves the offset point and the cycle
// runs on programmed points; G41/G42 stays in force, so the next compensated move (G70's path)
// starts up again from the cycle's end. Before that first move the cycle reads the programmed
// point (state_.comp_path) as its start.
void Executor::leave_offset_for_cycle() {
    if (!state_.radius_comp.engaged() && !state_.comp_path) return;
    state_.radius_comp.reset();
    state_.comp_path.reset();
    state_.programmed.reset();
}

void Executor::cancel_cycle_by_motion_code(const BlockContext& ctx) {
    if (state_.flags.modal_cycle) {
        bool motion = false, cycle = false;
        for (const ast::CodeRef& c : ctx.scan.g) {
            if (!c.info) continue;
            motion |= c.info->has(dialects::traits::motion_group);
            cycle |= is_cycle(*c.info);
        }
        if (motion && !cycle) {
            const std::uint8_t group = state_.flags.modal_cycle->group_index;
            const dialects::CodeInfo* cancel = nullptr;
            for (const dialects::CodeInfo& c : dialect_.codes())
                if (c.group_index == group && c.function == fn::canned_cycle_cancel) cancel = &c;
            state_.modal[group] = cancel;
            update_flags();
        }
    }
    if (!state_.flags.modal_cycle) state_.drill.active = false;
}

// --- profile blocks -----------------------------------------------------------------------------

std::optional<cycles::Profile> Executor::cycle_profile(const BlockContext& ctx, std::string_view spelling, double p,
                                                       double q, std::optional<ProfileBlocks>& blocks) {
    OrAlarm<ProfileRead> read = read_profile(ctx, spelling, p, q);
    if (!read.ok()) {
        raise(std::move(*read.alarm));
        return std::nullopt;
    }
    blocks = read.value.blocks;
    return std::move(read.value.profile);
}

OrAlarm<Executor::ProfileRead> Executor::read_profile(const BlockContext& ctx, std::string_view spelling, double p,
                                                      double q) const {
    const Frame& f = ctx.frame;
    const auto first = find_label(f, p);
    const auto last = find_label(f, q);
    if (!first || !last || *last < *first) {
        const std::string why = !first || !last ? fmt::format("sequence number N{} not found in this program", !first ? p : q)
                                                : fmt::format("N{} comes before N{}", q, p);
        return {{}, Alarm{ctx.source(), state_.position, 60, fmt::format("{} P{} Q{}: {} (alarm 060)", spelling, p, q, why)}};
    }
    // Each profile block is read with the executor's own word evaluation, from the running profile
    // point, on a copy of the state: the profile leaves the modal state as it was (cycles.md "Notation").
    MachineState s = state_;
    ProfileRead read;
    cycles::Profile& profile = read.profile;
    // Under G41/G42 the profile starts at the programmed point, not at the offset tool [comp3].
    if (s.comp_path) s.position = *s.comp_path;
    profile.start = s.position;
    profile.q_block = *last;
    dialects::FunctionId motion = s.flags.motion;
    for (std::uint32_t b = *first; b <= *last; ++b) {
        BlockAhead block{file_of(f).block(b), {}, {}};
        if (block.view.block().kind != ast::BlockKind::code) continue;
        if (block.view.block().has(ast::block_flags::deleted) && options_.block_delete) continue;
        scan_block(f, block.view, block.scan);
        block.scan.block = b;
        const BlockContext at{f, block.view, block.scan, block.words};
        if (auto failed = read_profile_block(s, at, block.words, motion, profile, *last)) return {{}, std::move(failed)};
    }
    read.blocks = ProfileBlocks{*first, *last};
    return {std::move(read), std::nullopt};
}

// One profile block: its end point from the running profile point, G00/G01/G02/G03 (modal within
// the profile), the arc's centre and sweep, its F (G70, cycles.md §1). Blocks without an end point
// with direct-drawing words go through the same resolver as a running program
// (executor_drawing.cpp), so a profile's corners are those of semantics.md §10.
std::optional<Alarm> Executor::read_profile_block(MachineState& s, const BlockContext& block, BlockWords& words,
                                                  dialects::FunctionId& motion, cycles::Profile& profile,
                                                  std::uint32_t last) const {
    if (auto failed = read_words(s, s.position, block, words)) return failed;
    for (const ast::CodeRef& c : block.scan.g)
        if (c.info && c.info->has(dialects::traits::motion_group)) motion = c.info->function;
    bool moves = false;
    const Position to = target_position(s, s.position, words, moves);
    if (motion == fn::linear && drawing_words(block)) return read_profile_drawing(s, block, to, profile, last);
    if (!moves) return std::nullopt;
    cycles::ProfileMove m;
    m.block = block.index();
    m.end = to;
    m.kind = motion == fn::rapid ? EventKind::rapid : EventKind::linear;
    if (const auto* w = words.get('F'); w && !w->data) m.feed = w->value;
    m.x_word = words.get('X') || words.incremental.count('X');
    m.z_word = words.get('Z') || words.incremental.count('Z');
    if (motion == fn::circular_cw || motion == fn::circular_ccw) {
        const motion::ArcResult arc = arc_geometry(s, motion == fn::circular_cw, s.position, to, words);
        if (!arc)
            return Alarm{block.source(), s.position, arc.error().fanuc_alarm,
                         fmt::format("profile arc: {} (found {:.4f}, allowed {:.4f})", motion::describe(arc.error().code),
                                     arc.error().found, arc.error().allowed)};
        m.kind = arc.arc().cw ? EventKind::arc_cw : EventKind::arc_ccw;
        m.center = from_geometric(arc.arc().center, to, setup_.diameter_x, s.unit_scale());
        m.sweep = arc.arc().sweep;
    }
    profile.moves.push_back(m);
    s.position = to;
    return std::nullopt;
}

// A direct-drawing block of a profile: the resolver's lines and fillet arcs, from the end of the
// last profile move (past a corner) and the programmed point s.position.
std::optional<Alarm> Executor::read_profile_drawing(MachineState& s, const BlockContext& block, const Position& to,
                                                    cycles::Profile& profile, std::uint32_t last) const {
    const BlockWords& words = block.words;
    const Position tool = profile.moves.empty() ? profile.start : profile.moves.back().end;
    OrAlarm<drawing::Result> drawn = resolve_drawing(s, s.position, block, s.position, tool, to, last);
    if (!drawn.ok()) return std::move(drawn.alarm);
    for (const drawing::Move& piece : drawn.value.moves) {
        cycles::ProfileMove m;
        m.block = block.index();
        m.end = plane_position(s, piece.end, to);
        m.kind = !piece.arc ? EventKind::linear : piece.sweep < 0 ? EventKind::arc_cw : EventKind::arc_ccw;
        m.center = plane_position(s, piece.center, to);
        m.sweep = piece.sweep;
        if (const auto* w = words.get('F'); w && !w->data) m.feed = w->value;
        m.x_word = m.z_word = true;   // a drawn line moves both axes in general
        profile.moves.push_back(m);
    }
    s.position = plane_position(s, drawn.value.end, to);
    return std::nullopt;
}

// An arc kerf computed (a cycle's, a compensated tool path's): its ends and centre carry rounding
// of the computation, not the program's digits, so the radius check is at least 0.1 µm.
motion::ArcOptions Executor::computed_arc_options() const {
    motion::ArcOptions options;
    options.radius_tolerance = std::max(setup_.arc_tolerance, 1e-4);
    return options;
}

// An arc of a cycle from the current point to `to` about `center` (work coordinates).
bool Executor::cycle_arc(bool cw, const Position& to, const Position& center, const BlockContext& ctx) {
    const double scale = state_.unit_scale();
    const motion::Vec3 start = geometric_mm(state_.position, setup_.diameter_x, scale);
    const motion::Vec3 end = geometric_mm(to, setup_.diameter_x, scale);
    const motion::Vec3 c = geometric_mm(center, setup_.diameter_x, scale);
    const motion::ArcResult arc = motion::arc_from_center(start, end, state_.plane(), cw ? motion::ArcDirection::cw : motion::ArcDirection::ccw,
                                                          c - start, computed_arc_options());
    if (!arc) {
        move(EventKind::linear, to, ctx);   // a degenerate piece of an arc: its chord
        return !stopped_;
    }
    emit_arc(arc.arc(), to, ctx);
    return !stopped_;
}

}  // namespace kerf::interpreter
