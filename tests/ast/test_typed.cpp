// The typed AST: roles bound from the dialect tables (dialects.md §3.1–§3.3, §11.4).
#include <catch2/catch.hpp>

#include "ast/typed.hpp"
#include "grammar/parse.hpp"

using namespace kerf;
using ast::Role;
namespace fn = kerf::dialects::functions;

namespace {

struct Bound {
    ast::SyntaxTree tree;
    std::optional<ast::TypedFile> typed;
};

std::unique_ptr<Bound> bind(const std::string& text, const char* dialect_id) {
    const dialects::Dialect* d = dialects::builtin_registry().find(dialect_id);
    REQUIRE(d);
    auto b = std::make_unique<Bound>();
    b->tree = grammar::parse(text, d->lexical);
    b->typed = ast::TypedFile::bind(b->tree, *d);
    return b;
}

Role role_of(const Bound& b, std::size_t block, char letter) {
    const auto w = b.typed->block(block).word(letter);
    REQUIRE(w);
    return b.tree.tokens[*w].role();
}

}  // namespace

TEST_CASE("system A: X/Z/C absolute, U/W/H incremental onto X/Z/C") {
    const auto b = bind("G01 X10 U2 Z-5 W-1 C90 H45 F.2\n", "fanuc-lathe-a");
    const auto axes = b->typed->block(0).axis_words();
    REQUIRE(axes.size() == 6);
    CHECK(axes[1].axis == 'X');
    CHECK(axes[1].incremental);
    CHECK(axes[5].axis == 'C');
    CHECK(axes[5].incremental);
    CHECK(role_of(*b, 0, 'F') == Role::parameter);
    const auto g = b->typed->block(0).g_codes();
    REQUIRE(g.size() == 1);
    REQUIRE(g[0].info);
    CHECK(g[0].info->group == "01");
    CHECK(g[0].info->function == fn::linear);
}

TEST_CASE("cycle and dwell data letters are parameters, not moves") {
    const auto b = bind("G71 U2. R.5\nG71 P10 Q20 U.4 W.1 F.25\nG04 X1.5\nG04 U2\nG10 P0 Z-103\nG28 U0 W0\n", "fanuc-lathe-a");
    CHECK(role_of(*b, 0, 'U') == Role::parameter);
    CHECK(role_of(*b, 1, 'W') == Role::parameter);
    CHECK(role_of(*b, 2, 'X') == Role::parameter);
    CHECK(role_of(*b, 3, 'U') == Role::parameter);
    CHECK(role_of(*b, 4, 'Z') == Role::parameter);
    // G28 U0: the intermediate point, an incremental axis word (dialects.md §3.2).
    CHECK(role_of(*b, 5, 'U') == Role::axis_incremental);
}

TEST_CASE("system B: G90/G91 decide, the same data letters in renamed cycles") {
    const auto b = bind("G91 G01 X1 Z2\nG71 U2 R1\n", "fanuc-lathe-b");
    CHECK(role_of(*b, 0, 'X') == Role::axis_absolute);
    CHECK(role_of(*b, 1, 'U') == Role::parameter);
    const auto c = bind("G73 U2 R1\n", "fanuc-lathe-c");   // C: G73 is the roughing cycle
    CHECK(role_of(*c, 0, 'U') == Role::parameter);
}

TEST_CASE("SPINNER plain A and R are direct-drawing words in G01 blocks, and stay modal") {
    const auto b = bind("G01 X55 R4\nA180 R15\nG00 X100 A5\n", "spinner-lathe-a");
    CHECK(role_of(*b, 0, 'R') == Role::direct_drawing);
    CHECK(role_of(*b, 1, 'A') == Role::direct_drawing);
    CHECK(role_of(*b, 2, 'A') != Role::direct_drawing);
    const auto plain = bind("G01 X55 R4\n", "fanuc-lathe-a");
    CHECK(role_of(*plain, 0, 'R') == Role::parameter);
}

TEST_CASE("G65 words are macro arguments; sequence and program words") {
    const auto b = bind("O9010\nN5 G65 P9010 X1. Z2. A3\n", "fanuc-lathe-a");
    CHECK(role_of(*b, 0, 'O') == Role::program);
    CHECK(role_of(*b, 1, 'N') == Role::sequence);
    CHECK(role_of(*b, 1, 'X') == Role::parameter);
    CHECK(b->typed->block(1).sequence_number() == 5.0);
}

TEST_CASE("unknown codes are bound as codes without table entry") {
    const auto b = bind("G999 M777\n", "fanuc-mill");
    const auto g = b->typed->block(0).g_codes();
    REQUIRE(g.size() == 1);
    CHECK(g[0].info == nullptr);
    CHECK(g[0].key == 9990);
    const auto m = b->typed->block(0).m_codes();
    REQUIRE(m.size() == 1);
    CHECK(m[0].info == nullptr);
}

TEST_CASE("decimal codes and leading zeros: G12.1, G112, G01.0, M003") {
    const auto b = bind("G12.1\nG112\nG01.0 M003\n", "fanuc-lathe-a");
    REQUIRE(b->typed->block(0).g_codes()[0].info);
    CHECK(b->typed->block(0).g_codes()[0].info->function == fn::polar_interpolation_on);
    CHECK(b->typed->block(1).g_codes()[0].info == b->typed->block(0).g_codes()[0].info);
    CHECK(b->typed->block(2).g_codes()[0].info->function == fn::linear);
    CHECK(b->typed->block(2).m_codes()[0].info->function == fn::spindle_cw);
}

TEST_CASE("rebinding one block takes its modal context from the blocks before") {
    const dialects::Dialect* d = dialects::builtin_registry().find("spinner-lathe-a");
    ast::SyntaxTree tree = grammar::parse("G01 X1\nX2 R3\n", d->lexical);
    auto typed = ast::TypedFile::bind(tree, *d);
    tree.tokens[typed.block(1).first_token() + 1].set_role(Role::none);
    typed.rebind_block(tree, 1);
    CHECK(tree.tokens[typed.block(1).first_token() + 1].role() == Role::direct_drawing);
}

TEST_CASE("a one-shot cycle code ends plain direct drawing for its block") {
    const auto b = bind("G1 X10 Z0\nG71 U3 R1\nG76 P010060 Q50 R0.03\nX20 R2\n", "spinner-lathe-a");
    CHECK(role_of(*b, 1, 'R') == Role::parameter);
    CHECK(role_of(*b, 2, 'R') == Role::parameter);
    CHECK(role_of(*b, 3, 'R') == Role::direct_drawing);   // G01 is still modal
}

TEST_CASE("SPINNER G384 H and M329 H are cycle data, not incremental C") {
    const auto b = bind("G384 X0 C0 Z2 H20. R1 F1.5\nM329 Z2 H-30. R1 F1.5\nG1 H45\n", "spinner-lathe-a");
    CHECK(role_of(*b, 0, 'H') == Role::parameter);
    CHECK(role_of(*b, 1, 'H') == Role::parameter);
    CHECK(role_of(*b, 2, 'H') == Role::axis_incremental);
}

TEST_CASE("a second N word in a block is diagnosed") {
    const auto b = bind("N50 G384 N30 F1\n", "spinner-lathe-a");
    REQUIRE(b->typed->diagnostics().size() == 1);
    CHECK(b->typed->diagnostics()[0].code == "S0302");
}
