// machine_to_toml: a machine as a complete file in the machine/SCHEMA.md format (no base), for
// `kerf machines --dump`-style output and round-trip tests.
#include <fmt/format.h>

#include <sstream>

#include <toml++/toml.h>

#include "machine/machine.hpp"
#include "machine/switch_table.hpp"

namespace kerf::machine {
namespace {

toml::table axis_values(const AxisValues& values) {
    toml::table t;
    for (const auto& [letter, value] : values) t.insert(std::string(1, letter), value);
    return t;
}

}  // namespace

std::string machine_to_toml(const Machine& m) {
    toml::table root;
    root.insert("id", m.id);
    root.insert("name", m.name);
    if (!m.reference.empty()) root.insert("reference", m.reference);
    root.insert("kind", m.kind == MachineKind::lathe ? "lathe" : "mill");
    toml::array dialect_ids;
    for (const std::string& id : m.dialects) dialect_ids.push_back(id);
    root.insert("dialects", std::move(dialect_ids));
    root.insert("diameter_x", m.diameter_x);
    root.insert("input_increment", m.increment == InputIncrement::is_c ? "IS-C" : "IS-B");
    if (m.follows_dialect("calculator_decimal")) root.insert("calculator_decimal", "dialect");
    else root.insert("calculator_decimal", m.calculator_decimal);
    root.insert("max_spindle_rpm", m.max_spindle_rpm);
    if (m.max_live_tool_rpm) root.insert("max_live_tool_rpm", *m.max_live_tool_rpm);
    if (m.max_cutting_feed) root.insert("max_cutting_feed", *m.max_cutting_feed);
    root.insert("tool_offset_count", m.tool_offset_count);
    root.insert("additional_work_offset_count", m.additional_work_offset_count);
    if (!m.m_codes.empty()) {
        toml::array codes;
        for (const int c : m.m_codes) codes.push_back(fmt::format("M{:02}", c));
        root.insert("m_codes", std::move(codes));
    }

    toml::table axes;
    for (const Axis& a : m.axes) {
        toml::table t;
        t.insert("rapid", a.rapid);
        t.insert("acceleration", a.acceleration);
        t.insert("rotary", a.rotary);
        t.insert("carries_tool", a.carries_tool);
        if (a.min) t.insert("min", *a.min);
        if (a.max) t.insert("max", *a.max);
        axes.insert(std::string(1, a.letter), std::move(t));
    }
    root.insert("axes", std::move(axes));

    toml::table offsets;
    for (int i = 0; i < 6; ++i) offsets.insert(fmt::format("G5{}", 4 + i), axis_values(m.work_offsets[i]));
    offsets.insert("external", axis_values(m.external_offset));
    for (const auto& [n, values] : m.additional_work_offsets) offsets.insert(fmt::format("P{}", n), axis_values(values));
    root.insert("work_offsets", std::move(offsets));
    root.insert("work_shift", axis_values(m.work_shift));
    toml::table refs;
    for (int i = 0; i < 4; ++i) refs.insert(fmt::format("{}", i + 1), axis_values(m.reference_points[i]));
    root.insert("reference_points", std::move(refs));

    toml::table tools;
    for (const auto& [number, tool] : m.tools) {
        toml::table t;
        if (!tool.geometry.empty()) t.insert("geometry", axis_values(tool.geometry));
        if (!tool.wear.empty()) t.insert("wear", axis_values(tool.wear));
        t.insert("nose_radius", tool.nose_radius);
        t.insert("nose_radius_wear", tool.nose_radius_wear);
        t.insert("tip", tool.tip);
        t.insert("length", tool.length);
        t.insert("length_wear", tool.length_wear);
        t.insert("radius", tool.radius);
        t.insert("radius_wear", tool.radius_wear);
        if (!tool.comment.empty()) t.insert("comment", tool.comment);
        tools.insert(fmt::format("{}", number), std::move(t));
    }
    root.insert("tools", std::move(tools));

    const CycleParameters& c = m.cycle_parameters;
    root.insert("cycle_parameters",
                toml::table{{"g71_depth", c.g71_depth},
                            {"g71_retract", c.g71_retract},
                            {"g72_depth", c.g72_depth},
                            {"g72_retract", c.g72_retract},
                            {"g73_relief_x", c.g73_relief_x},
                            {"g73_relief_z", c.g73_relief_z},
                            {"g73_divisions", c.g73_divisions},
                            {"g74_retract", c.g74_retract},
                            {"g75_retract", c.g75_retract},
                            {"g76_finishing_passes", c.g76_finishing_passes},
                            {"g76_chamfer", c.g76_chamfer},
                            {"g76_angle", c.g76_angle},
                            {"g76_min_depth", c.g76_min_depth},
                            {"g76_allowance", c.g76_allowance}});
    toml::table tailstock;
    if (m.tailstock.coupling_z) tailstock.insert("coupling_z", *m.tailstock.coupling_z);
    if (m.tailstock.coupling_z_second) tailstock.insert("coupling_z_second", *m.tailstock.coupling_z_second);
    if (m.tailstock.home_b) tailstock.insert("home_b", *m.tailstock.home_b);
    if (!tailstock.empty()) root.insert("tailstock", std::move(tailstock));

    toml::table switches;
    for (const detail::SwitchDef& def : detail::switch_defs()) {
        const std::string key(def.info.key);
        if (def.info.dialect_default && m.follows_dialect(def.info.key)) {
            switches.insert(key, "dialect");
            continue;
        }
        const detail::SwitchValue v = def.get(m.switches);
        if (const bool* b = std::get_if<bool>(&v)) switches.insert(key, *b);
        else if (const std::int64_t* i = std::get_if<std::int64_t>(&v)) switches.insert(key, *i);
        else if (const double* x = std::get_if<double>(&v)) switches.insert(key, *x);
        else switches.insert(key, std::get<std::string>(v));
    }
    root.insert("switches", std::move(switches));

    std::ostringstream out;
    // Full float precision (the dump must load back to the same values), no indented sub-tables.
    out << "# kerf machine configuration (machine/SCHEMA.md), written by machine_to_toml\n"
        << toml::toml_formatter(root, toml::toml_formatter::default_flags & ~toml::format_flags::indent_sub_tables)
        << "\n";
    return out.str();
}

}  // namespace kerf::machine
