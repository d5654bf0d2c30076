// The one atomic writer (project/writer.hpp): the whole new text or the old file, permissions
// kept, no temp file left behind, the original untouched when the write fails.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

#include "project/writer.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using kerf::project::write_atomically;
using kerf::test::read_text;
using kerf::test::write_text;

namespace {

std::size_t entries(const fs::path& dir) {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}));
}

}  // namespace

TEST_CASE("writer: replaces the text, keeps the permissions, leaves no temp file") {
    const fs::path dir = kerf::test::fresh_folder("writer-replace");
    const fs::path file = write_text(dir / "part.nc", "O1\nG0X1\nM30\n");
    REQUIRE(::chmod(file.c_str(), 0640) == 0);
    CHECK_FALSE(write_atomically(file, "O1\nG00 X1\nM30\n"));
    CHECK(read_text(file) == "O1\nG00 X1\nM30\n");
    struct stat st {};
    REQUIRE(::stat(file.c_str(), &st) == 0);
    CHECK((st.st_mode & 07777) == 0640);
    CHECK(entries(dir) == 1);
    fs::remove_all(dir);
}

TEST_CASE("writer: a new file is created; a big text is written whole") {
    const fs::path dir = kerf::test::fresh_folder("writer-new");
    const std::string big(5 << 20, 'X');
    CHECK_FALSE(write_atomically(dir / "new.nc", big));
    CHECK(read_text(dir / "new.nc") == big);
    CHECK(entries(dir) == 1);
    fs::remove_all(dir);
}

TEST_CASE("writer: on failure the original is untouched and nothing is left behind") {
    const fs::path dir = kerf::test::fresh_folder("writer-fail");
    // A folder where the file should be: rename() cannot replace it.
    fs::create_directories(dir / "part.nc");
    write_text(dir / "part.nc" / "inside", "kept");
    const auto error = write_atomically(dir / "part.nc", "new text");
    REQUIRE(error);
    CHECK(error->find("cannot replace the file") != std::string::npos);
    CHECK(error->find("the file is left as it was") != std::string::npos);
    CHECK(read_text(dir / "part.nc" / "inside") == "kept");
    CHECK(entries(dir) == 1);   // no temp file
    // A folder that does not exist: no temp file can be made.
    const auto missing = write_atomically(dir / "no" / "such" / "part.nc", "x");
    REQUIRE(missing);
    CHECK(missing->starts_with("cannot create a temp file next to it"));
    fs::remove_all(dir);
}
