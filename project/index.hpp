// The program index: O number → file, program and byte range, for every program inside every
// indexed file (not only files named O1234, O1234.nc or 1234.nc). The command line indexes the
// folder of each file it works on and the library folders of its .kerf.toml
// (project/workspace.hpp); the language server keeps the index current file by file as documents
// change. Pure and thread-safe: it stores what it is given (scan_programs, project/scan.hpp) and
// answers queries; reading files is the workspace's business.
//
// Which program a call reaches when several files hold its number (deterministic): the calling
// file itself first, then the calling file's folder, then the nearest folder (fewest steps up and
// down the folder tree), then path order. `duplicates()` lists the numbers several files hold,
// for the analyzer's finding.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <shared_mutex>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "project/scan.hpp"

namespace kerf::project {

struct IndexedProgram {
    std::filesystem::path file;
    ScannedProgram program;
};

// The folders a lookup may reach: each folder's own files, and every file under each tree.
// `everywhere` reaches the whole index (workspace symbols, go-to-definition in the server).
struct Scope {
    std::vector<std::filesystem::path> folders;
    std::vector<std::filesystem::path> trees;
    bool everywhere = false;
    bool contains(const std::filesystem::path& file) const;
};

struct DuplicateProgram {
    std::int64_t number = 0;
    std::vector<std::filesystem::path> files;   // in path order
};

class ProgramIndex {
public:
    // Paths are used as given: the workspace passes absolute, lexically normal paths.
    void update_file(const std::filesystem::path& file, std::string_view text, const ScanRules& rules = {});
    void set_file(const std::filesystem::path& file, std::vector<ScannedProgram> programs);
    void remove_file(const std::filesystem::path& file);

    bool has_file(const std::filesystem::path& file) const;
    std::vector<ScannedProgram> programs_in(const std::filesystem::path& file) const;
    // The program a call from `from` reaches (the order above), or nullopt.
    std::optional<IndexedProgram> find(std::int64_t number, const std::filesystem::path& from, const Scope& scope) const;
    // Every file's program `number` within `scope`, ranked as find() ranks them (one per file: the
    // first in the file).
    std::vector<IndexedProgram> find_all(std::int64_t number, const std::filesystem::path& from, const Scope& scope) const;
    // Numbers held by more than one file, in number order.
    std::vector<DuplicateProgram> duplicates() const;
    std::vector<std::filesystem::path> files() const;   // in path order
    std::size_t file_count() const;
    std::size_t program_count() const;

private:
    void erase_locked(const std::string& file);

    // Keyed by the path's native string: std::filesystem::path compares component by component,
    // which costs a third of indexing a folder (bench/RESULTS.md "Program index").
    mutable std::shared_mutex mutex_;
    std::map<std::string, std::vector<ScannedProgram>> files_;
    std::unordered_map<std::int64_t, std::vector<std::string>> by_number_;   // path order
};

// Steps from folder `a` to folder `b` through their common ancestor (0: the same folder).
std::size_t folder_distance(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace kerf::project
