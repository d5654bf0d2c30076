// The one reference resolver (references/references.hpp, issue 13): what each jump and call word
// refers to, its scope, and how it is written again for a new number. Every expected value below
// is read off the program text by hand: the token whose value range is asserted is quoted.
#include <catch2/catch.hpp>

#include <string>

#include "grammar/parse.hpp"
#include "references/references.hpp"

using namespace kerf;
using references::Kind;
using references::Reference;

namespace {

struct Bound {
    Bound(std::string text, const dialects::Dialect& d) : tree(grammar::parse(std::move(text), d.lexical)), typed(ast::TypedFile::bind(tree, d)) {}
    ast::SyntaxTree tree;
    ast::TypedFile typed;
    std::string_view at(const Reference& r) const { return tree.slice(r.range); }
};

const dialects::Dialect& dialect(const char* id) {
    const dialects::Dialect* d = dialects::builtin_registry().find(id);
    REQUIRE(d != nullptr);
    return *d;
}

// fanuc-mill with a Haas-style M97 (local subprogram call): no built-in dialect has one yet.
const dialects::Dialect& with_m97() {
    static const dialects::Dialect d = [] {
        dialects::Dialect copy = dialect("fanuc-mill");
        dialects::CodeInfo m97;
        m97.letter = 'M';
        m97.key = 970;
        m97.spelling = "M97";
        m97.function = dialects::functions::local_subprogram_call;
        m97.words = {"P", "L"};
        m97.en = "Local subprogram call";
        copy.add_or_replace(m97);
        copy.id = "test-m97";
        return copy;
    }();
    return d;
}

}  // namespace

TEST_CASE("every kind of reference, with its value and where the number is written") {
    const Bound f("O0001\n"
                  "N10 G65 P9010 A1.\n"      // block 1
                  "N20 G66 P9011\n"          // block 2
                  "N30 M98 P41001\n"         // block 3: packed, 4 times O1001
                  "N40 M98 P1002 L3\n"       // block 4: P/L form
                  "N50 M98 Q70\n"            // block 5: a label of this program
                  "N60 IF [#1 LT 3] GOTO 10\n"  // block 6
                  "N70 GOTO [20]\n"          // block 7: bracketed constant
                  "N80 GOTO #5\n"            // block 8: computed
                  "M30\n"
                  "O1001\nN5 M99 P40\n",
                  dialect("fanuc-mill"));
    const std::vector<Reference> refs = references::file_references(f.typed);
    REQUIRE(refs.size() == 9);
    CHECK(refs[0].kind == Kind::macro);
    CHECK(refs[0].value == 9010);
    CHECK(f.at(refs[0]) == "9010");
    CHECK(refs[1].kind == Kind::macro);
    CHECK(refs[1].value == 9011);
    CHECK(refs[2].kind == Kind::subprogram);
    CHECK(refs[2].value == 1001);
    CHECK(refs[2].packed);
    CHECK(refs[2].repeats == 4);
    CHECK(f.at(refs[2]) == "41001");
    CHECK(refs[3].kind == Kind::subprogram);
    CHECK(refs[3].value == 1002);
    CHECK_FALSE(refs[3].packed);   // "both" form with L: P is the program
    CHECK(refs[4].kind == Kind::call_label);
    CHECK(refs[4].value == 70);
    CHECK_FALSE(refs[4].label_program);
    CHECK(refs[5].kind == Kind::goto_label);
    CHECK(refs[5].value == 10);
    CHECK(f.at(refs[5]) == "10");
    CHECK(refs[6].kind == Kind::goto_label);
    CHECK(refs[6].value == 20);
    CHECK(f.at(refs[6]) == "20");   // the number inside the brackets
    CHECK(refs[7].kind == Kind::goto_label);
    CHECK_FALSE(refs[7].value);     // GOTO #5 is known only at run time
    CHECK(f.at(refs[7]) == "#5");
    CHECK(refs[8].kind == Kind::return_label);
    CHECK(refs[8].value == 40);
    CHECK(refs[8].program == 1);
    for (const Reference& r : refs) CHECK(references::program_of_block(f.typed, r.block) == r.program);
}

TEST_CASE("labels resolve to the first block of the program that carries them") {
    const Bound f("O0001\nN10 G0 X0\nN20 G1 X1\nN10 G1 X2\nGOTO 10\nM30\nO0002\nN10 G0 X5\nM99\n", dialect("fanuc-mill"));
    CHECK(references::find_label(f.typed, 0, 10) == 1u);
    CHECK(references::label_blocks(f.typed, 0, 10) == std::vector<std::uint32_t>{1, 3});
    CHECK(references::find_label(f.typed, 1, 10) == 7u);   // O0002's own N10
    CHECK_FALSE(references::find_label(f.typed, 0, 30));
    CHECK(references::program_numbered(f.typed, 2) == 1u);
    CHECK_FALSE(references::program_numbered(f.typed, 3));
}

TEST_CASE("G70–G73 P/Q by function id in G-code systems A and C") {
    // System A: G71/G70; system C numbers them G73/G72 (gcode-tables.md §2).
    const Bound a("O1\nG71 U1 R1\nG71 P10 Q20 U.2 W.1\nN10 G0 X10\nN20 G1 Z-5\nG70 P10 Q20\nM30\n", dialect("fanuc-lathe-a"));
    std::vector<Reference> refs = references::file_references(a.typed);
    REQUIRE(refs.size() == 4);
    for (const Reference& r : refs) CHECK(r.kind == Kind::profile_label);
    CHECK(refs[0].letter == 'P');
    CHECK(refs[1].letter == 'Q');
    CHECK(refs[3].value == 20);
    const Bound c("O1\nG73 P10 Q20 U.2 W.1\nN10 G0 X10\nN20 G1 Z-5\nG72 P10 Q20\nM30\n", dialect("fanuc-lathe-c"));
    refs = references::file_references(c.typed);
    REQUIRE(refs.size() == 4);
    CHECK(refs[0].kind == Kind::profile_label);
    CHECK(refs[2].kind == Kind::profile_label);
}

TEST_CASE("label scopes: M98 P Q names the called program's labels, M99 P the callers'") {
    const Bound f("O0001\nN1 M98 P0002 Q30\nN2 M98 P0009 Q40\nN3 M30\n"
                  "O0002\nN30 G0 X1\nM99 P3\n",
                  dialect("fanuc-mill"));
    const std::vector<Reference> refs = references::file_references(f.typed);
    REQUIRE(refs.size() == 5);
    // M98 P0002 Q30: N30 of O0002, which is in this file.
    CHECK(refs[1].kind == Kind::call_label);
    CHECK(refs[1].label_program == 2);
    references::LabelScope s = references::label_scope(f.typed, refs[1]);
    CHECK(s.programs == std::vector<std::uint32_t>{1});
    CHECK_FALSE(s.other_program);
    // M98 P0009 Q40: O0009 is elsewhere, so is its label.
    s = references::label_scope(f.typed, refs[3]);
    CHECK(s.programs.empty());
    CHECK(s.other_program == 9);
    // M99 P3 in O0002: the caller O0001 (and callers in other files).
    CHECK(refs[4].kind == Kind::return_label);
    s = references::label_scope(f.typed, refs[4]);
    CHECK(s.programs == std::vector<std::uint32_t>{0});
    CHECK(s.other_callers);
    CHECK(references::callers_of(f.typed, 1) == std::vector<std::uint32_t>{0});
}

TEST_CASE("M98 P Q with a computed P: the label is not followed") {
    const Bound f("O1\nM98 P#1 Q10\nN10 M30\n", dialect("fanuc-mill"));
    const std::vector<Reference> refs = references::file_references(f.typed);
    REQUIRE(refs.size() == 2);
    CHECK(refs[0].kind == Kind::subprogram);
    CHECK_FALSE(refs[0].value);
    CHECK(refs[1].kind == Kind::call_label);
    CHECK_FALSE(refs[1].value);
}

TEST_CASE("M97 P (Haas local subprogram) by function id") {
    const Bound f("O1\nM97 P100\nM30\nN100 G0 X1\nM99\n", with_m97());
    const std::vector<Reference> refs = references::file_references(f.typed);
    REQUIRE(refs.size() == 1);
    CHECK(refs[0].kind == Kind::local_call_label);
    CHECK(refs[0].value == 100);
    CHECK(references::label_scope(f.typed, refs[0]).programs == std::vector<std::uint32_t>{0});
    CHECK(references::find_label(f.typed, 0, 100) == 3u);
}

TEST_CASE("respell keeps the form of the reference") {
    const Bound f("O1\nM98 P31234\nM98 P0012\nM98 P30012\nG65 P9010\nGOTO 0100\nM98 P1234 L2\nM30\n", dialect("fanuc-mill"));
    const std::vector<Reference> refs = references::file_references(f.typed);
    REQUIRE(refs.size() == 6);
    // The example: M98 P31234 renamed to 1240 becomes M98 P31240.
    CHECK(references::respell(f.tree, refs[0], 1240) == "31240");
    CHECK_FALSE(references::respell(f.tree, refs[0], 12400));   // four digits of program in packed P
    CHECK(references::respell(f.tree, refs[1], 40) == "0040");  // leading zeros kept
    CHECK_FALSE(references::respell(f.tree, refs[1], 10000));   // P without L is read packed
    CHECK(references::respell(f.tree, refs[2], 40) == "30040");
    CHECK(references::respell(f.tree, refs[3], 9020) == "9020");
    CHECK(references::respell(f.tree, refs[4], 110) == "0110");
    CHECK(references::respell(f.tree, refs[5], 12345) == "12345");   // P/L form: P is the program
    CHECK_FALSE(references::respell(f.tree, refs[5], -1));
}

TEST_CASE("P/L dialects read M98 P as the program") {
    const Bound f("O1\nM98 P41001\nM30\n", dialect("adv400-mill"));
    const std::vector<Reference> refs = references::file_references(f.typed);
    REQUIRE(refs.size() == 1);
    CHECK(refs[0].value == 41001);
    CHECK_FALSE(refs[0].packed);
}
