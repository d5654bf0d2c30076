// LSP 3.17 types as Boost.JSON values: positions and ranges in UTF-16 code units (the protocol's
// default encoding; ast::LineIndex converts), locations, text edits, file URIs, and the few enums
// the features use. Reading a request's parameters checks them and throws RpcError(-32602) with
// what is missing.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "ast/source.hpp"
#include "lsp/document.hpp"
#include "lsp/jsonrpc.hpp"

namespace kerf::lsp {

json::object to_json(ast::Position p);
json::object range_json(const Document& doc, ast::Range r);
json::object location_json(const Document& doc, ast::Range r);
json::object text_edit(const Document& doc, ast::Range r, std::string_view new_text);

// "file:///a%20b/x.nc" ↔ "/a b/x.nc". A URI of another scheme gives an empty path.
std::filesystem::path uri_to_path(std::string_view uri);
std::string path_to_uri(const std::filesystem::path& path);

// Parameter access: the value or RpcError(invalid_params).
const json::object& object_param(const json::value& params, std::string_view name);   // params.name
std::string string_param(const json::object& o, std::string_view name);
std::int64_t int_param(const json::object& o, std::string_view name);
ast::Position position_param(const json::object& o, std::string_view name);
std::pair<ast::Position, ast::Position> range_param(const json::object& o, std::string_view name);
std::string document_uri(const json::value& params);   // params.textDocument.uri
const json::object& params_object(const json::value& params);

// Optional lookups: nullptr when absent or of another type.
const json::value* find_path(const json::value& v, std::initializer_list<std::string_view> path);
const json::value* find_path(const json::object& o, std::initializer_list<std::string_view> path);   // no copy of `o`

namespace symbol_kind {
inline constexpr int file = 1, module = 2, namespace_ = 3, function = 12, variable = 13, constant = 14, event = 24, operator_ = 25, key = 20, number = 16;
}
namespace completion_kind {
inline constexpr int text = 1, method = 2, function = 3, field = 5, variable = 6, module = 9, property = 10, unit = 11, value = 12,
                     keyword = 14, snippet = 15, reference = 18, constant = 21, event = 23, operator_ = 24;
}
namespace diagnostic_severity {
inline constexpr int error = 1, warning = 2, information = 3, hint = 4;
}

}  // namespace kerf::lsp
