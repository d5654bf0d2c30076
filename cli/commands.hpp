// One function per subcommand; each registers its options on the CLI11 app and returns the exit
// code. The subcommands parse arguments and print; the work is the libraries' and the project
// layer's (project/workspace.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace kerf::cli {

using Command = std::function<int()>;

// Exit codes (design.md): 0 clean, 1 findings, 2 usage or I/O error.
inline constexpr int kExitClean = 0;
inline constexpr int kExitFindings = 1;
inline constexpr int kExitUsage = 2;

Command add_parse_command(CLI::App& app);
Command add_dialects_command(CLI::App& app);
Command add_explain_command(CLI::App& app);
Command add_run_command(CLI::App& app);
Command add_plot_command(CLI::App& app);
Command add_check_command(CLI::App& app);
Command add_fmt_command(CLI::App& app);
Command add_convert_command(CLI::App& app);
Command add_lsp_command(CLI::App& app);

}  // namespace kerf::cli
