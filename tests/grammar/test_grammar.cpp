#include <catch2/catch.hpp>

#include "ast/printer.hpp"
#include "grammar/parse.hpp"

TEST_CASE("smoke") {
    kerf::dialects::LexicalRules rules;
    auto tree = kerf::grammar::parse("N10 G01 X-12.5 Z.5 F0.25;\n", rules);
    REQUIRE(kerf::ast::print(tree) == "N10 G01 X-12.5 Z.5 F0.25;\n");
}
