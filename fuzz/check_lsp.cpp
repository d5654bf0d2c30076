// The fuzz check of the language server's message loop (fuzz/checks.hpp check_lsp): the input is a
// script of messages that the real lsp::Server reads from a pipe, exactly as `kerf lsp` reads
// stdin, and what it writes is read back from another pipe and checked.
//
// The script: one byte picks the next message (its value modulo the number of kinds below), the
// bytes after it fill it in: document texts, versions, positions and ranges (which may lie outside
// the document), names, ids. Raw bytes and frames with a wrong Content-Length or a body that is not
// a JSON-RPC message break the framing on purpose; a script without them is "well formed".
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <unistd.h>

#include <boost/json.hpp>
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <string_view>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "fuzz/checks.hpp"
#include "lsp/protocol.hpp"
#include "lsp/server.hpp"

namespace kerf::fuzz {

namespace {

namespace json = boost::json;

// Programs a didOpen may send whole (the fuzzer mutates the script around them).
constexpr const char* kPrograms[] = {
    "O1000 (MAIN)\nN10 G50 S2000\nN20 T0101\nN30 G96 S200 M03\nN40 G00 X50. Z2.\nN50 G71 U1. R0.5\n"
    "N60 G71 P70 Q90 U0.4 W0.1 F0.25\nN70 G00 X20.\nN80 G01 Z-20.\nN90 X50.\nN100 G70 P70 Q90\nN110 M98 P31234\nN120 M30\n"
    "O1234 (SUB)\nN5 G01 U-2. F0.1\nN6 M99 P120\n",
    "%\nO0001\nN10 G00 X0. Y0. X1.\nN20 G01 X10. Y10.\nN30 G02 X20. Y0. R1.\nGOTO 10\nN10 M30\nG00 X5.\n%\n",
    "O2\n#1=0\nWHILE [#1 LT 3] DO 1\n#1=#1+1\nG65 P9010 A#1\nEND 1\nIF [#1 EQ 3] GOTO 5\nN5 M98 P41001\nM30\n",
    "O3\nT1 M06\nG90 G00 X0. Y0. S1000 M03\nG43 H2 Z50.\nG81 X10. Y10. Z-5. R2. F100.\nG80\nM30\n",
    "(kerf: ignore K1020)\nO4\nG0 X1\nG1 X2 F100\nM30\n",
};
constexpr const char* kPieces[] = {"", "X", "7", " ", "\n", "\r\n", "%", "(", "G71 P10 Q20 ", "N10 ", "GOTO 10\n", "#1=#1+1\n",
                                   "M98 P41001\n", "O1234\n", "Ф", "𝄞", "\t", ";", "IF [#1 LT 2] GOTO 5\n"};
constexpr const char* kDialects[] = {"", "auto", "nope", "fanuc-mill", "fanuc-lathe-a", "fanuc-lathe-c", "pcnc-mill"};
// The documents live in a folder of their own whose .kerf.toml bounds every dry run to a tenth of a
// second (a program may loop: the server stops it at the time limit, as kerf check does).
constexpr const char* kFiles[] = {"a.nc", "O1234", "sub/b.nc"};

const std::filesystem::path& folder() {
    static const std::filesystem::path dir = [] {
        const std::filesystem::path d = std::filesystem::temp_directory_path() / fmt::format("kerf-fuzz-lsp-{}", ::getpid());
        std::filesystem::create_directories(d / "sub");
        std::ofstream(d / ".kerf.toml") << "[limits]\ntime_limit = 0.1\n";
        return d;
    }();
    return dir;
}
constexpr const char* kRequests[] = {
    "textDocument/hover", "textDocument/completion", "textDocument/definition", "textDocument/references",
    "textDocument/documentHighlight", "textDocument/prepareRename", "textDocument/rename", "textDocument/semanticTokens/full",
    "textDocument/semanticTokens/range", "textDocument/foldingRange", "textDocument/inlayHint", "textDocument/documentSymbol",
    "workspace/symbol", "textDocument/codeAction", "codeAction/resolve", "textDocument/formatting", "textDocument/rangeFormatting",
    "textDocument/codeLens", "textDocument/prepareCallHierarchy", "callHierarchy/incomingCalls", "callHierarchy/outgoingCalls",
    "textDocument/selectionRange", "kerf/waitForAnalysis", "textDocument/unknownRequest"};

class Script {
public:
    explicit Script(std::string_view input) : in_(input) {}
    bool done() const { return at_ >= in_.size(); }
    std::uint8_t byte() { return at_ < in_.size() ? static_cast<std::uint8_t>(in_[at_++]) : 0; }
    std::string take(std::size_t n) {
        n = std::min(n, in_.size() - at_);
        std::string out(in_.substr(at_, n));
        at_ += n;
        return out;
    }
    template <std::size_t N>
    const char* pick(const char* const (&table)[N]) { return table[byte() % N]; }

private:
    std::string_view in_;
    std::size_t at_ = 0;
};

// A request's strings in ASCII: a body that is not UTF-8 is answered as not JSON (-32700, null id),
// which is right but leaves the request itself without an answer to check.
std::string ascii(std::string s) {
    for (char& c : s)
        if (static_cast<unsigned char>(c) >= 0x80) c = '?';
    return s;
}

std::string frame(const std::string& body) { return fmt::format("Content-Length: {}\r\n\r\n", body.size()) + body; }

json::object position(Script& s) { return {{"line", s.byte() % 24}, {"character", s.byte() % 48}}; }
json::object range(Script& s) { return {{"start", position(s)}, {"end", position(s)}}; }

// What the script sent, to check the answers against.
struct Sent {
    std::string bytes;
    std::set<std::int64_t> requests;          // ids of well-formed requests before `exit`
    bool well_formed = true;                  // no raw bytes, no broken frames
    bool exited = false;                      // an `exit` was sent (nothing after it is read)
    bool initialized = false, shut_down = false;
    int expected_exit = 1;
    // A $/cancelRequest may stop `initialize` or `shutdown` before they run: the exit code then
    // depends on timing.
    bool uncertain_exit = false;
    std::set<std::int64_t> lifecycle;   // ids of initialize and shutdown
};

class Writer {
public:
    Writer(Script& script, Sent& sent) : s_(script), sent_(sent) {}

    void run() {
        while (!s_.done()) step(s_.byte() % 20);
        if (!sent_.exited) sent_.expected_exit = sent_.shut_down ? 0 : 1;
    }

private:
    void message(json::object m) {
        m["jsonrpc"] = "2.0";
        if (!sent_.exited) sent_.bytes += frame(json::serialize(m));
    }
    void notify(const char* method, json::value params) { message({{"method", method}, {"params", std::move(params)}}); }
    void request(const char* method, json::value params) {
        const std::int64_t id = next_id_++;
        if (!sent_.exited) sent_.requests.insert(id);
        if (std::string_view(method) == "initialize" || std::string_view(method) == "shutdown") sent_.lifecycle.insert(id);
        json::object m{{"id", id}, {"method", method}};
        if (!params.is_null()) m["params"] = std::move(params);
        message(std::move(m));
    }
    void broken(std::string bytes) {
        if (sent_.exited) return;
        sent_.bytes += bytes;
        sent_.well_formed = false;
    }
    std::string uri() { return lsp::path_to_uri(folder() / s_.pick(kFiles)); }
    json::object doc() { return {{"uri", uri()}}; }
    std::string text() {
        const std::uint8_t choice = s_.byte();
        if (choice % 4 != 0) return kPrograms[choice % std::size(kPrograms)];
        return s_.take(s_.byte() * 4u);   // anything, NUL bytes (a binary document) included
    }

    void step(int kind) {
        switch (kind) {
            case 0: broken(s_.take(s_.byte())); break;   // raw bytes
            case 1: {
                const std::uint8_t flags = s_.byte();
                json::object caps{{"workspace", json::object{{"configuration", (flags & 1) != 0},
                                                             {"didChangeWatchedFiles", json::object{{"dynamicRegistration", (flags & 2) != 0}}}}}};
                json::object init{{"dialect", s_.pick(kDialects)}, {"language", flags & 4 ? "ru" : "en"}};
                request("initialize", json::object{{"processId", nullptr}, {"rootUri", nullptr}, {"capabilities", caps},
                                                   {"initializationOptions", init}});
                if (!sent_.shut_down) sent_.initialized = true;
                break;
            }
            case 2: notify("initialized", json::object{}); break;
            case 3: {
                json::object td = doc();
                td["languageId"] = "gcode";
                td["version"] = s_.byte();
                td["text"] = text();
                notify("textDocument/didOpen", json::object{{"textDocument", td}});
                break;
            }
            case 4: {
                json::array changes;
                for (int n = 1 + s_.byte() % 3; n > 0; --n) {
                    const std::uint8_t piece = s_.byte();
                    changes.push_back(json::object{{"range", range(s_)}, {"text", piece % 5 ? kPieces[piece % std::size(kPieces)] : s_.take(piece % 32)}});
                }
                json::object td = doc();
                td["version"] = ++version_;
                notify("textDocument/didChange", json::object{{"textDocument", td}, {"contentChanges", changes}});
                break;
            }
            case 5: {
                json::object td = doc();
                td["version"] = ++version_;
                notify("textDocument/didChange", json::object{{"textDocument", td}, {"contentChanges", json::array{json::object{{"text", text()}}}}});
                break;
            }
            case 6: {
                const char* method = s_.pick(kRequests);
                json::object p{{"textDocument", doc()}, {"position", position(s_)}, {"range", range(s_)}};
                const std::uint8_t b = s_.byte();
                p["newName"] = b % 3 ? std::to_string(b * 7) : ascii(s_.take(b % 8));
                p["context"] = json::object{{"includeDeclaration", (b & 1) != 0}, {"diagnostics", json::array{}},
                                            {"only", json::array{b & 2 ? "refactor" : "quickfix"}}};
                p["query"] = ascii(s_.take(b % 4));
                p["positions"] = json::array{position(s_), position(s_)};
                p["item"] = json::object{{"name", "O1234"}, {"kind", 12}, {"uri", uri()}, {"range", range(s_)}, {"selectionRange", range(s_)},
                                         {"data", json::object{{"number", b * 13}}}};
                p["data"] = json::object{{"uri", uri()}, {"kind", "renumber"}};
                request(method, p);
                break;
            }
            case 7: {
                const std::int64_t id = next_id_ - 1 - s_.byte() % 3;
                if (sent_.lifecycle.count(id)) sent_.uncertain_exit = true;
                notify("$/cancelRequest", json::object{{"id", id}});
                break;
            }
            case 8:
                request("shutdown", nullptr);
                if (sent_.initialized && !sent_.exited) sent_.shut_down = true;
                break;
            case 9:
                notify("exit", nullptr);
                if (!sent_.exited) sent_.expected_exit = sent_.shut_down ? 0 : 1;
                sent_.exited = true;
                break;
            case 10: notify("textDocument/didClose", json::object{{"textDocument", doc()}}); break;
            case 11:
                notify("workspace/didChangeConfiguration",
                       json::object{{"settings", json::object{{"kerf", json::object{{"dialect", s_.pick(kDialects)}, {"language", s_.byte() & 1 ? "ru" : "en"}}}}}});
                break;
            case 12: broken(frame(s_.take(s_.byte()))); break;   // a body that may not be JSON
            case 13: {                                             // a Content-Length that is wrong
                const std::string body = json::serialize(json::object{{"jsonrpc", "2.0"}, {"id", next_id_++}, {"method", "textDocument/hover"}});
                const int off = static_cast<int>(s_.byte() % 9) - 4;
                broken(fmt::format("Content-Length: {}\r\n\r\n", static_cast<int>(body.size()) + off) + body);
                break;
            }
            case 14: request("kerf/waitForAnalysis", nullptr); break;
            case 15:   // the client's answer to the server's requests (workspace/configuration, registerCapability)
                message({{"id", s_.byte() % 4}, {"result", json::array{json::object{{"dialect", s_.pick(kDialects)}}}}});
                break;
            case 16:
                notify("workspace/didChangeWatchedFiles",
                       json::object{{"changes", json::array{json::object{{"uri", s_.byte() & 1 ? lsp::path_to_uri(folder() / ".kerf.toml") : uri()},
                                                                         {"type", 1 + s_.byte() % 3}}}}});
                break;
            case 17: notify("workspace/unknownNotification", json::object{{"x", s_.byte()}}); break;
            case 18: {   // JSON, but not a JSON-RPC 2.0 message
                const std::uint8_t b = s_.byte();
                json::object m{{"method", "textDocument/hover"}};
                if (b & 1) m["jsonrpc"] = "1.0";
                if (b & 2) m["id"] = json::object{};
                if (b & 4) m["params"] = "text";
                broken(frame(json::serialize(m)));
                break;
            }
            default: notify("$/setTrace", json::object{{"value", "off"}}); break;
        }
    }

    Script& s_;
    Sent& sent_;
    std::int64_t next_id_ = 1;
    std::int64_t version_ = 1;
};

// One frame of the server's output, or what is wrong with the framing.
std::optional<std::string> next_frame(std::string_view& out, std::string& body) {
    const std::size_t head_end = out.find("\r\n\r\n");
    if (head_end == std::string_view::npos) return "output ends inside a header";
    const std::string_view head = out.substr(0, head_end);
    if (!head.starts_with("Content-Length: ")) return fmt::format("a header that is not Content-Length: '{}'", head.substr(0, 40));
    const std::size_t length = std::stoul(std::string(head.substr(16)));
    if (out.size() < head_end + 4 + length) return "output ends inside a body";
    body = std::string(out.substr(head_end + 4, length));
    out.remove_prefix(head_end + 4 + length);
    return std::nullopt;
}

// The server's output: every frame a JSON-RPC 2.0 message, every response to a request sent, once.
Broken check_output(std::string_view out, const Sent& sent) {
    std::set<std::int64_t> answered;
    std::string body;
    while (!out.empty()) {
        if (auto wrong = next_frame(out, body)) return *wrong;
        json::error_code ec;
        const json::value v = json::parse(body, ec);   // Boost.JSON rejects invalid UTF-8 too
        if (ec || !v.is_object()) return fmt::format("a frame that is not a JSON object: {}", body.substr(0, 200));
        const json::object& m = v.as_object();
        const json::value* version = m.if_contains("jsonrpc");
        if (!version || !version->is_string() || version->as_string() != "2.0") return "a message without \"jsonrpc\": \"2.0\"";
        if (const json::value* method = m.if_contains("method")) {
            if (!method->is_string()) return "a method that is not a string";
            continue;   // a notification, or a request of the server to the client
        }
        const json::value* id = m.if_contains("id");
        if (!id) return fmt::format("a message that is neither a request, a notification nor a response: {}", body.substr(0, 200));
        const bool result = m.contains("result"), error = m.contains("error");
        if (result == error) return fmt::format("a response needs exactly one of result and error: {}", body.substr(0, 200));
        if (error) {
            const json::value& e = m.at("error");
            if (!e.is_object() || !e.as_object().contains("code") || !e.as_object().at("code").is_int64() ||
                !e.as_object().contains("message") || !e.as_object().at("message").is_string())
                return fmt::format("an error without an integer code and a message: {}", body.substr(0, 200));
        }
        if (id->is_null()) {
            if (!error) return "a result for no request (null id)";
            continue;   // the answer to a body that was not JSON
        }
        if (!id->is_int64()) return fmt::format("a response id that no request had: {}", json::serialize(*id));
        if (!answered.insert(id->as_int64()).second) return fmt::format("request {} answered twice", id->as_int64());
        if (sent.well_formed && !sent.requests.count(id->as_int64())) return fmt::format("a response to request {}, which was not sent", id->as_int64());
    }
    if (sent.well_formed)
        for (const std::int64_t id : sent.requests)
            if (!answered.count(id)) return fmt::format("request {} was not answered", id);
    return std::nullopt;
}

// Writes `bytes` to `fd` and closes it (on its own thread: the pipe holds 64 KiB).
void feed(int fd, std::string bytes) {
    for (std::size_t at = 0; at < bytes.size();) {
        const ssize_t n = ::write(fd, bytes.data() + at, bytes.size() - at);
        if (n <= 0) break;   // the server stopped reading (exit): the rest is not read
        at += static_cast<std::size_t>(n);
    }
    ::close(fd);
}

std::string drain(int fd) {
    std::string out;
    char buf[65536];
    while (true) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n <= 0) break;
        out.append(buf, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return out;
}

}  // namespace

Broken check_lsp(std::string_view input) {
    Script script(input);
    Sent sent;
    Writer(script, sent).run();
    // KERF_FUZZ_LSP_SCRIPT=FILE writes the message stream a fuzz input makes (to replay it:
    // build/kerf lsp < FILE), so that a finding can be read as the messages it is.
    if (const char* path = std::getenv("KERF_FUZZ_LSP_SCRIPT")) {
        std::FILE* f = std::fopen(path, "wb");
        if (f) {
            std::fwrite(sent.bytes.data(), 1, sent.bytes.size(), f);
            std::fclose(f);
        }
    }
    int to_server[2], from_server[2];
    if (::pipe2(to_server, O_CLOEXEC) != 0) return std::nullopt;   // no pipes left: nothing to check
    if (::pipe2(from_server, O_CLOEXEC) != 0) {
        ::close(to_server[0]);
        ::close(to_server[1]);
        return std::nullopt;
    }
    // The server and the two ends of its pipes on threads of their own, sharing what they need:
    // if the server hangs, the check says so and leaves them running (the fuzzer stops at the
    // report, a test fails with it).
    struct Run {
        std::unique_ptr<lsp::Server> server;
        std::promise<int> code;
        std::promise<std::string> out;
    };
    auto run = std::make_shared<Run>();
    run->server = std::make_unique<lsp::Server>(to_server[0], from_server[1]);
    std::future<int> code = run->code.get_future();
    std::future<std::string> out = run->out.get_future();
    std::thread writer(feed, to_server[1], sent.bytes);
    std::thread reader([run, fd = from_server[0]] { run->out.set_value(drain(fd)); });
    std::thread server([run, in = to_server[0], out_fd = from_server[1]] {
        const int c = run->server->run();
        ::close(out_fd);
        ::close(in);
        run->code.set_value(c);
    });
    if (code.wait_for(std::chrono::seconds(60)) != std::future_status::ready) {
        for (std::thread* t : {&writer, &reader, &server}) t->detach();
        return "the server did not end within 60 s of the input's end";
    }
    for (std::thread* t : {&writer, &reader, &server}) t->join();
    const int exit_code = code.get();
    if (Broken b = check_output(out.get(), sent)) return b;
    if (sent.well_formed && !sent.uncertain_exit && exit_code != sent.expected_exit)
        return fmt::format("exit code {}, not {} (shutdown {}, exit {})", exit_code, sent.expected_exit, sent.shut_down, sent.exited);
    if (exit_code != 0 && exit_code != 1) return fmt::format("exit code {}", exit_code);
    return std::nullopt;
}

}  // namespace kerf::fuzz
