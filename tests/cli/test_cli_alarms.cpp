// A dialect's own alarm numbers ([alarms], dialects/SCHEMA.md) through the command line: kerf run,
// its --json summary and --trace, and kerf check show the control's number and text for a missing
// subprogram, an arc whose R is too small and a #3000 alarm, while kerf's number stays the alarm's
// identity (the trace's `code`, the rule of kerf check); a FANUC dialect keeps FANUC's numbers.
//
// The dialect is a user file derived from haas-mill with a table of a made-up control ("Test NGC",
// numbers 7xxx): the built-in Haas dialects map only what Haas's public documents say (docs/haas.md).
#include "tests/cli/cli_runner.hpp"

#include <unistd.h>

#include <boost/json.hpp>
#include <sstream>

namespace fs = std::filesystem;
namespace json = boost::json;
using kerf::test::CliRun;
using kerf::test::run_kerf;
using kerf::test::shell_quote;
using kerf::test::write_text;

namespace {

const fs::path kDir = fs::temp_directory_path() / ("kerf-cli-alarms-" + std::to_string(::getpid()));

const std::string kDialect =
    "id = \"test-ngc\"\n"
    "name = \"Test NGC (haas-mill with a test alarm table)\"\n"
    "base = \"haas-mill\"\n"
    "[alarms]\n"
    "control = \"Test NGC\"\n"
    "program_not_found = { number = 7078, text = \"TEST PROGRAM NOT FOUND\", reference = \"test data\" }\n"
    "arc_radius_mismatch = { number = 7020, text = \"TEST ARC RADIUS\", reference = \"test data\" }\n"
    "user_alarm_first = { number = 7000, reference = \"test data\" }\n";

// The three programs: a call to O1234, which is nowhere; a G02 from X0 to X10 with R2 (the chord
// of 10 is longer than the diameter 4: FANUC alarm 020); #3000 = 5, kerf's 3005.
struct Case {
    const char* file;
    const char* text;
    int line;              // of the alarm
    int kerf;              // kerf's number (the trace's code)
    int control;           // the test control's
    const char* rule;      // kerf check's rule for it
    const char* message;   // the start of the alarm's text under the test control
};
const Case kCases[] = {
    {"call.nc", "O0001\nG90 G00 X0. Y0.\nM98 P1234\nM30\n", 3, 78, 7078, "K3003",
     "Test NGC alarm 7078 TEST PROGRAM NOT FOUND: program O1234 not found (FANUC alarm 078)"},
    {"arc.nc", "O0002\nG90 G17 G00 X0. Y0.\nG02 X10. Y0. R2. F100.\nM30\n", 3, 20, 7020, "K5014",
     "Test NGC alarm 7020 TEST ARC RADIUS: "},
    {"user.nc", "O0003\nG90 G00 X0. Y0.\n#3000=5(NO TOOL)\nM30\n", 3, 3005, 7005, "K4006", "Test NGC alarm 7005: NO TOOL"},
};

CliRun run_cli(const std::string& args) { return run_kerf(args, kDir.string() + "-run"); }

// The folder: the dialect file and a .kerf.toml that reads every program in it.
void write_project() {
    write_text(kDir / "test-ngc.toml", kDialect);
    write_text(kDir / ".kerf.toml", "dialect = \"test-ngc\"\ndialect_files = [\"test-ngc.toml\"]\n");
    for (const Case& c : kCases) write_text(kDir / c.file, c.text);
}

json::object alarm_event(const fs::path& trace) {
    std::istringstream lines(kerf::test::read_text(trace));
    std::string line;
    while (std::getline(lines, line)) {
        json::object e = json::parse(line).as_object();
        if (e.at("kind").as_string() == "alarm") return e;
    }
    FAIL("no alarm event in " << trace);
    return {};
}

}  // namespace

TEST_CASE("kerf run shows the control's alarm number and text; the trace keeps kerf's number as the code") {
    write_project();
    for (const Case& c : kCases) {
        INFO(c.file);
        const fs::path nc = kDir / c.file;
        const CliRun run = run_cli("run " + shell_quote(nc));
        CHECK(run.code == 1);
        const std::string expected = nc.string() + ":" + std::to_string(c.line) + ": error: alarm " +
                                     std::to_string(c.control) + ": " + c.message;
        INFO(run.err);
        CHECK(run.err.find(expected) != std::string::npos);

        const json::object summary = json::parse(run_cli("run --json " + shell_quote(nc)).out).as_object();
        const json::object& alarm = summary.at("alarms").as_array().at(0).as_object();
        CHECK(alarm.at("code").as_int64() == c.kerf);
        CHECK(alarm.at("control_alarm").as_int64() == c.control);

        const fs::path trace = kDir.string() + "-run/" + c.file + ".jsonl";
        run_cli("run --trace " + shell_quote(trace) + " " + shell_quote(nc));
        const json::object e = alarm_event(trace);
        CHECK(e.at("code").as_int64() == c.kerf);
        CHECK(e.at("control_alarm").as_int64() == c.control);
        CHECK(std::string(e.at("text").as_string()).rfind(c.message, 0) == 0);
    }
    fs::remove_all(kDir);
    fs::remove_all(kDir.string() + "-run");
}

TEST_CASE("kerf check names the control's alarm under kerf's rule for it") {
    write_project();
    for (const Case& c : kCases) {
        INFO(c.file);
        const CliRun check = run_cli("check --format json " + shell_quote(kDir / c.file));
        INFO(check.out);
        bool found = false;
        const json::value report = json::parse(check.out);
        for (const json::value& f : report.at("findings").as_array()) {
            if (f.at("rule").as_string() != c.rule) continue;
            found = true;
            const std::string message(f.at("message").as_string());
            // K3003 is the static rule that finds the missing program before the run (it hides the run's
            // K4009 on the same line); it names the alarm the control will raise.
            if (std::string(c.rule) == "K3003")
                CHECK(message == "program O1234 is not in this file, the files of its folder or the library folders "
                                 "(Test NGC alarm 7078 TEST PROGRAM NOT FOUND)");
            else
                CHECK(message.rfind(c.message, 0) == 0);
        }
        CHECK(found);
    }
    fs::remove_all(kDir);
    fs::remove_all(kDir.string() + "-run");
}

TEST_CASE("the same programs under fanuc-mill keep FANUC's numbers and texts") {
    write_project();
    const CliRun call = run_cli("run --dialect fanuc-mill " + shell_quote(kDir / "call.nc"));
    CHECK(call.err.find(":3: error: alarm 78: program O1234 not found (alarm 078)") != std::string::npos);
    const json::object summary = json::parse(run_cli("run --json --dialect fanuc-mill " + shell_quote(kDir / "user.nc")).out).as_object();
    const json::object& alarm = summary.at("alarms").as_array().at(0).as_object();
    CHECK(alarm.at("code").as_int64() == 3005);
    CHECK_FALSE(alarm.contains("control_alarm"));
    CHECK(alarm.at("text").as_string() == "NO TOOL");
    const CliRun check = run_cli("check --dialect fanuc-mill " + shell_quote(kDir / "call.nc"));
    CHECK(check.out.find("(alarm 078)") != std::string::npos);
    fs::remove_all(kDir);
    fs::remove_all(kDir.string() + "-run");
}

// A code the dialect does not have stops a strict run with alarm 010 (Cherepanov's lathe programs
// begin with a mill's G49): the message says how to go past it, a lenient run does not stop, and an
// alarm no dialect or --lenient changes (078) gets no such hint.
TEST_CASE("kerf run and kerf plot say how to go past an unknown code's alarm 010") {
    write_text(kDir / "g49.nc", "O0001\nG21 G40 G49 G54\nG00 X10. Z5.\nM30\n");
    const std::string hint = "= hint: if the program is for another control, name its dialect (--dialect";
    const CliRun run = run_cli("run --dialect fanuc-lathe-a " + shell_quote(kDir / "g49.nc"));
    CHECK(run.code == 1);
    CHECK(run.err.find(":2: error: alarm 10: G49 is not a code of fanuc-lathe-a (alarm 010)") != std::string::npos);
    CHECK(run.err.find(hint) != std::string::npos);
    CHECK(run.err.find("or run past the block with --lenient") != std::string::npos);
    const CliRun plot = run_cli("plot --dialect fanuc-lathe-a -o " + shell_quote(kDir / "g49.svg") + " " + shell_quote(kDir / "g49.nc"));
    CHECK(plot.err.find(hint) != std::string::npos);
    const CliRun lenient = run_cli("run --lenient --dialect fanuc-lathe-a " + shell_quote(kDir / "g49.nc"));
    CHECK(lenient.code == 0);
    CHECK(lenient.err.find(hint) == std::string::npos);
    write_text(kDir / "call.nc", "O0001\nG90 G00 X0. Y0.\nM98 P1234\nM30\n");
    const CliRun call = run_cli("run --dialect fanuc-mill " + shell_quote(kDir / "call.nc"));
    CHECK(call.err.find("alarm 78") != std::string::npos);
    CHECK(call.err.find("hint") == std::string::npos);
    fs::remove_all(kDir);
    fs::remove_all(kDir.string() + "-run");
}
