// The program index (project/index.hpp): O number → file and program, kept current file by file,
// and the deterministic choice among files that hold the same number.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <thread>

#include "project/index.hpp"

namespace fs = std::filesystem;
using namespace kerf::project;

namespace {

Scope folders(std::initializer_list<fs::path> list) {
    Scope s;
    s.folders.assign(list.begin(), list.end());
    return s;
}

}  // namespace

TEST_CASE("index: add, query, update and remove one file") {
    ProgramIndex index;
    index.update_file("/w/a.nc", "%\nO1000 (ROUGH)\nG0 X1\nM99\nO2000\nM99\n%\n");
    CHECK(index.file_count() == 1);
    CHECK(index.program_count() == 2);
    const auto found = index.find(2000, "/w/main.nc", folders({"/w"}));
    REQUIRE(found);
    CHECK(found->file == "/w/a.nc");
    CHECK(found->program.program_index == 1);
    CHECK(found->program.begin == std::string("%\nO1000 (ROUGH)\nG0 X1\nM99\n").size());
    CHECK(index.programs_in("/w/a.nc").front().comment == "ROUGH");
    // An edit: O2000 renumbered to O3000.
    index.update_file("/w/a.nc", "O1000\nM99\nO3000\nM99\n");
    CHECK_FALSE(index.find(2000, "/w/main.nc", folders({"/w"})));
    CHECK(index.find(3000, "/w/main.nc", folders({"/w"})));
    index.remove_file("/w/a.nc");
    CHECK(index.file_count() == 0);
    CHECK_FALSE(index.find(1000, "/w/main.nc", folders({"/w"})));
    CHECK(index.duplicates().empty());
}

TEST_CASE("index: the same file first, then its folder, then the nearest folder, then path order") {
    ProgramIndex index;
    for (const char* f : {"/w/x/b.nc", "/w/x/a.nc", "/w/lib/a.nc", "/w/x/deep/a.nc", "/z/far/a.nc", "/w/x/main.nc"})
        index.update_file(f, "O1000\nM99\n");
    Scope everywhere;
    everywhere.everywhere = true;
    std::vector<fs::path> order;
    for (const IndexedProgram& p : index.find_all(1000, "/w/x/main.nc", everywhere)) order.push_back(p.file);
    // main.nc holds it itself; a.nc before b.nc (path order) in the same folder; deep/ is one step
    // away, lib/ two (up to /w, down to lib), /z/far four.
    CHECK(order == std::vector<fs::path>{"/w/x/main.nc", "/w/x/a.nc", "/w/x/b.nc", "/w/x/deep/a.nc", "/w/lib/a.nc", "/z/far/a.nc"});
    // A scope: the folder and a library folder only.
    order.clear();
    for (const IndexedProgram& p : index.find_all(1000, "/w/x/other.nc", folders({"/w/x", "/w/lib"}))) order.push_back(p.file);
    CHECK(order == std::vector<fs::path>{"/w/x/a.nc", "/w/x/b.nc", "/w/x/main.nc", "/w/lib/a.nc"});
    const std::vector<DuplicateProgram> d = index.duplicates();
    REQUIRE(d.size() == 1);
    CHECK(d[0].number == 1000);
    CHECK(d[0].files.size() == 6);
    CHECK(folder_distance("/w/x", "/w/x") == 0);
    CHECK(folder_distance("/w/x", "/w/lib") == 2);
    CHECK(folder_distance("/w/x", "/w/x/deep") == 1);
}

TEST_CASE("index: two copies in one file count once; the first one is taken") {
    ProgramIndex index;
    index.update_file("/w/a.nc", "O0100(MAIN)\nO0100(MAIN)\nM30\n");
    CHECK(index.duplicates().empty());
    const auto found = index.find(100, "/w/main.nc", folders({"/w"}));
    REQUIRE(found);
    CHECK(found->program.program_index == 0);
}

TEST_CASE("index: readers and a writer at once") {
    ProgramIndex index;
    std::thread writer([&] {
        for (int i = 0; i < 2000; ++i)
            index.update_file(fmt::format("/w/f{}.nc", i % 50), fmt::format("O{}\nM99\n", i));
    });
    std::size_t seen = 0;
    for (int i = 0; i < 2000; ++i) seen += index.find(i, "/w/main.nc", folders({"/w"})).has_value();
    writer.join();
    CHECK(index.file_count() == 50);
    CHECK(index.program_count() == 50);   // each file holds its last program
    CHECK(seen <= 2000);
}
