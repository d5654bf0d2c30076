// kerf convert FILE... | - --to D [--from D] [-o OUT] [--write] [--output-dir DIR] [--verify] [--expand]
//              [--incremental g91|letters] [--format human|json] [--dialect-file F] [--machine M]
//
// Converts programs to another dialect (converter/convert.hpp, docs/convert.md). One file (or `-`,
// standard input): the result on standard output or in -o OUT; several files or folders (walked as
// `kerf check` walks them, on all cores): --write replaces each file atomically (project/writer.hpp)
// and only when it converted cleanly, --output-dir writes the results under DIR. What could not be
// converted is reported with file:line:col and left as it is. Exit codes (design.md): 0 converted,
// 1 something was reported (or --verify found a difference, or a --write was refused), 2 usage or
// I/O error (an unknown dialect id names the valid ones).
#include <fmt/format.h>

#include <boost/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>

#include "ast/display.hpp"
#include "ast/input.hpp"
#include "cli/commands.hpp"
#include "cli/dry_run.hpp"
#include "cli/progress.hpp"
#include "project/convert.hpp"
#include "project/parallel.hpp"
#include "project/walk.hpp"
#include "project/writer.hpp"

namespace kerf::cli {

namespace {

namespace fs = std::filesystem;
namespace json = boost::json;

struct ConvertOptions {
    std::vector<std::string> paths;
    std::string to;
    std::string from = "auto";
    std::string output;
    std::string output_dir;
    bool write = false;
    bool verify = false;
    bool expand = false;
    std::string incremental = "g91";
    std::string format = "human";
    std::vector<std::string> dialect_files;
    std::string machine_file;
    project::LimitSettings limits;
};

struct FileResult {
    project::ConvertOutcome outcome;
    int usage_error = 0;
    ast::Encoding encoding = ast::Encoding::utf8;
    bool bom = false;
    std::string written;       // where the result went ("" when not written)
    std::string write_error;   // why it was not written
};

project::ConvertSettings settings_of(const ConvertOptions& o) {
    project::ConvertSettings s;
    s.target = o.to;
    s.incremental = o.incremental == "letters" ? converter::IncrementalStyle::letters : converter::IncrementalStyle::g91;
    s.expand = o.expand;
    s.verify = o.verify;
    return s;
}

// The target must be a dialect id the current folder's project knows: a usage error otherwise.
bool check_target(project::Workspace& w, const ConvertOptions& o, ProblemPrinter& problems) {
    const auto p = w.project_for(fs::current_path() / "-");
    problems.print(p->problems());
    if (p->dialects().find(o.to)) return true;
    std::cerr << fmt::format("kerf: --to: unknown dialect '{}' (known: {})\n", ast::printable(o.to), fmt::join(p->dialects().ids(), ", "));
    return false;
}

bool is_failure(const FileResult& r) {
    return !r.outcome.clean || r.outcome.verify_failure || !r.write_error.empty();
}

// Where --output-dir puts a file: its path under the folder argument it was found in, else its name.
fs::path output_path(const fs::path& dir, const fs::path& file, const std::vector<std::string>& arguments) {
    for (const std::string& a : arguments) {
        const fs::path arg = fs::path(a).lexically_normal();
        if (!fs::is_directory(arg)) continue;
        const fs::path rel = file.lexically_normal().lexically_relative(arg);
        if (!rel.empty() && *rel.begin() != "..") return dir / rel;
    }
    return dir / file.filename();
}

void write_result(const fs::path& path, const ConvertOptions& o, FileResult& r) {
    const project::ConvertOutcome& c = r.outcome;
    if (!c.converted) return;
    // A UTF-8 program is written as it is (a 100 MB file is not copied once more).
    std::string encoded;
    if (r.encoding != ast::Encoding::utf8) encoded = ast::encode_output(*c.converted, r.encoding, r.bom);
    const std::string_view bytes = r.encoding == ast::Encoding::utf8 ? std::string_view(*c.converted) : std::string_view(encoded);
    fs::path target;
    if (o.write) {
        // Nothing half-converted replaces a program: the file stays as it is (issue 16).
        if (!c.clean || c.verify_failure) {
            r.write_error = "not written: the conversion left something as it was (above); the file is unchanged";
            return;
        }
        target = path;
    } else if (!o.output_dir.empty()) {
        target = output_path(o.output_dir, path, o.paths);
        std::error_code ec;
        fs::create_directories(target.parent_path(), ec);
    } else if (!o.output.empty()) {
        target = o.output;
    } else {
        return;
    }
    if (const auto error = project::write_atomically(target, bytes)) {
        r.write_error = fmt::format("{}: {}", target.string(), *error);
        r.usage_error = kExitUsage;
        return;
    }
    r.written = target.string();
}

FileResult convert_file(project::Workspace& w, const fs::path& path, std::string text, const ConvertOptions& o,
                        ProblemPrinter& problems) {
    FileResult r;
    const std::shared_ptr<const project::Project> p = w.project_for(path);
    if (problems.print(p->problems())) {
        r.usage_error = kExitUsage;
        return r;
    }
    r.outcome = project::convert_text(w, path, std::move(text), settings_of(o));
    if (problems.print(r.outcome.problems)) r.usage_error = kExitUsage;
    return r;
}

json::object json_of(const fs::path& path, const FileResult& r, bool with_output) {
    const project::ConvertOutcome& c = r.outcome;
    json::object f;
    f["file"] = ast::valid_utf8(path.string());
    f["from"] = c.from;
    f["to"] = c.to;
    f["converted"] = c.converted.has_value();
    f["clean"] = c.clean;
    if (!r.written.empty()) f["written"] = ast::valid_utf8(r.written);
    if (!r.write_error.empty()) f["write_error"] = ast::valid_utf8(r.write_error);
    json::array reports;
    for (const project::ConvertReport& rep : c.reports)
        reports.push_back(json::object{{"line", rep.line},
                                       {"column", rep.column},
                                       {"kind", converter::to_string(rep.kind)},
                                       {"construct", ast::valid_utf8(rep.construct)},
                                       {"reason", ast::valid_utf8(rep.reason)}});
    f["reports"] = std::move(reports);
    if (c.verified || c.verify_failure) f["verified"] = c.verified;
    if (c.verify_stopped)
        f["verified_up_to_alarm"] = json::object{{"line", c.verify_stopped->line},
                                                 {"alarm", c.verify_stopped->number},
                                                 {"text", ast::valid_utf8(c.verify_stopped->text)}};
    if (c.verify_failure) {
        const project::VerifyFailure& v = *c.verify_failure;
        f["verify_failure"] = json::object{{"event", v.event},         {"input_file", ast::valid_utf8(v.input_file)},
                                           {"output_file", ast::valid_utf8(v.output_file)}, {"input_line", v.input_line},
                                           {"output_line", v.output_line}, {"input_block", ast::valid_utf8(v.input_block)},
                                           {"output_block", ast::valid_utf8(v.output_block)}, {"what", ast::valid_utf8(v.what)}};
    }
    if (with_output && c.converted) f["output"] = ast::valid_utf8(*c.converted);
    return f;
}

struct Summary {
    std::size_t files = 0, clean = 0, reported = 0, constructs = 0, verified = 0, verify_failed = 0, written = 0, errors = 0;
};

void count(Summary& s, const FileResult& r) {
    ++s.files;
    if (r.usage_error) {
        ++s.errors;
        return;
    }
    const project::ConvertOutcome& c = r.outcome;
    if (!c.converted) return;
    c.clean ? ++s.clean : ++s.reported;
    for (const project::ConvertReport& rep : c.reports)
        if (rep.kind == converter::ReportKind::unconverted || rep.kind == converter::ReportKind::syntax_error) ++s.constructs;
    if (c.verified) ++s.verified;
    if (c.verify_failure) ++s.verify_failed;
    if (!r.written.empty()) ++s.written;
}

void print_summary(const Summary& s, const ConvertOptions& o) {
    std::string line = fmt::format("kerf convert: {} file{} to {}: {} converted cleanly, {} with reports ({} construct{} left as {} were)",
                                   s.files, s.files == 1 ? "" : "s", o.to, s.clean, s.reported, s.constructs,
                                   s.constructs == 1 ? "" : "s", s.constructs == 1 ? "it" : "they");
    if (o.verify) line += fmt::format(", {} verified, {} differ", s.verified, s.verify_failed);
    if (o.write || !o.output_dir.empty()) line += fmt::format(", {} written", s.written);
    if (s.errors) line += fmt::format(", {} not read", s.errors);
    std::cerr << line << "\n";
}

int exit_code(const FileResult& r) {
    if (r.usage_error) return r.usage_error;
    if (!r.outcome.converted) return kExitUsage;
    return is_failure(r) ? kExitFindings : kExitClean;
}

int run_stdin(const ConvertOptions& o, project::Workspace& w, ProblemPrinter& problems) {
    std::string bytes(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>{});
    project::ReadResult read = project::decode_file("<stdin>", bytes, w.project_for("<stdin>")->limits().input);
    problems.print(project::input_problems("<stdin>", read.problems));
    if (!read.text) return kExitUsage;
    FileResult r = convert_file(w, "<stdin>", std::move(*read.text), o, problems);
    r.encoding = read.encoding;
    r.bom = read.bom;
    if (!r.usage_error) write_result("<stdin>", o, r);
    const bool to_stdout = o.output.empty();
    if (o.format == "json") {
        json::object doc{{"target", o.to}, {"files", json::array{json_of("<stdin>", r, to_stdout)}}};
        std::cout << json::serialize(doc) << "\n";
    } else {
        for (const std::string& line : project::describe("<stdin>", r.outcome)) std::cerr << line << "\n";
        if (!r.write_error.empty()) std::cerr << "<stdin>: error: " << r.write_error << "\n";
        if (to_stdout && r.outcome.converted) std::cout << ast::encode_output(*r.outcome.converted, r.encoding, r.bom);
    }
    return exit_code(r);
}

int run_convert(const ConvertOptions& o) {
    project::Workspace workspace(std::make_shared<project::DiskFileSystem>(),
                                 overrides_of(o.from, o.dialect_files, o.machine_file, o.limits));
    ProblemPrinter problems;
    if (!check_target(workspace, o, problems)) return kExitUsage;
    const bool stdin_path = std::find(o.paths.begin(), o.paths.end(), "-") != o.paths.end();
    if (stdin_path && (o.paths.size() > 1 || o.write || !o.output_dir.empty())) {
        std::cerr << "kerf: - (standard input) is converted alone, to standard output or -o OUT\n";
        return kExitUsage;
    }
    if (stdin_path) return run_stdin(o, workspace, problems);
    // Folders are walked as `kerf check` walks them ([check] include/exclude of each .kerf.toml).
    const project::WalkResult sources =
        project::collect_program_files({o.paths.begin(), o.paths.end()}, workspace.files(), workspace.check_selector());
    for (const std::string& e : sources.errors) std::cerr << "kerf: " << e << "\n";
    const bool single = !o.write && o.output_dir.empty();
    if (single && (sources.files.size() > 1 || (o.paths.size() == 1 && fs::is_directory(o.paths.front())))) {
        std::cerr << "kerf: convert prints one file; for several use --write or --output-dir DIR\n";
        return kExitUsage;
    }
    std::vector<FileResult> results(sources.files.size());
    ProgressBar bar("convert");
    project::run_parallel(
        sources.files.size(), 0,
        [&](std::size_t i) {
            const fs::path& path = sources.files[i];
            project::ReadResult read = workspace.read(path);
            std::vector<project::Problem> input = project::input_problems(path.string(), read.problems);
            if (!read.text && !project::has_errors(input)) input.push_back({project::Level::error, path.string(), 0, 0, "cannot open file"});
            problems.print(input);
            if (!read.text) {
                results[i].usage_error = kExitUsage;
                return;
            }
            results[i] = convert_file(workspace, path, std::move(*read.text), o, problems);
            results[i].encoding = read.encoding;
            results[i].bom = read.bom;
            if (!results[i].usage_error) write_result(path, o, results[i]);
        },
        [&](std::size_t done, std::size_t total) { bar.update(done, total); });
    int code = sources.errors.empty() ? kExitClean : kExitUsage;
    Summary summary;
    json::array files;
    const bool to_stdout = single && o.output.empty();
    for (std::size_t i = 0; i < sources.files.size(); ++i) {
        FileResult& r = results[i];
        const fs::path& path = sources.files[i];
        code = std::max(code, exit_code(r));
        count(summary, r);
        if (o.format == "json") {
            files.push_back(json_of(path, r, to_stdout));
            continue;
        }
        for (const std::string& line : project::describe(path.string(), r.outcome)) std::cerr << line << "\n";
        if (!r.write_error.empty()) std::cerr << path.string() << ": error: " << r.write_error << "\n";
        if (to_stdout && r.outcome.converted) std::cout << ast::encode_output(*r.outcome.converted, r.encoding, r.bom);
    }
    if (o.format == "json") {
        json::object doc{{"target", o.to}, {"files", std::move(files)}};
        doc["summary"] = json::object{{"files", summary.files},       {"clean", summary.clean},
                                      {"reported", summary.reported}, {"constructs", summary.constructs},
                                      {"verified", summary.verified}, {"verify_failed", summary.verify_failed},
                                      {"written", summary.written},   {"errors", summary.errors}};
        std::cout << json::serialize(doc) << "\n";
    } else if (!single) {
        print_summary(summary, o);
    }
    return code;
}

}  // namespace

Command add_convert_command(CLI::App& app) {
    auto o = std::make_shared<ConvertOptions>();
    CLI::App* cmd = app.add_subcommand("convert", "convert programs to another dialect by meaning (docs/convert.md)");
    cmd->add_option("paths", o->paths, "files or folders; - reads standard input")->required();
    cmd->add_option("--to", o->to, "the target dialect id (kerf dialects lists them)")->required();
    cmd->add_option("--from", o->from, "the source dialect id, or auto (default: configured or detected)");
    auto* out = cmd->add_option("-o,--output", o->output, "write the one converted file here instead of standard output");
    auto* write = cmd->add_flag("--write", o->write, "replace each file (atomically) when it converted cleanly")->excludes(out);
    cmd->add_option("--output-dir", o->output_dir, "write the converted files under this folder (same relative paths)")
        ->excludes(out)
        ->excludes(write);
    cmd->add_flag("--verify", o->verify, "dry-run input and output on the same machine and compare every motion");
    cmd->add_flag("--expand", o->expand, "replace what the target cannot express by the plain motion it makes");
    cmd->add_option("--incremental", o->incremental, "U/W into G90/G91 dialects: g91 (G91 X/Z, default) or letters (keep U/W)")
        ->check(CLI::IsMember({"g91", "letters"}));
    cmd->add_option("--format", o->format, "human (default) or json")->check(CLI::IsMember({"human", "json"}));
    cmd->add_option("--dialect-file", o->dialect_files, "load a dialect data file (TOML)");
    cmd->add_option("--machine", o->machine_file, "machine configuration file (TOML) both sides read");
    add_limit_options(*cmd, o->limits);
    return [o] { return run_convert(*o); };
}

}  // namespace kerf::cli
