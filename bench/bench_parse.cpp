// Parse benchmarks (bench/RESULTS.md). Reads the program named by $KERF_BENCH_FILE (default
// bench-100mb.nc in the working directory; bench/run.sh generates it with bench/gen_mill.py).
//
//   BM_ParseBind     grammar::parse + TypedFile::bind of the whole file: the requirement's figure
//   BM_ParseOnly     grammar::parse alone
//   BM_NaiveGetline  std::getline + std::istringstream word splitter: the comparison baseline
//   BM_SmallParseBind  parse + bind of a 4 KB slice, repeated: per-edit latency for the language server
//
// parse() takes the text by value and owns it, so the big benchmarks copy the text with the timer
// paused (the copy stands in for reading the file) and destroy the tree with the timer paused too.
// Each big iteration therefore measures one cold parse: the tree's arrays are fresh mmap'd memory
// every time, so their page faults are part of the figure, as they are for `kerf parse`.
//
// Counters of the big benchmarks: MBps (mean, decimal MB/s) and best_MBps / best_ms (the fastest
// iteration), user_ms / sys_ms / minflt (CPU time and minor page faults per iteration), tree_MB
// (bytes in the tree's arrays), blocks, tokens. Google Benchmark's own bytes_per_second column is in
// binary units (M/s = MiB/s).
//
// $KERF_BENCH_ITERS overrides the number of iterations of the big benchmarks (default 5; the naive
// baseline runs max(1, iters / 2)).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "ast/typed.hpp"
#include "bench/bench_input.hpp"
#include "bench/meter.hpp"
#include "dialects/dialect.hpp"
#include "grammar/parse.hpp"

namespace {

std::string bench_file_path() { return kerf::bench::env_or("KERF_BENCH_FILE", "bench-100mb.nc"); }

int big_iterations() { return kerf::bench::big_iterations(5); }

// The input, read once. nullopt (with `error` set) if the file is missing or empty.
const kerf::bench::Input& input() {
    static const kerf::bench::Input in = kerf::bench::read_input(bench_file_path(), "set KERF_BENCH_FILE, or generate it: python3 bench/gen_mill.py bench-100mb.nc 100");
    return in;
}

using kerf::bench::mill_dialect;

bool ready(benchmark::State& state) { return kerf::bench::ready(state, input()); }

// Bytes held by the tree's arrays (size, not capacity: reserved capacity that is never written
// costs address space only).
double tree_megabytes(const kerf::ast::SyntaxTree& t) {
    const std::size_t bytes = t.blocks.size() * sizeof(kerf::ast::Block) + t.tokens.size() * sizeof(kerf::ast::Token) +
                              t.exprs.size() * sizeof(kerf::ast::Expr) +
                              t.statements.size() * sizeof(kerf::ast::Statement) +
                              t.big_numbers.size() * sizeof(double);
    return static_cast<double>(bytes) / 1e6;
}

void report_tree(benchmark::State& state, const kerf::ast::SyntaxTree& tree, std::size_t diagnostics) {
    state.counters["blocks"] = static_cast<double>(tree.blocks.size());
    state.counters["tokens"] = static_cast<double>(tree.tokens.size());
    state.counters["tree_MB"] = tree_megabytes(tree);
    state.counters["diags"] = static_cast<double>(diagnostics);
}

using kerf::bench::Meter;

// Parses (and binds, when asked) the whole file once per iteration. The text copy and the tree's
// destruction (munmap of ~250 MB) happen with the timer paused: they are not parsing.
void parse_whole_file(benchmark::State& state, bool bind) {
    if (!ready(state)) return;
    const std::string& text = *input().text;
    const kerf::dialects::Dialect& dialect = *mill_dialect();
    Meter meter;
    for (auto _ : state) {
        state.PauseTiming();
        std::string copy = text;
        const Meter::Mark start = Meter::mark();
        state.ResumeTiming();

        kerf::ast::SyntaxTree tree = kerf::grammar::parse(std::move(copy), dialect.lexical);
        std::optional<kerf::ast::TypedFile> typed;
        if (bind) {
            typed.emplace(kerf::ast::TypedFile::bind(tree, dialect));
            benchmark::DoNotOptimize(typed->programs().data());
        }
        benchmark::DoNotOptimize(tree.tokens.data());
        benchmark::DoNotOptimize(tree.blocks.data());
        benchmark::ClobberMemory();

        state.PauseTiming();
        meter.add_since(start);
        report_tree(state, tree, tree.diagnostics.size() + (typed ? typed->diagnostics().size() : 0));
        if (typed) state.counters["programs"] = static_cast<double>(typed->programs().size());
        typed.reset();   // it points into the tree
        { kerf::ast::SyntaxTree dead = std::move(tree); }
        state.ResumeTiming();
    }
    meter.report(state, text.size());
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

// ---- (a) parse + bind of the whole file ----

void BM_ParseBind(benchmark::State& state) { parse_whole_file(state, true); }
BENCHMARK(BM_ParseBind)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(big_iterations());

// ---- (b) parse alone ----

void BM_ParseOnly(benchmark::State& state) { parse_whole_file(state, false); }
BENCHMARK(BM_ParseOnly)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(big_iterations());

// ---- (c) the naive baseline ----
//
// What a first attempt looks like: one std::getline per line, an std::istringstream per line, `>>`
// per word, the letter and std::strtod of the rest into a vector of structs. Parenthesised comments
// are skipped word by word. No expressions, no error recovery, no positions: it does much less than
// the real parser and is still the slow one.

struct NaiveWord {
    char letter;
    double value;
};
struct NaiveBlock {
    std::uint32_t first_word;
    std::uint32_t word_count;
};

void naive_parse(std::istream& in, std::vector<NaiveWord>& words, std::vector<NaiveBlock>& blocks) {
    std::string line;
    std::string w;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        NaiveBlock b{static_cast<std::uint32_t>(words.size()), 0};
        bool in_comment = false;
        while (ls >> w) {
            if (in_comment || w.front() == '(') {
                in_comment = w.back() != ')';
                continue;
            }
            if (w.front() == '%') continue;
            NaiveWord nw{static_cast<char>(std::toupper(static_cast<unsigned char>(w.front()))), 0.0};
            if (w.size() > 1) nw.value = std::strtod(w.c_str() + 1, nullptr);
            words.push_back(nw);
            ++b.word_count;
        }
        blocks.push_back(b);
    }
}

void BM_NaiveGetline(benchmark::State& state) {
    if (!input().text) {
        state.SkipWithError(input().error.c_str());
        return;
    }
    const std::string& text = *input().text;
    Meter meter;
    for (auto _ : state) {
        state.PauseTiming();
        std::istringstream in(text);   // the copy into the stream stands in for reading the file
        std::vector<NaiveWord> words;
        std::vector<NaiveBlock> blocks;
        const Meter::Mark start = Meter::mark();
        state.ResumeTiming();

        naive_parse(in, words, blocks);
        benchmark::DoNotOptimize(words.data());
        benchmark::DoNotOptimize(blocks.data());
        benchmark::ClobberMemory();

        state.PauseTiming();
        meter.add_since(start);
        state.counters["blocks"] = static_cast<double>(blocks.size());
        state.counters["words"] = static_cast<double>(words.size());
        state.ResumeTiming();
    }
    meter.report(state, text.size());
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_NaiveGetline)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(std::max(1, big_iterations() / 2));

// ---- (d) a 4 KB slice, repeated: what the language server pays per re-parse ----
//
// The slice is the start of the file (the '%' and O line included) cut back to a whole line. The
// copy of the 4 KB is inside the timed region here: pausing the timer costs more than copying it,
// and an editor holding the text must copy it for parse() anyway.

constexpr std::size_t kSmallSize = 4096;

void BM_SmallParseBind(benchmark::State& state) {
    if (!ready(state)) return;
    const std::string& text = *input().text;
    std::string slice = text.substr(0, std::min(kSmallSize, text.size()));
    if (const std::size_t nl = slice.rfind('\n'); nl != std::string::npos) slice.resize(nl + 1);
    const kerf::dialects::Dialect& dialect = *mill_dialect();
    std::size_t blocks = 0;
    for (auto _ : state) {
        std::string copy = slice;
        kerf::ast::SyntaxTree tree = kerf::grammar::parse(std::move(copy), dialect.lexical);
        const kerf::ast::TypedFile typed = kerf::ast::TypedFile::bind(tree, dialect);
        benchmark::DoNotOptimize(tree.tokens.data());
        benchmark::DoNotOptimize(typed.programs().data());
        benchmark::ClobberMemory();
        blocks = tree.blocks.size();
    }
    state.counters["slice_bytes"] = static_cast<double>(slice.size());
    state.counters["blocks"] = static_cast<double>(blocks);
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * slice.size()));
}
BENCHMARK(BM_SmallParseBind)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    const std::string path = bench_file_path();
    benchmark::AddCustomContext("kerf_bench_file", path);
    if (input().text) {
        benchmark::AddCustomContext("kerf_bench_file_bytes", std::to_string(input().text->size()));
    } else {
        std::cerr << "kerf_bench: " << input().error << "\n";
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return input().text ? 0 : 1;
}
