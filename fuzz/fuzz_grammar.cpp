// libFuzzer target for the grammar, the lossless printer and the binder (fuzz/README.md).
//
// Input: byte 0 picks the dialect (table below), the rest is the NC program text.
// Traps (__builtin_trap) when
//   - print(tree) differs from the input, byte for byte;
//   - check_lossless(tree) reports a violation;
//   - any index in the tree is out of range: block begins and first tokens, token ranges and their
//     payloads (expression, statement, big-number indices), expression children (which must come
//     before their parent: nodes are built in post-order, so this also rules out cycles), statement
//     fields, diagnostic ranges, what the typed layer (programs, block views) hands out after bind
//     and after rebind_block, and sampled LineIndex conversions.
// ASan and UBSan catch the rest (overflows, use after free, signed overflow, bad enum loads).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "ast/printer.hpp"
#include "ast/source.hpp"
#include "ast/syntax.hpp"
#include "ast/typed.hpp"
#include "dialects/dialect.hpp"
#include "grammar/parse.hpp"

namespace {

using namespace kerf;

constexpr std::size_t kMaxInput = 64 * 1024;

// Byte 0 picks the dialect: (byte + 6) % 9 indexes this table, so the seed corpus's ASCII digits
// '0'..'8' (fuzz/corpus/) pick the entries in this order, and every byte value picks some dialect.
constexpr const char* kDialects[9] = {
    "fanuc-lathe-a", "fanuc-lathe-b", "fanuc-lathe-c", "spinner-lathe-a", "fanuc-mill",
    "adv400-mill",   "adv400-lathe",  "pcnc-mill",     "iso-legacy-mill",
};
std::size_t dialect_index(std::uint8_t byte) { return (static_cast<std::size_t>(byte) + 6) % 9; }

[[noreturn]] void fail(const char* what, std::uint64_t a = 0, std::uint64_t b = 0) {
    std::fprintf(stderr, "fuzz_grammar: invariant broken: %s (%llu, %llu)\n", what,
                 static_cast<unsigned long long>(a), static_cast<unsigned long long>(b));
    std::fflush(stderr);
    __builtin_trap();
}

#define KERF_CHECK(cond, ...)                   \
    do {                                        \
        if (!(cond)) fail(#cond, ##__VA_ARGS__); \
    } while (0)

bool in_range(std::int64_t index, std::size_t size) { return index >= 0 && static_cast<std::uint64_t>(index) < size; }

void check_range(const ast::Range& r, std::size_t text_size) {
    KERF_CHECK(r.begin <= r.end, r.begin, r.end);
    KERF_CHECK(r.end <= text_size, r.end, text_size);
}

// Every index the grammar wrote; returns nothing, traps on the first broken one.
void check_tree(const ast::SyntaxTree& tree) {
    const std::size_t n_text = tree.text.size();
    const std::size_t n_tokens = tree.tokens.size();
    const std::size_t n_exprs = tree.exprs.size();
    const std::size_t n_statements = tree.statements.size();
    const std::size_t n_big = tree.big_numbers.size();

    // Blocks: contiguous, non-decreasing, the first at 0; token runs non-decreasing.
    KERF_CHECK(!tree.blocks.empty());
    KERF_CHECK(tree.blocks.front().begin == 0, tree.blocks.front().begin);
    KERF_CHECK(tree.blocks.front().first_token == 0, tree.blocks.front().first_token);
    for (std::size_t i = 0; i < tree.blocks.size(); ++i) {
        const ast::Block& b = tree.blocks[i];
        KERF_CHECK(b.begin <= n_text, b.begin, n_text);
        KERF_CHECK(b.first_token <= n_tokens, b.first_token, n_tokens);
        KERF_CHECK(static_cast<int>(b.kind) <= static_cast<int>(ast::BlockKind::tail), i);
        if (i + 1 < tree.blocks.size()) {
            KERF_CHECK(b.begin <= tree.blocks[i + 1].begin, i, b.begin);
            KERF_CHECK(b.first_token <= tree.blocks[i + 1].first_token, i, b.first_token);
        }
        check_range(tree.block_range(i), n_text);
        KERF_CHECK(tree.block_token_end(i) <= n_tokens, i, tree.block_token_end(i));
        // Tokens of a non-tail block lie inside it (check_lossless skips tail blocks' bytes, not tokens).
        const ast::Range br = tree.block_range(i);
        for (const ast::Token& t : tree.block_tokens(i)) {
            KERF_CHECK(t.begin >= br.begin && static_cast<std::uint64_t>(t.begin) + tree.length(t) <= br.end, t.begin, i);
        }
    }

    // Tokens.
    for (std::size_t i = 0; i < n_tokens; ++i) {
        const ast::Token& t = tree.tokens[i];
        KERF_CHECK(static_cast<std::uint64_t>(t.begin) + tree.length(t) <= n_text, t.begin, tree.length(t));
        KERF_CHECK(static_cast<int>(t.kind) <= static_cast<int>(ast::TokenKind::error), i);
        KERF_CHECK(static_cast<int>(t.role()) <= static_cast<int>(ast::Role::direct_drawing), i);
        KERF_CHECK(tree.length(t) > 0 || t.kind == ast::TokenKind::error, i, t.begin);
        if (i + 1 < n_tokens) KERF_CHECK(tree.end(t) <= tree.tokens[i + 1].begin, i, t.begin);
        const std::string_view spelling = tree.spelling(t);
        KERF_CHECK(spelling.size() == tree.length(t), i);
        switch (t.kind) {
            case ast::TokenKind::word:
            case ast::TokenKind::comma_word: {
                KERF_CHECK(t.letter >= 'A' && t.letter <= 'Z', i, static_cast<std::uint64_t>(t.letter));
                if (t.has(ast::token_flags::value_expr)) {
                    KERF_CHECK(in_range(t.payload, n_exprs), i, static_cast<std::uint64_t>(t.payload));
                    const ast::Expr& e = tree.exprs[static_cast<std::size_t>(t.payload)];
                    KERF_CHECK(e.begin >= t.begin && e.end <= tree.end(t), i, e.begin);
                } else if (t.has(ast::token_flags::value_big)) {
                    KERF_CHECK(in_range(t.payload, n_big), i, static_cast<std::uint64_t>(t.payload));
                } else if (!t.has(ast::token_flags::value_none)) {
                    KERF_CHECK(t.scale() <= 15, i, t.scale());
                }
                (void)tree.number_value(t);
                (void)tree.value_spelling(t);
                (void)ast::integer_value(tree, t);
                break;
            }
            case ast::TokenKind::statement: {
                KERF_CHECK(in_range(t.payload, n_statements), i, static_cast<std::uint64_t>(t.payload));
                const ast::Statement& s = tree.statements[static_cast<std::size_t>(t.payload)];
                KERF_CHECK(s.range.begin >= t.begin && s.range.end <= tree.end(t), i, s.range.begin);
                break;
            }
            case ast::TokenKind::block_delete:
                KERF_CHECK(t.letter == 0 || (t.letter >= '1' && t.letter <= '9'), i, t.letter);
                break;
            case ast::TokenKind::bom:
                KERF_CHECK(t.begin == 0 && tree.length(t) == 3, t.begin, tree.length(t));
                break;
            default:
                break;
        }
    }

    // Expressions: children exist and precede their parent (post-order), ranges lie in the text.
    auto child = [&](std::size_t parent, std::int32_t c) {
        KERF_CHECK(c >= 0 && static_cast<std::size_t>(c) < parent, parent, static_cast<std::uint64_t>(c));
    };
    for (std::size_t i = 0; i < n_exprs; ++i) {
        const ast::Expr& e = tree.exprs[i];
        check_range(e.range(), n_text);
        switch (e.kind) {
            case ast::ExprKind::number:
                if (e.flags & ast::token_flags::value_big) KERF_CHECK(in_range(e.a, n_big), i, static_cast<std::uint64_t>(e.a));
                else KERF_CHECK(e.scale <= 15, i, e.scale);
                (void)tree.number_value(e);
                break;
            case ast::ExprKind::variable:
            case ast::ExprKind::negate:
            case ast::ExprKind::plus:
            case ast::ExprKind::bracket:
                child(i, e.a);
                break;
            case ast::ExprKind::binary:
                child(i, e.a);
                child(i, e.b);
                KERF_CHECK(e.op <= static_cast<std::uint8_t>(ast::BinaryOp::le), i, e.op);
                (void)ast::to_string(e.binary_op());
                break;
            case ast::ExprKind::function:
                child(i, e.a);
                if (e.b != -1) child(i, e.b);
                KERF_CHECK(e.op <= static_cast<std::uint8_t>(ast::Function::adp), i, e.op);
                (void)ast::to_string(e.function());
                break;
            default:
                fail("unknown expression kind", i, static_cast<std::uint64_t>(e.kind));
        }
    }

    // Statements.
    auto expr_ref = [&](std::size_t s, std::int32_t e, bool required) {
        if (!required && e == -1) return;
        KERF_CHECK(in_range(e, n_exprs), s, static_cast<std::uint64_t>(e));
    };
    for (std::size_t i = 0; i < n_statements; ++i) {
        const ast::Statement& s = tree.statements[i];
        check_range(s.range, n_text);
        KERF_CHECK(static_cast<int>(s.kind) <= static_cast<int>(ast::StatementKind::if_words), i);
        expr_ref(i, s.target, s.kind == ast::StatementKind::assign);
        expr_ref(i, s.value,
                 s.kind == ast::StatementKind::assign || s.kind == ast::StatementKind::if_goto ||
                     s.kind == ast::StatementKind::if_then || s.kind == ast::StatementKind::while_do ||
                     s.kind == ast::StatementKind::if_words);
        expr_ref(i, s.label,
                 s.kind == ast::StatementKind::if_goto || s.kind == ast::StatementKind::while_do ||
                     s.kind == ast::StatementKind::goto_ || s.kind == ast::StatementKind::do_ ||
                     s.kind == ast::StatementKind::end);
        if (s.kind == ast::StatementKind::if_then) {
            // The nested statement is built first.
            KERF_CHECK(s.then_statement >= 0 && static_cast<std::size_t>(s.then_statement) < i, i,
                       static_cast<std::uint64_t>(s.then_statement));
        } else {
            KERF_CHECK(s.then_statement == -1, i, static_cast<std::uint64_t>(s.then_statement));
        }
        if (s.kind == ast::StatementKind::dprnt || s.kind == ast::StatementKind::bprnt) {
            check_range(s.text, n_text);
            KERF_CHECK(s.text.begin >= s.range.begin && s.text.end <= s.range.end, i, s.text.begin);
        }
    }

    for (std::size_t i = 0; i < tree.big_numbers.size(); ++i) (void)tree.big_numbers[i];
    for (std::size_t i = 0; i < tree.diagnostics.size(); ++i) check_range(tree.diagnostics[i].range, n_text);
}

void check_typed(const ast::TypedFile& file, const ast::SyntaxTree& tree) {
    const std::size_t n_tokens = tree.tokens.size();
    const std::size_t n_blocks = tree.block_count();
    for (const ast::Program& p : file.programs()) {
        KERF_CHECK(p.first_block <= p.end_block && p.end_block <= n_blocks, p.first_block, p.end_block);
        KERF_CHECK(p.o_token == -1 || in_range(p.o_token, n_tokens), static_cast<std::uint64_t>(p.o_token));
    }
    for (const ast::Diagnostic& d : file.diagnostics()) check_range(d.range, tree.text.size());
    auto token_ref = [&](std::uint32_t t) { KERF_CHECK(t < n_tokens, t, n_tokens); };
    for (std::size_t i = 0; i < n_blocks; ++i) {
        const ast::BlockView v = file.block(i);
        (void)v.sequence_number();
        (void)v.has_sequence_word();
        const int level = v.block_delete_level();
        KERF_CHECK(level >= 0 && level <= 9, i, static_cast<std::uint64_t>(level));
        for (const ast::CodeRef& c : v.g_codes()) token_ref(c.token);
        for (const ast::CodeRef& c : v.m_codes()) token_ref(c.token);
        for (const ast::AxisWord& a : v.axis_words()) token_ref(a.token);
        for (std::uint32_t t : v.parameters()) token_ref(t);
        for (std::uint32_t t : v.comma_words()) token_ref(t);
        for (std::uint32_t t : v.comments()) token_ref(t);
        for (std::uint32_t t : v.statements()) token_ref(t);
        if (const auto w = v.word('X')) token_ref(*w);
        if (const auto call = v.subprogram_call()) token_ref(call->p_token);
        if (const auto call = v.macro_call())
            for (std::uint32_t t : call->arguments) token_ref(t);
    }
}

// Line/column conversions the language server does on token boundaries. LineIndex::utf16 walks
// the line from its start, so calling it on every token of a 64 KiB one-line input is quadratic (by
// design, not a bug): sample at most kLineSamples tokens spread over the file.
constexpr std::size_t kLineSamples = 256;
void check_lines(const ast::SyntaxTree& tree) {
    const ast::LineIndex lines(tree.text);
    const std::size_t n = tree.text.size();
    const std::size_t count = tree.tokens.size();
    const std::size_t step = count / kLineSamples + 1;
    for (std::size_t i = 0; i < count; i += step) {
        const ast::Token& t = tree.tokens[i];
        const ast::Position p = lines.utf16(t.begin);
        KERF_CHECK(p.line < lines.line_count(), p.line, lines.line_count());
        KERF_CHECK(lines.offset_of_utf16(p) <= n, t.begin);
        const ast::Position q = lines.utf8(tree.end(t));
        KERF_CHECK(q.line < lines.line_count(), q.line, lines.line_count());
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0 || size > kMaxInput) return 0;   // byte 0 + at most 64 KiB - 1 of text
    static const dialects::Registry& registry = dialects::builtin_registry();
    const dialects::Dialect* dialect = registry.find(kDialects[dialect_index(data[0])]);
    if (!dialect) fail("built-in dialect missing", dialect_index(data[0]));

    const std::string input(reinterpret_cast<const char*>(data) + 1, size - 1);
    ast::SyntaxTree tree = grammar::parse(input, dialect->lexical);

    KERF_CHECK(tree.text == input, tree.text.size(), input.size());
    if (ast::print(tree) != input) fail("print(tree) != input", input.size());
    if (const auto violation = ast::check_lossless(tree)) {
        std::fprintf(stderr, "fuzz_grammar: check_lossless: %s\n", violation->what.c_str());
        fail("check_lossless", violation->offset);
    }
    check_tree(tree);

    ast::TypedFile file = ast::TypedFile::bind(tree, *dialect);
    check_tree(tree);   // bind only sets roles; everything else must be as it was
    if (ast::print(tree) != input) fail("print(tree) != input after bind", input.size());
    check_typed(file, tree);

    // The language server's partial re-bind: the last block and one in the middle.
    const std::size_t blocks = tree.block_count();
    file.rebind_block(tree, blocks - 1);
    if (blocks > 2) file.rebind_block(tree, blocks / 2);
    check_typed(file, tree);
    check_lines(tree);
    return 0;
}
