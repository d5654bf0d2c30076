// The project layer's entry point, shared by the command line and the language server (clangd's
// ClangdServer beside its index: `cli/` and `lsp/` are two faces of this layer). A Workspace
// answers, for any program file:
//
//   - its Project: the .kerf.toml found by walking up from the file's folder (project/config.hpp),
//     the dialect registry (built-ins, then the override's dialect files, then the .kerf.toml's)
//     and a cache of one interpreter Setup per dialect; projects are read once and shared;
//   - its dialect: the override (--dialect, the client's kerf.dialect), then the .kerf.toml's
//     `dialect`, then the `(DIALECT: ...)` header and detection over the project's registry
//     (grammar/detect.hpp: each dialect's `[detect]` evidence, so a user's dialect file is detected),
//     and for a file without evidence the folder rule (what most programs of its folder are);
//   - its machine: the override (--machine, kerf.machine), then `machine = ...`, then the dialect's
//     built-in machine;
//   - the programs its calls reach: the program index (project/index.hpp) of its folder and the
//     .kerf.toml's [programs] library folders, as a ProgramSet loader.
//
// Everything is read through a FileSystem (project/files.hpp): the disk for the command line,
// open documents over the disk for the server. Thread-safe: batch commands resolve files from
// many threads.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "dialects/dialect.hpp"
#include "grammar/detect.hpp"
#include "interpreter/program_set.hpp"
#include "interpreter/setup.hpp"
#include "project/config.hpp"
#include "project/files.hpp"
#include "project/index.hpp"
#include "project/problem.hpp"
#include "project/walk.hpp"

namespace kerf::project {

// What the user says above every .kerf.toml: the command line's flags, or the server's settings.
struct Overrides {
    std::string dialect;                                 // "" or "auto": not overridden
    std::vector<std::filesystem::path> dialect_files;    // loaded before the .kerf.toml's
    std::filesystem::path machine;                       // "": not overridden
    LimitSettings limits;                                // --max-file-bytes, --max-line-bytes, --time-limit
    RunSettings run;                                     // --call, --set, --passes (over [run])
    std::string dialect_origin = "--dialect";            // how problems name the override ("kerf.dialect")
    std::string machine_origin = "--machine";
};

enum class DialectSource { override_setting, config, detection };

struct DialectChoice {
    std::string id;
    DialectSource source = DialectSource::detection;
    std::string why;                     // "dialect fanuc-mill from --dialect", "... detected (score 7)"
    std::vector<std::string> evidence;   // detection's reasons (the header comment when it decided)
    bool no_evidence = false;            // detection found nothing in the file (the folder rule or the default chose)
    // Detection found a program of another control (a `foreign = true` profile outweighed every
    // dialect): `kerf check` then says so once instead of reading the file as FANUC (issue 15).
    std::optional<grammar::Detection::Foreign> foreign;
};

// For a file without evidence: the dialect most programs of its folder were detected as, and why
// ("3 of the 4 other programs with evidence in its folder"); nullopt when none had evidence.
using FolderRule = std::function<std::optional<std::pair<std::string, std::string>>()>;

// Pure: the override, else the configuration's dialect, else the header and detection on `text`
// over `registry`; `folder` is asked only when the file has no evidence.
DialectChoice choose_dialect(const Overrides& overrides, const Config& config, std::string_view text,
                             const dialects::Registry& registry = dialects::builtin_registry(),
                             const FolderRule& folder = {});

// The built-in dialects and the user dialect files, in order (dialects/SCHEMA.md); a file that
// cannot be read or has errors is a problem and adds nothing.
struct DialectRegistry {
    dialects::Registry registry;
    std::vector<Problem> problems;
};
DialectRegistry load_dialects(const std::vector<std::filesystem::path>& dialect_files, const FileSystem& files);

class Project {
public:
    Project(Config config, std::vector<Problem> problems, const Overrides& overrides, const FileSystem& files);

    const Config& config() const { return config_; }
    const dialects::Registry& dialects() const { return *registry_; }
    // The problems of the .kerf.toml and the dialect files (reported once per project).
    const std::vector<Problem>& problems() const { return problems_; }
    // The machine file in force: the override, else the .kerf.toml's; empty for the built-in machine.
    const std::filesystem::path& machine_file() const { return machine_file_; }
    // The bounds in force for the project's files: the overrides over [limits] over the defaults.
    const Limits& limits() const { return limits_; }
    // How a dry run starts: the overrides' --call/--passes over [run], their --set after [run] set.
    const RunSettings& run_settings() const { return run_; }

    struct SetupEntry {
        std::optional<interpreter::Setup> setup;   // nullopt when the machine file has errors
        std::vector<Problem> problems;             // the machine file's (warnings too)
    };
    // The Setup for `dialect`, read once per dialect id.
    const SetupEntry& setup(const dialects::Dialect& dialect) const;
    // The machine `machine_of` runs on (the machine file in force, else its dialect's built-in
    // machine) read for `dialect`: the same machine description in another dialect's reading
    // (its "dialect" switches resolved for `dialect`), for `kerf convert --verify`.
    const SetupEntry& setup(const dialects::Dialect& dialect, const dialects::Dialect& machine_of) const;
    // The folders a call from `file` reaches: the file's own folder, then the library folders.
    Scope program_scope(const std::filesystem::path& file) const;

private:
    Config config_;
    std::vector<Problem> problems_;
    // The built-in registry itself when the project has no dialect files (most do not: a copy was
    // 2.9 MB and 3 ms a process, bench/RESULTS.md); else its own, built-ins and the user's files.
    std::optional<dialects::Registry> own_registry_;
    const dialects::Registry* registry_ = nullptr;
    std::filesystem::path machine_file_;
    Limits limits_;
    RunSettings run_;
    const FileSystem& files_;
    mutable std::mutex setups_mutex_;
    mutable std::map<std::string, std::unique_ptr<SetupEntry>> setups_;
};

// What analysing one file needs. `dialect` and `setup` point into `project`.
struct Resolved {
    std::shared_ptr<const Project> project;
    const dialects::Dialect* dialect = nullptr;
    DialectChoice choice;
    const interpreter::Setup* setup = nullptr;
    std::vector<Problem> problems;   // the project's, an unknown dialect, the machine file's
    bool ok() const { return dialect && setup; }
};

class Workspace {
public:
    explicit Workspace(std::shared_ptr<const FileSystem> files = std::make_shared<DiskFileSystem>(), Overrides overrides = {});

    const FileSystem& files() const { return *files_; }
    // A program file, decoded under its project's limits (project/files.hpp).
    ReadResult read(const std::filesystem::path& file) { return files_->read(file, project_for(file)->limits().input); }

    // New overrides (the server's settings changed): projects are read again on next use.
    void set_overrides(Overrides overrides);
    Overrides overrides() const;
    // A .kerf.toml (or a dialect or machine file) changed: every project is read again on next use.
    void forget_projects();

    // The project of a file (or folder): its .kerf.toml, or the defaults when there is none.
    std::shared_ptr<const Project> project_for(const std::filesystem::path& file);
    // The .kerf.toml that governs `file`, walking up from its folder; nullopt when none.
    std::optional<std::filesystem::path> find_config(const std::filesystem::path& file) const;
    // Project, dialect and Setup of a file whose text is `text`.
    Resolved resolve(const std::filesystem::path& file, std::string_view text);

    ProgramIndex& index() { return index_; }
    const ProgramIndex& index() const { return index_; }
    // Indexes the program files directly in `folder` (once; again after forget_folder).
    void index_folder(const std::filesystem::path& folder);
    void forget_folder(const std::filesystem::path& folder);
    // Indexes what a call from `file` can reach: its folder and its project's library folders.
    void index_for(const std::filesystem::path& file);
    // The program `number` a call from `file` reaches outside `file` itself (index_for first).
    std::optional<IndexedProgram> find_program(std::int64_t number, const std::filesystem::path& file);
    // Every other file's program `number` a call from `file` can reach, the one it reaches first.
    std::vector<IndexedProgram> find_programs(std::int64_t number, const std::filesystem::path& file);
    // How messages name a file found through the index: relative to the current folder when the
    // calling file was named relatively.
    static std::filesystem::path display_name(const std::filesystem::path& found, const std::filesystem::path& from);
    // O number → (name, text) for interpreter::ProgramSet::set_loader: the program's file through
    // the index. Names are relative when `file` is.
    interpreter::ProgramSet::Loader loader_for(const std::filesystem::path& file);

    // [check] include/exclude of each file's project, for collect_program_files in `kerf check`.
    Selector check_selector();

    // The folder rule of detection (dialects/SCHEMA.md [detect]): the dialect most of the programs
    // in `folder` (at most kFolderSample of them, by name, recognised by content) are detected as
    // over `registry`, other than `file`. Cached per folder and registry until forget_projects().
    static constexpr std::size_t kFolderSample = 32;
    std::optional<std::pair<std::string, std::string>> folder_dialect(const std::filesystem::path& file,
                                                                      const dialects::Registry& registry);

private:
    std::shared_ptr<const Project> load_project(const std::optional<std::filesystem::path>& config);

    std::shared_ptr<const FileSystem> files_;
    mutable std::mutex mutex_;   // guards overrides_, projects_, config_of_, indexed_, folder_votes_
    Overrides overrides_;
    std::map<std::filesystem::path, std::shared_ptr<const Project>> projects_;        // by .kerf.toml ("" = none)
    std::map<std::filesystem::path, std::optional<std::filesystem::path>> config_of_;  // folder → .kerf.toml
    std::set<std::filesystem::path> indexed_;
    // folder_dialect's detections: folder + registry → the sampled files that had evidence.
    struct FolderVote {
        std::filesystem::path file;
        std::string dialect;
        int confidence = 0;
    };
    std::map<std::pair<std::filesystem::path, const dialects::Registry*>, std::vector<FolderVote>> folder_votes_;
    std::mutex index_mutex_;   // one folder indexed at a time
    ProgramIndex index_;
};

}  // namespace kerf::project
