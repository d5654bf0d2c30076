// `kerf parse`: output forms, exit codes, error format, dialect selection (flag > .kerf.toml > detection).
#include "tests/cli/cli_runner.hpp"

#include <boost/json.hpp>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using Run = kerf::test::CliRun;

namespace {

const fs::path kDir = fs::temp_directory_path() / "kerf-cli-parse";

// stdin is a file holding `stdin_text` (empty unless given).
Run run(const std::string& args, const std::string& stdin_text = "") { return kerf::test::run_kerf(args, kDir, stdin_text); }

fs::path write_temp(const std::string& name, const std::string& text) {
    return kerf::test::write_text(kDir / "files" / name, text);
}

}  // namespace

TEST_CASE("kerf parse --print gives the file back byte for byte, also from stdin") {
    const std::string text = "\xEF\xBB\xBF%\r\nO1 (X)\r\nG0 X1 (unclosed\r\n%\r\ntail";
    const fs::path p = write_temp("print.nc", text);
    const Run r = run("parse --print '" + p.string() + "'");
    CHECK(r.out == text);
    CHECK(r.code == 1);   // the unclosed comment is an error
    const Run s = run("parse --print -", text);
    CHECK(s.out == text);
}

TEST_CASE("kerf parse: errors on stderr as file:line:col: severity: message [id], exit 1") {
    const fs::path p = write_temp("bad.nc", "G0 X1\nG1 X-12.8. Z1\n");
    const Run r = run("parse --dialect fanuc-lathe-a '" + p.string() + "'");
    CHECK(r.code == 1);
    CHECK(r.err.find(p.string() + ":2:4: error: malformed number in 'X-12.8.'") != std::string::npos);
    CHECK(r.err.find("[K1002 (S0102)]") != std::string::npos);
    CHECK(r.err.find("hint: ") != std::string::npos);
}

// One defect, one id (issue 12): kerf parse, kerf fmt and kerf check all name MO6 K1003, the id a
// user suppresses; parse and fmt add the parser's S0103, check notes it.
TEST_CASE("kerf parse, fmt and check show the same id for one defect, and that id suppresses it") {
    const fs::path p = write_temp("mo6.nc", "O1\nT2 MO6\nM30\n");
    const Run parse = run("parse --dialect fanuc-mill '" + p.string() + "'");
    CHECK(parse.err.find(p.string() + ":2:4: error: letter O in 'MO6' where the digit zero is meant [K1003 (S0103)]") != std::string::npos);
    const Run fmt = run("fmt --dialect fanuc-mill '" + p.string() + "'");
    CHECK(fmt.err.find(p.string() + ":2:4: error: letter O in 'MO6' where the digit zero is meant [K1003 (S0103)]") != std::string::npos);
    const Run check = run("check --dialect fanuc-mill '" + p.string() + "'");
    CHECK(check.out.find(p.string() + ":2:4: error K1003 letter-o-for-zero:") != std::string::npos);
    CHECK(check.out.find("note: parser diagnostic S0103") != std::string::npos);
    const fs::path quiet = write_temp("mo6-ignored.nc", "O1\nT2 MO6 (kerf: ignore K1003)\nM30\n");
    const Run ignored = run("check --dialect fanuc-mill '" + quiet.string() + "'");
    CHECK(ignored.code == 0);
    CHECK(ignored.out.find("K1003") == std::string::npos);
}

TEST_CASE("kerf parse: clean file exits 0, missing file and unknown dialect exit 2") {
    const fs::path p = write_temp("good.nc", "O1\nG0 X1 Z2\nM30\n");
    CHECK(run("parse '" + p.string() + "'").code == 0);
    CHECK(run("parse /nonexistent/file.nc").code == 2);
    CHECK(run("parse --dialect nope '" + p.string() + "'").code == 2);
    CHECK(run("parse").code == 2);
}

TEST_CASE("kerf parse --json: typed AST with ranges, values, decimal points, roles") {
    const fs::path p = write_temp("json.nc", "O12\nN10 G01 U-2 X45. F.25 (CUT)\nM98 P41001\n");
    const Run r = run("parse --json --dialect fanuc-lathe-a '" + p.string() + "'");
    REQUIRE(r.code == 0);
    const boost::json::object root = boost::json::parse(r.out).as_object();
    CHECK(root.at("dialect").as_string() == "fanuc-lathe-a");
    const auto& blocks = root.at("blocks").as_array();
    REQUIRE(blocks.size() == 3);
    const auto& b1 = blocks[1].as_object();
    CHECK(b1.at("g_codes").as_array()[0].as_object().at("function").as_string() == "linear");
    const auto& axes = b1.at("axes").as_array();
    REQUIRE(axes.size() == 2);
    const auto& u = axes[0].as_object();
    CHECK(u.at("letter").as_string() == "U");
    CHECK(u.at("axis").as_string() == "X");
    CHECK(u.at("incremental").as_bool());
    CHECK(u.at("value").as_double() == -2.0);
    CHECK_FALSE(u.at("decimal_point").as_bool());
    CHECK(axes[1].as_object().at("decimal_point").as_bool());
    const auto& start = u.at("range").as_object().at("start").as_object();
    CHECK(start.at("line").as_int64() == 2);
    CHECK(start.at("column").as_int64() == 9);
    CHECK(b1.at("comments").as_array()[0].as_object().at("text").as_string() == "(CUT)");
    const auto& call = blocks[2].as_object().at("subprogram_call").as_object();
    CHECK(call.at("program").as_int64() == 1001);
    CHECK(call.at("repeats").as_int64() == 4);
    CHECK(root.at("programs").as_array()[0].as_object().at("number").as_int64() == 12);
}

TEST_CASE("kerf parse: --dialect beats .kerf.toml, which beats detection; --explain-dialect says why") {
    const fs::path dir = fs::temp_directory_path() / "kerf-cli-parse" / "project" / "sub";
    fs::create_directories(dir);
    std::ofstream(dir.parent_path() / ".kerf.toml") << "dialect = \"pcnc-mill\"\n";
    std::ofstream(dir / "p.nc") << "G0 X1 Y2 ; comment in pcnc-mill\n";
    const std::string file = kerf::test::shell_quote(dir / "p.nc");
    const Run from_config = run("parse --explain-dialect " + file);
    CHECK(from_config.code == 0);
    CHECK(from_config.err.find("dialect pcnc-mill from") != std::string::npos);
    const Run from_flag = run("parse --explain-dialect --dialect fanuc-mill " + file);
    CHECK(from_flag.err.find("dialect fanuc-mill from --dialect") != std::string::npos);
    fs::remove(dir.parent_path() / ".kerf.toml");
    const Run detected = run("parse --explain-dialect " + file);
    CHECK(detected.err.find("detected") != std::string::npos);
}
