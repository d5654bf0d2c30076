// The [switches] table: every open point of the reference that changes what a program does, with
// the documented default and the section it comes from (machine/SCHEMA.md lists the same rows).
#include <fmt/format.h>

#include <algorithm>
#include <initializer_list>
#include <utility>
#include <vector>

#include "machine/switch_table.hpp"

namespace kerf::machine::detail {
namespace {

template <class E>
using Names = std::vector<std::pair<std::string_view, E>>;

const Switches& defaults() {
    static const Switches s;
    return s;
}

template <class E>
SwitchDef choice(std::string_view key, E Switches::*field, Names<E> names, bool dialect, std::string_view source,
                 std::string_view meaning) {
    SwitchDef def;
    def.info.key = key;
    def.info.type = SwitchType::choice;
    for (const auto& [name, value] : names) def.info.choices.push_back(name);
    if (dialect) def.info.choices.push_back("dialect");
    def.info.dialect_default = dialect;
    def.info.source = source;
    def.info.meaning = meaning;
    const auto name_of = [names](E value) -> std::string_view {
        for (const auto& [name, v] : names)
            if (v == value) return name;
        return "?";
    };
    def.info.default_value = dialect ? std::string("dialect") : std::string(name_of(defaults().*field));
    def.set = [field, names](Switches& s, const SwitchValue& v) {
        const std::string& text = std::get<std::string>(v);
        for (const auto& [name, value] : names)
            if (name == text) s.*field = value;
    };
    def.get = [field, name_of](const Switches& s) -> SwitchValue { return std::string(name_of(s.*field)); };
    return def;
}

SwitchDef boolean(std::string_view key, bool Switches::*field, std::string_view source, std::string_view meaning) {
    SwitchDef def;
    def.info.key = key;
    def.info.type = SwitchType::boolean;
    def.info.source = source;
    def.info.meaning = meaning;
    def.info.default_value = defaults().*field ? "true" : "false";
    def.set = [field](Switches& s, const SwitchValue& v) { s.*field = std::get<bool>(v); };
    def.get = [field](const Switches& s) -> SwitchValue { return s.*field; };
    return def;
}

template <class I>
SwitchDef integer(std::string_view key, I Switches::*field, double min, double max, std::string_view source,
                  std::string_view meaning) {
    SwitchDef def;
    def.info.key = key;
    def.info.type = SwitchType::integer;
    def.info.min = min;
    def.info.max = max;
    def.info.source = source;
    def.info.meaning = meaning;
    def.info.default_value = fmt::format("{}", defaults().*field);
    def.set = [field](Switches& s, const SwitchValue& v) { s.*field = static_cast<I>(std::get<std::int64_t>(v)); };
    def.get = [field](const Switches& s) -> SwitchValue { return static_cast<std::int64_t>(s.*field); };
    return def;
}

SwitchDef number(std::string_view key, double Switches::*field, double min, double max, std::string_view source,
                 std::string_view meaning) {
    SwitchDef def;
    def.info.key = key;
    def.info.type = SwitchType::number;
    def.info.min = min;
    def.info.max = max;
    def.info.source = source;
    def.info.meaning = meaning;
    def.info.default_value = to_text(defaults().*field);
    def.set = [field](Switches& s, const SwitchValue& v) { s.*field = std::get<double>(v); };
    def.get = [field](const Switches& s) -> SwitchValue { return s.*field; };
    return def;
}

std::vector<SwitchDef> make_defs() {
    using S = Switches;
    std::vector<SwitchDef> d;
    // --- coordinate systems -------------------------------------------------------------------
    d.push_back(choice<G52Semantics>(
        "g52", &S::g52,
        {{"vector-shift", G52Semantics::vector_shift},
         {"current-point", G52Semantics::current_point},
         {"current-point-g152", G52Semantics::current_point_g152}},
        true, "semantics.md §2.4, §12.1; gcode-tables.md §7",
        "G52 local system: FANUC vector shift (G52 X0.. cancels); ADV400 'the current point takes the programmed "
        "values' (G52 with zeros cancels, G90 only); pcnc-mill the same with G152 / G54–G59 cancelling. "
        "dialect: the dialect's G52 function id (local-system-shift / local-system-current-point, with "
        "local-system-cancel present → current-point-g152)"));
    d.push_back(boolean("g52_cancel_on_reference_return", &S::g52_cancel_on_reference_return,
                        "semantics.md §2.4 ('(parameter) by reference return'); [FANUC] ZCL = 0",
                        "a reference return (G28) cancels the G52 local system"));
    d.push_back(choice<WorkShiftSign>("work_shift_sign", &S::work_shift_sign,
                                      {{"subtract", WorkShiftSign::subtract}, {"add", WorkShiftSign::add}}, false,
                                      "semantics.md §2.6, §2.7, §12.3",
                                      "G10 P0 work shift: machine = program + work offset − shift (FANUC: the shift is "
                                      "the vector from the new origin to the old one), or + shift"));
    d.push_back(boolean("x_offsets_diameter", &S::x_offsets_diameter, "semantics.md §2.7",
                        "X values of work offsets, the work shift and tool offsets are diameters (lathes with "
                        "diameter_x)"));
    d.push_back(choice<G53Motion>("g53_motion", &S::g53_motion,
                                  {{"rapid", G53Motion::rapid}, {"g0-g1", G53Motion::g0_g1}}, true,
                                  "semantics.md §2.2, §12.2",
                                  "G53 moves at rapid (FANUC) or with the modal G0/G1 and F (pcnc-mill). dialect: "
                                  "machine-coordinate-select-g0-g1 present → g0-g1"));
    d.push_back(boolean("g53_modal", &S::g53_modal, "semantics.md §2.2 (ADV400 bare G53) [inference]",
                        "G53 stays in effect until a work system is selected (false: one-shot, as FANUC)"));
    d.push_back(choice<PointFrame>("g28_intermediate", &S::g28_intermediate,
                                   {{"work", PointFrame::work}, {"machine", PointFrame::machine}}, false,
                                   "semantics.md §2.8; dialects.md §8",
                                   "coordinates of the G28/G30 intermediate point (and G29 target)"));
    d.push_back(integer("g30_default_p", &S::g30_default_p, 1, 4, "semantics.md §2.8 [FANUC]",
                        "reference point of a G30 without P"));
    d.push_back(choice<RotationSign>("g68_positive", &S::g68_positive,
                                     {{"ccw", RotationSign::ccw}, {"cw", RotationSign::cw}}, true,
                                     "semantics.md §2.9, §12.4; gcode-tables.md §8.10",
                                     "direction of a positive G68 R: FANUC counter-clockwise, ADV400 clockwise. "
                                     "dialect: coordinate-rotation-cw present → cw"));
    d.push_back(choice<G68Centre>("g68_centre", &S::g68_centre,
                                  {{"as-written", G68Centre::as_written}, {"plane-order", G68Centre::plane_order}},
                                  false, "semantics.md §2.9, §12.4 (`G18 G68 X1 Y1 R34`)",
                                  "G68 centre words that are not the plane's axes: each word is its own axis, "
                                  "plane axes not given are the current position [FANUC] (as-written), or the "
                                  "first two words are the plane's first and second axes (plane-order)"));
    d.push_back(boolean("v_alias_of_b", &S::v_alias_of_b, "dialects.md §3.1, §11.3",
                        "V moves the sub-spindle axis B (only if the machine says so)"));
    // --- power-on state ------------------------------------------------------------------------
    d.push_back(choice<Plane>("power_on_plane", &S::power_on_plane,
                              {{"G17", Plane::xy}, {"G18", Plane::zx}, {"G19", Plane::yz}}, true,
                              "dialects.md §3.8, §6.2, §11.6",
                              "plane at power-on and reset. dialect: the dialect's default plane code "
                              "(adv400-lathe: G18, not the seed's G17)"));
    d.push_back(boolean("warn_arc_without_plane", &S::warn_arc_without_plane, "dialects.md §11.6",
                        "warn when arcs are programmed before any G17/G18/G19 (ADV400 lathe)"));
    d.push_back(choice<Units>("power_on_units", &S::power_on_units, {{"metric", Units::metric}, {"inch", Units::inch}},
                              true, "dialects.md §3.8 ('G21 or G20 (parameter)')",
                              "input unit at power-on. dialect: the dialect's default inch/metric code, else metric"));
    d.push_back(choice<Distance>("power_on_distance", &S::power_on_distance,
                                 {{"absolute", Distance::absolute}, {"incremental", Distance::incremental}}, true,
                                 "dialects.md §4 ('the power-on state of G90/G91 … is a parameter')",
                                 "G90/G91 at power-on. dialect: the dialect's default code, else absolute"));
    d.push_back(choice<ReturnLevel>("power_on_return_level", &S::power_on_return_level,
                                    {{"initial", ReturnLevel::initial}, {"r-point", ReturnLevel::r_point}}, true,
                                    "dialects.md §4 ('… and G98/G99 is a parameter')",
                                    "canned-cycle return level at power-on. dialect: the dialect's default code, "
                                    "else initial"));
    // --- motion --------------------------------------------------------------------------------
    d.push_back(choice<RapidMode>("rapid", &S::rapid, {{"dog-leg", RapidMode::dog_leg}, {"linear", RapidMode::linear}},
                                  false, "gcode-tables.md §5 (seed 003 G00, [FANUC] LRP), §2 (ADV400 G00)",
                                  "G00: each axis at its own rapid rate (non-linear, the axes arrive one after "
                                  "another) or a straight line with no axis above its rate"));
    d.push_back(choice<ArcLargeR>("arc_negative_r", &S::arc_negative_r,
                                  {{"negative-r", ArcLargeR::negative_r}, {"reject", ArcLargeR::reject}}, false,
                                  "semantics.md §3, §12.5",
                                  "R < 0 in G02/G03: arc over 180° (FANUC mills) or an error (seed 003, lathes)"));
    d.push_back(choice<ArcMismatch>("arc_radius_mismatch", &S::arc_radius_mismatch,
                                    {{"alarm", ArcMismatch::alarm}, {"enlarge", ArcMismatch::enlarge}}, false,
                                    "semantics.md §3",
                                    "chord longer than 2·R by more than arc_tolerance: alarm [FANUC] or R enlarged (some models)"));
    d.push_back(number("arc_tolerance", &S::arc_tolerance, 0, 10, "semantics.md §3 [inference]",
                       "mm an arc end point may miss the circle (and chord − 2R may exceed 0) without an alarm"));
    d.push_back(number("transform_tolerance", &S::transform_tolerance, 0.0001, 10, "cycles.md §18, §19 [inference]",
                       "mm the tool may leave the programmed path of G112 polar / G107 cylindrical interpolation "
                       "between the pieces the dry run cuts it into (the real axes move linearly along a piece)"));
    d.push_back(choice<CompStartup>("cutter_comp_startup", &S::cutter_comp_startup,
                                    {{"A", CompStartup::type_a}, {"B", CompStartup::type_b}}, false,
                                    "semantics.md §6 ('type A/B (a parameter, default B)')",
                                    "FANUC cutter compensation start-up and cancel type"));
    d.push_back(choice<LengthOffsetMotion>("length_offset_motion", &S::length_offset_motion,
                                           {{"next-move", LengthOffsetMotion::next_move},
                                            {"at-once", LengthOffsetMotion::at_once}},
                                           false, "semantics.md §7; [FANUC] tool length compensation parameter",
                                           "G43/G44 H (or G49) in a block without axis words: the axes take the offset up "
                                           "with the next move, or Z moves by it at once"));
    d.push_back(choice<CompCorners>("cutter_comp_corners", &S::cutter_comp_corners,
                                    {{"intersection", CompCorners::intersection}, {"arc", CompCorners::arc}}, false,
                                    "semantics.md §6",
                                    "outside corners under G41/G42: offset paths joined at their intersection, acute ones "
                                    "extended by the radius (FANUC compensation C), or an arc about the corner (ADV400)"));
    d.push_back(boolean("comp_shift_without_motion", &S::comp_shift_without_motion, "semantics.md §6 (seed 004 ex. 2)",
                        "G41/G42 with D in a block without motion moves the tool centre to the offset point at once "
                        "(iso-legacy-mill); false: the compensation starts with the next move (FANUC)"));
    d.push_back(boolean("g41_g42_swapped", &S::g41_g42_swapped, "gcode-tables.md §2, §8.5; semantics.md §12.12",
                        "G41 = right, G42 = left (the ADV400 code list); false: the text and FANUC"));
    // --- units of words ------------------------------------------------------------------------
    d.push_back(choice<CyclePQUnits>("cycle_pq_units", &S::cycle_pq_units,
                                     {{"increment", CyclePQUnits::increment},
                                      {"micron", CyclePQUnits::micron},
                                      {"tenth-micron", CyclePQUnits::tenth_micron}},
                                     false, "cycles.md §0, §21.1; dialects.md §11.9",
                                     "unit of the integer P/Q words of G74–G76, G83, G87: the least input increment "
                                     "(0.001 mm IS-B, 0.0001 mm IS-C: the 'tens of microns' machines), or fixed"));
    d.push_back(choice<DwellUnit>("dwell_p_unit", &S::dwell_p_unit, {{"ms", DwellUnit::ms}, {"s", DwellUnit::s}}, true,
                                  "semantics.md §8.2; gcode-tables.md §2 (ADV400 G04)",
                                  "G04 P in milliseconds (FANUC) or seconds (ADV400). dialect: the dialect's "
                                  "[lexical] dwell_p_unit"));
    d.push_back(choice<ScalingUnit>("scaling_unit", &S::scaling_unit,
                                    {{"0.001", ScalingUnit::thousandth}, {"0.00001", ScalingUnit::hundred_thousandth}},
                                    false, "[FANUC] parameter 5400#7 SCR (gcode-tables.md §338 lists G51 as [FANUC])",
                                    "unit of the G51 magnification words P, I, J, K written without a decimal point "
                                    "(P1000 = ×1 with 0.001); a value with a point is the factor itself"));
    d.push_back(choice<DwellF>("dwell_f_word", &S::dwell_f_word,
                               {{"seconds", DwellF::seconds}, {"reject", DwellF::reject}}, false,
                               "semantics.md §8.2, §12.15 (`G4F1`, seed 001 §8.1)",
                               "G04 F: seconds with a warning, or an error"));
    // --- cycles --------------------------------------------------------------------------------
    d.push_back(choice<AllowanceU>("finish_allowance_u", &S::finish_allowance_u,
                                   {{"diameter", AllowanceU::diameter}, {"radius", AllowanceU::radius}}, false,
                                   "dialects.md §3.3, §11.2; cycles.md §2, §21.2",
                                   "G71–G73 second-block U (Δu): a diameter [FANUC] or a radius (seed 001)"));
    d.push_back(choice<Relief>("rough_relief", &S::rough_relief, {{"feed", Relief::feed}, {"rapid", Relief::rapid}},
                               false, "cycles.md §2 step 6, §21.3",
                               "G71/G72 45° relief after each pass: G01 at the roughing F (the safer choice) or rapid"));
    d.push_back(choice<RoughReturn>("rough_return", &S::rough_return,
                                    {{"simultaneous", RoughReturn::simultaneous},
                                     {"x-then-z", RoughReturn::x_then_z},
                                     {"z-then-x", RoughReturn::z_then_x}},
                                    false, "cycles.md §2, §21.3 [inference]",
                                    "G71–G73 rapid return to the start point: both axes, or one after the other"));
    d.push_back(choice<G76Infeed>("g76_infeed", &S::g76_infeed,
                                  {{"flank", G76Infeed::flank},
                                   {"opposite-flank", G76Infeed::opposite_flank},
                                   {"radial", G76Infeed::radial}},
                                  false, "cycles.md §7 step 3, §21.4",
                                  "G76 infeed: along the flank facing the thread end [FANUC], the other flank, or "
                                  "straight in X"));
    d.push_back(number("thread_chamfer", &S::thread_chamfer, 0, 12.7,
                       "cycles.md §8.2 (parameter 5130, 0.1L–12.7L; seed 001 §9.1) [inference]",
                       "G92 / M23 thread run-out length in leads"));
    d.push_back(number("peck_clearance", &S::peck_clearance, 0, 100, "cycles.md §10 ('default e.g. 0.1–1 mm')",
                       "mm above the previous depth where G83/G87 (and ADV400 G83) switch from rapid to feed"));
    d.push_back(number("high_speed_retract", &S::high_speed_retract, 0, 100,
                       "[FANUC] parameter 5114 (cycles.md §11 names G73 without its d)",
                       "mm the mill G73 high-speed peck cycle retracts after each peck"));
    d.push_back(number("homing_feed", &S::homing_feed, 0, 1e6, "cycles.md §11.4 ('configurable homing feed')",
                       "mm/min of the ADV400 G74 homing move; 0 = rapid"));
    d.push_back(choice<SixDigitWord>("adv400_g76_mra", &S::adv400_g76_mra,
                                     {{"P", SixDigitWord::p}, {"R", SixDigitWord::r}}, false, "cycles.md §7, §21.6",
                                     "ADV400 G76 preparatory block: the six digits m r a are in P (syntax, FANUC; R "
                                     "is the allowance) or in R (text)"));
    d.push_back(choice<Adv400G83K>("adv400_g83_k", &S::adv400_g83_k,
                                   {{"peck", Adv400G83K::peck}, {"initial-depth", Adv400G83K::initial_depth}}, false,
                                   "cycles.md §11.3, §21.7",
                                   "ADV400 lathe G83 K: the depth of every peck (as the text uses it) or the first "
                                   "depth only (as the list says)"));
    d.push_back(choice<Adv400LatheG98>("adv400_lathe_g98_g99", &S::adv400_lathe_g98_g99,
                                       {{"feed-mode", Adv400LatheG98::feed_mode},
                                        {"return-level", Adv400LatheG98::return_level}},
                                       false, "gcode-tables.md §3, §8.7; cycles.md §11.3, §21.7",
                                       "ADV400 lathe G98/G99: feed per minute/revolution (the code list; drilling "
                                       "cycles then return to the initial level) or canned-cycle return level"));
    d.push_back(choice<Adv400G84>("adv400_g84", &S::adv400_g84,
                                  {{"tapping", Adv400G84::tapping}, {"drill-dwell", Adv400G84::drill_dwell}}, false,
                                  "gcode-tables.md §2, §8.6; cycles.md §11.2",
                                  "ADV400 G84: tapping (text and figure: spindle reverses) or drilling with dwell "
                                  "(its title)"));
    d.push_back(choice<DrillRepeatL>("drill_repeat_l", &S::drill_repeat_l,
                                     {{"fanuc", DrillRepeatL::fanuc}, {"ignore", DrillRepeatL::ignore}}, false,
                                     "cycles.md §11.1, §21.8",
                                     "L in ADV400 drilling cycles: FANUC repeats (G90 the same hole, G91 stepping) "
                                     "or ignored"));
    d.push_back(choice<G38Stop>("g38_stop", &S::g38_stop,
                                {{"target", G38Stop::target}, {"half-tolerance", G38Stop::half_tolerance}}, false,
                                "cycles.md §12", "where the SPINNER G38 transfer is modelled to stop: at B, or B + Q/2"));
    d.push_back(choice<ClampContact>("clamp_contact", &S::clamp_contact,
                                     {{"half-tolerance", ClampContact::half_tolerance}, {"target", ClampContact::target}},
                                     false, "cycles.md §13, §14",
                                     "SPINNER G138/G238 contact position: B + Q/2 (inside the window) or B"));
    d.push_back(choice<G238ATiming>("g238_a_timing", &S::g238_a_timing,
                                    {{"start", G238ATiming::start}, {"after-clamp", G238ATiming::after_clamp}}, false,
                                    "cycles.md §14, §21.10",
                                    "when G238 executes the T code of its A word: at the start (parameter list) or "
                                    "after clamping (example text)"));
    d.push_back(choice<G384RadialH>("g384_radial_h", &S::g384_radial_h,
                                    {{"radius", G384RadialH::radius}, {"diameter", G384RadialH::diameter}}, false,
                                    "cycles.md §15, §21.9 [inference]",
                                    "SPINNER G384 T1 (radial) hole depth H along X: a radius or a diameter value"));
    d.push_back(number("g384_bottom_dwell", &S::g384_bottom_dwell, 0, 100, "cycles.md §15 step 5, §21.9",
                       "seconds G384 dwells at the hole bottom (the example text says 0.1 s; no word sets it)"));
    d.push_back(choice<CornerSlowdown>("corner_slowdown", &S::corner_slowdown,
                                       {{"ramp", CornerSlowdown::ramp}, {"step", CornerSlowdown::step}}, false,
                                       "semantics.md §9.5, §12.8",
                                       "iso-legacy-mill G28 K F: feed ramps from F to F·(1 − p) over the last K mm, "
                                       "or drops at once"));
    d.push_back(choice<IsoG43>("iso_g43", &S::iso_g43,
                               {{"approach-shorten", IsoG43::approach_shorten},
                                {"length-offset", IsoG43::length_offset}},
                               false, "semantics.md §9.4, §12.9; gcode-tables.md §8.13",
                               "iso-legacy-mill G43 without H in a motion block: stop D short of the point along the "
                               "approach (example 6), or a length offset direction"));
    // --- M codes -------------------------------------------------------------------------------
    d.push_back(choice<M23M24>("m23_m24", &S::m23_m24,
                               {{"by-mode", M23M24::by_mode},
                                {"live-tool", M23M24::live_tool},
                                {"thread-exit", M23M24::thread_exit}},
                               false, "mcodes.md §5.1; cycles.md §8.2",
                               "M23/M24: live tool CW/CCW in C-axis mode (after M60/M160) and inclined/straight "
                               "thread exit otherwise, with a warning (by-mode); or always one meaning"));
    d.push_back(boolean("m3_clockwise", &S::m3_clockwise, "mcodes.md §5.9, §5.10",
                        "M3 turns the spindle clockwise and M4 counter-clockwise (the tables), not as some comments "
                        "say"));
    d.push_back(choice<M10M11>("m10_m11", &S::m10_m11, {{"conveyor", M10M11::conveyor}, {"chuck", M10M11::chuck}},
                               false, "mcodes.md §2, §5.3",
                               "SPINNER M10/M11: chip conveyor on/off (table) or clamp/open the main chuck (§9.7)"));
    d.push_back(choice<M17Meaning>("m17", &S::m17,
                                   {{"hp-valve", M17Meaning::hp_valve}, {"pump-2-off", M17Meaning::pump_2_off}}, false,
                                   "mcodes.md §2, §5.2",
                                   "SPINNER M17: activate the high-pressure coolant valve (table) or stop the 2nd "
                                   "pump (TC82-108, §9.10)"));
    d.push_back(choice<M200Meaning>("m200", &S::m200,
                                    {{"part-off-check", M200Meaning::part_off_check}, {"washing", M200Meaning::washing}},
                                    false, "mcodes.md §3.2, §5.4",
                                    "SPINNER M200: part-off control (table, §9.4) or washing liquid on (§9.9)"));
    d.push_back(choice<M33M34>("m33_m34", &S::m33_m34,
                               {{"sub-spindle-rotation", M33M34::sub_spindle_rotation},
                                {"synchronisation", M33M34::synchronisation}},
                               false, "mcodes.md §5.5",
                               "SPINNER M33/M34: sub-spindle rotation (table) or speed/phase synchronisation (§9.7)"));
    d.push_back(choice<TurretIndexCode>("turret_index_during_motion", &S::turret_index_during_motion,
                                        {{"M318", TurretIndexCode::m318}, {"M46", TurretIndexCode::m46}}, false,
                                        "mcodes.md §2.1, §3.2, §5.6",
                                        "the code that lets the turret index before all axes finish: M318 (§11.4 "
                                        "text) or M46 (its heading)"));
    d.push_back(boolean("m042_on", &S::m042_on, "mcodes.md §2, §5.7",
                        "M042 switches the B-axis torque limit ON like M041 (as printed); false: it is the OFF"));
    d.push_back(boolean("m381_enables", &S::m381_enables, "mcodes.md §2.2, §5.8",
                        "M381 enables SuperCap C-axis mode (the §10.1.3 box); false: it disables it (table, text)"));
    d.push_back(boolean("m84_as_m23", &S::m84_as_m23, "mcodes.md §2.1, §5.12",
                        "read the undocumented M84 (O0009) as M23 live tool on; false: undocumented (warning)"));
    d.push_back(choice<M19C>("m19_c", &S::m19_c, {{"orient", M19C::orient}, {"reference", M19C::reference}}, false,
                             "mcodes.md §1, §5.11 [inference]",
                             "ADV400 `M19 C45`: orient the spindle to C (probable reading) or reference the C axis"));
    // --- limits --------------------------------------------------------------------------------
    d.push_back(choice<AtanRange>("atan_range", &S::atan_range,
                                  {{"0-360", AtanRange::zero_to_360}, {"-180-180", AtanRange::minus_180_to_180}},
                                  false, "[FANUC] parameter NAT (not in the reference)",
                                  "result range of the Macro B ATAN function"));
    d.push_back(integer("subprogram_nesting", &S::subprogram_nesting, 1, 100, "dialects.md §3.6 [FANUC]",
                        "M98 calls that may be nested (4; 10 on newer models)"));
    d.push_back(integer("macro_nesting", &S::macro_nesting, 1, 100, "dialects.md §3.6 [FANUC]",
                        "G65/G66 macro calls that may be nested (4; 5 on newer models)"));
    d.push_back(integer("max_blocks", &S::max_blocks, 1, 1e12, "design.md 'Tolerant' (no input hangs)",
                        "blocks a dry run executes before it stops with an alarm (endless M99 loops)"));
    d.push_back(integer("max_moves", &S::max_moves, 1, 1e12, "design.md 'Tolerant' (no input hangs)",
                        "moves a dry run emits before it stops with an alarm (a cycle whose step is far smaller than "
                        "its stroke, an endless loop of cycles)"));
    return d;
}

}  // namespace

std::span<const SwitchDef> switch_defs() {
    static const std::vector<SwitchDef> defs = make_defs();
    return defs;
}

const SwitchDef* find_switch_def(std::string_view key) {
    for (const SwitchDef& def : switch_defs())
        if (def.info.key == key) return &def;
    return nullptr;
}

std::string to_text(const SwitchValue& value) {
    if (const bool* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
    if (const std::int64_t* i = std::get_if<std::int64_t>(&value)) return fmt::format("{}", *i);
    if (const double* x = std::get_if<double>(&value)) return fmt::format("{}", *x);
    return std::get<std::string>(value);
}

}  // namespace kerf::machine::detail

namespace kerf::machine {

std::span<const SwitchInfo> switch_infos() {
    static const std::vector<SwitchInfo> infos = [] {
        std::vector<SwitchInfo> out;
        for (const detail::SwitchDef& def : detail::switch_defs()) out.push_back(def.info);
        return out;
    }();
    return infos;
}

const SwitchInfo* find_switch(std::string_view key) {
    for (const SwitchInfo& info : switch_infos())
        if (info.key == key) return &info;
    return nullptr;
}

std::optional<std::string> switch_value(const Machine& machine, std::string_view key) {
    const detail::SwitchDef* def = detail::find_switch_def(key);
    if (!def) return std::nullopt;
    return detail::to_text(def->get(machine.switches));
}

}  // namespace kerf::machine
