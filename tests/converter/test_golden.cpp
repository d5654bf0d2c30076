// Golden before/after pairs of `kerf convert` (issue 16, point 1): tests/golden/convert/<case>.nc
// converted as <case>.toml says must be <case>.expected byte for byte, with exactly the reports the
// .toml lists. The expected files and reports were written by hand (tests/golden/convert/REVIEW.md
// says how each was derived). Where the .toml says `reverse = true`, the expected text converted
// back gives the input byte for byte; unless `verify = false`, input and expected output dry-run to
// the same motion on one machine (0.001 mm).
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/converter/convert_fixture.hpp"
#include "tests/golden_diff.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf;

namespace {

// "not converted 5:4 G384": kind, line:column (1-based) and the construct's text.
std::string describe(const std::string& text, const converter::Report& r) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < r.range.begin && i < text.size(); ++i) {
        if (text[i] == '\n') ++line, column = 1;
        else ++column;
    }
    return std::string(converter::to_string(r.kind)) + " " + std::to_string(line) + ":" + std::to_string(column) + " " +
           r.construct;
}

// The built-in dialects and the case's `dialect_file`s (user dialects in tests/golden/convert/dialects).
dialects::Registry registry_of(const std::string& toml, const fs::path& dir) {
    dialects::Registry r = dialects::builtin_registry();
    for (const std::string& file : test::golden_values(toml, "dialect_file")) {
        const auto errors = r.add_text(test::read_text(dir / "dialects" / file), file);
        INFO(file << ": " << (errors.empty() ? std::string() : errors.front().message));
        REQUIRE(errors.empty());
    }
    return r;
}

const dialects::Dialect& find(const dialects::Registry& r, const std::string& id) {
    const dialects::Dialect* d = r.find(id);
    INFO("dialect " << id);
    REQUIRE(d != nullptr);
    return *d;
}

converter::Options options_of(const std::string& toml) {
    converter::Options o;
    if (test::golden_value(toml, "incremental") == "letters") o.incremental = converter::IncrementalStyle::letters;
    o.expand = test::golden_value(toml, "expand") == "true";
    return o;
}

}  // namespace

TEST_CASE("golden convert pairs: every rename, word rule and reported construct") {
    const fs::path dir = fs::path(KERF_SOURCE_DIR) / "tests" / "golden" / "convert";
    std::size_t cases = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".nc") continue;
        const fs::path input = entry.path();
        const std::string name = input.stem().string();
        INFO(name);
        const std::string toml = test::read_text(fs::path(input).replace_extension(".toml"));
        REQUIRE_FALSE(toml.empty());
        const dialects::Registry registry = registry_of(toml, dir);
        const dialects::Dialect& from = find(registry, test::golden_value(toml, "from"));
        const dialects::Dialect& to = find(registry, test::golden_value(toml, "to"));
        const std::string text = test::read_text(input);
        const std::string expected = test::read_text(fs::path(input).replace_extension(".expected"));
        const test::Converted out = test::convert_text(text, from, to, options_of(toml));
        INFO(test::line_diff(expected, out.text));
        CHECK(out.text == expected);
        std::vector<std::string> reports;
        for (const converter::Report& r : out.reports) reports.push_back(describe(text, r));
        CHECK(reports == test::golden_values(toml, "report"));
        CHECK(out.clean == (test::golden_value(toml, "clean", "true") == "true"));
        if (test::golden_value(toml, "verify", "true") == "true") {
            const auto difference = test::motion_difference(text, from, out.text, to);
            INFO((difference ? difference->what + " at input line " + std::to_string(difference->input_line) : std::string()));
            CHECK_FALSE(difference.has_value());
        }
        if (test::golden_value(toml, "reverse") == "true") {
            converter::Options back = options_of(toml);
            const test::Converted again = test::convert_text(expected, to, from, back);
            INFO("back: " << test::line_diff(text, again.text));
            CHECK(again.text == text);
        }
        ++cases;
    }
    CHECK(cases >= 30);
}
