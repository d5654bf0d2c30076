// Go to definition: from a jump or call to the block or program it reaches, as the control would
// (references/references.hpp): GOTO n, G70–G73 P/Q, M98 Q, M97 P to the label of the program;
// M99 P to the label in each caller; M98 P (both forms) and G65/G66 P to the O line, in this file or
// through the program index in another file of the workspace. On an N or O word: the word itself.
#include "lsp/features/common.hpp"

namespace kerf::lsp {

json::object label_location(const LabelTarget& t) {
    const ast::SyntaxTree& tree = t.doc->tree();
    const auto n = n_word(tree, t.block);
    return location_json(*t.doc, n ? tree.range(tree.tokens[*n]) : words_range(tree, t.block));
}

json::object program_location(const ProgramTarget& t) {
    const ast::Program& p = t.doc->typed().programs()[t.program];
    const ast::Range r = p.o_token >= 0 ? t.doc->tree().range(t.doc->tree().tokens[static_cast<std::size_t>(p.o_token)])
                                        : words_range(t.doc->tree(), p.first_block);
    return location_json(*t.doc, r);
}

json::value definition(const Snapshot& s, ast::Position at) {
    const Document& doc = s.document();
    const std::uint32_t offset = doc.offset(at);
    if (const auto r = reference_at(doc, offset)) {
        json::array out;
        if (references::is_label(r->kind)) {
            for (const LabelTarget& t : label_targets(s, *r)) out.push_back(label_location(t));
        } else if (r->value) {
            if (const auto t = program_target(s, s.doc, *r->value)) out.push_back(program_location(*t));
        }
        if (out.empty()) return nullptr;
        if (out.size() == 1) return out.front();
        return out;
    }
    if (const auto block = label_word_at(doc, offset)) return location_json(doc, doc.tree().range(doc.tree().tokens[*n_word(doc.tree(), *block)]));
    if (const auto p = program_word_at(doc, offset)) return program_location({s.doc, *p, doc.typed().programs()[*p].number.value_or(0)});
    return nullptr;
}

}  // namespace kerf::lsp
