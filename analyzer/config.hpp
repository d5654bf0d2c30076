// The analyzer's part of .kerf.toml: rule severities and on/off, and which files to check.
// Pure: it takes the TOML text; the CLI finds and reads the file.
//
//   [check]
//   include = ["**/*.nc"]          # globs relative to the .kerf.toml folder; empty: every program
//   exclude = ["old/**"]
//   [check.rules]                  # also accepted as a top-level [rules] table
//   K1020 = "off"                  # id or short name → "error" | "warning" | "info" | "hint" | "off"
//   duplicate-address = "error"
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analyzer/rule.hpp"

namespace kerf::analyzer {

struct CheckConfig {
    std::map<std::string, std::optional<Severity>, std::less<>> rules;   // nullopt = off
    std::vector<std::string> include;
    std::vector<std::string> exclude;

    bool enabled(const Rule& rule) const;
    Severity severity(const Rule& rule) const;
    // `relative` (with '/') is checked: matches an include glob (or there are none) and no exclude glob.
    bool selects(std::string_view relative) const;
};

struct ConfigResult {
    CheckConfig config;
    std::vector<std::string> errors;   // "<source>:line:col: what is wrong"
};

ConfigResult parse_check_config(std::string_view toml_text, std::string_view source);

// Globs: `*` any run without '/', `**` any run (also across '/'; `**/` may match nothing), `?` one
// character other than '/'.
bool glob_match(std::string_view pattern, std::string_view path);

std::optional<Severity> parse_severity(std::string_view text);   // nullopt for "off" and unknown words

}  // namespace kerf::analyzer
