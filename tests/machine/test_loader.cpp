// Machine configuration files (machine/SCHEMA.md): the built-ins, the dialect → machine mapping,
// `base` inheritance, errors with positions, the tool table, the dump round trip.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "dialects/dialect.hpp"
#include "machine/machine.hpp"

using namespace kerf::machine;

namespace {

const std::vector<std::string> kMachineIds = {"fanuc-lathe", "fanuc-mill", "adv400-mill",
                                              "adv400-lathe", "pcnc-mill", "iso-legacy-mill", "haas-mill", "haas-lathe"};

std::string messages(const std::vector<LoadError>& errors) {
    std::string out;
    for (const LoadError& e : errors) out += e.message + " (line " + std::to_string(e.line) + ")\n";
    return out;
}

const LoadError* find_error(const std::vector<LoadError>& errors, const std::string& text) {
    for (const LoadError& e : errors)
        if (e.message.find(text) != std::string::npos) return &e;
    return nullptr;
}

// A complete small machine without base; tests replace lines to provoke errors.
std::string small_lathe(const std::string& x_axis_line = "rapid = 20000") {
    return "id = \"shop-lathe\"\n"                        // 1
           "name = \"Shop lathe\"\n"                       // 2
           "kind = \"lathe\"\n"                            // 3
           "diameter_x = true\n"                           // 4
           "\n"                                            // 5
           "[axes.X]\n"                                    // 6
           + x_axis_line + "\n"                            // 7
           "acceleration = 2000\n"                         // 8
           "[axes.Z]\n"                                    // 9
           "rapid = 24000\n"                               // 10
           "\n"                                            // 11
           "[tools.1]\n"                                   // 12
           "geometry = { X = -120.5, Z = -48.25 }\n"       // 13
           "wear = { X = 0.02, Z = -0.01 }\n"              // 14
           "nose_radius = 0.8\n"                           // 15
           "tip = 3\n"                                     // 16
           "comment = \"OD roughing\"\n";                  // 17
}

}  // namespace

TEST_CASE("every built-in machine file loads without errors", "[machine][builtin]") {
    INFO(messages(builtin_machine_errors()));
    CHECK(builtin_machine_errors().empty());
    REQUIRE(builtin_machine_texts().size() == kMachineIds.size());
    for (const auto& [stem, text] : builtin_machine_texts()) {
        INFO("machine/data/" << stem << ".toml");
        const LoadResult loaded = load_machine_text(text, stem);
        INFO(messages(loaded.errors));
        REQUIRE(loaded.machine);
        CHECK(loaded.errors.empty());
        CHECK(loaded.machine->id == std::string(stem));
        CHECK(!loaded.machine->name.empty());
        CHECK(!loaded.machine->axes.empty());
        for (const Axis& a : loaded.machine->axes) {
            INFO("axis " << a.letter);
            CHECK(a.rapid > 0);
            CHECK(a.acceleration > 0);
        }
    }
    for (const std::string& id : kMachineIds) CHECK(builtin_machines().find(id) != nullptr);
}

TEST_CASE("every built-in dialect maps to a built-in machine", "[machine][builtin]") {
    const std::vector<std::string> ids = kerf::dialects::builtin_registry().ids();
    REQUIRE(ids.size() >= 11);
    for (const std::string& id : ids) {
        INFO("dialect " << id);
        const Machine* named = builtin_machines().for_dialect(id);
        REQUIRE(named != nullptr);
        const Machine& m = default_machine_for(id);
        CHECK(m.id == named->id);
        CHECK(m.resolved_dialect == id);
        const kerf::dialects::Dialect* d = kerf::dialects::builtin_registry().find(id);
        REQUIRE(d);
        CHECK(m.kind == d->machine);   // a lathe dialect gets a lathe
        // Every axis of the machine is an axis letter of the dialect.
        for (const Axis& a : m.axes) CHECK(d->lexical.is_axis(a.letter));
    }
    CHECK(default_machine_for("fanuc-lathe-a").id == "fanuc-lathe");
    CHECK(default_machine_for("fanuc-lathe-b").id == "fanuc-lathe");
    CHECK(default_machine_for("fanuc-lathe-c").id == "fanuc-lathe");
    CHECK(default_machine_for("spinner-lathe-a").id == "fanuc-lathe");
    CHECK(default_machine_for("spinner-lathe-c").id == "fanuc-lathe");
    CHECK(default_machine_for("fanuc-mill").id == "fanuc-mill");
    CHECK(default_machine_for("adv400-mill").id == "adv400-mill");
    CHECK(default_machine_for("adv400-lathe").id == "adv400-lathe");
    CHECK(default_machine_for("pcnc-mill").id == "pcnc-mill");
    CHECK(default_machine_for("iso-legacy-mill").id == "iso-legacy-mill");
    CHECK(default_machine_for("haas-mill").id == "haas-mill");
    CHECK(default_machine_for("haas-lathe").id == "haas-lathe");
    // The same object each time (a cache), and an unknown id falls back to the FANUC mill.
    CHECK(&default_machine_for("fanuc-mill") == &default_machine_for("fanuc-mill"));
    CHECK(default_machine_for("no-such-dialect").id == "fanuc-mill");
}

TEST_CASE("a user dialect without a machine falls back by its kind", "[machine][builtin]") {
    kerf::dialects::Dialect lathe;
    lathe.id = "my-lathe";
    lathe.machine = kerf::dialects::MachineKind::lathe;
    lathe.lexical.calculator_decimal = true;
    const Machine m = default_machine_for(lathe);
    CHECK(m.id == "fanuc-lathe");
    CHECK(m.resolved_dialect == "my-lathe");
    CHECK(m.calculator_decimal);   // from the dialect's lexical rules
    kerf::dialects::Dialect mill;
    mill.id = "my-mill";
    mill.machine = kerf::dialects::MachineKind::mill;
    CHECK(default_machine_for(mill).id == "fanuc-mill");
}

TEST_CASE("the SPINNER TS-like lathe: axes, diameter X, IS-B, calculator input per dialect", "[machine][builtin]") {
    const Machine& spinner = default_machine_for("spinner-lathe-a");
    CHECK(spinner.kind == MachineKind::lathe);
    CHECK(spinner.axis_letters() == "XZBC");   // canonical order X Y Z A B C U V W
    CHECK(spinner.diameter_x);
    CHECK(spinner.increment == InputIncrement::is_b);
    CHECK(spinner.increment_mm() == Approx(0.001));
    CHECK(spinner.calculator_decimal);   // dialects.md §2: X45 = 45 mm on SPINNER
    CHECK(spinner.axis('C')->rotary);
    CHECK_FALSE(spinner.axis('B')->rotary);
    // B is the tailstock / sub-spindle carriage: no cutting tool rides on it (cycles.md §12, §16).
    CHECK_FALSE(spinner.axis('B')->carries_tool);
    CHECK(spinner.axis('X')->carries_tool);
    CHECK(spinner.axis('C')->carries_tool);
    CHECK_FALSE(spinner.has_axis('Y'));
    const Machine& plain = default_machine_for("fanuc-lathe-a");
    CHECK_FALSE(plain.calculator_decimal);   // plain FANUC: X45 = 0.045 mm on IS-B
    CHECK(plain.follows_dialect("calculator_decimal"));
    CHECK(default_machine_for("fanuc-mill").calculator_decimal == false);
    CHECK(default_machine_for("adv400-mill").calculator_decimal);
    CHECK(default_machine_for("pcnc-mill").calculator_decimal);
    CHECK_FALSE(default_machine_for("iso-legacy-mill").calculator_decimal);
    CHECK_FALSE(default_machine_for("fanuc-mill").diameter_x);
    CHECK(default_machine_for("adv400-lathe").diameter_x);
}

TEST_CASE("built-in values read back: offsets, reference points, limits, cycle parameters", "[machine][builtin]") {
    const Machine* lathe = builtin_machines().find("fanuc-lathe");
    REQUIRE(lathe);
    // Built-in machines state no soft limits: kerf cannot know the travels (machine files set them;
    // the loader reads min/max in the inheritance tests below).
    CHECK_FALSE(lathe->axis('X')->min.has_value());
    CHECK_FALSE(lathe->axis('X')->max.has_value());
    CHECK(lathe->axis('X')->rapid == Approx(24000));
    CHECK_FALSE(lathe->axis('C')->min.has_value());
    // FANUC's usual arrangement: home is machine zero, the work zero (G54) lies on the minus side.
    CHECK(axis_value(lathe->reference_points[0], 'X') == Approx(0));
    CHECK(axis_value(lathe->reference_points[1], 'Z') == Approx(-150));
    CHECK(axis_value(lathe->work_offsets[0], 'X') == Approx(-300));
    CHECK(axis_value(lathe->work_offsets[0], 'Z') == Approx(-550));
    CHECK(axis_value(lathe->work_shift, 'Z') == Approx(0));
    CHECK(lathe->max_spindle_rpm == Approx(4000));
    CHECK(lathe->max_live_tool_rpm.value() == Approx(6000));
    CHECK(lathe->cycle_parameters.g71_depth == Approx(3.0));
    CHECK(lathe->cycle_parameters.g76_angle == 60);
    CHECK(lathe->tailstock.coupling_z.has_value());
    const Machine* mill = builtin_machines().find("fanuc-mill");
    REQUIRE(mill);
    CHECK(axis_value(mill->work_offsets[0], 'X') == Approx(-500));
    CHECK(axis_value(mill->work_offsets[0], 'Y') == Approx(-300));
    CHECK(axis_value(mill->external_offset, 'Z') == Approx(0));
    CHECK(mill->tool_offset_count == 200);
    // iso-legacy-mill: the D registers of seed 004 (semantics.md §9.1, D17 = +0.8 per §12.7).
    const Machine* iso = builtin_machines().find("iso-legacy-mill");
    REQUIRE(iso);
    REQUIRE(iso->tool(8));
    CHECK(iso->tool(8)->radius == Approx(10));
    CHECK(iso->tool(17)->radius == Approx(0.8));
    CHECK(iso->tool(21)->radius == Approx(15));
    CHECK(iso->tool(4) == nullptr);
}

TEST_CASE("a user file with base overrides one key and keeps the rest", "[machine][base]") {
    const std::string text = "id = \"my-vmc\"\n"
                             "base = \"fanuc-mill\"\n"
                             "[switches]\n"
                             "rapid = \"linear\"\n";
    const LoadResult loaded = load_machine_text(text, "my-vmc.toml");
    INFO(messages(loaded.errors));
    REQUIRE(loaded.machine);
    const Machine& m = *loaded.machine;
    const Machine& base = *builtin_machines().find("fanuc-mill");
    CHECK(m.id == "my-vmc");
    CHECK(m.base == "fanuc-mill");
    CHECK(m.switches.rapid == RapidMode::linear);
    CHECK(base.switches.rapid == RapidMode::dog_leg);
    // Everything else is the base's.
    CHECK(m.name == base.name);
    CHECK(m.kind == base.kind);
    CHECK(m.axis_letters() == base.axis_letters());
    CHECK(m.axis('X')->rapid == base.axis('X')->rapid);
    CHECK(m.axis('Z')->min == base.axis('Z')->min);
    CHECK(m.work_offsets == base.work_offsets);
    CHECK(m.reference_points == base.reference_points);
    CHECK(m.max_spindle_rpm == base.max_spindle_rpm);
    CHECK(m.from_dialect == base.from_dialect);
    for (const SwitchInfo& info : switch_infos()) {
        if (info.key == "rapid") continue;
        INFO("switch " << info.key);
        CHECK(switch_value(m, info.key) == switch_value(base, info.key));
    }
    CHECK(m.dialects.empty());   // not the built-in default of fanuc-mill
}

TEST_CASE("base inheritance merges tables key by key", "[machine][base]") {
    const std::string text = "id = \"shop-ts\"\n"
                             "base = \"fanuc-lathe\"\n"
                             "name = \"Our TS46\"\n"
                             "input_increment = \"IS-C\"\n"
                             "[axes.X]\n"
                             "max = 280.0\n"                 // only the limit; rapid stays
                             "[axes.B]\n"
                             "present = false\n"             // no tailstock axis
                             "[work_offsets]\n"
                             "G55 = { Z = 12.5 }\n"          // only Z of G55
                             "[tools.1]\n"
                             "nose_radius = 0.4\n"
                             "[tools.1.geometry]\n"
                             "X = -100.0\n"
                             "[switches]\n"
                             "g52 = \"vector-shift\"\n"     // explicit: no longer follows the dialect
                             "[cycle_parameters]\n"
                             "g71_depth = 1.5\n";
    const LoadResult loaded = load_machine_text(text, "shop-ts.toml");
    INFO(messages(loaded.errors));
    REQUIRE(loaded.machine);
    const Machine& m = *loaded.machine;
    const Machine& base = *builtin_machines().find("fanuc-lathe");
    CHECK(m.name == "Our TS46");
    CHECK(m.increment == InputIncrement::is_c);
    CHECK(m.increment_mm() == Approx(0.0001));
    CHECK(m.axis('X')->max.value() == Approx(280));
    CHECK(m.axis('X')->rapid == Approx(base.axis('X')->rapid));
    CHECK(m.axis('X')->min == base.axis('X')->min);
    CHECK_FALSE(m.has_axis('B'));
    CHECK(m.axis_letters() == "XZC");
    CHECK(m.reference_points[0].count('B') == 0);   // values of the removed axis are dropped
    CHECK(axis_value(m.work_offsets[1], 'Z') == Approx(12.5));
    CHECK(m.work_offsets[1].count('X') == 1);       // X of G55 kept from the base
    CHECK(m.work_offsets[0] == base.work_offsets[0]);
    REQUIRE(m.tool(1));
    CHECK(m.tool(1)->nose_radius == Approx(0.4));
    CHECK(axis_value(m.tool(1)->geometry, 'X') == Approx(-100));
    CHECK_FALSE(m.follows_dialect("g52"));
    CHECK(m.follows_dialect("g53_motion"));
    CHECK(m.cycle_parameters.g71_depth == Approx(1.5));
    CHECK(m.cycle_parameters.g72_depth == Approx(base.cycle_parameters.g72_depth));
    // Resolved for the pcnc dialect, the explicit G52 stays; the rest follows the dialect.
    const kerf::dialects::Dialect* pcnc = kerf::dialects::builtin_registry().find("pcnc-mill");
    REQUIRE(pcnc);
    const Machine r = resolve_for_dialect(m, *pcnc);
    CHECK(r.switches.g52 == G52Semantics::vector_shift);
    CHECK(r.switches.g53_motion == G53Motion::g0_g1);
}

TEST_CASE("a registry resolves bases among user files too", "[machine][base]") {
    Registry registry = builtin_machines();
    CHECK(registry.add_text("id = \"cell-1\"\nbase = \"fanuc-mill\"\nmax_spindle_rpm = 12000\n", "cell-1.toml").empty());
    const auto errors = registry.add_text("id = \"cell-1b\"\nbase = \"cell-1\"\n[axes.X]\nmin = -900.0\n", "cell-1b.toml");
    INFO(messages(errors));
    CHECK(errors.empty());
    const Machine* m = registry.find("cell-1b");
    REQUIRE(m);
    CHECK(m->max_spindle_rpm == Approx(12000));
    CHECK(m->axis('X')->min.value() == Approx(-900));
    // Unknown base: an error on the base line.
    const LoadResult bad = load_machine_text("id = \"x\"\nbase = \"fanuc-milll\"\n", "bad.toml", registry);
    CHECK_FALSE(bad.machine);
    const LoadError* e = find_error(bad.errors, "unknown machine 'fanuc-milll'");
    REQUIRE(e);
    CHECK(e->line == 2);
}

TEST_CASE("tool table entries read back", "[machine][tools]") {
    const LoadResult loaded = load_machine_text(small_lathe(), "shop.toml");
    INFO(messages(loaded.errors));
    REQUIRE(loaded.machine);
    const Machine& m = *loaded.machine;
    CHECK(m.from_dialect.size() > 1);   // no base: the dialect-following keys follow the dialect
    REQUIRE(m.tool(1));
    const ToolOffset& t = *m.tool(1);
    CHECK(t.number == 1);
    CHECK(axis_value(t.geometry, 'X') == Approx(-120.5));
    CHECK(axis_value(t.geometry, 'Z') == Approx(-48.25));
    CHECK(axis_value(t.wear, 'X') == Approx(0.02));
    CHECK(axis_value(t.wear, 'Z') == Approx(-0.01));
    CHECK(t.nose_radius == Approx(0.8));
    CHECK(t.tip == 3);
    CHECK(t.comment == "OD roughing");
    CHECK(m.tool(2) == nullptr);

    // Mill registers: length and radius with wear.
    const LoadResult mill = load_machine_text("id = \"m\"\nbase = \"fanuc-mill\"\n"
                                              "[tools.12]\nlength = 150.25\nlength_wear = -0.05\n"
                                              "radius = 5.0\nradius_wear = 0.01\ntip = 0\n",
                                              "m.toml");
    INFO(messages(mill.errors));
    REQUIRE(mill.machine);
    REQUIRE(mill.machine->tool(12));
    CHECK(mill.machine->tool(12)->length == Approx(150.25));
    CHECK(mill.machine->tool(12)->length_wear == Approx(-0.05));
    CHECK(mill.machine->tool(12)->radius == Approx(5.0));
    CHECK(mill.machine->tool(12)->radius_wear == Approx(0.01));
}

TEST_CASE("errors carry line numbers: syntax error", "[machine][errors]") {
    const LoadResult r = load_machine_text("id = \"x\"\nname = \"y\"\nkind = = \"mill\"\n", "syntax.toml");
    CHECK_FALSE(r.machine);
    REQUIRE(r.errors.size() == 1);
    CHECK(r.errors[0].line == 3);
    CHECK(r.errors[0].column > 0);
    CHECK(r.errors[0].message.find("syntax.toml") == 0);
}

TEST_CASE("errors carry line numbers: unknown keys", "[machine][errors]") {
    {   // in an axis table
        const LoadResult r = load_machine_text(small_lathe("rapidd = 20000"), "shop.toml");
        CHECK_FALSE(r.machine);
        const LoadError* e = find_error(r.errors, "unknown key 'rapidd'");
        INFO(messages(r.errors));
        REQUIRE(e);
        CHECK(e->line == 7);
        CHECK(e->message.find("axes.X") != std::string::npos);
    }
    {   // at the top level, a misspelt switch, a tool key
        const LoadResult r = load_machine_text("id = \"m\"\nbase = \"fanuc-mill\"\nmax_spindel_rpm = 1\n"
                                               "[switches]\nrapid_mode = \"linear\"\n[tools.3]\nnoseradius = 1.0\n",
                                               "u.toml");
        INFO(messages(r.errors));
        CHECK_FALSE(r.machine);
        const LoadError* top = find_error(r.errors, "unknown key 'max_spindel_rpm'");
        REQUIRE(top);
        CHECK(top->line == 3);
        const LoadError* sw = find_error(r.errors, "switches.rapid_mode: unknown switch");
        REQUIRE(sw);
        CHECK(sw->line == 5);
        const LoadError* tool = find_error(r.errors, "unknown key 'noseradius'");
        REQUIRE(tool);
        CHECK(tool->line == 7);
    }
}

TEST_CASE("errors carry line numbers: bad values", "[machine][errors]") {
    const auto first_error = [](const std::string& text) {
        const LoadResult r = load_machine_text(text, "bad.toml");
        CHECK_FALSE(r.machine);
        REQUIRE_FALSE(r.errors.empty());
        return r.errors.front();
    };
    const std::string head = "id = \"m\"\nbase = \"fanuc-lathe\"\n";   // lines 1-2
    {
        const LoadError e = first_error(head + "[switches]\nrapid = \"zigzag\"\n");
        CHECK(e.line == 4);
        CHECK(e.message.find("unknown value \"zigzag\"") != std::string::npos);
        CHECK(e.message.find("\"dog-leg\"") != std::string::npos);   // lists the choices
    }
    {
        const LoadError e = first_error(head + "[tools.1]\ntip = 12\n");
        CHECK(e.line == 4);
        CHECK(e.message.find("tools.1.tip") != std::string::npos);
    }
    {
        const LoadError e = first_error(head + "[axes.X]\nrapid = \"fast\"\n");
        CHECK(e.line == 4);
        CHECK(e.message.find("expected a number") != std::string::npos);
    }
    {
        const LoadError e = first_error(head + "[switches]\nsubprogram_nesting = 0\n");
        CHECK(e.line == 4);
        CHECK(e.message.find("out of range") != std::string::npos);
    }
    {
        const LoadError e = first_error(head + "[switches]\nwarn_arc_without_plane = \"yes\"\n");
        CHECK(e.line == 4);
    }
    {
        const LoadError e = first_error(head + "input_increment = \"IS-A\"\n");
        CHECK(e.line == 3);
    }
    {   // an axis the machine does not have
        const LoadError e = first_error(head + "[work_offsets]\nG54 = { Y = 10.0 }\n");
        CHECK(e.line == 4);
        CHECK(e.message.find("Y is not an axis of this machine") != std::string::npos);
    }
    {
        const LoadError e = first_error(head + "[tools.65]\nnose_radius = 0.4\n");   // count is 64
        CHECK(e.line == 3);
    }
    {
        const LoadError e = first_error(head + "[axes.Z]\nmin = 10.0\nmax = 5.0\n");
        CHECK(e.line == 3);
        CHECK(e.message.find("min") != std::string::npos);
    }
    {
        const LoadError e = first_error(head + "calculator_decimal = \"maybe\"\n");
        CHECK(e.line == 3);
    }
    {
        const LoadError e = first_error("id = \"m\"\nbase = \"fanuc-mill\"\ndiameter_x = true\n");
        CHECK(e.line == 3);   // diameter programming on a mill
    }
    {
        const LoadError e = first_error(head + "[cycle_parameters]\ng76_angle = 45\n");
        CHECK(e.line == 4);
    }
}

TEST_CASE("required keys of a file without base", "[machine][errors]") {
    const LoadResult r = load_machine_text("name = \"x\"\n[axes.X]\nrapid = 1000\n", "req.toml");
    CHECK_FALSE(r.machine);
    CHECK(find_error(r.errors, "missing or empty key 'id'"));
    CHECK(find_error(r.errors, "missing key 'kind'"));
    const LoadResult no_axes = load_machine_text("id = \"a\"\nname = \"b\"\nkind = \"mill\"\n", "axes.toml");
    CHECK(find_error(no_axes.errors, "no axes"));
    const LoadResult no_rapid = load_machine_text("id = \"a\"\nname = \"b\"\nkind = \"mill\"\n[axes.X]\nmin = 0.0\n",
                                                  "rapid.toml");
    const LoadError* e = find_error(no_rapid.errors, "rapid must be given");
    REQUIRE(e);
    CHECK(e->line == 4);
}

TEST_CASE("machine_to_toml round-trips every built-in", "[machine][dump]") {
    for (const std::string& id : kMachineIds) {
        INFO("machine " << id);
        const Machine& m = *builtin_machines().find(id);
        const std::string text = machine_to_toml(m);
        const LoadResult back = load_machine_text(text, "dump.toml");
        INFO(text);
        INFO(messages(back.errors));
        REQUIRE(back.machine);
        const Machine& b = *back.machine;
        CHECK(b.id == m.id);
        CHECK(b.name == m.name);
        CHECK(b.kind == m.kind);
        CHECK(b.dialects == m.dialects);
        CHECK(b.axis_letters() == m.axis_letters());
        for (const Axis& a : m.axes) {
            CHECK(b.axis(a.letter)->rapid == a.rapid);
            CHECK(b.axis(a.letter)->min == a.min);
            CHECK(b.axis(a.letter)->rotary == a.rotary);
            CHECK(b.axis(a.letter)->carries_tool == a.carries_tool);
        }
        CHECK(b.work_offsets == m.work_offsets);
        CHECK(b.reference_points == m.reference_points);
        CHECK(b.tools.size() == m.tools.size());
        for (const auto& [n, t] : m.tools) CHECK(b.tool(n)->radius == t.radius);
        CHECK(b.calculator_decimal == m.calculator_decimal);
        CHECK(b.follows_dialect("calculator_decimal") == m.follows_dialect("calculator_decimal"));
        for (const SwitchInfo& info : switch_infos()) {
            INFO("switch " << info.key);
            CHECK(switch_value(b, info.key) == switch_value(m, info.key));
            CHECK(b.follows_dialect(info.key) == m.follows_dialect(info.key));
        }
        CHECK(b.cycle_parameters.g76_min_depth == m.cycle_parameters.g76_min_depth);
    }
}

TEST_CASE("machine/SCHEMA.md documents every switch", "[machine][docs]") {
    std::ifstream in(std::string(KERF_SOURCE_DIR) + "/machine/SCHEMA.md");
    REQUIRE(in);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string schema = buffer.str();
    for (const SwitchInfo& info : switch_infos()) {
        INFO("switch " << info.key);
        std::string needle = "`";   // built in steps: GCC 12 warns (-Wrestrict) on "`" + s + "`"
        needle += info.key;
        needle += '`';
        CHECK(schema.find(needle) != std::string::npos);
        CHECK(!info.source.empty());
        CHECK(!info.meaning.empty());
        CHECK(!info.default_value.empty());
        if (info.type == SwitchType::choice) {
            CHECK(std::find(info.choices.begin(), info.choices.end(), info.default_value) != info.choices.end());
        }
    }
}

TEST_CASE("m_codes lists the machine builder's M codes, strictly", "[machine][m_codes]") {
    const Registry& bases = builtin_machines();
    const LoadResult ok = load_machine_text("id = \"shop\"\nbase = \"fanuc-mill\"\nm_codes = [\"M25\", 165, \"m7\"]\n", "shop.toml", bases);
    REQUIRE(ok.errors.empty());
    REQUIRE(ok.machine);
    CHECK(ok.machine->m_codes == std::vector<int>{25, 165, 7});
    // Derived from a machine with a list, without one: the base's stays.
    CHECK(builtin_machines().find("fanuc-mill")->m_codes.empty());
    for (const char* bad : {"m_codes = [\"G25\"]", "m_codes = [\"M25.5\"]", "m_codes = [-1]", "m_codes = \"M25\"",
                            "m_codes = [\"M25\", 25]"}) {
        INFO(bad);
        const LoadResult r = load_machine_text(std::string("id = \"shop\"\nbase = \"fanuc-mill\"\n") + bad + "\n", "shop.toml", bases);
        CHECK(find_error(r.errors, "m_codes") != nullptr);
    }
}
