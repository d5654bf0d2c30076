// Every G and M code of the source dialect mapped to what it becomes in the target, by function id
// (dialects/functions.hpp; gcode-tables.md §1.1 rename map, §7 conflict table): the same code, the
// target's code with the same function, a code whose words change with it (G68's sign, G52's
// reading), a code the distance-mode or return-level logic handles, or nothing (reported).
// Built once per pair of dialects; looked up per code token by the source entry's index.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dialects/dialect.hpp"

namespace kerf::converter {

enum class CodeAction : std::uint8_t {
    keep,            // the target has this code with this function
    rename,          // the target's code with the same function has another number
    rotation_sign,   // G68 + = CCW ↔ + = CW (gcode-tables.md §8.10): renamed if need be, R negated
    local_system,    // G52 vector shift ↔ current point (semantics.md §2.4): values from the dry run
    local_cancel,    // G152 (local-system-cancel) where the target cancels with a zero G52
    distance_mode,   // G90/G91: the distance logic writes the target's mode or drops it (system A)
    return_level,    // G98/G99 return level into a dialect without one (system A): removed where exact
    none,            // no code of the target has this function: reported, left as it is
};

struct CodeMapping {
    CodeAction action = CodeAction::none;
    const dialects::CodeInfo* target = nullptr;   // the target's code (keep, rename, rotation_sign, local_*)
};

class CodeMap {
public:
    CodeMap(const dialects::Dialect& from, const dialects::Dialect& to);
    const CodeMapping& operator()(const dialects::CodeInfo& source) const;
    // The target's code of a function, or nullptr (the G90/G91 the distance logic writes).
    const dialects::CodeInfo* target_code(dialects::FunctionId function) const;

private:
    const dialects::Dialect& from_;
    const dialects::Dialect& to_;
    std::vector<CodeMapping> by_index_;   // by the source entry's index in from.codes()
    CodeMapping map(const dialects::CodeInfo& source) const;
};

// The target code spelled as the source token was: its letter case, and its zero padding when it
// had one ("G04" style; "G90" → "G77", "G152" → "G52"), the decimal part from the target ("G12.1").
std::string respell_code(std::string_view source_spelling, const dialects::CodeInfo& target);

}  // namespace kerf::converter
