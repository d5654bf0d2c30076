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

// The text of the edited document between two of its offsets, without building it whole.
std::string edited_slice(const std::string& old, const ByteEdit& edit, std::size_t from, std::size_t to) {
    // New offsets: [0, edit.begin) as before, then the inserted text, then the old text from edit.end on.
    std::string out;
    out.reserve(to - from);
    const std::size_t ins_end = edit.begin + edit.text.size();
    for (std::size_t at = from; at < to;) {
        if (at < edit.begin) {
            const std::size_t n = std::min<std::size_t>(to, edit.begin) - at;
            out.append(old, at, n);
            at += n;
        } else if (at < ins_end) {
            const std::size_t n = std::min(to, ins_end) - at;
            out.append(edit.text.substr(at - edit.begin, n));
            at += n;
        } else {
            const std::size_t old_at = at - ins_end + edit.end;
            out.append(old, old_at, to - at);
            at = to;
        }
    }
    return out;
}

// What an edit does to a tree: computed from the old tree alone, applied by copying (reparse) or in
// place (reparse_in_place).
struct Plan {
    bool full = false;             // parse the edited text whole
    bool tail = false;             // the edit is inside the text after the closing '%'
    std::uint32_t line_begin = 0;  // the old bytes [line_begin, old_end) are the touched lines
    std::uint32_t old_end = 0;
    std::int64_t delta = 0;
    std::size_t first = 0, last = 0;   // the old blocks replaced
    std::size_t t0 = 0, t1 = 0, e0 = 0, e1 = 0, s0 = 0, s1 = 0;
    ast::SyntaxTree region;        // the touched lines of the new text, parsed (offsets from line_begin)
    Shift in_region, after;
};

Plan make_plan(const ast::SyntaxTree& old, const ByteEdit& edit, const dialects::LexicalRules& rules) {
    Plan p;
    const std::string& text = old.text;
    const std::size_t n = text.size();
    const std::size_t new_size = n - (edit.end - edit.begin) + edit.text.size();
    p.delta = static_cast<std::int64_t>(edit.text.size()) - static_cast<std::int64_t>(edit.end - edit.begin);
    if (n == 0 || new_size == 0 || n >= 0xFFFFFFF0u || new_size >= 0xFFFFFFF0u) {
        p.full = true;
        return p;
    }
    // The touched lines: from the start of the line of `begin` to the end of the line of `end`.
    const std::size_t before_nl = edit.begin == 0 ? std::string::npos : text.rfind('\n', edit.begin - 1);
    p.line_begin = before_nl == std::string::npos ? 0 : static_cast<std::uint32_t>(before_nl + 1);
    const std::size_t after_nl = text.find('\n', edit.end);
    p.old_end = after_nl == std::string::npos ? static_cast<std::uint32_t>(n) : static_cast<std::uint32_t>(after_nl + 1);

    const std::size_t count = old.block_count();
    const bool has_tail = count > 0 && old.blocks[count - 1].kind == BlockKind::tail;
    const std::uint32_t tail_begin = has_tail ? old.blocks[count - 1].begin : static_cast<std::uint32_t>(n);
    p.tail = has_tail && p.line_begin >= tail_begin;
    p.first = p.tail ? count - 1 : first_block_at(old, p.line_begin);
    if (!p.tail && p.first < count && old.blocks[p.first].begin != p.line_begin) {
        p.full = true;
        return p;
    }
    if (has_tail && p.old_end > tail_begin) p.old_end = static_cast<std::uint32_t>(n);

    grammar::ParseState start = state_before(old, p.first);
    start.file_start = p.line_begin == 0;
    p.last = p.first;
    if (p.tail) {
        // Inside the text after the closing '%': it stays one tail block (the control does not read it).
        p.last = count;
        p.old_end = static_cast<std::uint32_t>(n);
    } else {
        while (true) {
            p.last = p.old_end >= n ? count : first_block_at(old, p.old_end);
            const std::uint32_t new_end = moved(p.old_end, p.delta);
            grammar::ParseState end = start;
            if (new_end > p.line_begin)
                end = grammar::parse_into(p.region, edited_slice(text, edit, p.line_begin, new_end), rules, start);
            else
                p.region = ast::SyntaxTree{};
            if (p.old_end >= n) break;
            const grammar::ParseState old_state = state_before(old, p.last);
            if (!end.ended && !old_state.ended && end.program_seen == old_state.program_seen) break;
            p.old_end = static_cast<std::uint32_t>(n);   // the '%' state changed: the rest of the file reads differently
        }
    }
    // The offsets of the old nodes: [0, first) before, [last, count) after the edited lines.
    p.t0 = p.first < count ? old.blocks[p.first].first_token : old.tokens.size();
    p.t1 = p.last < count ? old.blocks[p.last].first_token : old.tokens.size();
    const auto expr_at = [&](std::uint32_t offset) {
        return static_cast<std::size_t>(std::partition_point(old.exprs.begin(), old.exprs.end(), [&](const ast::Expr& e) { return e.begin < offset; }) - old.exprs.begin());
    };
    const auto statement_at = [&](std::uint32_t offset) {
        return static_cast<std::size_t>(std::partition_point(old.statements.begin(), old.statements.end(), [&](const ast::Statement& st) { return st.range.begin < offset; }) - old.statements.begin());
    };
    p.e0 = expr_at(p.line_begin);
    p.e1 = p.old_end >= n ? old.exprs.size() : expr_at(p.old_end);
    p.s0 = statement_at(p.line_begin);
    p.s1 = p.old_end >= n ? old.statements.size() : statement_at(p.old_end);
    p.in_region = {p.line_begin, static_cast<std::int64_t>(p.t0), static_cast<std::int64_t>(p.e0), static_cast<std::int64_t>(p.s0),
                   static_cast<std::int64_t>(old.big_numbers.size())};
    p.after = {p.delta, static_cast<std::int64_t>(p.t0 + p.region.tokens.size()) - static_cast<std::int64_t>(p.t1),
               static_cast<std::int64_t>(p.e0 + p.region.exprs.size()) - static_cast<std::int64_t>(p.e1),
               static_cast<std::int64_t>(p.s0 + p.region.statements.size()) - static_cast<std::int64_t>(p.s1), 0};
    return p;
}

ast::Block shifted(ast::Block b, const Shift& s) {
    b.begin = moved(b.begin, s.bytes);
    b.first_token = moved(b.first_token, s.tokens);
    return b;
}

void fill_splice(const Plan& p, ast::BlockSplice& splice) {
    splice.first = static_cast<std::uint32_t>(p.first);
    splice.removed = p.tail ? 0 : static_cast<std::uint32_t>(p.last - p.first);
    splice.added = static_cast<std::uint32_t>(p.region.blocks.size());
    splice.old_begin = p.line_begin;
    splice.old_end = p.old_end;
    splice.shift = p.delta;
}

void full_splice(std::size_t old_blocks, std::size_t new_blocks, ast::BlockSplice& splice) {
    splice = {0, static_cast<std::uint32_t>(old_blocks), static_cast<std::uint32_t>(new_blocks), 0, 0xFFFFFFFFu, 0};
}

// The diagnostics: those before the touched lines, the new ones, those after them moved.
std::vector<ast::Diagnostic> spliced_diagnostics(const std::vector<ast::Diagnostic>& old, const Plan& p) {
    std::vector<ast::Diagnostic> out;
    for (const ast::Diagnostic& d : old)
        if (d.range.begin < p.line_begin) out.push_back(d);
    for (const ast::Diagnostic& d : p.region.diagnostics) out.push_back(shifted(d, p.line_begin));
    if (!p.tail)
        for (const ast::Diagnostic& d : old)
            if (d.range.begin >= p.old_end) out.push_back(shifted(d, p.delta));
    return out;
}

// The long tokens' lengths (ast/syntax.hpp LongToken), spliced like the diagnostics.
std::vector<ast::LongToken> spliced_long_tokens(const std::vector<ast::LongToken>& old, const Plan& p) {
    std::vector<ast::LongToken> out;
    for (const ast::LongToken& l : old)
        if (l.begin < p.line_begin) out.push_back(l);
    for (const ast::LongToken& l : p.region.long_tokens) out.push_back({moved(l.begin, p.line_begin), l.length});
    if (!p.tail)
        for (const ast::LongToken& l : old)
            if (l.begin >= p.old_end) out.push_back({moved(l.begin, p.delta), l.length});
    return out;
}

// Replaces v[first, last) by `with` (each through `fresh`) and moves the elements after it through
// `moved_tail`, in place: the tail is shifted once by memmove and once by the offset pass.
template <class V, class W, class F, class G>
void replace_in_place(V& v, std::size_t first, std::size_t last, const W& with, F fresh, G moved_tail) {
    const std::size_t removed = last - first, added = with.size();
    if (added > removed) v.insert(v.begin() + static_cast<std::ptrdiff_t>(last), added - removed, typename V::value_type{});
    else if (added < removed) v.erase(v.begin() + static_cast<std::ptrdiff_t>(first + added), v.begin() + static_cast<std::ptrdiff_t>(last));
    for (std::size_t i = 0; i < added; ++i) v[first + i] = fresh(with[i]);
    for (std::size_t i = first + added; i < v.size(); ++i) v[i] = moved_tail(v[i]);
}

}  // namespace

ast::SyntaxTree reparse(const ast::SyntaxTree& old, const ByteEdit& edit, const dialects::LexicalRules& rules,
                        ast::BlockSplice& splice) {
    Plan p = make_plan(old, edit, rules);
    std::string new_text;
    new_text.reserve(old.text.size() - (edit.end - edit.begin) + edit.text.size());
    new_text.append(old.text, 0, edit.begin).append(edit.text).append(old.text, edit.end, std::string::npos);
    if (p.full) {
        ast::SyntaxTree tree = grammar::parse(std::move(new_text), rules, grammar::parse_threads());
        full_splice(old.block_count(), tree.block_count(), splice);
        return tree;
    }
    const std::size_t count = old.block_count();
    const Shift keep{};
    ast::SyntaxTree tree;
    tree.text = std::move(new_text);
    tree.blocks.reserve(count - (p.last - p.first) + p.region.blocks.size());
    const auto block_shifted = [](const Shift& sh) { return [&sh](const ast::Block& b) { return shifted(b, sh); }; };
    append(tree.blocks, old.blocks, 0, p.first, block_shifted(keep));
    append(tree.blocks, p.region.blocks, 0, p.region.blocks.size(), block_shifted(p.in_region));
    if (p.tail) tree.blocks.push_back(old.blocks[count - 1]);   // the tail, where it was
    else append(tree.blocks, old.blocks, p.last, count, block_shifted(p.after));

    tree.tokens.reserve(old.tokens.size() - (p.t1 - p.t0) + p.region.tokens.size());
    const auto token_shifted = [](const Shift& sh) { return [&sh](const ast::Token& t) { return shifted(t, sh); }; };
    append(tree.tokens, old.tokens, 0, p.t0, token_shifted(keep));
    append(tree.tokens, p.region.tokens, 0, p.region.tokens.size(), token_shifted(p.in_region));
    append(tree.tokens, old.tokens, p.t1, old.tokens.size(), token_shifted(p.after));

    const auto expr_shifted = [](const Shift& sh) { return [&sh](const ast::Expr& e) { return shifted(e, sh); }; };
    append(tree.exprs, old.exprs, 0, p.e0, expr_shifted(keep));
    append(tree.exprs, p.region.exprs, 0, p.region.exprs.size(), expr_shifted(p.in_region));
    append(tree.exprs, old.exprs, p.e1, old.exprs.size(), expr_shifted(p.after));

    const auto statement_shifted = [](const Shift& sh) { return [&sh](const ast::Statement& st) { return shifted(st, sh); }; };
    append(tree.statements, old.statements, 0, p.s0, statement_shifted(keep));
    append(tree.statements, p.region.statements, 0, p.region.statements.size(), statement_shifted(p.in_region));
    append(tree.statements, old.statements, p.s1, old.statements.size(), statement_shifted(p.after));

    tree.big_numbers = old.big_numbers;
    tree.big_numbers.insert(tree.big_numbers.end(), p.region.big_numbers.begin(), p.region.big_numbers.end());
    tree.diagnostics = spliced_diagnostics(old.diagnostics, p);
    tree.long_tokens = spliced_long_tokens(old.long_tokens, p);
    fill_splice(p, splice);
    return tree;
}

void reparse_in_place(ast::SyntaxTree& tree, const ByteEdit& edit, const dialects::LexicalRules& rules, ast::BlockSplice& splice,
                      const BeforeSplice& before) {
    Plan p = make_plan(tree, edit, rules);
    if (before && !p.full) before(tree, static_cast<std::uint32_t>(p.first), static_cast<std::uint32_t>(p.tail ? p.first : p.last));
    tree.text.replace(edit.begin, edit.end - edit.begin, edit.text);
    if (p.full) {
        const std::size_t old_blocks = tree.block_count();
        tree = grammar::parse(std::move(tree.text), rules, grammar::parse_threads());
        full_splice(old_blocks, tree.block_count(), splice);
        return;
    }
    fill_splice(p, splice);
    tree.diagnostics = spliced_diagnostics(tree.diagnostics, p);
    tree.long_tokens = spliced_long_tokens(tree.long_tokens, p);
    if (p.tail) return;   // the tail block keeps its place; only the text changed
    replace_in_place(tree.blocks, p.first, p.last, p.region.blocks, [&](const ast::Block& b) { return shifted(b, p.in_region); },
                     [&](const ast::Block& b) { return shifted(b, p.after); });
    replace_in_place(tree.tokens, p.t0, p.t1, p.region.tokens, [&](const ast::Token& t) { return shifted(t, p.in_region); },
                     [&](const ast::Token& t) { return shifted(t, p.after); });
    replace_in_place(tree.exprs, p.e0, p.e1, p.region.exprs, [&](const ast::Expr& e) { return shifted(e, p.in_region); },
                     [&](const ast::Expr& e) { return shifted(e, p.after); });
    replace_in_place(tree.statements, p.s0, p.s1, p.region.statements, [&](const ast::Statement& st) { return shifted(st, p.in_region); },
                     [&](const ast::Statement& st) { return shifted(st, p.after); });
    tree.big_numbers.insert(tree.big_numbers.end(), p.region.big_numbers.begin(), p.region.big_numbers.end());
}

}  // namespace kerf::lsp
