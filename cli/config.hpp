// Project configuration (.kerf.toml, found by walking up from a file) and dialect selection.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dialects/dialect.hpp"

namespace kerf::cli {

struct ProjectConfig {
    std::optional<std::filesystem::path> path;   // the .kerf.toml found, if any
    std::string dialect;                         // "" or "auto": detect
    std::vector<std::filesystem::path> dialect_files;
    std::optional<std::filesystem::path> machine_file;   // `machine = "..."`, relative to the .kerf.toml
};

// Walks up from `start` (a file or folder) to the first .kerf.toml. Errors go to `errors`.
ProjectConfig find_config(const std::filesystem::path& start, std::vector<std::string>& errors);

std::optional<std::string> read_file(const std::filesystem::path& path, std::string& error);

// The registry: built-in dialects plus user dialect files (flags, then config).
struct RegistryResult {
    dialects::Registry registry;
    std::vector<std::string> errors;
};
RegistryResult make_registry(const std::vector<std::filesystem::path>& dialect_files);

// Exit codes (design.md): 0 clean, 1 findings, 2 usage or I/O error.
inline constexpr int kExitClean = 0;
inline constexpr int kExitFindings = 1;
inline constexpr int kExitUsage = 2;

}  // namespace kerf::cli
