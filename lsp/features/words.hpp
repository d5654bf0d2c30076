// What an address word means where it stands: `U` in the first G71 block is the depth of cut, in
// the second the finishing allowance, in a motion block an incremental X move (system A). The
// cycle tables come from reference/cycles.md (the section is cited in each text); the rest from the
// word's role in the binder (ast::Role) and the dialect's lexical rules.
#pragma once

#include <cstdint>
#include <string>

#include "lsp/document.hpp"

namespace kerf::lsp {

// The meaning of word `token` in its block, in `language` ("en"/"ru"); "" when kerf has nothing to say.
std::string word_meaning(const Document& doc, std::uint32_t token, const std::string& language);

// The value of a word without a decimal point, in mm, with the increment it counts
// ("X10 = 10 mm (calculator-type input)" or "X10 = 10 × 0.001 mm = 0.01 mm"); "" otherwise.
std::string value_in_units(const Document& doc, std::uint32_t token, const std::string& language);

}  // namespace kerf::lsp
