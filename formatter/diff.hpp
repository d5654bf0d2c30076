// A unified diff of two texts by lines (what `kerf fmt --diff` prints; no external tool).
#pragma once

#include <string>
#include <string_view>

namespace kerf::formatter {

// `--- a_name` / `+++ b_name` and hunks with `context` lines around each change; empty when the
// texts are equal. Lines keep their own line breaks ("\r\n" shows as it is); a last line without one
// is followed by "\ No newline at end of file". Minimal (Myers) for up to kMaxEdits changed lines
// between the common head and tail; past that the middle becomes one hunk.
std::string unified_diff(std::string_view a, std::string_view b, std::string_view a_name, std::string_view b_name,
                         int context = 3);

inline constexpr int kMaxEdits = 4000;

}  // namespace kerf::formatter
