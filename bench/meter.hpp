// Per-iteration CPU, page-fault and wall-time counters shared by the benchmarks in bench/.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstddef>

#include <sys/resource.h>

namespace kerf::bench {

// Per-iteration measurements of the timed region, on top of Google Benchmark's mean: user and
// system CPU time and minor page faults (how much of a cold parse is the kernel handing out fresh
// pages), and the best (shortest) wall time of the iterations. Each iteration of the whole-file
// benchmarks is one cold parse (or parse + run) of the whole file, so the best one is the figure
// least disturbed by other work on the machine.
struct Meter {
    double user_s = 0, sys_s = 0, minflt = 0;
    double best_wall_s = 0, total_wall_s = 0;

    struct Mark {
        double user_s, sys_s, minflt;
        std::chrono::steady_clock::time_point wall;
    };
    static Mark mark() {
        rusage r{};
        getrusage(RUSAGE_SELF, &r);
        return {static_cast<double>(r.ru_utime.tv_sec) + static_cast<double>(r.ru_utime.tv_usec) / 1e6,
                static_cast<double>(r.ru_stime.tv_sec) + static_cast<double>(r.ru_stime.tv_usec) / 1e6,
                static_cast<double>(r.ru_minflt), std::chrono::steady_clock::now()};
    }
    void add_since(const Mark& start) {
        const Mark end = mark();
        user_s += end.user_s - start.user_s;
        sys_s += end.sys_s - start.sys_s;
        minflt += end.minflt - start.minflt;
        const double wall = std::chrono::duration<double>(end.wall - start.wall).count();
        total_wall_s += wall;
        if (best_wall_s == 0 || wall < best_wall_s) best_wall_s = wall;
    }
    void report(benchmark::State& state, std::size_t bytes) const {
        const double n = static_cast<double>(std::max<benchmark::IterationCount>(1, state.iterations()));
        state.counters["user_ms"] = user_s * 1e3 / n;
        state.counters["sys_ms"] = sys_s * 1e3 / n;
        state.counters["minflt"] = minflt / n;
        // Decimal MB/s (1e6), as `kerf parse --stats` prints; Google Benchmark's bytes_per_second
        // column is in binary units (M = 2^20).
        state.counters["best_ms"] = best_wall_s * 1e3;
        if (best_wall_s > 0) state.counters["best_MBps"] = static_cast<double>(bytes) / 1e6 / best_wall_s;
        if (total_wall_s > 0) state.counters["MBps"] = static_cast<double>(bytes) * n / 1e6 / total_wall_s;
    }
};

}  // namespace kerf::bench
