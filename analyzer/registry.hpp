// The rules kerf knows. Each file under analyzer/rules/ registers a small family of rules; the
// list of those families is in registry.cpp, in one place (no switch over ids anywhere).
#pragma once

#include <deque>
#include <string_view>
#include <vector>

#include "analyzer/rule.hpp"

namespace kerf::analyzer {

class Registry {
public:
    void add(Rule rule);   // ids and names must be new (a duplicate is a programming error: it throws)
    const std::deque<Rule>& rules() const { return rules_; }
    const Rule* find(std::string_view id_or_name) const;   // "K1001" or "address-without-value"
    const Rule* for_diagnostic(std::string_view code) const;
    const Rule* for_alarm(int number) const;

private:
    std::deque<Rule> rules_;   // stable addresses: findings and reporters point at rules
};

// The built-in rules, built once (immutable afterwards), sorted by id.
const Registry& builtin_rules();

// Each family (analyzer/rules/*.cpp) adds its rules here.
namespace rules {
void add_syntax(Registry& r);
void add_numbers(Registry& r);
void add_dialect(Registry& r);
void add_references(Registry& r);
void add_macro(Registry& r);
void add_alarms(Registry& r);
void add_motion(Registry& r);
void add_safety(Registry& r);
}  // namespace rules

}  // namespace kerf::analyzer
