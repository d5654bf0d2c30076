// Document highlight: in this document, the label under the cursor and every jump to it, the
// program and every call of it, a macro variable and every use of the same number, or a G/M code
// and the other blocks of its program with the same code.
#include "lsp/features/common.hpp"

#include <cmath>

namespace kerf::lsp {

namespace {

constexpr int kText = 1, kRead = 2, kWrite = 3;
constexpr std::size_t kMaxHighlights = 2000;

json::object highlight(const Document& doc, ast::Range r, int kind) { return {{"range", range_json(doc, r)}, {"kind", kind}}; }

// The variable number of a `#n` expression node with a constant n.
std::optional<std::int64_t> variable_number(const ast::SyntaxTree& tree, const ast::Expr& e) {
    if (e.kind != ast::ExprKind::variable || e.a < 0) return std::nullopt;
    const ast::Expr& n = tree.exprs[static_cast<std::size_t>(e.a)];
    if (n.kind != ast::ExprKind::number) return std::nullopt;
    const double v = tree.number_value(n);
    if (v != std::floor(v)) return std::nullopt;
    return static_cast<std::int64_t>(v);
}

json::array variables(const Document& doc, std::uint32_t offset) {
    const ast::SyntaxTree& tree = doc.tree();
    std::optional<std::int64_t> number;
    for (const ast::Expr& e : tree.exprs)
        if ((e.range().contains(offset) || e.end == offset) && (number = variable_number(tree, e))) break;
    json::array out;
    if (!number) return out;
    for (const ast::Expr& e : tree.exprs)
        if (out.size() < kMaxHighlights && variable_number(tree, e) == number) out.push_back(highlight(doc, e.range(), kText));
    return out;
}

json::array codes(const Document& doc, std::uint32_t token) {
    const ast::SyntaxTree& tree = doc.tree();
    const ast::Token& t = tree.tokens[token];
    json::array out;
    if (t.role() != ast::Role::g_code && t.role() != ast::Role::m_code) return out;
    const double value = tree.number_value(t);
    const auto program = references::program_of_block(doc.typed(), doc.block_at(t.begin));
    if (!program) return out;
    const ast::Program& p = doc.typed().programs()[*program];
    const std::uint32_t first = tree.block_first_token(p.first_block);
    const std::uint32_t last = p.end_block < tree.block_count() ? tree.block_first_token(p.end_block) : static_cast<std::uint32_t>(tree.tokens.size());
    for (std::uint32_t i = first; i < last && out.size() < kMaxHighlights; ++i) {
        const ast::Token& o = tree.tokens[i];
        if (o.kind == ast::TokenKind::word && o.letter == t.letter && o.role() == t.role() && o.is_number() && tree.number_value(o) == value)
            out.push_back(highlight(doc, doc.tree().range(o), kText));
    }
    return out;
}

}  // namespace

json::value document_highlight(const Snapshot& s, ast::Position at) {
    const Document& doc = s.document();
    const std::uint32_t offset = doc.offset(at);
    const Named named = named_at(s, offset);
    json::array out;
    if (named.label && named.label->doc->path() == doc.path()) {
        const LabelTarget& t = *named.label;
        if (references::find_label(doc.typed(), t.program, t.label) == t.block) {
            const auto n = n_word(doc.tree(), t.block);
            if (n) out.push_back(highlight(doc, doc.tree().range(doc.tree().tokens[*n]), kWrite));
            for (const references::Reference& r : references::file_references(doc.typed())) {
                if (!references::is_label(r.kind) || r.value != t.label) continue;
                const auto scope = references::label_scope(doc.typed(), r);
                if (std::find(scope.programs.begin(), scope.programs.end(), t.program) != scope.programs.end())
                    out.push_back(highlight(doc, r.range, kRead));
            }
        }
        return out;
    }
    if (named.program) {
        const ProgramTarget& t = *named.program;
        if (t.doc->path() == doc.path()) {
            const ast::Program& p = doc.typed().programs()[t.program];
            if (p.o_token >= 0) out.push_back(highlight(doc, doc.tree().range(doc.tree().tokens[static_cast<std::size_t>(p.o_token)]), kWrite));
        }
        for (const references::Reference& r : references::file_references(doc.typed())) {
            if (references::is_label(r.kind) || r.value != t.number) continue;
            const auto reached = program_target(s, s.doc, t.number);
            if (reached && reached->doc->path() == t.doc->path() && reached->program == t.program) out.push_back(highlight(doc, r.range, kRead));
        }
        return out;
    }
    if (json::array v = variables(doc, offset); !v.empty()) return v;
    if (const auto token = doc.token_at(offset)) return codes(doc, *token);
    return out;
}

}  // namespace kerf::lsp
