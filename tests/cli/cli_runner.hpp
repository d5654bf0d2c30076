// Runs the kerf binary from a CLI test: stdout, stderr and the exit code, plus temp-file helpers.
#pragma once

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>

namespace kerf::test {

struct CliRun {
    int code = -1;
    std::string out;
    std::string err;
};

inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline std::filesystem::path write_text(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// Quoted for the shell.
inline std::string shell_quote(const std::filesystem::path& p) {
    std::string quoted = "'";
    quoted += p.string();
    quoted += '\'';
    return quoted;
}

// `kerf <args>` with stdin from /dev/null; `work` holds the captured stderr.
inline CliRun run_kerf(const std::string& args, const std::filesystem::path& work) {
    std::filesystem::create_directories(work);
    const std::filesystem::path err = work / "stderr.txt";
    const std::string cmd = std::string(KERF_BINARY) + " " + args + " </dev/null 2>" + shell_quote(err);
    FILE* pipe = popen(cmd.c_str(), "r");
    REQUIRE(pipe);
    CliRun r;
    char buf[4096];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) r.out.append(buf, n);
    const int status = pclose(pipe);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.err = read_text(err);
    return r;
}

}  // namespace kerf::test
