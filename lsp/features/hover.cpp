// Hover: what is under the cursor, in the document's language (en/ru), and what the dry run saw
// at the block.
//
//   G/M code     its dialect's description, modal group, the words it takes, what the same
//                function is called in the other G-code systems (and what this number means
//                there), notes and the reference section
//   address word its meaning in this block (U in a G71 first block vs a motion block: words.hpp),
//                and the value in mm and in increments when it has no decimal point
//   #variable    its kind (local, common, system and what that system number means), and its
//                value after the block in the dry run
//   M98 P/G65 P  the called program's first comment and file; a jump: the block it lands on
//   diagnostics  the rule's explanation (what, why) for each finding under the cursor
//   dry run      position, modal codes, F, S, T after the block, the first time it ran
//
// The structured `kerf explain` of the dialects helper replaces code_text() once it is on main.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <span>

#include "analyzer/registry.hpp"
#include "lsp/features/common.hpp"
#include "lsp/features/variables.hpp"
#include "lsp/features/words.hpp"

namespace kerf::lsp {

namespace {

// Dialects of the same family in other G-code systems: "fanuc-lathe-a" → "fanuc-lathe-b", "-c"
// (the registry's ids that differ only in the one-letter system suffix).
std::string family(std::string_view id) {
    if (id.size() > 2 && id[id.size() - 2] == '-') return std::string(id.substr(0, id.size() - 2));
    return {};
}

std::string other_systems(const FileSettings& settings, const dialects::CodeInfo& info, bool ru) {
    const std::string mine = family(settings.dialect->id);
    if (mine.empty() || info.function.empty()) return {};
    std::vector<std::string> lines;
    for (const std::string& id : settings.registry->ids()) {
        if (id == settings.dialect->id || family(id) != mine) continue;
        const dialects::Dialect* other = settings.registry->find(id);
        const std::vector<const dialects::CodeInfo*> same = other->codes_with_function(info.function);
        std::string line = fmt::format("{} ({}): ", id, char(std::toupper(static_cast<unsigned char>(id.back()))));
        line += same.empty() ? (ru ? "нет такой функции" : "no such function") : same.front()->spelling;
        const dialects::CodeInfo* here = other->code(info.letter, info.key);
        if (here && here->function != info.function)
            line += fmt::format(fmt::runtime(ru ? "; {} там — {}" : "; {} there is {}"), info.spelling, description(*here, ru ? "ru" : "en"));
        lines.push_back(line);
    }
    if (lines.empty()) return {};
    std::string out = ru ? "В других системах G-кодов:" : "In the other G-code systems:";
    for (const std::string& l : lines) out += "\n- " + l;
    return out;
}

std::string code_text(const FileSettings& settings, const dialects::CodeInfo& info) {
    const bool ru = settings.language == "ru";
    std::string out = fmt::format("**{}** — {}", info.spelling, description(info, settings.language));
    std::string group;
    if (info.group == "00") group = ru ? "группа 00 (действует в одном кадре)" : "group 00 (one-shot)";
    else if (!info.group.empty()) group = fmt::format(fmt::runtime(ru ? "группа {}{}" : "group {}{}"), info.group, info.modal ? (ru ? ", модальный" : ", modal") : "");
    if (info.power_on_default) group += ru ? ", при включении" : ", power-on default";
    out += fmt::format("\n\n`{}`{}", info.function.empty() ? std::string_view("-") : info.function.name(), group.empty() ? "" : " · " + group);
    if (!info.words.empty()) {
        std::string words;
        for (const std::string& w : info.words) words += (words.empty() ? "" : " ") + w;
        out += fmt::format("\n\n{}: {}", ru ? "Адреса" : "Words", words);
        if (!info.parameter_letters.empty()) out += fmt::format(fmt::runtime(ru ? " · данные (не оси): {}" : " · data, not axis moves: {}"), info.parameter_letters);
    }
    if (const std::string others = other_systems(settings, info, ru); !others.empty()) out += "\n\n" + others;
    if (info.availability != dialects::Availability::standard && !info.availability_note.empty())
        out += fmt::format("\n\n{}: {}", ru ? "Наличие" : "Availability", info.availability_note);
    if (!info.notes.empty()) out += "\n\n" + info.notes;
    if (!info.reference.empty()) out += fmt::format("\n\n*{}: {}*", ru ? "Справочник" : "Reference", info.reference);
    return out;
}

const dialects::CodeInfo* code_of(const Document& doc, const ast::Token& t) {
    if (t.role() != ast::Role::g_code && t.role() != ast::Role::m_code) return nullptr;
    if (!t.is_number()) return nullptr;
    const auto key = dialects::code_key(doc.tree().number_value(t));
    return key ? doc.dialect().code(t.letter, *key) : nullptr;
}

// The innermost `#n` around `offset`, with its range: among the expression nodes of the block there
// (the tree keeps them in text order from block to block).
std::optional<std::pair<std::int64_t, ast::Range>> variable_at(const Document& doc, std::uint32_t offset) {
    const ast::SyntaxTree& tree = doc.tree();
    if (tree.block_count() == 0) return std::nullopt;
    const ast::Range block = tree.block_range(doc.block_at(offset));
    const auto first = std::partition_point(tree.exprs.begin(), tree.exprs.end(), [&](const ast::Expr& e) { return e.begin < block.begin; });
    const auto last = std::partition_point(first, tree.exprs.end(), [&](const ast::Expr& e) { return e.begin < block.end; });
    std::optional<std::pair<std::int64_t, ast::Range>> best;
    for (const ast::Expr& e : std::span<const ast::Expr>(first, last)) {
        if (e.kind != ast::ExprKind::variable || e.a < 0 || !(e.range().contains(offset) || e.end == offset)) continue;
        const ast::Expr& n = tree.exprs[static_cast<std::size_t>(e.a)];
        if (n.kind != ast::ExprKind::number) continue;
        const double v = tree.number_value(n);
        if (v != std::floor(v)) continue;
        if (!best || e.range().size() < best->second.size()) best = std::make_pair(static_cast<std::int64_t>(v), e.range());
    }
    return best;
}

std::string reference_text(const Snapshot& s, const references::Reference& r, bool ru) {
    if (references::is_label(r.kind)) {
        std::string out;
        for (const LabelTarget& t : label_targets(s, r)) {
            const ast::Position p = t.doc->lines().utf8(t.doc->tree().blocks[t.block].begin);
            const std::string file = t.doc->path() == s.doc->path() ? "" : t.doc->path().filename().string() + " ";
            out += fmt::format("{}N{} → `{}` ({}{} {})", out.empty() ? "" : "\n\n", t.label, clip(t.doc->tree().slice(words_range(t.doc->tree(), t.block)), 80),
                               file, ru ? "строка" : "line", p.line + 1);
        }
        if (out.empty() && r.value) out = fmt::format(fmt::runtime(ru ? "N{}: такого кадра нет" : "N{}: no such block"), *r.value);
        return out;
    }
    if (!r.value) return ru ? "номер программы вычисляется при выполнении" : "the program number is computed at run time";
    const auto t = program_target(s, s.doc, *r.value);
    if (!t) return fmt::format(fmt::runtime(ru ? "O{:04}: программа не найдена ни в файле, ни в рабочей области" : "O{:04}: not in this file or the workspace"), *r.value);
    const auto indexed = ProjectSeam::programs_of(t->doc->path(), t->doc->typed());
    std::string comment;
    for (const IndexedProgram& p : indexed)
        if (p.program_index == t->program) comment = p.comment;
    std::string out = fmt::format("**O{:04}**{}", t->number, comment.empty() ? "" : " — " + comment);
    if (r.kind == references::Kind::subprogram && r.repeats > 1) out += fmt::format(fmt::runtime(ru ? " · {} раз" : " · {} times"), r.repeats);
    out += fmt::format("\n\n{}: `{}`", ru ? "Файл" : "File", t->doc->path() == s.doc->path() ? (ru ? "этот файл" : "this file") : t->doc->path().string());
    return out;
}

// The variable's value after its block in the dry run, the first time the block ran.
std::string variable_value(const Snapshot& s, std::uint32_t block, ast::Range range, bool ru) {
    const DryRun* run = s.run();
    const std::vector<MacroValue>* values = run ? run->values(block) : nullptr;
    if (!values) return {};
    for (const MacroValue& v : *values)
        if (v.variable >= 0 && v.range == range)
            return fmt::format(fmt::runtime(ru ? "Значение после этого кадра в пробном прогоне: **{}**" : "Value after this block in the dry run: **{}**"),
                               v.vacant ? (ru ? "пусто (vacant)" : "vacant") : number_text(v.value));
    return {};
}

std::string state_text(const Snapshot& s, std::uint32_t block, bool ru) {
    const DryRun* run = s.run();
    if (!run) return {};
    const BlockState* st = run->state(block);
    if (!st) return {};
    const dialects::LexicalRules& lex = s.doc->dialect().lexical;
    std::string position;
    for (std::size_t a = 0; a < interpreter::kAxisCount; ++a) {
        const char L = interpreter::kAxisLetters[a];
        if (!lex.is_axis(L) && !(L == 'X' || L == 'Z')) continue;
        position += fmt::format("{}{} {}", position.empty() ? "" : " · ", L, number_text(st->position[a]));
    }
    std::string out = fmt::format(fmt::runtime(ru ? "**Пробный прогон после этого кадра**{}:\n\n{}" : "**Dry run after this block**{}:\n\n{}"),
                                  st->runs > 1 ? fmt::format(fmt::runtime(ru ? " (первый из {} проходов)" : " (the first of {} runs)"), st->runs) : "", position);
    // T as the dialect writes it: tool and offset (`T0101`) or the tool number alone (`T5`).
    const std::string tool = lex.tool_word == "mmnn" ? fmt::format("T{:02}{:02}", st->tool, st->tool_offset) : fmt::format("T{}", st->tool);
    out += fmt::format(" · F {} · S {} · {}", number_text(st->feed), number_text(st->spindle), tool);
    out += fmt::format("\n\n{}: {}", ru ? "Модальные" : "Modal", run->modal_texts[st->modal]);
    return out;
}

std::string finding_text(const analyzer::Finding& f, bool ru) {
    std::string out = fmt::format("**{}** {} ({}): {}", f.rule, f.name, ast::to_string(f.severity), f.message);
    if (!f.hint.empty()) out += fmt::format("\n\n{}: {}", ru ? "Как исправить" : "Fix", f.hint);
    if (const analyzer::Rule* rule = analyzer::builtin_rules().find(f.rule))
        out += fmt::format("\n\n{} {}\n\n*{}*", rule->docs.what, rule->docs.why, rule->docs.reference);
    return out;
}

}  // namespace

json::value hover(const Snapshot& s, ast::Position at) {
    const Document& doc = s.document();
    if (!doc.refused().empty()) return nullptr;
    const bool ru = doc.settings().language == "ru";
    const std::uint32_t offset = doc.offset(at);
    std::vector<std::string> parts;
    std::optional<ast::Range> range;
    const auto token = doc.token_at(offset);
    if (const auto v = variable_at(doc, offset)) {
        parts.push_back(fmt::format("**#{}** — {}", v->first, variable_kind(v->first, doc.settings().language)));
        if (std::string value = variable_value(s, doc.block_at(offset), v->second, ru); !value.empty()) parts.push_back(std::move(value));
        range = v->second;
    } else if (token) {
        const ast::Token& t = doc.tree().tokens[*token];
        range = doc.tree().range(t);
        if (const dialects::CodeInfo* info = code_of(doc, t)) {
            parts.push_back(code_text(doc.settings(), *info));
        } else if (t.kind == ast::TokenKind::word) {
            if (const auto r = reference_at(doc, offset)) parts.push_back(reference_text(s, *r, ru));
            if (std::string m = word_meaning(doc, *token, doc.settings().language); !m.empty()) parts.push_back(std::move(m));
            if (std::string u = value_in_units(doc, *token, doc.settings().language); !u.empty()) parts.push_back(std::move(u));
        } else if (t.kind == ast::TokenKind::statement) {
            if (const auto r = reference_at(doc, offset)) parts.push_back(reference_text(s, *r, ru));
        }
    }
    if (s.analysis)
        for (const analyzer::Finding& f : s.analysis->findings)
            if (f.range.contains(offset) || (f.range.end == offset && f.range.size() > 0)) parts.push_back(finding_text(f, ru));
    if (!parts.empty() || token) {
        if (std::string state = state_text(s, doc.block_at(offset), ru); !state.empty()) parts.push_back(std::move(state));
    }
    if (parts.empty()) return nullptr;
    std::string text;
    for (const std::string& p : parts) text += (text.empty() ? "" : "\n\n---\n\n") + p;
    json::object out{{"contents", json::object{{"kind", "markdown"}, {"value", text}}}};
    if (range) out["range"] = range_json(doc, *range);
    return out;
}

}  // namespace kerf::lsp
