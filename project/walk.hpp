// Which files a batch command (`kerf check`, `kerf fmt`) works on. Files named on the command line
// are always taken, whatever they hold; folders are walked recursively and each file is taken or
// skipped by its content (project/recognize.hpp) and by the selection the caller gives (the
// [check] include/exclude globs of its .kerf.toml). Every file a walk skips is listed with the
// reason, so nothing is left out silently. Hidden files and folders (.git, .kerf.toml) are skipped.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "project/files.hpp"

namespace kerf::project {

struct SkippedFile {
    std::filesystem::path path;
    std::string reason;   // "binary: PNG image", "not a program: no NC block in the first 12 lines", "excluded by ..."
};

struct WalkResult {
    std::vector<std::filesystem::path> files;   // in argument order; the files of a folder in path order; no duplicates
    std::vector<SkippedFile> skipped;           // in path order per argument
    std::vector<std::string> errors;            // "PATH: no such file or folder"
};

// What the caller's configuration says of a file met in a folder walk.
struct Selection {
    enum class Verdict { by_content, take, skip };
    Verdict verdict = Verdict::by_content;
    std::string reason;   // for take and skip: "matched by [check] include \"**/*.src\" (.kerf.toml)"
};
using Selector = std::function<Selection(const std::filesystem::path& file)>;

// `select` may be empty (content decides). A file it takes is still refused when it is binary or
// empty.
WalkResult collect_program_files(const std::vector<std::filesystem::path>& arguments, const FileSystem& files,
                                 const Selector& select = {});

}  // namespace kerf::project
