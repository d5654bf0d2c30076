// Runs the kerf binary and measures it (issue 17: "a test for each item ... asserting the bounded
// time and memory, measured with getrusage"): fork, exec through `sh -c 'exec kerf ...'` (sh is
// replaced by kerf, so wait4 reports kerf's own peak resident memory and CPU time), wait4.
#pragma once

#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tests/cli/cli_runner.hpp"

namespace kerf::test {

struct MeasuredRun {
    int code = -1;          // exit code, -1 when killed by a signal
    std::string out;
    std::string err;
    double max_rss_mb = 0;  // peak resident set of the kerf process (getrusage via wait4)
    double cpu_s = 0;       // user + system time
    double wall_s = 0;
};

// Generous bounds for these tests; a sanitizer build (make test-sanitize) is several times slower
// and its allocator keeps freed memory in quarantine, so the bounds widen there.
#ifdef KERF_SANITIZE_BUILD
inline constexpr double kBoundScale = 6;
#else
inline constexpr double kBoundScale = 1;
#endif

// `kerf <args>` with stdout and stderr in files of `work`; `prefix` runs in the shell first
// (`ulimit -f 0; trap '' XFSZ;` to make writing fail).
inline MeasuredRun run_kerf_measured(const std::string& args, const std::filesystem::path& work,
                                     const std::string& prefix = "") {
    std::filesystem::create_directories(work);
    const std::filesystem::path out = work / "stdout.txt", err = work / "stderr.txt";
    const std::string cmd = prefix + "exec " + std::string(KERF_BINARY) + " " + args + " </dev/null >" + shell_quote(out) +
                            " 2>" + shell_quote(err);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    REQUIRE(wait4(pid, &status, 0, &usage) == pid);
    MeasuredRun r;
    r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.max_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024;   // Linux: kilobytes
    r.cpu_s = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
              static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
    r.out = read_text(out);
    r.err = read_text(err);
    return r;
}

// The bounds every command of these tests keeps.
inline void check_bounded(const MeasuredRun& r, double max_mb, double max_s) {
    INFO("peak RSS " << r.max_rss_mb << " MB, " << r.cpu_s << " s CPU, " << r.wall_s << " s wall");
    CHECK(r.code >= 0);   // not killed
    CHECK(r.max_rss_mb < max_mb * kBoundScale);
    CHECK(r.wall_s < max_s * kBoundScale);
}

}  // namespace kerf::test
