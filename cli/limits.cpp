#include "cli/limits.hpp"

#include <fmt/format.h>

namespace kerf::cli {

void add_limit_options(CLI::App& command, project::LimitSettings& flags, bool runs) {
    const ast::InputLimits defaults;
    command.add_option("--max-file-bytes", flags.max_file_bytes,
                       fmt::format("refuse files larger than this (default {} MiB; 64K, 512M ...; 0 = no limit)",
                                   defaults.max_file_bytes >> 20))
        ->transform(CLI::AsSizeValue(false));
    command.add_option("--max-line-bytes", flags.max_line_bytes,
                       fmt::format("refuse files with a line longer than this (default {} KiB; 0 = no limit)",
                                   defaults.max_line_bytes >> 10))
        ->transform(CLI::AsSizeValue(false));
    if (!runs) return;
    command.add_option("--time-limit", flags.time_limit_s,
                       fmt::format("stop a dry run after this many seconds with alarm 90005 (default {:g}; 0 = none)",
                                   project::kDefaultTimeLimitS))
        ->check(CLI::Range(0.0, 1e6));
}

}  // namespace kerf::cli
