// Selection range: the word under the cursor, then its block (without the line break), then its
// program, then the whole document.
#include "lsp/features/common.hpp"

namespace kerf::lsp {

json::value selection_ranges(const Snapshot& s, const std::vector<ast::Position>& at) {
    const Document& doc = s.document();
    json::array out;
    const ast::Range whole{0, static_cast<std::uint32_t>(doc.text().size())};
    for (const ast::Position p : at) {
        const std::uint32_t offset = doc.offset(p);
        std::vector<ast::Range> chain;   // innermost first
        if (doc.refused().empty() && doc.tree().block_count() > 0) {
            const std::uint32_t block = doc.block_at(offset);
            if (const auto t = doc.token_at(offset)) chain.push_back(doc.tree().range(doc.tree().tokens[*t]));
            const ast::Range words = words_range(doc.tree(), block);
            if (chain.empty() || !(chain.back() == words)) chain.push_back(words);
            if (const auto program = references::program_of_block(doc.typed(), block)) {
                const ast::Range r = program_range(doc, *program);
                if (!(chain.back() == r)) chain.push_back(r);
            }
        }
        if (chain.empty() || !(chain.back() == whole)) chain.push_back(whole);
        json::object node{{"range", range_json(doc, chain.back())}};
        for (std::size_t i = chain.size() - 1; i-- > 0;) node = json::object{{"range", range_json(doc, chain[i])}, {"parent", std::move(node)}};
        out.push_back(std::move(node));
    }
    return out;
}

}  // namespace kerf::lsp
