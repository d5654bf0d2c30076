// Which files `kerf check` and `kerf fmt` take from folders, and the parallel runner.
#include <catch2/catch.hpp>

#include <atomic>
#include <fstream>
#include <vector>

#include "cli/source_files.hpp"

namespace fs = std::filesystem;
using kerf::cli::collect_source_files;
using kerf::cli::looks_like_program;

namespace {

void write(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

}  // namespace

TEST_CASE("a program without extension is recognised by its first block") {
    CHECK(looks_like_program("O1000\nG0X0\n"));
    CHECK(looks_like_program("%\nO0012 (PART)\n"));
    CHECK(looks_like_program("\xEF\xBB\xBF%\r\n:1000\r\n"));
    CHECK(looks_like_program("N10 G0 X0\n"));
    CHECK_FALSE(looks_like_program("#!/bin/sh\necho\n"));
    CHECK_FALSE(looks_like_program("Once upon a time"));
    CHECK_FALSE(looks_like_program(std::string_view("O1\0\0", 4)));
    CHECK_FALSE(looks_like_program(""));
}

TEST_CASE("folders are walked recursively for program files, hidden folders skipped") {
    const fs::path root = fs::temp_directory_path() / "kerf_test_source_files";
    fs::remove_all(root);
    write(root / "a.nc", "O1\n");
    write(root / "sub" / "B.NGC", "O2\n");
    write(root / "sub" / "deep" / "c.MPF", "O3\n");
    write(root / "sub" / "O1000", "O1000\nG0X0\n");
    write(root / "sub" / "README", "notes about the parts\n");
    write(root / "picture.png", "\x89PNG");
    write(root / ".git" / "x.nc", "O4\n");
    const auto result = collect_source_files({root, root / "a.nc", root / "missing.nc"});
    std::vector<std::string> names;
    for (const fs::path& f : result.files) names.push_back(fs::relative(f, root).generic_string());
    CHECK(names == std::vector<std::string>{"a.nc", "sub/B.NGC", "sub/O1000", "sub/deep/c.MPF"});
    REQUIRE(result.errors.size() == 1);
    CHECK(result.errors[0].find("missing.nc") != std::string::npos);
    // A file named explicitly is taken whatever its extension.
    CHECK(collect_source_files({root / "sub" / "README"}).files.size() == 1);
    fs::remove_all(root);
}

TEST_CASE("run_parallel runs every index once and reports the end") {
    for (unsigned threads : {1u, 2u, 4u}) {
        std::vector<std::atomic<int>> runs(1000);
        std::size_t last_finished = 0;
        kerf::cli::run_parallel(
            runs.size(), threads, [&](std::size_t i) { ++runs[i]; },
            [&](std::size_t finished, std::size_t) { last_finished = finished; });
        for (const auto& r : runs) CHECK(r.load() == 1);
        CHECK(last_finished == runs.size());
    }
}
