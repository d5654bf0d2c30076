// Folding ranges: each program (its O line to its last block), each WHILE [...] DO m ... END m
// loop, each cycle profile N(P) ... N(Q) of G70–G73 (the lines the cycle reads, as
// references/references.hpp resolves P and Q), and each run of two or more comment lines.
#include <set>
#include <vector>

#include "lsp/features/common.hpp"

namespace kerf::lsp {

namespace {

json::object fold(std::uint32_t first, std::uint32_t last, const char* kind) {
    json::object f{{"startLine", first}, {"endLine", last}};
    if (kind) f["kind"] = kind;
    return f;
}

std::uint32_t line_of(const Document& doc, std::uint32_t block) { return doc.lines().utf8(doc.tree().blocks[block].begin).line; }

// The last line a block's words are on.
std::uint32_t end_line(const Document& doc, std::uint32_t block) {
    const ast::Range r = words_range(doc.tree(), block);
    return doc.lines().utf8(r.end > r.begin ? r.end - 1 : r.begin).line;
}

std::optional<std::int64_t> loop_label(const ast::SyntaxTree& tree, const ast::Statement& st) {
    std::int32_t e = st.label;
    while (e >= 0 && tree.exprs[static_cast<std::size_t>(e)].kind == ast::ExprKind::bracket) e = tree.exprs[static_cast<std::size_t>(e)].a;
    if (e < 0 || tree.exprs[static_cast<std::size_t>(e)].kind != ast::ExprKind::number) return std::nullopt;
    return ast::truncated_integer(tree.number_value(tree.exprs[static_cast<std::size_t>(e)]));
}

}  // namespace

json::value folding_ranges(const Snapshot& s) {
    const Document& doc = s.document();
    const ast::SyntaxTree& tree = doc.tree();
    json::array out;
    if (!doc.refused().empty()) return out;
    const auto& programs = doc.typed().programs();
    for (std::uint32_t p = 0; p < programs.size(); ++p) {
        const ast::Range r = program_range(doc, p);
        const std::uint32_t a = doc.lines().utf8(r.begin).line, b = doc.lines().utf8(r.end > r.begin ? r.end - 1 : r.begin).line;
        if (b > a) out.push_back(fold(a, b, "region"));
        // Loops: DO m opens, END m closes the innermost open loop with the same m (dialects.md §3.7).
        std::vector<std::pair<std::int64_t, std::uint32_t>> open;   // label, block
        for (std::uint32_t blk = programs[p].first_block; blk < programs[p].end_block; ++blk) {
            for (std::uint32_t t = tree.block_first_token(blk); t < tree.block_token_end(blk); ++t) {
                if (tree.tokens[t].kind != ast::TokenKind::statement) continue;
                const ast::Statement& st = tree.statements[static_cast<std::size_t>(tree.tokens[t].payload)];
                const auto m = loop_label(tree, st);
                if (!m) continue;
                if (st.kind == ast::StatementKind::while_do || st.kind == ast::StatementKind::do_) {
                    open.emplace_back(*m, blk);
                } else if (st.kind == ast::StatementKind::end) {
                    for (std::size_t i = open.size(); i-- > 0;)
                        if (open[i].first == *m) {
                            const std::uint32_t a2 = line_of(doc, open[i].second), b2 = end_line(doc, blk);
                            if (b2 > a2) out.push_back(fold(a2, b2, nullptr));
                            open.resize(i);
                            break;
                        }
                }
            }
        }
    }
    // Cycle profiles: P and Q of the same G70–G73 block (G71 and its G70 fold the same lines once).
    std::set<std::pair<std::uint32_t, std::uint32_t>> profiles;
    std::int64_t p_label = -1;
    std::uint32_t p_block = 0;
    for (const references::Reference& r : references::file_references(doc.typed())) {
        if (r.kind != references::Kind::profile_label || !r.value) continue;
        if (r.letter == 'P') {
            p_label = *r.value;
            p_block = r.block;
            continue;
        }
        if (p_label < 0 || p_block != r.block) continue;
        const auto first = references::find_label(doc.typed(), r.program, p_label);
        const auto last = references::find_label(doc.typed(), r.program, *r.value);
        if (first && last && *last > *first) profiles.emplace(line_of(doc, *first), end_line(doc, *last));
        p_label = -1;
    }
    for (const auto& [a, b] : profiles) out.push_back(fold(a, b, "region"));
    // Runs of comment lines.
    bool in_run = false;
    std::uint32_t run_start = 0, run_end = 0;
    const auto close_run = [&] {
        if (in_run && run_end > run_start) out.push_back(fold(run_start, run_end, "comment"));
        in_run = false;
    };
    for (std::uint32_t b = 0; b < tree.block_count(); ++b) {
        if (tree.blocks[b].kind == ast::BlockKind::comment_only) {
            const std::uint32_t line = line_of(doc, b);
            if (!in_run || line > run_end + 1) {
                close_run();
                in_run = true;
                run_start = line;
            }
            run_end = line;
        } else if (tree.blocks[b].kind != ast::BlockKind::blank) {
            close_run();
        }
    }
    close_run();
    return out;
}

}  // namespace kerf::lsp
