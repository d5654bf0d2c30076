// Runs the kerf binary from a CLI test: stdout, stderr and the exit code, plus temp-file helpers
// (read_text and write_text come from tests/shared_files.hpp).
#pragma once

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <sys/wait.h>

#include "tests/shared_files.hpp"

namespace kerf::test {

struct CliRun {
    int code = -1;
    std::string out;
    std::string err;
};

// Quoted for the shell (a ' inside becomes '\''). Appended piecewise: GCC 12 warns falsely on
// "'" + string + "'".
inline std::string shell_quote(const std::filesystem::path& p) {
    std::string quoted = "'";
    for (const char c : p.string()) {
        if (c == '\'') quoted += "'\\''";
        else quoted += c;
    }
    quoted += '\'';
    return quoted;
}

// What a shell command wrote to stdout, and its status as pclose gives it. REQUIREs the pipe.
// Where run_kerf keeps its stdin and stderr for the commands run on folder `dir`: beside the folder,
// not in it (a walk would read a .txt file there as a program).
inline std::filesystem::path runs_beside(const std::filesystem::path& dir) { return dir.string() + "-run"; }

struct Captured {
    std::string out;
    int status = -1;
};

inline Captured capture(const std::string& command) {
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe);
    Captured c;
    char buf[4096];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) c.out.append(buf, n);
    c.status = pclose(pipe);
    return c;
}

// `kerf <args>`; `work` holds the captured stderr. stdin is /dev/null, or a file `work`/stdin.txt
// holding `stdin_text` when one is given.
inline CliRun run_kerf(const std::string& args, const std::filesystem::path& work,
                       const std::optional<std::string>& stdin_text = std::nullopt) {
    std::filesystem::create_directories(work);
    const std::filesystem::path err = work / "stderr.txt";
    std::string input = "/dev/null";
    if (stdin_text) input = shell_quote(write_text(work / "stdin.txt", *stdin_text));
    const std::string cmd = std::string(KERF_BINARY) + " " + args + " <" + input + " 2>" + shell_quote(err);
    const Captured c = capture(cmd);
    CliRun r;
    r.out = c.out;
    r.code = WIFEXITED(c.status) ? WEXITSTATUS(c.status) : -1;
    r.err = read_text(err);
    return r;
}

}  // namespace kerf::test
