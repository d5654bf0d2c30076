// Every switch the reference leaves open has its documented default (machine/SCHEMA.md), on every
// built-in dialect's default machine; the "dialect" ones are read from the dialect tables.
#include <catch2/catch.hpp>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "dialects/dialect.hpp"
#include "machine/machine.hpp"

using namespace kerf::machine;

namespace {

const std::vector<std::string> kLathes = {"fanuc-lathe-a",   "fanuc-lathe-b",   "fanuc-lathe-c",
                                          "spinner-lathe-a", "spinner-lathe-b", "spinner-lathe-c"};
const std::vector<std::string> kAll = {"fanuc-lathe-a",   "fanuc-lathe-b", "fanuc-lathe-c", "spinner-lathe-a",
                                       "spinner-lathe-b", "spinner-lathe-c", "fanuc-mill",  "adv400-mill",
                                       "adv400-lathe",    "pcnc-mill",       "iso-legacy-mill"};

struct Expectation {
    std::string key;
    std::string documented;                      // default_value in the switch table / SCHEMA.md
    std::string usual;                           // value on the built-in machines ...
    std::map<std::string, std::string> except;   // ... except on these dialects
};

std::map<std::string, std::string> for_lathes(const std::string& value, std::map<std::string, std::string> more = {}) {
    for (const std::string& id : kLathes) more[id] = value;
    return more;
}

// The documented defaults (written out here on purpose: a change in code must change this test).
const std::vector<Expectation>& expectations() {
    static const std::vector<Expectation> e = {
        // semantics.md §2.4, §12.1: FANUC vector; ADV400 current point; pcnc current point + G152.
        {"g52", "dialect", "vector-shift",
         {{"adv400-mill", "current-point"}, {"adv400-lathe", "current-point"}, {"pcnc-mill", "current-point-g152"}}},
        {"g52_cancel_on_reference_return", "false", "false", {}},
        {"work_shift_sign", "subtract", "subtract", {}},                 // semantics.md §2.6, §12.3
        {"x_offsets_diameter", "true", "true", {}},                      // semantics.md §2.7
        {"g53_motion", "dialect", "rapid", {{"pcnc-mill", "g0-g1"}}},    // semantics.md §2.2, §12.2
        {"g53_modal", "false", "false", {}},                             // semantics.md §2.2
        {"g28_intermediate", "work", "work", {}},                        // semantics.md §2.8
        {"g30_default_p", "2", "2", {}},                                 // semantics.md §2.8
        {"g68_positive", "dialect", "ccw", {{"adv400-mill", "cw"}}},     // semantics.md §2.9, §12.4
        {"g68_centre", "as-written", "as-written", {}},                  // semantics.md §2.9
        {"v_alias_of_b", "false", "false", {}},                          // dialects.md §11.3
        {"power_on_plane", "dialect", "G17", for_lathes("G18", {{"adv400-lathe", "G18"}})},   // dialects.md §11.6
        {"warn_arc_without_plane", "false", "false", {{"adv400-lathe", "true"}}},              // dialects.md §11.6
        {"power_on_units", "dialect", "metric", {}},                     // dialects.md §3.8
        {"power_on_distance", "dialect", "absolute", {}},                // dialects.md §4
        {"power_on_return_level", "dialect", "initial", {}},             // dialects.md §4
        {"rapid", "dog-leg", "dog-leg", {}},                             // gcode-tables.md §5
        {"arc_negative_r", "negative-r", "negative-r", for_lathes("reject", {{"adv400-lathe", "reject"}})},
        {"arc_radius_mismatch", "alarm", "alarm", {}},                   // semantics.md §3
        {"arc_tolerance", "0.01", "0.01", {}},
        {"transform_tolerance", "0.01", "0.01", {}},                     // cycles.md §18, §19 [inference]
        {"cutter_comp_startup", "B", "B", {}},                           // semantics.md §6
        {"cutter_comp_corners", "intersection", "intersection", {{"adv400-mill", "arc"}}},   // semantics.md §6
        {"comp_shift_without_motion", "false", "false", {{"iso-legacy-mill", "true"}}},     // semantics.md §6
        {"length_offset_motion", "next-move", "next-move", {}},           // semantics.md §7 [FANUC parameter]
        {"g41_g42_swapped", "false", "false", {}},                       // gcode-tables.md §8.5
        {"cycle_pq_units", "increment", "increment", {}},                // cycles.md §0
        {"dwell_p_unit", "dialect", "ms", {{"adv400-mill", "s"}, {"adv400-lathe", "s"}}},   // semantics.md §8.2
        {"dwell_f_word", "seconds", "seconds", {}},                      // semantics.md §12.15
        {"scaling_unit", "0.001", "0.001", {}},                          // [FANUC] parameter 5400#7 SCR
        {"finish_allowance_u", "diameter", "diameter", {}},              // dialects.md §11.2
        {"rough_relief", "feed", "feed", {}},                            // cycles.md §2 step 6
        {"rough_return", "simultaneous", "simultaneous", {}},            // cycles.md §21.3
        {"g76_infeed", "flank", "flank", {}},                            // cycles.md §7
        {"thread_chamfer", "1", "1", {}},                                // cycles.md §8.2
        {"peck_clearance", "0.5", "0.5", {}},                            // cycles.md §10
        {"high_speed_retract", "0.1", "0.1", {}},                        // [FANUC] parameter 5114 (G73 d)
        {"homing_feed", "0", "0", {}},                                   // cycles.md §11.4
        {"adv400_g76_mra", "P", "P", {}},                                // cycles.md §21.6
        {"adv400_g83_k", "peck", "peck", {}},                            // cycles.md §21.7
        {"adv400_lathe_g98_g99", "feed-mode", "feed-mode", {}},          // gcode-tables.md §8.7
        {"adv400_g84", "tapping", "tapping", {}},                        // gcode-tables.md §8.6
        {"drill_repeat_l", "fanuc", "fanuc", {}},                        // cycles.md §21.8
        {"g38_stop", "target", "target", {}},                            // cycles.md §12
        {"clamp_contact", "half-tolerance", "half-tolerance", {}},       // cycles.md §13
        {"g238_a_timing", "start", "start", {}},                         // cycles.md §21.10
        {"g384_radial_h", "radius", "radius", {}},                       // cycles.md §21.9
        {"g384_bottom_dwell", "0.1", "0.1", {}},                         // cycles.md §15
        {"corner_slowdown", "ramp", "ramp", {}},                         // semantics.md §12.8
        {"iso_g43", "approach-shorten", "approach-shorten", {}},         // semantics.md §12.9
        {"m23_m24", "by-mode", "by-mode", {}},                           // mcodes.md §5.1
        {"m3_clockwise", "true", "true", {}},                            // mcodes.md §5.9
        {"m10_m11", "conveyor", "conveyor", {}},                         // mcodes.md §5.3
        {"m17", "hp-valve", "hp-valve", {}},                             // mcodes.md §5.2
        {"m200", "part-off-check", "part-off-check", {}},                // mcodes.md §5.4
        {"m33_m34", "sub-spindle-rotation", "sub-spindle-rotation", {}}, // mcodes.md §5.5
        {"turret_index_during_motion", "M318", "M318", {}},              // mcodes.md §5.6
        {"m042_on", "false", "false", {}},                               // mcodes.md §5.7
        {"m381_enables", "false", "false", {}},                          // mcodes.md §5.8
        {"m84_as_m23", "false", "false", {}},                            // mcodes.md §5.12
        {"m19_c", "orient", "orient", {}},                               // mcodes.md §5.11
        {"atan_range", "0-360", "0-360", {}},                            // [FANUC]
        {"subprogram_nesting", "4", "4", {}},                            // dialects.md §3.6
        {"macro_nesting", "4", "4", {}},                                 // dialects.md §3.6
        {"max_blocks", "10000000", "10000000", {}},
        {"max_moves", "10000000", "10000000", {}},
    };
    return e;
}

}  // namespace

TEST_CASE("the test covers every switch, and every switch is documented", "[machine][switches]") {
    std::set<std::string> tested;
    for (const Expectation& e : expectations()) tested.insert(e.key);
    for (const SwitchInfo& info : switch_infos()) {
        INFO("switch " << info.key << " has no expectation in this test");
        CHECK(tested.count(std::string(info.key)) == 1);
    }
    CHECK(tested.size() == switch_infos().size());
}

TEST_CASE("each switch has its documented default", "[machine][switches]") {
    for (const Expectation& e : expectations()) {
        INFO("switch " << e.key);
        const SwitchInfo* info = find_switch(e.key);
        REQUIRE(info);
        CHECK(info->default_value == e.documented);
        CHECK(info->dialect_default == (e.documented == "dialect"));
        // A machine built from nothing but the struct defaults (the FANUC fallbacks).
        const Machine blank;
        if (e.documented != "dialect") CHECK(switch_value(blank, e.key) == e.documented);
    }
}

TEST_CASE("each switch has its default on every built-in dialect's machine", "[machine][switches]") {
    for (const std::string& dialect : kAll) {
        const Machine& m = default_machine_for(dialect);
        for (const Expectation& e : expectations()) {
            INFO("dialect " << dialect << ", switch " << e.key);
            const auto it = e.except.find(dialect);
            const std::string expected = it == e.except.end() ? e.usual : it->second;
            CHECK(switch_value(m, e.key) == expected);
            CHECK(m.follows_dialect(e.key) == (e.documented == "dialect"));
        }
    }
}

TEST_CASE("typed fields agree with the documented defaults", "[machine][switches]") {
    const Switches s;   // the FANUC fallbacks
    CHECK(s.g52 == G52Semantics::vector_shift);
    CHECK(s.rapid == RapidMode::dog_leg);
    CHECK(s.finish_allowance_u == AllowanceU::diameter);
    CHECK(s.m23_m24 == M23M24::by_mode);
    CHECK(s.cycle_pq_units == CyclePQUnits::increment);
    CHECK(s.atan_range == AtanRange::zero_to_360);
    CHECK(s.subprogram_nesting == 4);
    CHECK(s.macro_nesting == 4);
    CHECK(s.max_blocks == 10'000'000);
    CHECK(s.max_moves == 10'000'000);
    CHECK(s.g68_positive == RotationSign::ccw);
    CHECK(s.g28_intermediate == PointFrame::work);
    CHECK(s.dwell_p_unit == DwellUnit::ms);
    CHECK(s.work_shift_sign == WorkShiftSign::subtract);

    CHECK(default_machine_for("adv400-mill").switches.g68_positive == RotationSign::cw);
    CHECK(default_machine_for("adv400-mill").switches.g52 == G52Semantics::current_point);
    CHECK(default_machine_for("pcnc-mill").switches.g52 == G52Semantics::current_point_g152);
    CHECK(default_machine_for("pcnc-mill").switches.g53_motion == G53Motion::g0_g1);
    CHECK(default_machine_for("fanuc-mill").switches.g52 == G52Semantics::vector_shift);
    CHECK(default_machine_for("adv400-lathe").switches.power_on_plane == Plane::zx);
    CHECK(default_machine_for("adv400-lathe").switches.dwell_p_unit == DwellUnit::s);
    CHECK(default_machine_for("spinner-lathe-a").switches.arc_negative_r == ArcLargeR::reject);
    CHECK(default_machine_for("fanuc-mill").switches.arc_negative_r == ArcLargeR::negative_r);
}

TEST_CASE("an unresolved machine keeps the FANUC fallbacks until resolved", "[machine][switches]") {
    const Machine* adv = builtin_machines().find("adv400-mill");
    REQUIRE(adv);
    CHECK(adv->resolved_dialect.empty());
    CHECK(adv->follows_dialect("g68_positive"));
    CHECK(adv->switches.g68_positive == RotationSign::ccw);   // fallback
    const kerf::dialects::Dialect* d = kerf::dialects::builtin_registry().find("adv400-mill");
    REQUIRE(d);
    const Machine r = resolve_for_dialect(*adv, *d);
    CHECK(r.switches.g68_positive == RotationSign::cw);
    CHECK(r.follows_dialect("g68_positive"));   // still follows: resolvable again
    // Resolved for another dialect, the same machine follows that one.
    const kerf::dialects::Dialect* fanuc = kerf::dialects::builtin_registry().find("fanuc-mill");
    REQUIRE(fanuc);
    CHECK(resolve_for_dialect(r, *fanuc).switches.g68_positive == RotationSign::ccw);
}

TEST_CASE("a user file sets switches; the dialect value can be restored", "[machine][switches]") {
    const LoadResult r = load_machine_text("id = \"u\"\nbase = \"pcnc-mill\"\n[switches]\n"
                                           "g52 = \"vector-shift\"\n"
                                           "cycle_pq_units = \"tenth-micron\"\n"
                                           "subprogram_nesting = 10\n"
                                           "arc_tolerance = 0.005\n"
                                           "transform_tolerance = 0.002\n"
                                           "m3_clockwise = false\n"
                                           "atan_range = \"-180-180\"\n",
                                           "u.toml");
    REQUIRE(r.machine);
    const Switches& s = r.machine->switches;
    CHECK(s.g52 == G52Semantics::vector_shift);
    CHECK(s.cycle_pq_units == CyclePQUnits::tenth_micron);
    CHECK(s.subprogram_nesting == 10);
    CHECK(s.arc_tolerance == Approx(0.005));
    CHECK(s.transform_tolerance == Approx(0.002));
    CHECK_FALSE(s.m3_clockwise);
    CHECK(s.atan_range == AtanRange::minus_180_to_180);
    CHECK_FALSE(r.machine->follows_dialect("g52"));
    const LoadResult back = load_machine_text("id = \"v\"\nbase = \"u\"\n[switches]\ng52 = \"dialect\"\n", "v.toml", [&] {
        Registry reg = builtin_machines();
        reg.add(*r.machine);
        return reg;
    }());
    REQUIRE(back.machine);
    CHECK(back.machine->follows_dialect("g52"));
    const kerf::dialects::Dialect* pcnc = kerf::dialects::builtin_registry().find("pcnc-mill");
    REQUIRE(pcnc);
    CHECK(resolve_for_dialect(*back.machine, *pcnc).switches.g52 == G52Semantics::current_point_g152);
}
