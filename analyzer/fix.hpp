// Applying the fixes of findings to a text.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "analyzer/finding.hpp"

namespace kerf::analyzer {

struct FixResult {
    std::string text;
    std::size_t applied = 0;   // findings whose fix went in
    std::size_t skipped = 0;   // fixes that overlapped an earlier one (run --fix again)
};

// Applies every finding's fix whose edits do not overlap those already taken (in text order).
FixResult apply_fixes(std::string_view text, const std::vector<Finding>& findings);

}  // namespace kerf::analyzer
