// kerf fmt from the command line (issue 6, point 4 and the CLI surface): --write on a folder leaves a
// file it cannot parse byte for byte and reports it, writes the others whole with their permissions;
// --check, --diff, stdin, .kerf.toml [format] under the flags, exit codes of design.md.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "tests/cli/cli_runner.hpp"

namespace fs = std::filesystem;
using kerf::test::read_text;
using kerf::test::run_kerf;
using kerf::test::shell_quote;
using kerf::test::write_text;

namespace {


fs::path fresh_folder(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("kerf-fmt-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
    fs::create_directories(dir);
    return dir;
}

const std::string kMessy = "%\no1000 (keep  THIS)\nn10  g0 x1   y2\n\n\nn20 m30\n%\n";
const std::string kTidy = "%\nO1000 (keep  THIS)\nN10 G0 X1 Y2\n\nN20 M30\n%\n";
// A file with a syntax error: `X1.2.3` has two decimal points (S0102).
const std::string kBroken = "%\no2000\ng0 x1.2.3\n\n\nm30\n%\n";

}  // namespace

TEST_CASE("kerf fmt --write: a file with syntax errors stays byte for byte, the others are written whole") {
    const fs::path dir = fresh_folder("write");
    write_text(dir / "a.nc", kMessy);
    // Large enough to notice a truncation: 200 000 blank lines that become one.
    write_text(dir / "sub" / "b.nc", "%\no1000 (keep  THIS)\nn10  g0 x1   y2\n" + std::string(200000, '\n') + "n20 m30\n%\n");
    write_text(dir / "bad.nc", kBroken);
    write_text(dir / "clean.nc", kTidy);
    fs::permissions(dir / "a.nc", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    const auto r = run_kerf("fmt --write --dialect fanuc-mill " + shell_quote(dir), kerf::test::runs_beside(dir));
    INFO(r.err);
    CHECK(r.code == 1);   // one file could not be formatted
    CHECK(read_text(dir / "bad.nc") == kBroken);
    CHECK(r.err.find((dir / "bad.nc").string() + ":3:4: error: malformed number") != std::string::npos);
    CHECK(r.err.find((dir / "bad.nc").string() + ": not formatted: 1 syntax error") != std::string::npos);
    CHECK(read_text(dir / "a.nc") == kTidy);
    CHECK(read_text(dir / "sub" / "b.nc") == kTidy);
    CHECK(read_text(dir / "clean.nc") == kTidy);
    CHECK(fs::status(dir / "a.nc").permissions() == (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
    for (const auto& e : fs::recursive_directory_iterator(dir))   // no temp file left behind
        CHECK(e.path().filename().string().find(".kerf-fmt-") == std::string::npos);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf fmt --check lists what would change; --diff shows it") {
    const fs::path dir = fresh_folder("check");
    write_text(dir / "a.nc", kMessy);
    write_text(dir / "clean.nc", kTidy);
    const auto check = run_kerf("fmt --check --dialect fanuc-mill " + shell_quote(dir), kerf::test::runs_beside(dir));
    CHECK(check.code == 1);
    CHECK(check.out == (dir / "a.nc").string() + "\n");
    CHECK(read_text(dir / "a.nc") == kMessy);   // --check writes nothing
    const auto clean = run_kerf("fmt --check --dialect fanuc-mill " + shell_quote(dir / "clean.nc"), kerf::test::runs_beside(dir));
    CHECK(clean.code == 0);
    CHECK(clean.out.empty());
    const auto diff = run_kerf("fmt --diff --dialect fanuc-mill " + shell_quote(dir / "a.nc"), kerf::test::runs_beside(dir));
    CHECK(diff.code == 1);
    const std::string name = (dir / "a.nc").string();
    CHECK(diff.out == "--- " + name + "\n+++ " + name + " (formatted)\n@@ -1,7 +1,6 @@\n %\n-o1000 (keep  THIS)\n"
                      "-n10  g0 x1   y2\n+O1000 (keep  THIS)\n+N10 G0 X1 Y2\n \n-\n-n20 m30\n+N20 M30\n %\n");
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf fmt: one file to stdout, - from stdin, several files need a mode") {
    const fs::path dir = fresh_folder("stdout");
    write_text(dir / "a.nc", kMessy);
    write_text(dir / "b.nc", kMessy);
    const auto one = run_kerf("fmt --dialect fanuc-mill " + shell_quote(dir / "a.nc"), kerf::test::runs_beside(dir));
    CHECK(one.code == 0);
    CHECK(one.out == kTidy);
    const auto piped = run_kerf("fmt - --dialect fanuc-mill", kerf::test::runs_beside(dir), kMessy);
    CHECK(piped.code == 0);
    CHECK(piped.out == kTidy);
    const auto broken = run_kerf("fmt - --dialect fanuc-mill", kerf::test::runs_beside(dir), kBroken);
    CHECK(broken.code == 1);
    CHECK(broken.out == kBroken);   // the editor gets its text back
    const auto two = run_kerf("fmt --dialect fanuc-mill " + shell_quote(dir), kerf::test::runs_beside(dir));
    CHECK(two.code == 2);
    CHECK(two.err.find("for several use --check, --diff or --write") != std::string::npos);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf fmt: .kerf.toml [format] under the flags; bad options are usage errors") {
    const fs::path dir = fresh_folder("config");
    write_text(dir / ".kerf.toml", "dialect = \"fanuc-mill\"\n[format]\nletter_case = \"lower\"\ncode_digits = \"two\"\n");
    write_text(dir / "a.nc", "G0 X1\n");
    const auto config = run_kerf("fmt " + shell_quote(dir / "a.nc"), kerf::test::runs_beside(dir));
    CHECK(config.out == "g00 x1\n");
    const auto flag = run_kerf("fmt --letter-case upper " + shell_quote(dir / "a.nc"), kerf::test::runs_beside(dir));
    CHECK(flag.out == "G00 X1\n");
    const auto bad_flag = run_kerf("fmt --spacing wide " + shell_quote(dir / "a.nc"), kerf::test::runs_beside(dir));
    CHECK(bad_flag.code == 2);
    CHECK(bad_flag.err.find("--spacing: 'wide' is not one of keep|spaced|compact") != std::string::npos);
    write_text(dir / ".kerf.toml", "[format]\nletter_cse = \"lower\"\n");
    const auto bad_key = run_kerf("fmt " + shell_quote(dir / "a.nc"), kerf::test::runs_beside(dir));
    CHECK(bad_key.code == 2);
    CHECK(bad_key.err.find("format.letter_cse: unknown key") != std::string::npos);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf fmt --verify and a renumbering refusal") {
    const fs::path dir = fresh_folder("verify");
    write_text(dir / "a.nc", "O1\nN10 G0 X1\nN20 #1=10\nN30 GOTO #1\nM30\n");
    write_text(dir / "b.nc", "O1\nN5 G0 X1 Y1\nN7 G1 X2 F100\nGOTO 7\nM30\n");
    const auto refused = run_kerf("fmt --write --dialect fanuc-mill --block-numbers renumber " + shell_quote(dir), kerf::test::runs_beside(dir));
    CHECK(refused.code == 1);
    CHECK(refused.err.find(":4:10: error: cannot renumber: GOTO '#1' is computed") != std::string::npos);
    CHECK(refused.err.find("in block 'N30 GOTO #1'") != std::string::npos);
    CHECK(read_text(dir / "a.nc") == "O1\nN10 G0 X1\nN20 #1=10\nN30 GOTO #1\nM30\n");
    // b.nc (an endless loop: the step limit ends both runs) was renumbered and verified.
    CHECK(read_text(dir / "b.nc") == "O1\nN10 G0 X1 Y1\nN20 G1 X2 F100\nN30 GOTO 20\nN40 M30\n");
    const auto verified = run_kerf("fmt --verify --check --dialect fanuc-mill --code-digits two " + shell_quote(dir / "b.nc"), kerf::test::runs_beside(dir));
    CHECK(verified.code == 1);   // it would change (G0 → G00), and the trace is the same
    CHECK(verified.err.empty());
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}
