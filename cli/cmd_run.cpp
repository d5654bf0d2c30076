// kerf run FILE [--dialect D] [--json] [--trace OUT.jsonl]: the dry run.
#include <fmt/format.h>

#include <boost/json/serialize.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/config.hpp"
#include "grammar/detect.hpp"
#include "interpreter/default_setup.hpp"
#include "interpreter/interpreter.hpp"
#include "interpreter/trace_json.hpp"

namespace kerf::cli {

namespace fs = std::filesystem;

namespace {

struct RunCliOptions {
    std::string file;
    std::string dialect = "auto";
    std::vector<std::string> dialect_files;
    bool json = false;
    bool lenient = false;
    std::string trace;
};

// Streams the trace as JSON lines while the interpreter runs.
class JsonLinesSink : public interpreter::EventSink {
public:
    JsonLinesSink(std::ostream* out, const interpreter::ProgramSet& programs, std::string axes)
        : out_(out), programs_(programs), axes_(std::move(axes)) {}
    void on_event(const interpreter::Event& e) override {
        if (out_) *out_ << boost::json::serialize(interpreter::event_to_json(e, programs_, axes_)) << '\n';
        if (e.kind == interpreter::EventKind::alarm) alarms_.push_back(e);
    }
    std::vector<interpreter::Event> alarms_;

private:
    std::ostream* out_;
    const interpreter::ProgramSet& programs_;
    std::string axes_;
};

// Subprograms not in the file: the same folder, as O1000, O1000.nc or 1000.nc (issue 3).
std::optional<std::pair<std::string, std::string>> load_from_folder(const fs::path& folder, std::int64_t number) {
    const std::string o = fmt::format("O{:04}", number);
    for (const std::string& name : {o, o + ".nc", fmt::format("{:04}.nc", number), fmt::format("{}.nc", number)}) {
        const fs::path p = folder / name;
        std::error_code ec;
        if (!fs::is_regular_file(p, ec)) continue;
        std::string error;
        if (auto text = read_file(p, error)) return std::make_pair(p.string(), std::move(*text));
    }
    return std::nullopt;
}

int run_run(const RunCliOptions& o) {
    std::string error;
    auto text = read_file(o.file, error);
    if (!text) {
        std::cerr << "kerf: " << error << "\n";
        return kExitUsage;
    }
    std::vector<std::string> config_errors;
    const ProjectConfig config = find_config(o.file, config_errors);
    std::vector<fs::path> files(o.dialect_files.begin(), o.dialect_files.end());
    files.insert(files.end(), config.dialect_files.begin(), config.dialect_files.end());
    RegistryResult reg = make_registry(files);
    for (const std::string& e : config_errors) std::cerr << "kerf: " << e << "\n";
    for (const std::string& e : reg.errors) std::cerr << "kerf: " << e << "\n";
    std::string id = o.dialect != "auto" ? o.dialect : (!config.dialect.empty() && config.dialect != "auto" ? config.dialect : grammar::detect_dialect(*text).dialect);
    const dialects::Dialect* dialect = reg.registry.find(id);
    if (!dialect) {
        std::cerr << fmt::format("kerf: unknown dialect '{}'; `kerf dialects` lists them\n", id);
        return kExitUsage;
    }
    interpreter::ProgramSet programs;
    const std::uint32_t main_file = programs.add(o.file, std::move(*text), *dialect);
    const fs::path folder = fs::path(o.file).parent_path();
    programs.set_loader([folder](std::int64_t n) { return load_from_folder(folder, n); }, dialect);
    const auto main = programs.first_program(main_file);
    if (!main) {
        std::cerr << fmt::format("kerf: {}: no program to run\n", o.file);
        return kExitFindings;
    }
    const interpreter::Setup setup = interpreter::default_setup(*dialect);
    std::ofstream trace_file;
    std::ostream* trace = nullptr;
    if (!o.trace.empty()) {
        trace_file.open(o.trace, std::ios::binary);
        if (!trace_file) {
            std::cerr << fmt::format("kerf: {}: cannot write the trace\n", o.trace);
            return kExitUsage;
        }
        trace = &trace_file;
    }
    const std::string axes = dialect->lexical.axes;
    JsonLinesSink sink(trace, programs, axes);
    interpreter::RunOptions run_options;
    run_options.lenient = o.lenient;
    const interpreter::RunResult result = interpreter::run(programs, *main, *dialect, setup, sink, run_options);
    if (o.json) {
        std::cout << boost::json::serialize(interpreter::summary_to_json(result, axes)) << "\n";
    } else {
        std::string final_position;
        for (std::size_t a = 0; a < interpreter::kAxisCount; ++a)
            if (axes.find(interpreter::kAxisLetters[a]) != std::string::npos)
                final_position += fmt::format(" {}{:.3f}", interpreter::kAxisLetters[a], result.final_position[a]);
        std::cout << fmt::format("dialect {}\nblocks executed {}\ncycle time {:.1f} s ({:.2f} min)\n", id, result.blocks,
                                 result.total_time_s, result.total_time_s / 60);
        std::cout << fmt::format("feed distance {:.1f} mm, rapid distance {:.1f} mm\nfinal position{}\n",
                                 result.feed_distance_mm, result.rapid_distance_mm, final_position);
        for (const auto& [tool, seconds] : result.time_per_tool_s) std::cout << fmt::format("tool {:>3}: {:.1f} s\n", tool, seconds);
        std::cout << (result.completed ? "ended normally\n" : "did not reach its end\n");
    }
    for (const interpreter::Event& a : result.alarms)
        std::cerr << fmt::format("{}:{}: error: alarm {}: {}\n", programs.file(a.source.file).name, a.source.line, a.code, a.text);
    return result.alarms.empty() ? kExitClean : kExitFindings;
}

}  // namespace

Command add_run_command(CLI::App& app) {
    auto o = std::make_shared<RunCliOptions>();
    CLI::App* cmd = app.add_subcommand("run", "dry-run a program: cycle time, distances, final position, alarms");
    cmd->add_option("file", o->file, "program file")->required();
    cmd->add_option("--dialect", o->dialect, "dialect id, or auto (default)");
    cmd->add_option("--dialect-file", o->dialect_files, "load a dialect data file (TOML)");
    cmd->add_flag("--json", o->json, "the summary as JSON");
    cmd->add_flag("--lenient", o->lenient, "run blocks with syntax errors without their defective words");
    cmd->add_option("--trace", o->trace, "write the trace as JSON lines to this file");
    return [o] { return run_run(*o); };
}

}  // namespace kerf::cli
