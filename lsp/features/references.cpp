// Find references: every jump to a label (GOTO, G70–G73 P/Q, M98 Q, M99 P, M97 P; M98 P Q from
// other files) or every call of a program (M98 P in both forms, G65/G66 P) across the workspace,
// through the one resolver (references/references.hpp) and the program index. A call counts only
// when it reaches this very program (a file with its own O1000 keeps its calls).
#include "lsp/features/common.hpp"

namespace kerf::lsp {

json::value references(const Snapshot& s, ast::Position at, bool include_declaration) {
    const Named named = named_at(s, s.document().offset(at));
    json::array out;
    if (named.label) {
        const LabelTarget& t = *named.label;
        if (references::find_label(t.doc->typed(), t.program, t.label) != t.block) return out;   // a shadowed duplicate N
        if (include_declaration) out.push_back(label_location(t));
        for (const CallSite& c : label_references(s, t)) out.push_back(location_json(*c.doc, reference_range(c.ref)));
    } else if (named.program) {
        if (include_declaration) out.push_back(program_location(*named.program));
        for (const CallSite& c : call_sites(s, *named.program)) out.push_back(location_json(*c.doc, reference_range(c.ref)));
    } else {
        return nullptr;
    }
    return out;
}

}  // namespace kerf::lsp
