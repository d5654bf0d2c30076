// The grammar's contract: text in, lossless syntax tree out. Never throws on input, never stops at
// the first error: a bad piece of a block becomes an error token with a diagnostic and parsing goes on.
#pragma once

#include <string>
#include <string_view>

#include "ast/syntax.hpp"
#include "dialects/dialect.hpp"

namespace kerf::grammar {

// `rules` are the dialect's lexical switches (what ';' means, line comments, comma words,
// decimal comma, macro B). The text is moved into the tree, which owns it. With `threads` >= 2 a
// long text (8 MiB or more) is parsed in two halves side by side; the tree is the same.
ast::SyntaxTree parse(std::string text, const dialects::LexicalRules& rules, unsigned threads = 1);

// The threads a parse of one long file may use on this machine (at most 2: what the halves gain).
unsigned parse_threads();

// A letter other than O, an optional sign, digits with at most one point (X1., M99, g-0.5): the
// words an O word may follow to start the next program on the same line (`M99O0810`). The program
// index's byte scan (project/scan.cpp) splits blocks by the same test.
bool is_plain_word(std::string_view spelling);

// Reading a long file in pieces (interpreter/loaded_file.hpp): a piece is a run of whole lines,
// and this is what the parse of one piece hands to the next.
struct ParseState {
    bool file_start = true;      // the piece starts the file (a BOM is read only there)
    bool program_seen = false;   // code since the opening '%' (the next '%' closes the tape)
    bool ended = false;          // the closing '%' was read: the rest of the file is not program text
};

// Parses `text` (whole lines) into `tree`, whose arrays keep their capacity: parsing piece after
// piece into one tree allocates nothing once it has grown. Offsets are relative to `text`. After a
// closing '%' the rest of `text` is one tail block and the result says `ended`.
ParseState parse_into(ast::SyntaxTree& tree, std::string_view text, const dialects::LexicalRules& rules,
                      ParseState start);

}  // namespace kerf::grammar
