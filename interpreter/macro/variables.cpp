#include "interpreter/macro/variables.hpp"

namespace kerf::interpreter::macro {

std::optional<Value> SystemVariables::read(int) { return std::nullopt; }
WriteResult SystemVariables::write(int, Value) { return WriteResult::undefined; }
bool SystemVariables::read_only(int) const { return false; }
bool SystemVariables::modelled(int) const { return true; }

namespace {
// Stateless, so one instance serves every Variables built without a system.
SystemVariables& no_system_variables() {
    static SystemVariables none;
    return none;
}

bool in(int number, int first, int last) { return number >= first && number <= last; }
}  // namespace

Variables::Variables() : Variables(no_system_variables()) {}

Variables::Variables(SystemVariables& system) : system_(&system) {
    levels_.emplace_back();   // level 0, all vacant (Value{} is vacant)
}

std::optional<Value> Variables::read(int number, SystemVariables& system) const {
    using namespace numbers;
    if (number == vacant) return Value::vacant_value();
    if (in(number, local_first, local_last)) return levels_.back()[static_cast<std::size_t>(number - local_first)];
    if (in(number, common_cleared_first, common_cleared_last))
        return cleared_[static_cast<std::size_t>(number - common_cleared_first)];
    if (in(number, common_kept_first, common_kept_last)) return kept_[static_cast<std::size_t>(number - common_kept_first)];
    if (number < 0) return std::nullopt;
    return system.read(number);
}

bool Variables::read_only(int number, const SystemVariables& system) const {
    // #0 "cannot be assigned" ([M-16i] "Null variables"); the rest is the interpreter's call.
    return number == numbers::vacant || system.read_only(number);
}

WriteResult Variables::write(int number, Value value, SystemVariables& system) {
    using namespace numbers;
    if (number < 0) return WriteResult::undefined;
    if (read_only(number, system)) return WriteResult::read_only;
    if (value.vacant) value = Value::vacant_value();
    if (in(number, local_first, local_last)) {
        levels_.back()[static_cast<std::size_t>(number - local_first)] = value;
        return WriteResult::ok;
    }
    if (in(number, common_cleared_first, common_cleared_last)) {
        cleared_[static_cast<std::size_t>(number - common_cleared_first)] = value;
        return WriteResult::ok;
    }
    if (in(number, common_kept_first, common_kept_last)) {
        kept_[static_cast<std::size_t>(number - common_kept_first)] = value;
        return WriteResult::ok;
    }
    return system.write(number, value);
}

void Variables::push_level() { levels_.emplace_back(); }

bool Variables::pop_level() {
    if (levels_.size() <= 1) return false;
    levels_.pop_back();
    return true;
}

void Variables::clear_cleared_commons() { cleared_.fill(Value::vacant_value()); }

void Variables::reset() {
    levels_.resize(1);
    levels_.front().fill(Value::vacant_value());
    if (!keep_commons_on_reset) clear_cleared_commons();
}

void Variables::power_cycle() {
    levels_.resize(1);
    levels_.front().fill(Value::vacant_value());
    clear_cleared_commons();
}

}  // namespace kerf::interpreter::macro
