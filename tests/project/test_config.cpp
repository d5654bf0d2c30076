// The .kerf.toml model (project/config.hpp): every key read, relative paths anchored at the file,
// and strictness: an unknown key, a wrong type or a bad value is a problem at its line and column
// that names what is allowed (as the dialect and machine files do).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <fstream>
#include <string>

#include "project/config.hpp"
#include "project/workspace.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf::project;

namespace {

const fs::path kFile = "/shop/parts/.kerf.toml";

std::string problems_of(const ConfigResult& r) {
    std::string s;
    for (const Problem& p : r.problems) s += to_string(p) + "\n";
    return s;
}

}  // namespace

TEST_CASE("config: every key of a full .kerf.toml") {
    const ConfigResult r = parse_config(R"(dialect = "fanuc-mill"
dialect_files = ["dialects/shop.toml"]
machine = "../machines/vf2.toml"
[check]
include = ["**/*.nc"]
exclude = ["old/**"]
[check.rules]
K1020 = "off"
duplicate-address = "error"
[format]
letter_case = "lower"
[run]
call = "G65 P9010 A1."
set = ["#100=5", "#500 = -1.5"]
passes = 3
[programs]
library = ["../macros", "/opt/renishaw"]
resident = ["O9000-O9999", "o8000 - o8999", "O7001"]
)", kFile);
    INFO(problems_of(r));
    REQUIRE(r.problems.empty());
    const Config& c = r.config;
    CHECK(c.file == kFile);
    CHECK(c.folder() == "/shop/parts");
    CHECK(c.dialect == "fanuc-mill");
    CHECK(c.dialect_files == std::vector<fs::path>{"/shop/parts/dialects/shop.toml"});
    CHECK(c.machine == fs::path("/shop/machines/vf2.toml"));
    CHECK(c.check.include == std::vector<std::string>{"**/*.nc"});
    CHECK(c.check.exclude == std::vector<std::string>{"old/**"});
    CHECK(c.check.rules.at("K1020") == std::nullopt);
    CHECK(c.check.rules.at("duplicate-address") == kerf::analyzer::Severity::error);
    CHECK(c.format.letter_case == kerf::formatter::LetterCase::lower);
    CHECK(c.run.call == "G65 P9010 A1.");
    CHECK(c.run.set == std::vector<std::string>{"#100=5", "#500 = -1.5"});
    CHECK(c.run.passes == 3);
    CHECK(c.programs.library == std::vector<fs::path>{"/shop/macros", "/opt/renishaw"});
    REQUIRE(c.programs.resident.size() == 3);
    CHECK(c.programs.resident_contains(9000));
    CHECK(c.programs.resident_contains(9999));
    CHECK(c.programs.resident_contains(8500));
    CHECK(c.programs.resident_contains(7001));
    CHECK_FALSE(c.programs.resident_contains(7002));
    CHECK_FALSE(c.programs.resident_contains(10000));
}

TEST_CASE("config: an empty file and \"auto\" are the defaults") {
    const ConfigResult empty = parse_config("", kFile);
    CHECK(empty.problems.empty());
    CHECK(empty.config.dialect.empty());
    CHECK_FALSE(empty.config.machine);
    CHECK_FALSE(empty.config.run.passes);
    CHECK(parse_config("dialect = \"auto\"\n", kFile).config.dialect.empty());
}

TEST_CASE("config: an unknown key is an error at its position that lists the valid keys") {
    // Line 2 column 1 is the key 'dialekt'; the message names the top-level keys.
    const ConfigResult r = parse_config("dialect = \"fanuc-mill\"\ndialekt = \"x\"\n[run]\npasess = 2\n[programs]\nlibary = []\n", kFile);
    REQUIRE(r.problems.size() == 3);
    CHECK(to_string(r.problems[0]) ==
          "/shop/parts/.kerf.toml:2:1: error: dialekt: unknown key; the keys at the top level are dialect, dialect_files, "
          "machine, check, rules, format, run, programs, limits (docs/config.md)");
    CHECK(to_string(r.problems[1]) ==
          "/shop/parts/.kerf.toml:4:1: error: run.pasess: unknown key; the keys of [run] are call, set, passes (docs/config.md)");
    CHECK(to_string(r.problems[2]) ==
          "/shop/parts/.kerf.toml:6:1: error: programs.libary: unknown key; the keys of [programs] are library, resident (docs/config.md)");
    CHECK(r.config.dialect == "fanuc-mill");   // what could be read is kept
}

TEST_CASE("config: unknown keys and bad values in [check] and [format] too, in file order") {
    const ConfigResult r = parse_config("[format]\nletter_cse = \"lower\"\n[check]\nincludes = [\"*.nc\"]\n[check.rules]\nK9999 = \"off\"\nK1020 = \"loud\"\n", kFile);
    REQUIRE(r.problems.size() == 4);
    CHECK(r.problems[0].line == 2);
    CHECK(r.problems[0].message.starts_with("format.letter_cse: unknown key; the keys of [format] are letter_case, "));
    CHECK(to_string(r.problems[1]) ==
          "/shop/parts/.kerf.toml:4:1: error: check.includes: unknown key; the keys of [check] are include, exclude and rules");
    CHECK(r.problems[2].line == 6);
    CHECK(r.problems[2].message == "check.rules.K9999: unknown rule (`kerf check --list-rules` lists the ids and names)");
    CHECK(r.problems[3].line == 7);
    CHECK(r.problems[3].column == 9);   // the value
    CHECK(r.problems[3].message == "check.rules.K1020: expected \"error\", \"warning\", \"info\", \"hint\" or \"off\"");
}

TEST_CASE("config: wrong types are errors, not silent defaults") {
    const ConfigResult r = parse_config(
        "dialect = 5\ndialect_files = \"one.toml\"\nmachine = [\"m.toml\"]\n[run]\ncall = \"\"\nset = [\"100=5\"]\npasses = 0\n"
        "[programs]\nresident = [\"O9999-O9000\", 9000]\n",
        kFile);
    std::vector<std::string> got;
    for (const Problem& p : r.problems) got.push_back(std::to_string(p.line) + ":" + std::to_string(p.column) + " " + p.message);
    CHECK(got == std::vector<std::string>{
                     "1:11 dialect: expected a string",
                     "2:17 dialect_files: expected an array of strings",
                     "3:11 machine: expected a string",
                     "5:8 run.call: expected the caller's block, e.g. \"G65 P9010 A1.\"",
                     "6:7 run.set: '100=5' is not an assignment such as \"#100=5\"",
                     "7:10 run.passes: expected a whole number from 1 to 1000000",
                     "9:13 programs.resident: expected a range of program numbers, \"O9000-O9999\" or \"O9010\"",
                     "9:28 programs.resident: expected a range of program numbers, \"O9000-O9999\" or \"O9010\"",
                 });
}

TEST_CASE("config: a TOML syntax error is one problem with its position") {
    const ConfigResult r = parse_config("dialect = = \"x\"\n", kFile);
    REQUIRE(r.problems.size() == 1);
    CHECK(r.problems[0].line == 1);
    CHECK(r.problems[0].column > 0);
}

TEST_CASE("config: program ranges") {
    CHECK(parse_program_range("O9000-O9999")->first == 9000);
    CHECK(parse_program_range("O9000-O9999")->last == 9999);
    CHECK(parse_program_range("9010")->first == 9010);
    CHECK(parse_program_range("9010")->last == 9010);
    CHECK_FALSE(parse_program_range("O9999-O9000"));
    CHECK_FALSE(parse_program_range("P9000"));
    CHECK_FALSE(parse_program_range(""));
    CHECK_FALSE(parse_program_range("O-5"));
    CHECK_FALSE(parse_program_range("O123456789"));
}

TEST_CASE("config: [limits] sets the bounds, the command line wins, bad values are errors") {
    const ConfigResult r = parse_config("[limits]\nmax_file_bytes = 1000\nmax_line_bytes = 0\ntime_limit = 2.5\n", kFile);
    CHECK(r.problems.empty());
    CHECK(r.config.limits.max_file_bytes == 1000u);
    CHECK(r.config.limits.max_line_bytes == 0u);
    REQUIRE(r.config.limits.time_limit_s);
    CHECK(*r.config.limits.time_limit_s == 2.5);
    // The file over the defaults; 0 = no limit stays 0.
    const kerf::project::Limits from_file = kerf::project::resolve_limits({}, r.config.limits);
    CHECK(from_file.input.max_file_bytes == 1000u);
    CHECK(from_file.input.max_line_bytes == 0u);
    CHECK(from_file.time_limit == std::chrono::milliseconds(2500));
    // A flag over the file; what neither sets keeps its default (64 KiB, 10 s).
    kerf::project::LimitSettings flags;
    flags.max_file_bytes = 5;
    const kerf::project::Limits both = kerf::project::resolve_limits(flags, {});
    CHECK(both.input.max_file_bytes == 5u);
    CHECK(both.input.max_line_bytes == 65536u);
    CHECK(both.time_limit == std::chrono::milliseconds(10000));

    const ConfigResult bad = parse_config("[limits]\nmax_file_bytes = -1\ntime_limit = \"10s\"\nmax_lines = 5\n", kFile);
    REQUIRE(bad.problems.size() == 3);
    CHECK(to_string(bad.problems[0]) ==
          "/shop/parts/.kerf.toml:2:18: error: limits.max_file_bytes: expected a number of bytes, 0 for no limit");
    CHECK(to_string(bad.problems[1]) ==
          "/shop/parts/.kerf.toml:3:14: error: limits.time_limit: expected seconds from 0 (no limit) to 1000000");
    CHECK(to_string(bad.problems[2]) ==
          "/shop/parts/.kerf.toml:4:1: error: limits.max_lines: unknown key; the keys of [limits] are max_file_bytes, "
          "max_line_bytes, time_limit (docs/config.md)");
}

TEST_CASE("config: docs/config.md documents every key") {
    const std::string doc = kerf::test::read_text(fs::path(KERF_SOURCE_DIR) / "docs/config.md");
    REQUIRE_FALSE(doc.empty());
    for (const KeyInfo& k : config_keys()) {
        INFO(k.table << "." << k.key);
        std::string quoted = "`";   // appended piecewise: GCC 12 warns falsely on "`" + string + "`"
        quoted += k.key;
        quoted += '`';
        CHECK(doc.find(quoted) != std::string::npos);
    }
    for (const kerf::formatter::OptionInfo& o : kerf::formatter::options()) {
        INFO("format." << o.key);
        CHECK(doc.find(std::string(o.key)) != std::string::npos);
    }
}

TEST_CASE("project: without dialect files it reads the built-in dialects themselves; with one, its own registry") {
    const DiskFileSystem disk;
    const Project plain(Config{}, {}, Overrides{}, disk);
    CHECK(&plain.dialects() == &kerf::dialects::builtin_registry());
    CHECK(plain.dialects().find("fanuc-mill") != nullptr);

    const fs::path file = fs::temp_directory_path() / ("kerf-test-project-dialect-" + std::to_string(::getpid()) + ".toml");
    {
        std::ofstream out(file);
        out << "id = \"shop-mill\"\nbase = \"fanuc-mill\"\nname = \"Shop mill\"\n";
    }
    Overrides overrides;
    overrides.dialect_files = {file};
    const Project shop(Config{}, {}, overrides, disk);
    fs::remove(file);
    CHECK(&shop.dialects() != &kerf::dialects::builtin_registry());
    CHECK(shop.problems().empty());
    CHECK(shop.dialects().find("shop-mill") != nullptr);
    CHECK(shop.dialects().find("fanuc-mill") != nullptr);
    CHECK(kerf::dialects::builtin_registry().find("shop-mill") == nullptr);
}
