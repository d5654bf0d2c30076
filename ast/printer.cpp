#include "ast/printer.hpp"

#include <fmt/format.h>

namespace kerf::ast {

std::string print(const SyntaxTree& tree) {
    std::string out;
    out.reserve(tree.text.size());
    for (std::size_t i = 0; i < tree.block_count(); ++i) {
        const Range range = tree.block_range(i);
        std::uint32_t at = range.begin;
        for (const Token& t : tree.block_tokens(i)) {
            out.append(tree.text, at, t.begin - at);   // trivia before the token
            out.append(tree.text, t.begin, tree.length(t));  // the token
            at = tree.end(t);
        }
        out.append(tree.text, at, range.end - at);     // trivia up to the next block (line break)
    }
    return out;
}

namespace {
bool is_trivia(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
}  // namespace

namespace {
// Every token too long for its 8 bits has its entry in long_tokens, and no other entry is there:
// both are in text order, so one walk over the two.
std::optional<InvariantViolation> check_long_tokens(const SyntaxTree& tree) {
    std::size_t next = 0;
    for (const Token& t : tree.tokens) {
        if (t.short_length != Token::kLongLength) continue;
        if (next == tree.long_tokens.size() || tree.long_tokens[next].begin != t.begin ||
            tree.long_tokens[next].length < Token::kLongLength)
            return InvariantViolation{t.begin, "a long token without its length in long_tokens"};
        ++next;
    }
    if (next != tree.long_tokens.size()) return InvariantViolation{tree.long_tokens[next].begin, "long_tokens holds the length of no token"};
    return std::nullopt;
}
}  // namespace

std::optional<InvariantViolation> check_lossless(const SyntaxTree& tree) {
    if (tree.blocks.empty()) return InvariantViolation{0, "no blocks"};
    if (tree.blocks.front().begin != 0) return InvariantViolation{0, "first block does not start at 0"};
    for (std::size_t i = 0; i < tree.block_count(); ++i) {
        const Range range = tree.block_range(i);
        if (range.end < range.begin) return InvariantViolation{range.begin, fmt::format("block {} ends before it starts", i)};
        if (tree.blocks[i].kind == BlockKind::tail) continue;
        std::uint32_t at = range.begin;
        for (const Token& t : tree.block_tokens(i)) {
            if (t.begin < at || tree.end(t) > range.end)
                return InvariantViolation{t.begin, fmt::format("token outside block {} or out of order", i)};
            for (std::uint32_t p = at; p < t.begin; ++p)
                if (!is_trivia(tree.text[p]))
                    return InvariantViolation{p, fmt::format("byte 0x{:02x} belongs to no token", static_cast<unsigned char>(tree.text[p]))};
            at = tree.end(t);
        }
        for (std::uint32_t p = at; p < range.end; ++p)
            if (!is_trivia(tree.text[p]))
                return InvariantViolation{p, fmt::format("byte 0x{:02x} belongs to no token", static_cast<unsigned char>(tree.text[p]))};
    }
    return check_long_tokens(tree);
}

}  // namespace kerf::ast
