// The program index (project/index.hpp) on a folder of 10,000 program files (bench/index.sh makes
// it with gen_library.py; $KERF_BENCH_LIBRARY names it). Issue 12 asks for under 1 s.
//
//   BM_IndexFolder   a fresh Workspace::index_folder: list the folder, read each file's head,
//                    recognise it (project/recognize.hpp), read the rest, scan its O numbers
//                    (project/scan.hpp) and add it to the index - what the first M98 P/G65 P of a
//                    run or check in that folder costs; the files come from the page cache
//   BM_ScanTexts     scan_programs over the same texts already in memory: the scan alone
//   BM_Lookup        ProgramIndex::find of a random number from a file of the folder
//
// Counters: files, programs, MBps (bytes scanned per second).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <random>

#include "bench/bench_input.hpp"
#include "project/recognize.hpp"
#include "project/scan.hpp"
#include "project/workspace.hpp"

namespace fs = std::filesystem;
using namespace kerf;

namespace {

fs::path library() { return bench::env_or("KERF_BENCH_LIBRARY", "bench-library"); }

void BM_IndexFolder(benchmark::State& state) {
    const fs::path folder = project::normal_path(library());
    if (!fs::is_directory(folder)) {
        state.SkipWithError(("no folder " + folder.string() + " (bench/index.sh makes it)").c_str());
        return;
    }
    std::size_t files = 0, programs = 0;
    for (auto _ : state) {
        project::Workspace w;
        w.index_folder(folder);
        files = w.index().file_count();
        programs = w.index().program_count();
        benchmark::DoNotOptimize(programs);
    }
    state.counters["files"] = static_cast<double>(files);
    state.counters["programs"] = static_cast<double>(programs);
}
BENCHMARK(BM_IndexFolder)->Unit(benchmark::kMillisecond)->Iterations(bench::big_iterations(5));

std::vector<std::string> texts() {
    std::vector<std::string> out;
    project::DiskFileSystem disk;
    for (const fs::path& f : disk.files_in(library()))
        if (auto r = disk.read(f); r.text) out.push_back(std::move(*r.text));
    return out;
}

void BM_ScanTexts(benchmark::State& state) {
    const std::vector<std::string> all = texts();
    std::size_t bytes = 0;
    for (const std::string& t : all) bytes += t.size();
    for (auto _ : state)
        for (const std::string& t : all) benchmark::DoNotOptimize(project::scan_programs(t));
    state.counters["files"] = static_cast<double>(all.size());
    state.counters["MBps"] = benchmark::Counter(static_cast<double>(bytes) / 1e6, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_ScanTexts)->Unit(benchmark::kMillisecond)->Iterations(bench::big_iterations(5));

void BM_Lookup(benchmark::State& state) {
    project::Workspace w;
    const fs::path folder = project::normal_path(library());
    w.index_folder(folder);
    project::Scope scope;
    scope.folders.push_back(folder);
    std::mt19937 random(7);
    std::uniform_int_distribution<std::int64_t> number(1000, 1000 + static_cast<std::int64_t>(w.index().program_count()) - 1);
    for (auto _ : state) benchmark::DoNotOptimize(w.index().find(number(random), folder / "main.nc", scope));
}
BENCHMARK(BM_Lookup);

}  // namespace

BENCHMARK_MAIN();
