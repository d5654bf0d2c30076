// kerf plot FILE [-o OUT.svg] [--dialect D] [--machine M.toml] [--lenient]: the toolpath of the dry
// run as SVG (plot/svg.hpp). Alarms are reported as by `kerf run`, and the picture still shows what
// ran up to them.
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/dry_run.hpp"
#include "plot/svg.hpp"

namespace kerf::cli {

namespace {

struct PlotCliOptions {
    DryRunOptions run;
    std::string output;   // "" = stdout
};

// "file.nc (dialect)": the picture says what it shows.
std::string title_of(const DryRun& run, const std::string& file) {
    return fmt::format("{} ({})", std::filesystem::path(file).filename().string(), run.dialect_id);
}

// Written only after the run, so a failed run leaves no half file; an unwritable file is exit 2.
bool write_svg(const std::string& svg, const std::string& output) {
    if (output.empty()) {
        std::cout << svg;
        return static_cast<bool>(std::cout.flush());
    }
    std::ofstream out(output, std::ios::binary);
    if (!(out << svg) || !out.flush()) {
        std::cerr << fmt::format("kerf: {}: cannot write the picture\n", output);
        return false;
    }
    return true;
}

int run_plot(const PlotCliOptions& o) {
    auto prepared = prepare_dry_run(o.run);
    if (const int* code = std::get_if<int>(&prepared)) return *code;
    DryRun& run = *std::get<std::unique_ptr<DryRun>>(prepared);
    interpreter::VectorSink sink;
    const interpreter::RunResult result = execute(run, sink);
    const plot::SvgOptions options{run.dialect->machine, run.setup.diameter_x, title_of(run, o.run.file)};
    const std::string svg = plot::render_svg(sink.events, options);
    const int code = report_alarms(run, result);
    return write_svg(svg, o.output) ? code : kExitUsage;
}

}  // namespace

Command add_plot_command(CLI::App& app) {
    auto o = std::make_shared<PlotCliOptions>();
    CLI::App* cmd = app.add_subcommand("plot", "draw the toolpath of a dry run as SVG (lathes Z-X, mills X-Y)");
    add_dry_run_options(*cmd, o->run);
    cmd->add_option("-o,--output", o->output, "write the SVG to this file (default: stdout)");
    return [o] { return run_plot(*o); };
}

}  // namespace kerf::cli
