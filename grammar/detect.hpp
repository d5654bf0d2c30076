// Dialect detection (reference/dialects.md §10): reads a file with permissive lexical rules and
// weighs the evidence. Always says why, so a wrong guess can be argued with and overridden.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace kerf::grammar {

struct Detection {
    std::string dialect;               // a built-in id
    std::vector<std::string> reasons;  // "G50 S2000 at 4:1 suggests a FANUC lathe (dialects.md §10)"
    int confidence = 0;                // the winning score
};

// Reads at most the first 256 KiB (whole lines): enough evidence, and a long file costs no more.
Detection detect_dialect(std::string_view text);

}  // namespace kerf::grammar
