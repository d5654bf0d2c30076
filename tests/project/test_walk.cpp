// Folder walks (project/walk.hpp): which files `kerf check` and `kerf fmt` take, every skipped file
// with its reason, [check] include/exclude through the workspace's selector; the parallel runner.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "project/parallel.hpp"
#include "project/walk.hpp"
#include "project/workspace.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf::project;
using kerf::test::write_text;

namespace {

std::vector<std::string> names(const std::vector<fs::path>& files, const fs::path& root) {
    std::vector<std::string> out;
    for (const fs::path& f : files) out.push_back(fs::relative(f, root).generic_string());
    return out;
}

std::vector<std::string> skipped(const WalkResult& r, const fs::path& root) {
    std::vector<std::string> out;
    for (const SkippedFile& s : r.skipped) out.push_back(fs::relative(s.path, root).generic_string() + ": " + s.reason);
    return out;
}

}  // namespace

TEST_CASE("walk: programs by content whatever their names; every other file listed with its reason") {
    const fs::path root = fs::temp_directory_path() / "kerf_test_walk";
    fs::remove_all(root);
    write_text(root / "a.nc", "O1\n");
    write_text(root / "sub" / "B.NGC", "O2\n");
    write_text(root / "sub" / "deep" / "c.MPF", "O3\n");
    write_text(root / "sub" / "O1000", "O1000\nG0X0\n");
    write_text(root / "sub" / "205", "(VTULKA)\nG21G40G49G54G80G90\nT0303\nM30\n");
    write_text(root / "sub" / "O0003", "%O0003( 300-11 MILL FIXTURE)\n()\nG0 X1.\nM30\n%\n");
    write_text(root / "sub" / "probe.eia", "O9810\nM99\n");
    write_text(root / "sub" / "macro.src", "#1 = SIN[1]\n#2 = #1 + 1\n");
    write_text(root / "sub" / "README", "notes about the parts\n");
    write_text(root / "MANIFEST.md", "# Files\n\n| file | what |\n|---|---|\n| a.nc | the first part |\n");
    write_text(root / "picture.png", "\x89PNG");
    write_text(root / "empty.nc", "");
    write_text(root / ".git" / "x.nc", "O4\n");
    const WalkResult result = collect_program_files({root, root / "a.nc", root / "missing.nc"}, DiskFileSystem());
    CHECK(names(result.files, root) == std::vector<std::string>{"a.nc", "sub/205", "sub/B.NGC", "sub/O0003", "sub/O1000",
                                                                "sub/deep/c.MPF", "sub/macro.src", "sub/probe.eia"});
    CHECK(skipped(result, root) == std::vector<std::string>{
                                       ".git: hidden folder",
                                       "MANIFEST.md: not a program: no NC block in the first 4 lines",
                                       "empty.nc: empty file",
                                       "picture.png: binary: PNG image",
                                       "sub/README: not a program: no NC block in the first 1 lines",
                                   });
    REQUIRE(result.errors.size() == 1);
    CHECK(result.errors[0] == (root / "missing.nc").string() + ": no such file or folder");
    // A file named on the command line is taken whatever it holds.
    CHECK(collect_program_files({root / "sub" / "README"}, DiskFileSystem()).files.size() == 1);
    fs::remove_all(root);
}

TEST_CASE("walk: [check] include adds files content would skip, exclude removes them, each with a reason") {
    const fs::path root = fs::temp_directory_path() / "kerf_test_walk_select";
    fs::remove_all(root);
    write_text(root / ".kerf.toml", "[check]\ninclude = [\"**/*.nc\", \"notes/*.txt\"]\nexclude = [\"old/**\"]\n");
    write_text(root / "a.nc", "O1\nM30\n");
    write_text(root / "old" / "b.nc", "O2\nM30\n");
    write_text(root / "notes" / "n.txt", "(ONLY COMMENTS)\n");   // content alone would skip it
    write_text(root / "c.eia", "O3\nM30\n");                     // a program, but include does not name it
    write_text(root / "pic.nc", std::string("\x89PNG\0\0", 6));  // included by name, still binary
    Workspace workspace;
    const WalkResult r = collect_program_files({root}, workspace.files(), workspace.check_selector());
    CHECK(names(r.files, root) == std::vector<std::string>{"a.nc", "notes/n.txt"});
    const std::string config = (root / ".kerf.toml").string();
    CHECK(skipped(r, root) == std::vector<std::string>{
                                  ".kerf.toml: hidden file",
                                  "c.eia: not matched by [check] include (" + config + ")",
                                  "old/b.nc: excluded by [check] exclude \"old/**\" (" + config + ")",
                                  "pic.nc: binary: PNG image",
                              });
    fs::remove_all(root);
}

TEST_CASE("run_parallel keeps `threads` items running at once, also with a progress callback") {
    // Two items that each wait (up to 5 s) until both have started: they meet only when two threads
    // work. With a progress callback the calling thread used to report instead of working, so a
    // folder check with -j2 ran on one core.
    for (const bool progress : {false, true}) {
        std::atomic<int> started{0};
        std::atomic<int> met{0};
        const auto work = [&](std::size_t) {
            ++started;
            const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
            while (started.load() < 2 && std::chrono::steady_clock::now() < until) std::this_thread::yield();
            if (started.load() == 2) ++met;
        };
        if (progress) run_parallel(2, 2, work, [](std::size_t, std::size_t) {});
        else run_parallel(2, 2, work);
        INFO(progress);
        CHECK(met.load() == 2);
    }
}

TEST_CASE("run_parallel runs every index once and reports the end") {
    for (unsigned threads : {1u, 2u, 4u}) {
        std::vector<std::atomic<int>> runs(1000);
        std::size_t last_finished = 0;
        run_parallel(
            runs.size(), threads, [&](std::size_t i) { ++runs[i]; },
            [&](std::size_t finished, std::size_t) { last_finished = finished; });
        for (const auto& r : runs) CHECK(r.load() == 1);
        CHECK(last_finished == runs.size());
    }
}

namespace {

// A program of at least `bytes` bytes whose lines all differ (N numbers count up), so that a part
// read into the wrong place cannot pass for the file.
std::string numbered_program(std::size_t bytes) {
    std::string text;
    for (int i = 0; text.size() < bytes; ++i) {   // appended piecewise: GCC 12 warns falsely on "N" + string
        text += 'N';
        text += std::to_string(i);
        text += " G01 X1.5 Y-2.25\r\n";
    }
    text += "M30";   // no line break at the end
    return text;
}

}  // namespace

// DiskFileSystem::read reads a file of 1 MiB or more straight into its string (project/files.cpp;
// from 8 MiB on, each half on its own thread) and smaller ones as a stream: all give the file's
// bytes, and the decoder's checks apply to all.
TEST_CASE("DiskFileSystem reads a large file byte for byte, in halves too, under the same limits") {
    const fs::path root = fs::temp_directory_path() / "kerf_test_read_mapped";
    fs::remove_all(root);
    fs::create_directories(root);
    const std::string big = numbered_program(std::size_t{3} << 19);
    const std::string halves = numbered_program((std::size_t{9} << 20) + 12345);   // two threads, odd halves
    write_text(root / "big.nc", big);
    write_text(root / "halves.nc", halves);
    write_text(root / "small.nc", "G00 X1.\n");
    const DiskFileSystem disk;
    const ReadResult read = disk.read(root / "big.nc", kerf::ast::InputLimits{});
    REQUIRE(read.text);
    CHECK(*read.text == big);
    CHECK(read.problems.empty());
    const ReadResult read_halves = disk.read(root / "halves.nc", kerf::ast::InputLimits{});
    REQUIRE(read_halves.text);
    CHECK(read_halves.text->size() == halves.size());
    CHECK(*read_halves.text == halves);
    const ReadResult small = disk.read(root / "small.nc", kerf::ast::InputLimits{});
    REQUIRE(small.text);
    CHECK(*small.text == "G00 X1.\n");
    // The limits hold for the direct path: a line over max_line_bytes is refused, the file too big too.
    const ReadResult long_lines = disk.read(root / "big.nc", kerf::ast::InputLimits{0, 16});
    CHECK_FALSE(long_lines.text);
    CHECK(long_lines.error.find("line") != std::string::npos);
    const ReadResult too_big = disk.read(root / "big.nc", kerf::ast::InputLimits{std::uint64_t{1} << 20, 0});
    CHECK_FALSE(too_big.text);
    fs::remove_all(root);
}
