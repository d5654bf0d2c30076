// kerf convert from the command line (issue 16): one file to stdout or -o, stdin, folders with
// --write (atomic; a file with reports is left as it was) and --output-dir (relative paths kept),
// --verify (a difference names the first differing block of each side), --format json, the UTF-16
// encoding kept, and the exit codes of design.md (an unknown dialect names the valid ones).
#include <catch2/catch.hpp>

#include <boost/json.hpp>

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
    const fs::path dir = kerf::test::fresh_folder("convert-" + name);   // tests/shared_files.hpp
    fs::remove_all(kerf::test::runs_beside(dir));
    return dir;
}

const std::string kLatheA = "(DIALECT: fanuc-lathe-a)\nO0001\nN10 G50 S2000\nN20 G99 G97 S500 M03\nN30 G00 X50. Z2.\n"
                            "N40 G01 W-10. F0.2\nN50 X60.\nN60 M30\n";
const std::string kLatheB = "(DIALECT: fanuc-lathe-b)\nO0001\nN10 G92 S2000\nN20 G95 G97 S500 M03\nN30 G00 X50. Z2.\n"
                            "N40 G91 G01 Z-10. F0.2\nN50 G90 X60.\nN60 M30\n";
// G384 has no equivalent in a plain FANUC lathe.
const std::string kSpinner = "(DIALECT: spinner-lathe-a)\nO0002\nN10 G0 X100. Z100.\nN20 G384 X0 C0 Z-15 R2 F1 S500 T1\n"
                             "N30 G380\nN40 M30\n";

}  // namespace

TEST_CASE("kerf convert FILE: the result on stdout, exit 0; -o writes it") {
    const fs::path dir = fresh_folder("one");
    write_text(dir / "a.nc", kLatheA);
    auto r = run_kerf("convert --to fanuc-lathe-b " + shell_quote(dir / "a.nc"), kerf::test::runs_beside(dir));
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(r.out == kLatheB);
    CHECK(r.err.empty());
    r = run_kerf("convert --to fanuc-lathe-b --verify -o " + shell_quote(dir / "b.nc") + " " + shell_quote(dir / "a.nc"), kerf::test::runs_beside(dir));
    CHECK(r.code == 0);
    CHECK(r.out.empty());
    CHECK(read_text(dir / "b.nc") == kLatheB);
    // And back: the same bytes (--from given, the header would say so too).
    r = run_kerf("convert --from fanuc-lathe-b --to fanuc-lathe-a " + shell_quote(dir / "b.nc"), kerf::test::runs_beside(dir));
    CHECK(r.code == 0);
    CHECK(r.out == kLatheA);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf convert -: standard input to standard output") {
    const fs::path dir = fresh_folder("stdin");
    const auto r = run_kerf("convert --from fanuc-lathe-a --to fanuc-lathe-c -", kerf::test::runs_beside(dir), kLatheA);
    CHECK(r.code == 0);
    CHECK(r.out.find("N10 G92 S2000\nN20 G95 G97") != std::string::npos);
    // --write has no file to write for standard input.
    const auto w = run_kerf("convert --write --from fanuc-lathe-a --to fanuc-lathe-c -", kerf::test::runs_beside(dir), kLatheA);
    CHECK(w.code == 2);
    CHECK(w.err.find("standard input") != std::string::npos);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf convert: a construct without an equivalent is reported with file:line:col, exit 1") {
    const fs::path dir = fresh_folder("report");
    write_text(dir / "s.nc", kSpinner);
    const auto r = run_kerf("convert --to fanuc-lathe-a " + shell_quote(dir / "s.nc"), kerf::test::runs_beside(dir));
    CHECK(r.code == 1);
    CHECK(r.err.find((dir / "s.nc").string() + ":4:5: not converted: G384: G384 (live-tool-rigid-tapping) has no equivalent in "
                                               "fanuc-lathe-a") != std::string::npos);
    CHECK(r.err.find((dir / "s.nc").string() + ":5:5: not converted: G380") != std::string::npos);
    // Left as it is, not dropped.
    CHECK(r.out.find("N20 G384 X0 C0 Z-15 R2 F1 S500 T1\n") != std::string::npos);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf convert: an unknown dialect is a usage error naming the valid ids; several files need --write") {
    const fs::path dir = fresh_folder("usage");
    write_text(dir / "a.nc", kLatheA);
    auto r = run_kerf("convert --to fanuc-lathe-d " + shell_quote(dir / "a.nc"), kerf::test::runs_beside(dir));
    CHECK(r.code == 2);
    CHECK(r.err.find("--to: unknown dialect 'fanuc-lathe-d' (known: ") != std::string::npos);
    CHECK(r.err.find("fanuc-lathe-b") != std::string::npos);
    CHECK(r.err.find("pcnc-mill") != std::string::npos);
    r = run_kerf("convert --to fanuc-lathe-b " + shell_quote(dir), kerf::test::runs_beside(dir));
    CHECK(r.code == 2);
    CHECK(r.err.find("--write or --output-dir") != std::string::npos);
    r = run_kerf("convert --to fanuc-lathe-b " + shell_quote(dir / "missing.nc"), kerf::test::runs_beside(dir));
    CHECK(r.code == 2);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf convert --write: converted files replaced atomically, a file with reports left as it was") {
    const fs::path dir = fresh_folder("write");
    write_text(dir / "a.nc", kLatheA);
    write_text(dir / "sub" / "a2.nc", kLatheA);
    write_text(dir / "s.nc", kSpinner);
    fs::permissions(dir / "a.nc", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    const auto r = run_kerf("convert --write --verify --to fanuc-lathe-b " + shell_quote(dir), kerf::test::runs_beside(dir));
    INFO(r.err);
    // s.nc is spinner-lathe-a: into fanuc-lathe-b G384 has no equivalent.
    CHECK(r.code == 1);
    CHECK(read_text(dir / "a.nc") == kLatheB);
    CHECK(read_text(dir / "sub" / "a2.nc") == kLatheB);
    CHECK(read_text(dir / "s.nc") == kSpinner);
    CHECK(r.err.find((dir / "s.nc").string() + ": error: not written") != std::string::npos);
    CHECK(r.err.find("kerf convert: 3 files to fanuc-lathe-b: 2 converted cleanly, 1 with reports") != std::string::npos);
    CHECK(fs::status(dir / "a.nc").permissions() == (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
    for (const auto& e : fs::recursive_directory_iterator(dir)) CHECK(e.path().filename().string().find(".kerf") == std::string::npos);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf convert --output-dir: the results under DIR at their relative paths, sources untouched") {
    const fs::path dir = fresh_folder("outdir");
    write_text(dir / "in" / "a.nc", kLatheA);
    write_text(dir / "in" / "deep" / "b.nc", kLatheA);
    const auto r = run_kerf("convert --to fanuc-lathe-b --output-dir " + shell_quote(dir / "out") + " " + shell_quote(dir / "in"),
                            kerf::test::runs_beside(dir));
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(read_text(dir / "out" / "a.nc") == kLatheB);
    CHECK(read_text(dir / "out" / "deep" / "b.nc") == kLatheB);
    CHECK(read_text(dir / "in" / "a.nc") == kLatheA);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf convert --verify: a difference fails the file with the first differing block of each side") {
    const fs::path dir = fresh_folder("verify");
    // The unknown code G91 of system A is left as it is; in B it is incremental: the runs differ.
    write_text(dir / "g91.nc", "(DIALECT: fanuc-lathe-a)\nO0003\nN10 G00 X100. Z100.\nN20 G91 G28 Z0.\nN30 M30\n");
    const auto r = run_kerf("convert --verify --to fanuc-lathe-b " + shell_quote(dir / "g91.nc"), kerf::test::runs_beside(dir));
    CHECK(r.code == 1);
    CHECK(r.err.find((dir / "g91.nc").string() + ":4:5: not converted: G91") != std::string::npos);
    CHECK(r.err.find("error: --verify: the converted program runs differently at motion event") != std::string::npos);
    CHECK(r.err.find("(fanuc-lathe-a) line 4: N20 G91 G28 Z0.") != std::string::npos);
    CHECK(r.err.find("  converted (fanuc-lathe-b) line 4: N20 G91 G28 Z0.") != std::string::npos);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf convert --verify: runs that stop at the same alarm are verified up to it, and it says so") {
    const fs::path dir = fresh_folder("verify-alarm");
    // G710 is a code of neither system: both controls stop at it with alarm 010.
    write_text(dir / "g710.nc", "(DIALECT: fanuc-lathe-a)\nO0004\nN10 G00 X100. Z100.\nN20 G710 U1.\nN30 G00 X50.\nN40 M30\n");
    const auto r = run_kerf("convert --verify --to fanuc-lathe-c " + shell_quote(dir / "g710.nc"), kerf::test::runs_beside(dir));
    CHECK(r.code == 0);
    CHECK(r.err.find((dir / "g710.nc").string() +
                     ":4: note: --verify compared the runs up to alarm 10 (G710 is not a code of fanuc-lathe-a (alarm 010)); "
                     "the blocks after it are not verified") != std::string::npos);
    const auto j = run_kerf("convert --verify --format json --to fanuc-lathe-c " + shell_quote(dir / "g710.nc"),
                            kerf::test::runs_beside(dir));
    CHECK(j.out.find(R"("verified_up_to_alarm":{"line":4,"alarm":10,)") != std::string::npos);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf convert --format json: one document with every report and the output") {
    const fs::path dir = fresh_folder("json");
    write_text(dir / "s.nc", kSpinner);
    const auto r = run_kerf("convert --format json --to fanuc-lathe-a " + shell_quote(dir / "s.nc"), kerf::test::runs_beside(dir));
    CHECK(r.code == 1);
    const boost::json::value doc = boost::json::parse(r.out);
    CHECK(doc.at("target").as_string() == "fanuc-lathe-a");
    const auto& file = doc.at("files").as_array().at(0).as_object();
    CHECK(file.at("from").as_string() == "spinner-lathe-a");
    CHECK(file.at("clean").as_bool() == false);
    const auto& report = file.at("reports").as_array().at(0).as_object();
    CHECK(report.at("line").as_int64() == 4);
    CHECK(report.at("column").as_int64() == 5);
    CHECK(report.at("kind").as_string() == "not converted");
    CHECK(report.at("construct").as_string() == "G384");
    CHECK(file.at("output").as_string().subview().find("N20 G384") != std::string::npos);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}

TEST_CASE("kerf convert keeps a UTF-16 file in UTF-16") {
    const fs::path dir = fresh_folder("utf16");
    std::string utf16 = "\xFF\xFE";   // UTF-16LE with BOM
    for (const char c : kLatheA) utf16 += std::string{c, '\0'};
    write_text(dir / "w.nc", utf16);
    const auto r = run_kerf("convert --to fanuc-lathe-b -o " + shell_quote(dir / "out.nc") + " " + shell_quote(dir / "w.nc"), kerf::test::runs_beside(dir));
    INFO(r.err);
    CHECK(r.code == 0);
    std::string expected = "\xFF\xFE";
    for (const char c : kLatheB) expected += std::string{c, '\0'};
    CHECK(read_text(dir / "out.nc") == expected);
    fs::remove_all(dir);
    fs::remove_all(kerf::test::runs_beside(dir));
}
