// The machine state of a dry run as one value (issue 13): where the tool is, the modal codes and
// the modes they set, the coordinate systems, feed, spindle and tool, compensation and the
// cycles' modal data. The executor keeps the live one and reads blocks with a MachineState it is
// given (executor.hpp): the live one through const functions for direct drawing's and
// compensation's next block, a copy whose point advances for a G70–G73 profile, so nothing a
// reading does can leak into the run. Internal to the interpreter library.
//
// A copy is 2.5 KB and at most two small allocations (the group slots, and the G66 arguments while
// a modal call is on): the state holds no table that grows with the program. The tables a program
// can grow (offset registers, G54.1 offsets, the dialect's variables, the macro variables) are the
// machine's memory (MachineMemory, and macro::Variables in the executor): a reading only reads
// them, through const functions of the executor and macro::evaluate's const Variables.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dialects/dialect.hpp"
#include "interpreter/compensation/radius_compensation.hpp"
#include "interpreter/cycles/context.hpp"
#include "interpreter/cycles/settings.hpp"
#include "interpreter/events.hpp"
#include "interpreter/macro/value.hpp"
#include "interpreter/setup.hpp"
#include "interpreter/transforms.hpp"
#include "motion/polar.hpp"
#include "motion/vec.hpp"

namespace kerf::interpreter {

// The modal state that motion reads on every block, derived from the active codes when a modal
// code changes (so a move does not search the code table).
struct ModalFlags {
    dialects::FunctionId motion;      // function id of group 01
    bool incremental = false;         // G91 (B/C, mills)
    bool per_revolution = false;      // G95/G99
    bool css = false;                 // G96
    bool inch = false;                // G20 (C: G70)
    motion::Plane plane = motion::Plane::xy;
    const dialects::CodeInfo* modal_cycle = nullptr;   // a modal canned cycle (G81.., lathe G83..)
    const dialects::CodeInfo* motion_cycle = nullptr;  // group 01 is a cycle (G90/G92/G94): X/Z blocks repeat it
};

// G66 modal macro call: called after each move block until G67 (dialects.md §3.7).
struct ModalCall {
    std::int64_t program = 0;
    std::int64_t repeats = 1;
    std::vector<std::pair<int, macro::Value>> arguments;
};

// [seed 004 G28 K F] the corner slow-down in force (executor_iso_specials.cpp, semantics.md §9.5).
struct Slowdown {
    double k_mm = 0;       // the distance before each G01 end point
    double fraction = 0;   // F percent / 100: the reduction
};

// [polar] G112/G107 in force (polar.cpp, cycles.md §18–§19).
struct PlaneTransform {
    motion::PlaneMap map;
    std::size_t linear = 0;   // the real axis of the plane's first coordinate (X; cylinder: Z for C)
    std::size_t rotary = 5;   // the rotary axis (C), degrees in the position
    double origin_deg = 0;    // polar: the rotary position at G112 = the plane's angle 0
    Position programmed{};    // the programmed point: rotary axis as mm of the virtual axis / arc
    std::string code;         // the code that started the mode (texts)
    std::optional<motion::P2> tool;   // under G41/G42: the tool centre in the plane (else the programmed point)
};

struct MachineState {
    MachineState(const dialects::Dialect& dialect, const Setup& setup);

    // --- modal codes: group → active code, one slot per group of the dialect (CodeInfo::group_index,
    // in the order of the group names), null while none is active; `flags` derived from them.
    std::vector<const dialects::CodeInfo*> modal;
    ModalFlags flags;

    // --- where the tool is ---------------------------------------------------------------------
    Position position{};             // work coordinates as programmed (lathe X diameter)
    // Where the axes stand (the machine end of the last motion event): an offset change moves the
    // work coordinates now and the axes with the next move (G43 H, a lathe T offset).
    Position machine_at{};
    // The programmed point when the tool stands elsewhere (past a corner of direct drawing, a
    // G45–G48 block, an offset point of compensation): the next block's coordinates are measured
    // from it (semantics.md §10.1).
    std::optional<Position> programmed;
    bool programmed_by_offset = false;   // programmed was set by a G45–G48 block (executor_offsets.cpp)
    // Under G41/G42 while the tool stands offset: the point of the programmed path (it differs from
    // `programmed` past a direct-drawing corner).
    std::optional<Position> comp_path;

    // --- coordinate systems (semantics.md §2) ----------------------------------------------------
    int work_system = 0;             // 0..5 = G54..G59
    int additional_system = 0;       // n of G54.1 Pn while one is selected (then work_system is unused)
    std::array<Position, 6> work_offsets{};   // G54..G59 (writable by #5221.., G10 L2)
    Position external_offset{};
    Position work_shift{};           // G10 P0 (lathe), subtracted (semantics.md §2.6)
    Position local_shift{};          // G52
    Position setting_shift{};        // G50/G92 correction
    std::array<std::optional<double>, kAxisCount> intermediate{};   // G28/G30 point, work coordinates
    // [transforms] G68 rotation, G15/G16 polar command, G50/G51 scaling, G50.1/G51.1 mirror.
    std::optional<Rotation> rotation;
    bool polar_command = false;      // G16 (power-on G15)
    std::optional<Scaling> scaling;  // G51 (power-on G50)
    Mirror mirror{};                 // G51.1 per axis (power-on G50.1)
    std::optional<PlaneTransform> transform;   // [polar] G112/G107 in force, else nullopt

    // --- feed, spindle, tool -------------------------------------------------------------------
    double feed = 0;
    double thread_lead = 0;          // lead of the thread being cut (F or E)
    double thread_lead_change = 0;   // G34 K: lead change per revolution (0 for G32)
    double spindle_rpm = 0;          // programmed S under G97
    double css = 0;                  // G96 S, m/min
    double max_rpm = 0;              // G50/G92 S clamp
    bool spindle_on = false;
    int tool = 0;
    int tool_offset = 0;
    int pending_tool = 0;            // mills: T selects, M06 changes
    std::array<std::optional<double>, 26> last_words{};   // B D E F H M N S T of the last blocks (#4102..#4120)

    // --- compensation (semantics.md §5–§7) -----------------------------------------------------
    compensation::RadiusCompensation radius_comp;
    int comp_side = 0;               // modal: +1 G41, −1 G42, 0 G40
    int length_sign = 0;             // +1 G43, −1 G44, 0 G49 (power-on)
    int length_h = 0;                // the H number in force
    double length_mm = 0;            // the signed offset on Z, mm, as commanded
    // The offset the axes have taken up: the commanded one from the next block that moves Z (or at
    // once, machine switch length_offset_motion). Machine positions use this one.
    double length_applied_mm = 0;
    std::optional<Event> pending_length_event;   // its coordinate_change, emitted when taken up

    // --- other modes ---------------------------------------------------------------------------
    std::optional<ModalCall> modal_call;   // G66
    bool soft_limits_on = true;      // G22 / G23
    bool thread_chamfer = true;      // [Haas] M23 / M24: chamfer out of a thread cycle
    std::optional<Slowdown> slowdown;   // [seed 004] G28 K F until G29

    // --- canned cycles (cycles.md §0) ----------------------------------------------------------
    cycles::Parameters cycle_parameters;   // persistent
    cycles::SingleCycleModal single_cycle;  // G90/G92/G94 repeat values
    cycles::DrillModal drill;               // drilling cycle levels for repeat blocks
    cycles::RigidTapModal rigid_tap;        // [spinner] SPINNER G384 until G380 (cycles/spinner.cpp)

    // Derived views.
    double unit_scale() const { return flags.inch ? 25.4 : 1.0; }
    double axis_scale(std::size_t a) const { return a < 3 ? unit_scale() : 1.0; }   // rotary: degrees
    motion::Plane plane() const { return flags.plane; }
    ProgramFrame program_frame() const { return {mirror, scaling, rotation}; }
};

// The machine's memory: what G10 and macro writes change and a program can grow without bound.
// Never copied: a block read ahead only reads it (the executor's look-ahead functions are const).
struct MachineMemory {
    std::map<int, ToolOffset> tools;              // offset registers (writable by #2001.., #10001..)
    std::map<int, Position> additional_offsets;   // G54.1 Pn, Haas G154 Pn (writable by #7001.., #14001.., G10 L20)
    std::map<std::int64_t, macro::Value> dialect_variables;   // [dialect variables] the dialect's [[variables]] ranges
    std::map<int, double> stored_system;          // #3003 #3004 #3901 #3902 ...: written, read back
    double clock_ms_offset = 0;                   // #3001 preset
    double clock_h_offset = 0;                    // #3002 preset
};

}  // namespace kerf::interpreter
