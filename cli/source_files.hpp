// Which files a batch command (`kerf check`, `kerf fmt`) works on, and how it runs them on all cores.
// design.md "Command line": folders are walked recursively; batch work runs on all cores and shows
// a progress bar on a terminal.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::cli {

// NC program extensions, lower case, with the dot.
inline constexpr std::string_view kProgramExtensions[] = {".nc", ".ngc", ".tap", ".cnc", ".mpf", ".txt"};

// True when `head` (the first bytes of a file without extension) looks like an NC program: after an
// optional UTF-8 BOM, blanks and a `%` line, it starts with an O number (`O1000`, `:1000`) or a
// block number / G word. Binary data (a NUL byte) is never a program.
bool looks_like_program(std::string_view head);

struct SourceFiles {
    std::vector<std::filesystem::path> files;   // sorted, without duplicates, in argument order per argument
    std::vector<std::string> errors;            // "PATH: no such file or folder"
};

// Files named on the command line are always taken (whatever their extension); folders are walked
// recursively for files with a program extension (any case) or, without extension, program content.
// Hidden folders (.git, .kerf-cache) are skipped.
SourceFiles collect_source_files(const std::vector<std::filesystem::path>& arguments);

// Runs `work(i)` for i in [0, count) on `threads` threads (0: all cores). `work` must be safe to
// call concurrently for different i. `done(finished, count)` is called on the calling thread
// about every 100 ms and at the end, for a progress bar; it may be empty.
void run_parallel(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& work,
                  const std::function<void(std::size_t, std::size_t)>& done = {});

// A one-line progress bar on stderr when stderr is a terminal; nothing otherwise.
class ProgressBar {
public:
    explicit ProgressBar(std::string label);
    ~ProgressBar();   // clears the line
    void update(std::size_t finished, std::size_t total);

private:
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
};

}  // namespace kerf::cli
