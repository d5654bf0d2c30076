// The converter's parts: exact decimal rewriting, code respelling, the edit list, the code map by
// function id (every code of the A/B/C tables of gcode-tables.md §1 maps to its row), and what
// only a user's dialect shows (a packed-only M98, dialects.md §3.6).
#include <catch2/catch.hpp>

#include "converter/codes.hpp"
#include "converter/numbers.hpp"
#include "converter/words.hpp"
#include "tests/converter/convert_fixture.hpp"

using namespace kerf;
using namespace kerf::converter;

TEST_CASE("decimals move their point exactly") {
    const auto d = [](const char* s) { return *parse_decimal(s); };
    CHECK(with_point(shifted(d("100"), -3)) == "0.1");
    CHECK(with_point(shifted(d("-250"), -3)) == "-0.25");
    CHECK(with_point(shifted(d("20500"), -3)) == "20.5");
    CHECK(with_point(shifted(d("0"), -3)) == "0.");
    CHECK(with_point(d("20")) == "20.");
    CHECK(plain(shifted(d("0.055"), 3)) == "55");
    CHECK(plain(shifted(d(".5"), 3)) == "500");
    CHECK(plain(shifted(d("1500"), -3)) == "1.5");
    CHECK(plain(shifted(d("2"), 3)) == "2000");
    CHECK(plain(negated(d("34"))) == "-34");
    CHECK(with_point(negated(d("-30."))) == "30.");
    CHECK(plain(negated(d("0"))) == "0");
    CHECK_FALSE(parse_decimal("#1").has_value());
    CHECK_FALSE(parse_decimal("-").has_value());
    CHECK(with_point(d("0,25")) == "0.25");   // F0,25 (decimal_comma words)
    CHECK(format_value(45, 3) == "45.");
    CHECK(format_value(12.5, 3) == "12.5");
    CHECK(format_value(-0.0004, 3) == "0.");
    CHECK(format_value(1.23456, 4) == "1.2346");
}

TEST_CASE("a renamed code keeps the source's spelling style") {
    const dialects::Dialect& b = test::dialect("fanuc-lathe-b");
    const dialects::Dialect& pcnc = test::dialect("pcnc-mill");
    CHECK(respell_code("G90", *b.code("G77")) == "G77");
    CHECK(respell_code("g90", *b.code("G77")) == "g77");
    CHECK(respell_code("G152", *test::dialect("fanuc-mill").code("G52")) == "G52");
    CHECK(respell_code("G04", *pcnc.code("G4")) == "G04");
    CHECK(respell_code("G4", *b.code("G04")) == "G4");
    CHECK(respell_code("G13.1", *b.code("G13.1")) == "G13.1");
}

TEST_CASE("edits apply in order, insertions before replacements at one place") {
    Edits e;
    e.insert(0, "G91 ");
    e.replace({0, 1}, "X");
    e.remove({3, 4});
    CHECK(e.size() == 3);
    CHECK(converter::apply("U2. W3.", e) == "G91 X2.W3.");
    CHECK(e.growth() == 4 - 1);
}

// gcode-tables.md §1.1: the rename map, row by row, through the function ids of the data files.
TEST_CASE("the A/B/C rename map of gcode-tables.md §1.1 comes out of the function ids") {
    const dialects::Dialect& a = test::dialect("fanuc-lathe-a");
    const dialects::Dialect& b = test::dialect("fanuc-lathe-b");
    const dialects::Dialect& c = test::dialect("fanuc-lathe-c");
    const CodeMap ab(a, b), ac(a, c), bc(b, c), ca(c, a);
    const auto target = [](const CodeMap& m, const dialects::Dialect& from, const char* code) -> std::string {
        const CodeMapping& x = m(*from.code(code));
        return x.target ? x.target->spelling : std::string("-");
    };
    const char* rows[][3] = {
        {"G32", "G33", "G33"}, {"G20", "G20", "G70"}, {"G21", "G21", "G71"}, {"G50", "G92", "G92"},
        {"G70", "G70", "G72"}, {"G71", "G71", "G73"}, {"G72", "G72", "G74"}, {"G73", "G73", "G75"},
        {"G74", "G74", "G76"}, {"G75", "G75", "G77"}, {"G76", "G76", "G78"}, {"G90", "G77", "G20"},
        {"G92", "G78", "G21"}, {"G94", "G79", "G24"}, {"G98", "G94", "G94"}, {"G99", "G95", "G95"},
    };
    for (const auto& row : rows) {
        INFO(row[0]);
        CHECK(target(ab, a, row[0]) == row[1]);
        CHECK(target(ac, a, row[0]) == row[2]);
        CHECK(target(bc, b, row[1]) == row[2]);
        CHECK(target(ca, c, row[2]) == row[0]);
    }
    // The hazards of §1.1: system C's G70/G71 are units, never cycles; B's G92 is a setting.
    CHECK(ca(*c.code("G70")).target->function == dialects::functions::inch_input);
    CHECK(CodeMap(b, a)(*b.code("G92")).target->spelling == "G50");
    // B/C G90/G91 and G98/G99 (return level) are decided block by block.
    CHECK(CodeMap(b, a)(*b.code("G91")).action == CodeAction::distance_mode);
    CHECK(CodeMap(b, a)(*b.code("G99")).action == CodeAction::return_level);
    CHECK(bc(*b.code("G99")).action == CodeAction::keep);
}

TEST_CASE("controls: G68's sign and G52's reading are substitutions, seed-004 G28 has nothing") {
    const dialects::Dialect& fanuc = test::dialect("fanuc-mill");
    const dialects::Dialect& adv = test::dialect("adv400-mill");
    const dialects::Dialect& pcnc = test::dialect("pcnc-mill");
    const dialects::Dialect& iso = test::dialect("iso-legacy-mill");
    CHECK(CodeMap(adv, fanuc)(*adv.code("G68")).action == CodeAction::rotation_sign);
    CHECK(CodeMap(fanuc, pcnc)(*fanuc.code("G52")).action == CodeAction::local_system);
    CHECK(CodeMap(pcnc, fanuc)(*pcnc.code("G152")).action == CodeAction::local_cancel);
    CHECK(CodeMap(iso, fanuc)(*iso.code("G28")).action == CodeAction::none);
    CHECK(CodeMap(fanuc, iso)(*fanuc.code("G28")).action == CodeAction::none);
}

TEST_CASE("drilling letters follow each table's word list") {
    const dialects::Dialect& fanuc = test::dialect("fanuc-mill");
    const dialects::Dialect& adv = test::dialect("adv400-lathe");
    CHECK(drill_letters(*fanuc.code("G83")).peck == 'Q');
    CHECK(drill_letters(*fanuc.code("G83")).repeat == 'K');
    CHECK(drill_letters(*adv.code("G83")).peck == 'K');    // cycles.md §11.3: K is the peck
    CHECK(drill_letters(*adv.code("G83")).repeat == 'L');
    CHECK(drill_letters(*fanuc.code("G81")).peck == 0);
}

// dialects.md §3.6: a control that reads only `M98 P<repeats><program>`, as a user's dialect file.
TEST_CASE("M98 P L into a packed-only dialect: the repeats go in front of a four-digit program") {
    dialects::Registry registry = dialects::builtin_registry();
    const auto errors = registry.add_text(
        "id = \"packed-mill\"\nname = \"a packed-only FANUC mill\"\nbase = \"fanuc-mill\"\nreference = \"test\"\n"
        "[lexical]\nsubprogram_call = \"packed\"\n",
        "packed-mill.toml");
    REQUIRE(errors.empty());
    const dialects::Dialect& packed = *registry.find("packed-mill");
    const dialects::Dialect& adv = test::dialect("adv400-mill");
    const std::string text = "N10 M98 P12 L100\nN20 M98P1001L4\nN30 M98 P1001 L1\nN40 M98 P12345 L2\nN50 M30\n";
    ast::SyntaxTree tree = grammar::parse(text, adv.lexical);
    const ast::TypedFile typed = ast::TypedFile::bind(tree, adv);
    const Conversion c = convert(typed, packed);
    CHECK(converter::apply(text, c.edits) == "N10 M98 P1000012\nN20 M98P41001\nN30 M98 P1001\nN40 M98 P12345 L2\nN50 M30\n");
    REQUIRE(c.reports.size() == 1);   // a five-digit program does not fit the packed P
    CHECK(c.reports[0].construct == "P12345");
    CHECK(c.reports[0].kind == ReportKind::unconverted);
}
