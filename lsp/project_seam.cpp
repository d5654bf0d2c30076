#include "lsp/project_seam.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "grammar/detect.hpp"
#include "interpreter/default_setup.hpp"
#include "project/files.hpp"
#include "project/scan.hpp"

namespace kerf::lsp {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// The open documents over the disk, read where they are (project::OverlayFileSystem keeps a copy
// of each text, which for an open million-line document is a 30 MB copy per keystroke: the
// server's store already holds the text, so this file system asks the store).
class OpenDocumentsFileSystem : public project::FileSystem {
public:
    explicit OpenDocumentsFileSystem(ProjectSeam::Reader open) : open_(std::move(open)) {}
    using project::FileSystem::read;
    // An open document is the editor's text (already decoded); a file is read and decoded from disk.
    project::ReadResult read(const fs::path& path, const ast::InputLimits& limits) const override {
        project::ReadResult r;
        if ((r.text = open_(path, std::string::npos))) return r;
        return disk_.read(path, limits);
    }
    project::ReadResult read_head(const fs::path& path, std::size_t bytes) const override {
        project::ReadResult r;
        if ((r.text = open_(path, bytes))) return r;
        return disk_.read_head(path, bytes);
    }
    bool is_file(const fs::path& path) const override { return open_(path, 0).has_value() || disk_.is_file(path); }
    std::vector<fs::path> files_in(const fs::path& folder) const override { return disk_.files_in(folder); }

private:
    ProjectSeam::Reader open_;
    project::DiskFileSystem disk_;
};

// The program's first comment: on its O line or the comment-only lines right after it.
std::string first_comment(const ast::TypedFile& typed, const ast::Program& p) {
    const ast::SyntaxTree& tree = typed.tree();
    for (std::uint32_t b = p.first_block; b < p.end_block && b < p.first_block + 3; ++b) {
        for (const std::uint32_t t : typed.block(b).comments()) {
            std::string_view s = tree.spelling(tree.tokens[t]);
            if (!s.empty() && s.front() == '(') s.remove_prefix(1);
            if (!s.empty() && s.back() == ')') s.remove_suffix(1);
            while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
            while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
            return std::string(s);
        }
        const ast::BlockKind kind = tree.blocks[b].kind;
        if (b > p.first_block && kind != ast::BlockKind::comment_only && kind != ast::BlockKind::blank) break;
    }
    return {};
}

IndexedProgram from_index(const project::IndexedProgram& p) {
    return {p.file, p.program.number, p.program.program_index, p.program.begin, p.program.end, p.program.comment};
}

std::vector<IndexedProgram> with_file(const fs::path& file, const std::vector<project::ScannedProgram>& programs) {
    std::vector<IndexedProgram> out;
    out.reserve(programs.size());
    for (const project::ScannedProgram& p : programs) out.push_back(from_index({file, p}));
    return out;
}

// The entries of a baseline that name `file`: the path as `kerf check` wrote it, absolute or
// relative to the baseline's folder (the usual: run from the repository root).
void load_baseline(const project::FileSystem& files, const fs::path& baseline, const fs::path& file, FileSettings& s) {
    const project::ReadResult read = files.read(baseline);
    if (!read.text) {
        s.problems.push_back(fmt::format("{}: cannot read the baseline (kerf.baseline)", baseline.string()));
        return;
    }
    std::string error;
    const auto entries = analyzer::read_baseline(*read.text, error);
    if (!entries) {
        s.problems.push_back(fmt::format("{}: {}", baseline.string(), error));
        return;
    }
    for (const analyzer::BaselineEntry& e : *entries) {
        const fs::path named(e.file);
        const fs::path absolute = named.is_absolute() ? named : (baseline.parent_path() / named);
        if (absolute.lexically_normal() == file.lexically_normal()) s.baseline.push_back(e);
    }
}

project::Overrides overrides_of(const ClientSettings& client) {
    project::Overrides o;
    o.dialect = client.dialect;
    o.machine = client.machine;
    o.dialect_origin = "the client setting kerf.dialect";
    o.machine_origin = "the client setting kerf.machine";
    return o;
}

}  // namespace

bool is_program_file(const fs::path& path) {
    static const std::string kExtensions[] = {".nc", ".ngc", ".tap", ".cnc", ".mpf", ".eia", ".txt"};
    const std::string ext = lower(path.extension().string());
    if (std::find(std::begin(kExtensions), std::end(kExtensions), ext) != std::end(kExtensions)) return true;
    if (!ext.empty()) return false;
    const std::string name = path.filename().string();
    return name.size() >= 2 && (name[0] == 'O' || name[0] == 'o') &&
           std::all_of(name.begin() + 1, name.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

ProjectSeam::ProjectSeam(Reader open_documents)
    : files_(std::make_shared<OpenDocumentsFileSystem>(std::move(open_documents))), workspace_(files_) {}

void ProjectSeam::set_client(ClientSettings settings) {
    const std::lock_guard lock(mutex_);
    if (overrides_of(settings).dialect != overrides_of(client_).dialect || settings.machine != client_.machine)
        workspace_.set_overrides(overrides_of(settings));
    client_ = std::move(settings);
    ++generation_;
}

ClientSettings ProjectSeam::client() const {
    const std::lock_guard lock(mutex_);
    return client_;
}

void ProjectSeam::forget_configs() {
    workspace_.forget_projects();
    ++generation_;
}

std::optional<fs::path> ProjectSeam::config_of(const fs::path& file) const { return workspace_.find_config(project::normal_path(file)); }

std::shared_ptr<const FileSettings> ProjectSeam::resolve(const fs::path& file, std::string_view text) {
    const ClientSettings client = this->client();
    const fs::path path = project::normal_path(file);
    const project::Resolved r = workspace_.resolve(path, text);
    auto s = std::make_shared<FileSettings>();
    for (const project::Problem& p : r.problems) s->problems.push_back(project::to_string(p));
    const project::Config& config = r.project->config();
    s->config_file = config.file;
    s->resolved = r;
    s->style = config.format;
    s->check = config.check;
    s->time_limit = r.project->limits().time_limit;
    s->language = client.language;
    // The registry lives as long as the project that holds it.
    s->registry = std::shared_ptr<const dialects::Registry>(r.project, &r.project->dialects());
    s->dialect = r.dialect;
    s->dialect_why = r.choice.why;
    s->detection = r.choice.evidence;
    s->detected = r.choice.source == project::DialectSource::detection;
    if (!s->dialect) {
        // An unknown dialect named by the setting or the .kerf.toml (a problem above): the text's own.
        const grammar::Detection d = grammar::detect_dialect(text);
        s->dialect = s->registry->find(d.dialect);
        s->dialect_why = fmt::format("{} detected from the text (the configured dialect is unknown)", d.dialect);
        s->detection = d.reasons;
        s->detected = true;
    }
    if (!s->dialect) return s;
    const fs::path& machine = r.project->machine_file();
    if (r.setup) {
        s->setup = *r.setup;
        s->machine_why = machine.empty() ? fmt::format("the built-in machine of {}", s->dialect->id) : machine.string();
    } else {
        s->setup = interpreter::default_setup(*s->dialect);
        s->machine_why = fmt::format("the built-in machine of {} ({} has errors)", s->dialect->id, machine.string());
    }
    s->format_context.calculator_decimal = s->setup.calculator_decimal;
    if (!client.baseline.empty()) load_baseline(*files_, fs::path(client.baseline), path, *s);
    return s;
}

void ProjectSeam::index_root(const fs::path& root) {
    std::error_code ec;
    workspace_.index_folder(root);
    fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec);
    if (ec) return;
    for (const fs::recursive_directory_iterator end; it != end; it.increment(ec)) {
        if (ec) break;
        const fs::directory_entry& entry = *it;
        if (!entry.is_directory(ec)) continue;
        const std::string name = entry.path().filename().string();
        if ((name.size() > 1 && name[0] == '.') || name == "node_modules" || name == "build") {
            it.disable_recursion_pending();
            continue;
        }
        workspace_.index_folder(entry.path());
    }
    ++generation_;
}

void ProjectSeam::update_file(const fs::path& file, std::string_view text) {
    const fs::path path = project::normal_path(file);
    const std::shared_ptr<const project::Project> p = workspace_.project_for(path);
    // The lexical rules of the file's dialect decide where its programs end (';', comments).
    const dialects::Dialect* d = p->dialects().find(project::choose_dialect(workspace_.overrides(), p->config(), text, p->dialects()).id);
    workspace_.index().update_file(path, text, d ? project::ScanRules::of(d->lexical) : project::ScanRules{});
    ++generation_;
}

std::vector<IndexedProgram> ProjectSeam::programs_of(const fs::path& file, const ast::TypedFile& typed) {
    std::vector<IndexedProgram> out;
    const ast::SyntaxTree& tree = typed.tree();
    for (std::uint32_t i = 0; i < typed.programs().size(); ++i) {
        const ast::Program& p = typed.programs()[i];
        if (!p.number) continue;
        const ast::Range first = tree.block_range(p.first_block);
        const std::uint32_t end = p.end_block < tree.block_count() ? tree.blocks[p.end_block].begin : static_cast<std::uint32_t>(tree.text.size());
        out.push_back({file, *p.number, i, first.begin, end, first_comment(typed, p)});
    }
    return out;
}

bool ProjectSeam::set_programs(const fs::path& file, std::vector<IndexedProgram> programs) {
    const fs::path path = project::normal_path(file);
    const std::vector<project::ScannedProgram> before = workspace_.index().programs_in(path);
    const bool same_numbers = std::equal(before.begin(), before.end(), programs.begin(), programs.end(),
                                         [](const project::ScannedProgram& a, const IndexedProgram& b) { return a.number == b.number; });
    std::vector<project::ScannedProgram> scanned;
    scanned.reserve(programs.size());
    for (IndexedProgram& p : programs) scanned.push_back({p.number, p.program_index, p.begin, p.end, std::move(p.comment)});
    workspace_.index().set_file(path, std::move(scanned));
    if (!same_numbers) ++generation_;
    return !same_numbers;
}

void ProjectSeam::remove_file(const fs::path& file) {
    workspace_.index().remove_file(project::normal_path(file));
    ++generation_;
}

std::optional<IndexedProgram> ProjectSeam::find_program(std::int64_t number, const fs::path& from, bool anywhere) {
    const fs::path path = project::normal_path(from);
    if (const std::optional<project::IndexedProgram> p = workspace_.find_program(number, path)) return from_index(*p);
    if (!anywhere) return std::nullopt;
    project::Scope everywhere;
    everywhere.everywhere = true;
    for (const project::IndexedProgram& p : workspace_.index().find_all(number, path, everywhere))
        if (p.file != path) return from_index(p);
    return std::nullopt;
}

std::vector<std::string> ProjectSeam::program_files(std::int64_t number, const fs::path& from) {
    std::vector<std::string> names;
    for (const project::IndexedProgram& p : workspace_.find_programs(number, project::normal_path(from))) names.push_back(p.file.string());
    return names;
}

std::vector<IndexedProgram> ProjectSeam::programs_in(const fs::path& file) const {
    const fs::path path = project::normal_path(file);
    return with_file(path, workspace_.index().programs_in(path));
}

std::vector<IndexedProgram> ProjectSeam::all_programs() const {
    std::vector<IndexedProgram> out;
    for (const fs::path& file : workspace_.index().files()) {
        std::vector<IndexedProgram> programs = with_file(file, workspace_.index().programs_in(file));
        out.insert(out.end(), std::make_move_iterator(programs.begin()), std::make_move_iterator(programs.end()));
    }
    return out;
}

std::vector<fs::path> ProjectSeam::files() const { return workspace_.index().files(); }

interpreter::ProgramSet::Loader ProjectSeam::loader_for(const fs::path& file) { return workspace_.loader_for(project::normal_path(file)); }

std::optional<std::string> ProjectSeam::read(const fs::path& file) const { return files_->read(file).text; }

}  // namespace kerf::lsp
