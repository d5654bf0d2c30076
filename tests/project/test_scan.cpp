// The program index's cheap scan (project/scan.hpp) against the parser and binder: the same
// programs (number, index in the file, byte range) on every reference example and corpus file,
// under every dialect's lexical rules; and the constructs the scan must read as the grammar does.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <filesystem>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "ast/typed.hpp"
#include "grammar/parse.hpp"
#include "project/scan.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using kerf::project::ScannedProgram;
using kerf::project::ScanRules;
using kerf::project::scan_programs;

namespace {

// The numbered programs as the parser and binder split them, in the scan's terms (no comment).
std::vector<ScannedProgram> parsed_programs(const std::string& text, const kerf::dialects::Dialect& dialect) {
    kerf::ast::SyntaxTree tree = kerf::grammar::parse(text, dialect.lexical);
    const kerf::ast::TypedFile typed = kerf::ast::TypedFile::bind(tree, dialect);
    std::vector<ScannedProgram> out;
    const auto begin_of = [&](std::uint32_t block) {
        return block < tree.block_count() ? tree.blocks[block].begin : static_cast<std::uint32_t>(text.size());
    };
    for (std::uint32_t i = 0; i < typed.programs().size(); ++i) {
        const kerf::ast::Program& p = typed.programs()[i];
        if (!p.number) continue;
        out.push_back({*p.number, i, begin_of(p.first_block), begin_of(p.end_block), {}});
    }
    return out;
}

std::string describe(const std::vector<ScannedProgram>& programs) {
    std::string s;
    for (const ScannedProgram& p : programs)
        s += fmt::format("O{} #{} [{},{}) ", p.number, p.program_index, p.begin, p.end);
    return s;
}

bool same(const std::vector<ScannedProgram>& a, const std::vector<ScannedProgram>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].number != b[i].number || a[i].program_index != b[i].program_index || a[i].begin != b[i].begin ||
            a[i].end != b[i].end)
            return false;
    return true;
}

void check_agrees(const std::string& text, const kerf::dialects::Dialect& dialect) {
    const std::vector<ScannedProgram> scanned = scan_programs(text, ScanRules::of(dialect.lexical));
    const std::vector<ScannedProgram> parsed = parsed_programs(text, dialect);
    INFO("scan:   " << describe(scanned));
    INFO("parser: " << describe(parsed));
    CHECK(same(scanned, parsed));
}

const kerf::dialects::Dialect& fanuc_mill() { return *kerf::dialects::builtin_registry().find("fanuc-mill"); }

}  // namespace

TEST_CASE("scan: every reference example and corpus file splits into the parser's programs, in every dialect") {
    const auto files = kerf::test::shared_files_or_warn("the scan was not compared with the parser on ../shared");
    if (files.empty()) return;
    REQUIRE(files.size() >= 148);   // 88 examples + 60 corpus files
    const auto& registry = kerf::dialects::builtin_registry();
    for (const fs::path& file : files) {
        const std::string text = kerf::test::read_text(file);
        for (const std::string& id : registry.ids()) {
            INFO(file.string() << " as " << id);
            check_agrees(text, *registry.find(id));
        }
    }
}

TEST_CASE("scan: the corpus's punch file holds sixteen programs, O0100 its O line twice") {
    const fs::path macro = fs::path(KERF_SHARED_DIR) / "corpus" / "macro";
    if (!fs::is_directory(macro)) {
        WARN("../shared is not there: the corpus programs were not scanned");
        return;
    }
    // The O lines of ALL-PROG.TXT (lines 2, 8, 124, ... 480 of the file, between '%' on lines 1 and
    // 529), and the four programs that start after an M99 on the same line (lines 36, 64, 92, 120:
    // `M99O0810(Z_AXIS)`, O0820, O0900, O0300; issue 12).
    std::vector<std::int64_t> numbers;
    for (const ScannedProgram& p : scan_programs(kerf::test::read_text(macro / "zhituaishangc__SK7420_750_N12_FANUC_HuBeiHengLong__ALL-PROG.TXT")))
        numbers.push_back(p.number);
    CHECK(numbers == std::vector<std::int64_t>{1, 800, 810, 820, 900, 300, 400, 500, 8000, 8100, 8300, 8400, 100, 600, 8200, 8501});
    // 'O0100(MAIN)' on lines 2 and 3: two programs, the first of them one block long.
    const std::vector<ScannedProgram> o100 = scan_programs(kerf::test::read_text(macro / "zhituaishangc__SK7420_750_N12_FANUC_HuBeiHengLong__O0100"));
    REQUIRE(o100.size() == 2);
    CHECK(o100[0].number == 100);
    CHECK(o100[1].number == 100);
    CHECK(o100[0].comment == "MAIN");
}

TEST_CASE("scan: O lines in their forms, and what does not start a program") {
    const char* const cases[] = {
        "o1000\nG0X1\nM99\nO 2000 (SPACE)\nG0X1\nM99\n/O3000\nM99\n(C) O4000\nM99\nO5000.\nM99\nO60.5\nM99\nG0X1;O7000;M99\n",
        ":1000\nG0 X1.\nM99\n",
        "%\nO0001\nG0 X1\nM30\n%\nO0002\nM99\n",                 // the tail after the closing '%' is not read
        "%O0003( 300-11 MILL FIXTURE)\n()\nG0 X1.\nM30\n%\n",     // '%' and O on one line
        "\xEF\xBB\xBF" "O0012 (BOM)\nM30\n",
        "\xEF\xBB\xBF" "00012 (BOM, O as zero: not after the BOM)\nM30\n",
        "00018 (O written as zero)\nM98 P41001\nM30\n00019\n/00020\n000180\n0001.\nM99\n",
        "(HEADER)\nG0 X1\nO0100 (MAIN)\nO0100 (MAIN)\nM30\n",     // code before the first O; the O line twice
        "N10 O1000\nG0 X1\n",                                     // an O word after N starts nothing
        "(O1234 in a comment)\nX1 (unclosed\nO2\n",
        "O1;;O2\nO3;M99\n",
        "",
        "\n\n",
    };
    for (const char* text : cases) {
        INFO(text);
        check_agrees(text, fanuc_mill());
        check_agrees(text, *kerf::dialects::builtin_registry().find("adv400-mill"));   // ';;' line comments
        check_agrees(text, *kerf::dialects::builtin_registry().find("pcnc-mill"));     // ';' a comment
    }
}

TEST_CASE("scan: numbers, ranges and first comments as written") {
    const std::string text = "%\nO1000 (PROBE CYCLE)\nG0 X1\nM99\nO2000\n(SECOND)\n(NOT THIS)\nG0 X1\n(NOR THIS)\nM99\n%\n";
    const std::vector<ScannedProgram> p = scan_programs(text);
    REQUIRE(p.size() == 2);
    CHECK(p[0].number == 1000);
    CHECK(p[0].program_index == 0);
    CHECK(p[0].begin == 2);                                   // after "%\n"
    CHECK(p[0].end == text.find("O2000"));
    CHECK(p[0].comment == "PROBE CYCLE");
    CHECK(p[1].number == 2000);
    CHECK(p[1].end == text.rfind('%'));                       // the closing '%' ends it
    CHECK(p[1].comment == "SECOND");
    // Programs without a number count for the index in the file but are not listed.
    const std::vector<ScannedProgram> q = scan_programs("G0 X1\nM30\nO5\nM99\n");
    REQUIRE(q.size() == 1);
    CHECK(q[0].program_index == 1);
}

// Random texts from the pieces the scan treats specially, many times over: any disagreement with
// the parser is printed with the text.
TEST_CASE("scan: random texts of O lines, '%', comments, ';' and block deletes agree with the parser") {
    const char* const pieces[] = {"O1", "o2", "O 3", ":4", "%", "%O5", "% (C) O6", "(C)", "(UNCLOSED", "/O7", "/2 O8",
                                  "N10 O9", "G0 X1", "00012", "0001.", "000123456", "#1=2", ";", ";;", "::", "O1.5",
                                  "O#1", "M99", "", "  ", "\r", "\xEF\xBB\xBF", "(A(B)C)", "X1;O10", "G1(C);O11",
                                  "OO12", "O?", "ORIGIN", "OR", "O1.2.", "O-5", "O1,5", "MO6", "DPRNT[X;Y]", "(;)", "O",
                                  "0", "IF[#1EQ1]GOTO5", "N10...", "O1X2"};
    std::mt19937 random(2026);
    std::uniform_int_distribution<std::size_t> piece(0, std::size(pieces) - 1), count(0, 3), lines(1, 12);
    const auto& registry = kerf::dialects::builtin_registry();
    const int rounds = std::getenv("KERF_SCAN_ROUNDS") ? std::atoi(std::getenv("KERF_SCAN_ROUNDS")) : 3000;
    for (int round = 0; round < rounds; ++round) {
        std::string text;
        for (std::size_t l = lines(random); l > 0; --l) {
            for (std::size_t n = count(random); n > 0; --n) text += std::string(pieces[piece(random)]) + (n % 2 ? "" : " ");
            text += "\n";
        }
        INFO(text);
        for (const char* id : {"fanuc-lathe-a", "adv400-mill", "pcnc-mill"}) check_agrees(text, *registry.find(id));
    }
}
