// Direct drawing, the executor's side (reference semantics.md §10): reads a block's angle and
// corner words (,A ,C ,R; plain A and R where the dialect's plain_direct_drawing switch makes the
// binder mark them, dialects.md §11.4), reads the next block ahead when the resolver needs it
// (an angle-only block, a corner), and runs the resolver's moves. G70–G73 profiles use the same
// functions (executor_cycles.cpp read_profile_block).
#include <fmt/format.h>

#include <cmath>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;
using drawing::Coordinate;

motion::P2 Executor::plane_point(const MachineState& s, const Position& p) const {
    const motion::PlanePoint q = motion::to_plane(geometric_mm(p, setup_.diameter_x, s.unit_scale()), s.plane());
    return {q.first, q.second};
}

Position Executor::plane_position(const MachineState& s, motion::P2 p, const Position& like) const {
    const double normal = motion::to_plane(geometric_mm(like, setup_.diameter_x, s.unit_scale()), s.plane()).normal;
    return from_geometric(motion::from_plane({p.a, p.b, normal}, s.plane()), like, setup_.diameter_x, s.unit_scale());
}

namespace {

// One plane coordinate of the block: written absolute, incremental (U/W or G91), or not at all.
Coordinate coordinate_of(const BlockWords& words, char letter, bool incremental_mode, double start, double to) {
    const auto* w = words.get(letter);
    const bool absolute_word = w && !w->data;
    if (words.incremental.count(letter)) return {Coordinate::Mode::incremental, to - start};
    if (!absolute_word) return {};
    return incremental_mode ? Coordinate{Coordinate::Mode::incremental, to - start} : Coordinate{Coordinate::Mode::absolute, to};
}

}  // namespace

drawing::Block Executor::drawing_block(const MachineState& s, const Position& at, const BlockContext& ctx, bool linear,
                                       const Position& start, const Position& to) const {
    const BlockWords& words = ctx.words;
    drawing::Block b;
    b.linear = linear;
    const motion::PlaneAxes axes = motion::plane_axes(s.plane());
    const motion::P2 a = plane_point(s, start), t = plane_point(s, to);
    b.first = coordinate_of(words, motion::axis_letter(axes.first), s.flags.incremental, a.a, t.a);
    b.second = coordinate_of(words, motion::axis_letter(axes.second), s.flags.incremental, a.b, t.b);
    // Angle and corner words: ,A ,C ,R (comma words) and plain A / R marked direct_drawing.
    const ast::SyntaxTree& tree = ctx.view.tree();
    for (const ast::Token& token : ctx.view.tokens()) {
        const bool plain = token.kind == ast::TokenKind::word && token.role() == ast::Role::direct_drawing;
        if (token.kind != ast::TokenKind::comma_word && !plain) continue;
        if (token.has(ast::token_flags::value_none)) continue;
        double value = 0;
        if (token.has(ast::token_flags::value_expr)) {
            ExecutorSystemVariables system(*this, s, at);
            const macro::Result r = macro::evaluate(tree, token.payload, variables_, system, macro_options(s, true));
            if (r.error || r.value.vacant) continue;   // a vacant value omits the word (macro B)
            value = r.value.number;
        } else {
            value = tree.number_value(token);
        }
        if (token.letter == 'A') b.angle = value;
        if (token.letter == 'C') b.corner = drawing::CornerKind::chamfer;
        if (token.letter == 'R') b.corner = drawing::CornerKind::fillet;
        // A corner size is a distance: without a decimal point it counts least input increments
        // like an axis word (dialects.md §2); the angle is in degrees.
        const bool point = token.has(ast::token_flags::has_point) || token.has(ast::token_flags::value_expr);
        const double size = point || setup_.calculator_decimal ? value : value * setup_.increment(s.flags.inch);
        if (token.letter == 'C' || token.letter == 'R') b.corner_size = size * s.unit_scale();
    }
    b.moves = b.named() || b.angle.has_value();
    return b;
}

OrAlarm<std::optional<drawing::Block>> Executor::look_ahead(const MachineState& s, const BlockContext& ctx,
                                                            std::optional<std::uint32_t> last, const Position& from) const {
    const Frame& f = ctx.frame;
    const LoadedFile& file = file_of(f);
    for (std::uint32_t b = ctx.index() + 1; file.in_program(f.program.program, b) && (!last || b <= *last); ++b) {
        BlockAhead next{file.block(b), {}, {}};
        if (next.view.block().kind != ast::BlockKind::code) continue;
        if (next.view.block().has(ast::block_flags::deleted) && options_.block_delete) continue;
        // Read with the executor's own word evaluation, the tool at `from`.
        scan_block(f, next.view, next.scan);
        next.scan.block = ctx.index();
        const BlockContext ahead{f, next.view, next.scan, next.words};
        // The chain is G01 (only G01 blocks are drawn): the next block is G01 unless it says otherwise.
        dialects::FunctionId motion = fn::linear;
        for (const ast::CodeRef& c : next.scan.g)
            if (c.info && c.info->has(dialects::traits::motion_group)) motion = c.info->function;
        if (auto failed = read_words(s, from, ahead, next.words)) return {{}, std::move(failed)};
        bool moves = false;
        const Position to = target_position(s, from, next.words, moves);
        return {drawing_block(s, from, ahead, motion == fn::linear, from, to), std::nullopt};
    }
    return {};
}

OrAlarm<drawing::Result> Executor::resolve_drawing(const MachineState& s, const Position& at, const BlockContext& ctx,
                                                   const Position& start, const Position& tool, const Position& to,
                                                   std::optional<std::uint32_t> last) const {
    const drawing::Block cur = drawing_block(s, at, ctx, true, start, to);
    OrAlarm<std::optional<drawing::Block>> next;
    // Only an angle-only block and a corner need the next block (semantics.md §10.1 (c)).
    if (!cur.named() || cur.corner != drawing::CornerKind::none) {
        const Position from = cur.named() ? to : start;
        next = look_ahead(s, ctx, last, from);
        if (!next.ok()) return {{}, std::move(next.alarm)};   // the block read ahead cannot be read
    }
    drawing::Result r = drawing::resolve(plane_point(s, start), plane_point(s, tool), cur, next.value ? &*next.value : nullptr);
    if (r.alarm) return {{}, Alarm{ctx.source(), at, r.alarm->number, r.alarm->text}};
    return {std::move(r), std::nullopt};
}

Outcome Executor::draw_block(const BlockContext& ctx, const Position& start, const Position& to) {
    auto drawn = resolve_drawing(state_, state_.position, ctx, start, state_.position, to, std::nullopt);
    if (!drawn.ok()) {
        raise(std::move(*drawn.alarm));
        return Outcome::stopped;
    }
    const drawing::Result* r = &drawn.value;
    for (const drawing::Move& m : r->moves) {
        const Position end = plane_position(state_, m.end, to);
        if (m.arc) cycle_arc(m.sweep < 0, end, plane_position(state_, m.center, to), ctx);
        else move(EventKind::linear, end, ctx);
        if (stopped_) return Outcome::stopped;
    }
    const Position programmed = plane_position(state_, r->end, to);
    const bool off = motion::norm(plane_point(state_, programmed) - plane_point(state_, state_.position)) > 1e-9;
    state_.programmed = off ? std::optional<Position>(programmed) : std::nullopt;
    if (!off) state_.position = programmed;   // exactly on the programmed point again
    return r->moves.empty() ? Outcome::done : Outcome::moved;
}

void Executor::note_drawing_outside_g01(const BlockContext& ctx) {
    if (drawing_words(ctx)) {
        // Direct drawing is a G01 feature (semantics.md §10.1); G01 blocks never come here.
        Event e = event_at(EventKind::message, ctx);
        e.text = "direct drawing (,A ,C ,R) in a block that is not G01: the words are ignored (semantics.md §10.1)";
        emit(e);
    }
}

}  // namespace kerf::interpreter
