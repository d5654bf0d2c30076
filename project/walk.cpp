#include "project/walk.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "project/parallel.hpp"
#include "project/recognize.hpp"

namespace kerf::project {

namespace fs = std::filesystem;

namespace {

bool is_hidden(const fs::path& path) {
    const std::string name = path.filename().string();
    return name.size() > 1 && name[0] == '.' && name != "..";
}

// The verdict on one file met in a walk.
std::optional<std::string> skip_reason(const fs::path& path, const FileSystem& files, const Selector& select) {
    if (is_hidden(path)) return "hidden file";
    const Selection selection = select ? select(path) : Selection{};
    if (selection.verdict == Selection::Verdict::skip) return selection.reason;
    const ReadResult head = files.read_head(path, kRecognitionHead);
    if (!head.text) return head.error;
    const Recognition r = recognize_program(path.filename().string(), *head.text);
    if (r.program) return std::nullopt;
    // Taken by the configuration: only what cannot be a program at all is still refused.
    const bool hopeless = head.text->empty() || r.reason.starts_with("binary");
    if (selection.verdict == Selection::Verdict::take && !hopeless) return std::nullopt;
    return r.reason;
}

void walk_folder(const fs::path& folder, const FileSystem& files, const Selector& select, WalkResult& out) {
    std::error_code ec;
    fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
        out.errors.push_back(fmt::format("{}: {}", folder.string(), ec.message()));
        return;
    }
    std::vector<fs::path> candidates;
    std::vector<SkippedFile> skipped;
    for (const fs::recursive_directory_iterator end; it != end; it.increment(ec)) {
        if (ec) {
            out.errors.push_back(fmt::format("{}: {}", it->path().string(), ec.message()));
            ec.clear();
            continue;
        }
        const fs::directory_entry& entry = *it;
        if (entry.is_directory(ec)) {
            if (is_hidden(entry.path())) {
                it.disable_recursion_pending();
                skipped.push_back({entry.path(), "hidden folder"});
            }
            continue;
        }
        if (!entry.is_regular_file(ec)) continue;
        candidates.push_back(entry.path());
    }
    // Reading each file's head and recognizing it is most of a walk of 10,000 files: on every core.
    std::vector<std::optional<std::string>> reasons(candidates.size());
    run_parallel(candidates.size(), 0, [&](std::size_t i) { reasons[i] = skip_reason(candidates[i], files, select); });
    std::vector<fs::path> found;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (reasons[i]) skipped.push_back({candidates[i], std::move(*reasons[i])});
        else found.push_back(candidates[i]);
    }
    std::sort(found.begin(), found.end());
    std::sort(skipped.begin(), skipped.end(), [](const SkippedFile& a, const SkippedFile& b) { return a.path < b.path; });
    out.files.insert(out.files.end(), found.begin(), found.end());
    out.skipped.insert(out.skipped.end(), skipped.begin(), skipped.end());
}

}  // namespace

WalkResult collect_program_files(const std::vector<fs::path>& arguments, const FileSystem& files, const Selector& select) {
    WalkResult result;
    for (const fs::path& argument : arguments) {
        std::error_code ec;
        const fs::file_status status = fs::status(argument, ec);
        if (ec || !fs::exists(status)) result.errors.push_back(fmt::format("{}: no such file or folder", argument.string()));
        else if (fs::is_directory(status)) walk_folder(argument, files, select, result);
        else result.files.push_back(argument);
    }
    std::set<fs::path> seen;
    std::vector<fs::path> unique;
    for (fs::path& file : result.files) {
        std::error_code ec;
        fs::path key = fs::weakly_canonical(file, ec);   // the same file named twice, or through a link
        if (ec) key = normal_path(file);
        if (seen.insert(key).second) unique.push_back(std::move(file));
    }
    result.files = std::move(unique);
    return result;
}

}  // namespace kerf::project
