// Inline suppressions: a comment `(kerf: ignore K1001 K1020)` (ids or names, separated by blanks or
// commas; none = every rule) silences those rules on its block; in a block before the first code
// block (the header, the O line) it silences them in the whole file.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "analyzer/finding.hpp"
#include "ast/syntax.hpp"

namespace kerf::analyzer {

struct Suppression {
    ast::Range block;                 // the block it applies to; the whole text for file-wide ones
    std::vector<std::string> rules;   // ids or names; empty = all
};

std::vector<Suppression> find_suppressions(const ast::SyntaxTree& tree);

// True when a suppression covers the start of the finding and names its rule (or names none).
bool suppressed(const std::vector<Suppression>& suppressions, const Finding& finding);
// The same for a finding of rule `rule` (id) / `name` that starts at `at`, before it is built.
bool suppressed(const std::vector<Suppression>& suppressions, std::uint32_t at, std::string_view rule, std::string_view name);

}  // namespace kerf::analyzer
