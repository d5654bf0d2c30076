#include "lsp/jsonrpc.hpp"

#include <fmt/format.h>

#include "ast/display.hpp"

namespace kerf::lsp {

namespace {

bool valid_id(const json::value& id) { return id.is_int64() || id.is_uint64() || id.is_string(); }

BadMessage bad(int code, std::string message, json::value id = nullptr) { return {code, std::move(message), std::move(id)}; }

}  // namespace

Parsed parse_message(std::string_view body) {
    json::parse_options options;
    options.max_depth = 128;
    json::error_code ec;
    json::value v = json::parse(json::string_view(body.data(), body.size()), ec, {}, options);
    if (ec) return {std::nullopt, bad(error_code::parse_error, fmt::format("the message is not JSON: {}", ec.message()))};
    if (!v.is_object())
        return {std::nullopt, bad(error_code::invalid_request, "a JSON-RPC message is an object (batches are not used by LSP)")};
    json::object& o = v.as_object();
    json::value id = nullptr;
    if (const auto* i = o.if_contains("id")) {
        if (valid_id(*i)) id = *i;
        else if (!i->is_null()) return {std::nullopt, bad(error_code::invalid_request, "\"id\" must be a number or a string")};
    }
    const auto* version = o.if_contains("jsonrpc");
    if (!version || !version->is_string() || version->as_string() != "2.0")
        return {std::nullopt, bad(error_code::invalid_request, "\"jsonrpc\" must be \"2.0\"", id)};
    Message m;
    m.id = id;
    if (const auto* method = o.if_contains("method")) {
        if (!method->is_string()) return {std::nullopt, bad(error_code::invalid_request, "\"method\" must be a string", id)};
        m.method = std::string(method->as_string());
        m.kind = o.contains("id") ? MessageKind::request : MessageKind::notification;
        if (m.kind == MessageKind::request && id.is_null())
            return {std::nullopt, bad(error_code::invalid_request, "a request's \"id\" must be a number or a string")};
        if (auto* params = o.if_contains("params"); params && !params->is_null()) {   // null: as if absent (some clients send it for shutdown)
            if (!params->is_object() && !params->is_array())
                return {std::nullopt, bad(error_code::invalid_request, "\"params\" must be an object or an array", id)};
            m.params = std::move(*params);   // not copied: a didOpen holds the whole document
        }
        return {std::move(m), std::nullopt};
    }
    if (o.contains("result") || o.contains("error")) {
        m.kind = MessageKind::response;
        if (auto* r = o.if_contains("result")) m.result = std::move(*r);
        if (const auto* e = o.if_contains("error"); e && e->is_object()) m.error = e->as_object();
        return {std::move(m), std::nullopt};
    }
    return {std::nullopt, bad(error_code::invalid_request, "a message needs \"method\" (request, notification) or \"result\"/\"error\" (response)", id)};
}

std::string id_key(const json::value& id) {
    if (id.is_string()) return "s:" + std::string(id.as_string());
    if (id.is_int64()) return "n:" + std::to_string(id.as_int64());
    if (id.is_uint64()) return "n:" + std::to_string(id.as_uint64());
    return "null";
}

std::string valid_utf8(std::string text) {
    // The common case: nothing to replace, no copy.
    return ast::is_valid_utf8(text) ? std::move(text) : ast::valid_utf8(text);
}

std::string_view clip(std::string_view text, std::size_t bytes) {
    if (text.size() <= bytes) return text;
    std::size_t cut = bytes;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    return text.substr(0, cut);
}

std::string response(const json::value& id, json::value result) {
    return json::serialize(json::object{{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}});
}

std::string error_response(const json::value& id, int code, std::string_view message) {
    return json::serialize(json::object{
        {"jsonrpc", "2.0"}, {"id", id}, {"error", json::object{{"code", code}, {"message", message}}}});
}

std::string notification(std::string_view method, json::value params) {
    return json::serialize(json::object{{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
}

std::string request(const json::value& id, std::string_view method, json::value params) {
    return json::serialize(json::object{{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}});
}

}  // namespace kerf::lsp
