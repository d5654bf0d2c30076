// A test client for the language server: the real lsp::Server runs its message loop on a thread,
// talking over two pipes exactly as `kerf lsp` talks over stdin/stdout; the test sends framed
// messages and reads what comes back (clangd's lit tests in C++). Catch2 assertions stay on the
// test's thread: the reader thread only queues messages.
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <boost/json.hpp>
#include <catch2/catch.hpp>

#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "lsp/jsonrpc.hpp"
#include "lsp/protocol.hpp"
#include "lsp/server.hpp"
#include "lsp/transport.hpp"

namespace kerf::test {

namespace json = boost::json;
using namespace std::chrono_literals;

// A folder under /tmp that is removed with the object.
class TempFolder {
public:
    TempFolder() {
        std::string pattern = (std::filesystem::temp_directory_path() / "kerf-lsp-XXXXXX").string();
        REQUIRE(::mkdtemp(pattern.data()) != nullptr);
        path_ = pattern;
    }
    ~TempFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const std::filesystem::path p = path_ / name;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
    std::string uri(const std::string& name) const { return lsp::path_to_uri(path_ / name); }

private:
    std::filesystem::path path_;
};

class LspClient {
public:
    explicit LspClient(lsp::ServerOptions options = {}) {
        REQUIRE(::pipe2(to_server_, O_CLOEXEC) == 0);
        REQUIRE(::pipe2(from_server_, O_CLOEXEC) == 0);
        server_ = std::make_unique<lsp::Server>(to_server_[0], from_server_[1], options);
        server_thread_ = std::thread([this] {
            exit_code_ = server_->run();
            ::close(from_server_[1]);   // the reader sees the end
            from_server_[1] = -1;
        });
        reader_ = std::thread([this] { read_loop(); });
    }
    ~LspClient() {
        close_input();
        if (server_thread_.joinable()) server_thread_.join();
        if (reader_.joinable()) reader_.join();
        for (int fd : {to_server_[0], from_server_[0], from_server_[1]})
            if (fd >= 0) ::close(fd);
    }

    // --- sending ---------------------------------------------------------------------------
    void send_raw(const std::string& bytes) {
        for (std::size_t at = 0; at < bytes.size();) {
            const ssize_t n = ::write(to_server_[1], bytes.data() + at, bytes.size() - at);
            REQUIRE(n > 0);
            at += static_cast<std::size_t>(n);
        }
    }
    void send_body(const std::string& body) { send_raw("Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body); }
    std::int64_t send_request(const std::string& method, json::value params) {
        const std::int64_t id = next_id_++;
        json::object m{{"jsonrpc", "2.0"}, {"id", id}, {"method", method}};
        if (!params.is_null()) m["params"] = std::move(params);
        send_body(json::serialize(m));
        return id;
    }
    void notify(const std::string& method, json::value params) {
        json::object m{{"jsonrpc", "2.0"}, {"method", method}};
        if (!params.is_null()) m["params"] = std::move(params);
        send_body(json::serialize(m));
    }
    void close_input() {
        if (to_server_[1] >= 0) {
            ::close(to_server_[1]);
            to_server_[1] = -1;
        }
    }

    // --- receiving -------------------------------------------------------------------------
    // The first message (in arrival order, not yet taken) that `match` accepts; it is taken.
    json::object wait_for(const std::function<bool(const json::object&)>& match, std::chrono::milliseconds timeout = 60s) {
        std::unique_lock lock(mutex_);
        const auto deadline = std::chrono::steady_clock::now() + timeout;
        while (true) {
            for (auto it = inbox_.begin(); it != inbox_.end(); ++it)
                if (match(*it)) {
                    json::object m = std::move(*it);
                    inbox_.erase(it);
                    return m;
                }
            if (ended_) FAIL("the server closed its output while a message was awaited");
            if (changed_.wait_until(lock, deadline) == std::cv_status::timeout) FAIL("no such message within the timeout");
        }
    }
    json::object response(std::int64_t id) {
        return wait_for([id](const json::object& m) { return !m.contains("method") && m.contains("id") && m.at("id").is_int64() && m.at("id").as_int64() == id; });
    }
    json::object request(const std::string& method, json::value params = nullptr) { return response(send_request(method, std::move(params))); }
    // The result of a request that must succeed.
    json::value result(const std::string& method, json::value params = nullptr) {
        json::object r = request(method, std::move(params));
        INFO(json::serialize(r));
        REQUIRE(r.contains("result"));
        return r.at("result");
    }
    // The error code of a request that must fail.
    std::int64_t error_code(const std::string& method, json::value params = nullptr) {
        json::object r = request(method, std::move(params));
        INFO(json::serialize(r));
        REQUIRE(r.contains("error"));
        return r.at("error").as_object().at("code").as_int64();
    }
    json::object notification(const std::string& method, std::chrono::milliseconds timeout = 60s) {
        return wait_for([&](const json::object& m) { return m.contains("method") && m.at("method").as_string() == method && !m.contains("id"); }, timeout);
    }
    // A log message containing `text`.
    json::object log_containing(const std::string& text) {
        return wait_for([&](const json::object& m) {
            return m.contains("method") && m.at("method").as_string() == "window/logMessage" &&
                   std::string(m.at("params").as_object().at("message").as_string()).find(text) != std::string::npos;
        });
    }
    // True when no message that `match` accepts arrives within `wait`.
    bool none_within(const std::function<bool(const json::object&)>& match, std::chrono::milliseconds wait) {
        std::unique_lock lock(mutex_);
        const auto deadline = std::chrono::steady_clock::now() + wait;
        while (std::chrono::steady_clock::now() < deadline) {
            for (const json::object& m : inbox_)
                if (match(m)) return false;
            changed_.wait_until(lock, deadline);
        }
        for (const json::object& m : inbox_)
            if (match(m)) return false;
        return true;
    }
    // Every message received so far, in order (taken or not).
    std::vector<json::object> history() {
        std::lock_guard lock(mutex_);
        return history_;
    }
    bool ended() {
        std::lock_guard lock(mutex_);
        return ended_;
    }
    int wait_exit() {
        close_input();
        if (server_thread_.joinable()) server_thread_.join();
        return exit_code_;
    }
    int exit_code_after_run() {
        if (server_thread_.joinable()) server_thread_.join();
        return exit_code_;
    }

    // --- the usual session -----------------------------------------------------------------
    json::value initialize(json::object extra = {}, const std::optional<std::filesystem::path>& root = std::nullopt) {
        json::object params{{"processId", nullptr}, {"capabilities", json::object{}}};
        params["rootUri"] = root ? json::value(lsp::path_to_uri(*root)) : json::value(nullptr);
        for (auto& [k, v] : extra) params[k] = v;
        json::value r = result("initialize", params);
        notify("initialized", json::object{});
        return r;
    }
    void open(const std::string& uri, const std::string& text, std::int64_t version = 1) {
        notify("textDocument/didOpen", json::object{{"textDocument", json::object{{"uri", uri}, {"languageId", "gcode"}, {"version", version}, {"text", text}}}});
    }
    // The diagnostics of `uri` at `version` once the dry run is in (phase "complete").
    json::array diagnostics(const std::string& uri, std::int64_t version, const char* phase = "complete") {
        const json::object m = wait_for([&](const json::object& n) {
            if (!n.contains("method") || n.at("method").as_string() != "textDocument/publishDiagnostics") return false;
            const json::object& p = n.at("params").as_object();
            return p.at("uri").as_string() == uri && p.contains("version") && p.at("version").as_int64() == version &&
                   p.at("kerf").as_object().at("phase").as_string() == phase;
        });
        return m.at("params").as_object().at("diagnostics").as_array();
    }
    void shutdown_and_exit() {
        result("shutdown");
        notify("exit", nullptr);
    }

private:
    void read_loop() {
        lsp::Transport transport(from_server_[0], -1);
        while (true) {
            std::optional<lsp::Frame> frame = transport.read();
            std::lock_guard lock(mutex_);
            if (!frame) {
                ended_ = true;
                changed_.notify_all();
                return;
            }
            if (!frame->problem.empty()) continue;
            json::error_code ec;
            json::value v = json::parse(frame->body, ec);
            if (!ec && v.is_object()) {
                history_.push_back(v.as_object());
                inbox_.push_back(std::move(v.as_object()));
            }
            changed_.notify_all();
        }
    }

    int to_server_[2] = {-1, -1};
    int from_server_[2] = {-1, -1};
    std::unique_ptr<lsp::Server> server_;
    std::thread server_thread_, reader_;
    int exit_code_ = -1;
    std::int64_t next_id_ = 1;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<json::object> inbox_;
    std::vector<json::object> history_;
    bool ended_ = false;
};

// {"textDocument": {"uri": uri}, "position": {line, character}}
inline json::object at(const std::string& uri, std::uint32_t line, std::uint32_t character) {
    return {{"textDocument", json::object{{"uri", uri}}}, {"position", json::object{{"line", line}, {"character", character}}}};
}
inline json::object doc(const std::string& uri) { return {{"textDocument", json::object{{"uri", uri}}}}; }
inline json::object range(std::uint32_t l1, std::uint32_t c1, std::uint32_t l2, std::uint32_t c2) {
    return {{"start", json::object{{"line", l1}, {"character", c1}}}, {"end", json::object{{"line", l2}, {"character", c2}}}};
}
// "line:col-line:col" of an LSP Range, for readable assertions.
inline std::string span(const json::value& r) {
    const auto& s = r.as_object().at("start").as_object();
    const auto& e = r.as_object().at("end").as_object();
    return std::to_string(s.at("line").as_int64()) + ":" + std::to_string(s.at("character").as_int64()) + "-" +
           std::to_string(e.at("line").as_int64()) + ":" + std::to_string(e.at("character").as_int64());
}
inline std::string str(const json::value& v) { return std::string(v.as_string()); }

}  // namespace kerf::test
