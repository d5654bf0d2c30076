#include "interpreter/direct_drawing.hpp"

#include <fmt/format.h>

namespace kerf::interpreter::drawing {

using motion::P2;
using Mode = Coordinate::Mode;

namespace {

constexpr double kEps = 1e-6;   // mm: lengths below this are no move

double coordinate(const Coordinate& c, double start) {
    return c.mode == Mode::absolute ? c.value : c.mode == Mode::incremental ? start + c.value : start;
}

Alarm make_alarm(int number, std::string text) { return {number, std::move(text)}; }

// The end of an angle-only block: where its line from `start` meets the line of the next block,
// which must give an end point and an angle (§10.1 (c)); its end point is absolute (an
// incremental one would be measured from the corner being looked for).
std::optional<P2> meet_next(P2 start, double angle, const Block* next, std::optional<Alarm>& alarm) {
    const bool full = next && next->linear && next->angle && next->first.mode == Mode::absolute &&
                      next->second.mode == Mode::absolute;
    if (!full) {
        alarm = make_alarm(56, "an angle-only block must be followed by a G01 block with an absolute end point and an "
                               "angle (alarm 056, semantics.md §10.1)");
        return std::nullopt;
    }
    const P2 next_end{next->first.value, next->second.value};
    const auto corner = motion::intersect(start, motion::direction_at(angle), next_end, motion::direction_at(*next->angle));
    if (!corner)
        alarm = make_alarm(57, fmt::format("the lines at {}° and {}° are parallel: no intersection (alarm 057, "
                                           "semantics.md §10.1)", angle, *next->angle));
    return corner;
}

// The programmed end of `cur` (§10.1 (a)–(c)).
std::optional<P2> block_end(P2 start, const Block& cur, const Block* next, std::optional<Alarm>& alarm) {
    if (!cur.angle || (cur.first.mode != Mode::none && cur.second.mode != Mode::none)) return written_end(cur, start);
    if (!cur.named()) return meet_next(start, *cur.angle, next, alarm);
    const bool second = cur.second.mode != Mode::none;
    const double value = second ? coordinate(cur.second, start.b) : coordinate(cur.first, start.a);
    const auto end = motion::point_with_coordinate(start, motion::direction_at(*cur.angle), second, value);
    if (!end)
        alarm = make_alarm(57, fmt::format("a line at {}° never reaches the programmed coordinate (alarm 057, "
                                           "semantics.md §10.1)", *cur.angle));
    return end;
}

// The direction the path leaves the corner in: the next block's angle, or toward its end point.
std::optional<P2> leaving_direction(P2 corner, const Block& next) {
    if (next.angle) return motion::direction_at(*next.angle);
    const P2 d = written_end(next, corner) - corner;
    if (motion::norm(d) <= kEps) return std::nullopt;
    return d;
}

// The length of the next block's line from the corner, when its end is known without reading
// further ahead (for the "corner does not fit" check).
std::optional<double> next_length(P2 corner, const Block& next) {
    std::optional<Alarm> ignored;
    if (!next.named()) return std::nullopt;
    const auto end = block_end(corner, next, nullptr, ignored);
    if (!end) return std::nullopt;
    return motion::norm(*end - corner);
}

}  // namespace

P2 written_end(const Block& b, P2 start) { return {coordinate(b.first, start.a), coordinate(b.second, start.b)}; }

Result resolve(P2 start, P2 tool, const Block& cur, const Block* next) {
    Result r;
    const auto end = block_end(start, cur, next, r.alarm);
    if (!end) return r;
    r.end = *end;
    if (cur.corner == CornerKind::none) {
        if (motion::norm(*end - tool) > kEps) r.moves.push_back(Move{*end, false, {}, 0});
        return r;
    }
    const char* what = cur.corner == CornerKind::chamfer ? "chamfer" : "corner R";
    if (!next || !next->moves) {
        r.alarm = make_alarm(51, fmt::format("no move after the {} (alarm 051, semantics.md §10.1)", what));
        return r;
    }
    if (!next->linear) {
        r.alarm = make_alarm(52, fmt::format("the block after a {} is not G01 (alarm 052, semantics.md §10.1)", what));
        return r;
    }
    const P2 dir_in = cur.angle ? motion::direction_at(*cur.angle) : *end - start;
    const auto dir_out = leaving_direction(*end, *next);
    if (motion::norm(dir_in) <= kEps || !dir_out) {
        r.alarm = make_alarm(55, fmt::format("a {} needs a line on both sides of its corner (alarm 055)", what));
        return r;
    }
    const auto piece = cur.corner == CornerKind::chamfer ? std::optional(motion::chamfer(*end, dir_in, *dir_out, cur.corner_size))
                                                         : motion::fillet(*end, dir_in, *dir_out, cur.corner_size);
    const double room_in = motion::dot(*end - tool, motion::unit(dir_in));
    const auto room_out = next_length(*end, *next);
    if (!piece || cur.corner_size < 0 || piece->setback > room_in + kEps || (room_out && piece->setback > *room_out + kEps)) {
        r.alarm = make_alarm(55, fmt::format("{} {:g} does not fit between its lines (alarm 055, semantics.md §10.1)", what,
                                             cur.corner_size));
        return r;
    }
    if (motion::norm(piece->in_end - tool) > kEps) r.moves.push_back(Move{piece->in_end, false, {}, 0});
    if (motion::norm(piece->out_start - piece->in_end) > kEps)
        r.moves.push_back({piece->out_start, piece->arc, piece->center, piece->sweep});
    return r;
}

}  // namespace kerf::interpreter::drawing
