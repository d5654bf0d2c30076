// The project layer through the command line (issues 12 and 13): folder walks that find every
// program and list what they skip, .kerf.toml strictness in every command, calls that reach
// programs inside other files of the folder and of library folders, and one finding for one
// missing program.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <boost/json.hpp>
#include <filesystem>

#include "tests/cli/cli_runner.hpp"

namespace fs = std::filesystem;
using namespace kerf::test;

namespace {

const fs::path kWork = fs::temp_directory_path() / ("kerf-test-cli-project-" + std::to_string(::getpid()));

CliRun run(const std::string& args) { return run_kerf(args, kWork / "runs"); }

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("kerf check on the corpus folder finds all 60 programs and skips only MANIFEST.md") {
    const fs::path corpus = fs::path(KERF_SHARED_DIR) / "corpus";
    if (!fs::is_directory(corpus)) {
        WARN("../shared is not there: the corpus walk was not checked");
        return;
    }
    // Before the project layer the walk found 54 (no 205, 220, 240, O0003, O8000, test.src).
    const CliRun r = run("check --verbose --format json " + shell_quote(corpus));
    REQUIRE((r.code == 0 || r.code == 1));
    CHECK(boost::json::parse(r.out).at("files_checked").as_int64() == 60);
    CHECK(r.err == (corpus / "MANIFEST.md").string() + ": skipped: not a program: no NC block in the first 65 lines\n");
}

TEST_CASE("kerf check counts the skipped files in its summary; --verbose lists them") {
    const fs::path dir = kWork / "summary";
    write_text(dir / "a.nc", "O1\nM30\n");
    write_text(dir / "notes.txt", "notes about the parts\n");
    const CliRun quiet = run("check --dialect fanuc-mill " + shell_quote(dir));
    CHECK(quiet.out.find("in 1 file(s) checked; 1 file(s) skipped (--verbose lists them)\n") != std::string::npos);
    CHECK(quiet.err.empty());
    const CliRun verbose = run("check --verbose --dialect fanuc-mill " + shell_quote(dir));
    CHECK(verbose.out.find("in 1 file(s) checked; 1 file(s) skipped (listed on stderr)\n") != std::string::npos);
    CHECK(verbose.err == (dir / "notes.txt").string() + ": skipped: not a program: no NC block in the first 1 lines\n");
    fs::remove_all(dir);
}

TEST_CASE("an unknown .kerf.toml key stops every command with its position and the valid keys") {
    const fs::path dir = kWork / "strict";
    write_text(dir / ".kerf.toml", "dialect = \"fanuc-mill\"\n[check]\nincludes = [\"*.nc\"]\n");
    const fs::path nc = write_text(dir / "a.nc", "O1\nG00 X1. Y1.\nM30\n");
    const std::string where = (dir / ".kerf.toml").string() + ":3:1: error: check.includes: unknown key; the keys of [check] are include, exclude and rules";
    for (const char* command : {"check", "run", "plot", "fmt --check", "parse"}) {
        INFO(command);
        const CliRun r = run(std::string(command) + " " + shell_quote(nc));
        CHECK(r.code == 2);
        CHECK(r.err.find(where) != std::string::npos);
        CHECK(count(r.err, where) == 1);   // once, not once per file or per dialect
    }
    fs::remove_all(dir);
}

TEST_CASE("calls reach programs inside other files of the folder and of library folders") {
    const fs::path dir = kWork / "calls";
    const fs::path lib = kWork / "macros";
    // O2000 is the second program of a punch-out named ALL.TXT; O9810 lives in a library folder.
    write_text(dir / "ALL.TXT", "%\nO1000 (FIRST)\nM99\nO2000 (SECOND)\nG00 X20. Y0.\nM99\n%\n");
    write_text(lib / "probe", "O9810 (MOVE)\nG00 X30. Y0.\nM99\n");
    write_text(dir / ".kerf.toml", "dialect = \"fanuc-mill\"\n[programs]\nlibrary = [\"../macros\"]\n");
    const fs::path main = write_text(dir / "main.nc", "O0001\nG90 G00 X0. Y0.\nM98 P2000\nG65 P9810\nM98 P4321\nM30\n");
    // kerf run: both calls reached (final X30. from O9810), O4321 missing: alarm 078 at line 5.
    const CliRun r = run("run " + shell_quote(main));
    CHECK(r.code == 1);
    CHECK(r.err == main.string() + ":5: error: alarm 78: program O4321 not found (alarm 078)\n");
    CHECK(r.out.find("final position X30.000 Y0.000") != std::string::npos);
    // kerf check: the missing program once (K3003 at the P word), not also as K4009.
    const CliRun c = run("check " + shell_quote(main));
    CHECK(c.code == 1);
    CHECK(count(c.out, "error K") == 1);
    CHECK(c.out.find(main.string() + ":5:5: error K3003 program-not-found: program O4321 is not in this file, the files of its folder or the library folders (alarm 078)") != std::string::npos);
    fs::remove_all(dir);
    fs::remove_all(lib);
}

// [programs] resident (issue 15): a call into the machine's resident range is skipped by the dry
// run of kerf run and kerf plot (project/start.hpp resident_programs), which then go on to the end;
// without the key the same call is alarm 078 and the run stops there.
TEST_CASE("[programs] resident: kerf run and kerf plot go on past a call to a resident program") {
    const fs::path dir = kWork / "resident";
    const fs::path main = write_text(dir / "main.nc", "O0001\nG90 G00 X0. Y0.\nG65 P9832 A1.\nG00 X10. Y5.\nM30\n");
    write_text(dir / ".kerf.toml", "dialect = \"haas-mill\"\n");
    const CliRun without = run("run " + shell_quote(main));
    CHECK(without.code == 1);
    CHECK(without.err.find(main.string() + ":3: error: alarm 78") != std::string::npos);
    write_text(dir / ".kerf.toml", "dialect = \"haas-mill\"\n[programs]\nresident = [\"O9000-O9999\"]\n");
    const CliRun with = run("run " + shell_quote(main));
    CHECK(with.code == 0);
    CHECK(with.out.find("final position X10.000 Y5.000") != std::string::npos);
    CHECK(with.out.find("ended normally") != std::string::npos);
    const CliRun plot = run("plot " + shell_quote(main));
    CHECK(plot.code == 0);
    CHECK(plot.out.find("alarm") == std::string::npos);   // no alarm marker: the run reached M30
    fs::remove_all(dir);
}

// [programs] resident in the three commands (issue 15): a call to O9810, which is in no file of the
// folder, is a resident program's for kerf check (no finding), kerf run (skipped with a message, the
// run goes on to M30) and kerf fmt --verify (both runs go on past it and are compared to M30);
// without the key all three stop at it: K3003, alarm 078, and a --verify that says it compared the
// runs only up to that alarm.
TEST_CASE("[programs] resident: kerf fmt --block-numbers renumber --verify treats the call as kerf check and kerf run do") {
    const fs::path dir = kWork / "resident-fmt";
    const std::string program = "O0001\nN5 G90 G00 X0. Y0.\nN7 M98 P9810\nN9 G00 X10. Y5.\nN11 G01 X20. F100.\nN13 M30\n";
    const fs::path main = write_text(dir / "main.nc", program);
    const std::string renumbered = "O0001\nN10 G90 G00 X0. Y0.\nN20 M98 P9810\nN30 G00 X10. Y5.\nN40 G01 X20. F100.\nN50 M30\n";
    const std::string fmt = "fmt --block-numbers renumber --verify " + shell_quote(main);

    write_text(dir / ".kerf.toml", "dialect = \"haas-mill\"\n[programs]\nresident = [\"O9800-O9899\"]\n");
    const CliRun check = run("check --format json " + shell_quote(main));
    INFO(check.out);
    CHECK(check.out.find("9810") == std::string::npos);   // no K3003, no K4009
    const CliRun ran = run("run " + shell_quote(main));
    CHECK(ran.code == 0);
    CHECK(ran.out.find("ended normally") != std::string::npos);
    CHECK(ran.out.find("final position X20.000 Y5.000") != std::string::npos);
    const CliRun formatted = run(fmt);
    INFO(formatted.err);
    CHECK(formatted.code == 0);
    CHECK(formatted.out == renumbered);   // P9810 is a program number, not a label: it stays
    CHECK(formatted.err.empty());         // compared to M30: nothing to say

    write_text(dir / ".kerf.toml", "dialect = \"haas-mill\"\n");
    const CliRun check_without = run("check " + shell_quote(main));
    CHECK(check_without.out.find("K3003") != std::string::npos);
    const CliRun ran_without = run("run " + shell_quote(main));
    CHECK(ran_without.code == 1);
    CHECK(ran_without.err.find(main.string() + ":3: error: alarm 78") != std::string::npos);
    const CliRun formatted_without = run(fmt);
    CHECK(formatted_without.code == 0);   // the runs agree, up to the alarm
    CHECK(formatted_without.out == renumbered);
    CHECK(formatted_without.err == main.string() + ":3: note: --verify compared the runs up to alarm 78 (program O9810 "
                                                   "not found (FANUC alarm 078) (Haas NGC numbers this alarm its own way; "
                                                   "kerf gives FANUC's)); the blocks after it are not verified\n");
    fs::remove_all(dir);
}

TEST_CASE("kerf check --fix and kerf fmt --write replace files through the one atomic writer") {
    const fs::path dir = kWork / "writer";
    const fs::path check_file = write_text(dir / "fix.nc", "O1\nT2 MO6\nM30\n");
    const fs::path fmt_file = write_text(dir / "fmt.nc", "O1\ng0 x1.\nM30\n");
    for (const fs::path& f : {check_file, fmt_file}) fs::permissions(f, fs::perms(0640));
    run("check --fix --dialect fanuc-mill " + shell_quote(check_file));
    run("fmt --write --dialect fanuc-mill " + shell_quote(fmt_file));
    CHECK(read_text(check_file) == "O1\nT2 M06\nM30\n");
    CHECK(read_text(fmt_file) == "O1\nG0 X1.\nM30\n");
    for (const fs::path& f : {check_file, fmt_file}) CHECK((fs::status(f).permissions() & fs::perms::all) == fs::perms(0640));
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
    CHECK(entries == 2);   // no temp file left
    fs::remove_all(dir);
}
