// kerf plot FILE [-o OUT.svg] [--frame part|all] [--dialect D] [--machine M.toml] [--lenient]: the
// toolpath of the dry run as SVG (plot/svg.hpp), framed on the part or on the whole path. Alarms are
// reported as by `kerf run`, and the picture still shows what ran up to them.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/dry_run.hpp"
#include "plot/svg.hpp"
#include "project/writer.hpp"

namespace kerf::cli {

namespace {

struct PlotCliOptions {
    DryRunOptions run;
    std::string output;   // "" = stdout
    std::string frame = "part";
};

// "file.nc (dialect)": the picture says what it shows.
std::string title_of(const project::DryRun& run, const std::string& file) {
    return fmt::format("{} ({})", std::filesystem::path(file).filename().string(), run.choice.id);
}

// Written only after the run, and atomically (project/writer.hpp): never half a picture; an
// unwritable file is exit 2.
bool write_svg(const std::string& svg, const std::string& output) {
    if (output.empty()) {
        std::cout << svg;
        return static_cast<bool>(std::cout.flush());
    }
    if (const auto error = project::write_atomically(output, svg)) {
        std::cerr << fmt::format("{}: error: cannot write the picture: {}\n", output, *error);
        return false;
    }
    return true;
}

int run_plot(const PlotCliOptions& o) {
    auto prepared = prepare(o.run);
    if (const int* code = std::get_if<int>(&prepared)) return *code;
    project::DryRun& run = *std::get<std::unique_ptr<project::DryRun>>(prepared);
    // The toolpath is built and simplified while the run goes on: no event is kept (plot/toolpath.hpp).
    const plot::Frame frame = o.frame == "all" ? plot::Frame::all : plot::Frame::part;
    plot::ToolpathSink sink({run.dialect->machine, run.setup.diameter_x, frame});
    const interpreter::RunResult result = project::execute(run, sink, o.run.lenient);
    const plot::SvgOptions options{run.dialect->machine, run.setup.diameter_x, title_of(run, o.run.file), frame};
    const std::string svg = plot::render_svg(std::move(sink).finish(), options);
    const int code = report_alarms(run, result, o.run.lenient);
    return write_svg(svg, o.output) ? code : kExitUsage;
}

}  // namespace

Command add_plot_command(CLI::App& app) {
    auto o = std::make_shared<PlotCliOptions>();
    CLI::App* cmd = app.add_subcommand("plot", "draw the toolpath of a dry run as SVG (lathes Z-X, mills X-Y)");
    add_dry_run_options(*cmd, o->run);
    cmd->add_option("-o,--output", o->output, "write the SVG to this file (default: stdout)");
    cmd->add_option("--frame", o->frame,
                    "what the picture frames: part (the cutting moves; rapids that leave it are cut off at its edge "
                    "with an arrow) or all (the whole path, home returns included)")
        ->check(CLI::IsMember({"part", "all"}));
    return [o] { return run_plot(*o); };
}

}  // namespace kerf::cli
