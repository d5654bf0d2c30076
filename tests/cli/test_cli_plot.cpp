// `kerf plot` (and `kerf run --machine`): output to a file or stdout, exit codes as `kerf run`,
// alarms on stderr with the picture still written, machine files from --machine and .kerf.toml.
#include "tests/cli/cli_runner.hpp"
#include "tests/plot/svg_reader.hpp"

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

// A lathe program that starts and ends at home (fanuc-lathe-a's machine: home is machine X0 Z0, G54
// at machine X-300 Z-550, so home is X300 Z550 in work coordinates, drawn at the radius: Z550 X150).
// Cutting: G1 Z-30 at X40 (radius 20) from Z2, then X50 (radius 25) at Z-30.
//
// --frame part (the default), derived by hand: the cuts span Z-30..2 and radius 20..25; a lathe
// picture holds the part axis, so radius 0..25; the extent max(32, 25) = 32 gives a margin of
// 10 % = 3.2 on every side: Z-33.2..5.2, radius -3.2..28.2. The scale is min(900 / 38.4, 640 / 31.4)
// = 20.382 px/mm (the height decides: the plot is 640 px high and 38.4 x 20.382 = 782.675 px wide,
// over the minimum 420 x 220), so the picture is 76 + 782.675 + 28 -> 887 px wide (the legend,
// 91 + 217 + 84 = 392 px, and the subtitle are narrower: "lathe, Z-X view, X drawn at the radius |
// feed 37.0 mm | rapid 1156.9 mm | framed on the cuts (--frame all)", 106 characters x 7 + 32 =
// 774 px, with the rapids 563.2 + 83.8 + 509.9 mm: home to Z2 X40, Z-30 X50 to Z50 X100, back home)
// and 70 + 640 + 40 + 2 x 30 + 6 = 816 px high.
// The rapid G0 X100 Z50 from Z-30 X50 (radius 25) to Z50 radius 50 leaves the frame at its top edge
// (radius 28.2) at t = 3.2 / 25 = 0.128 along it: Z = -30 + 0.128 x 80 = -19.76, i.e. at
// x = 76 + (-19.76 + 33.2) x 20.382 = 349.936 px, y = 70 px (the top of the plot).
//
// --frame all: everything from home (Z550, radius 150) to the part (Z-30, radius 20), with the axis
// radius 0..150: the extent 580 gives 5 % = 29: Z-59..579, radius -29..179.
TEST_CASE("kerf plot frames a lathe part, not its home returns; --frame all frames everything") {
    const fs::path nc = write_temp("home.nc", "O1000\nG28 U0. W0.\nT0101\nG0 X40. Z2.\nG1 Z-30. F.2 S1000 M3\nX50.\n"
                                              "G0 X100. Z50.\nG28 U0. W0.\nM30\n");
    const Run part = run("plot --dialect fanuc-lathe-a " + shell_quote(nc));
    REQUIRE(part.code == 0);
    const auto frame = kerf::test::elements_with(part.out, "class=\"frame\"");
    REQUIRE(frame.size() == 1);
    CHECK(kerf::test::attribute(frame[0], "data-view") == "-33.2 -3.2 5.2 28.2");
    CHECK(kerf::test::attribute(frame[0], "width") == "782.675");
    CHECK(kerf::test::attribute(frame[0], "height") == "640");
    const auto root = kerf::test::elements_with(part.out, "<svg ");
    REQUIRE(root.size() == 1);
    CHECK(kerf::test::attribute(root[0], "viewBox") == "0 0 887 816");
    // The paths are clipped to the plot area; the rapid that leaves it has an arrow saying where it goes.
    CHECK(part.out.find("<clipPath id=\"plot-area\">") != std::string::npos);
    CHECK(part.out.find("<g clip-path=\"url(#plot-area)\">") != std::string::npos);
    const auto arrows = kerf::test::elements_with(part.out, "<path class=\"leaves\"");
    REQUIRE(arrows.size() == 2);   // the rapid's and the legend's
    CHECK(kerf::test::attribute(arrows[0], "d").rfind("M349.936 70 L", 0) == 0);
    CHECK(part.out.find("<title>rapid to Z50 X100</title>") != std::string::npos);
    CHECK(part.out.find("feed 37.0 mm | rapid 1156.9 mm | framed on the cuts (--frame all)") != std::string::npos);
    // Home is outside: no start or end marker, and the legend does not list them.
    CHECK(part.out.find("class=\"start\"") == std::string::npos);
    CHECK(part.out.find("class=\"end\"") == std::string::npos);
    CHECK(part.out.find(">rapid leaving the frame<") != std::string::npos);

    const Run all = run("plot --frame all --dialect fanuc-lathe-a " + shell_quote(nc));
    REQUIRE(all.code == 0);
    const auto all_frame = kerf::test::elements_with(all.out, "class=\"frame\"");
    REQUIRE(all_frame.size() == 1);
    CHECK(kerf::test::attribute(all_frame[0], "data-view") == "-59 -29 579 179");
    CHECK(all.out.find("clip-path") == std::string::npos);
    CHECK(all.out.find("class=\"leaves\"") == std::string::npos);
    CHECK(all.out.find(">start<") != std::string::npos);
    CHECK(all.out.find(">end<") != std::string::npos);

    const Run bad = run("plot --frame some --dialect fanuc-lathe-a " + shell_quote(nc));
    CHECK(bad.code == 2);
}

// The legend lists the kinds of move the picture has (issue: it always listed "thread").
TEST_CASE("kerf plot: the legend lists thread only for a program that threads") {
    const fs::path plain = write_temp("plain.nc", kLathe);
    const Run p = run("plot --dialect fanuc-lathe-a " + shell_quote(plain));
    REQUIRE(p.code == 0);
    const std::size_t legend = p.out.find("<g class=\"legend\">");
    REQUIRE(legend != std::string::npos);
    CHECK(p.out.find(">thread<", legend) == std::string::npos);
    CHECK(p.out.find(">feed (lines, arcs)<", legend) != std::string::npos);   // the G02
    CHECK(p.out.find(">rapid<", legend) != std::string::npos);

    // G32 (system A) from Z2 to Z-20 at X19 with a 1.5 mm lead; then a G76 of the reference form.
    for (const std::string& thread : {std::string("O2\nG0 X19. Z2. S500 M3\nG32 Z-20. F1.5\nG0 X30.\nZ5.\nM30\n"),
                                      std::string("O3\nG0 X25. Z5. S500 M3\nG76 P010060 Q50 R0.03\n"
                                                  "G76 X18.16 Z-20. P920 Q300 F1.5\nG0 X50. Z50.\nM30\n")}) {
        INFO(thread);
        const fs::path nc = write_temp("thread.nc", thread);
        const Run t = run("plot --dialect fanuc-lathe-a " + shell_quote(nc));
        REQUIRE(t.code == 0);
        const std::size_t at = t.out.find("<g class=\"legend\">");
        REQUIRE(at != std::string::npos);
        CHECK(t.out.find(">thread<", at) != std::string::npos);
        CHECK(t.out.find("<path class=\"thread\"") != std::string::npos);
    }
}
