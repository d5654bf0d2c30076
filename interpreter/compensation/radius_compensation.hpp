// Cutter radius compensation (mills, semantics.md §6) and tool nose radius compensation (lathes,
// §5) as a state machine: fed the programmed elements one by one, each with the next programmed
// element (the control's look-ahead of one motion block), it returns the tool-centre moves of the
// element. FANUC compensation C: offset elements joined where they cross, acute outside corners
// extended by the radius along both elements and joined by a straight move, start-up and cancel
// of type A or B; or ADV400's arc about the corner at outside corners. Pure: plane frame, mm.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "motion/offset.hpp"

namespace kerf::interpreter::compensation {

enum class StartType { a, b };   // FANUC start-up / cancel type (machine switch cutter_comp_startup)
enum class CornerStyle {
    intersection,   // FANUC compensation C: no arc at a corner unless G39 asks for one
    arc,            // ADV400: an arc of the cutter radius about the corner at outside corners
};

struct Settings {
    StartType start = StartType::b;   // semantics.md §6 "type A/B (a parameter, default B)"
    CornerStyle corners = CornerStyle::intersection;
    // mm: how far an arc's programmed end may lie off its circle (Setup::arc_tolerance, motion/arc.hpp);
    // the joint of two such arcs lands up to that far past the first one's end without the block
    // being short (Haas 1006.nc N6150: two half circles whose centres differ by 0.0001 in).
    double end_tolerance = 0.01;
};

// A programmed element and the compensation in force in its block.
struct Programmed {
    motion::Element path;
    int side = 0;          // +1 tool left of the path (G41), −1 right (G42), 0 none (G40)
    double radius = 0;     // mm, the D register / nose radius in force in the block
    bool moves() const { return motion::norm(path.end - path.start) > 1e-9 || path.arc; }
};

struct ToolMove {
    motion::P2 end;
    bool arc = false;
    motion::P2 center;
    bool ccw = true;
};

struct Alarm {
    int number = 0;
    std::string text;
};

struct Step {
    std::vector<ToolMove> moves;   // from the tool's point, in order
    std::optional<Alarm> alarm;
};

class RadiusCompensation {
public:
    explicit RadiusCompensation(Settings settings = {}) : settings_(settings) {}
    // The tool stands at an offset point (between the start-up and the cancel).
    bool engaged() const { return engaged_; }
    // The tool-centre moves of `current` from where the tool stands: the corner with `next` (the
    // next programmed element, nullopt when the look-ahead found none: the tool then stops
    // perpendicular to the element's end) is made now, its connecting moves kept for `next`.
    // A start-up (not engaged, side ≠ 0) starts at current.path.start; a zero-length start-up
    // shifts the tool at once (the seed-004 `G42 D02` block without motion).
    Step step(const Programmed& current, const std::optional<Programmed>& next);
    // The tool was put at `tool`, an offset point, by a move the compensation did not plan (the
    // seed-004 G43 approach, semantics.md §9.4): the next element goes on from there.
    void stand_at(motion::P2 tool) {
        engaged_ = true;
        tool_ = tool;
        entry_.clear();
    }
    // Forget the compensation (after an alarm, or a move the compensation does not follow).
    void reset() {
        engaged_ = false;
        entry_.clear();
    }

private:
    struct Join {
        motion::P2 end;                  // where the element's own move ends
        std::optional<motion::P2> extension;   // acute corner: a straight run past the end
        std::vector<ToolMove> entry;     // moves the next element starts with
    };
    Step start_up(const Programmed& current, const std::optional<Programmed>& next);
    Step cancel(const Programmed& current);
    Step follow(const Programmed& current, const std::optional<Programmed>& next);
    // The corner between the offset elements a and b at the programmed corner point `corner`.
    std::optional<Join> join(const motion::Element& a, const motion::Element& b, const Programmed& pa,
                             const Programmed& pb, motion::P2 corner, bool cancel_block) const;
    // a to its own end, then a straight move to b's start (a tangent run, a nearly tangent corner).
    static Join straight_join(const motion::Element& a, const motion::Element& b);
    void run(Step& step, const ToolMove& m) {
        if (!m.arc && motion::norm(m.end - tool_) < 1e-9) return;   // a join already reached
        step.moves.push_back(m);
        tool_ = m.end;
    }

    Settings settings_;
    bool engaged_ = false;
    motion::P2 tool_{};
    std::vector<ToolMove> entry_;   // connecting moves of the last corner, run by the next element
};

// The nose centre → imaginary tip vector of a lathe tool with tip number 0–9 and nose radius r,
// in the G18 plane frame (first = Z, second = X as a radius): FANUC's tip numbers as a rear-turret
// lathe draws them (X up, Z right): 1 (+X +Z), 2 (+X −Z), 3 (−X −Z) the usual outside turning
// tool, 4 (−X +Z), 5 (+Z), 6 (+X), 7 (−Z), 8 (−X); 0 and 9 the nose centre itself
// (semantics.md §5, §12.13: the table is only referenced, this is the FANUC definition).
motion::P2 tip_vector(int tip, double r);

}  // namespace kerf::interpreter::compensation
