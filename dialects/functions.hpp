// The function vocabulary: every id a dialect's `function` key may name (docs/functions.md lists
// them; tests/dialects/test_functions.cpp keeps the two equal), what kerf does with a code of each
// (its traits), and named constants for the ids code refers to. Code looks codes up by what they
// do, never by number, so that G32 (A) and G33 (B/C) are one thing; an id is a `FunctionId`, so a
// misspelt one does not compile here and does not load from a dialect file.
#pragma once

#include <algorithm>
#include <cstdint>
#include <iosfwd>
#include <iterator>
#include <optional>
#include <span>
#include <string_view>

#include <fmt/format.h>

namespace kerf::dialects {

// What the code base does with a code, as bits, so that a block ORs its codes' traits and skips whole
// families of checks with one test. A code's traits are its function's (below) and its group's
// (`one_shot`, `motion_group`: CodeInfo::traits). Every trait has a bit of its own; the plane is two
// bits for three values (read it with `plane_of`).
namespace traits {
inline constexpr std::uint32_t cycle = 1u << 0;             // a canned cycle: its block does not move as a plain move (interpreter/cycles)
inline constexpr std::uint32_t profile_cycle = 1u << 1;     // P/Q are the N labels of a profile (G70–G73, cycles.md §1–§4)
inline constexpr std::uint32_t incremental = 1u << 2;       // G91: axis words are increments
inline constexpr std::uint32_t per_revolution = 1u << 3;    // feed per revolution
inline constexpr std::uint32_t css = 1u << 4;               // constant surface speed on
inline constexpr std::uint32_t inch = 1u << 5;              // inch input
inline constexpr std::uint32_t plane_xy = 1u << 6;          // plane selection: 1, 2 or 3 in the two bits of plane_mask
inline constexpr std::uint32_t plane_zx = 2u << 6;
inline constexpr std::uint32_t plane_yz = 3u << 6;
inline constexpr std::uint32_t plane_mask = 3u << 6;
inline constexpr std::uint32_t one_shot = 1u << 8;          // a G code of group 00 (G04, G10, G28, G53 ...): from the code's group
inline constexpr std::uint32_t motion_group = 1u << 9;      // a G code of group 01 (G00–G03, G32, modal cycles): from the code's group
inline constexpr std::uint32_t position_offset = 1u << 10;  // G45–G48 one-block offsets (FunctionDef::position_offset)
inline constexpr std::uint32_t radius_comp = 1u << 11;      // G40/G41/G42
inline constexpr std::uint32_t plane_transform = 1u << 12;  // G112/G113, G107 (cycles.md §18, §19)
inline constexpr std::uint32_t length_comp = 1u << 13;      // G43/G44/G49 and seed-004 G43/G44
inline constexpr std::uint32_t corner_slowdown = 1u << 14;  // seed-004 G28/G29 (semantics.md §9.4)
inline constexpr std::uint32_t approach_offset = 1u << 15;  // seed-004 G43/G44 without H (semantics.md §9.5)
inline constexpr std::uint32_t arc_approach = 1u << 16;     // seed-004 G12/G13
inline constexpr std::uint32_t program_transform = 1u << 17;   // G15/G16, G50/G51, G50.1/G51.1
inline constexpr std::uint32_t takes_arguments = 1u << 18;  // G65/G66: the block's other words are macro arguments
inline constexpr std::uint32_t linear = 1u << 19;           // G01: plain A/R may be direct drawing (SPINNER)
inline constexpr std::uint32_t calls_subprogram = 1u << 20; // M98
inline constexpr std::uint32_t threading = 1u << 21;        // cuts a thread (a block or a cycle): the lead needs a fixed rpm
inline constexpr std::uint32_t peck = 1u << 22;             // Q is the depth of one peck, more than 0
inline constexpr std::uint32_t radius_comp_on = 1u << 23;   // G41/G42: the tool left or right of the path
inline constexpr std::uint32_t not_in_plane_transform = 1u << 24;   // [FANUC] not allowed in G112/G107 mode (reference returns, G53, G50/G92, G52, threads, planes)
inline constexpr std::uint32_t not_modelled = 1u << 26;     // moves the machine in a way the dry run does not reproduce: a warning (kerf_warning::not_modelled, K5009)
inline constexpr std::uint32_t after_motion = 1u << 25;     // an M code that acts after the block's motion (semantics.md §1.2 step 9: M5, M9, M0, M1, M2, M30, M98, M99); the others act before it (step 3)
}  // namespace traits

enum class PlaneTrait : std::uint8_t { none, xy, zx, yz };
constexpr PlaneTrait plane_of(std::uint32_t bits) { return static_cast<PlaneTrait>((bits & traits::plane_mask) >> 6); }

// One id of the vocabulary. `letter` is the table of docs/functions.md it is listed in.
struct FunctionDef {
    std::string_view id;
    char letter = 'G';
    std::uint32_t traits = 0;
    std::string_view meaning;
    std::int8_t position_offset = 0;   // G45–G48: the move changes by this many D (+1, −1, +2, −2; semantics.md §9.3)
    std::int8_t work_coordinate = 0;   // G54–G59: 1–6
};

// Sorted by id (FunctionId::known searches it at compile time); entry 0 is "no function".
inline constexpr FunctionDef kFunctionDefs[] = {
    {"", 'G', 0, "no function"},
    {"absolute-programming", 'G', 0, "Absolute programming"},
    {"accuracy-control", 'G', 0, "[Haas] G187: smoothness P1 rough, P2 medium, P3 finish and the corner rounding E of the path"},
    {"arc-approach", 'G', traits::arc_approach, "Seed-004 G12: tangential arc approach to the contour"},
    {"arc-exit", 'G', traits::arc_approach, "Seed-004 G13: tangential arc exit from the contour"},
    {"automatic-corner-override", 'G', 0, "Automatic feed override at inside corners"},
    {"automatic-tool-comp-x", 'G', traits::not_modelled, "Automatic tool compensation, X axis (lathe)"},
    {"automatic-tool-comp-z", 'G', traits::not_modelled, "Automatic tool compensation, Z axis (lathe)"},
    {"axial-offset-direction-minus", 'G', traits::length_comp | traits::approach_offset, "Seed-004 'direction of axial offset' (−)"},
    {"axial-offset-direction-plus", 'G', traits::length_comp | traits::approach_offset, "Seed-004 'direction of axial offset' (+), used as a one-block approach offset by D – not FANUC length compensation"},
    {"axis-homing", 'G', traits::not_modelled, "Home (machine-zero search) of the named axes (ADV400 G74)"},
    {"b-axis-torque-limit-off", 'M', 0, "B-axis torque limitation off"},
    {"b-axis-torque-limit-on", 'M', 0, "B-axis torque limitation on"},
    {"back-boring-cycle", 'G', traits::cycle, "Back boring cycle"},
    {"bar-feed", 'M', 0, "Bar feed"},
    {"bar-feeder-advance", 'M', 0, "Bar feeder advance"},
    {"bolt-hole-pattern", 'G', traits::cycle, "[Haas] mill G70/G71/G72: holes on a circle, an arc or a line, each made by the active drilling cycle"},
    {"boring-cycle", 'G', traits::cycle, "Boring cycle, feed out"},
    {"boring-dwell-cycle", 'G', traits::cycle, "Boring cycle with dwell, feed out"},
    {"boring-manual-retract-cycle", 'G', traits::cycle, "Boring cycle with dwell and manual retract"},
    {"boring-spindle-stop-cycle", 'G', traits::cycle, "Boring cycle, spindle stop and rapid out"},
    {"c-axis-mode-off", 'M', 0, "C axis back to spindle mode (spindle 1)"},
    {"c-axis-mode-off-coupled", 'M', 0, "C-axis mode off, coupled spindles"},
    {"c-axis-mode-off-spindle-2", 'M', 0, "C-axis mode off, spindle 2"},
    {"c-axis-mode-off-supercap", 'M', 0, "SuperCap C-axis mode disable"},
    {"c-axis-mode-on", 'M', 0, "Spindle (1) to C-axis mode"},
    {"c-axis-mode-on-coupled", 'M', 0, "C-axis mode on, spindles 1 and 2 coupled"},
    {"c-axis-mode-on-spindle-2", 'M', 0, "C-axis mode on, spindle 2"},
    {"c-axis-mode-on-supercap", 'M', 0, "SuperCap C-axis mode enable"},
    {"c-axis-supercap-spindle-1", 'M', 0, "SuperCap: C axis on spindle 1"},
    {"c-axis-supercap-spindle-2", 'M', 0, "SuperCap: C axis on spindle 2"},
    {"cancel-coordinate-setting", 'G', 0, "Cancel a coordinate system setting / workpiece coordinate preset (restore the work system)"},
    {"canned-cycle-cancel", 'G', 0, "Canned cycle cancel"},
    {"chip-conveyor-off", 'M', 0, "Chip conveyor off"},
    {"chip-conveyor-on", 'M', 0, "Chip conveyor on"},
    {"chuck-close", 'M', 0, "Close main chuck"},
    {"chuck-close-no-part", 'M', 0, "Close main chuck without part"},
    {"chuck-open", 'M', 0, "Open main chuck"},
    {"circular-ccw", 'G', 0, "Circular (helical) interpolation counter-clockwise"},
    {"circular-cw", 'G', 0, "Circular (helical) interpolation clockwise"},
    {"circular-pocket-ccw", 'G', traits::cycle, "[Haas] G13: circular pocket milling counter-clockwise (I first radius, K finish radius, Q step, Z depth)"},
    {"circular-pocket-cw", 'G', traits::cycle, "[Haas] G12: circular pocket milling clockwise (I first radius, K finish radius, Q step, Z depth)"},
    {"clamp-external-main", 'M', 0, "External clamping, main spindle"},
    {"clamp-external-sub", 'M', 0, "External clamping, sub-spindle"},
    {"clamp-internal-main", 'M', 0, "Internal clamping, main spindle"},
    {"clamp-internal-sub", 'M', 0, "Internal clamping, sub-spindle"},
    {"constant-surface-speed", 'G', traits::css, "Constant surface speed on (S in m/min)"},
    {"constant-surface-speed-cancel", 'G', 0, "Constant surface speed off (S in rpm)"},
    {"continue-during-parts-catcher", 'M', 0, "Continue the program during M432"},
    {"continuous-cutting-mode", 'G', 0, "Continuous (blending) cutting mode, cancels exact-stop mode"},
    {"coolant-high-pressure-on", 'M', 0, "High-pressure coolant on"},
    {"coolant-high-pressure-valve", 'M', 0, "High-pressure coolant valve"},
    {"coolant-mist-on", 'M', 0, "Coolant 2 / mist on"},
    {"coolant-off", 'M', traits::after_motion, "Coolant off (all)"},
    {"coolant-on", 'M', 0, "Coolant (1) on"},
    {"coolant-over-main-spindle-off", 'M', 0, "Coolant over the main spindle off"},
    {"coolant-over-main-spindle-on", 'M', 0, "Coolant over the main spindle on"},
    {"coolant-over-subspindle-off", 'M', 0, "Coolant over the sub-spindle off"},
    {"coolant-over-subspindle-on", 'M', 0, "Coolant over the sub-spindle on"},
    {"coolant-pump-2-on", 'M', 0, "Second coolant pump on"},
    {"coolant-pump-off", 'M', 0, "Coolant pump only off"},
    {"coolant-through-subspindle-off", 'M', 0, "Coolant through the sub-spindle off"},
    {"coolant-through-subspindle-on", 'M', 0, "Coolant through the sub-spindle on"},
    {"coordinate-rotation", 'G', 0, "Coordinate system rotation, + = counter-clockwise (FANUC)"},
    {"coordinate-rotation-cancel", 'G', 0, "Coordinate system rotation cancel"},
    {"coordinate-rotation-cw", 'G', 0, "Coordinate system rotation, + = CLOCKWISE (ADV400; negate R when converting)"},
    {"coordinate-system-setting", 'G', traits::not_in_plane_transform, "Coordinate system setting: the current position takes the programmed values (lathes: S = max rpm clamp)"},
    {"corner-circular-interpolation", 'G', traits::not_modelled, "Corner offset circular interpolation (cutter compensation)"},
    {"corner-slowdown", 'G', traits::corner_slowdown, "Seed-004 G28: feed reduced by F % over the last K mm before each G01 end point"},
    {"corner-slowdown-cancel", 'G', traits::corner_slowdown, "Seed-004 G29: cancel the corner slow-down"},
    {"cylindrical-interpolation", 'G', traits::plane_transform, "Cylindrical interpolation on/off (G07.1 C<r> / C0)"},
    {"door-open", 'M', 0, "Automatic door opening"},
    {"double-turret-mirror-off", 'G', traits::not_modelled, "FANUC T mirror image for double turrets / balance cut off"},
    {"double-turret-mirror-on", 'G', traits::not_modelled, "FANUC T mirror image for double turrets / balance cut on"},
    {"drilling-cycle", 'G', traits::cycle, "Drilling cycle (feed in, rapid out)"},
    {"drilling-dwell-cycle", 'G', traits::cycle, "Drilling cycle with dwell at the bottom"},
    {"dwell", 'G', 0, "Dwell (units differ: FANUC X/U s, P ms; ADV400 X/P s)"},
    {"dynamic-work-offset", 'G', traits::not_modelled, "[Haas] G254: dynamic work offset (the work offset follows the rotary axes)"},
    {"dynamic-work-offset-cancel", 'G', 0, "[Haas] G255: dynamic work offset cancel"},
    {"engraving", 'G', traits::cycle, "[Haas] G47: text or serial number engraving"},
    {"exact-stop-check", 'G', 0, "Exact stop at the end of this block only"},
    {"exact-stop-mode", 'G', 0, "Exact stop at every block end (modal)"},
    {"face-boring-cycle", 'G', traits::cycle, "Lathe face boring cycle"},
    {"face-drilling-cycle", 'G', traits::cycle, "Lathe face (axial) drilling / peck drilling with C indexing (live tool)"},
    {"face-peck-drilling-cycle", 'G', traits::cycle | traits::peck, "Lathe end-face peck drilling / face grooving cycle"},
    {"face-tapping-cycle", 'G', traits::cycle, "Lathe face tapping cycle"},
    {"facing-cycle", 'G', traits::cycle, "Single end-face (step) turning cycle"},
    {"feed-per-minute", 'G', 0, "Feed per minute (mm/min)"},
    {"feed-per-revolution", 'G', traits::per_revolution, "Feed per revolution (mm/rev)"},
    {"fine-boring-cycle", 'G', traits::cycle, "Mill fine boring cycle"},
    {"finishing-cycle", 'G', traits::cycle | traits::profile_cycle, "Lathe finishing cycle over profile P..Q"},
    {"floating-reference-return", 'G', traits::not_modelled, "Floating reference point return"},
    {"grooving-cycle", 'G', traits::cycle, "Lathe OD/ID grooving (X peck) cycle"},
    {"high-speed-peck-drilling-cycle", 'G', traits::cycle | traits::peck, "Mill high-speed peck drilling cycle"},
    {"inch-input", 'G', traits::inch, "Inch input"},
    {"incremental-programming", 'G', traits::incremental, "Incremental programming"},
    {"jaws-close", 'M', 0, "Close spindle jaws (§9.7)"},
    {"jaws-open", 'M', 0, "Open spindle jaws (§9.7)"},
    {"left-hand-tapping-cycle", 'G', traits::cycle, "Mill left-hand (counter) tapping cycle"},
    {"linear", 'G', traits::linear, "Straight-line move at the cutting feed"},
    {"live-tool-ccw", 'M', 0, "Live tool counter-clockwise (SPINNER M24)"},
    {"live-tool-cw", 'M', 0, "Live tool clockwise (SPINNER M23; thread-exit meaning in §9.1)"},
    {"live-tool-rigid-tapping", 'G', traits::cycle, "SPINNER G384: rigid tapping with a live tool (repeat G384 in every hole block)"},
    {"live-tool-rigid-tapping-cancel", 'G', traits::cycle, "SPINNER G380: cancel G384"},
    {"live-tool-stop", 'M', traits::after_motion, "Live tool stop"},
    {"local-subprogram-call", 'M', traits::after_motion, "[Haas] M97 P: call a label of this program as a local subroutine (references/references.hpp)"},
    {"local-system-cancel", 'G', 0, "Cancel the local coordinate system (pcnc-mill G152)"},
    {"local-system-current-point", 'G', traits::not_in_plane_transform, "Local coordinate system placed so that the current tool point takes the programmed values"},
    {"local-system-shift", 'G', traits::not_in_plane_transform, "FANUC local coordinate system: origin shifted by the programmed vector"},
    {"look-ahead-control", 'G', 0, "FANUC G05.1 Q1/Q0 (AI contour control / advanced preview) and G08: look-ahead on or off"},
    {"look-ahead-limit", 'G', 0, "[Haas] G103 P: the blocks the control may read ahead (P0 or none: no limit)"},
    {"machine-builder-code", 'M', 0, "A machine builder's code whose meaning kerf does not model (user dialects; en/ru say what it does)"},
    {"machine-coordinate-select", 'G', traits::not_in_plane_transform, "One-shot move in machine coordinates (rapid, offsets ignored)"},
    {"machine-coordinate-select-g0-g1", 'G', traits::not_in_plane_transform, "One-shot move in machine coordinates with the active G0 or G1 (F allowed)"},
    {"macro-call", 'G', traits::takes_arguments, "Custom macro call (one-shot)"},
    {"main-spindle-air-off", 'M', 0, "Main spindle air off"},
    {"main-spindle-air-on", 'M', 0, "Main spindle air on"},
    {"main-spindle-winding-auto", 'M', 0, "Main spindle star/delta automatic"},
    {"main-spindle-winding-delta", 'M', 0, "Main spindle delta winding"},
    {"main-spindle-winding-star", 'M', 0, "Main spindle star winding"},
    {"metric-input", 'G', 0, "Metric input"},
    {"mirror", 'G', traits::program_transform, "Programmable mirror image"},
    {"mirror-cancel", 'G', traits::program_transform, "Programmable mirror image cancel"},
    {"modal-macro-call", 'G', traits::takes_arguments, "Modal custom macro call (after every move)"},
    {"modal-macro-call-cancel", 'G', 0, "Modal macro call cancel"},
    {"multiple-threading-cycle", 'G', traits::cycle | traits::threading, "Multi-pass threading cycle (two blocks)"},
    {"one-block-face-peck-cycle", 'G', traits::cycle | traits::peck, "[Haas] lathe G74 X Z I K D: end-face grooving / peck drilling in one block (K Z peck, I X step)"},
    {"one-block-grooving-cycle", 'G', traits::cycle | traits::peck, "[Haas] lathe G75 X Z I K D: O.D./I.D. grooving in one block (I X peck, K Z step)"},
    {"one-block-pattern-repeating-cycle", 'G', traits::cycle | traits::profile_cycle, "[Haas] lathe G73 P Q I K D U W: irregular path stock removal in one block (D passes)"},
    {"one-block-rough-facing-cycle", 'G', traits::cycle | traits::profile_cycle, "[Haas] lathe G72 P Q U W D: end-face stock removal in one block (D depth of cut)"},
    {"one-block-rough-turning-cycle", 'G', traits::cycle | traits::profile_cycle, "[Haas] lathe G71 P Q U W D: O.D./I.D. stock removal in one block (D depth of cut)"},
    {"one-block-threading-cycle", 'G', traits::cycle | traits::threading, "[Haas] lathe G76 X Z K D A: multiple pass threading in one block (K thread height, D first depth)"},
    {"optional-stop", 'M', traits::after_motion, "Optional stop"},
    {"part-counter", 'M', 0, "Part counter"},
    {"part-off-control", 'M', 0, "Part-off control"},
    {"parts-catcher-cycle", 'M', traits::cycle, "Parts-catcher cycle"},
    {"parts-catcher-in", 'M', 0, "Parts catcher in"},
    {"parts-catcher-out", 'M', 0, "Parts catcher out"},
    {"pattern-repeating-cycle", 'G', traits::cycle | traits::profile_cycle, "Lathe pattern repeating cycle"},
    {"peck-drilling-cycle", 'G', traits::cycle | traits::peck, "Peck (deep-hole) drilling cycle on a mill-type axis layout"},
    {"plane-xy", 'G', traits::plane_xy | traits::not_in_plane_transform, "Plane selection XY (Xp-Yp)"},
    {"plane-yz", 'G', traits::plane_yz | traits::not_in_plane_transform, "Plane selection YZ (Yp-Zp)"},
    {"plane-zx", 'G', traits::plane_zx | traits::not_in_plane_transform, "Plane selection ZX (Zp-Xp)"},
    {"pocket-milling-cycle", 'G', traits::cycle, "[Haas] G150: general purpose pocket milling over the contour of subprogram P"},
    {"polar-coordinate-command", 'G', traits::program_transform, "Polar coordinate command (end point as radius and angle)"},
    {"polar-coordinate-command-cancel", 'G', traits::program_transform, "Polar coordinate command cancel"},
    {"polar-interpolation-off", 'G', traits::plane_transform, "Polar coordinate interpolation cancel"},
    {"polar-interpolation-on", 'G', traits::plane_transform, "Polar coordinate interpolation mode (Cartesian programming with a rotary axis)"},
    {"polygon-turning-off", 'G', traits::not_modelled, "Polygon turning cancel"},
    {"polygon-turning-on", 'G', traits::not_modelled, "Polygon turning"},
    {"position-offset-decrease", 'G', traits::position_offset, "One-block position offset: move decreased by D", -1},
    {"position-offset-double-decrease", 'G', traits::position_offset, "One-block position offset: move decreased by 2·D", -2},
    {"position-offset-double-increase", 'G', traits::position_offset, "One-block position offset: move increased by 2·D", 2},
    {"position-offset-increase", 'G', traits::position_offset, "One-block position offset: move increased by D", 1},
    {"program-end", 'M', traits::after_motion, "End of program (no rewind)"},
    {"program-end-rewind", 'M', traits::after_motion, "End of program and rewind"},
    {"program-stop", 'M', traits::after_motion, "Program stop"},
    {"programmable-data-input", 'G', 0, "Programmable data input: offsets, work shift (G10 P0), parameters"},
    {"programmable-data-input-cancel", 'G', 0, "End of programmable data input mode"},
    {"radius-comp-cancel", 'G', traits::radius_comp, "Tool nose / cutter radius compensation cancel"},
    {"radius-comp-left", 'G', traits::radius_comp | traits::radius_comp_on, "Tool nose / cutter radius compensation, tool left of the path"},
    {"radius-comp-right", 'G', traits::radius_comp | traits::radius_comp_on, "Tool nose / cutter radius compensation, tool right of the path"},
    {"rapid", 'G', 0, "Positioning at rapid traverse (linear or dog-leg by machine)"},
    {"reference-return", 'G', traits::not_in_plane_transform, "Return to the (1st) reference point / machine zero via an intermediate point"},
    {"reference-return-check", 'G', 0, "Reference position return check"},
    {"reference-return-nth", 'G', traits::not_in_plane_transform, "Return to the 2nd/3rd/4th reference point (P); pcnc-mill also P1"},
    {"return-from-reference", 'G', traits::not_in_plane_transform, "Return from the reference point via the stored intermediate point"},
    {"return-initial-level", 'G', 0, "Canned cycle return to the initial level"},
    {"return-r-level", 'G', 0, "Canned cycle return to the R-point level"},
    {"rigid-tapping-mode", 'M', 0, "FANUC rigid tapping mode"},
    {"rough-facing-cycle", 'G', traits::cycle | traits::profile_cycle, "Lathe stock removal in facing (roughing along X)"},
    {"rough-turning-cycle", 'G', traits::cycle | traits::profile_cycle, "Lathe stock removal in turning (roughing along Z)"},
    {"scaling", 'G', traits::program_transform, "Scaling"},
    {"scaling-cancel", 'G', traits::program_transform, "Scaling cancel"},
    {"side-boring-cycle", 'G', traits::cycle, "Lathe side (radial) boring cycle"},
    {"side-drilling-cycle", 'G', traits::cycle, "Lathe side (radial) drilling cycle"},
    {"side-tapping-cycle", 'G', traits::cycle, "Lathe side (radial) tapping cycle"},
    {"single-direction-positioning", 'G', traits::not_modelled, "Single-direction positioning (backlash removal)"},
    {"skip-function", 'G', traits::not_modelled, "Skip function (move until the skip signal)"},
    {"spindle-brake-low-off", 'M', 0, "Low brake pressure / brake off (TC82-108)"},
    {"spindle-brake-low-on", 'M', 0, "Main spindle brake with reduced force / low pressure on"},
    {"spindle-brake-off", 'M', 0, "Main spindle brake off"},
    {"spindle-brake-on", 'M', 0, "Main spindle brake on"},
    {"spindle-ccw", 'M', 0, "Spindle counter-clockwise"},
    {"spindle-cw", 'M', 0, "Spindle clockwise"},
    {"spindle-fluctuation-detect-off", 'G', 0, "FANUC spindle speed fluctuation detection off"},
    {"spindle-fluctuation-detect-on", 'G', 0, "FANUC spindle speed fluctuation detection on (alarm on deviation)"},
    {"spindle-flushing-off", 'M', 0, "Spindle (chip) flushing off"},
    {"spindle-flushing-on", 'M', 0, "Spindle (chip) flushing on"},
    {"spindle-index-position-1", 'M', 0, "Spindle indexing to position 1"},
    {"spindle-index-position-2", 'M', 0, "Spindle indexing to position 2"},
    {"spindle-index-position-3", 'M', 0, "Spindle indexing to position 3"},
    {"spindle-index-position-4", 'M', 0, "Spindle indexing to position 4"},
    {"spindle-orientation", 'M', 0, "Spindle orientation"},
    {"spindle-phase-sync-on", 'M', 0, "Phase and speed synchronisation on"},
    {"spindle-rigid-tapping-cycle", 'M', traits::cycle, "SPINNER M329: rigid tapping cycle with the work spindle"},
    {"spindle-speed-detect-off", 'G', 0, "ADV400 spindle speed detection off (no wait for the spindle)"},
    {"spindle-speed-detect-on", 'G', 0, "ADV400 spindle speed detection on (next block waits until the spindle is at speed)"},
    {"spindle-stop", 'M', traits::after_motion, "Spindle stop"},
    {"spindle-sync-off", 'M', 0, "Synchronisation off"},
    {"spindle-sync-on", 'M', 0, "Main/sub-spindle speed synchronisation on"},
    {"stroke-check-off", 'G', 0, "Stored stroke check off"},
    {"stroke-check-on", 'G', 0, "Stored stroke check on"},
    {"subprogram-call", 'M', traits::calls_subprogram | traits::after_motion, "Subprogram call"},
    {"subprogram-return", 'M', traits::after_motion, "End of subprogram / return"},
    {"subspindle-air-off", 'M', 0, "Sub-spindle air off"},
    {"subspindle-air-on", 'M', 0, "Sub-spindle air on"},
    {"subspindle-brake-low-on", 'M', 0, "Sub-spindle brake with reduced force on"},
    {"subspindle-brake-off", 'M', 0, "Sub-spindle brake off"},
    {"subspindle-brake-on", 'M', 0, "Sub-spindle brake on"},
    {"subspindle-ccw", 'M', 0, "Sub-spindle counter-clockwise"},
    {"subspindle-chuck-close", 'M', 0, "Close sub-spindle chuck"},
    {"subspindle-chuck-close-no-part", 'M', 0, "Close sub-spindle chuck without part"},
    {"subspindle-chuck-open", 'M', 0, "Open sub-spindle chuck"},
    {"subspindle-cw", 'M', 0, "Sub-spindle clockwise"},
    {"subspindle-jaw-blow", 'M', 0, "Sub-spindle jaw blowing"},
    {"subspindle-orientation", 'M', 0, "Sub-spindle orientation"},
    {"subspindle-stop", 'M', traits::after_motion, "Sub-spindle stop"},
    {"subspindle-winding-auto", 'M', 0, "Sub-spindle star/delta automatic"},
    {"subspindle-winding-delta", 'M', 0, "Sub-spindle delta winding"},
    {"subspindle-winding-star", 'M', 0, "Sub-spindle star winding"},
    {"tailstock-clamping-cycle-1", 'G', traits::cycle, "SPINNER G138: tailstock clamping (I), E1 clamp / E2 release"},
    {"tailstock-clamping-cycle-2", 'G', traits::cycle, "SPINNER G238: tailstock clamping (II) with X/Z positioning, E1 clamp / E2 release"},
    {"tailstock-coupling-carry", 'G', traits::cycle, "SPINNER G100: couple the tailstock to the carriage and carry it to Z (I1: home)"},
    {"tailstock-coupling-position", 'G', traits::cycle, "SPINNER G101: carriage to the tailstock coupling position"},
    {"tailstock-fix", 'M', 0, "Tailstock fixing (decouple and clamp)"},
    {"tailstock-quill-back", 'M', 0, "Tailstock quill back"},
    {"tailstock-quill-forward", 'M', 0, "Tailstock quill forward"},
    {"tailstock-release", 'M', 0, "Tailstock release"},
    {"tapping-cycle", 'G', traits::cycle, "Tapping cycle (spindle reverses at the bottom)"},
    {"tapping-mode", 'G', 0, "Tapping mode (overrides fixed, no exact-stop check)"},
    {"thread-chamfer-off", 'M', 0, "[Haas] lathe M24: no chamfer (pull-out) at the end of a thread cycle"},
    {"thread-chamfer-on", 'M', 0, "[Haas] lathe M23: chamfer (pull-out) at the end of a thread cycle"},
    {"thread-cutting", 'G', traits::threading | traits::not_in_plane_transform, "Thread cutting block (lead F, or E)"},
    {"thread-cutting-cycle", 'G', traits::cycle | traits::threading, "Single thread cutting cycle"},
    {"tool-change", 'M', 0, "Tool change"},
    {"tool-length-comp-cancel", 'G', traits::length_comp, "Tool length compensation cancel"},
    {"tool-length-comp-minus", 'G', traits::length_comp, "Tool length compensation, − direction (H)"},
    {"tool-length-comp-plus", 'G', traits::length_comp, "Tool length compensation, + direction (H)"},
    {"turning-cycle", 'G', traits::cycle, "Single OD/ID turning cycle"},
    {"turret-index-during-motion", 'M', 0, "Allow turret indexing while the axes move"},
    {"turret-lock", 'M', 0, "Turret lock"},
    {"turret-unlock", 'M', 0, "Turret unlock"},
    {"undocumented", 'M', 0, "Code mentioned in a seed without a usable meaning"},
    {"unloader-back", 'M', 0, "Unloader back"},
    {"unloader-done", 'M', 0, "Unloader finished"},
    {"unloader-forward", 'M', 0, "Unloader forward"},
    {"unloader-start", 'M', 0, "Unloader start"},
    {"variable-lead-thread-cutting", 'G', traits::threading, "Variable-lead thread cutting"},
    {"washing-liquid-off", 'M', 0, "Washing liquid off"},
    {"work-coordinate-1", 'G', 0, "Work coordinate system 1", 0, 1},
    {"work-coordinate-2", 'G', 0, "Work coordinate system 2", 0, 2},
    {"work-coordinate-3", 'G', 0, "Work coordinate system 3", 0, 3},
    {"work-coordinate-4", 'G', 0, "Work coordinate system 4", 0, 4},
    {"work-coordinate-5", 'G', 0, "Work coordinate system 5", 0, 5},
    {"work-coordinate-6", 'G', 0, "Work coordinate system 6", 0, 6},
    {"work-coordinate-additional", 'G', 0, "Additional work coordinate systems (G54.1 P1–P48, [Haas] G154 P1–P99 and G110–G129)"},
    {"workpiece-transfer-cycle", 'G', traits::cycle, "SPINNER G38: push the part into the sub-spindle (torque limited), check position, clamp"},
};

class FunctionId {
public:
    constexpr FunctionId() = default;   // no function
    // A known id, checked at compile time: an unknown one does not compile.
    static consteval FunctionId known(std::string_view id) {
        const std::optional<FunctionId> f = lookup(id);
        if (!f) throw "unknown function id: add it to kFunctionDefs and docs/functions.md";
        return *f;
    }
    // The loader's lookup (dialect files, user input).
    static constexpr std::optional<FunctionId> find(std::string_view id) {
        if (id.empty()) return std::nullopt;
        return lookup(id);
    }
    static constexpr std::span<const FunctionDef> all() { return {kFunctionDefs + 1, std::size(kFunctionDefs) - 1}; }

    constexpr const FunctionDef& def() const { return kFunctionDefs[index_]; }
    constexpr std::string_view name() const { return def().id; }
    constexpr std::uint16_t index() const { return index_; }
    constexpr bool empty() const { return index_ == 0; }
    constexpr explicit operator bool() const { return index_ != 0; }
    friend constexpr bool operator==(FunctionId, FunctionId) = default;
    friend constexpr auto operator<=>(FunctionId, FunctionId) = default;

private:
    constexpr explicit FunctionId(std::uint16_t index) : index_(index) {}
    static constexpr std::optional<FunctionId> lookup(std::string_view id) {
        const auto begin = std::begin(kFunctionDefs), end = std::end(kFunctionDefs);
        const auto it = std::lower_bound(begin, end, id, [](const FunctionDef& d, std::string_view v) { return d.id < v; });
        if (it == end || it->id != id) return std::nullopt;
        return FunctionId(static_cast<std::uint16_t>(it - begin));
    }
    std::uint16_t index_ = 0;
};

std::ostream& operator<<(std::ostream& out, FunctionId f);   // its name (test messages)

// The closest known ids to a misspelt one ("linaer" → "linear"), for load errors.
std::optional<std::string_view> closest_function_id(std::string_view id);
// The closest of `candidates` to a misspelt word, within a few typos (not another word), for load
// errors ("program_not_fund" → "program_not_found").
std::optional<std::string_view> closest_name(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace kerf::dialects

template <>
struct fmt::formatter<kerf::dialects::FunctionId> : fmt::formatter<std::string_view> {
    auto format(kerf::dialects::FunctionId f, format_context& ctx) const {
        return fmt::formatter<std::string_view>::format(f.name(), ctx);
    }
};

// Named constants for the ids code refers to (the full vocabulary is the table above).
namespace kerf::dialects::functions {

inline constexpr FunctionId rapid = FunctionId::known("rapid");
inline constexpr FunctionId linear = FunctionId::known("linear");
inline constexpr FunctionId dwell = FunctionId::known("dwell");
inline constexpr FunctionId macro_call = FunctionId::known("macro-call");
inline constexpr FunctionId modal_macro_call = FunctionId::known("modal-macro-call");
inline constexpr FunctionId subprogram_call = FunctionId::known("subprogram-call");
inline constexpr FunctionId subprogram_return = FunctionId::known("subprogram-return");
// [Haas] M97 P: no built-in dialect has it yet (issue 15's Haas dialects); the resolver knows it.
inline constexpr FunctionId local_subprogram_call = FunctionId::known("local-subprogram-call");
inline constexpr FunctionId circular_cw = FunctionId::known("circular-cw");
inline constexpr FunctionId circular_ccw = FunctionId::known("circular-ccw");
inline constexpr FunctionId thread_cutting = FunctionId::known("thread-cutting");
inline constexpr FunctionId absolute_programming = FunctionId::known("absolute-programming");
inline constexpr FunctionId incremental_programming = FunctionId::known("incremental-programming");
inline constexpr FunctionId feed_per_minute = FunctionId::known("feed-per-minute");
inline constexpr FunctionId feed_per_revolution = FunctionId::known("feed-per-revolution");
inline constexpr FunctionId css_on = FunctionId::known("constant-surface-speed");
inline constexpr FunctionId css_off = FunctionId::known("constant-surface-speed-cancel");
inline constexpr FunctionId coordinate_system_setting = FunctionId::known("coordinate-system-setting");
inline constexpr FunctionId cancel_coordinate_setting = FunctionId::known("cancel-coordinate-setting");
inline constexpr FunctionId machine_coordinate_select = FunctionId::known("machine-coordinate-select");
inline constexpr FunctionId machine_coordinate_select_g0_g1 = FunctionId::known("machine-coordinate-select-g0-g1");
inline constexpr FunctionId programmable_data_input = FunctionId::known("programmable-data-input");
inline constexpr FunctionId reference_return = FunctionId::known("reference-return");
inline constexpr FunctionId local_system_shift = FunctionId::known("local-system-shift");
inline constexpr FunctionId local_system_current_point = FunctionId::known("local-system-current-point");
inline constexpr FunctionId local_system_cancel = FunctionId::known("local-system-cancel");
inline constexpr FunctionId plane_xy = FunctionId::known("plane-xy");
inline constexpr FunctionId plane_zx = FunctionId::known("plane-zx");
inline constexpr FunctionId plane_yz = FunctionId::known("plane-yz");
inline constexpr FunctionId inch_input = FunctionId::known("inch-input");
inline constexpr FunctionId metric_input = FunctionId::known("metric-input");
inline constexpr FunctionId spindle_cw = FunctionId::known("spindle-cw");
inline constexpr FunctionId spindle_ccw = FunctionId::known("spindle-ccw");
inline constexpr FunctionId spindle_stop = FunctionId::known("spindle-stop");
inline constexpr FunctionId coolant_on = FunctionId::known("coolant-on");
inline constexpr FunctionId coolant_off = FunctionId::known("coolant-off");
inline constexpr FunctionId program_stop = FunctionId::known("program-stop");
inline constexpr FunctionId optional_stop = FunctionId::known("optional-stop");
inline constexpr FunctionId program_end = FunctionId::known("program-end");
inline constexpr FunctionId program_end_rewind = FunctionId::known("program-end-rewind");
inline constexpr FunctionId tool_change = FunctionId::known("tool-change");
inline constexpr FunctionId skip_function = FunctionId::known("skip-function");   // G31
inline constexpr FunctionId reference_return_check = FunctionId::known("reference-return-check");   // G27
inline constexpr FunctionId reference_return_nth = FunctionId::known("reference-return-nth");
inline constexpr FunctionId return_from_reference = FunctionId::known("return-from-reference");
inline constexpr FunctionId coordinate_rotation = FunctionId::known("coordinate-rotation");
inline constexpr FunctionId coordinate_rotation_cw = FunctionId::known("coordinate-rotation-cw");
inline constexpr FunctionId coordinate_rotation_cancel = FunctionId::known("coordinate-rotation-cancel");
inline constexpr FunctionId modal_macro_call_cancel = FunctionId::known("modal-macro-call-cancel");
inline constexpr FunctionId stroke_check_on = FunctionId::known("stroke-check-on");
inline constexpr FunctionId stroke_check_off = FunctionId::known("stroke-check-off");
inline constexpr FunctionId polar_interpolation_on = FunctionId::known("polar-interpolation-on");     // G12.1/G112 (cycles.md §18)
inline constexpr FunctionId polar_interpolation_off = FunctionId::known("polar-interpolation-off");   // G13.1/G113
inline constexpr FunctionId cylindrical_interpolation = FunctionId::known("cylindrical-interpolation");   // G07.1/G107 (cycles.md §19)
// [FANUC] programmable transforms of mills (interpreter/executor_transforms.cpp).
inline constexpr FunctionId polar_coordinate_command = FunctionId::known("polar-coordinate-command");                 // G16
inline constexpr FunctionId polar_coordinate_command_cancel = FunctionId::known("polar-coordinate-command-cancel");   // G15
inline constexpr FunctionId scaling = FunctionId::known("scaling");                                                   // G51
inline constexpr FunctionId scaling_cancel = FunctionId::known("scaling-cancel");                                     // G50
inline constexpr FunctionId mirror = FunctionId::known("mirror");                                                     // G51.1
inline constexpr FunctionId mirror_cancel = FunctionId::known("mirror-cancel");                                       // G50.1

// Compensation (reference/semantics.md §5–§7; interpreter/executor_compensation.cpp).
inline constexpr FunctionId radius_comp_cancel = FunctionId::known("radius-comp-cancel");
inline constexpr FunctionId radius_comp_left = FunctionId::known("radius-comp-left");
inline constexpr FunctionId radius_comp_right = FunctionId::known("radius-comp-right");
inline constexpr FunctionId tool_length_comp_plus = FunctionId::known("tool-length-comp-plus");
inline constexpr FunctionId tool_length_comp_minus = FunctionId::known("tool-length-comp-minus");
inline constexpr FunctionId tool_length_comp_cancel = FunctionId::known("tool-length-comp-cancel");

// Canned cycles (reference/cycles.md; interpreter/cycles/ expands them).
inline constexpr FunctionId finishing_cycle = FunctionId::known("finishing-cycle");
inline constexpr FunctionId rough_turning_cycle = FunctionId::known("rough-turning-cycle");
inline constexpr FunctionId rough_facing_cycle = FunctionId::known("rough-facing-cycle");
inline constexpr FunctionId pattern_repeating_cycle = FunctionId::known("pattern-repeating-cycle");
inline constexpr FunctionId face_peck_drilling_cycle = FunctionId::known("face-peck-drilling-cycle");
inline constexpr FunctionId grooving_cycle = FunctionId::known("grooving-cycle");
inline constexpr FunctionId multiple_threading_cycle = FunctionId::known("multiple-threading-cycle");
inline constexpr FunctionId thread_cutting_cycle = FunctionId::known("thread-cutting-cycle");
inline constexpr FunctionId variable_lead_thread_cutting = FunctionId::known("variable-lead-thread-cutting");
inline constexpr FunctionId turning_cycle = FunctionId::known("turning-cycle");
inline constexpr FunctionId facing_cycle = FunctionId::known("facing-cycle");
inline constexpr FunctionId canned_cycle_cancel = FunctionId::known("canned-cycle-cancel");
inline constexpr FunctionId return_initial_level = FunctionId::known("return-initial-level");
inline constexpr FunctionId return_r_level = FunctionId::known("return-r-level");
inline constexpr FunctionId drilling_cycle = FunctionId::known("drilling-cycle");
inline constexpr FunctionId drilling_dwell_cycle = FunctionId::known("drilling-dwell-cycle");
inline constexpr FunctionId peck_drilling_cycle = FunctionId::known("peck-drilling-cycle");
inline constexpr FunctionId high_speed_peck_drilling_cycle = FunctionId::known("high-speed-peck-drilling-cycle");
inline constexpr FunctionId tapping_cycle = FunctionId::known("tapping-cycle");
inline constexpr FunctionId left_hand_tapping_cycle = FunctionId::known("left-hand-tapping-cycle");
inline constexpr FunctionId boring_cycle = FunctionId::known("boring-cycle");
inline constexpr FunctionId boring_dwell_cycle = FunctionId::known("boring-dwell-cycle");
inline constexpr FunctionId boring_spindle_stop_cycle = FunctionId::known("boring-spindle-stop-cycle");
inline constexpr FunctionId boring_manual_retract_cycle = FunctionId::known("boring-manual-retract-cycle");
inline constexpr FunctionId back_boring_cycle = FunctionId::known("back-boring-cycle");
// SPINNER cycles (cycles.md §12–§17, interpreter/cycles/spinner.cpp).
inline constexpr FunctionId workpiece_transfer_cycle = FunctionId::known("workpiece-transfer-cycle");
inline constexpr FunctionId tailstock_clamping_cycle_1 = FunctionId::known("tailstock-clamping-cycle-1");
inline constexpr FunctionId tailstock_clamping_cycle_2 = FunctionId::known("tailstock-clamping-cycle-2");
inline constexpr FunctionId live_tool_rigid_tapping = FunctionId::known("live-tool-rigid-tapping");
inline constexpr FunctionId live_tool_rigid_tapping_cancel = FunctionId::known("live-tool-rigid-tapping-cancel");
inline constexpr FunctionId spindle_rigid_tapping_cycle = FunctionId::known("spindle-rigid-tapping-cycle");
inline constexpr FunctionId tailstock_coupling_carry = FunctionId::known("tailstock-coupling-carry");
inline constexpr FunctionId tailstock_coupling_position = FunctionId::known("tailstock-coupling-position");
inline constexpr FunctionId parts_catcher_cycle = FunctionId::known("parts-catcher-cycle");
inline constexpr FunctionId fine_boring_cycle = FunctionId::known("fine-boring-cycle");
inline constexpr FunctionId face_drilling_cycle = FunctionId::known("face-drilling-cycle");
inline constexpr FunctionId face_tapping_cycle = FunctionId::known("face-tapping-cycle");
inline constexpr FunctionId face_boring_cycle = FunctionId::known("face-boring-cycle");
inline constexpr FunctionId side_drilling_cycle = FunctionId::known("side-drilling-cycle");
inline constexpr FunctionId side_tapping_cycle = FunctionId::known("side-tapping-cycle");
inline constexpr FunctionId side_boring_cycle = FunctionId::known("side-boring-cycle");

// seed 004 (iso-legacy-mill) specials (semantics.md §9.4–§9.6).
inline constexpr FunctionId corner_slowdown = FunctionId::known("corner-slowdown");
inline constexpr FunctionId corner_slowdown_cancel = FunctionId::known("corner-slowdown-cancel");
inline constexpr FunctionId axial_offset_plus = FunctionId::known("axial-offset-direction-plus");
inline constexpr FunctionId axial_offset_minus = FunctionId::known("axial-offset-direction-minus");
inline constexpr FunctionId arc_approach = FunctionId::known("arc-approach");
inline constexpr FunctionId arc_exit = FunctionId::known("arc-exit");
inline constexpr FunctionId one_block_rough_turning_cycle = FunctionId::known("one-block-rough-turning-cycle");     // [Haas] G71 D
inline constexpr FunctionId one_block_rough_facing_cycle = FunctionId::known("one-block-rough-facing-cycle");       // [Haas] G72 D
inline constexpr FunctionId one_block_pattern_repeating_cycle = FunctionId::known("one-block-pattern-repeating-cycle");   // [Haas] G73 D
inline constexpr FunctionId one_block_threading_cycle = FunctionId::known("one-block-threading-cycle");             // [Haas] G76 K D
inline constexpr FunctionId one_block_grooving_cycle = FunctionId::known("one-block-grooving-cycle");               // [Haas] G75 I
inline constexpr FunctionId one_block_face_peck_cycle = FunctionId::known("one-block-face-peck-cycle");             // [Haas] G74 K
inline constexpr FunctionId thread_chamfer_on = FunctionId::known("thread-chamfer-on");                             // [Haas] M23
inline constexpr FunctionId thread_chamfer_off = FunctionId::known("thread-chamfer-off");                           // [Haas] M24
inline constexpr FunctionId work_coordinate_additional = FunctionId::known("work-coordinate-additional");           // G54.1 P, [Haas] G154 P, G110–G129
inline constexpr FunctionId dynamic_work_offset = FunctionId::known("dynamic-work-offset");                         // [Haas] G254
inline constexpr FunctionId machine_builder_code = FunctionId::known("machine-builder-code");   // user dialects: no behaviour
inline constexpr FunctionId undocumented = FunctionId::known("undocumented");                   // a seed's code without a usable meaning
// Modes the converter knows read the same in G90 and G91 (converter/convert.cpp), and ADV400's homing.
inline constexpr FunctionId exact_stop_check = FunctionId::known("exact-stop-check");
inline constexpr FunctionId exact_stop_mode = FunctionId::known("exact-stop-mode");
inline constexpr FunctionId continuous_cutting_mode = FunctionId::known("continuous-cutting-mode");
inline constexpr FunctionId axis_homing = FunctionId::known("axis-homing");                     // ADV400 G74 (cycles.md §11.4)
// G54–G59 are work-coordinate-1 ... -6: read FunctionDef::work_coordinate, not the id.

}  // namespace kerf::dialects::functions
