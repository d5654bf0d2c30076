// Every input a fuzzer ever broke (fuzz/regressions/) passes its target's check again: the
// grammar's files (the directory itself) parse losslessly under every dialect, without crashing,
// overflowing the stack or taking quadratic time; fuzz/regressions/<target>/ hold the other
// targets' inputs, run through fuzz/checks.hpp.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "ast/printer.hpp"
#include "ast/typed.hpp"
#include "fuzz/checks.hpp"
#include "grammar/parse.hpp"

namespace fs = std::filesystem;

namespace {

std::string read_all(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Every file of fuzz/regressions/<target>/ through the target's check (fuzz/checks.hpp); returns
// how many there were.
std::size_t run_regressions(const char* target, kerf::fuzz::Broken (*check)(std::string_view)) {
    const fs::path dir = fs::path(KERF_SOURCE_DIR) / "fuzz" / "regressions" / target;
    std::size_t n = 0;
    if (!fs::is_directory(dir)) return n;
    for (const auto& e : fs::directory_iterator(dir)) {
        INFO(e.path().string());
        const kerf::fuzz::Broken broken = check(read_all(e.path()));
        CHECK(broken.value_or("") == "");
        ++n;
    }
    return n;
}

}  // namespace

// The seeds of each target pass its check too: the checks hold on ordinary programs.
TEST_CASE("fuzz checks hold on the seed corpus and the examples") {
    const fs::path corpus = fs::path(KERF_SOURCE_DIR) / "fuzz" / "corpus";
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(corpus)) {
        INFO(e.path().string());
        const std::string input = read_all(e.path());
        CHECK(kerf::fuzz::check_interpreter(input).value_or("") == "");
        CHECK(kerf::fuzz::check_analyzer(input).value_or("") == "");
        CHECK(kerf::fuzz::check_formatter(input).value_or("") == "");
        ++n;
    }
    CHECK(n >= 80);
    for (const auto& e : fs::directory_iterator(fs::path(KERF_SOURCE_DIR) / "machine" / "data")) {
        INFO(e.path().string());
        CHECK(kerf::fuzz::check_machine_toml(read_all(e.path())).value_or("") == "");
    }
    for (const auto& e : fs::directory_iterator(fs::path(KERF_SOURCE_DIR) / "dialects" / "data")) {
        INFO(e.path().string());
        CHECK(kerf::fuzz::check_dialect_toml(read_all(e.path())).value_or("") == "");
    }
}

TEST_CASE("fuzz regressions of the interpreter, analyzer, formatter and TOML loaders stay fixed") {
    run_regressions("interpreter", kerf::fuzz::check_interpreter);
    run_regressions("analyzer", kerf::fuzz::check_analyzer);
    run_regressions("formatter", kerf::fuzz::check_formatter);
    run_regressions("machine_toml", kerf::fuzz::check_machine_toml);
    run_regressions("dialect_toml", kerf::fuzz::check_dialect_toml);
}

TEST_CASE("fuzz regressions stay fixed") {
    const fs::path dir = fs::path(KERF_SOURCE_DIR) / "fuzz" / "regressions";
    REQUIRE(fs::is_directory(dir));
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.is_directory()) continue;   // the other targets' regressions (above)
        std::ifstream in(e.path(), std::ios::binary);
        std::ostringstream ss;
        ss << in.rdbuf();
        const std::string text = ss.str();
        INFO(e.path().filename().string());
        for (const std::string& id : kerf::dialects::builtin_registry().ids()) {
            const kerf::dialects::Dialect* d = kerf::dialects::builtin_registry().find(id);
            kerf::ast::SyntaxTree tree = kerf::grammar::parse(text, d->lexical);
            (void)kerf::ast::TypedFile::bind(tree, *d);
            REQUIRE(kerf::ast::print(tree) == text);
            REQUIRE_FALSE(kerf::ast::check_lossless(tree).has_value());
        }
        ++n;
    }
    CHECK(n >= 4);
}
