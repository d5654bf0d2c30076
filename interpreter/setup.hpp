// What the interpreter needs to know about the machine, in the form it uses. Filled from the
// machine configuration (machine/machine.hpp) by make_setup(); tests build it directly.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dialects/functions.hpp"
#include "interpreter/compensation/radius_compensation.hpp"
#include "interpreter/cycles/settings.hpp"
#include "interpreter/events.hpp"

namespace kerf::interpreter {

struct ToolOffset {
    Position geometry{};   // X (diameter on lathes), Z, ... geometry offsets
    Position wear{};
    double nose_radius = 0;
    double nose_radius_wear = 0;
    int tip = 0;
    double length = 0;        // mill: H register, geometry and wear
    double length_wear = 0;
    double radius = 0;        // mill: D register, geometry and wear
    double radius_wear = 0;
};

struct SoftLimit {
    std::optional<double> min;   // machine coordinates (lathe X as diameter)
    std::optional<double> max;
};

struct Setup {
    bool diameter_x = false;           // lathe: X and U are diameters (dialects.md §3.3)
    std::string axis_order = "XYZ";    // the machine's axes in control order: #5001 is the first (FANUC)
    double increment_mm = 0.001;       // IS-B 0.001, IS-C 0.0001
    // The least input increment of a word written without a decimal point, in the unit it is read
    // in ([FANUC] "Least input increment": IS-B 0.001 mm, 0.0001 inch, 0.001 deg; IS-C a tenth of
    // each). Rotary axes count degrees whatever G20/G21 says.
    double increment(bool inch) const { return inch ? increment_mm / 10.0 : increment_mm; }
    double increment_deg() const { return increment_mm; }
    bool calculator_decimal = true;    // an axis value without point is mm (true) or increments (false)
    std::array<Position, 6> work_offsets{};   // G54..G59, machine coordinates of each zero
    int additional_work_offset_count = 48;     // G54.1 P1..count ([FANUC] option 48 or 300)
    std::map<int, Position> additional_work_offsets;   // G54.1 Pn (an unlisted n is zero)
    Position external_offset{};
    Position work_shift{};             // G10 P0 register at power-on (semantics.md §2.6)
    double work_shift_sign = -1;       // machine = program + offset ∓ shift: −1 subtract (FANUC), +1 add (machine work_shift_sign, §12.3)
    std::array<Position, 4> reference_points{};   // G28 (1), G30 P2..P4
    bool start_at_reference = true;    // the run starts at reference point 1 (homed), else at machine zero
    Position rapid_mm_min{};           // per axis; 0 = axis absent
    Position accel_mm_s2{};
    std::array<bool, kAxisCount> rotary{false, false, false, true, true, true};   // degrees, not mm: no path length, F in deg/min            // per axis; 0 = acceleration not modelled (motion/time.hpp)
    std::array<bool, kAxisCount> carries_tool{true, true, true, true, true, true};   // machine/SCHEMA.md axes carries_tool
    std::array<SoftLimit, kAxisCount> soft_limits{};   // stored stroke check 1 (alarm 500/501)
    double max_rpm = 0;                // 0 = no limit
    double max_cutting_feed = 0;       // mm/min, 0 = no limit (machine max_cutting_feed): threads are checked against it
    bool rapid_dogleg = true;          // G00 axes move independently (gcode-tables.md §5)
    bool dwell_p_in_seconds = false;   // ADV400: G04 P in seconds (semantics.md §8.2)
    bool g52_current_point = false;    // pcnc/ADV400: G52 makes the current point take the values
    bool g52_zeros_cancel = true;      // current-point G52 with all zeros cancels (ADV400; pcnc: only G152)
    bool g54_cancels_g52 = false;      // pcnc: selecting G54–G59 cancels G52 (semantics.md §2.4)
    bool g28_point_in_machine = false; // G28/G30 intermediate point in machine coordinates (semantics.md §2.8)
    int g30_default_p = 2;             // G30 without P (semantics.md §2.8)
    bool g68_positive_cw = false;      // ADV400: positive G68 R turns clockwise (semantics.md §2.9, §12.4)
    double scaling_unit = 0.001;       // G51 P/I/J/K without a point: the factor per unit ([FANUC] SCR)
    double arc_tolerance = 0.01;       // mm, end-point radius mismatch allowed (semantics.md §3)
    double transform_tolerance = 0.01; // mm, G112/G107 path → pieces of linear real-axis motion (cycles.md §18, §19)
    bool arc_negative_r = true;        // R < 0 = arc over 180° (semantics.md §3, §12.5)
    bool arc_enlarge_small_r = false;  // a too small R becomes chord/2 instead of alarm 020
    bool atan_minus_180 = false;       // Macro B ATAN result in -180..180 instead of 0..360 ([FANUC] NAT)
    bool dwell_f_seconds = true;       // `G4 F1` dwells F seconds (semantics.md §8.2, §12.15); false: ignored
    int tool_offset_count = 64;        // offset numbers 1..count exist
    std::vector<int> m_codes;          // the machine builder's M codes (machine file m_codes); empty: not listed
    // The machine comes from a machine file (the user's): its limits are the machine's. A built-in
    // machine's spindle limit and M codes per block are guesses, so the rules that compare a
    // program with them (K5021, K2006) stay silent without a machine file (issue 15).
    bool machine_given = false;
    std::map<int, ToolOffset> tools;   // by offset number
    std::uint64_t step_limit = 10'000'000;
    std::uint64_t move_limit = 10'000'000;   // moves a run emits before it stops (machine switch max_moves)
    int max_call_depth = 4;            // M98 nesting ([FANUC], dialects.md §3.6)
    int max_macro_depth = 4;           // G65/G66 nesting
    // G40–G42 (semantics.md §5, §6): start-up/cancel type, corner style (FANUC C / ADV400 arcs).
    compensation::Settings radius_comp;
    bool comp_shift_without_motion = false;   // seed 004: `G42 D02` alone moves the centre at once (§6)
    bool g41_g42_swapped = false;             // G41 = right (ADV400 list, semantics.md §12.12)
    bool corner_slowdown_step = false;        // seed 004 G28 K F: the feed drops at once (true) or ramps (§9.5, §12.8)
    bool length_offset_at_once = false;       // G43/G44/G49 without axis words moves Z at once (machine length_offset_motion)
    bool iso_g43_approach = true;             // seed 004 G43 in a move: stop D short along the approach (§9.4, §12.9)
    cycles::Settings cycles;           // persistent cycle parameters and cycle switches (cycles.md §0, §21)
    // The modes the machine powers on in where the reference leaves them to parameters (machine
    // switches power_on_units/plane/distance/return_level; dialects.md §3.8, §4, §11.6): the
    // function of the code active at power-on, over the dialect table's default. A function the
    // dialect has no code for (G90/G91 in system A) changes nothing.
    std::vector<dialects::FunctionId> power_on;
};

}  // namespace kerf::interpreter
