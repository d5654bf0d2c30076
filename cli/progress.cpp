#include "cli/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace kerf::cli {

bool ProblemPrinter::print(const std::vector<project::Problem>& problems) {
    const std::lock_guard lock(mutex_);
    for (const project::Problem& p : problems) {
        std::string line = project::to_string(p);
        if (p.file.empty()) line = "kerf: " + line;
        if (printed_.insert(line).second) std::cerr << line << "\n";
    }
    return project::has_errors(problems);
}

ProgressBar::ProgressBar(std::string label) : label_(std::move(label)), enabled_(isatty(STDERR_FILENO) != 0) {}

ProgressBar::~ProgressBar() {
    if (drawn_) std::fputs("\r\033[K", stderr);
}

void ProgressBar::update(std::size_t finished, std::size_t total) {
    if (!enabled_ || total < 2) return;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(kWidth * finished / total);
    fmt::print(stderr, "\r{} [{:=<{}}{: <{}}] {}/{}", label_, "", filled, "", kWidth - filled, finished, total);
    std::fflush(stderr);
    drawn_ = true;
}

}  // namespace kerf::cli
