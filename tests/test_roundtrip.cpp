// Round trip over every reference example and every corpus file (issue: foundation, point 2):
// `kerf parse --print` gives back the input byte for byte, and the library does so under every
// dialect's lexical rules, with every byte in a token or trivia. Skips with a message when
// ../shared is absent.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "ast/printer.hpp"
#include "ast/typed.hpp"
#include "grammar/parse.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;

namespace {

// `kerf parse --print <file>`: its stdout (stderr dropped).
std::string run_print(const fs::path& p) {
    return kerf::test::capture(std::string(KERF_BINARY) + " parse --print " + kerf::test::shell_quote(p) + " 2>/dev/null").out;
}

}  // namespace

TEST_CASE("reference examples and corpus: lossless under every dialect") {
    const auto files = kerf::test::shared_files_or_warn("round-trip checks over the reference and corpus were not run");
    if (files.empty()) return;
    REQUIRE(files.size() >= 140);   // 88 examples + 60 corpus files
    const auto& registry = kerf::dialects::builtin_registry();
    std::size_t parses = 0;
    for (const fs::path& file : files) {
        const std::string text = kerf::test::read_text(file);
        for (const std::string& id : registry.ids()) {
            const kerf::dialects::Dialect* d = registry.find(id);
            kerf::ast::SyntaxTree tree = kerf::grammar::parse(text, d->lexical);
            (void)kerf::ast::TypedFile::bind(tree, *d);
            INFO(file.string() << " as " << id);
            REQUIRE(kerf::ast::print(tree) == text);
            const auto violation = kerf::ast::check_lossless(tree);
            INFO((violation ? violation->what : std::string()));
            REQUIRE_FALSE(violation.has_value());
            ++parses;
        }
    }
    CHECK(parses == files.size() * registry.ids().size());
}

TEST_CASE("reference examples and corpus: kerf parse --print is byte for byte") {
    const auto files = kerf::test::shared_files_or_warn("round-trip checks over the reference and corpus were not run");
    if (files.empty()) return;
    for (const fs::path& file : files) {
        INFO(file.string());
        REQUIRE(run_print(file) == kerf::test::read_text(file));
    }
}
