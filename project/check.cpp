#include "project/check.hpp"

#include <memory>

#include "analyzer/analyze.hpp"
#include "analyzer/fix.hpp"
#include "project/writer.hpp"

namespace kerf::project {

namespace fs = std::filesystem;
namespace an = analyzer;

namespace {

struct Analysis {
    std::unique_ptr<interpreter::ProgramSet> programs = std::make_unique<interpreter::ProgramSet>();
    std::uint32_t file = 0;
    std::vector<an::Finding> findings;
};

Analysis analyze(Workspace& workspace, const fs::path& path, std::string text, const Resolved& r) {
    Analysis a;
    a.file = a.programs->add(path.string(), std::move(text), *r.dialect);
    a.programs->set_loader(workspace.loader_for(path), r.dialect);
    an::CheckOptions options;
    options.config = r.project->config().check;
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

CheckedFile check(Workspace& workspace, const fs::path& path, std::string text, bool fix) {
    CheckedFile out;
    const Resolved r = workspace.resolve(path, text);
    out.problems = r.problems;
    if (!r.ok() || has_errors(out.problems)) return out;
    const std::string original = fix ? text : std::string();
    Analysis a = analyze(workspace, path, std::move(text), r);
    if (fix) {
        an::FixResult fixed = an::apply_fixes(original, a.findings);
        if (fixed.applied > 0) {
            if (const auto error = write_atomically(path, fixed.text)) {
                out.problems.push_back({Level::error, path.string(), 0, 0, *error});
                return out;
            }
            out.fixed = fixed.applied;
            a = analyze(workspace, path, std::move(fixed.text), r);
        }
    }
    report(path, a, out);
    return out;
}

}  // namespace

CheckedFile check_file(Workspace& workspace, const fs::path& file, bool fix) {
    ReadResult read = workspace.read(file);
    if (!read.text) {
        CheckedFile out;
        out.problems.push_back({Level::error, file.string(), 0, 0, "cannot open file"});
        return out;
    }
    return check(workspace, file, std::move(*read.text), fix);
}

CheckedFile check_text(Workspace& workspace, const fs::path& file, std::string text) {
    return check(workspace, file, std::move(text), false);
}

}  // namespace kerf::project
