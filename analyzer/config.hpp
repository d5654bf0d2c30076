// The analyzer's part of .kerf.toml: rule severities and on/off, and which files to check.
// Pure: it takes the TOML text; the project layer (project/config.hpp) finds and reads the file.
//
//   [check]
//   include = ["**/*.nc"]          # globs relative to the .kerf.toml folder; empty: every program a
//                                  # folder walk recognises; a file a glob names is taken even where
//                                  # its content does not look like a program (project/walk.hpp)
//   exclude = ["old/**"]           # never checked (the walk lists them as skipped)
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
    // The first include (exclude) glob that matches `relative`, or nullptr.
    const std::string* included_by(std::string_view relative) const;
    const std::string* excluded_by(std::string_view relative) const;
};

struct ConfigError {
    int line = 0;          // 1-based in the TOML text
    int column = 0;
    std::string message;   // "check.includ: unknown key; the keys of [check] are include, exclude, rules"
};

struct ConfigResult {
    CheckConfig config;
    std::vector<ConfigError> errors;   // in the order of the file
};

// The [check] table (and a top-level [rules] table) of a .kerf.toml text; other tables are the
// business of their owners (project/config.hpp reads the whole file). Strict: an unknown key, a
// wrong type, an unknown rule or severity is an error with its position.
ConfigResult parse_check_config(std::string_view toml_text);

// Globs: `*` any run without '/', `**` any run (also across '/'; `**/` may match nothing), `?` one
// character other than '/'.
bool glob_match(std::string_view pattern, std::string_view path);

std::optional<Severity> parse_severity(std::string_view text);   // nullopt for "off" and unknown words

}  // namespace kerf::analyzer
