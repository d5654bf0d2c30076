// `kerf fmt` on one text, as the command line and the language server run it: dialect and Setup
// resolved by the workspace (the machine's decimal-point mode decides `decimal_point = add`), a
// text with syntax errors refused, the formatter run, and with `verify` both texts dry-run and
// compared (subprograms through the program index). The style is the caller's: the project's
// [format] table (Project::config().format) with the command line's flags over it.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "formatter/style.hpp"
#include "project/workspace.hpp"

namespace kerf::project {

struct FormatOutcome {
    std::optional<std::string> formatted;   // nullopt: not formatted (messages say why); the file is left as it is
    bool changed = false;                   // formatted differs from the text
    std::vector<std::string> messages;      // "file:line:col: error: ... [S0103]" lines, hints, refusals
    std::vector<Problem> problems;          // with errors: the file could not be formatted at all (exit 2)
};

FormatOutcome format_text(Workspace& workspace, const std::filesystem::path& file, std::string text,
                          const formatter::Style& style, bool verify);

}  // namespace kerf::project
