#include "project/check.hpp"

#include <memory>

#include "analyzer/analyze.hpp"
#include "analyzer/fix.hpp"
#include "project/start.hpp"
#include "project/writer.hpp"

namespace kerf::project {

namespace fs = std::filesystem;
namespace an = analyzer;

an::CheckOptions project_check_options(const Resolved& r, interpreter::ProgramSet& programs, std::uint32_t file,
                                       const std::string& name) {
    an::CheckOptions options;
    // The dry run starts as [run] says (a caller's block for a macro library, preset variables,
    // passes); its problems were reported when the project was read.
    RunStart start = run_start(r.project->run_settings(), programs, file, *r.dialect, name);
    options.run = std::move(start.options);
    options.main = start.main;
    options.config = r.project->config().check;
    options.time_limit = r.project->limits().time_limit;
    options.resident = resident_programs(r.project->config().programs);
    if (r.choice.foreign) {
        // Detection found another control's program: the check says so once (K2009).
        const grammar::Detection::Foreign& f = *r.choice.foreign;
        options.foreign = an::ForeignControl{f.id, f.name, static_cast<std::uint32_t>(f.first.line),
                                             static_cast<std::uint32_t>(f.first.column), f.first.what, f.first.proves};
    }
    return options;
}

namespace {

struct Analysis {
    std::unique_ptr<interpreter::ProgramSet> programs = std::make_unique<interpreter::ProgramSet>();
    std::uint32_t file = 0;
    std::vector<an::Finding> findings;
};

Analysis analyze(Workspace& workspace, const fs::path& path, std::string text, const Resolved& r, std::size_t max_per_rule) {
    Analysis a;
    a.file = a.programs->add(path.string(), std::move(text), *r.dialect);
    a.programs->set_loader(workspace.loader_for(path), r.dialect);
    an::CheckOptions options = project_check_options(r, *a.programs, a.file, path.string());
    options.max_findings_per_rule = max_per_rule;
    options.program_files = [&workspace, path](std::int64_t number) {
        std::vector<std::string> names;
        for (const IndexedProgram& p : workspace.find_programs(number, path))
            names.push_back(Workspace::display_name(p.file, path).string());
        return names;
    };
    a.findings = an::check_file(*a.programs, a.file, *r.dialect, *r.setup, options);
    return a;
}

void report(const fs::path& path, Analysis& a, CheckedFile& out) {
    const std::string name = path.string();
    const interpreter::LoadedFile& loaded = a.programs->file(a.file);
    for (const an::Finding& f : a.findings)
        out.keys.push_back({name, f.rule, an::block_text(*loaded.whole_tree(), f.range.begin)});
    out.report = an::make_report(name, *loaded.whole_tree(), *loaded.whole_lines(), std::move(a.findings));
}

// `encoding`: the file's (ast/input.hpp), for writing the fixes back.
struct Source {
    std::string text;
    ast::Encoding encoding = ast::Encoding::utf8;
    bool bom = false;
};

CheckedFile check(Workspace& workspace, const fs::path& path, Source source, const CheckSettings& settings,
                  std::vector<Problem> problems) {
    CheckedFile out;
    out.problems = std::move(problems);
    const Resolved r = workspace.resolve(path, source.text);
    out.problems.insert(out.problems.end(), r.problems.begin(), r.problems.end());
    if (!r.ok() || has_errors(out.problems)) return out;
    const std::string original = settings.fix ? source.text : std::string();
    Analysis a = analyze(workspace, path, std::move(source.text), r, settings.max_findings_per_rule);
    if (settings.fix) {
        an::FixResult fixed = an::apply_fixes(original, a.findings);
        if (fixed.applied > 0) {
            // A file that cannot be written keeps its findings in the report: the error says why
            // they were not fixed (issue 17: in a read-only folder they vanished).
            if (const auto error = write_atomically(path, ast::encode_output(fixed.text, source.encoding, source.bom))) {
                out.problems.push_back({Level::error, path.string(), 0, 0,
                                        *error + "; nothing was fixed: its findings are reported as they are"});
            } else {
                out.fixed = fixed.applied;
                a = analyze(workspace, path, std::move(fixed.text), r, settings.max_findings_per_rule);
            }
        }
    }
    report(path, a, out);
    out.checked = true;
    return out;
}

}  // namespace

CheckedFile check_file(Workspace& workspace, const fs::path& file, const CheckSettings& settings) {
    ReadResult read = workspace.read(file);
    std::vector<Problem> problems = input_problems(file.string(), read.problems);
    if (!read.text) {
        CheckedFile out;
        out.problems = std::move(problems);
        if (!has_errors(out.problems)) out.problems.push_back({Level::error, file.string(), 0, 0, "cannot open file"});
        return out;
    }
    return check(workspace, file, {std::move(*read.text), read.encoding, read.bom}, settings, std::move(problems));
}

CheckedFile check_file(Workspace& workspace, const fs::path& file, bool fix) {
    CheckSettings settings;
    settings.fix = fix;
    return check_file(workspace, file, settings);
}

CheckedFile check_text(Workspace& workspace, const fs::path& file, std::string text, std::size_t max_findings_per_rule) {
    CheckSettings settings;
    settings.max_findings_per_rule = max_findings_per_rule;
    return check(workspace, file, {std::move(text)}, settings, {});
}

}  // namespace kerf::project
