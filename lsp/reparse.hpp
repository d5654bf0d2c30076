// Incremental re-parse: an edit of a parsed text re-parses only the lines it touches and splices
// them into a copy of the old tree. Blocks never span lines (grammar/parse.cpp), so a line parses
// the same wherever it is, given the parser's state at its start (the opening/closing '%' of the
// tape); when the edit changes that state for the lines after it (a '%' typed or deleted), the
// re-parse runs to the end of the file. The result is the tree `grammar::parse` gives for the new
// text (tests/lsp/test_reparse.cpp compares them on every reference example and corpus file).
//
// Arrays of the tree: blocks and tokens are copied around the new ones with their offsets
// shifted; expression nodes and statements keep the tree's text order, so the old ones of the
// touched lines are found by position and replaced; numbers too big for a token stay in
// `big_numbers` (the new ones are appended: a few unused entries, dropped by the next full parse).
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>

#include "ast/syntax.hpp"
#include "ast/typed.hpp"
#include "dialects/dialect.hpp"

namespace kerf::lsp {

struct ByteEdit {
    std::uint32_t begin = 0;   // the bytes [begin, end) of the old text ...
    std::uint32_t end = 0;
    std::string_view text;     // ... become these
};

// The tree of the edited text; `splice` says which blocks changed (for ast::TypedFile::bind_edited).
ast::SyntaxTree reparse(const ast::SyntaxTree& old, const ByteEdit& edit, const dialects::LexicalRules& rules,
                        ast::BlockSplice& splice);
// The same edit made to `tree` itself (no copy: the document store's path when nobody else holds
// the version); afterwards `tree` is what reparse() would have returned. `before`, when given, sees
// the old tree and the old blocks [first, end) the edit replaces just before they are replaced
// (not when the text is parsed again whole).
using BeforeSplice = std::function<void(const ast::SyntaxTree& old, std::uint32_t first, std::uint32_t end)>;
void reparse_in_place(ast::SyntaxTree& tree, const ByteEdit& edit, const dialects::LexicalRules& rules, ast::BlockSplice& splice,
                      const BeforeSplice& before = {});

}  // namespace kerf::lsp
