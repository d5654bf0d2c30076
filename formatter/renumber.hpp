// Block numbers: keep, remove the unreferenced ones, renumber every code block, or number only the
// referenced ones — and every reference follows its block: G70–G73 P/Q (by function id: finishing,
// rough-turning, rough-facing and pattern-repeating cycles; reference/cycles.md §1–§4), M98 Q
// (the called program's label), M99 P (the caller's label; reference/dialects.md §3.6) and GOTO n
// (Macro B). A reference kerf cannot follow — a computed GOTO #1, a P or Q written as an
// expression, an M99 P whose target several programs of the file number differently — makes the
// plan refuse with a diagnostic naming the block, instead of guessing.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <variant>
#include <vector>

#include "ast/diagnostic.hpp"
#include "ast/typed.hpp"
#include "formatter/style.hpp"

namespace kerf::formatter {

inline constexpr std::int64_t kMaxSequenceNumber = 99999;   // N + up to 5 digits (dialects.md §2)

struct LabelEdit {
    ast::Range range;          // the label expression inside the statement token
    std::int64_t value = 0;
};

struct Renumbering {
    // Block index → its new N (kRemove: the N word goes). Blocks not listed keep their N words.
    std::unordered_map<std::uint32_t, std::int64_t> blocks;
    // Word token index → the new integer value of a reference word (P/Q of a cycle, M98 Q, M99 P).
    std::unordered_map<std::uint32_t, std::int64_t> words;
    // Statement token index → the labels to rewrite in it (GOTO n, IF [...] GOTO n).
    std::unordered_map<std::uint32_t, std::vector<LabelEdit>> statements;
    static constexpr std::int64_t kRemove = -1;
    bool empty() const { return blocks.empty() && words.empty() && statements.empty(); }
};

// The plan for `style.block_numbers` (empty for keep), or the reasons it cannot be done.
// An O word with digits that is not its block's first word (`X9 D 2O 3`): the grammar starts a new
// program there only after plain words (grammar/parse.cpp, program_word_after_first), and `D 2` is
// not one, so the O is a word of this block. Reprinted (`D2O3`), the words before it would become
// plain and the next reading would start a program at `O3` (fuzz_formatter, not idempotent): the
// formatter leaves such a block as written, and renumbering, which would have to change it, refuses.
bool has_inner_program_word(const ast::SyntaxTree& tree, std::span<const ast::Token> tokens);

std::variant<Renumbering, std::vector<ast::Diagnostic>> plan_renumbering(const ast::TypedFile& file, const Style& style);

}  // namespace kerf::formatter
