// Inlay hints from the dry run of the same document version, at the end of a block's words:
//
//   - the absolute end point of a block that moves incrementally (U/W in system A, or any axis word
//     under the incremental-programming code, G91): "→ X40 Z-12.5";
//   - a block that cuts in several moves (a canned cycle, a direct-drawing corner; not a dog-leg
//     rapid): its feed moves, rapids and time: "⟳ 14 feed · 9 rapid · 0:42 min";
//   - the value of a macro expression the first time its block ran: after a word's expression
//     (X[#1+2.] "= 7") and after an assignment (#2=#1*2 "= 10").
#include <fmt/format.h>

#include "dialects/functions.hpp"
#include "lsp/features/common.hpp"

namespace kerf::lsp {

namespace {

json::object hint(const Document& doc, std::uint32_t offset, std::string label, std::string tooltip) {
    return {{"position", to_json(doc.position(offset))},
            {"label", std::move(label)},
            {"paddingLeft", true},
            {"tooltip", std::move(tooltip)}};
}

// The block moves incrementally: an incremental letter, or an axis word while the incremental
// code is in force (the dry run's modal text names the active codes).
bool incremental(const Document& doc, const ast::BlockView& view, const DryRun& run, const BlockState& st) {
    bool axis = false;
    for (const ast::AxisWord& a : view.axis_words()) {
        if (a.incremental) return true;
        axis = true;
    }
    if (!axis) return false;
    for (const dialects::CodeInfo* c : doc.dialect().codes_with_function(dialects::functions::incremental_programming)) {
        const std::string& modal = run.modal_texts[st.modal];
        const std::size_t at = modal.find(c->spelling);
        if (at != std::string::npos && (at + c->spelling.size() == modal.size() || modal[at + c->spelling.size()] == ' ')) return true;
    }
    return false;
}

std::string value_text(const MacroValue& v, bool ru) { return v.vacant ? (ru ? "= пусто" : "= vacant") : "= " + number_text(v.value); }

// The values of a block's expression words and assignments (DryRun::macro_values).
void macro_hints(const Document& doc, const ast::BlockView& view, const std::vector<MacroValue>& values, bool ru, json::array& out) {
    const ast::SyntaxTree& tree = doc.tree();
    for (const MacroValue& v : values)
        if (v.variable < 0)
            out.push_back(hint(doc, v.range.end, value_text(v, ru), ru ? "значение выражения в пробном прогоне" : "the expression's value in the dry run"));
    for (const std::uint32_t s : view.statements()) {
        const ast::Statement& st = tree.statements[tree.tokens[s].payload];
        if (st.kind != ast::StatementKind::assign || st.target < 0) continue;
        const ast::Range target = tree.exprs[static_cast<std::size_t>(st.target)].range();
        for (const MacroValue& v : values)
            if (v.variable >= 0 && v.range == target)
                out.push_back(hint(doc, st.range.end, value_text(v, ru),
                                   fmt::format(fmt::runtime(ru ? "#{} после этого кадра в пробном прогоне" : "#{} after this block in the dry run"), v.variable)));
    }
}

}  // namespace

json::value inlay_hints(const Snapshot& s, std::pair<ast::Position, ast::Position> range) {
    const Document& doc = s.document();
    json::array out;
    const DryRun* run = s.run();
    if (!run || !doc.refused().empty()) return out;
    const bool ru = doc.settings().language == "ru";
    const std::uint32_t first = doc.block_at(doc.offset(range.first));
    const std::uint32_t last = std::min<std::uint32_t>(static_cast<std::uint32_t>(doc.tree().block_count()), doc.block_at(doc.offset(range.second)) + 1);
    const dialects::LexicalRules& lex = doc.dialect().lexical;
    for (std::uint32_t b = first; b < last; ++b) {
        const BlockState* st = run->state(b);
        if (!st) continue;
        const ast::BlockView view = doc.typed().block(b);
        const std::uint32_t end = words_range(doc.tree(), b).end;
        if (incremental(doc, view, *run, *st)) {
            std::string label = "→";
            for (const ast::AxisWord& a : view.axis_words()) {
                if (label.find(a.axis) != std::string::npos) continue;
                const auto axis = interpreter::axis_of_letter(a.axis);
                if (!axis) continue;
                label += fmt::format(" {}{}", a.axis, number_text(st->position[static_cast<std::size_t>(*axis)]));
            }
            out.push_back(hint(doc, end, label,
                               ru ? fmt::format("конечная точка в абсолютных координатах заготовки{}", lex.is_diameter('X') ? " (X на диаметр)" : "")
                                  : fmt::format("end point in absolute work coordinates{}", lex.is_diameter('X') ? " (X as diameter)" : "")));
        }
        if (const std::vector<MacroValue>* values = run->values(b)) macro_hints(doc, view, *values, ru, out);
        // A block that cuts in several moves (a cycle, a corner): not a dog-leg rapid or a G28.
        if (const auto m = run->motion.find(b); m != run->motion.end() && (m->second.feeds >= 2 || (m->second.feeds >= 1 && m->second.rapids >= 2))) {
            const BlockMotion& mm = m->second;
            out.push_back(hint(doc, end,
                               fmt::format(fmt::runtime(ru ? "⟳ {} рабочих · {} ускоренных · {}" : "⟳ {} feed · {} rapid · {}"), mm.feeds, mm.rapids, duration(mm.time_s)),
                               fmt::format(fmt::runtime(ru ? "ход инструмента {} мм за {}; по пробному прогону" : "{} mm of tool path in {}, from the dry run"),
                                           number_text(mm.length_mm), duration(mm.time_s))));
        }
    }
    return out;
}

}  // namespace kerf::lsp
