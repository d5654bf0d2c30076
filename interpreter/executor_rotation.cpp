// G68 / G69 coordinate rotation (semantics.md §2.9). The interpreter keeps positions in work
// coordinates (what the tool does); a rotated block's words are in the program's frame, so the
// target is built in that frame and turned into work coordinates.
#include <cmath>
#include <numbers>

#include "interpreter/executor.hpp"

namespace kerf::interpreter {

// The whole programmed-point stage (G68 with G51 scaling and G51.1 mirror image) is one map,
// transforms.hpp; a G68 given inside G51/G51.1 has its centre in their frame (FANUC nesting).
Position Executor::to_program(const MachineState& s, const Position& work) const {
    return s.program_frame().to_program(work);
}

Position Executor::from_program(const MachineState& s, const Position& program) const {
    return s.program_frame().to_work(program);
}

// `G68 <centre words of the plane> R<angle>`: a missing centre word is the current position, a
// missing R is 0 ([FANUC] parameter 5410). Positive R turns counter-clockwise on FANUC and
// clockwise on ADV400: the machine's g68_positive switch says which, and its default "dialect"
// reads the dialect's function id (machine.cpp resolve_for_dialect), so a machine file that writes
// "ccw" wins over the ADV400 table.
void Executor::apply_rotation(const BlockContext& ctx) {
    const BlockWords& words = ctx.words;
    Rotation r;
    r.plane = state_.flags.plane;
    const auto [i, j] = plane_indices(r.plane);
    const Position here = to_program(state_, state_.position);
    r.center_first = here[i];
    r.center_second = here[j];
    for (const auto& [letter, w] : words.words) {
        const auto axis = axis_of_letter(letter);
        if (!axis) continue;
        const std::size_t a = static_cast<std::size_t>(*axis);
        if (a == i) r.center_first = axis_value(state_, w, letter);
        if (a == j) r.center_second = axis_value(state_, w, letter);
    }
    const auto* angle = words.get('R');
    const double degrees = angle ? angle->value : 0.0;
    const bool clockwise_positive = setup_.g68_positive_cw;
    r.angle = (clockwise_positive ? -degrees : degrees) * std::numbers::pi / 180.0;
    state_.rotation = r;
}

}  // namespace kerf::interpreter
