// Direct drawing dimensions (reference semantics.md §10): a G01 block may give its line by an
// angle (,A; plain A in SPINNER, dialects.md §11.4) and one or no end coordinate, and a chamfer
// (,C) or a fillet (,R; plain R in SPINNER) at its end. This is the pure resolver: it turns one
// block (and the block after it, read ahead by the executor) into the moves the control makes.
// The executor feeds it from a running program (executor_drawing.cpp) and from the profile of a
// G70–G73 cycle (executor_cycles.cpp), so both give the same corners. Plane coordinates are
// geometric mm in the plane frame (motion/corner.hpp: G18 = (Z, X radius)).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "motion/corner.hpp"

namespace kerf::interpreter::drawing {

// One plane coordinate of a block: not written, an absolute end value, or an incremental delta.
struct Coordinate {
    enum class Mode { none, absolute, incremental } mode = Mode::none;
    double value = 0;
};

enum class CornerKind { none, chamfer, fillet };

// What the resolver needs of one block.
struct Block {
    bool linear = false;               // G01 in effect (direct drawing is a G01 feature, §10.1)
    bool moves = false;                // a plane coordinate or an angle is written
    Coordinate first, second;          // plane coordinates (first, second axis)
    std::optional<double> angle;       // degrees from the first axis, counter-clockwise (§10.1)
    CornerKind corner = CornerKind::none;
    double corner_size = 0;            // C or R
    bool named() const { return first.mode != Coordinate::Mode::none || second.mode != Coordinate::Mode::none; }
};

// The end point the block's coordinates give from `start` (unwritten coordinates stay).
motion::P2 written_end(const Block& b, motion::P2 start);

// One move the control makes: a line to `end`, or an arc about `center` (sweep > 0: G03).
struct Move {
    motion::P2 end;
    bool arc = false;
    motion::P2 center;
    double sweep = 0;
};

// The alarms of FANUC direct drawing (T series): 051 no move after a corner, 052 the block after
// a corner is not G01, 055 the corner does not fit its lines, 056 an angle-only block not followed
// by an end point and an angle, 057 no intersection (parallel lines).
struct Alarm {
    int number = 0;
    std::string text;
};

struct Result {
    motion::P2 end;                    // the programmed end of the block (the virtual corner)
    std::vector<Move> moves;           // from the tool's point on; empty when it stays
    std::optional<Alarm> alarm;
};

// The moves of block `cur` starting at the programmed point `start`, the tool standing at `tool`
// (on the block's line, past the previous block's corner). `next` is the following block (null
// when there is none); it is needed for an angle-only block and for a corner.
Result resolve(motion::P2 start, motion::P2 tool, const Block& cur, const Block* next);

// Whether a block needs the resolver: direct-drawing words of any kind.
inline bool needs_resolver(const Block& b) { return b.angle || b.corner != CornerKind::none; }

}  // namespace kerf::interpreter::drawing
