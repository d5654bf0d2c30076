// `kerf check` on one file, as the command line and the language server run it: the text read
// (or given), project, dialect and Setup resolved by the workspace, subprograms reached through
// the program index, the [check] rule settings applied; with `fix`, the safe fixes written back
// atomically (project/writer.hpp) and the file checked again.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "analyzer/baseline.hpp"
#include "analyzer/output.hpp"
#include "project/workspace.hpp"

namespace kerf::project {

struct CheckedFile {
    analyzer::FileReport report;
    std::vector<analyzer::BaselineEntry> keys;   // one per finding of the report
    std::vector<Problem> problems;               // with errors: the file was not checked (exit 2)
    std::size_t fixed = 0;                       // fixes applied (check_file with fix)
};

// Reads `file` through the workspace and checks it; `name` is how reports name it.
CheckedFile check_file(Workspace& workspace, const std::filesystem::path& file, bool fix);
// Checks `text` as the contents of `file` (an open document): nothing is read or written but the
// subprograms its calls reach.
CheckedFile check_text(Workspace& workspace, const std::filesystem::path& file, std::string text);

}  // namespace kerf::project
