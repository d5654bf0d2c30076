// One function per subcommand; each registers its options on the CLI11 app and returns the exit code.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace kerf::cli {

using Command = std::function<int()>;

Command add_parse_command(CLI::App& app);
Command add_dialects_command(CLI::App& app);
Command add_explain_command(CLI::App& app);
Command add_run_command(CLI::App& app);
Command add_plot_command(CLI::App& app);
Command add_check_command(CLI::App& app);
Command add_fmt_command(CLI::App& app);

}  // namespace kerf::cli
