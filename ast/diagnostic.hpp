// Errors are values: what is wrong, where, and how to fix it.
#pragma once

#include <string>
#include <vector>

#include "ast/source.hpp"

namespace kerf::ast {

enum class Severity : std::uint8_t { error, warning, info, hint };
const char* to_string(Severity s);

struct Diagnostic {
    Range range;
    Severity severity = Severity::error;
    std::string code;      // stable id, see docs/diagnostics.md ("S0101")
    std::string message;   // what is wrong, quoting the text
    std::string hint;      // how to fix it; empty when there is nothing to say
};

}  // namespace kerf::ast
