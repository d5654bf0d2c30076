// Dry-run benchmarks (bench/RESULTS.md, "Dry-run benchmark against LinuxCNC's rs274"). Reads the
// program named by $KERF_DRYRUN_FILE (default bench-dryrun-100mb.nc in the working directory;
// bench/dryrun_vs_rs274.sh generates it with `bench/gen_mill.py FILE 100 --runnable`, a program
// whose arcs are all valid, so the interpreter runs it to its M30).
//
//   BM_DryRunCount      parse + bind + interpreter::run of the whole file, events counted by a sink
//                       that does nothing else: the interpreter's own cost
//   BM_DryRunJsonLines  the same with the sink of `kerf run --trace` (cli/cmd_run.cpp): every event
//                       appended as its JSON line by interpreter::append_event_json + '\n' to a
//                       buffer that is discarded at 1 MiB instead of written: the cost of the
//                       streamed trace without the file system
//   BM_RunOnlyCount     interpreter::run alone on a file parsed and bound once (outside the timer):
//                       how the whole-file figure splits between the front end and the interpreter
//
// Each big iteration is one cold run: the text copy (it stands in for reading the file) and the
// destruction of the program set are outside the timer; parse, bind, the line index and the run
// are inside. Counters: MBps / best_MBps (decimal MB/s of the input), blocks_per_s (executed
// blocks over the best wall time), user_ms / sys_ms / minflt per iteration (bench/meter.hpp),
// front_ms / run_ms (the best iteration's split: ProgramSet::add = parse + bind + line index, then
// interpreter::run), blocks (executed), events, trace_MB (JSON bytes produced), completed (1 when
// the run reached M30 without an alarm; a benchmark whose run stops early reports an error).
//
// $KERF_BENCH_ITERS overrides the number of iterations (default 3).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "bench/bench_input.hpp"
#include "bench/meter.hpp"
#include "dialects/dialect.hpp"
#include "interpreter/default_setup.hpp"
#include "interpreter/interpreter.hpp"
#include "interpreter/trace_json.hpp"

namespace {

using kerf::bench::Meter;
namespace interp = kerf::interpreter;

std::string bench_file_path() { return kerf::bench::env_or("KERF_DRYRUN_FILE", "bench-dryrun-100mb.nc"); }

int big_iterations() { return kerf::bench::big_iterations(3); }

const kerf::bench::Input& input() {
    static const kerf::bench::Input in = kerf::bench::read_input(bench_file_path(), "set KERF_DRYRUN_FILE, or generate it: python3 bench/gen_mill.py bench-dryrun-100mb.nc 100 --runnable");
    return in;
}

using kerf::bench::mill_dialect;

bool ready(benchmark::State& state) { return kerf::bench::ready(state, input()); }

// Counts events; nothing else (the sink's virtual call is the only cost).
class CountingSink : public interp::EventSink {
public:
    void on_event(const interp::Event& e) override {
        ++events;
        checksum += e.end[0];
    }
    std::uint64_t events = 0;
    double checksum = 0;
};

// `kerf run --trace`'s sink with the write left out: append_event_json into a buffer that is
// thrown away every 1 MiB (cmd_run.cpp flushes at the same size).
class JsonLinesDiscardSink : public interp::EventSink {
public:
    JsonLinesDiscardSink(const interp::ProgramSet& programs, const std::string& axes) : writer_(programs, axes) {
        buffer_.reserve(kFlush + 4096);
    }
    void on_event(const interp::Event& e) override {
        ++events;
        writer_.append(buffer_, e);
        buffer_.push_back('\n');
        if (buffer_.size() >= kFlush) flush();
    }
    void flush() {
        benchmark::DoNotOptimize(buffer_.data());
        bytes += buffer_.size();
        buffer_.clear();
    }
    std::uint64_t events = 0;
    std::uint64_t bytes = 0;

private:
    static constexpr std::size_t kFlush = 1 << 20;
    interp::TraceWriter writer_;
    fmt::memory_buffer buffer_;
};

struct Totals {
    double best_front_s = 0, best_run_s = 0, best_wall_s = 0;
    std::uint64_t blocks = 0, events = 0, trace_bytes = 0;
    bool completed = true;
};

void report(benchmark::State& state, const Meter& meter, const Totals& t, std::size_t bytes) {
    meter.report(state, bytes);
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
    state.counters["blocks"] = static_cast<double>(t.blocks);
    state.counters["events"] = static_cast<double>(t.events);
    if (meter.best_wall_s > 0) state.counters["blocks_per_s"] = static_cast<double>(t.blocks) / meter.best_wall_s;
    if (t.best_front_s > 0) state.counters["front_ms"] = t.best_front_s * 1e3;
    state.counters["run_ms"] = t.best_run_s * 1e3;
    if (t.trace_bytes) state.counters["trace_MB"] = static_cast<double>(t.trace_bytes) / 1e6;
    state.counters["completed"] = t.completed ? 1 : 0;
    if (!t.completed) state.SkipWithError("the run did not reach its end (alarm or step limit): not a whole-file figure");
}

using seconds = std::chrono::duration<double>;

// One cold dry run per iteration: ProgramSet::add (parse + bind + line index) and interpreter::run,
// with the sink made by `make_sink(programs, axes)`.
template <class MakeSink>
void dry_run_whole_file(benchmark::State& state, MakeSink make_sink) {
    if (!ready(state)) return;
    const std::string& text = *input().text;
    const kerf::dialects::Dialect& dialect = *mill_dialect();
    const interp::Setup setup = interp::default_setup(dialect);
    // The trace's axes as `kerf run` chooses them: the machine's, else the dialect's letters.
    const std::string axes = setup.axis_order.empty() ? dialect.lexical.axes : setup.axis_order;
    Meter meter;
    Totals t;
    for (auto _ : state) {
        state.PauseTiming();
        std::string copy = text;
        auto programs = std::make_unique<interp::ProgramSet>();
        const Meter::Mark start = Meter::mark();
        state.ResumeTiming();

        const std::uint32_t file = programs->add(bench_file_path(), std::move(copy), dialect);
        const auto front_end = std::chrono::steady_clock::now();
        auto sink = make_sink(*programs, axes);
        const std::optional<interp::ProgramRef> main = programs->first_program(file);
        interp::RunResult result;
        if (main) result = interp::run(*programs, *main, dialect, setup, *sink);
        if constexpr (requires { sink->flush(); }) sink->flush();
        benchmark::DoNotOptimize(result.final_position.data());
        benchmark::ClobberMemory();

        state.PauseTiming();
        const auto stop = std::chrono::steady_clock::now();
        meter.add_since(start);
        const double front = seconds(front_end - start.wall).count(), total = seconds(stop - start.wall).count();
        if (t.best_wall_s == 0 || total < t.best_wall_s) {
            t.best_wall_s = total;
            t.best_front_s = front;
            t.best_run_s = total - front;
        }
        t.blocks = result.blocks;
        t.events = sink->events;
        if constexpr (requires { sink->bytes; }) t.trace_bytes = sink->bytes;
        t.completed = t.completed && main && result.completed && result.alarms.empty();
        sink.reset();
        programs.reset();   // munmap of the tree: not part of the run
        state.ResumeTiming();
    }
    report(state, meter, t, text.size());
}

void BM_DryRunCount(benchmark::State& state) {
    dry_run_whole_file(state, [](const interp::ProgramSet&, const std::string&) { return std::make_unique<CountingSink>(); });
}
BENCHMARK(BM_DryRunCount)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(big_iterations());

void BM_DryRunJsonLines(benchmark::State& state) {
    dry_run_whole_file(state, [](const interp::ProgramSet& programs, const std::string& axes) {
        return std::make_unique<JsonLinesDiscardSink>(programs, axes);
    });
}
BENCHMARK(BM_DryRunJsonLines)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(big_iterations());

// The interpreter alone: the file is parsed and bound once; each iteration runs it again.
void BM_RunOnlyCount(benchmark::State& state) {
    if (!ready(state)) return;
    const std::string& text = *input().text;
    const kerf::dialects::Dialect& dialect = *mill_dialect();
    const interp::Setup setup = interp::default_setup(dialect);
    interp::ProgramSet programs;
    const std::uint32_t file = programs.add(bench_file_path(), text, dialect);
    const std::optional<interp::ProgramRef> main = programs.first_program(file);
    if (!main) {
        state.SkipWithError("no program in the file");
        return;
    }
    Meter meter;
    Totals t;
    for (auto _ : state) {
        state.PauseTiming();
        CountingSink sink;
        const Meter::Mark start = Meter::mark();
        state.ResumeTiming();

        const interp::RunResult result = interp::run(programs, *main, dialect, setup, sink);
        benchmark::DoNotOptimize(result.final_position.data());
        benchmark::ClobberMemory();

        state.PauseTiming();
        meter.add_since(start);
        t.best_run_s = meter.best_wall_s;
        t.blocks = result.blocks;
        t.events = sink.events;
        t.completed = t.completed && result.completed && result.alarms.empty();
        state.ResumeTiming();
    }
    report(state, meter, t, text.size());
}
BENCHMARK(BM_RunOnlyCount)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(big_iterations());

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    const std::string path = bench_file_path();
    benchmark::AddCustomContext("kerf_dryrun_file", path);
    if (input().text) {
        benchmark::AddCustomContext("kerf_dryrun_file_bytes", std::to_string(input().text->size()));
    } else {
        std::cerr << "kerf_bench_dryrun: " << input().error << "\n";
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return input().text ? 0 : 1;
}
