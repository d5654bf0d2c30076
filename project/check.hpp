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
#include "analyzer/analyze.hpp"
#include "analyzer/output.hpp"
#include "interpreter/program_set.hpp"
#include "project/workspace.hpp"

namespace kerf::project {

struct CheckedFile {
    analyzer::FileReport report;
    std::vector<analyzer::BaselineEntry> keys;   // one per finding of the report
    // With errors: exit 2. The file was not checked when `checked` is false (it cannot be read, the
    // decoder refuses it, its project is bad); a file checked whose fixes cannot be written has
    // its report, and the error says why nothing was fixed. Notes: the decoder's (an empty file).
    std::vector<Problem> problems;
    bool checked = false;
    std::size_t fixed = 0;                       // fixes applied (check_file with fix)
};

struct CheckSettings {
    bool fix = false;
    // Findings shown per rule and file before one "and N more" (analyzer::CheckOptions; 0 = all).
    std::size_t max_findings_per_rule = 100;
};

// The check options the project gives file `file` of `programs` (named `name`, resolved as `r`):
// the dry run's start ([run]: passes, preset variables, a caller's block, which may add a file to
// `programs`), the rule settings ([check]), the time limit ([limits]), the resident programs
// ([programs]) and a foreign control detection found. kerf check and the language server take the
// same; the caller adds what is its own (the cap per rule, the other files of a program).
analyzer::CheckOptions project_check_options(const Resolved& r, interpreter::ProgramSet& programs, std::uint32_t file,
                                             const std::string& name);

// Reads `file` through the workspace (decoded under its project's limits) and checks it; with
// `fix`, the fixed text is written back in the file's encoding.
CheckedFile check_file(Workspace& workspace, const std::filesystem::path& file, const CheckSettings& settings);
CheckedFile check_file(Workspace& workspace, const std::filesystem::path& file, bool fix);
// Checks `text` as the contents of `file` (an open document): nothing is read or written but the
// subprograms its calls reach.
CheckedFile check_text(Workspace& workspace, const std::filesystem::path& file, std::string text,
                       std::size_t max_findings_per_rule = 100);

}  // namespace kerf::project
