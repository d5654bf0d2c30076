// Golden before/after pairs for every style option and every block-number mode (issue 6, point 1):
// tests/golden/format/<case>.nc formatted in the style of <case>.toml must be <case>.expected byte
// for byte. The expected files were written by hand (tests/golden/format/REVIEW.md). Each case is
// also formatted again (idempotent) and run before and after (same trace).
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "tests/formatter/format_fixture.hpp"
#include "tests/golden_diff.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf;


TEST_CASE("golden format pairs: each style option and block-number mode") {
    const fs::path dir = fs::path(KERF_SOURCE_DIR) / "tests" / "golden" / "format";
    std::size_t cases = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".nc") continue;
        const fs::path input = entry.path();
        const std::string name = input.stem().string();
        INFO(name);
        const std::string toml = test::read_text(fs::path(input).replace_extension(".toml"));
        REQUIRE_FALSE(toml.empty());
        const formatter::StyleResult style = formatter::style_from_toml(toml, name + ".toml");
        REQUIRE(style.errors.empty());
        const dialects::Dialect& d = test::fmt_dialect(test::golden_value(toml, "dialect"));
        const std::string calc = test::golden_value(toml, "calculator_decimal");
        const std::optional<bool> calculator = calc.empty() ? std::nullopt : std::optional<bool>(calc == "true");
        const std::string text = test::read_text(input);
        const std::string expected = test::read_text(fs::path(input).replace_extension(".expected"));
        const std::string out = test::formatted(text, d, style.style, calculator);
        INFO(test::line_diff(expected, out));
        CHECK(out == expected);
        CHECK(test::formatted(out, d, style.style, calculator) == out);
        formatter::VerifyOptions o;
        o.dialect = &d;
        o.setup = interpreter::default_setup(d);
        if (calculator) o.setup.calculator_decimal = *calculator;
        const auto difference = formatter::verify(name, text, out, o).difference;
        INFO((difference ? difference->what : std::string()));
        CHECK_FALSE(difference.has_value());
        ++cases;
    }
    CHECK(cases >= 21);
}
