// Call hierarchy over subprogram and macro calls (M98 P, G65/G66 P): a program is an item; its
// incoming calls are the programs across the workspace whose calls reach it, its outgoing calls
// the programs its own calls reach (through the one resolver and the program index).
#include <fmt/format.h>

#include <map>

#include "lsp/features/common.hpp"

namespace kerf::lsp {

namespace {

json::object item(const ProgramTarget& t) {
    const Document& doc = *t.doc;
    const ast::Program& p = doc.typed().programs()[t.program];
    std::string comment;
    for (const IndexedProgram& i : ProjectSeam::programs_of(doc.path(), doc.typed()))
        if (i.program_index == t.program) comment = i.comment;
    const ast::Range selection = p.o_token >= 0 ? doc.tree().range(doc.tree().tokens[static_cast<std::size_t>(p.o_token)]) : words_range(doc.tree(), p.first_block);
    return {{"name", fmt::format("O{:04}", t.number)},
            {"kind", symbol_kind::function},
            {"detail", comment.empty() ? doc.path().filename().string() : comment},
            {"uri", doc.uri()},
            {"range", range_json(doc, program_range(doc, t.program))},
            {"selectionRange", range_json(doc, selection)},
            {"data", json::object{{"number", t.number}, {"uri", doc.uri()}}}};
}

// The program an item names, found again from its data (the document may have changed since).
std::optional<ProgramTarget> target_of(const Snapshot& s, const json::object& it) {
    const json::value* number = find_path(it, {"data", "number"});
    if (!number || !number->is_int64()) return std::nullopt;
    const auto p = references::program_numbered(s.doc->typed(), number->as_int64());
    if (!p) return std::nullopt;
    return ProgramTarget{s.doc, *p, number->as_int64()};
}

Snapshot snapshot_of(const OpenDocuments& open, ProjectSeam& project, const json::object& it) {
    const json::value* uri = find_path(it, {"uri"});
    if (!uri || !uri->is_string()) throw RpcError(error_code::invalid_params, "the item has no uri");
    std::shared_ptr<const Document> doc;
    if (const auto found = open.find(std::string(uri->as_string())); found != open.end()) doc = found->second;
    Snapshot probe{nullptr, nullptr, open, project};
    if (!doc) doc = probe.document_at(uri_to_path(std::string_view(uri->as_string())));
    if (!doc) throw RpcError(error_code::request_failed, "the item's file cannot be read");
    return Snapshot{doc, nullptr, open, project};
}

}  // namespace

json::value prepare_call_hierarchy(const Snapshot& s, ast::Position at) {
    const Document& doc = s.document();
    const std::uint32_t offset = doc.offset(at);
    const Named named = named_at(s, offset);
    if (named.program) return json::array{item(*named.program)};
    // Anywhere else inside a numbered program: that program.
    const auto p = references::program_of_block(doc.typed(), doc.block_at(offset));
    if (!p || !doc.typed().programs()[*p].number) return nullptr;
    return json::array{item({s.doc, *p, *doc.typed().programs()[*p].number})};
}

json::value incoming_calls(const OpenDocuments& open, ProjectSeam& project, const json::object& it) {
    const Snapshot s = snapshot_of(open, project, it);
    const auto target = target_of(s, it);
    json::array out;
    if (!target) return out;
    std::map<std::pair<std::string, std::uint32_t>, std::pair<json::object, json::array>> by_caller;
    for (const CallSite& c : call_sites(s, *target)) {
        const auto number = c.doc->typed().programs()[c.ref.program].number;
        auto& entry = by_caller[{c.doc->uri(), c.ref.program}];
        if (entry.first.empty()) {
            entry.first = number ? item({c.doc, c.ref.program, *number})
                                 : json::object{{"name", c.doc->path().filename().string()}, {"kind", symbol_kind::file}, {"uri", c.doc->uri()},
                                                {"range", range_json(*c.doc, program_range(*c.doc, c.ref.program))},
                                                {"selectionRange", range_json(*c.doc, words_range(c.doc->tree(), c.doc->typed().programs()[c.ref.program].first_block))}};
        }
        entry.second.push_back(range_json(*c.doc, c.ref.range));
    }
    for (auto& [key, entry] : by_caller) out.push_back(json::object{{"from", std::move(entry.first)}, {"fromRanges", std::move(entry.second)}});
    return out;
}

json::value outgoing_calls(const OpenDocuments& open, ProjectSeam& project, const json::object& it) {
    const Snapshot s = snapshot_of(open, project, it);
    const auto source = target_of(s, it);
    json::array out;
    if (!source) return out;
    std::map<std::pair<std::string, std::uint32_t>, std::pair<json::object, json::array>> by_callee;
    const ast::Program& p = s.doc->typed().programs()[source->program];
    for (std::uint32_t b = p.first_block; b < p.end_block; ++b)
        for (const references::Reference& r : references::block_references(s.doc->typed(), source->program, b)) {
            if (references::is_label(r.kind) || !r.value) continue;
            const auto callee = program_target(s, s.doc, *r.value);
            if (!callee) continue;
            auto& entry = by_callee[{callee->doc->uri(), callee->program}];
            if (entry.first.empty()) entry.first = item(*callee);
            entry.second.push_back(range_json(*s.doc, r.range));
        }
    for (auto& [key, entry] : by_callee) out.push_back(json::object{{"to", std::move(entry.first)}, {"fromRanges", std::move(entry.second)}});
    return out;
}

}  // namespace kerf::lsp
