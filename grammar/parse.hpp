// The grammar's contract: text in, lossless syntax tree out. Never throws on input, never stops at
// the first error: a bad piece of a block becomes an error token with a diagnostic and parsing goes on.
#pragma once

#include <string>

#include "ast/syntax.hpp"
#include "dialects/dialect.hpp"

namespace kerf::grammar {

// `rules` are the dialect's lexical switches (what ';' means, line comments, comma words,
// decimal comma, macro B). The text is moved into the tree, which owns it.
ast::SyntaxTree parse(std::string text, const dialects::LexicalRules& rules);

}  // namespace kerf::grammar
