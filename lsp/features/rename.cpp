// Rename a label or a program number with every reference to it.
//
// A label (N100 → N120): the block's N word and every jump to it in its program (GOTO, G70–G73
// P/Q, M98 Q, M99 P, M97 P) and M98 P Q from other files. Refused as `kerf fmt` refuses a
// renumbering (formatter/renumber.hpp): a computed label reference in the file (GOTO #1, P#2), an
// M99 P whose callers are several programs of the file, a new number that a block of the program
// already has (the jumps would change meaning), or one over N99999.
//
// A program (O1234 → O1240): the O word and every call that reaches it across the workspace, in
// files not open too, each keeping its form (M98 P31234 → M98 P31240, P0012 → P0040). Refused when
// a program of that number already exists where the calls could reach it, or a packed M98 P cannot
// hold the new number.
#include <fmt/format.h>

#include <cctype>
#include <map>

#include "formatter/renumber.hpp"
#include "lsp/features/common.hpp"

namespace kerf::lsp {

namespace {

using Edits = std::map<std::string, json::array>;   // uri → TextEdits

[[noreturn]] void refuse(const std::string& why) { throw RpcError(error_code::request_failed, why); }

std::string where(const Document& doc, std::uint32_t offset) {
    const ast::Position p = doc.lines().utf8(offset);
    return fmt::format("{}:{}", doc.path().filename().string(), p.line + 1);
}

std::int64_t parse_number(std::string name, char letter) {
    while (!name.empty() && name.front() == ' ') name.erase(0, 1);
    while (!name.empty() && name.back() == ' ') name.pop_back();
    if (!name.empty() && std::toupper(static_cast<unsigned char>(name.front())) == letter) name.erase(0, 1);
    if (name.empty() || name.size() > 9 || !std::all_of(name.begin(), name.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
        refuse(fmt::format("'{}' is not a {} number: give digits, like {}120", name, letter == 'N' ? "sequence" : "program", letter));
    return std::stoll(name);
}

// The digits of a word's value for `number`, keeping leading zeros ("0100" → 120: "0120").
std::string same_width(std::string_view written, std::int64_t number) {
    const bool padded = written.size() > 1 && written.front() == '0' &&
                        std::all_of(written.begin(), written.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    return fmt::format("{:0{}}", number, padded ? written.size() : 0);
}

void add(Edits& edits, const Document& doc, ast::Range r, const std::string& text) { edits[doc.uri()].push_back(text_edit(doc, r, text)); }

json::value workspace_edit(Edits edits) {
    json::object changes;
    for (auto& [uri, list] : edits) changes[uri] = std::move(list);
    return json::object{{"changes", std::move(changes)}};
}

// A label reference of the file that kerf cannot follow: renaming would miss it.
void refuse_computed(const Document& doc, std::int64_t label) {
    for (const references::Reference& r : references::file_references(doc.typed())) {
        if (!references::is_label(r.kind)) continue;
        if (!r.value)
            refuse(fmt::format("cannot rename N{}: '{}' at {} is computed, so the block it jumps to is known only at run time",
                               label, doc.tree().slice(r.kind == references::Kind::goto_label ? r.range : doc.tree().range(doc.tree().tokens[r.token])),
                               where(doc, r.range.begin)));
    }
}

json::value rename_label(const Snapshot& s, const LabelTarget& t, std::int64_t number) {
    const Document& doc = *t.doc;
    if (references::find_label(doc.typed(), t.program, t.label) != t.block)
        refuse(fmt::format("N{} here is a second block with that number: jumps reach the first one", t.label));
    if (number > formatter::kMaxSequenceNumber) refuse(fmt::format("N{} is over N{}", number, formatter::kMaxSequenceNumber));
    if (number == t.label) return workspace_edit({});
    if (const auto clash = references::find_label(doc.typed(), t.program, number))
        refuse(fmt::format("N{} is already on a block of this program ({}): the jumps would change meaning", number,
                           where(doc, doc.tree().block_range(*clash).begin)));
    refuse_computed(doc, t.label);
    Edits edits;
    const ast::Token& n = doc.tree().tokens[*n_word(doc.tree(), t.block)];
    add(edits, doc, doc.tree().value_range(n), same_width(doc.tree().value_spelling(n), number));
    for (const CallSite& c : label_references(s, t)) {
        if (c.ref.kind == references::Kind::return_label && references::label_scope(c.doc->typed(), c.ref).programs.size() > 1)
            refuse(fmt::format("cannot rename N{}: M99 P{} at {} returns to several programs of the file", t.label, t.label,
                               where(*c.doc, c.ref.range.begin)));
        const auto text = references::respell(c.doc->tree(), c.ref, number);
        if (!text) refuse(fmt::format("cannot rename N{}: the reference at {} cannot hold {}", t.label, where(*c.doc, c.ref.range.begin), number));
        add(edits, *c.doc, c.ref.range, *text);
    }
    return workspace_edit(std::move(edits));
}

json::value rename_program(const Snapshot& s, const ProgramTarget& t, std::int64_t number) {
    const Document& doc = *t.doc;
    if (number < 1 || number > 99999999) refuse(fmt::format("O{} is not a program number (1 to 99999999)", number));
    if (number == t.number) return workspace_edit({});
    if (const auto p = references::program_numbered(doc.typed(), number))
        refuse(fmt::format("O{:04} is already a program of this file ({})", number, where(doc, program_range(doc, *p).begin)));
    if (const auto other = s.project.find_program(number, doc.path()))
        refuse(fmt::format("O{:04} already exists in {}: calls would reach one or the other", number, other->file.string()));
    const ast::Program& p = doc.typed().programs()[t.program];
    if (p.o_token < 0) refuse("the program has no O word to rename");
    Edits edits;
    const ast::Token& o = doc.tree().tokens[static_cast<std::size_t>(p.o_token)];
    add(edits, doc, doc.tree().value_range(o), same_width(doc.tree().value_spelling(o), number));
    for (const CallSite& c : call_sites(s, t)) {
        const auto text = references::respell(c.doc->tree(), c.ref, number);
        if (!text)
            refuse(fmt::format("cannot rename O{:04}: M98 P{} at {} packs the program into four digits; O{} does not fit", t.number,
                               c.doc->tree().slice(c.ref.range), where(*c.doc, c.ref.range.begin), number));
        add(edits, *c.doc, c.ref.range, *text);
    }
    return workspace_edit(std::move(edits));
}

}  // namespace

json::value prepare_rename(const Snapshot& s, ast::Position at) {
    const Document& doc = s.document();
    const std::uint32_t offset = doc.offset(at);
    const Named named = named_at(s, offset);
    ast::Range range{};
    std::string placeholder;
    if (const auto r = reference_at(doc, offset)) {
        range = r->range;
        if (named.label) placeholder = std::to_string(named.label->label);
        else if (named.program) placeholder = std::to_string(named.program->number);
    } else if (named.label) {
        range = doc.tree().value_range(doc.tree().tokens[*n_word(doc.tree(), named.label->block)]);
        placeholder = std::to_string(named.label->label);
    } else if (named.program) {
        const ast::Program& p = doc.typed().programs()[named.program->program];
        range = doc.tree().value_range(doc.tree().tokens[static_cast<std::size_t>(p.o_token)]);
        placeholder = std::to_string(named.program->number);
    }
    if (placeholder.empty()) return nullptr;
    return json::object{{"range", range_json(doc, range)}, {"placeholder", placeholder}};
}

json::value rename(const Snapshot& s, ast::Position at, const std::string& new_name) {
    const Named named = named_at(s, s.document().offset(at));
    if (named.label) return rename_label(s, *named.label, parse_number(new_name, 'N'));
    if (named.program) return rename_program(s, *named.program, parse_number(new_name, 'O'));
    refuse("there is no label (N) or program number (O) here to rename");
}

}  // namespace kerf::lsp
