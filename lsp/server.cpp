#include "lsp/server.hpp"

#include <fmt/format.h>

#include <atomic>
#include <condition_variable>
#include <deque>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "lsp/analysis.hpp"
#include "lsp/features.hpp"
#include "lsp/jsonrpc.hpp"
#include "lsp/protocol.hpp"
#include "lsp/transport.hpp"

namespace kerf::lsp {

namespace fs = std::filesystem;

namespace {

enum class Phase { uninitialized, running, shutting_down };

namespace message_type {
inline constexpr int error = 1, warning = 2, info = 3, log = 4;
}

// What the reader hands to the message loop.
struct Incoming {
    std::optional<Message> message;
    std::optional<BadMessage> bad;
    std::string problem;              // a framing problem, to log
    std::function<void()> task;       // work posted by another thread of the server (indexing done)
    bool eof = false;
};

std::optional<std::string> read_disk(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Requests whose answer describes one document version: a didChange of that document already in
// the queue makes them stale (ContentModified), as LSP 3.17 allows.
const std::set<std::string, std::less<>> kVersionedRequests = {
    "textDocument/hover",          "textDocument/completion",    "textDocument/semanticTokens/full",
    "textDocument/semanticTokens/range", "textDocument/inlayHint", "textDocument/codeLens",
    "textDocument/documentHighlight", "textDocument/foldingRange", "textDocument/documentSymbol",
    "textDocument/selectionRange", "textDocument/codeAction",     "textDocument/definition"};

}  // namespace

struct Server::Impl {
    using RequestFn = std::function<json::value(const json::value& params)>;
    // Notifications may take what they keep out of their parameters (didOpen: the document).
    using NotifyFn = std::function<void(json::value& params)>;

    Impl(int in_fd, int out_fd, ServerOptions o)
        : options(std::move(o)), transport(in_fd, out_fd), project([this](const fs::path& p, std::size_t max_bytes) { return open_text(p, max_bytes); }) {
        register_handlers();
    }

    ServerOptions options;
    Transport transport;
    ProjectSeam project;
    std::unique_ptr<AnalysisWorker> worker;
    std::thread reader_thread, index_thread;

    // The queue between the reader and the message loop.
    std::mutex queue_mutex;
    std::condition_variable queue_cv;
    std::deque<Incoming> queue;
    std::set<std::string> cancelled;   // ids of $/cancelRequest not yet answered
    std::string running_id;            // the request being answered
    std::atomic<bool> running_cancel{false};

    // Open documents: written by the message loop, read under the lock by the worker's publisher
    // and the project seam's reader.
    std::mutex docs_mutex;
    OpenDocuments docs;

    Phase phase = Phase::uninitialized;
    std::optional<int> exit_code;
    bool pull_configuration = false;
    bool watch_registration = false;
    std::vector<fs::path> roots;
    std::int64_t next_request = 1;
    std::map<std::string, std::function<void(const Message&)>> pending;   // our requests to the client
    std::map<std::string, RequestFn, std::less<>> requests;
    std::map<std::string, NotifyFn, std::less<>> notifications;

    // --- output ------------------------------------------------------------------------------

    void send(std::string body) {
        body = valid_utf8(std::move(body));
        if (options.log) options.log(fmt::format("<- {}", clip(body, 300)));
        transport.write(body);
    }
    void log(int type, const std::string& text) {
        if (options.log) options.log(text);
        send(notification("window/logMessage", json::object{{"type", type}, {"message", text}}));
    }
    void request_client(std::string_view method, json::value params, std::function<void(const Message&)> done) {
        const json::value id = next_request++;
        pending[id_key(id)] = std::move(done);
        send(request(id, method, std::move(params)));
    }

    // --- files -------------------------------------------------------------------------------

    // The text of an open document at `path`, its first `max_bytes` (the project layer reads the
    // disk for the rest).
    std::optional<std::string> open_text(const fs::path& path, std::size_t max_bytes) {
        const std::lock_guard lock(docs_mutex);
        for (const auto& [uri, doc] : docs)
            if (doc->path() == path) return doc->text().substr(0, max_bytes);
        return std::nullopt;
    }

    // --- the reader thread -------------------------------------------------------------------

    void push(Incoming in) {
        {
            const std::lock_guard lock(queue_mutex);
            queue.push_back(std::move(in));
        }
        queue_cv.notify_one();
    }

    void reader() {
        while (true) {
            std::optional<Frame> frame = transport.read();
            if (!frame) {
                Incoming end;
                end.eof = true;
                push(std::move(end));
                return;
            }
            Incoming in;
            if (!frame->problem.empty()) {
                in.problem = std::move(frame->problem);
                push(std::move(in));
                continue;
            }
            Parsed parsed = parse_message(frame->body);
            if (parsed.bad && parsed.bad->code == error_code::parse_error) {
                // A Content-Length too large swallows the next message's header: read on from it, when
                // the text before it is a whole JSON value (a document's text that says "Content-Length:"
                // inside a message that is broken otherwise is no header: fuzz_lsp).
                const std::size_t next = frame->body.find("Content-Length:");
                json::error_code ec;
                if (next != std::string::npos) (void)json::parse(std::string_view(frame->body).substr(0, next), ec);
                if (next != std::string::npos && !ec) transport.unread(std::string_view(frame->body).substr(next));
            }
            if (parsed.message && parsed.message->method == "$/cancelRequest") note_cancel(*parsed.message);
            in.message = std::move(parsed.message);
            in.bad = std::move(parsed.bad);
            push(std::move(in));
        }
    }

    void note_cancel(const Message& m) {
        const json::value* id = find_path(m.params, {"id"});
        if (!id) return;
        const std::lock_guard lock(queue_mutex);
        const std::string key = id_key(*id);
        if (key == running_id) running_cancel = true;
        else cancelled.insert(key);
    }

    Incoming pop() {
        std::unique_lock lock(queue_mutex);
        queue_cv.wait(lock, [&] { return !queue.empty(); });
        Incoming in = std::move(queue.front());
        queue.pop_front();
        return in;
    }

    // A didChange of `uri` is waiting in the queue.
    bool change_queued(const std::string& uri) {
        const std::lock_guard lock(queue_mutex);
        for (const Incoming& in : queue) {
            if (!in.message || in.message->method != "textDocument/didChange") continue;
            const json::value* u = find_path(in.message->params, {"textDocument", "uri"});
            if (u && u->is_string() && u->as_string() == uri) return true;
        }
        return false;
    }

    // --- the message loop --------------------------------------------------------------------

    int run() {
        if (options.analysis)
            worker = std::make_unique<AnalysisWorker>(project, [this](const Document& d, const Analysis& a, bool final) { publish(d, a, final); });
        reader_thread = std::thread([this] { reader(); });
        while (!exit_code) {
            Incoming in = pop();
            if (in.eof) {
                exit_code = phase == Phase::shutting_down ? 0 : 1;
                break;
            }
            handle(in);
        }
        stop();
        return *exit_code;
    }

    void stop() {
        transport.interrupt();
        if (reader_thread.joinable()) reader_thread.join();
        if (index_thread.joinable()) index_thread.join();
        worker.reset();
    }

    void handle(Incoming& in) {
        if (in.task) {
            in.task();
            return;
        }
        if (!in.problem.empty()) {
            log(message_type::warning, "kerf lsp: " + in.problem);
            return;
        }
        if (in.bad) {
            log(message_type::warning, fmt::format("kerf lsp: bad message ({}): {}", in.bad->code, in.bad->message));
            send(error_response(in.bad->id, in.bad->code, in.bad->message));
            return;
        }
        Message& m = *in.message;
        if (options.log) options.log(fmt::format("-> {} {}", m.method, id_key(m.id)));
        switch (m.kind) {
            case MessageKind::request: handle_request(m); break;
            case MessageKind::notification: handle_notification(m); break;
            case MessageKind::response: handle_response(m); break;
        }
    }

    void handle_request(const Message& m) {
        const std::string key = id_key(m.id);
        {
            const std::lock_guard lock(queue_mutex);
            if (cancelled.erase(key)) {
                send(error_response(m.id, error_code::request_cancelled, "cancelled by $/cancelRequest"));
                return;
            }
        }
        if (phase == Phase::uninitialized && m.method != "initialize") {
            send(error_response(m.id, error_code::server_not_initialized, fmt::format("'{}' before 'initialize'", m.method)));
            return;
        }
        if (phase == Phase::shutting_down) {
            send(error_response(m.id, error_code::invalid_request, fmt::format("'{}' after 'shutdown'", m.method)));
            return;
        }
        const auto it = requests.find(m.method);
        if (it == requests.end()) {
            log(message_type::log, fmt::format("kerf lsp: unknown request '{}'", m.method));
            send(error_response(m.id, error_code::method_not_found, fmt::format("unknown method '{}'", m.method)));
            return;
        }
        if (kVersionedRequests.count(m.method)) {
            const json::value* uri = find_path(m.params, {"textDocument", "uri"});
            if (uri && uri->is_string() && change_queued(std::string(uri->as_string()))) {
                send(error_response(m.id, error_code::content_modified, "the document changed; ask again"));
                return;
            }
        }
        {
            const std::lock_guard lock(queue_mutex);
            running_id = key;
            running_cancel = false;
        }
        try {
            json::value result = it->second(m.params);
            if (running_cancel) send(error_response(m.id, error_code::request_cancelled, "cancelled by $/cancelRequest"));
            else send(response(m.id, std::move(result)));
        } catch (const RpcError& e) {
            send(error_response(m.id, e.code, e.what()));
        } catch (const std::exception& e) {
            log(message_type::error, fmt::format("kerf lsp: '{}' failed: {}", m.method, e.what()));
            send(error_response(m.id, error_code::internal_error, fmt::format("internal error: {}", e.what())));
        }
        const std::lock_guard lock(queue_mutex);
        running_id.clear();
    }

    void handle_notification(Message& m) {
        if (m.method == "exit") {
            exit_code = phase == Phase::shutting_down ? 0 : 1;
            return;
        }
        if (phase == Phase::uninitialized) return;   // LSP 3.17: dropped before initialize
        const auto it = notifications.find(m.method);
        if (it == notifications.end()) {
            if (!m.method.starts_with("$/")) log(message_type::log, fmt::format("kerf lsp: unknown notification '{}' ignored", m.method));
            return;
        }
        try {
            it->second(m.params);
        } catch (const RpcError& e) {
            log(message_type::warning, fmt::format("kerf lsp: '{}': {}", m.method, e.what()));
        } catch (const std::exception& e) {
            log(message_type::error, fmt::format("kerf lsp: '{}' failed: {}", m.method, e.what()));
        }
    }

    void handle_response(const Message& m) {
        const auto it = pending.find(id_key(m.id));
        if (it == pending.end()) return;
        auto done = std::move(it->second);
        pending.erase(it);
        if (m.error) {
            log(message_type::log, fmt::format("kerf lsp: the client answered an error: {}", json::serialize(*m.error)));
            return;
        }
        done(m);
    }

    // --- documents ---------------------------------------------------------------------------

    void publish(const Document& doc, const Analysis& analysis, bool final) {
        const std::lock_guard lock(docs_mutex);
        const auto it = docs.find(doc.uri());
        if (it == docs.end() || it->second->version() != doc.version()) return;   // closed or superseded
        send(notification("textDocument/publishDiagnostics", publish_diagnostics(doc, analysis, final)));
    }

    void set_document(const std::shared_ptr<const Document>& doc) {
        {
            const std::lock_guard lock(docs_mutex);
            docs[doc->uri()] = doc;
        }
        const bool numbers = project.set_programs(doc->path(), ProjectSeam::programs_of(doc->path(), doc->typed()));
        if (!worker) return;
        worker->schedule(doc);
        // New program numbers: a call in another open document may reach a program now, or no more.
        if (numbers)
            for (const auto& [uri, other] : docs)
                if (other != doc) worker->schedule(other);
    }

    std::shared_ptr<const Document> open_document(const std::string& uri) const {
        const auto it = docs.find(uri);
        if (it == docs.end()) throw RpcError(error_code::invalid_params, fmt::format("'{}' is not open", uri));
        return it->second;
    }

    Snapshot snapshot(const json::value& params) {
        const std::shared_ptr<const Document> doc = open_document(document_uri(params));
        std::shared_ptr<const Analysis> analysis = worker ? worker->latest(doc->uri()) : nullptr;
        if (analysis && analysis->version != doc->version()) analysis.reset();
        return Snapshot{doc, std::move(analysis), docs, project, &running_cancel};
    }

    void did_open(json::value& params) {
        const json::object& td = object_param(params, "textDocument");
        const std::string uri = string_param(td, "uri");
        const fs::path path = uri_to_path(uri);
        std::string text = string_param(td, "text");
        const std::int64_t version = int_param(td, "version");
        // The message's copy goes before the document is parsed (memory: bench/RESULTS.md).
        if (json::value* sent = params.as_object().if_contains("textDocument")->as_object().if_contains("text")) *sent = nullptr;
        const auto settings = project.resolve(path, text);
        for (const std::string& p : settings->problems) log(message_type::warning, "kerf: " + p);
        const auto doc = Document::open(uri, path, version, std::move(text), settings);
        if (!doc->refused().empty()) log(message_type::warning, fmt::format("kerf lsp: {}: {}", uri, doc->refused()));
        set_document(doc);
    }

    // The current version of `uri`, taken out of the store with every other holder let go (the
    // analysis worker stops with it): an edit can then change it in place.
    std::shared_ptr<const Document> take_document(const std::string& uri) {
        std::shared_ptr<const Document> doc;
        {
            const std::lock_guard lock(docs_mutex);
            const auto it = docs.find(uri);
            if (it == docs.end()) throw RpcError(error_code::invalid_params, fmt::format("'{}' is not open", uri));
            doc = std::move(it->second);
            docs.erase(it);
        }
        if (worker) worker->release(uri);
        return doc;
    }

    void did_change(const json::value& params) {
        const json::object& td = object_param(params, "textDocument");
        const std::string uri = string_param(td, "uri");
        open_document(uri);   // an error for a document that is not open, before anything changes
        const json::value* changes = params_object(params).if_contains("contentChanges");
        if (!changes || !changes->is_array()) throw RpcError(error_code::invalid_params, "'contentChanges' must be an array");
        std::vector<ContentChange> list;
        for (const json::value& c : changes->as_array()) {
            if (!c.is_object()) throw RpcError(error_code::invalid_params, "a content change must be an object");
            ContentChange change;
            change.text = string_param(c.as_object(), "text");
            if (c.as_object().contains("range")) change.range = range_param(c.as_object(), "range");
            list.push_back(std::move(change));
        }
        const std::int64_t version = int_param(td, "version");
        std::shared_ptr<const Document> doc = take_document(uri);
        const bool was_refused = !doc->refused().empty();
        std::vector<std::string> problems;
        std::shared_ptr<const Document> next = Document::edit(std::move(doc), version, list, problems);
        for (const std::string& p : problems) log(message_type::warning, fmt::format("kerf lsp: {}: {}", uri, p));
        if (!next->refused().empty() && !was_refused) log(message_type::warning, fmt::format("kerf lsp: {}: {}", uri, next->refused()));
        // A dialect detected from the text may change with the header: resolve again when the edit
        // reached the first lines (detection weighs the header first).
        if (next->settings().detected && touches_head(list)) {
            const auto settings = project.resolve(next->path(), next->text());
            if (settings->dialect != next->settings().dialect) next = next->with_settings(settings);
        }
        set_document(next);
    }

    static bool touches_head(const std::vector<ContentChange>& changes) {
        for (const ContentChange& c : changes)
            if (!c.range || c.range->first.line < 32) return true;
        return false;
    }

    void did_close(const json::value& params) {
        const std::string uri = document_uri(params);
        fs::path path;
        {
            const std::lock_guard lock(docs_mutex);
            const auto it = docs.find(uri);
            if (it == docs.end()) return;
            path = it->second->path();
            docs.erase(it);
        }
        if (worker) worker->forget(uri);
        send(notification("textDocument/publishDiagnostics", json::object{{"uri", uri}, {"diagnostics", json::array{}}}));
        // The file on disk counts again in the index (or nothing, when there is none), and the
        // other documents' calls are checked against it.
        if (const auto text = read_disk(path)) project.update_file(path, *text);
        else project.remove_file(path);
        reanalyse_documents();
    }

    // Every open document under the current settings again (a new dialect parses it again).
    void refresh_documents() {
        std::vector<std::shared_ptr<const Document>> open;
        for (const auto& [uri, doc] : docs) open.push_back(doc);
        for (const auto& doc : open) {
            const auto settings = project.resolve(doc->path(), doc->text());
            set_document(doc->with_settings(settings));
        }
    }

    void reanalyse_documents() {
        if (!worker) return;
        for (const auto& [uri, doc] : docs) worker->schedule(doc);
    }

    // --- configuration and the workspace ------------------------------------------------------

    void apply_settings(const json::value& kerf) {
        ClientSettings s = project.client();
        const auto text = [&](std::string_view key, std::string& out) {
            if (const json::value* v = find_path(kerf, {key}); v && v->is_string()) out = std::string(v->as_string());
            else if (v && v->is_null()) out.clear();
        };
        text("dialect", s.dialect);
        text("machine", s.machine);
        text("language", s.language);
        text("baseline", s.baseline);
        if (s.language != "ru") s.language = "en";
        if (s == project.client()) return;
        project.set_client(s);
        log(message_type::info, fmt::format("kerf lsp: settings: dialect '{}', machine '{}', language {}", s.dialect.empty() ? "auto" : s.dialect,
                                            s.machine.empty() ? "(built-in)" : s.machine, s.language));
        refresh_documents();
    }

    void pull_settings() {
        request_client("workspace/configuration", json::object{{"items", json::array{json::object{{"section", "kerf"}}}}},
                       [this](const Message& m) {
                           if (m.result.is_array() && !m.result.as_array().empty() && m.result.as_array()[0].is_object())
                               apply_settings(m.result.as_array()[0]);
                       });
    }

    void start_indexing() {
        if (roots.empty()) return;
        if (index_thread.joinable()) index_thread.join();
        index_thread = std::thread([this, roots = roots] {
            for (const fs::path& root : roots) project.index_root(root);
            Incoming done;
            done.task = [this] {
                // Open documents win over their files on disk.
                for (const auto& [uri, doc] : docs) project.set_programs(doc->path(), ProjectSeam::programs_of(doc->path(), doc->typed()));
                log(message_type::info, fmt::format("kerf lsp: indexed {} programs in {} files", project.all_programs().size(), project.files().size()));
                reanalyse_documents();
            };
            push(std::move(done));
        });
    }

    void watched_files_changed(const json::value& params) {
        const json::value* changes = find_path(params, {"changes"});
        if (!changes || !changes->is_array()) throw RpcError(error_code::invalid_params, "'changes' must be an array");
        bool configs = false;
        for (const json::value& c : changes->as_array()) {
            const json::value* uri = find_path(c, {"uri"});
            const json::value* type = find_path(c, {"type"});
            if (!uri || !uri->is_string() || !type || !type->is_int64()) continue;
            const fs::path path = uri_to_path(std::string_view(uri->as_string()));
            const std::string ext = path.extension().string();
            if (path.filename() == ".kerf.toml" || ext == ".toml") {
                configs = true;
                continue;
            }
            bool open = false;
            for (const auto& [u, doc] : docs) open = open || doc->path() == path;
            if (open) continue;   // the open document wins over the file
            if (type->as_int64() == 3) project.remove_file(path);
            else if (is_program_file(path))
                if (const auto text = read_disk(path)) project.update_file(path, *text);
        }
        if (configs) {
            project.forget_configs();
            refresh_documents();
        } else {
            reanalyse_documents();
        }
    }

    json::value initialize(const json::value& params) {
        if (phase != Phase::uninitialized) throw RpcError(error_code::invalid_request, "'initialize' was already received");
        phase = Phase::running;
        pull_configuration = [&] {
            const json::value* v = find_path(params, {"capabilities", "workspace", "configuration"});
            return v && v->is_bool() && v->as_bool();
        }();
        watch_registration = [&] {
            const json::value* v = find_path(params, {"capabilities", "workspace", "didChangeWatchedFiles", "dynamicRegistration"});
            return v && v->is_bool() && v->as_bool();
        }();
        if (const json::value* folders = find_path(params, {"workspaceFolders"}); folders && folders->is_array()) {
            for (const json::value& f : folders->as_array())
                if (const json::value* uri = find_path(f, {"uri"}); uri && uri->is_string())
                    roots.push_back(uri_to_path(std::string_view(uri->as_string())));
        }
        if (const json::value* root = find_path(params, {"rootUri"}); roots.empty() && root && root->is_string())
            roots.push_back(uri_to_path(std::string_view(root->as_string())));
        std::erase_if(roots, [](const fs::path& p) { return p.empty(); });
        ClientSettings s;
        if (const json::value* locale = find_path(params, {"locale"}); locale && locale->is_string() && locale->as_string().starts_with("ru"))
            s.language = "ru";
        project.set_client(s);
        if (const json::value* init = find_path(params, {"initializationOptions"}); init && init->is_object()) {
            const json::value* kerf = find_path(*init, {"kerf"});
            apply_settings(kerf && kerf->is_object() ? *kerf : *init);
        }
        json::object sync{{"openClose", true}, {"change", 2}, {"save", json::object{{"includeText", false}}}};
        json::object capabilities{
            {"positionEncoding", "utf-16"},
            {"textDocumentSync", sync},
            {"hoverProvider", true},
            {"definitionProvider", true},
            {"referencesProvider", true},
            {"documentHighlightProvider", true},
            {"renameProvider", json::object{{"prepareProvider", true}}},
            {"completionProvider", json::object{{"triggerCharacters", json::array{"G", "M", "g", "m", "P", "p", "Q", "#", " "}},
                                                {"resolveProvider", false}}},
            {"semanticTokensProvider", json::object{{"legend", semantic_tokens_legend()}, {"full", true}, {"range", true}}},
            {"foldingRangeProvider", true},
            {"inlayHintProvider", true},
            {"documentSymbolProvider", true},
            {"workspaceSymbolProvider", true},
            {"codeActionProvider", json::object{{"codeActionKinds", json::array{"quickfix", "source.fixAll.kerf", "refactor.rewrite", "source.convert.kerf"}},
                                                {"resolveProvider", true}}},
            {"documentFormattingProvider", true},
            {"documentRangeFormattingProvider", true},
            {"codeLensProvider", json::object{{"resolveProvider", false}}},
            {"callHierarchyProvider", true},
            {"selectionRangeProvider", true},
            {"workspace", json::object{{"workspaceFolders", json::object{{"supported", true}, {"changeNotifications", true}}}}},
        };
        return json::object{{"capabilities", capabilities}, {"serverInfo", json::object{{"name", "kerf"}, {"version", "0.1.0"}}}};
    }

    void initialized() {
        if (pull_configuration) pull_settings();
        if (watch_registration) {
            json::array watchers;
            for (const char* glob : {"**/*.{nc,NC,ngc,NGC,tap,TAP,cnc,CNC,mpf,MPF,eia,EIA,txt}", "**/O[0-9]*", "**/.kerf.toml", "**/*.toml"})
                watchers.push_back(json::object{{"globPattern", glob}});
            request_client("client/registerCapability",
                           json::object{{"registrations", json::array{json::object{{"id", "kerf-watch"},
                                                                                    {"method", "workspace/didChangeWatchedFiles"},
                                                                                    {"registerOptions", json::object{{"watchers", watchers}}}}}}},
                           [](const Message&) {});
        }
        start_indexing();
    }

    // --- the handler table -------------------------------------------------------------------

    void register_handlers() {
        requests["initialize"] = [this](const json::value& p) { return initialize(p); };
        requests["shutdown"] = [this](const json::value&) -> json::value {
            phase = Phase::shutting_down;
            return nullptr;
        };
        notifications["initialized"] = [this](const json::value&) { initialized(); };
        notifications["textDocument/didOpen"] = [this](json::value& p) { did_open(p); };
        notifications["textDocument/didChange"] = [this](const json::value& p) { did_change(p); };
        notifications["textDocument/didClose"] = [this](const json::value& p) { did_close(p); };
        notifications["textDocument/didSave"] = [](const json::value&) {};
        notifications["workspace/didChangeConfiguration"] = [this](const json::value& p) {
            const json::value* kerf = find_path(p, {"settings", "kerf"});
            if (kerf && kerf->is_object()) apply_settings(*kerf);
            else if (pull_configuration) pull_settings();
        };
        notifications["workspace/didChangeWatchedFiles"] = [this](const json::value& p) { watched_files_changed(p); };
        notifications["workspace/didChangeWorkspaceFolders"] = [this](const json::value& p) {
            if (const json::value* added = find_path(p, {"event", "added"}); added && added->is_array())
                for (const json::value& f : added->as_array())
                    if (const json::value* uri = find_path(f, {"uri"}); uri && uri->is_string())
                        roots.push_back(uri_to_path(std::string_view(uri->as_string())));
            start_indexing();
        };
        notifications["$/cancelRequest"] = [](const json::value&) {};   // noted by the reader

        const auto at = [](const json::value& p) { return position_param(params_object(p), "position"); };
        requests["textDocument/hover"] = [this, at](const json::value& p) { return hover(snapshot(p), at(p)); };
        requests["textDocument/definition"] = [this, at](const json::value& p) { return definition(snapshot(p), at(p)); };
        requests["textDocument/references"] = [this, at](const json::value& p) {
            const json::value* decl = find_path(p, {"context", "includeDeclaration"});
            return references(snapshot(p), at(p), decl && decl->is_bool() && decl->as_bool());
        };
        requests["textDocument/documentHighlight"] = [this, at](const json::value& p) { return document_highlight(snapshot(p), at(p)); };
        requests["textDocument/prepareRename"] = [this, at](const json::value& p) { return prepare_rename(snapshot(p), at(p)); };
        requests["textDocument/rename"] = [this, at](const json::value& p) {
            return rename(snapshot(p), at(p), string_param(params_object(p), "newName"));
        };
        requests["textDocument/completion"] = [this, at](const json::value& p) { return completion(snapshot(p), at(p)); };
        requests["textDocument/semanticTokens/full"] = [this](const json::value& p) { return semantic_tokens(snapshot(p), std::nullopt); };
        requests["textDocument/semanticTokens/range"] = [this](const json::value& p) {
            return semantic_tokens(snapshot(p), range_param(params_object(p), "range"));
        };
        requests["textDocument/foldingRange"] = [this](const json::value& p) { return folding_ranges(snapshot(p)); };
        requests["textDocument/inlayHint"] = [this](const json::value& p) { return inlay_hints(snapshot(p), range_param(params_object(p), "range")); };
        requests["textDocument/documentSymbol"] = [this](const json::value& p) { return document_symbols(snapshot(p)); };
        requests["workspace/symbol"] = [this](const json::value& p) {
            const json::value* q = find_path(p, {"query"});
            return workspace_symbols(docs, project, q && q->is_string() ? std::string(q->as_string()) : std::string());
        };
        requests["textDocument/codeAction"] = [this](const json::value& p) {
            const json::value* context = find_path(p, {"context"});
            return code_actions(snapshot(p), range_param(params_object(p), "range"), context ? *context : json::value());
        };
        requests["codeAction/resolve"] = [this](const json::value& p) {
            const json::value* uri = find_path(p, {"data", "uri"});
            if (!uri || !uri->is_string()) throw RpcError(error_code::invalid_params, "the code action has no data.uri");
            return resolve_code_action(snapshot(json::object{{"textDocument", json::object{{"uri", *uri}}}}), params_object(p));
        };
        requests["textDocument/formatting"] = [this](const json::value& p) { return formatting(snapshot(p)); };
        requests["textDocument/rangeFormatting"] = [this](const json::value& p) { return range_formatting(snapshot(p), range_param(params_object(p), "range")); };
        requests["textDocument/codeLens"] = [this](const json::value& p) { return code_lens(snapshot(p)); };
        requests["textDocument/prepareCallHierarchy"] = [this, at](const json::value& p) { return prepare_call_hierarchy(snapshot(p), at(p)); };
        requests["callHierarchy/incomingCalls"] = [this](const json::value& p) { return incoming_calls(docs, project, object_param(p, "item")); };
        requests["callHierarchy/outgoingCalls"] = [this](const json::value& p) { return outgoing_calls(docs, project, object_param(p, "item")); };
        requests["textDocument/selectionRange"] = [this](const json::value& p) {
            const json::value* list = find_path(p, {"positions"});
            if (!list || !list->is_array()) throw RpcError(error_code::invalid_params, "'positions' must be an array");
            std::vector<ast::Position> at_list;
            for (const json::value& v : list->as_array()) {
                if (!v.is_object()) throw RpcError(error_code::invalid_params, "a position must be an object");
                json::object wrapper{{"p", v}};
                at_list.push_back(position_param(wrapper, "p"));
            }
            return selection_ranges(snapshot(p), at_list);
        };
        // Test and benchmark hook: answers once the analysis of every scheduled version is done.
        requests["kerf/waitForAnalysis"] = [this](const json::value&) -> json::value {
            if (worker) worker->wait_idle();
            return nullptr;
        };
    }
};

Server::Server(int in_fd, int out_fd, ServerOptions options) : impl_(std::make_unique<Impl>(in_fd, out_fd, std::move(options))) {}
Server::~Server() = default;
int Server::run() { return impl_->run(); }
void Server::interrupt() { impl_->transport.interrupt(); }

std::shared_ptr<const Document> Snapshot::document_at(const fs::path& path) const {
    for (const auto& [uri, open_doc] : open)
        if (open_doc->path() == path) return open_doc;
    const std::optional<std::string> text = project.read(path);
    if (!text) return nullptr;
    return Document::open(path_to_uri(path), path, 0, *text, project.resolve(path, *text));
}

}  // namespace kerf::lsp
