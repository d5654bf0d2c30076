// The machine configuration: axes, increments, offsets, tools, rates, limits and the switches the
// reference leaves open (design.md "Machine configuration is data too"). Built from TOML files
// (machine/SCHEMA.md): built-in defaults per dialect in machine/data (embedded), user files that may
// inherit from one (`base = "fanuc-mill"`). No I/O here: the loader takes text, the CLI reads files.
//
// Every open point of the reference (the "Ambiguities" lists of ../shared/reference/*.md) that
// changes what a program does is a field of `Switches`, initialised to the documented default, with
// the section it comes from. Some defaults come from the dialect (`"dialect"` in a file): they are
// filled in by resolve_for_dialect() from the dialect tables (function ids, power-on codes,
// lexical rules), never from the dialect's name.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "dialects/dialect.hpp"

namespace kerf::machine {

using dialects::MachineKind;

// Values per axis letter ('X' → 100.0). A letter that is absent means 0 (not set).
using AxisValues = std::map<char, double>;
double axis_value(const AxisValues& values, char letter);   // 0 when absent

// ---------------------------------------------------------------------------------------------
// Switches. Each enum lists the readings the reference gives; the comment names the section.
// ---------------------------------------------------------------------------------------------

// G52: semantics.md §2.4, §12.1; gcode-tables.md §7. Default "dialect": the dialect's G52 function id.
enum class G52Semantics {
    vector_shift,         // FANUC: local origin = work origin + programmed vector; G52 X0.. cancels
    current_point,        // ADV400: the current point takes the programmed values; G52 with zeros cancels
    current_point_g152,   // pcnc-mill: as current_point, G152 cancels, selecting G54–G59 cancels
};
enum class RapidMode { dog_leg, linear };               // gcode-tables.md §5 (seed 003 G00, FANUC LRP)
enum class WorkShiftSign { subtract, add };             // semantics.md §2.6, §12.3
enum class G53Motion { rapid, g0_g1 };                  // semantics.md §2.2, §12.2
enum class PointFrame { work, machine };                // semantics.md §2.8 (G28/G30 intermediate point)
enum class RotationSign { ccw, cw };                    // positive G68 R; semantics.md §2.9, §12.4
enum class G68Centre { as_written, plane_order };       // semantics.md §2.9 (`G18 G68 X1 Y1`)
enum class Plane { xy, zx, yz };                        // G17 / G18 / G19
enum class Units { metric, inch };                      // G21 / G20 at power-on (dialects.md §3.8)
enum class Distance { absolute, incremental };          // G90 / G91 at power-on (dialects.md §4)
enum class ReturnLevel { initial, r_point };            // G98 / G99 (canned cycles) at power-on (dialects.md §4)
enum class ArcLargeR { negative_r, reject };            // R < 0 → arc > 180° (semantics.md §3, §12.5)
enum class ArcMismatch { alarm, enlarge };              // |chord| > 2|R| (semantics.md §3)
enum class CompStartup { type_a, type_b };              // cutter compensation start-up (semantics.md §6)
enum class CompCorners { intersection, arc };          // outside corners: FANUC C or ADV400 arcs (semantics.md §6)
enum class DwellUnit { ms, s };                         // G04 P (semantics.md §8.2)
enum class ScalingUnit { thousandth, hundred_thousandth };   // G51 P/I/J/K without a point ([FANUC] SCR)
enum class DwellF { seconds, reject };                  // `G4F1` (semantics.md §8.2, §12.15)
enum class AllowanceU { diameter, radius };             // G71–G73 Δu (dialects.md §11.2, cycles.md §21.2)
enum class CyclePQUnits { increment, micron, tenth_micron };   // G74–G76/G83/G87 P, Q (cycles.md §0, §21.1)
enum class Relief { feed, rapid };                      // G71/G72 45° relief (cycles.md §2, §21.3)
enum class RoughReturn { simultaneous, x_then_z, z_then_x };   // G71–G73 return to A (cycles.md §21.3)
enum class G76Infeed { flank, opposite_flank, radial };          // G76 flank shift (cycles.md §7, §21.4)
enum class SixDigitWord { p, r };                       // ADV400 G76 m/r/a word (cycles.md §7, §21.6)
enum class Adv400G83K { peck, initial_depth };          // cycles.md §11.3, §21.7
enum class Adv400LatheG98 { feed_mode, return_level };  // gcode-tables.md §3, §8.7; cycles.md §21.7
enum class Adv400G84 { tapping, drill_dwell };          // gcode-tables.md §2, §8.6
enum class DrillRepeatL { fanuc, ignore };              // ADV400 G81/G84/G83 L (cycles.md §11.1, §21.8)
enum class G38Stop { target, half_tolerance };          // cycles.md §12
enum class ClampContact { half_tolerance, target };     // G138/G238 (cycles.md §13, §14)
enum class G238ATiming { start, after_clamp };          // cycles.md §14, §21.10
enum class G384RadialH { radius, diameter };            // cycles.md §15, §21.9
enum class CornerSlowdown { ramp, step };               // iso-legacy G28 K F (semantics.md §9.5, §12.8)
enum class IsoG43 { approach_shorten, length_offset };  // semantics.md §9.4, §12.9; gcode-tables.md §8.13
enum class LengthOffsetMotion { next_move, at_once };   // G43/G44/G49 without an axis word ([FANUC] parameter; semantics.md §7)
enum class M23M24 { by_mode, live_tool, thread_exit };  // mcodes.md §5.1
enum class M10M11 { conveyor, chuck };                  // mcodes.md §5.3
enum class M17Meaning { hp_valve, pump_2_off };         // mcodes.md §5.2
enum class M200Meaning { part_off_check, washing };     // mcodes.md §5.4
enum class M33M34 { sub_spindle_rotation, synchronisation };   // mcodes.md §5.5
enum class TurretIndexCode { m318, m46 };               // mcodes.md §5.6
enum class M19C { orient, reference };                  // mcodes.md §1, §5.11
enum class AtanRange { zero_to_360, minus_180_to_180 }; // Macro B ATAN result ([FANUC] parameter NAT)

struct Switches {
    // Coordinate systems
    G52Semantics g52 = G52Semantics::vector_shift;            // "dialect"; semantics.md §2.4, §12.1
    bool g52_cancel_on_reference_return = false;              // semantics.md §2.4 "(parameter)"; [FANUC] ZCL = 0
    WorkShiftSign work_shift_sign = WorkShiftSign::subtract;  // semantics.md §2.6, §12.3: new origin = old − shift
    bool x_offsets_diameter = true;                           // semantics.md §2.7: X offsets/shift are diameters (lathe)
    G53Motion g53_motion = G53Motion::rapid;                  // "dialect"; semantics.md §2.2, §12.2
    bool g53_modal = false;                                   // semantics.md §2.2 (ADV400 bare G53): one-shot [inference]
    PointFrame g28_intermediate = PointFrame::work;           // semantics.md §2.8: intermediate point in work coordinates
    int g30_default_p = 2;                                    // semantics.md §2.8: G30 without P = 2nd point [FANUC]
    RotationSign g68_positive = RotationSign::ccw;            // "dialect"; semantics.md §2.9, §12.4 (ADV400 + = CW)
    G68Centre g68_centre = G68Centre::as_written;             // semantics.md §2.9 (centre words outside the plane)
    bool v_alias_of_b = false;                                // dialects.md §11.3: V is the sub-spindle axis B

    // Power-on state the reference leaves to parameters
    Plane power_on_plane = Plane::xy;                         // "dialect"; dialects.md §11.6 (ADV400 lathe: G18)
    bool warn_arc_without_plane = false;                      // dialects.md §11.6 (ADV400 lathe: warn)
    Units power_on_units = Units::metric;                     // "dialect"; dialects.md §3.8 "G21 or G20 (parameter)"
    Distance power_on_distance = Distance::absolute;          // "dialect"; dialects.md §4 (B/C: a parameter)
    ReturnLevel power_on_return_level = ReturnLevel::initial; // "dialect"; dialects.md §4 (B/C: a parameter)

    // Motion
    RapidMode rapid = RapidMode::dog_leg;                     // gcode-tables.md §5, §2 (G00)
    ArcLargeR arc_negative_r = ArcLargeR::negative_r;         // semantics.md §3, §12.5 (lathes: reject)
    ArcMismatch arc_radius_mismatch = ArcMismatch::alarm;     // semantics.md §3
    double arc_tolerance = 0.01;                              // mm; semantics.md §3 "within tolerance" [inference]
    double transform_tolerance = 0.01;                        // mm; G112/G107 pieces, cycles.md §18–§19 [inference]
    CompStartup cutter_comp_startup = CompStartup::type_b;    // semantics.md §6 "type A/B (a parameter, default B)"
    bool g41_g42_swapped = false;                             // gcode-tables.md §8.5, semantics.md §12.12 (ADV400 list)
    LengthOffsetMotion length_offset_motion = LengthOffsetMotion::next_move;   // semantics.md §7 [FANUC parameter]
    CompCorners cutter_comp_corners = CompCorners::intersection;   // semantics.md §6 (ADV400: arcs)
    bool comp_shift_without_motion = false;                   // semantics.md §6 (seed 004 `G42 D02` alone)

    // Units of words
    CyclePQUnits cycle_pq_units = CyclePQUnits::increment;    // cycles.md §0, §21.1 ("tens of microns")
    DwellUnit dwell_p_unit = DwellUnit::ms;                   // semantics.md §8.2 (ADV400: s)
    ScalingUnit scaling_unit = ScalingUnit::thousandth;       // G51 P1000 = ×1 ([FANUC] parameter 5400#7 SCR)
    DwellF dwell_f_word = DwellF::seconds;                    // semantics.md §8.2, §12.15 (`G4F1`, with a warning)

    // Cycles
    AllowanceU finish_allowance_u = AllowanceU::diameter;     // dialects.md §11.2, cycles.md §2, §21.2
    Relief rough_relief = Relief::feed;                       // cycles.md §2 step 6, §21.3
    RoughReturn rough_return = RoughReturn::simultaneous;     // cycles.md §21.3 [inference]
    G76Infeed g76_infeed = G76Infeed::flank;                  // cycles.md §7 step 3, §21.4
    double thread_chamfer = 1.0;                              // × lead; G92/M23 run-out (cycles.md §8.2, parameter 5130) [inference]
    double peck_clearance = 0.5;                              // mm; G83/G87 re-approach (cycles.md §10) [inference]
    double high_speed_retract = 0.1;                          // mm; G73 retract d ([FANUC] parameter 5114)
    double homing_feed = 0;                                   // mm/min, 0 = rapid; ADV400 G74 (cycles.md §11.4)
    SixDigitWord adv400_g76_mra = SixDigitWord::p;            // cycles.md §7, §21.6
    Adv400G83K adv400_g83_k = Adv400G83K::peck;               // cycles.md §11.3, §21.7
    Adv400LatheG98 adv400_lathe_g98_g99 = Adv400LatheG98::feed_mode;   // gcode-tables.md §3, §8.7
    Adv400G84 adv400_g84 = Adv400G84::tapping;                // gcode-tables.md §2, §8.6; cycles.md §11.2
    DrillRepeatL drill_repeat_l = DrillRepeatL::fanuc;        // cycles.md §11.1, §21.8
    G38Stop g38_stop = G38Stop::target;                       // cycles.md §12 ("model the stop position as B")
    ClampContact clamp_contact = ClampContact::half_tolerance;   // cycles.md §13, §14 (default B + Q/2)
    G238ATiming g238_a_timing = G238ATiming::start;           // cycles.md §14, §21.10
    G384RadialH g384_radial_h = G384RadialH::radius;          // cycles.md §15, §21.9 [inference]
    double g384_bottom_dwell = 0.1;                           // s; cycles.md §15 step 5, §21.9
    CornerSlowdown corner_slowdown = CornerSlowdown::ramp;    // semantics.md §9.5, §12.8
    IsoG43 iso_g43 = IsoG43::approach_shorten;                // semantics.md §9.4, §12.9

    // M codes whose meaning the seeds contradict
    M23M24 m23_m24 = M23M24::by_mode;                         // mcodes.md §5.1
    bool m3_clockwise = true;                                 // mcodes.md §5.9, §5.10 (M4 is the other way)
    M10M11 m10_m11 = M10M11::conveyor;                        // mcodes.md §5.3
    M17Meaning m17 = M17Meaning::hp_valve;                    // mcodes.md §5.2
    M200Meaning m200 = M200Meaning::part_off_check;           // mcodes.md §5.4
    M33M34 m33_m34 = M33M34::sub_spindle_rotation;            // mcodes.md §5.5
    TurretIndexCode turret_index_during_motion = TurretIndexCode::m318;   // mcodes.md §2.1, §5.6
    bool m042_on = false;                                     // mcodes.md §5.7: M042 is the OFF of M041
    bool m381_enables = false;                                // mcodes.md §5.8: M381 disables (table)
    bool m84_as_m23 = false;                                  // mcodes.md §2.1, §5.12: M84 undocumented
    M19C m19_c = M19C::orient;                                // mcodes.md §1, §5.11 [inference]

    // Limits of the control
    AtanRange atan_range = AtanRange::zero_to_360;            // [FANUC] (not in the reference)
    int subprogram_nesting = 4;                               // dialects.md §3.6 [FANUC] (10 on newer models)
    int macro_nesting = 4;                                    // dialects.md §3.6 [FANUC] (5 on newer models)
    std::int64_t max_blocks = 10'000'000;                     // blocks executed before a dry run stops (no hang)
    std::int64_t max_moves = 10'000'000;                      // moves emitted before a dry run stops (no hang)
};

// ---------------------------------------------------------------------------------------------
// The machine
// ---------------------------------------------------------------------------------------------

enum class InputIncrement { is_b, is_c };   // 0.001 mm / 0.0001 mm (dialects.md §11.9, cycles.md §0)
double increment_mm(InputIncrement increment);

struct Axis {
    char letter = 'X';
    bool rotary = false;
    bool carries_tool = true;  // false: no cutting tool rides on it (lathe tailstock / transfer B): a feed of it alone cuts nothing
    double rapid = 0;          // mm/min (deg/min for rotary axes)
    double acceleration = 0;   // mm/s² (deg/s²)
    std::optional<double> min; // soft limits in machine coordinates (X as diameter when diameter_x)
    std::optional<double> max;
};

struct ToolOffset {
    int number = 0;            // offset number (T mmnn → nn; D/H register on mills)
    AxisValues geometry;       // lathe: X (diameter when x_offsets_diameter), Z, ...
    AxisValues wear;
    double nose_radius = 0;    // lathe tool nose R (semantics.md §5)
    double nose_radius_wear = 0;
    int tip = 0;               // imaginary tip 0–9 (0/9 = nose centre)
    double length = 0;         // mill: length offset (H), geometry
    double length_wear = 0;
    double radius = 0;         // mill: cutter radius (D), geometry
    double radius_wear = 0;
    std::string comment;
};

// Initial values of the persistent cycle parameters (cycles.md §0: "initial values = machine
// configuration"); a program's first cycle block overwrites them.
struct CycleParameters {
    double g71_depth = 2.0;          // Δd, mm radius
    double g71_retract = 1.0;        // e, mm
    double g72_depth = 2.0;
    double g72_retract = 1.0;
    double g73_relief_x = 0;         // Δi, mm radius
    double g73_relief_z = 0;         // Δk, mm
    int g73_divisions = 1;           // d
    double g74_retract = 0.5;        // e, mm
    double g75_retract = 0.5;
    int g76_finishing_passes = 1;    // m
    int g76_chamfer = 0;             // r, tenths of the lead
    int g76_angle = 60;              // a, degrees
    double g76_min_depth = 0.05;     // Δdmin, mm radius
    double g76_allowance = 0.03;     // d, mm
};

// SPINNER programmable tailstock (cycles.md §17): positions the machine builder sets.
struct Tailstock {
    std::optional<double> coupling_z;          // G100: carriage Z where the tailstock couples (machine)
    std::optional<double> coupling_z_second;   // G101: second coupling hole
    std::optional<double> home_b;              // G100 I1: tailstock home
};

struct Machine {
    std::string id;                    // "fanuc-lathe"
    std::string name;
    std::string reference;             // where the values come from
    std::string base;                  // the machine this file inherits from ("" = none)
    MachineKind kind = MachineKind::mill;
    std::vector<std::string> dialects; // dialect ids this machine is the built-in default for

    std::vector<Axis> axes;            // in the order X Y Z A B C U V W
    bool diameter_x = false;           // lathe: X and U are diameters (dialects.md §3.3)
    InputIncrement increment = InputIncrement::is_b;
    bool calculator_decimal = false;   // "dialect"; an axis value without point = mm (true) or increments
    double max_spindle_rpm = 0;        // 0 = no limit
    std::optional<double> max_live_tool_rpm;
    std::optional<double> max_cutting_feed;   // mm/min

    std::array<AxisValues, 6> work_offsets{};   // G54..G59: machine coordinates of each work zero
    // G54.1 P1..P<count>, the additional work coordinate systems ([FANUC] option: 48, or 300),
    // machine coordinates of each work zero; an unlisted one is zero.
    int additional_work_offset_count = 48;
    std::map<int, AxisValues> additional_work_offsets;
    AxisValues external_offset;                 // common to all six (parameter 1220, semantics.md §2.3)
    AxisValues work_shift;                      // G10 P0 register at power-on (lathe, semantics.md §2.6)
    std::array<AxisValues, 4> reference_points{};   // 1 = G28, 2–4 = G30 P2..P4; machine coordinates
    int tool_offset_count = 64;                 // offset numbers 1..count exist; unlisted ones are zero
    // The machine builder's M codes this machine has (`m_codes = ["M25", "M165"]`): with the list,
    // an M code neither the dialect nor the list has is a warning (K2011); without it, a note (K2010).
    std::vector<int> m_codes;
    std::map<int, ToolOffset> tools;            // by offset number
    CycleParameters cycle_parameters;
    Tailstock tailstock;
    Switches switches;

    // Keys whose value is "dialect" ("g52", "calculator_decimal", ...): resolve_for_dialect() fills
    // their fields; until then the fields hold the FANUC fallback. Kept after resolving, so that a
    // dump writes "dialect" again and the machine can be resolved for another dialect.
    std::vector<std::string> from_dialect;
    std::string resolved_dialect;      // the dialect the values were resolved for, "" if not
    bool follows_dialect(std::string_view key) const;

    double increment_mm() const { return kerf::machine::increment_mm(increment); }
    const Axis* axis(char letter) const;
    bool has_axis(char letter) const { return axis(letter) != nullptr; }
    std::string axis_letters() const;   // "XZCB"
    // The offset register, or nullptr when it is not listed (a listed number ≤ tool_offset_count
    // that is absent reads as zero).
    const ToolOffset* tool(int number) const;
};

// ---------------------------------------------------------------------------------------------
// Loading
// ---------------------------------------------------------------------------------------------

// "<source>: <key path>: what is wrong", 1-based line and column (0 if unknown): the dialect loader's.
using LoadError = dialects::LoadError;

struct LoadResult {
    std::optional<Machine> machine;
    std::vector<LoadError> errors;
};

class Registry;

// Parses one machine file. With `base = "<id>"` the file starts from that machine (looked up in
// `bases`; the built-ins by default) and changes only the keys it gives.
LoadResult load_machine_text(std::string_view toml_text, std::string_view source_name);
LoadResult load_machine_text(std::string_view toml_text, std::string_view source_name, const Registry& bases);

// Fills the "dialect" values (keys in from_dialect) from the dialect tables: G52/G53/G68 function
// ids, power-on codes, lexical calculator_decimal. Values set explicitly stay.
Machine resolve_for_dialect(Machine machine, const dialects::Dialect& dialect);

class Registry {
public:
    const Machine* find(std::string_view id) const;
    std::vector<std::string> ids() const;
    void add(Machine machine);   // replaces a machine with the same id
    // Loads a file (its base looked up here) and adds it.
    std::vector<LoadError> add_text(std::string_view toml_text, std::string_view source_name);
    // The machine whose `dialects` list names this dialect id, or nullptr.
    const Machine* for_dialect(std::string_view dialect_id) const;

private:
    std::deque<Machine> machines_;   // stable addresses
};

// The machines compiled into the binary (machine/data/*.toml), unresolved.
const Registry& builtin_machines();
// Errors from loading the built-ins (empty unless a data file is broken; tested).
const std::vector<LoadError>& builtin_machine_errors();

// The built-in default machine for a dialect id, resolved for that dialect (built-in dialects).
// Unknown ids fall back by the dialect's kind (fanuc-lathe / fanuc-mill), then to fanuc-mill.
const Machine& default_machine_for(std::string_view dialect_id);
// The same for any dialect (a user dialect too): its id, else its kind; resolved for it.
Machine default_machine_for(const dialects::Dialect& dialect);

// The built-in data file texts by file stem ("fanuc-lathe"), generated by dialects/embed.cmake.
std::span<const std::pair<std::string_view, std::string_view>> builtin_machine_texts();

// ---------------------------------------------------------------------------------------------
// Switch introspection (docs, `kerf machines`, tests) and dumping
// ---------------------------------------------------------------------------------------------

enum class SwitchType { choice, boolean, integer, number };

struct SwitchInfo {
    std::string_view key;                       // key in [switches]
    SwitchType type = SwitchType::choice;
    std::vector<std::string_view> choices;      // choice: the allowed spellings
    bool dialect_default = false;               // "dialect" is allowed (and is the built-ins' value)
    double min = 0, max = 0;                    // integer / number range
    std::string default_value;                  // the documented default, as written in a file
    std::string_view source;                    // reference section
    std::string_view meaning;
};

std::span<const SwitchInfo> switch_infos();
const SwitchInfo* find_switch(std::string_view key);
// The value in effect as it would be written in a file ("dog-leg", "true", "4", "0.5"), or nullopt
// for an unknown key. For a key in from_dialect this is the resolved value (the FANUC fallback
// before resolve_for_dialect).
std::optional<std::string> switch_value(const Machine& machine, std::string_view key);

// The machine as a complete TOML file (no base): loading it gives the same machine.
std::string machine_to_toml(const Machine& machine);

}  // namespace kerf::machine
