// Symbols. Document: each program (O number and its first comment) with, as children, its labels
// that something jumps to (all its labels when it has at most 500: a CAM program numbers every
// block) and its tool changes. Workspace: every O number of the workspace index and of the open
// documents, and the jump targets of the open documents, filtered by the query (case-insensitive,
// on "O1234", the number, or the comment).
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <set>

#include "dialects/functions.hpp"
#include "lsp/features/common.hpp"

namespace kerf::lsp {

namespace {

constexpr std::size_t kAllLabelsUpTo = 500;
constexpr std::size_t kMaxWorkspaceSymbols = 2000;

std::string program_name(const ast::Program& p) { return p.number ? fmt::format("O{:04}", *p.number) : std::string("(no O number)"); }

json::object symbol(const Document& doc, std::string name, std::string detail, int kind, ast::Range range, ast::Range selection) {
    return {{"name", std::move(name)},
            {"detail", std::move(detail)},
            {"kind", kind},
            {"range", range_json(doc, range)},
            {"selectionRange", range_json(doc, selection)}};
}

// Per program, the labels that something in the file jumps to.
std::vector<std::set<std::int64_t>> targets(const Document& doc) {
    std::vector<std::set<std::int64_t>> out(doc.typed().programs().size());
    for (const references::Reference& r : references::file_references(doc.typed())) {
        if (!references::is_label(r.kind) || !r.value) continue;
        for (const std::uint32_t p : references::label_scope(doc.typed(), r).programs) out[p].insert(*r.value);
    }
    return out;
}

bool tool_change(const ast::BlockView& view) {
    return view.has_code('M', dialects::functions::tool_change) || view.word('T').has_value();
}

bool contains_folded(const std::string& haystack, const std::string& needle) {
    const auto it = std::search(haystack.begin(), haystack.end(), needle.begin(), needle.end(),
                                [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b)); });
    return it != haystack.end();
}

}  // namespace

json::value document_symbols(const Snapshot& s) {
    const Document& doc = s.document();
    const ast::SyntaxTree& tree = doc.tree();
    json::array out;
    if (!doc.refused().empty()) return out;
    const auto indexed = ProjectSeam::programs_of(doc.path(), doc.typed());
    const auto& programs = doc.typed().programs();
    const auto jump_targets = targets(doc);
    for (std::uint32_t p = 0; p < programs.size(); ++p) {
        const ast::Program& prog = programs[p];
        const ast::Range range = program_range(doc, p);
        const ast::Range selection = prog.o_token >= 0 ? tree.range(tree.tokens[static_cast<std::size_t>(prog.o_token)]) : words_range(tree, prog.first_block);
        std::string comment;
        for (const IndexedProgram& i : indexed)
            if (i.program_index == p) comment = i.comment;
        json::object sym = symbol(doc, program_name(prog), comment, symbol_kind::function, range, selection);
        const std::set<std::int64_t>& jumped = jump_targets[p];
        std::size_t labels = 0;
        for (std::uint32_t b = prog.first_block; b < prog.end_block; ++b) labels += n_word(tree, b).has_value();
        json::array children;
        std::set<std::int64_t> listed;
        for (std::uint32_t b = prog.first_block; b < prog.end_block; ++b) {
            const ast::BlockView view = doc.typed().block(b);
            const ast::Range words = words_range(tree, b);
            if (const auto n = n_word(tree, b)) {
                const auto v = ast::integer_value(tree, tree.tokens[*n]);
                if (v && (labels <= kAllLabelsUpTo || jumped.count(*v)) && listed.insert(*v).second)
                    children.push_back(symbol(doc, fmt::format("N{}", *v), std::string(clip(tree.slice(words), 60)),
                                              jumped.count(*v) ? symbol_kind::key : symbol_kind::number, words, tree.range(tree.tokens[*n])));
            }
            if (tool_change(view)) {
                const auto t = view.word('T');
                const ast::Range name_range = t ? tree.range(tree.tokens[*t]) : words;
                std::string detail;
                for (const std::uint32_t c : view.comments()) detail = std::string(tree.spelling(tree.tokens[c]));
                children.push_back(symbol(doc, t ? std::string(tree.spelling(tree.tokens[*t])) : std::string("tool change"), detail,
                                          symbol_kind::event, words, name_range));
            }
        }
        if (!children.empty()) sym["children"] = std::move(children);
        out.push_back(std::move(sym));
    }
    return out;
}

json::value workspace_symbols(const OpenDocuments& open, ProjectSeam& project, const std::string& query) {
    json::array out;
    std::set<std::filesystem::path> open_paths;
    const auto matches = [&](const std::string& name, const std::string& detail) {
        return query.empty() || contains_folded(name, query) || contains_folded(detail, query);
    };
    for (const auto& [uri, doc] : open) {
        open_paths.insert(doc->path());
        if (!doc->refused().empty()) continue;
        for (const IndexedProgram& p : ProjectSeam::programs_of(doc->path(), doc->typed())) {
            const std::string name = fmt::format("O{:04}", p.number);
            if (matches(name, p.comment) && out.size() < kMaxWorkspaceSymbols)
                out.push_back(json::object{{"name", name}, {"kind", symbol_kind::function}, {"containerName", p.comment},
                                           {"location", location_json(*doc, {p.begin, p.begin})}});
        }
        const auto jump_targets = targets(*doc);
        for (std::uint32_t prog = 0; prog < doc->typed().programs().size(); ++prog) {
            const auto& pr = doc->typed().programs()[prog];
            for (const std::int64_t label : jump_targets[prog]) {
                const auto block = references::find_label(doc->typed(), prog, label);
                if (!block) continue;
                const std::string name = fmt::format("N{}", label);
                const std::string container = program_name(pr);
                if (matches(name, container) && out.size() < kMaxWorkspaceSymbols)
                    out.push_back(json::object{{"name", name}, {"kind", symbol_kind::key}, {"containerName", container},
                                               {"location", location_json(*doc, words_range(doc->tree(), *block))}});
            }
        }
    }
    for (const IndexedProgram& p : project.all_programs()) {
        if (open_paths.count(p.file) || out.size() >= kMaxWorkspaceSymbols) continue;
        const std::string name = fmt::format("O{:04}", p.number);
        if (!matches(name, p.comment)) continue;
        // Positions need the file's lines: read it (only the matching ones).
        const std::optional<std::string> text = project.read(p.file);
        if (!text) continue;
        const ast::LineIndex lines(*text);
        const ast::Position at = lines.utf16(p.begin);
        out.push_back(json::object{{"name", name},
                                   {"kind", symbol_kind::function},
                                   {"containerName", p.comment},
                                   {"location", json::object{{"uri", path_to_uri(p.file)},
                                                             {"range", json::object{{"start", to_json(at)}, {"end", to_json(at)}}}}}});
    }
    return out;
}

}  // namespace kerf::lsp
