#include "interpreter/block_scan.hpp"

namespace kerf::interpreter {

void scan_tokens(const ast::BlockView& view, BlockScan& scan) {
    view.collect_codes(scan.g, scan.m);
    scan.data_letters = 0;
    scan.macro_call = false;
    scan.classes = 0;
    for (const std::vector<ast::CodeRef>* codes : {&scan.g, &scan.m})
        for (const ast::CodeRef& c : *codes) {
            if (!c.info) continue;
            scan.classes |= code_class_of(*c.info);
            scan.data_letters |= c.info->parameter_mask;
            scan.macro_call |= c.info->has(dialects::traits::takes_arguments);
        }
    scan.statements = scan.comma_words = scan.direct_drawing = false;
    scan.sequence.reset();
    const ast::SyntaxTree& tree = view.tree();
    for (const ast::Token& t : view.tokens()) {
        if (t.kind == ast::TokenKind::word && t.letter == 'N' && t.is_number() && !scan.sequence)
            scan.sequence = tree.number_value(t);
        scan.statements |= t.kind == ast::TokenKind::statement;
        scan.comma_words |= t.kind == ast::TokenKind::comma_word;
        scan.direct_drawing |= t.kind == ast::TokenKind::word && t.role() == ast::Role::direct_drawing;
    }
}

void PieceScans::build(const ast::TypedFile& typed, const ast::LineIndex& lines, std::size_t text_begin,
                       std::uint32_t first_line) {
    clear();
    blocks_.reserve(typed.block_count());
    BlockScan scan;
    std::uint32_t line = 0;   // of the piece: the hint for the next block's line
    for (std::size_t b = 0; b < typed.block_count(); ++b) {
        const ast::BlockView view = typed.block(b);
        scan_tokens(view, scan);
        Facts f;
        f.tokens = static_cast<const TokenFacts&>(scan);
        f.first_code = static_cast<std::uint32_t>(codes_.size());
        f.g_codes = static_cast<std::uint32_t>(scan.g.size());
        f.m_codes = static_cast<std::uint32_t>(scan.m.size());
        codes_.insert(codes_.end(), scan.g.begin(), scan.g.end());
        codes_.insert(codes_.end(), scan.m.begin(), scan.m.end());
        const ast::Range local = view.range();
        line = lines.line_near(local.begin, line);
        f.line = first_line + line;
        f.range = {static_cast<std::uint32_t>(local.begin + text_begin), static_cast<std::uint32_t>(local.end + text_begin)};
        blocks_.push_back(f);
    }
}

void PieceScans::clear() {
    blocks_.clear();
    codes_.clear();
}

void PieceScans::fill(std::size_t index, BlockScan& scan) const {
    const Facts& f = blocks_[index];
    const auto first = codes_.begin() + f.first_code;
    scan.g.assign(first, first + f.g_codes);
    scan.m.assign(first + f.g_codes, first + f.g_codes + f.m_codes);
    static_cast<TokenFacts&>(scan) = f.tokens;
    scan.source.range = f.range;
    scan.source.line = f.line + 1;   // SourceRef lines are 1-based
}

}  // namespace kerf::interpreter
