// Machine accessors, the registry of machines, the built-ins and the dialect → machine mapping, and
// resolve_for_dialect (the "dialect" values, read from the dialect tables, never from its name).
#include <fmt/format.h>

#include <algorithm>
#include <mutex>

#include "machine/machine.hpp"

namespace kerf::machine {

namespace fn = dialects::functions;

double axis_value(const AxisValues& values, char letter) {
    const auto it = values.find(letter);
    return it == values.end() ? 0.0 : it->second;
}

double increment_mm(InputIncrement increment) { return increment == InputIncrement::is_c ? 0.0001 : 0.001; }

const Axis* Machine::axis(char letter) const {
    for (const Axis& a : axes)
        if (a.letter == letter) return &a;
    return nullptr;
}

std::string Machine::axis_letters() const {
    std::string out;
    for (const Axis& a : axes) out += a.letter;
    return out;
}

const ToolOffset* Machine::tool(int number) const {
    const auto it = tools.find(number);
    return it == tools.end() ? nullptr : &it->second;
}

bool Machine::follows_dialect(std::string_view key) const {
    return std::find(from_dialect.begin(), from_dialect.end(), key) != from_dialect.end();
}

// ---------------------------------------------------------------------------------------------

Machine resolve_for_dialect(Machine m, const dialects::Dialect& d) {
    const auto has = [&](dialects::FunctionId function) { return !d.codes_with_function(function).empty(); };
    const auto power_on = [&](dialects::FunctionId function) {
        for (const dialects::CodeInfo* c : d.codes_with_function(function))
            if (c->power_on_default) return true;
        return false;
    };
    Switches& s = m.switches;
    for (const std::string& key : m.from_dialect) {
        if (key == "calculator_decimal") {
            m.calculator_decimal = d.lexical.calculator_decimal;   // dialects/SCHEMA.md: the machine switch's default
        } else if (key == "g52") {
            // semantics.md §2.4: the dialect tables name the reading by function id.
            if (has(fn::local_system_shift)) s.g52 = G52Semantics::vector_shift;
            else if (has(fn::local_system_current_point))
                s.g52 = has(fn::local_system_cancel) ? G52Semantics::current_point_g152 : G52Semantics::current_point;
            else s.g52 = G52Semantics::vector_shift;
        } else if (key == "g53_motion") {
            s.g53_motion = has(fn::machine_coordinate_select_g0_g1) ? G53Motion::g0_g1 : G53Motion::rapid;
        } else if (key == "g68_positive") {
            s.g68_positive = has(fn::coordinate_rotation_cw) ? RotationSign::cw : RotationSign::ccw;
        } else if (key == "dwell_p_unit") {
            s.dwell_p_unit = d.lexical.dwell_p_seconds ? DwellUnit::s : DwellUnit::ms;   // dialects/SCHEMA.md [lexical]
        } else if (key == "power_on_plane") {
            if (power_on(fn::plane_xy)) s.power_on_plane = Plane::xy;
            else if (power_on(fn::plane_zx)) s.power_on_plane = Plane::zx;
            else if (power_on(fn::plane_yz)) s.power_on_plane = Plane::yz;
            else s.power_on_plane = d.machine == MachineKind::lathe ? Plane::zx : Plane::xy;
        } else if (key == "power_on_units") {
            s.power_on_units = power_on(fn::inch_input) ? Units::inch : Units::metric;
        } else if (key == "power_on_distance") {
            s.power_on_distance = power_on(fn::incremental_programming) ? Distance::incremental : Distance::absolute;
        } else if (key == "power_on_return_level") {
            s.power_on_return_level = power_on(fn::return_r_level) ? ReturnLevel::r_point : ReturnLevel::initial;
        }
    }
    m.resolved_dialect = d.id;
    return m;
}

// ---------------------------------------------------------------------------------------------

const Machine* Registry::find(std::string_view id) const {
    for (const Machine& m : machines_)
        if (m.id == id) return &m;
    return nullptr;
}

std::vector<std::string> Registry::ids() const {
    std::vector<std::string> out;
    for (const Machine& m : machines_) out.push_back(m.id);
    return out;
}

void Registry::add(Machine machine) {
    for (Machine& m : machines_) {
        if (m.id == machine.id) {
            m = std::move(machine);
            return;
        }
    }
    machines_.push_back(std::move(machine));
}

std::vector<LoadError> Registry::add_text(std::string_view toml_text, std::string_view source_name) {
    LoadResult loaded = load_machine_text(toml_text, source_name, *this);
    if (loaded.machine) add(std::move(*loaded.machine));
    return loaded.errors;
}

const Machine* Registry::for_dialect(std::string_view dialect_id) const {
    for (const Machine& m : machines_)
        if (std::find(m.dialects.begin(), m.dialects.end(), dialect_id) != m.dialects.end()) return &m;
    return nullptr;
}

// ---------------------------------------------------------------------------------------------

namespace {

struct Builtins {
    Registry registry;
    std::vector<LoadError> errors;
};

const Builtins& builtins() {
    static const Builtins b = [] {
        Builtins out;
        // Files whose base is not loaded yet wait for the next round (built-ins may inherit too).
        std::vector<std::pair<std::string_view, std::string_view>> pending(builtin_machine_texts().begin(),
                                                                            builtin_machine_texts().end());
        while (!pending.empty()) {
            std::vector<std::pair<std::string_view, std::string_view>> later;
            std::vector<LoadError> round_errors;
            for (const auto& [stem, text] : pending) {
                LoadResult loaded = load_machine_text(text, fmt::format("machine/data/{}.toml", stem), out.registry);
                if (loaded.machine) {
                    if (loaded.machine->id != stem)
                        out.errors.push_back({fmt::format("machine/data/{}.toml: id '{}' differs from the file name",
                                                          stem, loaded.machine->id),
                                              0, 0});
                    out.registry.add(std::move(*loaded.machine));
                } else {
                    later.emplace_back(stem, text);
                    round_errors.insert(round_errors.end(), loaded.errors.begin(), loaded.errors.end());
                }
            }
            if (later.size() == pending.size()) {   // no progress: report and stop
                out.errors.insert(out.errors.end(), round_errors.begin(), round_errors.end());
                break;
            }
            pending = std::move(later);
        }
        return out;
    }();
    return b;
}

const Machine& fallback_machine() {
    static const Machine empty = [] {
        Machine m;
        m.id = "none";
        m.name = "no built-in machine (machine/data is broken)";
        return m;
    }();
    return empty;
}

}  // namespace

const Registry& builtin_machines() { return builtins().registry; }
const std::vector<LoadError>& builtin_machine_errors() { return builtins().errors; }

Machine default_machine_for(const dialects::Dialect& dialect) {
    const Registry& r = builtin_machines();
    // The machine that names the dialect, else the one that names its nearest base (a user dialect
    // derived from adv400-lathe runs on the ADV400 lathe), else the FANUC machine of its kind.
    const Machine* m = r.for_dialect(dialect.id);
    for (const std::string& base : dialect.bases)
        if (!m) m = r.for_dialect(base);
    if (!m) m = r.find(dialect.machine == MachineKind::lathe ? "fanuc-lathe" : "fanuc-mill");
    if (!m) return fallback_machine();
    return resolve_for_dialect(*m, dialect);
}

const Machine& default_machine_for(std::string_view dialect_id) {
    // Batch work runs on all cores: one lock around a cache that only grows by the ids asked for.
    static std::mutex mutex;
    static std::map<std::string, Machine, std::less<>> cache;
    const std::lock_guard lock(mutex);
    if (const auto it = cache.find(dialect_id); it != cache.end()) return it->second;
    Machine m;
    if (const dialects::Dialect* d = dialects::builtin_registry().find(dialect_id)) {
        m = default_machine_for(*d);
    } else if (const Machine* named = builtin_machines().for_dialect(dialect_id)) {
        m = *named;   // named by a machine file but not a built-in dialect: nothing to resolve against
    } else if (const Machine* mill = builtin_machines().find("fanuc-mill")) {
        m = *mill;   // unknown dialect: nothing to resolve against; the FANUC fallbacks stay
    } else {
        m = fallback_machine();
    }
    return cache.emplace(std::string(dialect_id), std::move(m)).first->second;
}

}  // namespace kerf::machine
