// Cutter radius compensation (mills, reference semantics.md §6) and tool nose radius
// compensation (lathes, §5), the executor's side: the block's programmed elements (a line, an
// arc, the pieces of a direct-drawing block) and the next motion block read ahead go through
// compensation::RadiusCompensation (the pure state machine), whose tool moves run through
// move()/cycle_arc() like any other (times, soft limits, machine positions). The radius is the D
// register's (mill) or the nose radius of the T offset (lathe); a lathe's controlled point is the
// imaginary tip, so the nose centre path is shifted by the tip vector (tip 0/9: the centre).
// Entered from apply_motion only while compensation is asked for or engaged.
#include <fmt/format.h>

#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;
using compensation::Programmed;

// G02/G03 with only I/J/K: a full circle (semantics.md §3); data words (G28 K) are not centres.
bool Executor::full_circle(dialects::FunctionId motion, const BlockWords& words) {
    if (motion != fn::circular_cw && motion != fn::circular_ccw) return false;
    for (const char letter : {'I', 'J', 'K'})
        if (const auto* w = words.get(letter); w && !w->data) return true;
    return false;
}

int Executor::comp_side_of_block(const MachineState& s, const BlockContext& ctx, int current) const {
    int side = current;
    for (const ast::CodeRef& c : ctx.scan.g) {
        if (!c.info || !(code_class_of(*c.info) & kRadiusCompCode)) continue;
        const dialects::FunctionId f = c.info->function;
        // semantics.md §12.12; [transforms] a mirror of one plane axis swaps G41 and G42 [FANUC].
        const int left = (setup_.g41_g42_swapped ? -1 : 1) * (s.program_frame().reverses(s.plane()) ? -1 : 1);
        side = f == fn::radius_comp_cancel ? 0 : f == fn::radius_comp_left ? left : -left;
    }
    return side;
}

double Executor::comp_radius(const MachineState& s, const BlockWords& words) const {
    if (dialect_.machine == dialects::MachineKind::lathe) {
        const auto it = memory_.tools.find(s.tool_offset);
        return it == memory_.tools.end() ? 0 : it->second.nose_radius + it->second.nose_radius_wear;
    }
    // The block's D, else the modal one (remember_words keeps it); seed-004 D registers are
    // signed (semantics.md §9.1): a negative radius puts the tool on the other side.
    const auto* d = words.get('D');
    const auto& modal = s.last_words[static_cast<std::size_t>('D' - 'A')];
    const std::optional<double> number = d ? std::optional<double>(d->value) : modal;
    if (!number) return 0;
    const auto it = memory_.tools.find(static_cast<int>(std::lround(*number)));
    return it == memory_.tools.end() ? 0 : it->second.radius + it->second.radius_wear;
}

motion::P2 Executor::tip_offset() const {
    if (dialect_.machine != dialects::MachineKind::lathe) return {};
    const auto it = memory_.tools.find(state_.tool_offset);
    if (it == memory_.tools.end()) return {};
    return compensation::tip_vector(it->second.tip, it->second.nose_radius + it->second.nose_radius_wear);
}

namespace {

// A signed radius as a side and a size (a negative D register flips the side).
Programmed with_comp(const motion::Element& path, int side, double radius) {
    return {path, radius < 0 ? -side : side, std::fabs(radius)};
}

}  // namespace

Executor::CompPieces Executor::comp_pieces(const MachineState& s, const BlockContext& ctx, const Position& start,
                                           const Position& to, bool ahead) const {
    const BlockWords& words = ctx.words;
    const int side = comp_side_of_block(s, ctx, s.comp_side);
    const double radius = comp_radius(s, words);
    CompPieces out;
    out.programmed_end = to;
    const dialects::FunctionId motion = ctx.motion_in(s);
    if (s.transform) {   // [polar] the Cartesian plane of G112/G107 (polar_compensation.cpp)
        OrAlarm<motion::Element> element = transform_element(s, ctx, start, to);
        if (!element.ok()) out.alarm = std::move(element.alarm);
        else out.pieces.push_back({with_comp(element.value, side, radius), to});
        return out;
    }
    if (motion == fn::linear && drawing_words(ctx) && ahead) {
        // Read ahead: the direction towards the named end is enough for the corner (a corner
        // word or an angle-only block is resolved when the block runs).
        if (motion::norm(plane_point(s, to) - plane_point(s, start)) > 1e-9)
            out.pieces.push_back({with_comp({plane_point(s, start), plane_point(s, to), false, {}, true}, side, radius), to});
        return out;
    }
    if (motion == fn::linear && drawing_words(ctx)) {
        // Read from the programmed path (an alarm stands there), the tool taken to be on it.
        OrAlarm<drawing::Result> drawn = resolve_drawing(s, start, ctx, s.programmed.value_or(start), start, to, std::nullopt);
        if (!drawn.ok()) {
            out.alarm = std::move(drawn.alarm);
            return out;
        }
        motion::P2 from = plane_point(s, start);
        for (const drawing::Move& m : drawn.value.moves) {
            out.pieces.push_back({with_comp({from, m.end, m.arc, m.center, m.sweep > 0}, side, radius), plane_position(s, m.end, to)});
            from = m.end;
        }
        out.programmed_end = plane_position(s, drawn.value.end, to);
        return out;
    }
    const motion::P2 a = plane_point(s, start), b = plane_point(s, to);
    if (motion == fn::circular_cw || motion == fn::circular_ccw) {
        const motion::ArcResult arc = arc_geometry(s, motion == fn::circular_cw, start, to, words);
        if (!arc) {
            // FANUC runs an R arc whose end is its start as a 0° arc (semantics.md §3, arc_move).
            if (arc.error().code == motion::ArcErrorCode::r_zero_chord) out.zero_arc = true;
            else
                out.alarm = Alarm{ctx.source(), s.position, arc.error().fanuc_alarm,
                                  fmt::format("arc: {} (found {:.4f}, allowed {:.4f})", motion::describe(arc.error().code),
                                              arc.error().found, arc.error().allowed)};
            return out;
        }
        const motion::PlanePoint c = motion::to_plane(arc.arc().center, s.plane());
        out.pieces.push_back({with_comp({a, b, true, {c.first, c.second}, !arc.arc().cw}, side, radius), to});
        return out;
    }
    out.pieces.push_back({with_comp({a, b, false, {}, true}, side, radius), to});
    return out;
}

OrAlarm<std::optional<Programmed>> Executor::comp_look_ahead(const BlockContext& ctx, const Position& from) const {
    const Frame& f = ctx.frame;
    const LoadedFile& file = file_of(f);
    // [FANUC] up to two blocks without motion in the plane between (semantics.md §5).
    int idle = 0;
    // The modal motion after the running block (a G12/G13 quarter arc is no mode), carried through
    // the blocks read ahead: `G03` alone on a block is the motion of the move after it.
    dialects::FunctionId running = state_.flags.motion;
    for (std::uint32_t b = ctx.index() + 1; file.in_program(f.program.program, b) && idle <= 2; ++b) {
        BlockAhead next{file.block(b), {}, {}};
        if (next.view.block().kind != ast::BlockKind::code) continue;
        if (next.view.block().has(ast::block_flags::deleted) && options_.block_delete) continue;
        scan_block(f, next.view, next.scan);
        next.scan.block = b;
        // A cycle, a call or a return ends the look-ahead: the element then ends perpendicular.
        bool stop = next.scan.macro_call || (next.scan.classes & kCycleCode);
        for (const ast::CodeRef& c : next.scan.m)
            stop |= c.info && (c.info->function == fn::subprogram_call || c.info->function == fn::subprogram_return);
        if (stop) return {};
        // The block runs with its own motion code, else with the modal motion.
        dialects::FunctionId motion = running;
        for (const ast::CodeRef& c : next.scan.g)
            if (c.info && c.info->has(dialects::traits::motion_group)) motion = c.info->function;
        if (!(next.scan.classes & kArcApproachCode)) running = motion;
        if (auto failed = read_words(state_, state_.position, {f, next.view, next.scan, next.words}, next.words))
            return {{}, std::move(failed)};
        bool moves = false;
        const Position to = target_position(state_, from, next.words, moves);   // from the end of the running block
        if ((next.scan.classes & kArcApproachCode) && moves) {   // seed-004 G12/G13 (executor_iso_specials.cpp)
            bool ccw = true;
            next.words = arc_approach_words(state_, {f, next.view, next.scan, next.words}, from, to, ccw);
            motion = ccw ? fn::circular_ccw : fn::circular_cw;
        }
        if (moves || full_circle(motion, next.words)) {
            const CompPieces pieces = comp_pieces(state_, {f, next.view, next.scan, next.words, motion}, from, to, true);
            if (pieces.alarm || pieces.pieces.empty()) return {};   // its alarm comes when the block runs
            return {pieces.pieces.front().programmed, std::nullopt};
        }
        ++idle;
    }
    return {};
}

// The live block's pieces: an alarm raised, a 0° arc said; false when there is nothing to run.
bool Executor::block_pieces_run(CompPieces& read, const BlockContext& ctx) {
    if (read.alarm) {
        raise(std::move(*read.alarm));
        return false;
    }
    if (read.zero_arc) {
        Event m = event_at(EventKind::message, ctx);
        m.text = "arc with R whose end point is its start point: no motion (a 0° arc)";
        emit(m);
        return false;
    }
    return !read.pieces.empty();
}

// The state machine's moves for `current`; nullopt after its alarm (034, 041), which forgets the
// compensation.
std::optional<compensation::Step> Executor::comp_step(const Programmed& current, const std::optional<Programmed>& next,
                                                      const BlockContext& ctx) {
    compensation::Step step = state_.radius_comp.step(current, next);
    if (!step.alarm) return step;
    state_.radius_comp.reset();
    alarm(ctx, step.alarm->number, step.alarm->text);
    return std::nullopt;
}

namespace {

// The in-plane length of each tool move of a step, from `from`.
std::vector<double> move_lengths(const compensation::Step& step, motion::P2 from) {
    std::vector<double> lengths;
    for (const compensation::ToolMove& m : step.moves) {
        double l = motion::norm(m.end - from);
        if (m.arc) {
            const motion::P2 u = from - m.center, v = m.end - m.center;
            double sweep = std::atan2(motion::cross(u, v), motion::dot(u, v));
            if (m.ccw && sweep < 0) sweep += 2 * M_PI;
            if (!m.ccw && sweep > 0) sweep -= 2 * M_PI;
            l = motion::norm(u) * std::fabs(sweep);
        }
        lengths.push_back(l);
        from = m.end;
    }
    return lengths;
}

}  // namespace

bool Executor::run_comp_moves(const compensation::Step& step, bool rapid, bool cancels, const Position& like,
                              const BlockContext& ctx) {
    const motion::P2 tip = tip_offset();
    // Compensation acts in the plane (semantics.md §6); the axes off the plane (a helix's Z) go from
    // the tool's start to the block's end along the whole path, shared by length: a connecting move
    // of a few microns takes a few microns of the helix, not all of it (differential A4).
    const Position from = state_.position;
    const std::vector<double> lengths = move_lengths(step, plane_point(state_, state_.position));
    double total = 0, done = 0;
    for (const double l : lengths) total += l;
    for (std::size_t i = 0; i < step.moves.size(); ++i) {
        const compensation::ToolMove& m = step.moves[i];
        done += lengths[i];
        Position off_plane = like;
        const double share = total > 0 ? done / total : 1.0;
        for (std::size_t a = 0; a < kAxisCount; ++a) off_plane[a] = from[a] + (like[a] - from[a]) * share;
        // The cancel's last move ends on the programmed point itself (no tip shift).
        const motion::P2 shift = cancels && i + 1 == step.moves.size() ? motion::P2{} : tip;
        const Position end = plane_position(state_, m.end + shift, off_plane);
        if (m.arc) cycle_arc(!m.ccw, end, plane_position(state_, m.center + shift, off_plane), ctx);
        else move(rapid ? EventKind::rapid : EventKind::linear, end, ctx);
        if (stopped_) return false;
    }
    return true;
}

Outcome Executor::compensate_motion(const BlockContext& ctx, const Position& to, bool moves_words) {
    const BlockWords& words = ctx.words;
    const dialects::FunctionId motion = ctx.motion_in(state_);
    bool moves = moves_words;
    const Position start = state_.comp_path.value_or(state_.position);
    const bool circle = full_circle(motion, words);
    const int side = comp_side_of_block(state_, ctx, state_.comp_side);
    // An angle-only block of direct drawing moves without axis words (semantics.md §10.1).
    moves = moves || (drawing_words(ctx) && motion == fn::linear);
    const bool immediate = !moves && !circle && side != 0 && !state_.radius_comp.engaged() && setup_.comp_shift_without_motion;
    if (!moves && !circle && !immediate) {
        state_.comp_side = side;   // G41/G42/G40 without motion: in force from the next move
        return Outcome::done;
    }
    // A move off the plane (a Z plunge in G17, a C turn): the offset stays, the compensation
    // starts or goes on with the next move in the plane ([FANUC]; semantics.md §5 "blocks
    // without motion in the plane").
    const bool arc = motion == fn::circular_cw || motion == fn::circular_ccw;
    const bool in_plane = arc || drawing_words(ctx) || motion::norm(plane_point(state_, to) - plane_point(state_, start)) > 1e-9;
    if (!in_plane && !immediate) {
        state_.comp_side = side;
        const Position end = plane_position(state_, plane_point(state_, state_.position), to);
        move(motion == fn::rapid ? EventKind::rapid : EventKind::linear, end, ctx);
        if (state_.radius_comp.engaged()) {
            state_.comp_path = plane_position(state_, plane_point(state_, start), to);
            state_.programmed = to;
        }
        return unless_stopped(Outcome::moved);
    }
    CompPieces read = comp_pieces(state_, ctx, start, to, false);
    state_.comp_side = side;
    if (!block_pieces_run(read, ctx)) return unless_stopped(Outcome::done);
    const std::vector<CompPiece>& pieces = read.pieces;
    const Position& programmed_end = read.programmed_end;
    const bool rapid = motion == fn::rapid;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const Programmed& cur = pieces[i].programmed;
        std::optional<Programmed> next;
        if (i + 1 < pieces.size()) {
            next = pieces[i + 1].programmed;
        } else {
            OrAlarm<std::optional<Programmed>> ahead = comp_look_ahead(ctx, programmed_end);
            if (!ahead.ok()) {
                raise(std::move(*ahead.alarm));   // the block read ahead cannot be read
                return Outcome::stopped;
            }
            next = ahead.value;
        }
        const bool cancels = state_.radius_comp.engaged() && cur.side == 0;
        const auto step = comp_step(cur, next, ctx);
        if (!step) return Outcome::stopped;
        if (!run_comp_moves(*step, rapid, cancels, pieces[i].end, ctx)) return Outcome::stopped;
    }
    if (state_.radius_comp.engaged()) {
        state_.comp_path = pieces.empty() ? start : pieces.back().end;
        state_.programmed = programmed_end;
    } else {
        state_.comp_path.reset();
        state_.programmed.reset();
        state_.position = programmed_end;   // exactly on the programmed point after the cancel
    }
    return Outcome::moved;
}

// G70 under G41/G42 (cycles.md §1 "tool-nose radius compensation active before G70 is applied to
// the profile"; semantics.md §5): the finishing path, the return to A included, through the same
// state machine as programmed blocks, each element with the following one as its look-ahead. The
// F of a profile block is in effect for its own moves.
bool Executor::compensate_path(const std::vector<cycles::ProfileMove>& path, const BlockContext& ctx) {
    const double radius = comp_radius(state_, ctx.words);
    std::vector<Programmed> elements;
    Position from = state_.comp_path.value_or(state_.position);
    for (const cycles::ProfileMove& m : path) {
        const bool arc = m.kind == EventKind::arc_cw || m.kind == EventKind::arc_ccw;
        const motion::Element e{plane_point(state_, from), plane_point(state_, m.end), arc, arc ? plane_point(state_, m.center) : motion::P2{},
                                m.kind == EventKind::arc_ccw};
        elements.push_back(with_comp(e, state_.comp_side, radius));
        from = m.end;
    }
    for (std::size_t i = 0; i < elements.size(); ++i) {
        if (!elements[i].moves()) continue;
        std::optional<Programmed> next;
        for (std::size_t k = i + 1; k < elements.size() && !next; ++k)
            if (elements[k].moves()) next = elements[k];
        const auto step = comp_step(elements[i], next, ctx);
        if (!step) return false;
        if (path[i].feed) state_.feed = *path[i].feed;
        if (!run_comp_moves(*step, path[i].kind == EventKind::rapid, false, path[i].end, ctx)) return false;
    }
    state_.comp_path = path.back().end;
    state_.programmed = path.back().end;
    return true;
}

}  // namespace kerf::interpreter
