// The persistent cycle parameters and the machine switches of the canned cycles, as the
// interpreter's Setup carries them (filled from machine/ by interpreter::make_setup).
#pragma once

#include <optional>

namespace kerf::interpreter::cycles {

// Initial values of the persistent parameters (machine [cycle_parameters]) and the machine
// switches the reference leaves open (machine/SCHEMA.md "Cycles").
struct Parameters {
    double g71_depth = 2.0, g71_retract = 1.0;        // G71 U(Δd) R(e), mm (Δd radius)
    double g72_depth = 2.0, g72_retract = 1.0;        // G72 W(Δd) R(e)
    double g73_relief_x = 0, g73_relief_z = 0;        // G73 U(Δi) radius, W(Δk)
    int g73_divisions = 1;                            // G73 R(d)
    double g74_retract = 0.5, g75_retract = 0.5;      // G74 / G75 R(e)
    int g76_finishing_passes = 1, g76_chamfer = 0, g76_angle = 60;   // G76 P m r a
    double g76_min_depth = 0.05, g76_allowance = 0.03;               // G76 Q(Δdmin) mm, R(d)
};

enum class Relief { feed, rapid };                           // G71/G72 45° relief (cycles.md §2 step 6)
enum class Return { simultaneous, x_then_z, z_then_x };      // G71–G73 return to A (cycles.md §21.3)
enum class Infeed { flank, opposite_flank, radial };         // G76 (cycles.md §7 step 3, §21.4)

// The SPINNER cycles' open points (machine/SCHEMA.md switches g38_stop, clamp_contact, g238_a_timing,
// g384_radial_h, g384_bottom_dwell) and the builder-set tailstock positions ([tailstock]), cycles.md §12–§17.
struct SpinnerSettings {
    bool g38_stop_half_tolerance = false;   // G38 stops at B + Q/2 instead of B (§12)
    bool clamp_contact_target = false;      // G138/G238 contact at B instead of B + Q/2 (§13, §14)
    bool g238_a_after_clamp = false;        // G238 A: the T code after clamping instead of at the start (§21.10)
    bool g384_radial_h_diameter = false;    // G384 T1: H is a diameter depth instead of a radius (§21.9)
    double g384_bottom_dwell_s = 0.1;       // G384 dwell at the hole bottom (§15 step 5)
    std::optional<double> coupling_z;       // G100 coupling position, machine Z (§17)
    std::optional<double> coupling_z_second;   // G101 second coupling hole, machine Z
    std::optional<double> home_b;           // G100 I1 tailstock home
};

struct Settings {
    Parameters initial;                     // cycles.md §0: "initial values = machine configuration"
    bool allowance_u_radius = false;        // G71–G73 Δu is a radius (seed 001) instead of a diameter
    double pq_unit_mm = 0;                  // unit of integer P/Q (G74–G76, G83, G87); 0 = input increment
    Relief relief = Relief::feed;
    Return rough_return = Return::simultaneous;
    Infeed infeed = Infeed::flank;
    double thread_chamfer_leads = 1.0;      // G92 run-out length in leads (cycles.md §8.2)
    double peck_clearance = 0.5;            // mm: G83/G87 re-approach above the last depth (cycles.md §10)
    double high_speed_retract = 0.1;        // mm: G73 retract d after each peck ([FANUC] parameter 5114)
    bool adv400_k_first_peck_only = false;  // ADV400 G83 K: the first depth only (cycles.md §11.3, §21.7)
    bool tapping_reverses = true;           // ADV400 G84: tapping (false: drilling with dwell, §11.2, gcode-tables §8.6)
    bool repeat_l = true;                   // L repeats a drilling cycle (cycles.md §11.1, §21.8)
    SpinnerSettings spinner;
};

}  // namespace kerf::interpreter::cycles
