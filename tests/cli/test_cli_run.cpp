// `kerf run`: the summary (text and --json), the streamed trace (--trace, --state) and exit codes.
#include "tests/cli/cli_runner.hpp"

#include <boost/json.hpp>
#include <sstream>

namespace fs = std::filesystem;
namespace json = boost::json;
using kerf::test::run_kerf;
using kerf::test::shell_quote;

namespace {

const fs::path kDir = fs::temp_directory_path() / "kerf-cli-run";

// fanuc-lathe-a, decimal points throughout: from the reference point (machine X300 Z550, work
// zero at machine Z100 after G10 P0 Z-100) rapid to X40 Z2, feed to Z-20, G02 R5 to X50 Z-25
// (centre X50 Z-20: radius 5, start X40 is 5 below on the radius), dwell, back.
const std::string kProgram = "O1\nG10 P0 Z-100.\nG0 X40. Z2.\nG1 Z-20. F.2 S1000 M3\nG2 X50. Z-25. R5.\n"
                             "G4 X1.5\nG0 X150. Z150.\nM30\n";

}  // namespace

TEST_CASE("kerf run --json: the summary keys the issue names") {
    const fs::path nc = kerf::test::write_text(kDir / "p.nc", kProgram);
    const auto r = run_kerf("run --dialect fanuc-lathe-a --json " + shell_quote(nc), kDir);
    CHECK(r.code == 0);
    const json::object s = json::parse(r.out).as_object();
    CHECK(s.at("final_position").at("X").to_number<double>() == Approx(150));
    CHECK(s.at("final_position").at("Z").to_number<double>() == Approx(150));
    // Feed distance: the Z move 22 mm + the quarter arc pi/2 * 5 = 7.854 mm.
    CHECK(s.at("feed_distance_mm").as_double() == Approx(22 + M_PI / 2 * 5).epsilon(1e-9));
    CHECK(s.at("total_time_s").to_number<double>() > 1.5);   // the 1.5 s dwell alone
    CHECK(s.at("tools").as_array().empty());
    CHECK(s.at("alarms").as_array().empty());
    CHECK(s.at("completed").as_bool());
}

TEST_CASE("kerf run --trace - writes the trace on standard output and the summary on standard error") {
    const fs::path nc = kerf::test::write_text(kDir / "dash.nc", kProgram);
    const fs::path dash = fs::current_path() / "-";
    fs::remove(dash);
    const auto r = run_kerf("run --dialect fanuc-lathe-a --trace - " + shell_quote(nc), kDir);
    CHECK(r.code == 0);
    CHECK_FALSE(fs::exists(dash));   // it wrote a file named '-' (issue 13, hygiene)
    std::istringstream lines(r.out);
    std::string line;
    int events = 0;
    while (std::getline(lines, line)) {
        CHECK(json::parse(line).as_object().contains("kind"));   // stdout is JSON lines only
        ++events;
    }
    CHECK(events > 5);
    CHECK(r.err.find("ended normally") != std::string::npos);
}

TEST_CASE("kerf run --trace writes one JSON object per event; --state adds the modal state") {
    const fs::path nc = kerf::test::write_text(kDir / "p.nc", kProgram);
    const fs::path trace = kDir / "p.jsonl";
    const auto r = run_kerf("run --dialect fanuc-lathe-a --state --trace " + shell_quote(trace) + " " + shell_quote(nc), kDir);
    CHECK(r.code == 0);
    std::istringstream lines(kerf::test::read_text(trace));
    std::string line;
    int states = 0, arcs = 0;
    while (std::getline(lines, line)) {
        const json::object e = json::parse(line).as_object();
        CHECK(e.contains("kind"));
        CHECK(e.contains("line"));
        CHECK(e.contains("file"));
        CHECK(e.contains("end"));
        const std::string kind(e.at("kind").as_string());
        if (kind == "state") {
            ++states;
            // Structured (issue 13): the modal codes in text, F and S and the tool in fields.
            CHECK(e.at("text").as_string().find("G") != json::string::npos);
            CHECK(e.at("text").as_string().find(" F") == json::string::npos);
            CHECK(e.contains("feed"));
            CHECK(e.contains("spindle_rpm"));
            CHECK(e.contains("tool"));
        }
        if (kind == "arc_cw") {
            ++arcs;
            CHECK(e.at("line").to_number<int>() == 5);
            CHECK(e.at("center").at("X").to_number<double>() == Approx(50));   // diameter, like end
            CHECK(e.at("center").at("Z").to_number<double>() == Approx(-20));
            CHECK(e.at("radius").to_number<double>() == Approx(5));
            CHECK(e.at("machine").at("Z").to_number<double>() == Approx(-475));   // -25 + 100 (G10 P0) - 550 (G54)
        }
    }
    CHECK(arcs == 1);
    CHECK(states == 7);   // one per executed block after the O line: lines 2..8
}

TEST_CASE("kerf run: an alarm is reported on stderr with the line and exit code 1") {
    const fs::path nc = kerf::test::write_text(kDir / "bad.nc", "O1\nG0 X0. Z0.\nM98 P4242\nM30\n");
    const auto r = run_kerf("run --dialect fanuc-lathe-a " + shell_quote(nc), kDir);
    CHECK(r.code == 1);
    CHECK(r.err.find("bad.nc:3: error: alarm 78") != std::string::npos);
}
