#include "lsp/reparse.hpp"

#include <algorithm>

#include "grammar/parse.hpp"

namespace kerf::lsp {

namespace {

using ast::BlockKind;

// The parser's state before block `i` (grammar/parse.cpp Driver::run): it changes only at the end
// of a line, by the line's last block: code sets program_seen, a '%' after code closes the tape
// (the rest is one tail block), any other '%' opens it again.
grammar::ParseState state_before(const ast::SyntaxTree& tree, std::size_t i) {
    grammar::ParseState state;
    state.file_start = false;
    if (i < tree.block_count() && tree.blocks[i].kind == BlockKind::tail) {
        state.program_seen = true;
        state.ended = true;
        return state;
    }
    for (std::size_t b = i; b-- > 0;) {
        const bool last_of_line = b + 1 == i || tree.text[tree.blocks[b + 1].begin - 1] == '\n';
        if (!last_of_line) continue;
        const BlockKind kind = tree.blocks[b].kind;
        if (kind == BlockKind::code || kind == BlockKind::program_start) {
            state.program_seen = true;
            return state;
        }
        if (kind == BlockKind::percent) return state;   // an opening '%': a closing one has the tail after it
    }
    return state;
}

std::size_t first_block_at(const ast::SyntaxTree& tree, std::uint32_t offset) {
    const auto it = std::lower_bound(tree.blocks.begin(), tree.blocks.end(), offset,
                                     [](const ast::Block& b, std::uint32_t o) { return b.begin < o; });
    return static_cast<std::size_t>(it - tree.blocks.begin());
}

// Index shifts of the arrays after the edit: `region` for the new nodes (numbered from 0 in the
// scratch tree), `after` for the old nodes behind the edited lines.
struct Shift {
    std::int64_t bytes = 0;
    std::int64_t tokens = 0;
    std::int64_t exprs = 0;
    std::int64_t statements = 0;
    std::int64_t big = 0;
};

template <class T>
T moved(T value, std::int64_t by) { return static_cast<T>(static_cast<std::int64_t>(value) + by); }

ast::Token shifted(ast::Token t, const Shift& s) {
    t.begin = moved(t.begin, s.bytes);
    if (t.kind == ast::TokenKind::statement) t.payload = moved(t.payload, s.statements);
    else if ((t.kind == ast::TokenKind::word || t.kind == ast::TokenKind::comma_word)) {
        if (t.has(ast::token_flags::value_expr)) t.payload = moved(t.payload, s.exprs);
        else if (t.has(ast::token_flags::value_big)) t.payload = moved(t.payload, s.big);
    }
    return t;
}

ast::Expr shifted(ast::Expr e, const Shift& s) {
    e.begin = moved(e.begin, s.bytes);
    e.end = moved(e.end, s.bytes);
    if (e.kind == ast::ExprKind::number) {
        if (e.flags & ast::token_flags::value_big) e.a = moved(e.a, s.big);
        return e;
    }
    if (e.a >= 0) e.a = moved(e.a, s.exprs);
    if (e.b >= 0 && (e.kind == ast::ExprKind::binary || e.kind == ast::ExprKind::function)) e.b = moved(e.b, s.exprs);
    return e;
}

ast::Statement shifted(ast::Statement st, const Shift& s) {
    st.range = {moved(st.range.begin, s.bytes), moved(st.range.end, s.bytes)};
    if (st.kind == ast::StatementKind::dprnt || st.kind == ast::StatementKind::bprnt)
        st.text = {moved(st.text.begin, s.bytes), moved(st.text.end, s.bytes)};
    for (std::int32_t* e : {&st.target, &st.value, &st.label})
        if (*e >= 0) *e = moved(*e, s.exprs);
    if (st.then_statement >= 0) st.then_statement = moved(st.then_statement, s.statements);
    return st;
}

ast::Diagnostic shifted(ast::Diagnostic d, std::int64_t bytes) {
    d.range = {moved(d.range.begin, bytes), moved(d.range.end, bytes)};
    return d;
}

template <class V, class F>
void append(V& out, const V& in, std::size_t first, std::size_t last, F f) {
    for (std::size_t i = first; i < last; ++i) out.push_back(f(in[i]));
}

ast::SyntaxTree full_parse(std::string text, const dialects::LexicalRules& rules, std::size_t old_blocks, ast::BlockSplice& splice) {
    ast::SyntaxTree tree = grammar::parse(std::move(text), rules);
    splice = {0, static_cast<std::uint32_t>(old_blocks), static_cast<std::uint32_t>(tree.block_count()), 0,
              0xFFFFFFFFu, 0};
    return tree;
}

}  // namespace

ast::SyntaxTree reparse(const ast::SyntaxTree& old, const ByteEdit& edit, const dialects::LexicalRules& rules,
                        ast::BlockSplice& splice) {
    const std::string& text = old.text;
    const std::size_t n = text.size();
    std::string new_text;
    new_text.reserve(n - (edit.end - edit.begin) + edit.text.size());
    new_text.append(text, 0, edit.begin).append(edit.text).append(text, edit.end, std::string::npos);
    if (n == 0 || new_text.empty() || n >= 0xFFFFFFF0u || new_text.size() >= 0xFFFFFFF0u)
        return full_parse(std::move(new_text), rules, old.block_count(), splice);

    const std::int64_t delta = static_cast<std::int64_t>(edit.text.size()) - static_cast<std::int64_t>(edit.end - edit.begin);
    // The touched lines: from the start of the line of `begin` to the end of the line of `end`.
    const std::size_t before_nl = edit.begin == 0 ? std::string::npos : text.rfind('\n', edit.begin - 1);
    const std::uint32_t line_begin = before_nl == std::string::npos ? 0 : static_cast<std::uint32_t>(before_nl + 1);
    const std::size_t after_nl = text.find('\n', edit.end);
    std::uint32_t old_end = after_nl == std::string::npos ? static_cast<std::uint32_t>(n) : static_cast<std::uint32_t>(after_nl + 1);

    const std::size_t count = old.block_count();
    const bool has_tail = count > 0 && old.blocks[count - 1].kind == BlockKind::tail;
    const std::uint32_t tail_begin = has_tail ? old.blocks[count - 1].begin : static_cast<std::uint32_t>(n);
    const bool in_tail = has_tail && line_begin >= tail_begin;
    const std::size_t first = in_tail ? count - 1 : first_block_at(old, line_begin);
    if (!in_tail && first < count && old.blocks[first].begin != line_begin) return full_parse(std::move(new_text), rules, count, splice);
    if (has_tail && old_end > tail_begin) old_end = static_cast<std::uint32_t>(n);

    grammar::ParseState start = state_before(old, first);
    start.file_start = line_begin == 0;
    ast::SyntaxTree region;
    std::size_t last = first;
    if (start.ended) {
        // Inside the text after the closing '%': it stays one tail block (the control does not read it).
        last = count;
        old_end = static_cast<std::uint32_t>(n);
    } else {
        while (true) {
            last = old_end >= n ? count : first_block_at(old, old_end);
            const std::uint32_t new_end = moved(old_end, delta);
            grammar::ParseState end = start;
            if (new_end > line_begin)
                end = grammar::parse_into(region, std::string_view(new_text).substr(line_begin, new_end - line_begin), rules, start);
            else
                region = ast::SyntaxTree{};
            if (old_end >= n) break;
            const grammar::ParseState old_state = state_before(old, last);
            if (!end.ended && !old_state.ended && end.program_seen == old_state.program_seen) break;
            old_end = static_cast<std::uint32_t>(n);   // the '%' state changed: the rest of the file reads differently
        }
    }

    // The offsets of the old nodes: [0, first) before, [last, count) after the edited lines.
    const std::size_t t0 = first < count ? old.blocks[first].first_token : old.tokens.size();
    const std::size_t t1 = last < count ? old.blocks[last].first_token : old.tokens.size();
    const auto expr_at = [&](std::uint32_t offset) {
        return static_cast<std::size_t>(std::partition_point(old.exprs.begin(), old.exprs.end(), [&](const ast::Expr& e) { return e.begin < offset; }) - old.exprs.begin());
    };
    const auto statement_at = [&](std::uint32_t offset) {
        return static_cast<std::size_t>(std::partition_point(old.statements.begin(), old.statements.end(), [&](const ast::Statement& s) { return s.range.begin < offset; }) - old.statements.begin());
    };
    const std::size_t e0 = expr_at(line_begin), e1 = old_end >= n ? old.exprs.size() : expr_at(old_end);
    const std::size_t s0 = statement_at(line_begin), s1 = old_end >= n ? old.statements.size() : statement_at(old_end);

    const Shift keep{};
    const Shift in_region{line_begin, static_cast<std::int64_t>(t0), static_cast<std::int64_t>(e0), static_cast<std::int64_t>(s0),
                          static_cast<std::int64_t>(old.big_numbers.size())};
    const Shift after{delta, static_cast<std::int64_t>(t0 + region.tokens.size()) - static_cast<std::int64_t>(t1),
                      static_cast<std::int64_t>(e0 + region.exprs.size()) - static_cast<std::int64_t>(e1),
                      static_cast<std::int64_t>(s0 + region.statements.size()) - static_cast<std::int64_t>(s1), 0};

    ast::SyntaxTree tree;
    tree.text = std::move(new_text);
    tree.blocks.reserve(count - (last - first) + region.blocks.size());
    const auto block_shifted = [](const Shift& s) {
        return [&s](ast::Block b) {
            b.begin = moved(b.begin, s.bytes);
            b.first_token = moved(b.first_token, s.tokens);
            return b;
        };
    };
    append(tree.blocks, old.blocks, 0, first, block_shifted(keep));
    append(tree.blocks, region.blocks, 0, region.blocks.size(), block_shifted(in_region));
    if (start.ended) {
        tree.blocks.push_back(old.blocks[count - 1]);   // the tail, where it was
    } else {
        append(tree.blocks, old.blocks, last, count, block_shifted(after));
    }

    tree.tokens.reserve(old.tokens.size() - (t1 - t0) + region.tokens.size());
    const auto token_shifted = [](const Shift& s) { return [&s](const ast::Token& t) { return shifted(t, s); }; };
    append(tree.tokens, old.tokens, 0, t0, token_shifted(keep));
    append(tree.tokens, region.tokens, 0, region.tokens.size(), token_shifted(in_region));
    append(tree.tokens, old.tokens, t1, old.tokens.size(), token_shifted(after));

    const auto expr_shifted = [](const Shift& s) { return [&s](const ast::Expr& e) { return shifted(e, s); }; };
    append(tree.exprs, old.exprs, 0, e0, expr_shifted(keep));
    append(tree.exprs, region.exprs, 0, region.exprs.size(), expr_shifted(in_region));
    append(tree.exprs, old.exprs, e1, old.exprs.size(), expr_shifted(after));

    const auto statement_shifted = [](const Shift& s) { return [&s](const ast::Statement& st) { return shifted(st, s); }; };
    append(tree.statements, old.statements, 0, s0, statement_shifted(keep));
    append(tree.statements, region.statements, 0, region.statements.size(), statement_shifted(in_region));
    append(tree.statements, old.statements, s1, old.statements.size(), statement_shifted(after));

    tree.big_numbers = old.big_numbers;
    tree.big_numbers.insert(tree.big_numbers.end(), region.big_numbers.begin(), region.big_numbers.end());

    for (const ast::Diagnostic& d : old.diagnostics)
        if (d.range.begin < line_begin) tree.diagnostics.push_back(d);
    for (const ast::Diagnostic& d : region.diagnostics) tree.diagnostics.push_back(shifted(d, line_begin));
    for (const ast::Diagnostic& d : old.diagnostics)
        if (d.range.begin >= old_end && !start.ended) tree.diagnostics.push_back(shifted(d, delta));

    splice.first = static_cast<std::uint32_t>(first);
    splice.removed = start.ended ? 0 : static_cast<std::uint32_t>(last - first);
    splice.added = static_cast<std::uint32_t>(region.blocks.size());
    splice.old_begin = line_begin;
    splice.old_end = old_end;
    splice.shift = delta;
    return tree;
}

}  // namespace kerf::lsp
