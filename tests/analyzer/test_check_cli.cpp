// kerf check end to end: the corpus defects its MANIFEST names, reported at the right place;
// JSON fields; --fix (atomic, re-checked); suppressions; baseline; SARIF shape; --list-rules.
#include <catch2/catch.hpp>

#include <boost/json.hpp>
#include <filesystem>
#include <set>
#include <tuple>

#include "tests/cli/cli_runner.hpp"

namespace fs = std::filesystem;
namespace json = boost::json;
using namespace kerf::test;

namespace {

const fs::path kWork = fs::temp_directory_path() / "kerf-test-check";

using Key = std::tuple<std::string, std::int64_t, std::int64_t, std::string>;   // file, line, column, rule

std::set<Key> findings_of(const std::string& out) {
    std::set<Key> keys;
    const json::value v = json::parse(out);
    for (const json::value& f : v.at("findings").as_array()) {
        const json::object& o = f.as_object();
        keys.insert({fs::path(std::string(o.at("file").as_string())).filename().string(), o.at("line").as_int64(),
                     o.at("column").as_int64(), std::string(o.at("rule").as_string())});
    }
    return keys;
}

}  // namespace

// The defects ../shared/corpus/MANIFEST.md names, with the line and column found with grep in the
// files (not taken from kerf's output).
TEST_CASE("kerf check reports the corpus defects of the MANIFEST at their line and column") {
    const fs::path corpus = fs::path(KERF_SHARED_DIR) / "corpus";
    if (!fs::is_directory(corpus)) {
        WARN("../shared is not there: corpus test skipped");
        return;
    }
    const CliRun r = run_kerf("check --format json " + shell_quote(corpus), kWork / "corpus");
    CHECK(r.code == 1);
    const std::set<Key> got = findings_of(r.out);
    const std::vector<Key> expected = {
        {"MechatronicsCherepanovMA__CNCLearn__1004.NC", 27, 7, "K1002"},
        {"MechatronicsCherepanovMA__CNCLearn__1004.NC", 50, 7, "K1002"},
        {"MechatronicsCherepanovMA__CNCLearn__1004.NC", 52, 6, "K1001"},    // X-11.Z
        {"MechatronicsCherepanovMA__CNCLearn__1002.NC", 60, 4, "K1002"},    // Z-0.5.
        {"MechatronicsCherepanovMA__CNCLearn__1003.NC", 55, 1, "K1003"},    // GO Y0.
        {"MechatronicsCherepanovMA__CNCLearn__1003.NC", 60, 12, "K1022"},   // M08.
        {"MechatronicsCherepanovMA__CNCLearn__O0001.txt", 1, 1, "K1023"},   // BOM
        {"MechatronicsCherepanovMA__CNCLearn__O0001.txt", 5, 5, "K1007"},   // N10 21 G40
        {"MechatronicsCherepanovMA__CNCLearn__O0001.txt", 8, 5, "K1003"},   // MO6
        {"MechatronicsCherepanovMA__CNCLearn__O0001.txt", 9, 9, "K1003"},   // HO1
        {"MechatronicsCherepanovMA__CNCLearn__O0001.txt", 11, 9, "K1020"},  // X10 Y10 (integer coordinates)
        {"MechatronicsCherepanovMA__CNCLearn__O0005.nc", 1, 1, "K1023"},    // BOM
        {"johnhinfinity__Steady-rest-macro-Program__Steady_rest_maker.nc", 19, 20, "K1021"},   // F0.010 F.010
        {"mikemacfarland__Doosan-DNM-5700__O1000", 20, 10, "K1004"},        // X?
        {"mikemacfarland__Doosan-DNM-5700__O1000", 20, 12, "K1004"},        // Y?
    };
    for (const Key& k : expected) {
        INFO(std::get<0>(k) << ":" << std::get<1>(k) << ":" << std::get<2>(k) << " " << std::get<3>(k));
        CHECK(got.count(k) == 1);
    }
}

TEST_CASE("kerf check: JSON fields, suppressions, exit codes") {
    const fs::path dir = kWork / "json";
    write_text(dir / "a.nc", "O0001\nT0101\nG01 X10. Z-1. F0.2 F0.2\nG00 X20. (kerf: ignore K1021)\nMO6\nM30\n");
    const CliRun r = run_kerf("check --format json --dialect fanuc-lathe-a " + shell_quote(dir / "a.nc"), dir);
    CHECK(r.code == 1);   // MO6 is an error
    const json::value v = json::parse(r.out);
    const json::object& f = v.at("findings").as_array().at(0).as_object();
    for (const char* key : {"file", "line", "column", "end_line", "end_column", "severity", "rule", "name", "message"})
        CHECK(f.contains(key));
    const std::set<Key> got = findings_of(r.out);
    CHECK(got.count({"a.nc", 3, 20, "K1021"}) == 1);
    CHECK(got.count({"a.nc", 5, 1, "K1003"}) == 1);

    write_text(dir / "b.nc", "O0001\nT0101\nG97 S800 M03\nG01 X10. Z-1. F0.2 F0.2 (kerf: ignore K1021)\nM30\n");
    CHECK(findings_of(run_kerf("check --format json --dialect fanuc-lathe-a " + shell_quote(dir / "b.nc"), dir).out).empty());
    write_text(dir / "c.nc", "(kerf: ignore duplicate-address)\nO0001\nT0101\nG01 X10. Z-1. F0.2 F0.2\nM30\n");
    const CliRun c = run_kerf("check --dialect fanuc-lathe-a " + shell_quote(dir / "c.nc"), dir);
    CHECK(c.code == 0);
    CHECK(c.out.find("K1021") == std::string::npos);
}

TEST_CASE("kerf check --fix rewrites the file atomically, keeps its mode and re-checks") {
    const fs::path dir = kWork / "fix";
    const fs::path file = write_text(dir / "f.nc", "O0001\nT0101\nMO6\nG01 X10. Z-1,5 F0.2 (CUT\nM30\n");
    fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    const CliRun r = run_kerf("check --fix --dialect fanuc-mill " + shell_quote(file), dir);
    CHECK(read_text(file) == "O0001\nT0101\nM06\nG01 X10. Z-1.5 F0.2 (CUT)\nM30\n");
    CHECK((fs::status(file).permissions() & fs::perms::all) ==
          (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
    CHECK(!fs::exists(dir / "f.nc.kerf-tmp"));
    CHECK(r.out.find("3 fix(es) applied") != std::string::npos);
    CHECK(r.code == 0);
}

TEST_CASE("kerf check --write-baseline then --baseline accepts the old findings, not new ones") {
    const fs::path dir = kWork / "baseline";
    const fs::path file = write_text(dir / "p.nc", "O0001\nT0101\nG01 X10. Z-1. F0.2 F0.2\nM30\n");
    const fs::path base = dir / "baseline.json";
    run_kerf("check --dialect fanuc-lathe-a --write-baseline " + shell_quote(base) + " " + shell_quote(file), dir);
    CHECK(read_text(base).find("\"rule\":\"K1021\"") != std::string::npos);
    // A block inserted above moves the finding down one line: still accepted (matched by block text).
    write_text(file, "O0001\nT0101\nG00 X20.\nG01 X10. Z-1. F0.2 F0.2\nMO6\nM30\n");
    const CliRun r = run_kerf("check --format json --dialect fanuc-lathe-a --baseline " + shell_quote(base) + " " + shell_quote(file), dir);
    const std::set<Key> got = findings_of(r.out);
    CHECK(got.count({"p.nc", 4, 20, "K1021"}) == 0);
    CHECK(got.count({"p.nc", 5, 1, "K1003"}) == 1);
}

TEST_CASE("kerf check --format sarif has the SARIF 2.1.0 shape code scanning needs") {
    const fs::path dir = kWork / "sarif";
    const fs::path file = write_text(dir / "s.nc", "O0001\nMO6\nM30\n");
    const json::value v = json::parse(run_kerf("check --format sarif --dialect fanuc-mill " + shell_quote(file), dir).out);
    CHECK(v.at("version").as_string() == "2.1.0");
    const json::object& run = v.at("runs").as_array().at(0).as_object();
    CHECK(run.at("tool").at("driver").at("name").as_string() == "kerf");
    const json::array& rules = run.at("tool").at("driver").at("rules").as_array();
    CHECK(rules.size() >= 50);
    const json::object& result = run.at("results").as_array().at(0).as_object();
    CHECK(result.at("ruleId").as_string() == "K1003");
    CHECK(result.at("level").as_string() == "error");
    const json::object& region = result.at("locations").as_array().at(0).at("physicalLocation").at("region").as_object();
    CHECK(region.at("startLine").as_int64() == 2);
    CHECK(region.at("startColumn").as_int64() == 1);
    CHECK(rules.at(static_cast<std::size_t>(result.at("ruleIndex").as_int64())).at("id").as_string() == "K1003");
}

TEST_CASE("docs/rules.md is what the registry generates, and --list-rules and explain show every rule") {
    const CliRun md = run_kerf("check --list-rules --format markdown", kWork / "docs");
    CHECK(md.out == read_text(fs::path(KERF_SOURCE_DIR) / "docs/rules.md"));
    const CliRun list = run_kerf("check --list-rules", kWork / "docs");
    CHECK(std::count(list.out.begin(), list.out.end(), '\n') >= 50);
    const CliRun explain = run_kerf("explain K1002", kWork / "docs");
    CHECK(explain.code == 0);
    CHECK(explain.out.find("malformed-number") != std::string::npos);
    CHECK(explain.out.find("X-12.8.") != std::string::npos);
}
