// Dialect detection (reference/dialects.md §10): the evidence table, one case per dialect.
#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/detect.hpp"

using kerf::grammar::detect_dialect;

TEST_CASE("detection follows the evidence of dialects.md §10 and says why") {
    struct Case {
        const char* text;
        const char* dialect;
    };
    const Case cases[] = {
        {"O1\nG50 S2000\nG96 S200 M3\nG0 X50 Z2\nG71 U2 R1\nG71 P10 Q20 U.5 W.1 F.25\nG1 U-2 W-3\nM30\n", "fanuc-lathe-a"},
        {"O1\nG38 B-300 F2000 Q1\nG0 X50 Z2\nM30\n", "spinner-lathe-a"},
        {"O1\nG90 G54 G17\nT1 M06\nG43 H01 Z50\nG0 X0 Y0\nM30\n", "fanuc-mill"},
        {"::LOOP.NC header\nG0 X1 Y1\nM98 P12 L100\nG92.1\nM30\n", "adv400-mill"},
        {";;LOOP.NC header\nG0 X1 Z1\nM98 P12 L100\nM30\n", "adv400-lathe"},
        {"G52 X5 Y5 ; local system\nG152\nG30 P3 X0 Y0\nM2\n", "pcnc-mill"},
        {"G90 G17\nG28 K5 F50\nG46 X30 D17\nG0 X1 Y1\nM02\n", "iso-legacy-mill"},
        {"G0 G91 G28 U0 W0\nG94 G96 S100\nG77 X50 Z-20 F100\n", "fanuc-lathe-b"},
    };
    for (const Case& c : cases) {
        const auto d = detect_dialect(c.text);
        INFO(c.text);
        CHECK(d.dialect == c.dialect);
        CHECK_FALSE(d.reasons.empty());
    }
}

TEST_CASE("X and Z without Y is lathe evidence; a file with no evidence takes the default dialect and says so") {
    const auto mill = detect_dialect("G0 X1 Y2\n");
    CHECK(mill.dialect == "fanuc-mill");
    // fanuc-lathe-a.toml [detect]: `absent = "Y", given = ["X", "Z"]`, weight 2.
    const auto lathe = detect_dialect("G0 X1 Z2\n");
    CHECK(lathe.dialect == "fanuc-lathe-a");
    CHECK(lathe.evidence);
    // Only macro statements: nothing points anywhere. fanuc-mill is `[detect] default = true`.
    const auto none = detect_dialect("#1=5\n#2=#1+1\nM30\n");
    CHECK_FALSE(none.evidence);
    CHECK(none.dialect == "fanuc-mill");
    REQUIRE_FALSE(none.reasons.empty());
    CHECK(none.reasons.front().find("no dialect evidence") != std::string::npos);
    // The caller's fallback (the folder rule) wins over the registry default, with its reason.
    const auto folder = detect_dialect("#1=5\nM30\n", kerf::dialects::builtin_registry(),
                                       {"fanuc-lathe-a", "3 of the 3 other programs with evidence in its folder"});
    CHECK(folder.dialect == "fanuc-lathe-a");
    CHECK(folder.reasons.front().find("3 of the 3 other programs") != std::string::npos);
}

// Issue 12: `G65 P9724 W#23` passes argument W; it is no incremental Z. The Renishaw mill macros
// O09811/O09812 were read as lathe programs because of such words.
TEST_CASE("G65 argument letters are not axis evidence") {
    // Only G65 calls: U and W are arguments, so nothing in the file is evidence (before: U and W
    // scored 3 each for fanuc-lathe-a).
    const auto d = detect_dialect("O9811\nG65 P9724 U#21 W#23\nG65 P9726 U1. W2.\nM99\n");
    CHECK_FALSE(d.evidence);
    CHECK(d.dialect == "fanuc-mill");
    for (const kerf::grammar::Clue& c : d.clues) {
        INFO(c.dialect << " " << c.what);
        CHECK(c.what != "word U");
        CHECK(c.what != "word W");
    }
}

TEST_CASE("a user dialect's [detect] evidence makes it detectable") {
    kerf::dialects::Registry registry = kerf::dialects::builtin_registry();
    const auto errors = registry.add_text(R"(id = "user-lathe-b2"
name = "User lathe derived from system B"
base = "fanuc-lathe-b"
[detect]
inherit = true
codes = [ { code = "M213", weight = 9, proves = "M213 is this shop's live tool on" } ]
[[m]]
code = "M213"
function = "machine-builder-code"
en = "Live tool on"
ru = "Приводной инструмент вкл."
reference = "test"
)", "user.toml");
    INFO((errors.empty() ? std::string() : errors.front().message));
    REQUIRE(errors.empty());
    const auto d = detect_dialect("O1\nG0 X20. Z2.\nM213\nG1 Z-5. F100.\nM30\n", registry);
    CHECK(d.dialect == "user-lathe-b2");
    bool explained = false;
    for (const std::string& r : d.reasons) explained |= r.find("M213 is this shop's live tool on") != std::string::npos;
    CHECK(explained);
    // The built-in registry does not know it.
    CHECK(detect_dialect("O1\nG0 X20. Z2.\nM213\nM30\n").dialect != "user-lathe-b2");
}

// reference/README.md "Example files": `(DIALECT: <dialect id> [- machine options])` heads every
// example; a known id there decides, whatever the code below suggests.
TEST_CASE("a header comment naming a known dialect id is decisive") {
    const auto spinner = detect_dialect("(SOURCE: seed)\n(DIALECT: spinner-lathe-a - live tools)\nG0 X1 Y2\nM30\n");
    CHECK(spinner.dialect == "spinner-lathe-a");
    REQUIRE(spinner.reasons.size() == 1);
    CHECK(spinner.reasons[0] == "header comment at 2:1 names the dialect spinner-lathe-a (decisive)");
    // The evidence would say fanuc-lathe-a (G50 S, U/W); the header says ADV400.
    CHECK(detect_dialect("(DIALECT: adv400-lathe)\nG50 S2000\nG1 U-2 W-3\n").dialect == "adv400-lathe");
    CHECK(detect_dialect("( dialect:  pcnc-mill)\nG0 X1 Y1\n").dialect == "pcnc-mill");
}

TEST_CASE("a DIALECT comment that is no header, or names no known id, is not decisive") {
    // An unknown id: the evidence decides (Y words → mill).
    CHECK(detect_dialect("(DIALECT: heidenhain)\nG0 X1 Y2\n").dialect == "fanuc-mill");
    // After the first word the comment is about something else.
    CHECK(detect_dialect("G0 X1 Y2\n(DIALECT: fanuc-lathe-a)\nM30\n").dialect == "fanuc-mill");
    // The tag must lead the comment.
    CHECK(detect_dialect("(NOT DIALECT: fanuc-lathe-a)\nG0 X1 Y2\n").dialect == "fanuc-mill");
}

namespace {

// The rule of a `line` clue read line by line, as the SCHEMA says it: lines end at '\n' or '\r',
// leading spaces and tabs are not part of a line, each line counts once.
std::vector<std::uint32_t> naive_line_clue(std::string_view text, std::string_view pattern, bool prefix) {
    std::vector<std::uint32_t> out;
    for (std::size_t at = 0; at < text.size();) {
        std::size_t end = text.find_first_of("\r\n", at);
        if (end == std::string_view::npos) end = text.size();
        std::size_t begin = at;
        while (begin < end && (text[begin] == ' ' || text[begin] == '\t')) ++begin;
        const std::string_view line = text.substr(begin, end - begin);
        if (!line.empty() && (prefix ? line.starts_with(pattern) : line.find(pattern) != std::string_view::npos))
            out.push_back(static_cast<std::uint32_t>(begin));
        at = end + 1;
    }
    return out;
}

}  // namespace

TEST_CASE("detection: a line clue holds on the lines a line-by-line reading finds, once per line") {
    // The clues search the whole text once; random texts of the patterns' pieces, blanks and every
    // kind of line break must give the offsets the line-by-line rule gives.
    const std::vector<std::string> patterns = {"%@", ":=", "//", "N ", " X", "G1", "", "A", "::", "\tB"};
    const std::string alphabet = ":=/%@NG1AB X\t \r\n\n";
    std::mt19937 random(11);
    for (int round = 0; round < 3000; ++round) {
        std::string text;
        const std::size_t length = random() % 48;
        for (std::size_t i = 0; i < length; ++i) text += alphabet[random() % alphabet.size()];
        for (const std::string& pattern : patterns)
            for (const bool prefix : {true, false}) {
                INFO("text '" << text << "' pattern '" << pattern << "' prefix " << prefix);
                CHECK(kerf::grammar::detail::line_clue_offsets(text, pattern, prefix) == naive_line_clue(text, pattern, prefix));
            }
    }
    CHECK(kerf::grammar::detail::line_clue_offsets("  %@MACRO\n%@ x %@\nA %@\n", "%@", true) == std::vector<std::uint32_t>{2, 10});
    CHECK(kerf::grammar::detail::line_clue_offsets("  %@MACRO\n%@ x %@\nA %@\n", "%@", false) == std::vector<std::uint32_t>{2, 10, 18});
}
