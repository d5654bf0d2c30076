// Every input the fuzzer ever broke (fuzz/regressions/) parses losslessly under its dialect,
// without crashing, overflowing the stack or taking quadratic time.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "ast/printer.hpp"
#include "ast/typed.hpp"
#include "grammar/parse.hpp"

namespace fs = std::filesystem;

TEST_CASE("fuzz regressions stay fixed") {
    const fs::path dir = fs::path(KERF_SOURCE_DIR) / "fuzz" / "regressions";
    REQUIRE(fs::is_directory(dir));
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
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
