// Reads one machine file (machine/SCHEMA.md) into a Machine. Every problem is reported with its key
// path and TOML position; unknown keys are errors (a misspelt key must not silently keep a default).
// With `base = "<id>"` the file starts from that machine and changes only the keys it gives.
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include <toml++/toml.h>

#include "dialects/toml_errors.hpp"
#include "machine/machine.hpp"
#include "machine/switch_table.hpp"

namespace kerf::machine {
namespace {

constexpr std::string_view kAxisOrder = "XYZABCUVW";

class Reader : public dialects::TomlErrors {
public:
    using TomlErrors::TomlErrors;

    void check_keys(const toml::table& t, std::initializer_list<std::string_view> allowed, std::string_view where) {
        TomlErrors::check_keys(t, allowed, where, "machine/SCHEMA.md");
    }

    std::optional<std::string> string(const toml::table& t, std::string_view key, std::string_view where) {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        if (const auto v = n->value<std::string>()) return *v;
        error(n, fmt::format("{}{}: expected a string", where, key));
        return std::nullopt;
    }

    std::optional<bool> boolean(const toml::table& t, std::string_view key, std::string_view where) {
        const toml::node* n = t.get(key);
        if (!n) return std::nullopt;
        if (n->is_boolean()) return n->as_boolean()->get();
        error(n, fmt::format("{}{}: expected true or false", where, key));
        return std::nullopt;
    }

    // A number (integer or float) within [min, max].
    std::optional<double> number(const toml::node* n, std::string_view path, double min, double max) {
        if (!n) return std::nullopt;
        double v = 0;
        if (n->is_integer()) v = static_cast<double>(n->as_integer()->get());
        else if (n->is_floating_point()) v = n->as_floating_point()->get();
        else {
            error(n, fmt::format("{}: expected a number", path));
            return std::nullopt;
        }
        if (!std::isfinite(v) || v < min || v > max) {
            error(n, fmt::format("{}: {} is out of range ({} .. {})", path, v, min, max));
            return std::nullopt;
        }
        return v;
    }
    std::optional<double> number(const toml::table& t, std::string_view key, std::string_view where, double min,
                                 double max) {
        return number(t.get(key), fmt::format("{}{}", where, key), min, max);
    }

    std::optional<std::int64_t> integer(const toml::node* n, std::string_view path, std::int64_t min,
                                        std::int64_t max) {
        if (!n) return std::nullopt;
        if (!n->is_integer()) {
            error(n, fmt::format("{}: expected an integer", path));
            return std::nullopt;
        }
        const std::int64_t v = n->as_integer()->get();
        if (v < min || v > max) {
            error(n, fmt::format("{}: {} is out of range ({} .. {})", path, v, min, max));
            return std::nullopt;
        }
        return v;
    }
    std::optional<std::int64_t> integer(const toml::table& t, std::string_view key, std::string_view where,
                                        std::int64_t min, std::int64_t max) {
        return integer(t.get(key), fmt::format("{}{}", where, key), min, max);
    }

    const toml::table* table(const toml::table& t, std::string_view key, std::string_view where) {
        const toml::node* n = t.get(key);
        if (!n) return nullptr;
        if (const toml::table* tt = n->as_table()) return tt;
        error(n, fmt::format("{}{}: expected a table", where, key));
        return nullptr;
    }

};

std::optional<char> axis_letter(std::string_view key) {
    if (key.size() != 1 || kAxisOrder.find(key[0]) == std::string_view::npos) return std::nullopt;
    return key[0];
}

void sort_axes(std::vector<Axis>& axes) {
    std::sort(axes.begin(), axes.end(),
              [](const Axis& a, const Axis& b) { return kAxisOrder.find(a.letter) < kAxisOrder.find(b.letter); });
}

void set_from_dialect(Machine& m, std::string_view key, bool follows) {
    auto it = std::find(m.from_dialect.begin(), m.from_dialect.end(), key);
    if (follows && it == m.from_dialect.end()) m.from_dialect.emplace_back(key);
    if (!follows && it != m.from_dialect.end()) m.from_dialect.erase(it);
}

void prune(AxisValues& values, const Machine& m) {
    std::erase_if(values, [&](const auto& entry) { return !m.has_axis(entry.first); });
}

void prune_absent_axes(Machine& m) {
    for (AxisValues& v : m.work_offsets) prune(v, m);
    for (auto& [number, v] : m.additional_work_offsets) prune(v, m);
    prune(m.external_offset, m);
    prune(m.work_shift, m);
    for (AxisValues& v : m.reference_points) prune(v, m);
    for (auto& [number, tool] : m.tools) {
        prune(tool.geometry, m);
        prune(tool.wear, m);
    }
}

class MachineReader {
public:
    MachineReader(Reader& r, Machine& m) : r_(r), m_(m) {}

    void read_axes(const toml::table& axes) {
        for (const auto& [key, node] : axes) {
            const std::string where = fmt::format("axes.{}", key.str());
            const auto letter = axis_letter(key.str());
            if (!letter) {
                r_.error(&node, fmt::format("{}: not an axis letter (one of {})", where, kAxisOrder));
                continue;
            }
            const toml::table* t = node.as_table();
            if (!t) {
                r_.error(&node, fmt::format("{}: expected a table", where));
                continue;
            }
            r_.check_keys(*t, {"rapid", "acceleration", "min", "max", "rotary", "carries_tool", "present"}, where);
            const std::string prefix = where + ".";
            if (const auto present = r_.boolean(*t, "present", prefix); present && !*present) {
                std::erase_if(m_.axes, [&](const Axis& a) { return a.letter == *letter; });
                continue;
            }
            auto it = std::find_if(m_.axes.begin(), m_.axes.end(), [&](const Axis& a) { return a.letter == *letter; });
            const bool added = it == m_.axes.end();
            if (added) {
                Axis a;
                a.letter = *letter;
                a.rotary = *letter == 'A' || *letter == 'C';   // B is linear on lathes (tailstock, sub-spindle)
                m_.axes.push_back(a);
                it = m_.axes.end() - 1;
            }
            Axis& a = *it;
            if (const auto v = r_.boolean(*t, "rotary", prefix)) a.rotary = *v;
            if (const auto v = r_.boolean(*t, "carries_tool", prefix)) a.carries_tool = *v;
            if (const auto v = r_.number(*t, "rapid", prefix, 0, 1e7)) a.rapid = *v;
            if (const auto v = r_.number(*t, "acceleration", prefix, 0, 1e7)) a.acceleration = *v;
            if (const auto v = r_.number(*t, "min", prefix, -1e7, 1e7)) a.min = *v;
            if (const auto v = r_.number(*t, "max", prefix, -1e7, 1e7)) a.max = *v;
            if (a.rapid <= 0) r_.error(&node, fmt::format("{}: rapid must be given and greater than 0", where));
            if (a.min && a.max && *a.min >= *a.max)
                r_.error(&node, fmt::format("{}: min ({}) must be less than max ({})", where, *a.min, *a.max));
        }
        sort_axes(m_.axes);
    }

    // LETTER = number, merged into `values`; letters must be axes of the machine.
    void read_axis_values(const toml::node& node, std::string_view where, AxisValues& values) {
        const toml::table* t = node.as_table();
        if (!t) {
            r_.error(&node, fmt::format("{}: expected a table of axis values ({{ X = 0, Z = 0 }})", where));
            return;
        }
        for (const auto& [key, value] : *t) {
            const std::string path = fmt::format("{}.{}", where, key.str());
            const auto letter = axis_letter(key.str());
            if (!letter) {
                r_.error(&value, fmt::format("{}: not an axis letter", path));
                continue;
            }
            if (!m_.has_axis(*letter)) {
                r_.error(&value, fmt::format("{}: {} is not an axis of this machine (axes: {})", path, *letter,
                                             m_.axis_letters()));
                continue;
            }
            if (const auto v = r_.number(&value, path, -1e7, 1e7)) values[*letter] = *v;
        }
    }

    // G54 … G59, external, and P1 … P<additional_work_offset_count> for G54.1 Pn.
    void read_work_offsets(const toml::table& t) {
        for (const auto& [key, node] : t) {
            const std::string_view k = key.str();
            if (k == "G54" || k == "G55" || k == "G56" || k == "G57" || k == "G58" || k == "G59" || k == "external") continue;
            int n = 0;
            const bool p = k.size() > 1 && k.front() == 'P';
            const auto [end, ec] = p ? std::from_chars(k.data() + 1, k.data() + k.size(), n) : std::from_chars_result{};
            if (!p || ec != std::errc() || end != k.data() + k.size() || n < 1 || n > m_.additional_work_offset_count) {
                r_.error(&node, fmt::format("work_offsets: unknown key '{}': G54 … G59, external, or P1 … P{} for G54.1 Pn "
                                            "(additional_work_offset_count; see machine/SCHEMA.md)",
                                            k, m_.additional_work_offset_count));
                continue;
            }
            read_axis_values(node, fmt::format("work_offsets.{}", k), m_.additional_work_offsets[n]);
        }
        for (int i = 0; i < 6; ++i) {
            const std::string key = fmt::format("G5{}", 4 + i);
            if (const toml::node* n = t.get(key)) read_axis_values(*n, "work_offsets." + key, m_.work_offsets[i]);
        }
        if (const toml::node* n = t.get("external")) read_axis_values(*n, "work_offsets.external", m_.external_offset);
    }

    void read_reference_points(const toml::table& t) {
        r_.check_keys(t, {"1", "2", "3", "4"}, "reference_points");
        for (int i = 0; i < 4; ++i) {
            const std::string key = fmt::format("{}", i + 1);
            if (const toml::node* n = t.get(key))
                read_axis_values(*n, "reference_points." + key, m_.reference_points[i]);
        }
    }

    void read_tools(const toml::table& tools) {
        for (const auto& [key, node] : tools) {
            const std::string where = fmt::format("tools.{}", key.str());
            int number = 0;
            const std::string_view k = key.str();
            const auto [end, ec] = std::from_chars(k.data(), k.data() + k.size(), number);
            if (ec != std::errc() || end != k.data() + k.size() || number < 1 || number > m_.tool_offset_count) {
                r_.error(&node, fmt::format("{}: the key must be an offset number 1 .. {} (tool_offset_count)", where,
                                            m_.tool_offset_count));
                continue;
            }
            const toml::table* t = node.as_table();
            if (!t) {
                r_.error(&node, fmt::format("{}: expected a table", where));
                continue;
            }
            r_.check_keys(*t,
                          {"geometry", "wear", "nose_radius", "nose_radius_wear", "tip", "length", "length_wear",
                           "radius", "radius_wear", "comment"},
                          where);
            ToolOffset& tool = m_.tools[number];
            tool.number = number;
            const std::string prefix = where + ".";
            if (const toml::node* n = t->get("geometry")) read_axis_values(*n, prefix + "geometry", tool.geometry);
            if (const toml::node* n = t->get("wear")) read_axis_values(*n, prefix + "wear", tool.wear);
            if (const auto v = r_.number(*t, "nose_radius", prefix, 0, 1000)) tool.nose_radius = *v;
            if (const auto v = r_.number(*t, "nose_radius_wear", prefix, -1000, 1000)) tool.nose_radius_wear = *v;
            if (const auto v = r_.integer(*t, "tip", prefix, 0, 9)) tool.tip = static_cast<int>(*v);
            if (const auto v = r_.number(*t, "length", prefix, -1e5, 1e5)) tool.length = *v;
            if (const auto v = r_.number(*t, "length_wear", prefix, -1e5, 1e5)) tool.length_wear = *v;
            if (const auto v = r_.number(*t, "radius", prefix, -1e4, 1e4)) tool.radius = *v;
            if (const auto v = r_.number(*t, "radius_wear", prefix, -1e4, 1e4)) tool.radius_wear = *v;
            if (const auto v = r_.string(*t, "comment", prefix)) tool.comment = *v;
        }
    }

    void read_cycle_parameters(const toml::table& t) {
        CycleParameters& c = m_.cycle_parameters;
        const std::string_view w = "cycle_parameters.";
        r_.check_keys(t,
                      {"g71_depth", "g71_retract", "g72_depth", "g72_retract", "g73_relief_x", "g73_relief_z",
                       "g73_divisions", "g74_retract", "g75_retract", "g76_finishing_passes", "g76_chamfer",
                       "g76_angle", "g76_min_depth", "g76_allowance"},
                      "cycle_parameters");
        const auto num = [&](std::string_view key, double& field, double min, double max) {
            if (const auto v = r_.number(t, key, w, min, max)) field = *v;
        };
        const auto integer = [&](std::string_view key, int& field, int min, int max) {
            if (const auto v = r_.integer(t, key, w, min, max)) field = static_cast<int>(*v);
        };
        num("g71_depth", c.g71_depth, 0, 1000);
        num("g71_retract", c.g71_retract, 0, 1000);
        num("g72_depth", c.g72_depth, 0, 1000);
        num("g72_retract", c.g72_retract, 0, 1000);
        num("g73_relief_x", c.g73_relief_x, -1000, 1000);
        num("g73_relief_z", c.g73_relief_z, -1000, 1000);
        integer("g73_divisions", c.g73_divisions, 1, 999);
        num("g74_retract", c.g74_retract, 0, 1000);
        num("g75_retract", c.g75_retract, 0, 1000);
        integer("g76_finishing_passes", c.g76_finishing_passes, 1, 99);
        integer("g76_chamfer", c.g76_chamfer, 0, 99);
        if (const toml::node* n = t.get("g76_angle")) {
            if (const auto v = r_.integer(n, "cycle_parameters.g76_angle", 0, 99)) {
                if (*v == 80 || *v == 60 || *v == 55 || *v == 30 || *v == 29 || *v == 0)
                    c.g76_angle = static_cast<int>(*v);
                else
                    r_.error(n, fmt::format("cycle_parameters.g76_angle: {} is not one of 80, 60, 55, 30, 29, 0 "
                                            "(cycles.md §7)",
                                            *v));
            }
        }
        num("g76_min_depth", c.g76_min_depth, 0, 100);
        num("g76_allowance", c.g76_allowance, 0, 100);
    }

    void read_tailstock(const toml::table& t) {
        r_.check_keys(t, {"coupling_z", "coupling_z_second", "home_b"}, "tailstock");
        if (const auto v = r_.number(t, "coupling_z", "tailstock.", -1e5, 1e5)) m_.tailstock.coupling_z = *v;
        if (const auto v = r_.number(t, "coupling_z_second", "tailstock.", -1e5, 1e5))
            m_.tailstock.coupling_z_second = *v;
        if (const auto v = r_.number(t, "home_b", "tailstock.", -1e5, 1e5)) m_.tailstock.home_b = *v;
    }

    void read_switches(const toml::table& t) {
        for (const auto& [key, node] : t) {
            const std::string path = fmt::format("switches.{}", key.str());
            const detail::SwitchDef* def = detail::find_switch_def(key.str());
            if (!def) {
                r_.error(&node, fmt::format("{}: unknown switch (see machine/SCHEMA.md)", path));
                continue;
            }
            const SwitchInfo& info = def->info;
            switch (info.type) {
            case SwitchType::choice: {
                const auto v = node.value<std::string>();
                const bool known = v && std::find(info.choices.begin(), info.choices.end(), *v) != info.choices.end();
                if (!known) {
                    std::string choices;
                    for (const std::string_view c : info.choices) choices += fmt::format("{}\"{}\"", choices.empty() ? "" : ", ", c);
                    r_.error(&node, v ? fmt::format("{}: unknown value \"{}\" (one of {})", path, *v, choices)
                                      : fmt::format("{}: expected a string (one of {})", path, choices));
                    break;
                }
                if (*v == "dialect") {
                    set_from_dialect(m_, info.key, true);
                } else {
                    set_from_dialect(m_, info.key, false);
                    def->set(m_.switches, *v);
                }
                break;
            }
            case SwitchType::boolean:
                if (node.is_boolean()) def->set(m_.switches, node.as_boolean()->get());
                else r_.error(&node, fmt::format("{}: expected true or false", path));
                break;
            case SwitchType::integer:
                if (const auto v = r_.integer(&node, path, static_cast<std::int64_t>(info.min),
                                              static_cast<std::int64_t>(info.max)))
                    def->set(m_.switches, *v);
                break;
            case SwitchType::number:
                if (const auto v = r_.number(&node, path, info.min, info.max)) def->set(m_.switches, *v);
                break;
            }
        }
    }

private:
    Reader& r_;
    Machine& m_;
};

}  // namespace

LoadResult load_machine_text(std::string_view toml_text, std::string_view source_name) {
    return load_machine_text(toml_text, source_name, builtin_machines());
}

LoadResult load_machine_text(std::string_view toml_text, std::string_view source_name, const Registry& bases) {
    LoadResult result;
    std::optional<toml::table> parsed = dialects::parse_toml(toml_text, source_name, result.errors);
    if (!parsed) return result;
    const toml::table& root = *parsed;
    Reader r(source_name);
    Machine m;
    r.check_keys(root,
                 {"id", "name", "kind", "base", "reference", "dialects", "diameter_x", "input_increment",
                  "calculator_decimal", "max_spindle_rpm", "max_live_tool_rpm", "max_cutting_feed",
                  "tool_offset_count", "additional_work_offset_count", "m_codes", "axes", "work_offsets", "work_shift", "reference_points", "tools",
                  "cycle_parameters", "tailstock", "switches"},
                 "top level");

    // The base first: everything below changes it.
    const auto base = r.string(root, "base", "");
    if (base && !base->empty()) {
        const Machine* found = bases.find(*base);
        if (!found) {
            std::string known;
            for (const std::string& id : bases.ids()) known += (known.empty() ? "" : ", ") + id;
            r.error(root.get("base"), fmt::format("base: unknown machine '{}' (known: {})", *base, known));
            result.errors = std::move(r.errors);
            return result;
        }
        m = *found;
        m.base = *base;
        m.dialects.clear();   // a derived machine is not the built-in default of the base's dialects
        m.resolved_dialect.clear();
    } else {
        // A machine without base starts with every key that may follow the dialect doing so.
        m.from_dialect.emplace_back("calculator_decimal");
        for (const SwitchInfo& info : switch_infos())
            if (info.dialect_default) m.from_dialect.emplace_back(info.key);
    }
    const bool derived = !m.base.empty();

    if (const auto v = r.string(root, "id", "")) m.id = *v;
    if (!root.contains("id") || m.id.empty())
        r.error(root.contains("id") ? root.get("id") : &root, "top level: missing or empty key 'id'");
    if (const auto v = r.string(root, "name", "")) m.name = *v;
    else if (!derived) r.error(&root, "top level: missing key 'name'");
    if (const auto v = r.string(root, "reference", "")) m.reference = *v;
    if (const auto v = r.string(root, "kind", "")) {
        if (*v == "lathe") m.kind = MachineKind::lathe;
        else if (*v == "mill") m.kind = MachineKind::mill;
        else r.error(root.get("kind"), fmt::format("kind: unknown value \"{}\" (\"lathe\" or \"mill\")", *v));
    } else if (!derived) {
        r.error(&root, "top level: missing key 'kind' (\"lathe\" or \"mill\")");
    }
    if (const toml::node* n = root.get("dialects")) {
        m.dialects.clear();
        if (const toml::array* a = n->as_array()) {
            for (const toml::node& item : *a) {
                if (const auto s = item.value<std::string>()) m.dialects.push_back(*s);
                else r.error(&item, "dialects: expected strings (dialect ids)");
            }
        } else {
            r.error(n, "dialects: expected an array of dialect ids");
        }
    }

    MachineReader mr(r, m);
    // Axes before everything that names axes.
    if (const toml::table* t = r.table(root, "axes", "")) mr.read_axes(*t);
    if (m.axes.empty()) r.error(root.contains("axes") ? root.get("axes") : &root, "axes: the machine has no axes");
    prune_absent_axes(m);   // values a base gave for axes this file removed

    if (const auto v = r.boolean(root, "diameter_x", "")) m.diameter_x = *v;
    if (m.diameter_x && m.kind != MachineKind::lathe)
        r.error(root.contains("diameter_x") ? root.get("diameter_x") : &root,
                "diameter_x: diameter programming is for lathes (kind = \"lathe\")");
    if (m.diameter_x && !m.has_axis('X')) r.error(&root, "diameter_x: the machine has no X axis");
    if (const toml::node* n = root.get("input_increment")) {
        const auto s = n->value<std::string>();
        const auto x = n->is_floating_point() ? std::optional<double>(n->as_floating_point()->get()) : std::nullopt;
        if ((s && *s == "IS-B") || (x && *x == 0.001)) m.increment = InputIncrement::is_b;
        else if ((s && *s == "IS-C") || (x && *x == 0.0001)) m.increment = InputIncrement::is_c;
        else r.error(n, "input_increment: expected \"IS-B\" (0.001 mm) or \"IS-C\" (0.0001 mm)");
    }
    if (const toml::node* n = root.get("calculator_decimal")) {
        if (n->is_boolean()) {
            m.calculator_decimal = n->as_boolean()->get();
            set_from_dialect(m, "calculator_decimal", false);
        } else if (const auto s = n->value<std::string>(); s && *s == "dialect") {
            set_from_dialect(m, "calculator_decimal", true);
        } else {
            r.error(n, "calculator_decimal: expected true, false or \"dialect\"");
        }
    }
    if (const auto v = r.number(root, "max_spindle_rpm", "", 0, 1e6)) m.max_spindle_rpm = *v;
    if (const auto v = r.number(root, "max_live_tool_rpm", "", 0, 1e6)) m.max_live_tool_rpm = *v;
    if (const auto v = r.number(root, "max_cutting_feed", "", 0, 1e7)) m.max_cutting_feed = *v;
    if (const auto v = r.integer(root, "tool_offset_count", "", 1, 9999)) m.tool_offset_count = static_cast<int>(*v);
    if (const auto v = r.integer(root, "additional_work_offset_count", "", 0, 300))
        m.additional_work_offset_count = static_cast<int>(*v);
    if (const toml::node* n = root.get("m_codes")) {
        // The builder's M codes: "M25" or 25, each once (machine/SCHEMA.md).
        m.m_codes.clear();
        const toml::array* a = n->as_array();
        if (!a) r.error(n, "m_codes: expected an array of M codes (\"M25\" or 25)");
        for (const toml::node& item : a ? *a : toml::array{}) {
            std::optional<std::int64_t> code;
            if (item.is_integer()) code = item.as_integer()->get();
            else if (const auto text = item.value<std::string>()) {
                const auto spelled = dialects::parse_code_spelling(*text);
                if (spelled && spelled->first == 'M' && spelled->second % 10 == 0) code = spelled->second / 10;
            }
            if (!code || *code < 0 || *code > 9999) {
                r.error(&item, "m_codes: each entry is an M code, \"M25\" or 25 (0 .. 9999)");
                continue;
            }
            if (std::find(m.m_codes.begin(), m.m_codes.end(), static_cast<int>(*code)) != m.m_codes.end())
                r.error(&item, fmt::format("m_codes: M{} is listed twice", *code));
            else
                m.m_codes.push_back(static_cast<int>(*code));
        }
    }

    if (const toml::table* t = r.table(root, "work_offsets", "")) mr.read_work_offsets(*t);
    if (const toml::node* n = root.get("work_shift")) mr.read_axis_values(*n, "work_shift", m.work_shift);
    if (const toml::table* t = r.table(root, "reference_points", "")) mr.read_reference_points(*t);
    if (const toml::table* t = r.table(root, "tools", "")) mr.read_tools(*t);
    if (const toml::table* t = r.table(root, "cycle_parameters", "")) mr.read_cycle_parameters(*t);
    if (const toml::table* t = r.table(root, "tailstock", "")) mr.read_tailstock(*t);
    if (const toml::table* t = r.table(root, "switches", "")) mr.read_switches(*t);

    // Tools listed by a base above a lowered count.
    for (const auto& [number, tool] : m.tools)
        if (number > m.tool_offset_count)
            r.error(root.contains("tool_offset_count") ? root.get("tool_offset_count") : &root,
                    fmt::format("tool_offset_count: {} is less than the listed offset {}", m.tool_offset_count, number));

    result.errors = std::move(r.errors);
    if (result.errors.empty()) result.machine = std::move(m);
    return result;
}

}  // namespace kerf::machine
