// The command line's bounds (ARCHITECTURE.md "Bounded resources"): --max-file-bytes and
// --max-line-bytes (the input decoder's limits, ast/input.hpp) and --time-limit (a dry run's wall
// clock). They override .kerf.toml's [limits] (project/config.hpp) through the workspace's
// Overrides.
#pragma once

#include <CLI/CLI.hpp>

#include "project/config.hpp"

namespace kerf::cli {

// --max-file-bytes, --max-line-bytes (sizes like 64K or 512M; 0 = no limit) and, for commands that
// dry-run the program (`runs`), --time-limit SECONDS (0 = none).
void add_limit_options(CLI::App& command, project::LimitSettings& flags, bool runs = true);

}  // namespace kerf::cli
