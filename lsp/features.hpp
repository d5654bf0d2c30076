// The language features (rust-analyzer's `ide`, clangd's one file per feature): each a pure function
// of an immutable snapshot and the request's parameters, returning the LSP result as JSON. They
// never lock, never write and never wait for the analysis worker: what the dry run knows comes from
// the last finished analysis of the same document version, when there is one.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lsp/analysis.hpp"
#include "lsp/document.hpp"
#include "lsp/jsonrpc.hpp"
#include "lsp/project_seam.hpp"

namespace kerf::lsp {

using OpenDocuments = std::map<std::string, std::shared_ptr<const Document>>;

struct Snapshot {
    std::shared_ptr<const Document> doc;
    std::shared_ptr<const Analysis> analysis;   // of doc->version() only; null otherwise
    const OpenDocuments& open;
    ProjectSeam& project;
    const std::atomic<bool>* cancel = nullptr;  // set by $/cancelRequest for long requests

    const Document& document() const { return *doc; }
    const DryRun* run() const { return analysis ? analysis->run.get() : nullptr; }
    // The document of `path`: the open one, else the file read and parsed (not kept).
    std::shared_ptr<const Document> document_at(const std::filesystem::path& path) const;
    bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
};

// diagnostics.cpp: the params of textDocument/publishDiagnostics.
json::object publish_diagnostics(const Document& doc, const Analysis& analysis, bool final);
json::object diagnostic_json(const Document& doc, const analyzer::Finding& f);

json::value hover(const Snapshot& s, ast::Position at);                                  // hover.cpp
json::value definition(const Snapshot& s, ast::Position at);                             // definition.cpp
json::value references(const Snapshot& s, ast::Position at, bool include_declaration);   // references.cpp
json::value document_highlight(const Snapshot& s, ast::Position at);                     // document_highlight.cpp
json::value prepare_rename(const Snapshot& s, ast::Position at);                         // rename.cpp
json::value rename(const Snapshot& s, ast::Position at, const std::string& new_name);
json::value completion(const Snapshot& s, ast::Position at);                             // completion.cpp
json::object semantic_tokens_legend();                                                   // semantic_tokens.cpp
json::value semantic_tokens(const Snapshot& s, std::optional<std::pair<ast::Position, ast::Position>> range);
json::value folding_ranges(const Snapshot& s);                                           // folding.cpp
json::value inlay_hints(const Snapshot& s, std::pair<ast::Position, ast::Position> range);   // inlay_hints.cpp
json::value document_symbols(const Snapshot& s);                                         // symbols.cpp
json::value workspace_symbols(const OpenDocuments& open, ProjectSeam& project, const std::string& query);
json::value code_actions(const Snapshot& s, std::pair<ast::Position, ast::Position> range, const json::value& context);   // code_actions.cpp
json::value resolve_code_action(const Snapshot& s, json::object action);
void conversion_actions(const Snapshot& s, json::array& out);                            // convert.cpp
json::value resolve_conversion(const Snapshot& s, json::object action);
json::value formatting(const Snapshot& s);                                               // formatting.cpp
json::value range_formatting(const Snapshot& s, std::pair<ast::Position, ast::Position> range);
json::value code_lens(const Snapshot& s);                                                // code_lens.cpp
json::value prepare_call_hierarchy(const Snapshot& s, ast::Position at);                 // call_hierarchy.cpp
json::value incoming_calls(const OpenDocuments& open, ProjectSeam& project, const json::object& item);
json::value outgoing_calls(const OpenDocuments& open, ProjectSeam& project, const json::object& item);
json::value selection_ranges(const Snapshot& s, const std::vector<ast::Position>& at);   // selection_range.cpp

}  // namespace kerf::lsp
