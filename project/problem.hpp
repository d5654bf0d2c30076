// A problem of the project layer as a value: a .kerf.toml key, a dialect or machine file, a file
// that cannot be read. Every problem says where (file, and line:column when it is inside a TOML
// file) and what is wrong; the CLI prints it, the language server publishes it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ast/input.hpp"
#include "dialects/dialect.hpp"

namespace kerf::project {

enum class Level { error, warning, note };

struct Problem {
    Level level = Level::error;
    std::string file;      // the file concerned ("" when none)
    int line = 0;          // 1-based; 0 when the problem has no position
    int column = 0;
    std::string message;   // what is wrong and how to fix it
};

// "file:line:col: error: message" (the form of every kerf diagnostic), or "file: error: message"
// without a position.
std::string to_string(const Problem& p);

inline bool has_errors(const std::vector<Problem>& problems) {
    for (const Problem& p : problems)
        if (p.level == Level::error) return true;
    return false;
}

// The input decoder's problems about `file` (ast/input.hpp: a refusal is an error, "file is empty"
// a note), at their line (column 1) when they have one, the hint after the message.
std::vector<Problem> input_problems(const std::string& file, const std::vector<ast::InputProblem>& problems);

// A dialect or machine loader error (dialects/toml_errors.hpp): its message starts with its source
// ("<file>: <key>: what is wrong"), which the Problem names apart.
Problem from_load_error(std::string_view source, const dialects::LoadError& e);

}  // namespace kerf::project
