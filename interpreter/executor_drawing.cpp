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

motion::P2 Executor::plane_point(const Position& p) const {
    const motion::PlanePoint q = motion::to_plane(geometric_mm(p, setup_.diameter_x, unit_scale()), plane());
    return {q.first, q.second};
}

Position Executor::plane_position(motion::P2 p, const Position& like) const {
    const double normal = motion::to_plane(geometric_mm(like, setup_.diameter_x, unit_scale()), plane()).normal;
    return from_geometric(motion::from_plane({p.a, p.b, normal}, plane()), like, setup_.diameter_x, unit_scale());
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

drawing::Block Executor::drawing_block(const BlockContext& ctx, bool linear,
                                       const Position& start, const Position& to) {
    const BlockWords& words = ctx.words;
    drawing::Block b;
    b.linear = linear;
    const motion::PlaneAxes axes = motion::plane_axes(plane());
    const motion::P2 s = plane_point(start), t = plane_point(to);
    b.first = coordinate_of(words, motion::axis_letter(axes.first), state_.flags.incremental, s.a, t.a);
    b.second = coordinate_of(words, motion::axis_letter(axes.second), state_.flags.incremental, s.b, t.b);
    // Angle and corner words: ,A ,C ,R (comma words) and plain A / R marked direct_drawing.
    const ast::SyntaxTree& tree = ctx.view.tree();
    for (const ast::Token& token : ctx.view.tokens()) {
        const bool plain = token.kind == ast::TokenKind::word && token.role() == ast::Role::direct_drawing;
        if (token.kind != ast::TokenKind::comma_word && !plain) continue;
        if (token.has(ast::token_flags::value_none)) continue;
        double value = 0;
        if (token.has(ast::token_flags::value_expr)) {
            const macro::Result r = macro::evaluate(tree, token.payload, variables_, macro_options(true));
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
        const double size = point || setup_.calculator_decimal ? value : value * setup_.increment(state_.flags.inch);
        if (token.letter == 'C' || token.letter == 'R') b.corner_size = size * unit_scale();
    }
    b.moves = b.named() || b.angle.has_value();
    return b;
}

std::optional<drawing::Block> Executor::look_ahead(const BlockContext& ctx, std::optional<std::uint32_t> last,
                                                   const Position& from) {
    const Frame& f = ctx.frame;
    const LoadedFile& file = file_of(f);
    for (std::uint32_t b = ctx.index() + 1; file.in_program(f.program.program, b) && (!last || b <= *last); ++b) {
        const ast::BlockView next = file.block(b);
        if (next.block().kind != ast::BlockKind::code) continue;
        if (next.block().has(ast::block_flags::deleted) && options_.block_delete) continue;
        // Read with the executor's own word evaluation; the running block's state comes back after.
        BlockScan scan;
        scan_block(f, next, scan);
        scan.block = ctx.index();
        BlockWords words;
        const BlockContext ahead{f, next, scan, words};
        const LookAheadScope guard(*this);
        // The chain is G01 (only G01 blocks are drawn): the next block is G01 unless it says otherwise.
        dialects::FunctionId motion = fn::linear;
        for (const ast::CodeRef& c : scan.g)
            if (c.info && c.info->has(dialects::traits::motion_group)) motion = c.info->function;
        std::optional<drawing::Block> out;
        state_.position = from;
        if (evaluate_words(ahead, words)) {
            bool moves = false;
            const Position to = target_position(words, moves);
            out = drawing_block(ahead, motion == fn::linear, from, to);
        }
        return out;
    }
    return std::nullopt;
}

std::optional<drawing::Result> Executor::resolve_drawing(const BlockContext& ctx,
                                                         const Position& start, const Position& tool, const Position& to,
                                                         std::optional<std::uint32_t> last) {
    const drawing::Block cur = drawing_block(ctx, true, start, to);
    std::optional<drawing::Block> next;
    // Only an angle-only block and a corner need the next block (semantics.md §10.1 (c)).
    if (!cur.named() || cur.corner != drawing::CornerKind::none) {
        const Position from = cur.named() ? to : start;
        next = look_ahead(ctx, last, from);
    }
    if (stopped_) return std::nullopt;   // the block read ahead raised an alarm
    drawing::Result r = drawing::resolve(plane_point(start), plane_point(tool), cur, next ? &*next : nullptr);
    if (r.alarm) {
        alarm(ctx, r.alarm->number, r.alarm->text);
        return std::nullopt;
    }
    return r;
}

Position Executor::programmed_target(const BlockWords& words, bool& moves) {
    const Position tool = state_.position;
    state_.position = *state_.programmed;
    const Position to = target_position(words, moves);
    state_.position = tool;
    return to;
}

bool Executor::draw_block(const BlockContext& ctx, const Position& start, const Position& to) {
    const auto r = resolve_drawing(ctx, start, state_.position, to, std::nullopt);
    if (!r) return false;
    for (const drawing::Move& m : r->moves) {
        const Position end = plane_position(m.end, to);
        if (m.arc) cycle_arc(m.sweep < 0, end, plane_position(m.center, to), ctx);
        else move(EventKind::linear, end, ctx);
        if (stopped_) return true;
    }
    const Position programmed = plane_position(r->end, to);
    const bool off = motion::norm(plane_point(programmed) - plane_point(state_.position)) > 1e-9;
    state_.programmed = off ? std::optional<Position>(programmed) : std::nullopt;
    if (!off) state_.position = programmed;   // exactly on the programmed point again
    return !r->moves.empty();
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
