#include "lsp/protocol.hpp"

#include <fmt/format.h>

#include <cctype>

namespace kerf::lsp {

json::object to_json(ast::Position p) { return {{"line", p.line}, {"character", p.column}}; }

json::object range_json(const Document& doc, ast::Range r) {
    return {{"start", to_json(doc.position(r.begin))}, {"end", to_json(doc.position(r.end))}};
}

json::object location_json(const Document& doc, ast::Range r) { return {{"uri", doc.uri()}, {"range", range_json(doc, r)}}; }

json::object text_edit(const Document& doc, ast::Range r, std::string_view new_text) {
    return {{"range", range_json(doc, r)}, {"newText", new_text}};
}

namespace {
int hex(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}
}  // namespace

std::filesystem::path uri_to_path(std::string_view uri) {
    constexpr std::string_view scheme = "file://";
    if (uri.substr(0, scheme.size()) != scheme) return {};
    uri.remove_prefix(scheme.size());
    if (!uri.empty() && uri.front() != '/') {   // file://host/path: the host is dropped
        const std::size_t slash = uri.find('/');
        uri = slash == std::string_view::npos ? std::string_view() : uri.substr(slash);
    }
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() + 0 && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out += static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return std::filesystem::path(out).lexically_normal();
}

std::string path_to_uri(const std::filesystem::path& path) {
    std::string out = "file://";
    for (const unsigned char c : path.string()) {
        if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') out += static_cast<char>(c);
        else out += fmt::format("%{:02X}", c);
    }
    return out;
}

const json::object& params_object(const json::value& params) {
    if (!params.is_object()) throw RpcError(error_code::invalid_params, "params must be an object");
    return params.as_object();
}

const json::object& object_param(const json::value& params, std::string_view name) {
    const json::value* v = params_object(params).if_contains(json::string_view(name.data(), name.size()));
    if (!v || !v->is_object()) throw RpcError(error_code::invalid_params, fmt::format("params.{} must be an object", name));
    return v->as_object();
}

std::string string_param(const json::object& o, std::string_view name) {
    const json::value* v = o.if_contains(json::string_view(name.data(), name.size()));
    if (!v || !v->is_string()) throw RpcError(error_code::invalid_params, fmt::format("'{}' must be a string", name));
    return std::string(v->as_string());
}

std::int64_t int_param(const json::object& o, std::string_view name) {
    const json::value* v = o.if_contains(json::string_view(name.data(), name.size()));
    if (v && v->is_int64()) return v->as_int64();
    if (v && v->is_uint64() && v->as_uint64() < (std::uint64_t{1} << 62)) return static_cast<std::int64_t>(v->as_uint64());
    if (v && v->is_double() && v->as_double() == static_cast<double>(static_cast<std::int64_t>(v->as_double())))
        return static_cast<std::int64_t>(v->as_double());
    throw RpcError(error_code::invalid_params, fmt::format("'{}' must be an integer", name));
}

ast::Position position_param(const json::object& o, std::string_view name) {
    const json::value* v = o.if_contains(json::string_view(name.data(), name.size()));
    if (!v || !v->is_object()) throw RpcError(error_code::invalid_params, fmt::format("'{}' must be a Position", name));
    const std::int64_t line = int_param(v->as_object(), "line");
    const std::int64_t character = int_param(v->as_object(), "character");
    if (line < 0 || character < 0 || line > 0xFFFFFFFFll || character > 0xFFFFFFFFll)
        throw RpcError(error_code::invalid_params, fmt::format("'{}' has a negative or too large line or character", name));
    return {static_cast<std::uint32_t>(line), static_cast<std::uint32_t>(character)};
}

std::pair<ast::Position, ast::Position> range_param(const json::object& o, std::string_view name) {
    const json::value* v = o.if_contains(json::string_view(name.data(), name.size()));
    if (!v || !v->is_object()) throw RpcError(error_code::invalid_params, fmt::format("'{}' must be a Range", name));
    return {position_param(v->as_object(), "start"), position_param(v->as_object(), "end")};
}

std::string document_uri(const json::value& params) { return string_param(object_param(params, "textDocument"), "uri"); }

const json::value* find_path(const json::object& o, std::initializer_list<std::string_view> path) {
    if (path.size() == 0) return nullptr;
    const std::string_view first = *path.begin();
    const json::value* at = o.if_contains(json::string_view(first.data(), first.size()));
    for (auto it = path.begin() + 1; at && it != path.end(); ++it) {
        if (!at->is_object()) return nullptr;
        at = at->as_object().if_contains(json::string_view(it->data(), it->size()));
    }
    return at;
}

const json::value* find_path(const json::value& v, std::initializer_list<std::string_view> path) {
    const json::value* at = &v;
    for (const std::string_view key : path) {
        if (!at->is_object()) return nullptr;
        at = at->as_object().if_contains(json::string_view(key.data(), key.size()));
        if (!at) return nullptr;
    }
    return at;
}

}  // namespace kerf::lsp
