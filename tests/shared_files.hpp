// Files in tests: whole-file reading and writing, and the reference examples and corpus files of
// ../shared (KERF_SHARED_DIR) that the sweep and round-trip tests run over.
#pragma once

#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace kerf::test {

inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Writes `text` to `path` (creating its directory); gives `path` back.
inline std::filesystem::path write_text(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// An empty folder `<temp>/kerf-<name>-<pid>` (removed first if it is there); the caller removes it.
inline std::filesystem::path fresh_folder(const std::string& name);

// Every file under ../shared/reference/examples and ../shared/corpus but MANIFEST.md, sorted;
// none when ../shared is absent.
inline std::vector<std::filesystem::path> shared_files() {
    namespace fs = std::filesystem;
    std::vector<fs::path> files;
    for (const char* sub : {"reference/examples", "corpus"}) {
        const fs::path dir = fs::path(KERF_SHARED_DIR) / sub;
        if (!fs::is_directory(dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(dir))
            if (e.is_regular_file() && e.path().filename() != "MANIFEST.md") files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// shared_files(); when there are none, a WARN "../shared is not there: <skipped>" first. A test
// that gets none returns: it skips with that message.
inline std::vector<std::filesystem::path> shared_files_or_warn(const std::string& skipped) {
    std::vector<std::filesystem::path> files = shared_files();
    if (files.empty()) WARN("../shared is not there: " << skipped);
    return files;
}

inline std::filesystem::path fresh_folder(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("kerf-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace kerf::test
