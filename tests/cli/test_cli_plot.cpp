// `kerf plot` (and `kerf run --machine`): output to a file or stdout, exit codes as `kerf run`,
// alarms on stderr with the picture still written, machine files from --machine and .kerf.toml.
#include "tests/cli/cli_runner.hpp"

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using kerf::test::read_text;
using kerf::test::shell_quote;
using kerf::test::write_text;
using Run = kerf::test::CliRun;

namespace {

const fs::path kDir = fs::temp_directory_path() / "kerf-cli-plot";

Run run(const std::string& args) { return kerf::test::run_kerf(args, kDir); }

fs::path write_temp(const std::string& name, const std::string& text) { return write_text(kDir / "files" / name, text); }

bool is_svg(const std::string& s) { return s.rfind("<svg", 0) == 0 && s.find("</svg>") != std::string::npos; }

// A lathe program with a G02 fillet (reference O0004 shape), decimal points throughout.
const std::string kLathe = "O1\nG0 X30. Z2.\nG1 Z-22. F.2\nG2 X40. Z-27. R5.\nG0 X150. Z150.\nM30\n";

}  // namespace

TEST_CASE("kerf plot -o writes the SVG to the file, without -o to stdout") {
    const fs::path nc = write_temp("lathe.nc", kLathe);
    const fs::path svg = kDir / "files" / "lathe.svg";
    fs::remove(svg);
    const Run r = run("plot --dialect fanuc-lathe-a " + shell_quote(nc) + " -o " + shell_quote(svg));
    CHECK(r.code == 0);
    CHECK(r.out.empty());
    CHECK(r.err.empty());
    const std::string file = read_text(svg);
    CHECK(is_svg(file));
    CHECK(file.find("lathe.nc (fanuc-lathe-a)") != std::string::npos);   // the title
    CHECK(file.find(" A") != std::string::npos);                          // the G02 is an arc
    CHECK(file.find("X drawn at the radius") != std::string::npos);      // the built-in lathe
    const Run s = run("plot --dialect fanuc-lathe-a " + shell_quote(nc));
    CHECK(s.code == 0);
    CHECK(s.out == file);
}

TEST_CASE("kerf plot: alarms on stderr, exit 1, the picture of what ran is still written") {
    // R1 cannot reach X100: alarm 020 after the rapid.
    const fs::path nc = write_temp("alarm.nc", "O1\nG0 X10. Z0.\nG2 X100. Z-5. R1.\nM30\n");
    const fs::path svg = kDir / "files" / "alarm.svg";
    fs::remove(svg);
    const Run r = run("plot --dialect fanuc-lathe-a " + shell_quote(nc) + " -o " + shell_quote(svg));
    CHECK(r.code == 1);
    CHECK(r.err.find(nc.string() + ":3: error: alarm 20:") != std::string::npos);
    const std::string file = read_text(svg);
    CHECK(is_svg(file));
    CHECK(file.find("<path class=\"rapid\"") != std::string::npos);
    CHECK(file.find("<path class=\"alarm\"") != std::string::npos);
}

TEST_CASE("kerf plot: usage and I/O errors exit 2") {
    const fs::path nc = write_temp("ok.nc", kLathe);
    CHECK(run("plot /nonexistent/file.nc").code == 2);
    CHECK(run("plot --dialect nope " + shell_quote(nc)).code == 2);
    CHECK(run("plot").code == 2);
    const Run r = run("plot --dialect fanuc-lathe-a " + shell_quote(nc) + " -o /nonexistent/dir/out.svg");
    CHECK(r.code == 2);
    CHECK(r.err.find("/nonexistent/dir/out.svg: error: cannot write the picture") != std::string::npos);
}

TEST_CASE("kerf plot: a program without motion is a clean run and a picture saying so") {
    const fs::path empty = write_temp("empty.nc", "");
    const Run r = run("plot --dialect fanuc-lathe-a " + shell_quote(empty));
    CHECK(r.code == 0);
    CHECK(is_svg(r.out));
    CHECK(r.out.find("no motion") != std::string::npos);
}

// A lathe whose X is programmed as a radius: the fillet's X40 is then 40 mm from the axis, so R5
// no longer reaches (alarm), and the plot no longer halves X.
TEST_CASE("kerf plot/run --machine: a good machine file changes the run, a bad one is reported with its position") {
    const fs::path nc = write_temp("machine.nc", kLathe);
    const fs::path good = write_temp("radius-lathe.toml", "id = \"radius-lathe\"\nbase = \"fanuc-lathe\"\ndiameter_x = false\n");
    const Run p = run("plot --dialect fanuc-lathe-a --machine " + shell_quote(good) + " " + shell_quote(nc));
    CHECK(p.code == 1);
    CHECK(p.err.find("alarm 20") != std::string::npos);
    CHECK(is_svg(p.out));
    CHECK(p.out.find("X drawn at the radius") == std::string::npos);
    CHECK(run("run --dialect fanuc-lathe-a " + shell_quote(nc)).code == 0);
    CHECK(run("run --dialect fanuc-lathe-a --machine " + shell_quote(good) + " " + shell_quote(nc)).code == 1);

    // Line 3 column 10 is the value of the unknown key; line 5 column 9 the string where a number belongs.
    const fs::path bad = write_temp("bad-machine.toml", "id = \"bad\"\nbase = \"fanuc-lathe\"\ncolour = 1\n[axes.X]\nrapid = \"fast\"\n");
    for (const char* command : {"plot", "run"}) {
        INFO(command);
        const Run b = run(std::string(command) + " --dialect fanuc-lathe-a --machine " + shell_quote(bad) + " " + shell_quote(nc));
        CHECK(b.code == 2);
        CHECK(b.out.empty());
        CHECK(b.err.find(bad.string() + ":3:10: error: top level: unknown key 'colour'") != std::string::npos);
        CHECK(b.err.find(bad.string() + ":5:9: error: axes.X.rapid: expected a number") != std::string::npos);
    }
    const Run missing = run("plot --machine /nonexistent/m.toml " + shell_quote(nc));
    CHECK(missing.code == 2);
    CHECK(missing.err.find("/nonexistent/m.toml: error: cannot open file") != std::string::npos);
}

TEST_CASE("kerf run --machine: the machine's rates change the cycle time") {
    const fs::path nc = write_temp("rates.nc", "O1\nG0 X100. Z100.\nG0 X0. Z0.\nM30\n");
    const fs::path slow = write_temp("slow.toml",
                                     "id = \"slow\"\nbase = \"fanuc-lathe\"\n[axes.X]\nrapid = 100.0\n[axes.Z]\nrapid = 100.0\n");
    const Run fast_run = run("run --json --dialect fanuc-lathe-a " + shell_quote(nc));
    const Run slow_run = run("run --json --dialect fanuc-lathe-a --machine " + shell_quote(slow) + " " + shell_quote(nc));
    REQUIRE(fast_run.code == 0);
    REQUIRE(slow_run.code == 0);
    const auto seconds = [](const std::string& json) {
        const std::size_t at = json.find("\"total_time_s\":");
        REQUIRE(at != std::string::npos);
        return std::strtod(json.c_str() + at + 15, nullptr);
    };
    // Two rapids of 100 mm in Z (and 50 mm of radius in X) at 100 mm/min: at least 2 × 60 s.
    CHECK(seconds(slow_run.out) >= 120.0 - 1e-6);
    CHECK(seconds(fast_run.out) < 60.0);
}

TEST_CASE("kerf plot: .kerf.toml names the machine file, relative to itself; --machine wins") {
    const fs::path project = kDir / "project";
    write_text(project / "machines" / "radius.toml", "id = \"radius\"\nbase = \"fanuc-lathe\"\ndiameter_x = false\n");
    write_text(project / ".kerf.toml", "dialect = \"fanuc-lathe-a\"\nmachine = \"machines/radius.toml\"\n");
    const fs::path nc = write_text(project / "parts" / "part.nc", "O1\nG0 X30. Z2.\nG1 Z-10. F.2\nM30\n");
    const Run r = run("plot " + shell_quote(nc));
    CHECK(r.code == 0);
    CHECK(r.out.find("fanuc-lathe-a") != std::string::npos);
    CHECK(r.out.find("X drawn at the radius") == std::string::npos);
    const fs::path diameter = write_text(project / "diameter.toml", "id = \"d\"\nbase = \"fanuc-lathe\"\ndiameter_x = true\n");
    const Run flag = run("plot --machine " + shell_quote(diameter) + " " + shell_quote(nc));
    CHECK(flag.code == 0);
    CHECK(flag.out.find("X drawn at the radius") != std::string::npos);
}
