// [FANUC] programmable coordinate transforms of mills, the executor's side: G15/G16 polar
// coordinate command, G50/G51 scaling, G50.1/G51.1 programmable mirror image (gcode-tables.md
// §338–339 lists them as [FANUC]; semantics.md §2.5 notes FANUC G50.1 is mirror cancel). The modes
// are read here; their geometry is one map with G68 (transforms.hpp), applied to every programmed
// point in target_position and to arcs in arc_geometry. Codes are found by function id.
//
// What is and is not transformed (FANUC: "scaling is not applied to offsets"): end points, arc
// centres (I/J/K) and R are; the D and H registers are not (compensation runs on the transformed
// path with the register's radius). The drilling cycles' R and Z levels are read from their words
// and stay as written (FANUC scales them too: a limit of the dry run).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dialects/functions.hpp"
#include "interpreter/executor.hpp"

namespace kerf::interpreter {

namespace fn = dialects::functions;

namespace {

bool has_axis_word(const BlockWords& words) {
    return std::any_of(kAxisLetters, kAxisLetters + kAxisCount, [&](char l) { return words.get(l) != nullptr; });
}

}  // namespace

// The block's G15/G16, G50/G51, G50.1/G51.1. Done when the block has G51, G51.1 or G50.1 with
// axis words: they are a centre or mirror positions, and the block does not move (like G68); a
// bare `G50.1` in a safety block lets the rest of the block (M codes) run (not_mine).
Outcome Executor::apply_program_transforms(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    const bool axis_words = has_axis_word(words);
    bool moves = true;
    for (const ast::CodeRef& c : ctx.scan.g) {
        if (!c.info || !(code_class_of(*c.info) & kProgramTransformCode)) continue;
        const dialects::FunctionId f = c.info->function;
        if (f == fn::polar_coordinate_command || f == fn::polar_coordinate_command_cancel) {
            const bool on = f == fn::polar_coordinate_command;
            if (on != state_.polar_command) note_transform(ctx, on ? "polar coordinate command (G16)" : "polar coordinate command cancel (G15)");
            state_.polar_command = on;
        } else if (f == fn::scaling) {
            start_scaling(ctx);
            moves = !axis_words;
        } else if (f == fn::scaling_cancel && state_.scaling) {
            state_.scaling.reset();
            note_transform(ctx, "scaling cancel (G50)");
        } else if (f == fn::mirror || f == fn::mirror_cancel) {
            set_mirror(ctx, f == fn::mirror);
            moves = !axis_words;
        }
    }
    return unless_stopped(moves ? Outcome::not_mine : Outcome::done);
}

void Executor::note_transform(const BlockContext& ctx, std::string text) {
    Event e = event_at(EventKind::coordinate_change, ctx);
    e.text = std::move(text);
    emit(std::move(e));
}

double Executor::magnification(const Word& w) const {
    return w.has_point ? w.value : w.value * setup_.scaling_unit;
}

// `G51 X Y Z P` (one magnification) or `G51 X Y Z I J K` (each axis its own; negative = mirror
// image of that axis) [FANUC]. The centre words are absolute program coordinates; an axis without
// one is centred on the current point. P is a magnification from 0 up: zero or negative is FANUC
// alarm 142 (illegal scale rate), as is a zero I/J/K. Without P, I, J, K the magnification is 1
// (FANUC reads parameter 5411 there; kerf has no such setting).
void Executor::start_scaling(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    Scaling s;
    // The centre is in the frame scaling maps from: inside G51.1 (a mirror is its own inverse),
    // outside G68 (FANUC nesting G51.1 ⊃ G51 ⊃ G68; transforms.hpp).
    const Position here = ProgramFrame{state_.mirror, std::nullopt, std::nullopt}.to_program(state_.position);
    for (std::size_t a = 0; a < 3; ++a) {
        const auto* w = words.get(kAxisLetters[a]);
        s.center[a] = w ? axis_value(state_, *w, kAxisLetters[a]) : here[a];
    }
    const auto* p = words.get('P');
    if (p) s.factor.fill(magnification(*p));
    for (std::size_t a = 0; a < 3 && !p; ++a)
        if (const auto* k = words.get(static_cast<char>('I' + a))) s.factor[a] = magnification(*k);
    const bool bad = (p && s.factor[0] <= 0) || std::any_of(s.factor.begin(), s.factor.end(), [](double k) { return k == 0; });
    if (bad) {
        alarm(ctx, 142, fmt::format("G51: magnification {:g} {:g} {:g} is not allowed (FANUC alarm 142, illegal "
                                              "scale rate: P must be positive, I/J/K not zero)",
                                              s.factor[0], s.factor[1], s.factor[2]));
        return;
    }
    state_.scaling = s;
    note_transform(ctx, fmt::format("scaling (G51) about X{:g} Y{:g} Z{:g}, magnification X{:g} Y{:g} Z{:g}", s.center[0],
                                     s.center[1], s.center[2], s.factor[0], s.factor[1], s.factor[2]));
}

// `G51.1 X_ Y_ ...`: each named axis is mirrored about the given position (absolute program
// coordinates); `G50.1 X_ ...` cancels the named axes, and kerf reads a G50.1 without axis words
// as cancelling all of them (FANUC wants the axes named) [FANUC].
void Executor::set_mirror(const BlockContext& ctx, bool on) {
    const BlockWords& words = ctx.words;
    const bool named = has_axis_word(words);
    std::string axes;
    for (std::size_t a = 0; a < kAxisCount; ++a) {
        const char letter = kAxisLetters[a];
        const auto* w = words.get(letter);
        if (on && w) {
            state_.mirror[a] = axis_value(state_, *w, letter);
            axes += fmt::format(" {}{:g}", letter, *state_.mirror[a]);
        } else if (!on && state_.mirror[a] && (w || !named)) {
            state_.mirror[a].reset();
            axes += fmt::format(" {}", letter);
        }
    }
    if (axes.empty()) return;
    note_transform(ctx, on ? fmt::format("mirror image (G51.1) about{}", axes) : fmt::format("mirror image cancel (G50.1){}", axes));
}

// G16 [FANUC]: in the plane of G17/G18/G19 the first axis word is the radius, the second the
// angle in degrees (counter-clockwise from the first axis; in the axis' input unit like any axis
// word). The centre is the program's origin (the work or G52 local origin) under G90 and for a
// block without a radius word; an incremental radius (G91) measures from the current point. An
// absolute angle is the angle; an incremental one is added to the angle of the current point
// about the origin (FANUC's bolt-hole example: `G91 Y120.` steps 120° round the circle); a block
// without an angle word keeps that angle, one without a radius word the current point's distance
// from the origin. An arc's end point is polar, its R a radius and its I/J/K Cartesian as ever.
// `start` and `to` are in the program's frame (transforms.hpp undone), so G16 inside G51/G68
// describes the pattern before it is scaled and turned. G51/G51.1/G68/G52/G92/G10 blocks do not
// come here (their words are centres and values, not polar: [FANUC]).
void Executor::polar_target(const MachineState& s, const BlockWords& words, const Position& start, Position& to) const {
    const auto [i, j] = plane_indices(s.flags.plane);
    const auto word = [&](std::size_t axis) -> const Word* {
        const Word* w = words.get(kAxisLetters[axis]);
        return w && !w->data ? w : nullptr;
    };
    const Word* radius = word(i);
    const Word* angle = word(j);
    if (!radius && !angle) return;
    constexpr double kDeg = std::numbers::pi / 180.0;
    const double here_angle = std::atan2(start[j], start[i]) / kDeg;
    double r = std::hypot(start[i], start[j]);
    double centre_i = 0, centre_j = 0;
    if (radius) {
        r = axis_value(s, *radius, kAxisLetters[i]);
        if (s.flags.incremental) {
            centre_i = start[i];
            centre_j = start[j];
        }
    }
    double degrees = here_angle;
    if (angle) degrees = axis_value(s, *angle, kAxisLetters[j]) + (s.flags.incremental ? here_angle : 0.0);
    to[i] = centre_i + r * std::cos(degrees * kDeg);
    to[j] = centre_j + r * std::sin(degrees * kDeg);
}

}  // namespace kerf::interpreter
