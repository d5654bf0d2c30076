// kerf: one binary, subcommands (design.md "Command line").
#include <fmt/format.h>

#include <map>

#include "cli/commands.hpp"

int main(int argc, char** argv) {
    CLI::App app{"kerf: read, check and convert FANUC-family CNC programs"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "kerf 0.1.0");
    std::map<CLI::App*, kerf::cli::Command> commands;
    auto add = [&](const char* name, kerf::cli::Command command) {
        commands[app.get_subcommand(name)] = std::move(command);
    };
    add("parse", kerf::cli::add_parse_command(app));
    add("dialects", kerf::cli::add_dialects_command(app));
    add("explain", kerf::cli::add_explain_command(app));
    add("run", kerf::cli::add_run_command(app));
    add("plot", kerf::cli::add_plot_command(app));
    add("check", kerf::cli::add_check_command(app));
    add("fmt", kerf::cli::add_fmt_command(app));
    add("convert", kerf::cli::add_convert_command(app));
    add("lsp", kerf::cli::add_lsp_command(app));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : kerf::cli::kExitUsage;
    }
    for (CLI::App* sub : app.get_subcommands())
        if (const auto it = commands.find(sub); it != commands.end()) return it->second();
    return kerf::cli::kExitUsage;
}
