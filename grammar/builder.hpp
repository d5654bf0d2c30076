// The parser's output side: appends tokens, expression nodes, statements and diagnostics to a
// SyntaxTree. Grammar actions reach it through the X3 context (builder_tag). Rules that can fail
// after building something are wrapped in `transactional[...]`, which rolls the builder back.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ast/syntax.hpp"
#include "dialects/dialect.hpp"

namespace kerf::grammar {

struct builder_tag;

// A number as written: exact decimal mantissa / 10^scale, or a double when it does not fit.
struct NumberLit {
    std::int64_t mantissa = 0;
    int scale = 0;
    bool point = false;
    bool negative = false;
    bool comma = false;    // decimal comma
    bool big = false;
    double big_value = 0;
    const char* begin = nullptr;
    const char* end = nullptr;
};

enum class PendingValue : std::uint8_t { none, number, expr };

class Builder {
public:
    // Offsets count from `text_base`: the start of the whole text, also when `target` receives
    // only a later stretch of it (grammar/parse.cpp, the second half of a parse on two threads).
    Builder(ast::SyntaxTree& target, const dialects::LexicalRules& lexical, const char* text_base)
        : tree(target), rules(lexical), base(text_base) {}

    ast::SyntaxTree& tree;
    const dialects::LexicalRules& rules;
    const char* base;

    // Expression construction: nodes are pushed in post-order; operators pop their operands.
    std::vector<std::int32_t> stack;
    std::vector<std::int32_t> statement_stack;
    struct FunctionMark { ast::Function function; std::size_t depth; };
    std::vector<FunctionMark> functions;
    std::vector<std::uint8_t> operators;   // pending binary operators of the current level

    // Expression nesting (FANUC allows 5 bracket levels; the analyzer says so). Deeper than this the
    // grammar gives up on the expression and the error rules report too_deep_at.
    static constexpr int kMaxExpressionDepth = 64;
    int depth = 0;
    const char* too_deep_at = nullptr;

    // Diagnostics of merged error runs whose message is written when the block ends (one message
    // per run, not one per piece: a 1 MB line of junk must not cost 1 MB per character).
    std::vector<std::size_t> merged_diagnostics;

    // The value of the word being parsed.
    PendingValue pending = PendingValue::none;
    NumberLit pending_number;
    ast::Range pending_text;   // DPRNT[...] content

    std::uint32_t offset(const char* p) const { return static_cast<std::uint32_t>(p - base); }

    struct Checkpoint {
        std::size_t tokens, exprs, statements, stack, statement_stack, functions, operators, diagnostics, big, long_tokens;
    };
    Checkpoint save() const {
        return {tree.tokens.size(), tree.exprs.size(), tree.statements.size(), stack.size(),
                statement_stack.size(), functions.size(), operators.size(), tree.diagnostics.size(),
                tree.big_numbers.size(), tree.long_tokens.size()};
    }
    void restore(const Checkpoint& c) {
        // Most rollbacks undo nothing; only shrink what grew.
        shrink(tree.tokens, c.tokens);
        shrink(tree.exprs, c.exprs);
        shrink(tree.statements, c.statements);
        shrink(stack, c.stack);
        shrink(statement_stack, c.statement_stack);
        shrink(functions, c.functions);
        shrink(operators, c.operators);
        shrink(tree.diagnostics, c.diagnostics);
        shrink(tree.big_numbers, c.big);
        shrink(tree.long_tokens, c.long_tokens);
    }
    template <typename V>
    static void shrink(V& v, std::size_t size) {
        if (v.size() > size) v.erase(v.begin() + static_cast<std::ptrdiff_t>(size), v.end());
    }

    // Stores a number's value into payload/scale/flags fields (shared by tokens and expr nodes).
    template <typename Node>
    void store_number(const NumberLit& n, Node& node, std::uint8_t& flags) {
        if (n.point) flags |= ast::token_flags::has_point;
        if (n.negative) flags |= ast::token_flags::negative;
        if (n.comma) flags |= ast::token_flags::decimal_comma;
        if (n.big) {
            flags |= ast::token_flags::value_big;
            tree.big_numbers.push_back(n.big_value);
            node = static_cast<std::int32_t>(tree.big_numbers.size() - 1);
        } else {
            node = static_cast<std::int32_t>(n.negative ? -n.mantissa : n.mantissa);
        }
    }

    // A word's number: exact in the token (mantissa and scale) when the mantissa fits its 28 bits,
    // else in big_numbers like any number too long for the exact form.
    void store_token_number(const NumberLit& n, ast::Token& t) {
        NumberLit stored = n;
        if (!n.big && n.mantissa > ast::Token::kMaxMantissa) {
            stored.big = true;
            stored.big_value = ast::exact_decimal(n.negative ? -n.mantissa : n.mantissa, n.scale);
        }
        std::int32_t payload = 0;
        store_number(stored, payload, t.flags);
        if (stored.big) t.payload = payload;
        else t.set_number(payload, n.scale);
    }

    std::int32_t push_expr(const ast::Expr& e) {
        tree.exprs.push_back(e);
        const auto index = static_cast<std::int32_t>(tree.exprs.size() - 1);
        stack.push_back(index);
        return index;
    }
    std::int32_t pop() {
        const std::int32_t top = stack.back();
        stack.pop_back();
        return top;
    }

    void diagnose(const char* b, const char* e, ast::Severity severity, const char* code, std::string message,
                  std::string hint) {
        tree.diagnostics.push_back({{offset(b), offset(e)}, severity, code, std::move(message), std::move(hint)});
    }

    ast::Token& add_token(ast::TokenKind kind, const char* b, const char* e) {
        ast::Token t;
        t.kind = kind;
        t.begin = offset(b);
        tree.tokens.push_back(t);
        ast::Token& added = tree.tokens.back();
        const auto length = static_cast<std::uint32_t>(e - b);
        if (length < ast::Token::kLongLength) added.short_length = static_cast<std::uint8_t>(length);
        else tree.set_length(added, length);
        return added;
    }

    // Adds an error token; consecutive generic error pieces separated only by blanks merge into one
    // token and one diagnostic, so a line of prose gives one finding, not one per word.
    void add_error(const char* b, const char* e, const char* code, std::string message, std::string hint,
                   bool mergeable);

    // True while the last token of the block is a mergeable error piece.
    bool last_error_mergeable = false;
    std::size_t block_first_token = 0;
    void start_block(std::size_t first_token) {
        block_first_token = first_token;
        last_error_mergeable = false;
    }
};

}  // namespace kerf::grammar
