// What the interpreter needs to know about the machine, in the form it uses. Filled from the
// machine configuration (machine/machine.hpp) by make_setup(); tests build it directly.
#pragma once

#include <array>
#include <cstdint>
#include <map>

#include "interpreter/events.hpp"

namespace kerf::interpreter {

struct ToolOffset {
    Position geometry{};   // X (diameter on lathes), Z, ... geometry offsets
    Position wear{};
    double nose_radius = 0;
    int tip = 0;
};

struct Setup {
    bool diameter_x = false;           // lathe: X and U are diameters (dialects.md §3.3)
    double increment_mm = 0.001;       // IS-B 0.001, IS-C 0.0001
    bool calculator_decimal = true;    // an axis value without point is mm (true) or increments (false)
    std::array<Position, 6> work_offsets{};   // G54..G59, machine coordinates of each zero
    Position external_offset{};
    std::array<Position, 4> reference_points{};   // G28 (1), G30 P2..P4
    Position rapid_mm_min{};           // per axis; 0 = axis absent
    double max_rpm = 0;                // 0 = no limit
    bool rapid_dogleg = true;          // G00 axes move independently (gcode-tables.md §5)
    bool dwell_p_in_seconds = false;   // ADV400: G04 P in seconds (semantics.md §8.2)
    bool g52_current_point = false;    // pcnc/ADV400: G52 makes the current point take the values
    std::map<int, ToolOffset> tools;   // by offset number
    std::uint64_t step_limit = 10'000'000;
    int max_call_depth = 4;            // M98 nesting ([FANUC], dialects.md §3.6)
    int max_macro_depth = 4;           // G65/G66 nesting
};

}  // namespace kerf::interpreter
