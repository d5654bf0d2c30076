// `kerf lsp`: the language server's protocol layer (clangd's ClangdLSPServer). A reader thread
// frames and parses messages and notes cancellations; the message loop answers requests in order
// of arrival, keeps the open documents (document.hpp) and the project seam current, and hands
// every new document version to the analysis worker (analysis.hpp), which publishes diagnostics.
// Features are pure functions of a snapshot (features.hpp). Nothing here knows G-code.
//
// Robustness (issue 14): a body that is not JSON is answered with -32700, a message that is not
// JSON-RPC 2.0 with -32600, an unknown method with -32601, a request before `initialize` with
// -32002, bad parameters with -32602; broken framing is skipped up to the next header; what the
// server cannot use is said in a window/logMessage; it keeps serving. `shutdown` then `exit` ends
// it with 0; `exit` without `shutdown`, or the end of the input, with 1 (LSP 3.17).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>

namespace kerf::lsp {

struct ServerOptions {
    // Extra log lines (the --log file of `kerf lsp`); empty: none.
    std::function<void(std::string_view)> log;
    // Run the analysis worker (diagnostics); off only in tests of the protocol alone.
    bool analysis = true;
};

class Server {
public:
    Server(int in_fd, int out_fd, ServerOptions options = {});
    ~Server();
    Server(const Server&) = delete;
    Server& operator=(const Server&) = delete;

    // Serves until `exit` or the end of the input; the process exit code.
    int run();
    // Ends run() from another thread as if the input had ended (tests, signals).
    void interrupt();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace kerf::lsp
