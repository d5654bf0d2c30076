// kerf lsp [--log FILE]: the language server on stdin/stdout (lsp/server.hpp). Thin: the server
// is the library; this only wires the standard streams and an optional log file.
#include <csignal>
#include <fstream>
#include <memory>
#include <mutex>

#include "cli/commands.hpp"
#include "lsp/server.hpp"

namespace kerf::cli {

Command add_lsp_command(CLI::App& app) {
    auto log = std::make_shared<std::string>();
    auto stdio = std::make_shared<bool>(true);
    CLI::App* cmd = app.add_subcommand("lsp", "the language server (LSP 3.17 on stdin/stdout) for editors");
    cmd->add_option("--log", *log, "append a log of the messages to this file");
    cmd->add_flag("--stdio", *stdio, "talk over stdin/stdout (the default and only transport; accepted for clients that pass it)");
    return [log] {
        std::signal(SIGPIPE, SIG_IGN);   // a client that goes away must not kill the server mid-write
        lsp::ServerOptions options;
        std::shared_ptr<std::ofstream> file;
        if (!log->empty()) {
            file = std::make_shared<std::ofstream>(*log, std::ios::app);
            auto mutex = std::make_shared<std::mutex>();
            options.log = [file, mutex](std::string_view line) {
                const std::lock_guard lock(*mutex);
                *file << line << '\n' << std::flush;
            };
        }
        lsp::Server server(0, 1, options);
        return server.run();
    };
}

}  // namespace kerf::cli
