// The program file a whole-file benchmark reads once, and the dialect it is run under, shared by
// bench_parse.cpp and bench_dryrun.cpp.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "dialects/dialect.hpp"

namespace kerf::bench {

// The environment variable `name`, or `fallback` when it is unset or empty.
inline std::string env_or(const char* name, const char* fallback) {
    const char* env = std::getenv(name);
    return env && *env ? env : fallback;
}

// KERF_BENCH_ITERS when it is a positive number, else `fallback`: the big benchmarks' iterations.
inline int big_iterations(int fallback) {
    const char* env = std::getenv("KERF_BENCH_ITERS");
    const int n = env ? std::atoi(env) : 0;
    return n > 0 ? n : fallback;
}

struct Input {
    std::optional<std::string> text;
    std::string error;   // why there is no text
};

// Reads `path`; `how_to_make` says how to get the file when it is missing.
inline Input read_input(const std::string& path, const std::string& how_to_make) {
    Input r;
    std::ifstream f(path, std::ios::binary);
    if (!f) {
        r.error = "cannot open " + path + " (" + how_to_make + ")";
        return r;
    }
    std::ostringstream ss;
    ss << f.rdbuf();
    if (ss.str().empty()) {
        r.error = path + " is empty";
        return r;
    }
    r.text = std::move(ss).str();
    return r;
}

// The generated programs are fanuc-mill.
inline const dialects::Dialect* mill_dialect() {
    static const dialects::Dialect* d = dialects::builtin_registry().find("fanuc-mill");
    return d;
}

// Skips the benchmark with a message if the input or the dialect is missing.
inline bool ready(benchmark::State& state, const Input& input) {
    if (!input.text) {
        state.SkipWithError(input.error.c_str());
        return false;
    }
    if (!mill_dialect()) {
        state.SkipWithError("dialect fanuc-mill is not in the built-in registry");
        return false;
    }
    return true;
}

}  // namespace kerf::bench
