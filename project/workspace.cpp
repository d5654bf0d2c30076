#include "project/workspace.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "grammar/detect.hpp"
#include "interpreter/default_setup.hpp"
#include "machine/machine.hpp"
#include "project/parallel.hpp"
#include "project/recognize.hpp"
#include "project/scan.hpp"

namespace kerf::project {

namespace fs = std::filesystem;

namespace {

const char* kind_name(dialects::MachineKind k) { return k == dialects::MachineKind::lathe ? "lathe" : "mill"; }

bool is_hidden(const fs::path& path) {
    const std::string name = path.filename().string();
    return name.size() > 1 && name[0] == '.';
}

// The machine of a file (machine/SCHEMA.md), resolved for the dialect ("dialect" values). Any load
// error is fatal: a misspelt key must not run with a default.
Project::SetupEntry load_setup(const fs::path& file, const dialects::Dialect& dialect, const FileSystem& files) {
    Project::SetupEntry entry;
    const ReadResult read = files.read(file);
    if (!read.text) {
        entry.problems.push_back({Level::error, file.string(), 0, 0, "cannot open file"});
        return entry;
    }
    const machine::LoadResult loaded = machine::load_machine_text(*read.text, file.string());
    for (const dialects::LoadError& e : loaded.errors) entry.problems.push_back(from_load_error(file.string(), e));
    if (!loaded.machine || !loaded.errors.empty()) return entry;
    const machine::Machine m = machine::resolve_for_dialect(*loaded.machine, dialect);
    if (m.kind != dialect.machine)
        entry.problems.push_back({Level::warning, file.string(), 0, 0,
                                  fmt::format("machine '{}' is a {} but dialect '{}' is for {}s", m.id, kind_name(m.kind),
                                              dialect.id, kind_name(dialect.machine))});
    entry.setup = interpreter::make_setup(m);
    entry.setup->machine_given = true;
    return entry;
}

}  // namespace

DialectChoice choose_dialect(const Overrides& overrides, const Config& config, std::string_view text,
                             const dialects::Registry& registry, const FolderRule& folder) {
    DialectChoice c;
    if (!overrides.dialect.empty() && overrides.dialect != "auto") {
        c.id = overrides.dialect;
        c.source = DialectSource::override_setting;
        c.why = fmt::format("dialect {} from {}", c.id, overrides.dialect_origin);
    } else if (!config.dialect.empty()) {
        c.id = config.dialect;
        c.source = DialectSource::config;
        c.why = fmt::format("dialect {} from {}", c.id, config.file.string());
    } else {
        grammar::Detection d = grammar::detect_dialect(text, registry);
        if (!d.evidence && folder) {
            if (const auto majority = folder())
                d = grammar::detect_dialect(text, registry, {majority->first, majority->second});
        }
        c.id = d.dialect;
        c.source = DialectSource::detection;
        c.no_evidence = !d.evidence;
        c.why = d.evidence ? fmt::format("dialect {} detected (score {})", c.id, d.confidence)
                           : fmt::format("dialect {}: no dialect evidence in the file", c.id);
        c.evidence = d.reasons;
        c.foreign = d.foreign;
    }
    return c;
}

DialectRegistry load_dialects(const std::vector<fs::path>& dialect_files, const FileSystem& files) {
    DialectRegistry r{dialects::builtin_registry(), {}};
    for (const fs::path& file : dialect_files) {
        const ReadResult read = files.read(file);
        if (!read.text) {
            r.problems.push_back({Level::error, file.string(), 0, 0, "cannot open file"});
            continue;
        }
        for (const dialects::LoadError& e : r.registry.add_text(*read.text, file.string()))
            r.problems.push_back(from_load_error(file.string(), e));
    }
    return r;
}

Project::Project(Config config, std::vector<Problem> problems, const Overrides& overrides, const FileSystem& files)
    : config_(std::move(config)), problems_(std::move(problems)), files_(files) {
    std::vector<fs::path> dialect_files = overrides.dialect_files;
    dialect_files.insert(dialect_files.end(), config_.dialect_files.begin(), config_.dialect_files.end());
    if (dialect_files.empty()) {
        registry_ = &dialects::builtin_registry();
    } else {
        DialectRegistry loaded = load_dialects(dialect_files, files);
        own_registry_.emplace(std::move(loaded.registry));
        registry_ = &*own_registry_;
        problems_.insert(problems_.end(), loaded.problems.begin(), loaded.problems.end());
    }
    machine_file_ = !overrides.machine.empty() ? overrides.machine : config_.machine.value_or(fs::path{});
    limits_ = resolve_limits(overrides.limits, config_.limits);
    run_ = config_.run;
    if (overrides.run.call) {
        run_.call = overrides.run.call;
        run_.call_everywhere = overrides.run.call_everywhere;
    }
    if (overrides.run.passes) run_.passes = overrides.run.passes;
    run_.set.insert(run_.set.end(), overrides.run.set.begin(), overrides.run.set.end());
}

const Project::SetupEntry& Project::setup(const dialects::Dialect& dialect) const {
    const std::lock_guard lock(setups_mutex_);
    std::unique_ptr<SetupEntry>& entry = setups_[dialect.id];
    if (!entry) {
        if (machine_file_.empty()) entry = std::make_unique<SetupEntry>(SetupEntry{interpreter::default_setup(dialect), {}});
        else entry = std::make_unique<SetupEntry>(load_setup(machine_file_, dialect, files_));
    }
    return *entry;
}

const Project::SetupEntry& Project::setup(const dialects::Dialect& dialect, const dialects::Dialect& machine_of) const {
    if (!machine_file_.empty() || dialect.id == machine_of.id) return setup(dialect);
    const std::lock_guard lock(setups_mutex_);
    std::unique_ptr<SetupEntry>& entry = setups_[machine_of.id + " as " + dialect.id];
    if (!entry) {
        const machine::Machine m = machine::resolve_for_dialect(machine::default_machine_for(machine_of), dialect);
        entry = std::make_unique<SetupEntry>(SetupEntry{interpreter::make_setup(m), {}});
    }
    return *entry;
}

Scope Project::program_scope(const fs::path& file) const {
    Scope scope;
    scope.folders.push_back(normal_path(file).parent_path());
    for (const fs::path& folder : config_.programs.library) scope.folders.push_back(normal_path(folder));
    return scope;
}

Workspace::Workspace(std::shared_ptr<const FileSystem> files, Overrides overrides)
    : files_(std::move(files)), overrides_(std::move(overrides)) {}

void Workspace::set_overrides(Overrides overrides) {
    const std::lock_guard lock(mutex_);
    overrides_ = std::move(overrides);
    projects_.clear();
    folder_votes_.clear();
}

Overrides Workspace::overrides() const {
    const std::lock_guard lock(mutex_);
    return overrides_;
}

void Workspace::forget_projects() {
    const std::lock_guard lock(mutex_);
    projects_.clear();
    config_of_.clear();
    folder_votes_.clear();
}

std::optional<std::pair<std::string, std::string>> Workspace::folder_dialect(const fs::path& file,
                                                                               const dialects::Registry& registry) {
    const fs::path self = normal_path(file);
    const std::pair key{self.parent_path(), &registry};
    std::vector<FolderVote> votes;
    bool cached = false;
    {
        const std::lock_guard lock(mutex_);
        if (const auto it = folder_votes_.find(key); it != folder_votes_.end()) {
            votes = it->second;
            cached = true;
        }
    }
    if (!cached) {
        std::vector<fs::path> files = files_->files_in(key.first);
        std::sort(files.begin(), files.end());
        std::size_t sampled = 0;
        for (const fs::path& f : files) {
            if (sampled == kFolderSample) break;
            if (is_hidden(f)) continue;
            const ReadResult head = files_->read_head(f, kRecognitionHead);
            if (!head.text || !recognize_program(f.filename().string(), *head.text).program) continue;
            ++sampled;
            const grammar::Detection d = grammar::detect_dialect(*head.text, registry);
            if (d.evidence) votes.push_back({normal_path(f), d.dialect, d.confidence});
        }
        const std::lock_guard lock(mutex_);
        folder_votes_.emplace(key, votes);
    }
    std::vector<grammar::Detection> others;
    for (const FolderVote& v : votes) {
        if (v.file == self) continue;
        grammar::Detection d;
        d.dialect = v.dialect;
        d.confidence = v.confidence;
        others.push_back(std::move(d));
    }
    return grammar::folder_majority(others);
}

std::optional<fs::path> Workspace::find_config(const fs::path& file) const {
    for (fs::path dir = normal_path(file).parent_path(); !dir.empty(); dir = dir.parent_path()) {
        const fs::path candidate = dir / ".kerf.toml";
        if (files_->is_file(candidate)) return candidate;
        if (dir == dir.root_path()) break;
    }
    return std::nullopt;
}

std::shared_ptr<const Project> Workspace::load_project(const std::optional<fs::path>& config_file) {
    Overrides overrides = this->overrides();
    if (!config_file) return std::make_shared<Project>(Config{}, std::vector<Problem>{}, overrides, *files_);
    const ReadResult read = files_->read(*config_file);
    if (!read.text) {
        Config defaults;
        defaults.file = *config_file;
        return std::make_shared<Project>(std::move(defaults),
                                         std::vector<Problem>{{Level::error, config_file->string(), 0, 0, "cannot open file"}},
                                         overrides, *files_);
    }
    ConfigResult parsed = parse_config(*read.text, *config_file);
    return std::make_shared<Project>(std::move(parsed.config), std::move(parsed.problems), overrides, *files_);
}

std::shared_ptr<const Project> Workspace::project_for(const fs::path& file) {
    const fs::path folder = normal_path(file).parent_path();
    std::optional<fs::path> config;
    {
        const std::lock_guard lock(mutex_);
        if (const auto it = config_of_.find(folder); it != config_of_.end()) config = it->second;
        else config = config_of_[folder] = find_config(file);
        if (const auto it = projects_.find(config.value_or(fs::path{})); it != projects_.end()) return it->second;
    }
    std::shared_ptr<const Project> project = load_project(config);
    const std::lock_guard lock(mutex_);
    // Two threads may have read it at once: the first one stored wins, so every file shares one.
    return projects_.emplace(config.value_or(fs::path{}), std::move(project)).first->second;
}

Resolved Workspace::resolve(const fs::path& file, std::string_view text) {
    Resolved r;
    r.project = project_for(file);
    r.problems = r.project->problems();
    const dialects::Registry& registry = r.project->dialects();
    r.choice = choose_dialect(overrides(), r.project->config(), text, registry,
                              [&] { return folder_dialect(file, registry); });
    r.dialect = r.project->dialects().find(r.choice.id);
    if (!r.dialect) {
        const std::string origin = r.choice.source == DialectSource::config ? r.project->config().file.string() : "";
        r.problems.push_back({Level::error, origin, 0, 0, fmt::format("unknown dialect '{}'; `kerf dialects` lists them", r.choice.id)});
        return r;
    }
    const Project::SetupEntry& setup = r.project->setup(*r.dialect);
    r.problems.insert(r.problems.end(), setup.problems.begin(), setup.problems.end());
    if (setup.setup) r.setup = &*setup.setup;
    return r;
}

void Workspace::index_folder(const fs::path& folder) {
    const fs::path normal = normal_path(folder);
    const std::lock_guard index_lock(index_mutex_);
    {
        const std::lock_guard lock(mutex_);
        if (!indexed_.insert(normal).second) return;
    }
    // The lexical rules of the folder's configured dialect, else FANUC's (';' ends a block).
    const std::shared_ptr<const Project> project = project_for(normal / ".");
    ScanRules rules;
    if (const dialects::Dialect* d = project->dialects().find(project->config().dialect)) rules = ScanRules::of(d->lexical);
    // On every core: a folder check's other worker waits for this index (a call K3003 could not
    // place), and 10,000 files read one by one were its longest serial part (bench/RESULTS.md).
    // The index keeps each number's files sorted, so the order the files come in does not matter.
    const std::vector<fs::path> files = files_->files_in(normal);
    run_parallel(files.size(), 0, [&](std::size_t i) {
        const fs::path& file = files[i];
        if (is_hidden(file)) return;
        ReadResult read = files_->read_head(file, kRecognitionHead);
        if (!read.text || !recognize_program(file.filename().string(), *read.text).program) return;
        if (read.text->size() == kRecognitionHead) read = files_->read(file);   // the head was not all of it
        if (read.text) index_.update_file(normal_path(file), *read.text, rules);
    });
}

void Workspace::forget_folder(const fs::path& folder) {
    const fs::path normal = normal_path(folder);
    {
        const std::lock_guard lock(mutex_);
        indexed_.erase(normal);
        std::erase_if(folder_votes_, [&](const auto& entry) { return entry.first.first == normal; });
    }
    for (const fs::path& file : index_.files())
        if (file.parent_path() == normal) index_.remove_file(file);
}

void Workspace::index_for(const fs::path& file) {
    const std::shared_ptr<const Project> project = project_for(file);
    for (const fs::path& folder : project->program_scope(file).folders) index_folder(folder);
}

std::vector<IndexedProgram> Workspace::find_programs(std::int64_t number, const fs::path& file) {
    index_for(file);
    const fs::path from = normal_path(file);
    std::vector<IndexedProgram> found = index_.find_all(number, from, project_for(file)->program_scope(file));
    std::erase_if(found, [&](const IndexedProgram& p) { return p.file == from; });
    return found;
}

std::optional<IndexedProgram> Workspace::find_program(std::int64_t number, const fs::path& file) {
    std::vector<IndexedProgram> found = find_programs(number, file);
    if (found.empty()) return std::nullopt;
    return std::move(found.front());
}

fs::path Workspace::display_name(const fs::path& found, const fs::path& from) {
    return from.is_relative() ? found.lexically_proximate(fs::current_path()) : found;
}

interpreter::ProgramSet::Loader Workspace::loader_for(const fs::path& file) {
    return [this, file](std::int64_t number) -> std::optional<std::pair<std::string, std::string>> {
        const std::optional<IndexedProgram> found = find_program(number, file);
        if (!found) return std::nullopt;
        ReadResult read = files_->read(found->file);
        if (!read.text) return std::nullopt;
        return std::make_pair(display_name(found->file, file).string(), std::move(*read.text));
    };
}

Selector Workspace::check_selector() {
    return [this](const fs::path& file) -> Selection {
        const std::shared_ptr<const Project> project = project_for(file);
        const Config& config = project->config();
        if (config.file.empty()) return {};
        const std::string relative = normal_path(file).lexically_relative(config.folder()).generic_string();
        if (const std::string* glob = config.check.excluded_by(relative))
            return {Selection::Verdict::skip, fmt::format("excluded by [check] exclude \"{}\" ({})", *glob, config.file.string())};
        if (config.check.include.empty()) return {};
        if (const std::string* glob = config.check.included_by(relative))
            return {Selection::Verdict::take, fmt::format("included by [check] include \"{}\"", *glob)};
        return {Selection::Verdict::skip, fmt::format("not matched by [check] include ({})", config.file.string())};
    };
}

}  // namespace kerf::project
