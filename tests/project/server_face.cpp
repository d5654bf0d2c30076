// The project layer without cli/ (issue 13: "the server able to use the project layer without
// cli/"): this test is linked against kerf_project alone (tests/CMakeLists.txt), and does what the
// language server will do with it - open documents laid over the disk, dialect and machine
// resolution with client settings above .kerf.toml, the program index kept current as documents
// change, the loader and `kerf check` on an unsaved document.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>

#include "project/check.hpp"
#include "project/workspace.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf::project;
using kerf::test::write_text;

namespace {

std::vector<std::string> rules_of(const CheckedFile& c) {
    std::vector<std::string> out;
    for (const kerf::analyzer::Finding& f : c.report.findings) out.push_back(f.rule);
    return out;
}

}  // namespace

TEST_CASE("server face: dialect from the client setting, then .kerf.toml, then the header, then detection") {
    const fs::path dir = kerf::test::fresh_folder("server-face-dialect");
    write_text(dir / "cfg" / ".kerf.toml", "dialect = \"fanuc-lathe-b\"\n");
    const std::string headed = "(DIALECT: fanuc-mill)\nO1\nG00 X1. Y1.\nM30\n";
    auto overlay = std::make_shared<OverlayFileSystem>(std::make_shared<DiskFileSystem>());
    overlay->set(dir / "cfg" / "part.nc", headed);   // an unsaved document: nothing on disk
    Workspace w(overlay);
    const Resolved in_project = w.resolve(dir / "cfg" / "part.nc", headed);
    CHECK(in_project.choice.id == "fanuc-lathe-b");
    CHECK(in_project.choice.source == DialectSource::config);
    CHECK(in_project.choice.why == "dialect fanuc-lathe-b from " + (dir / "cfg" / ".kerf.toml").string());
    REQUIRE(in_project.ok());
    const Resolved headed_only = w.resolve(dir / "free" / "part.nc", headed);
    CHECK(headed_only.choice.id == "fanuc-mill");
    CHECK(headed_only.choice.source == DialectSource::detection);
    REQUIRE_FALSE(headed_only.choice.evidence.empty());
    CHECK(headed_only.choice.evidence.front().find("header comment") != std::string::npos);
    // The client's kerf.dialect wins over both; a change re-reads the projects.
    Overrides client;
    client.dialect = "fanuc-lathe-c";
    client.dialect_origin = "kerf.dialect";
    w.set_overrides(client);
    const Resolved overridden = w.resolve(dir / "cfg" / "part.nc", headed);
    CHECK(overridden.choice.id == "fanuc-lathe-c");
    CHECK(overridden.choice.why == "dialect fanuc-lathe-c from kerf.dialect");
    // An unknown setting is a problem, not a crash.
    client.dialect = "no-such";
    w.set_overrides(client);
    const Resolved unknown = w.resolve(dir / "cfg" / "part.nc", headed);
    CHECK_FALSE(unknown.ok());
    REQUIRE_FALSE(unknown.problems.empty());
    CHECK(unknown.problems.back().message == "unknown dialect 'no-such'; `kerf dialects` lists them");
    fs::remove_all(dir);
}

TEST_CASE("server face: a bad .kerf.toml is a problem on its line; the machine from the config or the setting") {
    const fs::path dir = kerf::test::fresh_folder("server-face-machine");
    write_text(dir / "radius.toml", "id = \"radius\"\nbase = \"fanuc-lathe\"\ndiameter_x = false\n");
    write_text(dir / ".kerf.toml", "dialect = \"fanuc-lathe-a\"\nmachine = \"radius.toml\"\n");
    Workspace w;
    const Resolved r = w.resolve(dir / "a.nc", "O1\nM30\n");
    REQUIRE(r.ok());
    CHECK_FALSE(r.setup->diameter_x);   // the machine file's
    CHECK(r.project->machine_file() == dir / "radius.toml");
    write_text(dir / ".kerf.toml", "dialect = \"fanuc-lathe-a\"\nmachin = \"radius.toml\"\n");
    w.forget_projects();
    const Resolved bad = w.resolve(dir / "a.nc", "O1\nM30\n");
    REQUIRE_FALSE(bad.problems.empty());
    CHECK(bad.problems.front().file == (dir / ".kerf.toml").string());
    CHECK(bad.problems.front().line == 2);
    CHECK(bad.setup->diameter_x);   // the built-in machine: the misspelt key named none
    CHECK(has_errors(bad.problems));
    fs::remove_all(dir);
}

TEST_CASE("server face: the index finds programs inside other files and follows document edits") {
    const fs::path dir = kerf::test::fresh_folder("server-face-index");
    write_text(dir / "library.nc", "%\nO9000 (PROBE)\nM99\nO9001 (ALIGN)\nM99\n%\n");
    write_text(dir / ".kerf.toml", "dialect = \"fanuc-mill\"\n[programs]\nlibrary = [\"../macros-" + std::to_string(::getpid()) + "\"]\n");
    const fs::path macros = dir.parent_path() / ("macros-" + std::to_string(::getpid()));
    fs::remove_all(macros);
    write_text(macros / "renishaw.nc", "O9810 (PROTECTED POSITIONING)\nM99\n");
    auto overlay = std::make_shared<OverlayFileSystem>(std::make_shared<DiskFileSystem>());
    Workspace w(overlay);
    const fs::path main = dir / "main.nc";
    const std::string text = "O0001\nG65 P9001\nG65 P9810\nM98 P1234\nM30\n";
    overlay->set(main, text);
    // O9001 is the second program of library.nc; O9810 is in the library folder.
    const std::optional<IndexedProgram> align = w.find_program(9001, main);
    REQUIRE(align);
    CHECK(align->file == normal_path(dir / "library.nc"));
    CHECK(align->program.program_index == 1);
    CHECK(align->program.comment == "ALIGN");
    const std::optional<IndexedProgram> probe = w.find_program(9810, main);
    REQUIRE(probe);
    CHECK(probe->file == normal_path(macros / "renishaw.nc"));
    const auto loaded = w.loader_for(main)(9001);
    REQUIRE(loaded);
    CHECK(loaded->second.find("O9001 (ALIGN)") != std::string::npos);
    // kerf check on the unsaved document: only O1234 is missing, reported once (K3003, not K4009).
    CheckedFile checked = check_text(w, main, text);
    CHECK(rules_of(checked) == std::vector<std::string>{"K3003"});
    CHECK(checked.report.locations.front().line == 4);
    // A new document in the folder holds O1234: the server updates the index and the finding goes.
    overlay->set(dir / "sub1234.nc", "O1234\nM99\n");
    w.index().update_file(normal_path(dir / "sub1234.nc"), "O1234\nM99\n");
    checked = check_text(w, main, text);
    CHECK(rules_of(checked).empty());
    // The same number in a second file of the folder: K3010 names both, the nearer first.
    overlay->set(dir / "zz-copy.nc", "O1234\nM99\n");
    w.index().update_file(normal_path(dir / "zz-copy.nc"), "O1234\nM99\n");
    checked = check_text(w, main, text);
    REQUIRE(rules_of(checked) == std::vector<std::string>{"K3010"});
    CHECK(checked.report.findings.front().message.find("sub1234.nc, also in") != std::string::npos);
    // The document closes without being saved: gone from the index.
    w.index().remove_file(normal_path(dir / "zz-copy.nc"));
    w.index().remove_file(normal_path(dir / "sub1234.nc"));
    CHECK_FALSE(w.find_program(1234, main));
    fs::remove_all(dir);
    fs::remove_all(macros);
}
