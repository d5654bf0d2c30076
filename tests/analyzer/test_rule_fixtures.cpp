// Every rule of the registry has a fixture tests/golden/check/<ID>-<name>/ with bad.nc (fires),
// good.nc (does not) and expected.txt (the findings of that rule in bad.nc, checked by hand: see
// REVIEW.md there). Every fix is applied, the result re-parsed, and the rule must no longer fire.
#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>

#include "analyzer/fix.hpp"
#include "tests/analyzer/check_fixture.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf;

namespace {

const fs::path kFixtures = fs::path(KERF_SOURCE_DIR) / "tests/golden/check";

struct Expected {
    std::string dialect = "fanuc-lathe-a";
    std::vector<std::string> findings;
    test::SoftLimit limit;
    std::int64_t program = 0;                  // "# program-files N FILE...": what the program index
    std::vector<std::string> program_files;    // answers for O N (the files of a folder the test has not)
    bool foreign = false;                      // "# foreign": detection's foreign control goes to the check
};

// "# dialect ID" sets the dialect; other lines are "line:col severity ID".
Expected read_expected(const fs::path& file) {
    Expected e;
    std::istringstream in(test::read_text(file));
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with("# dialect ")) e.dialect = line.substr(10);
        else if (line.starts_with("# soft-limit ")) {
            std::istringstream words(line.substr(13));
            words >> e.limit.axis >> e.limit.min >> e.limit.max;
        } else if (line == "# foreign") {
            e.foreign = true;
        } else if (line.starts_with("# machine-file")) {
            // "# machine-file [M25 M165 ...]": checked as with a machine file listing these M codes.
            e.limit.machine_given = true;
            std::istringstream words(line.substr(14));
            for (std::string code; words >> code;) e.limit.m_codes.push_back(std::stoi(code.substr(1)));
        } else if (line.starts_with("# program-files ")) {
            std::istringstream words(line.substr(16));
            words >> e.program;
            for (std::string name; words >> name;) e.program_files.push_back(name);
        }
        else if (!line.empty() && line[0] != '#') e.findings.push_back(line);
    }
    return e;
}

fs::path fixture_of(const analyzer::Rule& r) { return kFixtures / (r.id + "-" + r.name); }

}  // namespace

TEST_CASE("every rule has a fixture with bad.nc, good.nc and expected.txt") {
    for (const analyzer::Rule& r : analyzer::builtin_rules().rules()) {
        INFO(r.id << " " << r.name);
        for (const char* f : {"bad.nc", "good.nc", "expected.txt"}) CHECK(fs::is_regular_file(fixture_of(r) / f));
    }
    CHECK(fs::is_regular_file(kFixtures / "REVIEW.md"));
}

TEST_CASE("each rule fires on its bad program as expected and not on its good one") {
    for (const analyzer::Rule& r : analyzer::builtin_rules().rules()) {
        const fs::path dir = fixture_of(r);
        if (!fs::is_regular_file(dir / "expected.txt")) continue;   // the test above fails for it
        INFO(r.id << " " << r.name);
        const Expected expected = read_expected(dir / "expected.txt");
        REQUIRE(!expected.findings.empty());
        auto options = test::all_rules_on();
        if (!expected.program_files.empty())
            options.program_files = [&](std::int64_t n) { return n == expected.program ? expected.program_files : std::vector<std::string>{}; };
        // "# foreign": detection runs on the text, as the project layer does (project/check.cpp).
        const auto with_detection = [&](const std::string& text) {
            analyzer::CheckOptions o = options;
            if (expected.foreign) o.foreign = test::foreign_control(text);
            return o;
        };
        const std::string bad = test::read_text(dir / "bad.nc"), good = test::read_text(dir / "good.nc");
        CHECK(test::summary(test::check(bad, expected.dialect, with_detection(bad), expected.limit), r.id) == expected.findings);
        CHECK(test::summary(test::check(good, expected.dialect, with_detection(good), expected.limit), r.id).empty());
    }
}

TEST_CASE("each fix applies, re-parses and the rule no longer fires") {
    std::size_t fixes = 0;
    for (const analyzer::Rule& r : analyzer::builtin_rules().rules()) {
        if (!r.has_fix) continue;
        INFO(r.id << " " << r.name);
        const fs::path dir = fixture_of(r);
        const Expected expected = read_expected(dir / "expected.txt");
        const std::string bad = test::read_text(dir / "bad.nc");
        std::vector<analyzer::Finding> mine;
        for (const analyzer::Finding& f : test::check(bad, expected.dialect).findings)
            if (f.rule == r.id) mine.push_back(f);
        REQUIRE(!mine.empty());
        const analyzer::FixResult fixed = analyzer::apply_fixes(bad, mine);
        CHECK(fixed.applied > 0);
        CHECK(fixed.text != bad);
        CHECK(test::summary(test::check(fixed.text, expected.dialect), r.id).empty());
        ++fixes;
    }
    CHECK(fixes >= 8);
}
