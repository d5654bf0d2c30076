// What the batch commands print besides their results: the project layer's problems (once each)
// and a progress bar on a terminal.
#pragma once

#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "project/problem.hpp"

namespace kerf::cli {

// Problems on stderr as `file:line:col: error: message`, each text once however many files
// share it (one .kerf.toml governs a whole folder).
class ProblemPrinter {
public:
    // Prints the problems not printed before; true when any of `problems` is an error.
    bool print(const std::vector<project::Problem>& problems);

private:
    std::mutex mutex_;
    std::set<std::string> printed_;
};

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
