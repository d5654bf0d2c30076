// Internal to kerf_machine: the table behind [switches] (one row per switch: its public SwitchInfo,
// how to set it and how to read it back). Used by the loader, the dump and switch_value().
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <variant>

#include "machine/machine.hpp"

namespace kerf::machine::detail {

// A value as it appears in a file: choice names are strings.
using SwitchValue = std::variant<bool, std::int64_t, double, std::string>;

struct SwitchDef {
    SwitchInfo info;
    std::function<void(Switches&, const SwitchValue&)> set;   // the value is already validated
    std::function<SwitchValue(const Switches&)> get;
};

std::span<const SwitchDef> switch_defs();
const SwitchDef* find_switch_def(std::string_view key);
std::string to_text(const SwitchValue& value);

}  // namespace kerf::machine::detail
