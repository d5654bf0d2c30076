// kerf run FILE [--dialect D] [--machine M.toml] [--json] [--trace OUT.jsonl]: the dry run.
#include <fmt/format.h>

#include <boost/json/serialize.hpp>
#include <fstream>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/dry_run.hpp"
#include "interpreter/trace_json.hpp"

namespace kerf::cli {

namespace {

struct RunCliOptions {
    DryRunOptions run;
    bool json = false;
    bool state = false;
    std::string trace;
};

// Streams the trace as JSON lines while the interpreter runs, through a buffer written in large
// pieces: memory stays flat however long the trace (docs/trace.md).
class JsonLinesSink : public interpreter::EventSink {
public:
    JsonLinesSink(std::ostream* out, const interpreter::ProgramSet& programs, const std::string& axes)
        : out_(out), writer_(programs, axes) {}
    ~JsonLinesSink() override { flush(); }
    JsonLinesSink(const JsonLinesSink&) = delete;
    JsonLinesSink& operator=(const JsonLinesSink&) = delete;
    void on_event(const interpreter::Event& e) override {
        if (!out_) return;
        writer_.append(buffer_, e);
        buffer_.push_back('\n');
        if (buffer_.size() >= kFlushBytes) flush();
    }
    void flush() {
        if (out_ && buffer_.size() > 0) out_->write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
        buffer_.clear();
    }

private:
    static constexpr std::size_t kFlushBytes = 1 << 20;
    std::ostream* out_;
    interpreter::TraceWriter writer_;
    fmt::memory_buffer buffer_;
};

// A distance in mm, and in inches too for a program that works in inches.
std::string distance(double mm, bool inch) {
    return inch ? fmt::format("{:.1f} mm ({:.3f} in)", mm, mm / 25.4) : fmt::format("{:.1f} mm", mm);
}

void print_summary(std::ostream& out, const project::DryRun& run, const interpreter::RunResult& result, const std::string& axes) {
    std::string final_position;
    for (std::size_t a = 0; a < interpreter::kAxisCount; ++a)
        if (axes.find(interpreter::kAxisLetters[a]) != std::string::npos)
            final_position += fmt::format(" {}{:.3f}", interpreter::kAxisLetters[a], result.final_position[a]);
    out << fmt::format("dialect {}\nblocks executed {}\ncycle time {:.1f} s ({:.2f} min)\n", run.choice.id,
                             result.blocks, result.total_time_s, result.total_time_s / 60);
    out << fmt::format("feed distance {}, rapid distance {}\nfinal position{} ({})\n",
                             distance(result.feed_distance_mm, result.inch), distance(result.rapid_distance_mm, result.inch),
                             final_position, result.inch ? "inch" : "mm");
    for (const auto& [tool, seconds] : result.time_per_tool_s) out << fmt::format("tool {:>3}: {:.1f} s\n", tool, seconds);
    if (result.repeats)
        out << fmt::format("ended normally; the program repeats (M99 in the main program): {} pass{} run, times "
                                 "are for {} (--passes N)\n",
                                 result.passes, result.passes == 1 ? "" : "es", result.passes == 1 ? "one pass" : "them");
    else
        out << (result.completed ? "ended normally\n" : "did not reach its end\n");
}

int run_run(const RunCliOptions& o) {
    auto prepared = prepare(o.run);
    if (const int* code = std::get_if<int>(&prepared)) return *code;
    project::DryRun& run = *std::get<std::unique_ptr<project::DryRun>>(prepared);
    // `--trace -`: the trace on standard output (as `fmt -` reads standard input), and the summary
    // on standard error so that standard output is JSON lines only.
    const bool trace_to_stdout = o.trace == "-";
    std::ofstream trace_file;
    if (!o.trace.empty() && !trace_to_stdout) {
        trace_file.open(o.trace, std::ios::binary);
        if (!trace_file) {
            std::cerr << fmt::format("kerf: {}: cannot write the trace\n", o.trace);
            return kExitUsage;
        }
    }
    // The machine's axes (a lathe has no Y even where the dialect knows the letter).
    const std::string axes = run.setup.axis_order.empty() ? run.dialect->lexical.axes : run.setup.axis_order;
    std::ostream* trace_out = trace_to_stdout ? &std::cout : o.trace.empty() ? nullptr : &trace_file;
    JsonLinesSink sink(trace_out, run.programs, axes);
    const interpreter::RunResult result = project::execute(run, sink, o.run.lenient, o.state);
    sink.flush();
    std::ostream& summary = trace_to_stdout ? std::cerr : std::cout;
    if (o.json)
        summary << boost::json::serialize(interpreter::summary_to_json(result, axes)) << "\n";
    else
        print_summary(summary, run, result, axes);
    return report_alarms(run, result, o.run.lenient);
}

}  // namespace

Command add_run_command(CLI::App& app) {
    auto o = std::make_shared<RunCliOptions>();
    CLI::App* cmd = app.add_subcommand("run", "dry-run a program: cycle time, distances, final position, alarms");
    add_dry_run_options(*cmd, o->run);
    cmd->add_flag("--json", o->json, "the summary as JSON");
    cmd->add_option("--trace", o->trace, "write the trace as JSON lines to this file (- : standard output, the summary then on standard error)");
    cmd->add_flag("--state", o->state, "with --trace: a `state` line (active modal codes, F S T) after every block");
    return [o] { return run_run(*o); };
}

}  // namespace kerf::cli
