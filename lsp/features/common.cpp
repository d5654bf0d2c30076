#include "lsp/features/common.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace kerf::lsp {

namespace fs = std::filesystem;
using references::Kind;
using references::Reference;

ast::Range words_range(const ast::SyntaxTree& tree, std::uint32_t block) {
    const auto tokens = tree.block_tokens(block);
    if (tokens.empty()) {
        ast::Range r = tree.block_range(block);
        while (r.end > r.begin && (tree.text[r.end - 1] == '\n' || tree.text[r.end - 1] == '\r')) --r.end;
        return r;
    }
    return {tokens.front().begin, tree.end(tokens.back())};
}

ast::Range program_range(const Document& doc, std::uint32_t program) {
    const ast::Program& p = doc.typed().programs()[program];
    const ast::Range first = doc.tree().block_range(p.first_block);
    std::uint32_t end = first.end;
    for (std::uint32_t b = p.end_block; b-- > p.first_block;) {
        const ast::Range w = words_range(doc.tree(), b);
        if (w.end > w.begin) {
            end = w.end;
            break;
        }
    }
    return {first.begin, std::max(first.begin, end)};
}

std::optional<std::uint32_t> n_word(const ast::SyntaxTree& tree, std::uint32_t block) {
    for (std::uint32_t t = tree.block_first_token(block); t < tree.block_token_end(block); ++t)
        if (tree.tokens[t].kind == ast::TokenKind::word && tree.tokens[t].letter == 'N' && tree.tokens[t].is_number()) return t;
    return std::nullopt;
}

namespace {
bool touches(ast::Range r, std::uint32_t offset) { return r.contains(offset) || r.end == offset; }
}  // namespace

std::optional<Reference> reference_at(const Document& doc, std::uint32_t offset) {
    if (doc.tree().block_count() == 0) return std::nullopt;
    const std::uint32_t block = doc.block_at(offset);
    const auto program = references::program_of_block(doc.typed(), block);
    if (!program) return std::nullopt;
    for (Reference& r : references::block_references(doc.typed(), *program, block)) {
        const bool hit = r.kind == Kind::goto_label ? touches(r.range, offset) : touches(doc.tree().range(doc.tree().tokens[r.token]), offset);
        if (hit) return std::move(r);
    }
    return std::nullopt;
}

std::optional<std::uint32_t> label_word_at(const Document& doc, std::uint32_t offset) {
    const auto t = doc.token_at(offset);
    if (!t) return std::nullopt;
    const ast::Token& tok = doc.tree().tokens[*t];
    if (tok.kind != ast::TokenKind::word || tok.role() != ast::Role::sequence || !tok.is_number()) return std::nullopt;
    const std::uint32_t block = doc.block_at(tok.begin);
    if (n_word(doc.tree(), block) != *t) return std::nullopt;   // a second N word is no label
    return block;
}

std::optional<std::uint32_t> program_word_at(const Document& doc, std::uint32_t offset) {
    const auto t = doc.token_at(offset);
    if (!t) return std::nullopt;
    const auto& programs = doc.typed().programs();
    for (std::uint32_t p = 0; p < programs.size(); ++p)
        if (programs[p].o_token == static_cast<std::int32_t>(*t)) return p;
    return std::nullopt;
}

std::optional<ProgramTarget> program_target(const Snapshot& s, const std::shared_ptr<const Document>& from, std::int64_t number) {
    if (const auto p = references::program_numbered(from->typed(), number)) return ProgramTarget{from, *p, number};
    const std::optional<IndexedProgram> found = s.project.find_program(number, from->path());
    if (!found) return std::nullopt;
    const auto doc = s.document_at(found->file);
    if (!doc) return std::nullopt;
    // The index may be a version behind an edit: find the program by number in the document.
    const auto p = references::program_numbered(doc->typed(), number);
    if (!p) return std::nullopt;
    return ProgramTarget{doc, *p, number};
}

std::vector<LabelTarget> label_targets(const Snapshot& s, const Reference& r) {
    std::vector<LabelTarget> out;
    if (!r.value) return out;
    const references::LabelScope scope = references::label_scope(s.doc->typed(), r);
    const auto add = [&](const std::shared_ptr<const Document>& doc, std::uint32_t program) {
        if (const auto block = references::find_label(doc->typed(), program, *r.value))
            out.push_back({doc, program, *r.value, *block});
    };
    for (const std::uint32_t p : scope.programs) add(s.doc, p);
    if (scope.other_program)
        if (const auto t = program_target(s, s.doc, *scope.other_program)) add(t->doc, t->program);
    if (scope.other_callers) {
        const auto number = s.doc->typed().programs()[r.program].number;
        if (number) {
            std::set<std::pair<std::string, std::uint32_t>> seen;
            for (const CallSite& c : call_sites(s, {s.doc, r.program, *number})) {
                if (c.doc->path() == s.doc->path()) continue;   // this file's callers are in scope.programs
                if (seen.emplace(c.doc->uri(), c.ref.program).second) add(c.doc, c.ref.program);
            }
        }
    }
    return out;
}

namespace {

// Every document a workspace-wide search reads: the open ones, then the indexed files.
std::vector<std::shared_ptr<const Document>> workspace_documents(const Snapshot& s, const std::string& needle) {
    std::vector<std::shared_ptr<const Document>> out;
    std::set<fs::path> seen;
    for (const auto& [uri, doc] : s.open) {
        seen.insert(doc->path());
        out.push_back(doc);
    }
    for (const fs::path& path : s.project.files()) {
        if (s.cancelled()) break;
        if (!seen.insert(path).second) continue;
        const std::optional<std::string> text = s.project.read(path);
        if (!text || text->find(needle) == std::string::npos) continue;   // no call can name the number
        out.push_back(Document::open(path_to_uri(path), path, 0, *text, s.project.resolve(path, *text)));
    }
    return out;
}

bool reaches(const Snapshot& s, const std::shared_ptr<const Document>& from, std::int64_t number, const ProgramTarget& target) {
    const auto t = program_target(s, from, number);
    return t && t->doc->path() == target.doc->path() && t->program == target.program;
}

}  // namespace

std::vector<CallSite> call_sites(const Snapshot& s, const ProgramTarget& target) {
    std::vector<CallSite> out;
    for (const auto& doc : workspace_documents(s, std::to_string(target.number))) {
        if (s.cancelled()) break;
        for (Reference& r : references::file_references(doc->typed())) {
            if (references::is_label(r.kind) || r.value != target.number) continue;
            if (reaches(s, doc, target.number, target)) out.push_back({doc, std::move(r)});
        }
    }
    return out;
}

std::vector<CallSite> label_references(const Snapshot& s, const LabelTarget& target) {
    std::vector<CallSite> out;
    for (Reference& r : references::file_references(target.doc->typed())) {
        if (!references::is_label(r.kind) || r.value != target.label) continue;
        const references::LabelScope scope = references::label_scope(target.doc->typed(), r);
        if (std::find(scope.programs.begin(), scope.programs.end(), target.program) != scope.programs.end())
            out.push_back({target.doc, std::move(r)});
    }
    // M98 P<this program> Q<label> in other files.
    const auto number = target.doc->typed().programs()[target.program].number;
    if (!number) return out;
    const ProgramTarget program{target.doc, target.program, *number};
    for (const auto& doc : workspace_documents(s, std::to_string(*number))) {
        if (doc->path() == target.doc->path() || s.cancelled()) continue;
        for (Reference& r : references::file_references(doc->typed()))
            if (r.kind == Kind::call_label && r.value == target.label && r.label_program == *number && reaches(s, doc, *number, program))
                out.push_back({doc, std::move(r)});
    }
    return out;
}

Named named_at(const Snapshot& s, std::uint32_t offset) {
    const Document& doc = s.document();
    Named out;
    if (const auto r = reference_at(doc, offset)) {
        if (references::is_label(r->kind)) {
            const std::vector<LabelTarget> targets = label_targets(s, *r);
            if (!targets.empty()) out.label = targets.front();
        } else if (r->value) {
            out.program = program_target(s, s.doc, *r->value);
        }
        return out;
    }
    if (const auto block = label_word_at(doc, offset)) {
        const auto program = references::program_of_block(doc.typed(), *block);
        const ast::Token& n = doc.tree().tokens[*n_word(doc.tree(), *block)];
        const auto value = ast::integer_value(doc.tree(), n);
        if (program && value) out.label = LabelTarget{s.doc, *program, *value, *block};
        return out;
    }
    if (const auto p = program_word_at(doc, offset); p && doc.typed().programs()[*p].number)
        out.program = ProgramTarget{s.doc, *p, *doc.typed().programs()[*p].number};
    return out;
}

json::array edits_to(const Document& doc, const std::string& text) {
    const std::string& old = doc.text();
    if (old == text) return {};
    std::size_t begin = 0;
    while (begin < old.size() && begin < text.size() && old[begin] == text[begin]) ++begin;
    while (begin > 0 && old[begin - 1] != '\n') --begin;   // whole lines
    std::size_t old_end = old.size(), new_end = text.size();
    while (old_end > begin && new_end > begin && old[old_end - 1] == text[new_end - 1]) --old_end, --new_end;
    while (old_end < old.size() && old_end > 0 && old[old_end - 1] != '\n') ++old_end, ++new_end;
    json::array out;
    out.push_back(text_edit(doc, {static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(old_end)}, text.substr(begin, new_end - begin)));
    return out;
}

std::string duration(double seconds) {
    if (!std::isfinite(seconds)) return "?";
    if (seconds < 60) return fmt::format("{:.1f} s", seconds);
    const auto total = static_cast<long>(std::lround(seconds));
    if (total < 3600) return fmt::format("{}:{:02} min", total / 60, total % 60);
    return fmt::format("{}:{:02}:{:02} h", total / 3600, total / 60 % 60, total % 60);
}

std::string number_text(double v) {
    if (v == 0) return "0";
    std::string s = fmt::format("{:.4f}", v);
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s == "-0" ? "0" : s;
}

std::string description(const dialects::CodeInfo& info, const std::string& language) {
    return language == "ru" && !info.ru.empty() ? info.ru : info.en;
}

}  // namespace kerf::lsp
