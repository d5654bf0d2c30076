// JSON-RPC 2.0 as LSP 3.17 uses it: what a message body is (a request, a notification or a
// response), checked strictly, and the error codes of both specifications. Pure: bodies in,
// values out.
#pragma once

#include <boost/json.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace kerf::lsp {

namespace json = boost::json;

namespace error_code {
inline constexpr int parse_error = -32700;            // the body is not JSON
inline constexpr int invalid_request = -32600;        // JSON, but not a JSON-RPC 2.0 message
inline constexpr int method_not_found = -32601;
inline constexpr int invalid_params = -32602;
inline constexpr int internal_error = -32603;
inline constexpr int server_not_initialized = -32002; // a request before `initialize`
inline constexpr int request_failed = -32803;         // LSP: the request was valid and failed (rename refused)
inline constexpr int server_cancelled = -32802;
inline constexpr int content_modified = -32801;       // an edit made the request stale
inline constexpr int request_cancelled = -32800;      // $/cancelRequest
}  // namespace error_code

// Thrown by a handler to answer its request with an error.
struct RpcError : std::runtime_error {
    RpcError(int error_code, const std::string& message) : std::runtime_error(message), code(error_code) {}
    int code;
};

enum class MessageKind { request, notification, response };

struct Message {
    MessageKind kind = MessageKind::notification;
    json::value id;          // requests and responses (null for notifications)
    std::string method;      // requests and notifications
    json::value params;      // requests and notifications (null when absent)
    json::value result;      // responses
    std::optional<json::object> error;   // responses with an error
};

// A body that is not a message: the error to answer with, and the id when one could be read.
struct BadMessage {
    int code = error_code::invalid_request;
    std::string message;
    json::value id;   // null when unknown
};

// Parses and checks one body. Exactly one of the two is set.
struct Parsed {
    std::optional<Message> message;
    std::optional<BadMessage> bad;
};
Parsed parse_message(std::string_view body);

// The id as a map key: "n:12" or "s:abc".
std::string id_key(const json::value& id);

// `text` with every byte sequence that is not UTF-8 replaced by U+FFFD. A serialized message must
// be UTF-8 (LSP 3.17 base protocol); a file read from disk may be CP1251 or anything.
std::string valid_utf8(std::string text);
// At most `bytes` bytes of `text`, cut at a character boundary.
std::string_view clip(std::string_view text, std::size_t bytes);

std::string response(const json::value& id, json::value result);
std::string error_response(const json::value& id, int code, std::string_view message);
std::string notification(std::string_view method, json::value params);
std::string request(const json::value& id, std::string_view method, json::value params);

}  // namespace kerf::lsp
