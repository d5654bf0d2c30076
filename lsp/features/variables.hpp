// Macro B variables (reference/dialects.md §3.7; FANUC custom macro B, "Types of variables"): what
// a number means, for hover and completion.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace kerf::lsp {

// "local variable (#1–#33): one set per macro call level ...".
std::string variable_kind(std::int64_t number, const std::string& language);

struct SystemVariable {
    std::int64_t first;
    std::int64_t last;
    const char* en;
    const char* ru;
};
// The system variables kerf knows ([FANUC] 0i/30i manuals; interpreter/executor_system.cpp).
std::span<const SystemVariable> system_variables();
const SystemVariable* system_variable(std::int64_t number);

}  // namespace kerf::lsp
