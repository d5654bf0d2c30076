#include "project/index.hpp"

#include <algorithm>
#include <mutex>
#include <tuple>

namespace kerf::project {

namespace fs = std::filesystem;

namespace {

bool under(const fs::path& file, const fs::path& tree) {
    auto f = file.begin();
    for (auto t = tree.begin(); t != tree.end(); ++t, ++f) {
        if (t->empty()) continue;   // a trailing '/' of the tree
        if (f == file.end() || *f != *t) return false;
    }
    return true;
}

}  // namespace

bool Scope::contains(const fs::path& file) const {
    if (everywhere) return true;
    const fs::path folder = file.parent_path();
    if (std::find(folders.begin(), folders.end(), folder) != folders.end()) return true;
    return std::any_of(trees.begin(), trees.end(), [&](const fs::path& t) { return under(file, t); });
}

std::size_t folder_distance(const fs::path& a, const fs::path& b) {
    auto ia = a.begin(), ib = b.begin();
    while (ia != a.end() && ib != b.end() && *ia == *ib) ++ia, ++ib;
    return static_cast<std::size_t>(std::distance(ia, a.end()) + std::distance(ib, b.end()));
}

void ProgramIndex::update_file(const fs::path& file, std::string_view text, const ScanRules& rules) {
    set_file(file, scan_programs(text, rules));
}

void ProgramIndex::erase_locked(const std::string& file) {
    const auto it = files_.find(file);
    if (it == files_.end()) return;
    for (const ScannedProgram& p : it->second) {
        const auto n = by_number_.find(p.number);
        if (n == by_number_.end()) continue;
        std::erase(n->second, file);
        if (n->second.empty()) by_number_.erase(n);
    }
    files_.erase(it);
}

void ProgramIndex::set_file(const fs::path& path, std::vector<ScannedProgram> programs) {
    const std::string& file = path.native();
    const std::unique_lock lock(mutex_);
    erase_locked(file);
    for (const ScannedProgram& p : programs) {
        std::vector<std::string>& holders = by_number_[p.number];
        const auto at = std::lower_bound(holders.begin(), holders.end(), file);
        if (at == holders.end() || *at != file) holders.insert(at, file);
    }
    files_[file] = std::move(programs);
}

void ProgramIndex::remove_file(const fs::path& file) {
    const std::unique_lock lock(mutex_);
    erase_locked(file.native());
}

bool ProgramIndex::has_file(const fs::path& file) const {
    const std::shared_lock lock(mutex_);
    return files_.contains(file.native());
}

std::vector<ScannedProgram> ProgramIndex::programs_in(const fs::path& file) const {
    const std::shared_lock lock(mutex_);
    const auto it = files_.find(file.native());
    return it == files_.end() ? std::vector<ScannedProgram>{} : it->second;
}

std::vector<IndexedProgram> ProgramIndex::find_all(std::int64_t number, const fs::path& from, const Scope& scope) const {
    const std::shared_lock lock(mutex_);
    const auto n = by_number_.find(number);
    if (n == by_number_.end()) return {};
    struct Ranked {
        bool other_file;
        std::size_t distance;
        const std::string* file;
    };
    std::vector<Ranked> ranked;
    const fs::path from_folder = from.parent_path();
    for (const std::string& file : n->second) {
        const fs::path path(file);
        if (file == from.native() || scope.contains(path))
            ranked.push_back({file != from.native(), folder_distance(from_folder, path.parent_path()), &file});
    }
    std::stable_sort(ranked.begin(), ranked.end(), [](const Ranked& a, const Ranked& b) {
        return std::tie(a.other_file, a.distance) < std::tie(b.other_file, b.distance);   // then path order (stable)
    });
    std::vector<IndexedProgram> out;
    for (const Ranked& r : ranked) {
        const std::vector<ScannedProgram>& programs = files_.at(*r.file);
        const auto p = std::find_if(programs.begin(), programs.end(), [&](const ScannedProgram& s) { return s.number == number; });
        out.push_back({fs::path(*r.file), *p});
    }
    return out;
}

std::optional<IndexedProgram> ProgramIndex::find(std::int64_t number, const fs::path& from, const Scope& scope) const {
    std::vector<IndexedProgram> all = find_all(number, from, scope);
    if (all.empty()) return std::nullopt;
    return std::move(all.front());
}

std::vector<DuplicateProgram> ProgramIndex::duplicates() const {
    const std::shared_lock lock(mutex_);
    std::vector<DuplicateProgram> out;
    for (const auto& [number, files] : by_number_)
        if (files.size() > 1) out.push_back({number, std::vector<fs::path>(files.begin(), files.end())});
    std::sort(out.begin(), out.end(), [](const DuplicateProgram& a, const DuplicateProgram& b) { return a.number < b.number; });
    return out;
}

std::vector<fs::path> ProgramIndex::files() const {
    const std::shared_lock lock(mutex_);
    std::vector<fs::path> out;
    out.reserve(files_.size());
    for (const auto& [file, programs] : files_) out.emplace_back(file);
    return out;
}

std::size_t ProgramIndex::file_count() const {
    const std::shared_lock lock(mutex_);
    return files_.size();
}

std::size_t ProgramIndex::program_count() const {
    const std::shared_lock lock(mutex_);
    std::size_t n = 0;
    for (const auto& [file, programs] : files_) n += programs.size();
    return n;
}

}  // namespace kerf::project
