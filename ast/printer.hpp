// The lossless printer and the invariant behind it.
#pragma once

#include <optional>
#include <string>

#include "ast/syntax.hpp"

namespace kerf::ast {

// Prints the tree back: each token's text and the trivia between tokens, block after block.
// For an unchanged tree this is the input, byte for byte.
std::string print(const SyntaxTree& tree);

// Checks that blocks are contiguous, tokens are ordered inside their block, and every byte that is
// not in a token is trivia (blank or line break), except in a tail block. Returns the first
// offending offset and a description, or nullopt.
struct InvariantViolation {
    std::uint32_t offset = 0;
    std::string what;
};
std::optional<InvariantViolation> check_lossless(const SyntaxTree& tree);

}  // namespace kerf::ast
