// `kerf convert` on one text, as the command line (and later the language server) runs it: the
// source dialect resolved by the workspace (or the --from override), the target looked up in the
// file's project registry, both machines read from one machine description (the machine file in
// force, else the source dialect's built-in machine, each side in its own dialect's reading), the
// conversion (converter/convert.hpp) and, with `verify`, both texts dry-run and compared motion
// for motion (interpreter/trace_compare.hpp). Subprograms in other files reach the output's run
// converted the same way.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "converter/convert.hpp"
#include "project/workspace.hpp"

namespace kerf::project {

struct ConvertSettings {
    std::string target;                                   // dialect id
    converter::IncrementalStyle incremental = converter::IncrementalStyle::g91;
    bool expand = false;
    bool verify = false;
};

struct ConvertReport {
    int line = 0, column = 0;   // 1-based, in the source text
    converter::ReportKind kind = converter::ReportKind::unconverted;
    std::string construct;
    std::string reason;
};

struct VerifyFailure {
    std::size_t event = 0;
    std::string input_file, output_file;   // the file of each side's block (a subprogram's file, or the converted one)
    int input_line = 0, output_line = 0;   // 1-based; 0 when that side has no such event
    std::string input_block, output_block;   // the blocks' text (shortened, printable)
    std::string what;
};

// Equal runs that both stopped at an alarm of the program: what follows it was not compared.
struct VerifyStop {
    int line = 0;      // 1-based, in the input
    int number = 0;    // as the control shows it
    std::string text;
};

struct ConvertOutcome {
    std::string from, to;                    // dialect ids
    std::optional<std::string> converted;    // nullopt: not converted at all (problems say why)
    std::vector<ConvertReport> reports;
    bool clean = false;                      // nothing left unconverted, no syntax error
    bool verified = false;                   // --verify ran and the traces agree
    std::size_t verified_events = 0;
    std::optional<VerifyFailure> verify_failure;
    std::optional<VerifyStop> verify_stopped;   // verified up to this alarm only
    std::vector<Problem> problems;           // errors: the file could not be converted (exit 2)
};

ConvertOutcome convert_text(Workspace& workspace, const std::filesystem::path& file, std::string text,
                            const ConvertSettings& settings);

// "file:line:col: not converted: G384: reason" lines and the --verify failure, for people.
std::vector<std::string> describe(const std::string& file, const ConvertOutcome& outcome);

}  // namespace kerf::project
