// Issue 17, "what must be shown" 1: each input of the issue's first list, with the bounded time and
// memory of the command measured by getrusage (tests/cli/measured_run.hpp, generous bounds) and
// the message the user gets. The figures before the change are the issue's.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/cli/measured_run.hpp"

namespace fs = std::filesystem;
using kerf::test::check_bounded;
using kerf::test::run_kerf_measured;
using kerf::test::shell_quote;
using kerf::test::write_text;

namespace {

const fs::path kWork = fs::temp_directory_path() / "kerf_test_cli_bounds";

std::string repeat(const std::string& piece, std::size_t times) {
    std::string s;
    s.reserve(piece.size() * times);
    for (std::size_t i = 0; i < times; ++i) s += piece;
    return s;
}

std::size_t count(const std::string& text, const std::string& needle) {
    std::size_t n = 0;
    for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + needle.size())) ++n;
    return n;
}

bool has_raw_control_bytes(const std::string& text) {
    for (const char c : text)
        if ((static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') || c == 0x7F) return true;
    return false;
}

fs::path finding(const char* name) { return fs::path(KERF_SHARED_DIR) / "findings" / "cli-mutation" / name; }

// A run stopped by one of its bounds: the step or move limit, or on a slow machine the clock.
bool stopped_by_a_bound(const std::string& err) {
    return err.find("alarm 90001") != std::string::npos || err.find("alarm 90004") != std::string::npos ||
           err.find("alarm 90005") != std::string::npos;
}

}  // namespace

// Before: 23 GB and killed after 47 s (std::bad_alloc under 4 GB).
TEST_CASE("bounds: kerf check on a 1 MB line of 'X1. Y1.' is refused by the line limit, or checked within bounds") {
    const fs::path file = write_text(kWork / "line" / "line.nc", repeat("X1. Y1. ", 131072) + "\n");
    const auto refused = run_kerf_measured("check --dialect fanuc-mill " + shell_quote(file), kWork / "line" / "a");
    check_bounded(refused, 100, 10);
    CHECK(refused.code == 2);
    CHECK(refused.err.find("line.nc:1:1: error: line 1 is 1.0 MiB long, over the limit of 64.0 KiB per line") !=
          std::string::npos);
    CHECK(refused.err.find("--max-line-bytes") != std::string::npos);
    // Without the limit the file is checked: 262,142 repeated addresses (131,072 X words and 131,072 Y words, each but the first a repeat), 100 shown.
    const auto checked =
        run_kerf_measured("check --max-line-bytes 0 --dialect fanuc-mill " + shell_quote(file), kWork / "line" / "b");
    check_bounded(checked, 400, 60);
    CHECK(count(checked.out, "warning K1021") == 100);
    CHECK(checked.out.find("info K1021 duplicate-address: and 262042 more findings of K1021 in this file, not shown") !=
          std::string::npos);
    CHECK(checked.out.size() < 100'000);
}

// Before: 3,998 warnings and 97 MB of output, each reprinting the whole line.
TEST_CASE("bounds: a 16 KB line repeating an address gives 100 findings, 'and N more', and short excerpts") {
    const fs::path file = write_text(kWork / "dup" / "dup.nc", "G01 " + repeat("X1. ", 4000) + "F100.\n");
    const auto r = run_kerf_measured("check --dialect fanuc-mill " + shell_quote(file), kWork / "dup");
    check_bounded(r, 100, 10);
    CHECK(count(r.out, "warning K1021") == 100);
    // 3,999 repeats of X: 100 shown, the rest in one line (hand count: 4000 X words, the first is no repeat).
    CHECK(r.out.find("and 3899 more findings of K1021 in this file, not shown") != std::string::npos);
    CHECK(r.out.size() < 60'000);
    for (std::size_t at = 0, next; at < r.out.size(); at = next + 1) {
        next = r.out.find('\n', at);
        if (next == std::string::npos) break;
        CHECK(next - at < 200);   // the excerpt is a window around the column, not the 16 KB line
    }
    // --max-findings-per-rule 0 shows them all.
    const auto all = run_kerf_measured("check --max-findings-per-rule 0 --dialect fanuc-mill " + shell_quote(file), kWork / "dup" / "all");
    CHECK(count(all.out, "warning K1021") == 3999);
}

// Before: a 10-line M99 loop took 13.8 s and 3.5 GB and wrote a 407 MB SVG. Now the dry run runs
// one pass of a bar-feed loop by default (issue 12); asked for a million passes, the bounds end it.
TEST_CASE("bounds: kerf plot of an endless M99 loop stops at the step limit with a small SVG") {
    const std::string program = "O1000\nG21 G90 G17\nT1 M06\nS1000 M03\nG00 X0 Y0 Z5.\nG01 Z-1. F100.\n"
                                "G01 X50. Y0\nX50. Y50.\nX0 Y50.\nX0 Y0\nM99\n";
    const fs::path file = write_text(kWork / "loop" / "loop.nc", program);
    const fs::path svg = kWork / "loop" / "loop.svg";
    const auto one = run_kerf_measured("plot --dialect fanuc-mill -o " + shell_quote(svg) + " " + shell_quote(file), kWork / "loop");
    check_bounded(one, 100, 10);
    CHECK(one.code == 0);   // one pass, no alarm
    const auto r = run_kerf_measured("plot --passes 1000000 --dialect fanuc-mill -o " + shell_quote(svg) + " " + shell_quote(file),
                                     kWork / "loop");
    check_bounded(r, 100, 60);
    CHECK(r.code == 1);
    CHECK(stopped_by_a_bound(r.err));
    CHECK(fs::file_size(svg) < 20'000);
    // The square is drawn once however often the loop ran it.
    CHECK(kerf::test::read_text(svg).find("</svg>") != std::string::npos);
}

// Before: run, check and fmt --verify did not finish in 20 s (the run not in 120 s): the G76 of
// system C (face peck drilling) with Q400 from Z550 to Z-30 expands into ~340,000 moves per pass
// of the main program's M99 loop, and the step limit counted blocks only. Now the move limit
// (90004) ends a run asked for a million passes; by default one pass runs (issue 12) and ends.
TEST_CASE("bounds: ../shared/findings hang-run-check-fmt stops at the move limit in run, check and fmt --verify") {
    const fs::path file = finding("hang-run-check-fmt.fanuc-lathe-c.nc");
    if (!fs::exists(file)) {
        WARN("../shared/findings is not there: skipped");
        return;
    }
    const std::string f = shell_quote(file);
    const auto run = run_kerf_measured("run --lenient --passes 1000000 --dialect fanuc-lathe-c " + f, kWork / "hang1" / "run");
    check_bounded(run, 100, 60);
    CHECK(run.code == 1);
    CHECK((run.err.find("alarm 90004: move limit of 10000000 moves reached") != std::string::npos ||
           run.err.find("alarm 90005") != std::string::npos));
    const auto one = run_kerf_measured("run --lenient --dialect fanuc-lathe-c " + f, kWork / "hang1" / "one");
    check_bounded(one, 100, 60);
    CHECK(one.out.find("the program repeats") != std::string::npos);
    const auto check = run_kerf_measured("check --format json --dialect fanuc-lathe-c " + f, kWork / "hang1" / "check");
    check_bounded(check, 100, 60);
    CHECK(check.out.find("\"rule\":\"K4004\"") == std::string::npos);   // one pass: no endless loop
    const auto verify = run_kerf_measured("fmt --verify --dialect fanuc-lathe-c " + f, kWork / "hang1" / "fmt");
    check_bounded(verify, 200, 60);
    // No difference reported. Its G103 is no code of system C: both runs stop there with alarm 010,
    // and fmt says up to where it compared.
    CHECK(verify.err.find("runs differently") == std::string::npos);
    CHECK(verify.err.find("compared the runs up to alarm 10 (G103 is not a code of fanuc-lathe-c") != std::string::npos);
}

// Before: kerf plot did not finish in 20 s. An M99 loop of G41 moves with an arc of R11.e5 runs
// 2-5 µs a block: the step limit (10 million blocks) or the clock ends it; the plot keeps a few
// pieces.
TEST_CASE("bounds: ../shared/findings hang-plot finishes with a small SVG") {
    const fs::path file = finding("hang-plot.adv400-mill.nc");
    if (!fs::exists(file)) {
        WARN("../shared/findings is not there: skipped");
        return;
    }
    const fs::path svg = kWork / "hang2" / "out.svg";
    // Lenient: its G43 (line 6) is no code of adv400-mill, and a strict run stops there with alarm 010.
    const auto r = run_kerf_measured("plot --lenient --passes 1000000 --dialect adv400-mill -o " + shell_quote(svg) + " " +
                                         shell_quote(file),
                                     kWork / "hang2");
    check_bounded(r, 100, 60);
    CHECK(r.code == 1);
    // Its G01 (line 13) has no F: alarm 011 stops it now (issue 12), before the loop could.
    CHECK((stopped_by_a_bound(r.err) || r.err.find("alarm 11: feed move with no feed rate") != std::string::npos));
    CHECK(fs::file_size(svg) < 100'000);
}

// Before: std::bad_alloc under a 6 GiB limit: the plot kept every move of a run to the step limit.
TEST_CASE("bounds: ../shared/findings oom-plot files plot within bounds") {
    for (const char* name : {"oom-plot.adv400-lathe.nc", "oom-plot.fanuc-lathe-a.nc", "oom-plot.fanuc-mill.nc",
                             "oom-plot.pcnc-mill.nc", "oom-plot.spinner-lathe-a.nc"}) {
        const fs::path file = finding(name);
        if (!fs::exists(file)) {
            WARN("../shared/findings is not there: skipped");
            return;
        }
        INFO(name);
        std::string dialect = fs::path(name).stem().extension().string().substr(1);
        const fs::path svg = kWork / "oom" / (std::string(name) + ".svg");
        // The findings loop with M99. One pass is the default; asked for a million passes they run
        // until the passes are done or a bound stops them, and the picture does not grow with the
        // passes: a pass drawn again adds nothing (plot/toolpath.hpp), whatever the pass draws.
        const fs::path one_svg = kWork / "oom" / (std::string(name) + ".one.svg");
        const auto one = run_kerf_measured("plot --dialect " + dialect + " -o " + shell_quote(one_svg) + " " + shell_quote(file),
                                           kWork / "oom");
        check_bounded(one, 100, 60);
        const auto r = run_kerf_measured("plot --passes 1000000 --dialect " + dialect + " -o " + shell_quote(svg) + " " +
                                             shell_quote(file),
                                         kWork / "oom");
        check_bounded(r, 100, 60);
        CHECK((r.code == 0 || stopped_by_a_bound(r.err) || r.err.find(": error: alarm ") != std::string::npos));
        CHECK(fs::file_size(svg) <= fs::file_size(one_svg) + 20'000);
        CHECK(fs::file_size(svg) < 1'000'000);   // ARCHITECTURE.md "Bounded resources": a few MB at most
    }
}

// Before: 11,203 findings and 20 MB of raw binary and escape bytes on the terminal.
TEST_CASE("bounds: a binary file is refused with one message by every command") {
    const fs::path file = kWork / "binary" / "x.nc";
    fs::create_directories(file.parent_path());
    fs::copy_file("/bin/ls", file, fs::copy_options::overwrite_existing);
    for (const std::string command : {"check", "run", "plot -o /dev/null", "fmt", "parse"}) {
        INFO(command);
        const auto r = run_kerf_measured(command + " " + shell_quote(file), kWork / "binary" / "out");
        check_bounded(r, 100, 10);
        CHECK(r.code == 2);
        CHECK(count(r.err, "error: binary data, not an NC program") == 1);
        CHECK(count(r.err, "\n") == 1);
        CHECK(!has_raw_control_bytes(r.out + r.err));
        CHECK(r.out.size() < 200);
    }
}

// Before: 53 "stray text" errors with NUL bytes printed. UTF-16/32 files are read (and written
// back in their encoding by fmt --write).
TEST_CASE("bounds: UTF-16 and UTF-32 files, with or without BOM, are read like their UTF-8 text") {
    const std::string text = "O1000\nG0 X1. Y2.\nG1 X5. F100. (\xD0\x96)\nM30\n";
    const auto plain = run_kerf_measured("check --dialect fanuc-mill " + shell_quote(write_text(kWork / "u" / "utf8.nc", text)),
                                         kWork / "u" / "plain");
    // UTF-16LE with BOM: FF FE, then each ASCII character as c 00; Ж (U+0416) as 16 04.
    std::string utf16le = "\xFF\xFE";
    std::string utf16be;   // no BOM
    std::string utf32le;   // no BOM
    for (std::size_t i = 0; i < text.size(); ++i) {
        char16_t c = static_cast<unsigned char>(text[i]);
        if (text.compare(i, 2, "\xD0\x96") == 0) {
            c = 0x0416;
            ++i;
        }
        utf16le += static_cast<char>(c & 0xFF);
        utf16le += static_cast<char>(c >> 8);
        utf16be += static_cast<char>(c >> 8);
        utf16be += static_cast<char>(c & 0xFF);
        utf32le += static_cast<char>(c & 0xFF);
        utf32le += static_cast<char>(c >> 8);
        utf32le += std::string(2, '\0');
    }
    const std::string expected_note[] = {"read as UTF-16LE with a byte-order mark", "read as UTF-16BE;", "read as UTF-32LE;"};
    int k = 0;
    for (const auto& [name, bytes] : {std::pair{"u16le.nc", utf16le}, std::pair{"u16be.nc", utf16be}, std::pair{"u32le.nc", utf32le}}) {
        INFO(name);
        const fs::path file = write_text(kWork / "u" / name, bytes);
        const auto r = run_kerf_measured("check --dialect fanuc-mill " + shell_quote(file), kWork / "u" / "out");
        check_bounded(r, 100, 10);
        CHECK(r.err.find(expected_note[k++]) != std::string::npos);
        CHECK(r.out.find("K1001") == std::string::npos);   // no stray text
        CHECK(r.out.find('\0') == std::string::npos);
        // The same findings as the UTF-8 file (the file name aside).
        std::string same = r.out;
        for (std::size_t at; (at = same.find(name)) != std::string::npos;) same.replace(at, std::string(name).size(), "utf8.nc");
        CHECK(same == plain.out);
    }
    // fmt --write keeps UTF-16LE and its BOM: the only change is G0 -> G00 (code_digits = two? no:
    // the default style keeps spellings; a trailing blank goes).
    const fs::path file = write_text(kWork / "u" / "w16.nc", utf16le.substr(0, utf16le.size() - 2) + std::string(" \0\n\0", 4));
    const auto w = run_kerf_measured("fmt --write --dialect fanuc-mill " + shell_quote(file), kWork / "u" / "w");
    CHECK(w.code == 0);
    const std::string written = kerf::test::read_text(file);
    CHECK(written == utf16le);
}

// Before: check said clean, run said "no program to run".
TEST_CASE("bounds: a file with CR-only line ends reads line by line in every command") {
    const std::string lf = "O1000\nG0 X1. Y2.\nG1 X5. F100.\nX-5\nM30\n";
    std::string cr = lf;
    for (char& c : cr)
        if (c == '\n') c = '\r';
    const fs::path lf_file = write_text(kWork / "cr" / "lf.nc", lf), cr_file = write_text(kWork / "cr" / "cr.nc", cr);
    const auto lf_check = run_kerf_measured("check --dialect fanuc-mill " + shell_quote(lf_file), kWork / "cr" / "a");
    const auto cr_check = run_kerf_measured("check --dialect fanuc-mill " + shell_quote(cr_file), kWork / "cr" / "b");
    check_bounded(cr_check, 100, 10);
    // X-5 on line 4 has no decimal point (K1020) and the cut has no tool (K5008, line 3).
    CHECK(cr_check.out.find("cr.nc:4:1: warning K1020") != std::string::npos);
    std::string same = cr_check.out;
    same.replace(same.find("cr.nc"), 5, "lf.nc");
    for (std::size_t at; (at = same.find("cr.nc")) != std::string::npos;) same.replace(at, 5, "lf.nc");
    CHECK(same == lf_check.out);
    const auto run = run_kerf_measured("run --dialect fanuc-mill " + shell_quote(cr_file), kWork / "cr" / "c");
    CHECK(run.code == 0);
    CHECK(run.out.find("blocks executed 5") != std::string::npos);
    CHECK(run.out.find("ended normally") != std::string::npos);
    const auto fmt = run_kerf_measured("fmt --dialect fanuc-mill " + shell_quote(cr_file), kWork / "cr" / "d");
    CHECK(fmt.code == 0);
    CHECK(fmt.out == cr);   // formatted already; the CR line ends stay
}

// Before: exit 2 and the file's 29 findings vanished from the report.
TEST_CASE("bounds: kerf check --fix that cannot write the file still reports its findings") {
    const fs::path dir = kWork / "fix";
    fs::remove_all(dir);   // the folder is counted below
    const fs::path file = write_text(dir / "x.nc", "O1000\nG0 X1. Y2.\nMO6\nM30\n");
    // A file size limit of 0 makes every write to a file fail, for root too (SIGXFSZ ignored: write
    // gets EFBIG). kerf's output goes through a pipe, which the limit does not cover; the exit code
    // is written by the unlimited shell around it.
    const fs::path out = dir / "out.txt", code = dir / "code.txt";
    const std::string cmd = "( (trap '' XFSZ; ulimit -f 0; exec " + std::string(KERF_BINARY) +
                            " check --fix --dialect fanuc-mill " + shell_quote(file) + " </dev/null 2>&1); echo $? >" +
                            shell_quote(code) + " ) | cat >" + shell_quote(out);
    REQUIRE(std::system(cmd.c_str()) == 0);
    const std::string printed = kerf::test::read_text(out);
    INFO(printed);
    CHECK(kerf::test::read_text(code) == "2\n");
    CHECK(printed.find("nothing was fixed: its findings are reported as they are") != std::string::npos);
    CHECK(printed.find("x.nc:3:1: error K1003") != std::string::npos);   // MO6: the letter O for a zero
    CHECK(printed.find("in 1 file(s) checked") != std::string::npos);
    CHECK(kerf::test::read_text(file) == "O1000\nG0 X1. Y2.\nMO6\nM30\n");
    std::size_t entries = 0;   // x.nc, out.txt, code.txt: no temporary file left behind
    for (const auto& e : fs::directory_iterator(dir)) entries += e.path().filename() != "stdout.txt" && e.path().filename() != "stderr.txt";
    CHECK(entries == 3);
}

// Before: every command said all was well.
TEST_CASE("bounds: an empty file gets a note from every command") {
    const fs::path empty = write_text(kWork / "empty" / "empty.nc", "");
    const fs::path blank = write_text(kWork / "empty" / "blank.nc", "\n  \r\n\t\n");
    for (const std::string command : {"check", "run", "plot -o /dev/null", "fmt", "parse"}) {
        INFO(command);
        const auto r = run_kerf_measured(command + " --dialect fanuc-mill " + shell_quote(empty), kWork / "empty" / "out");
        CHECK(r.err.find("empty.nc: note: the file is empty: no program") != std::string::npos);
        const auto b = run_kerf_measured(command + " --dialect fanuc-mill " + shell_quote(blank), kWork / "empty" / "out");
        CHECK(b.err.find("blank.nc: note: the file holds only blanks and line breaks: no program") != std::string::npos);
    }
}

TEST_CASE("bounds: control bytes of a file are escaped in what kerf prints") {
    // ESC [2J (clear screen) in a comment, a NUL and a BEL in junk, C1 CSI (U+009B) in a comment.
    // Twenty ordinary blocks keep the two control bytes under 1 % of the file: a stray NUL in a
    // program is read and shown escaped (in a file of a few lines it would be refused as binary).
    const std::string program =
        "O1000\n" + repeat("G1 X1. Y1.\n", 20) + std::string("G0 X1. (\x1b[2J)\nX2. @\x07@ \0@\nG1 X3 (\xC2\x9B" "31m)\nM30\n", 43);
    const fs::path file = write_text(kWork / "ctl" / "ctl.nc", program);
    for (const std::string command : {"check", "parse", "fmt"}) {
        INFO(command);
        const auto r = run_kerf_measured(command + " --dialect fanuc-mill " + shell_quote(file), kWork / "ctl" / "out");
        CHECK(!has_raw_control_bytes(command == "fmt" ? r.err : r.out + r.err));
    }
    const auto r = run_kerf_measured("check --dialect fanuc-mill " + shell_quote(file), kWork / "ctl" / "out");
    CHECK(r.out.find("@\\x07@ \\x00@") != std::string::npos);
    CHECK(r.out.find("(\\u009b31m)") != std::string::npos);
}
