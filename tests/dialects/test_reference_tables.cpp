// Cross-checks the built-in dialect tables against the reference specification in ../shared/reference:
// every G and M code listed in the tables of gcode-tables.md (§1–§6) and mcodes.md (§1, §2, §2.1, §2.2)
// must be defined in the dialect the table describes, by its spelling and by every alias the table
// gives, with non-empty English and Russian descriptions.
//
// The markdown is parsed at run time, so the test follows the reference when it changes. The floors
// below are the numbers of codes the tables held when this test was written: a parser that silently
// finds nothing (or loses a table) fails instead of passing vacuously.
// For Catch::TestEventListenerBase (the run-end summary across all sections).
#define CATCH_CONFIG_EXTERNAL_INTERFACES
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "dialects/dialect.hpp"

namespace fs = std::filesystem;
using kerf::dialects::CodeInfo;
using kerf::dialects::Dialect;

namespace {

const fs::path kReference = fs::path(KERF_SHARED_DIR) / "reference";

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

std::string trim(std::string s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos) return {};
    const auto last = s.find_last_not_of(" \t\r");
    return s.substr(first, last - first + 1);
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

// Section number ("1", "2.1") → body text up to the next "##"/"###" heading.
std::map<std::string, std::string> sections(const std::string& text) {
    static const std::regex heading(R"(^#{2,3} (\d+(?:\.\d+)?)\.? .*)");
    std::map<std::string, std::string> out;
    std::string* current = nullptr;
    for (const std::string& line : lines_of(text)) {
        std::smatch m;
        if (line.rfind("##", 0) == 0) {
            current = std::regex_match(line, m, heading) ? &out[m[1].str()] : nullptr;
            continue;
        }
        if (current) *current += line + "\n";
    }
    return out;
}

struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;

    int column(const std::string& name) const {
        for (std::size_t i = 0; i < header.size(); ++i)
            if (header[i] == name) return static_cast<int>(i);
        return -1;
    }
};

std::vector<std::string> split_row(const std::string& line) {
    std::string s = trim(line);
    if (!s.empty() && s.front() == '|') s.erase(0, 1);
    if (!s.empty() && s.back() == '|') s.pop_back();
    std::vector<std::string> cells;
    std::string cell;
    for (char c : s) {
        if (c == '|') {
            cells.push_back(trim(cell));
            cell.clear();
        } else {
            cell += c;
        }
    }
    cells.push_back(trim(cell));
    return cells;
}

// Markdown pipe tables of a section body: header row, separator row, data rows.
std::vector<Table> tables(const std::string& body) {
    static const std::regex separator(R"(^\|[-:| ]+\|\s*$)");
    std::vector<Table> out;
    bool in_table = false;
    for (const std::string& line : lines_of(body)) {
        if (line.empty() || line[0] != '|') {
            in_table = false;
            continue;
        }
        if (std::regex_match(line, separator)) continue;
        if (!in_table) {
            out.push_back(Table{split_row(line), {}});
            in_table = true;
        } else {
            out.back().rows.push_back(split_row(line));
        }
    }
    return out;
}

struct Spelling {
    std::string code;                   // as printed: "G12.1"
    std::vector<std::string> aliases;   // "(G112)" after it
};

// The codes of one table cell: "G00", "G12.1 (G112)", "G50.2 (250 sic)", "G55–G59", "G25 / G26",
// "M301, M302", "G02/G03". OCR remarks such as "(`GO`, `GOO` in OCR)" hold no digits and are ignored.
std::vector<Spelling> expand(std::string cell, char letter) {
    std::vector<Spelling> out;
    std::string text;
    for (char c : cell)
        if (c != '`') text += c;
    const std::string L(1, letter);
    // Ranges (en dash or hyphen).
    const std::regex range("\\b" + L + "(\\d+)\\s*(?:\xE2\x80\x93|-)\\s*" + L + "(\\d+)\\b");
    for (std::smatch m; std::regex_search(text, m, range);) {
        const int from = std::stoi(m[1].str()), to = std::stoi(m[2].str());
        const std::size_t width = m[1].length();
        for (int n = from; n <= to; ++n) {
            std::string digits = std::to_string(n);
            if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
            out.push_back({L + digits, {}});
        }
        text = m.prefix().str() + " " + m.suffix().str();
    }
    // A code followed by a parenthesised alias; the alias may lack the letter ("250 sic").
    const std::regex aliased("\\b(" + L + "\\d+(?:\\.\\d)?)\\s*\\(\\s*" + L + "?(\\d+(?:\\.\\d)?)(?:\\s+sic)?\\s*\\)");
    for (std::smatch m; std::regex_search(text, m, aliased);) {
        out.push_back({m[1].str(), {L + m[2].str()}});
        text = m.prefix().str() + " " + m.suffix().str();
    }
    const std::regex plain("\\b" + L + "\\d+(?:\\.\\d)?\\b");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), plain); it != std::sregex_iterator(); ++it)
        out.push_back({it->str(), {}});
    return out;
}

bool has_cyrillic(const std::string& s) {
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
        const auto a = static_cast<unsigned char>(s[i]), b = static_cast<unsigned char>(s[i + 1]);
        if ((a == 0xD0 || a == 0xD1) && b >= 0x80 && b <= 0xBF) return true;   // U+0400–U+047F
    }
    return false;
}

struct Tally {
    std::map<std::string, int> per_table;                          // table label → codes checked
    std::map<std::string, std::set<std::string>> per_dialect;      // dialect id → spellings checked
    std::map<std::string, std::set<const CodeInfo*>> entries;      // dialect id → distinct entries checked
};

// Everything checked in this run, over all sections; printed when the run ends.
Tally& run_total() {
    static Tally total;
    return total;
}

// Requires `spelling` (and its aliases, resolving to the same entry) in `dialect_id`, with descriptions.
void check_code(Tally& tally, const std::string& table, const std::string& dialect_id, const Spelling& spelling) {
    INFO("table " << table << ", dialect " << dialect_id << ", code " << spelling.code);
    const Dialect* d = kerf::dialects::builtin_registry().find(dialect_id);
    REQUIRE(d != nullptr);
    const CodeInfo* info = d->code(spelling.code);
    REQUIRE(info != nullptr);
    CHECK(info->letter == spelling.code[0]);
    for (const std::string& alias : spelling.aliases) {
        INFO("alias " << alias);
        const CodeInfo* by_alias = d->code(alias);
        REQUIRE(by_alias != nullptr);
        REQUIRE(by_alias == info);
    }
    REQUIRE_FALSE(info->en.empty());
    REQUIRE_FALSE(info->ru.empty());
    REQUIRE(has_cyrillic(info->ru));
    ++tally.per_table[table];
    tally.per_dialect[dialect_id].insert(spelling.code);
    tally.entries[dialect_id].insert(info);
    ++run_total().per_table[table];
    run_total().per_dialect[dialect_id].insert(spelling.code);
    run_total().entries[dialect_id].insert(info);
}

std::string summary(const Tally& tally) {
    std::ostringstream out;
    out << "reference codes checked, per table:";
    for (const auto& [table, n] : tally.per_table) out << "\n  " << table << ": " << n;
    out << "\nper dialect (distinct codes, of the dialect's total):";
    for (const auto& [id, codes] : tally.entries) {
        const Dialect* d = kerf::dialects::builtin_registry().find(id);
        out << "\n  " << id << ": " << codes.size() << " of " << (d ? d->codes().size() : 0);
    }
    return out.str();
}

struct SummaryListener : Catch::TestEventListenerBase {
    using TestEventListenerBase::TestEventListenerBase;
    void testRunEnded(const Catch::TestRunStats&) override {
        if (!run_total().per_table.empty()) std::cout << "\n[reference tables, whole run] " << summary(run_total()) << "\n";
    }
};
CATCH_REGISTER_LISTENER(SummaryListener)

// Checks every code of `column` of every table in `body` against the dialects.
int check_tables(Tally& tally, const std::string& label, const std::string& body, const std::string& column,
                 char letter, const std::vector<std::string>& dialect_ids) {
    int codes = 0;
    int tables_seen = 0;
    for (const Table& t : tables(body)) {
        const int col = t.column(column);
        if (col < 0) continue;
        ++tables_seen;
        for (const auto& row : t.rows) {
            REQUIRE(static_cast<int>(row.size()) > col);
            for (const Spelling& s : expand(row[static_cast<std::size_t>(col)], letter)) {
                for (const std::string& id : dialect_ids) check_code(tally, label, id, s);
                ++codes;
            }
        }
    }
    INFO(label);
    REQUIRE(tables_seen >= 1);
    return codes;
}

}  // namespace

TEST_CASE("cell expansion of the reference tables") {
    auto spellings = [](const std::string& cell, char letter) {
        std::vector<std::string> out;
        for (const Spelling& s : expand(cell, letter)) {
            out.push_back(s.code);
            for (const std::string& a : s.aliases) out.push_back("=" + a);
        }
        std::sort(out.begin(), out.end());
        return out;
    };
    using V = std::vector<std::string>;
    CHECK(spellings("G00", 'G') == V{"G00"});
    CHECK(spellings("G12.1 (G112)", 'G') == V{"=G112", "G12.1"});
    CHECK(spellings("G50.2 (250 sic)", 'G') == V{"=G250", "G50.2"});
    CHECK(spellings("G55\xE2\x80\x93G59", 'G') == V{"G55", "G56", "G57", "G58", "G59"});
    CHECK(spellings("G25 / G26", 'G') == V{"G25", "G26"});
    CHECK(spellings("G02/G03", 'G') == V{"G02", "G03"});
    CHECK(spellings("M301, M302", 'M') == V{"M301", "M302"});
    CHECK(spellings("M203 / M204", 'M') == V{"M203", "M204"});
    CHECK(spellings("G00 (`GO`, `GOO` in OCR)", 'G') == V{"G00"});
    CHECK(spellings("\xE2\x80\x93", 'G').empty());
}

TEST_CASE("reference tables: every listed code is in its dialect") {
    const fs::path gtables = kReference / "gcode-tables.md";
    const fs::path mtables = kReference / "mcodes.md";
    if (!fs::exists(gtables) || !fs::exists(mtables)) {
        WARN("reference folder " << kReference.string()
                                 << " is absent: the reference-table cross-check was not run");
        SUCCEED("skipped: no reference tables");
        return;
    }
    const auto g = sections(read_text(gtables));
    const auto m = sections(read_text(mtables));
    for (const char* s : {"1", "2", "3", "4", "5", "6"}) {
        INFO("gcode-tables.md section " << s);
        REQUIRE(g.count(s) == 1);
    }
    for (const char* s : {"1", "2", "2.1", "2.2"}) {
        INFO("mcodes.md section " << s);
        REQUIRE(m.count(s) == 1);
    }

    Tally tally;
    const std::vector<std::string> spinner = {"spinner-lathe-a", "spinner-lathe-b", "spinner-lathe-c"};

    SECTION("gcode-tables.md §1: FANUC lathe systems A/B/C and the SPINNER rows") {
        static const std::set<std::string> kSpinnerG = {"G38", "G138", "G238", "G380", "G384"};
        const std::vector<std::pair<std::string, char>> columns = {{"A", 'a'}, {"B", 'b'}, {"C", 'c'}};
        int rows = 0, spinner_codes = 0, fanuc_codes = 0;
        for (const Table& t : tables(g.at("1"))) {
            if (t.column("A") < 0) continue;
            REQUIRE(t.column("B") >= 0);
            REQUIRE(t.column("C") >= 0);
            for (const auto& row : t.rows) {
                ++rows;
                for (const auto& [name, suffix] : columns) {
                    const auto col = static_cast<std::size_t>(t.column(name));
                    REQUIRE(row.size() > col);
                    for (const Spelling& s : expand(row[col], 'G')) {
                        if (kSpinnerG.count(s.code)) {
                            check_code(tally, "gcode §1 SPINNER", std::string("spinner-lathe-") + suffix, s);
                            // A SPINNER code must not leak into the plain FANUC dialect.
                            const Dialect* base =
                                kerf::dialects::builtin_registry().find(std::string("fanuc-lathe-") + suffix);
                            REQUIRE(base != nullptr);
                            INFO(s.code << " in fanuc-lathe-" << suffix);
                            REQUIRE(base->code(s.code) == nullptr);
                            ++spinner_codes;
                        } else {
                            check_code(tally, std::string("gcode §1 column ") + name,
                                       std::string("fanuc-lathe-") + suffix, s);
                            // The combined SPINNER dialects keep every code of their base.
                            check_code(tally, "gcode §1 base in spinner", std::string("spinner-lathe-") + suffix, s);
                            ++fanuc_codes;
                        }
                    }
                }
            }
        }
        // G100/G101 are described in the notes under the table, not in it.
        const std::string& body = g.at("1");
        REQUIRE(body.find("G100 and G101") != std::string::npos);
        for (const char* code : {"G100", "G101"})
            for (const std::string& id : spinner) {
                check_code(tally, "gcode §1 SPINNER", id, Spelling{code, {}});
                ++spinner_codes;
            }
        // 70 rows; columns A/B/C hold 61/65/65 FANUC codes (A has four "–" cells);
        // 5 SPINNER rows × 3 columns + G100/G101 × 3 dialects.
        REQUIRE(rows >= 70);
        REQUIRE(tally.per_table["gcode §1 column A"] >= 61);
        REQUIRE(tally.per_table["gcode §1 column B"] >= 65);
        REQUIRE(tally.per_table["gcode §1 column C"] >= 65);
        REQUIRE(spinner_codes >= 21);
        REQUIRE(fanuc_codes >= 191);
    }

    SECTION("gcode-tables.md §2: adv400-mill") {
        const int n = check_tables(tally, "gcode §2", g.at("2"), "Code", 'G', {"adv400-mill"});
        REQUIRE(tally.per_dialect["adv400-mill"].count("G55") == 1);   // the G55–G59 range row
        REQUIRE(tally.per_dialect["adv400-mill"].count("G59") == 1);
        REQUIRE(n >= 38);
    }

    SECTION("gcode-tables.md §3: adv400-lathe") {
        const int n = check_tables(tally, "gcode §3", g.at("3"), "Code", 'G', {"adv400-lathe"});
        for (const char* code : {"G25", "G26", "G41", "G42"}) {   // "G25 / G26", "G41 / G42" rows
            INFO(code);
            REQUIRE(tally.per_dialect["adv400-lathe"].count(code) == 1);
        }
        REQUIRE(n >= 32);
    }

    SECTION("gcode-tables.md §4: pcnc-mill") {
        const int n = check_tables(tally, "gcode §4", g.at("4"), "Code", 'G', {"pcnc-mill"});
        for (const char* code : {"G0", "G1", "G54", "G59"}) {
            INFO(code);
            REQUIRE(tally.per_dialect["pcnc-mill"].count(code) == 1);
        }
        REQUIRE(n >= 16);
    }

    SECTION("gcode-tables.md §5: seed 003 lathe part (fanuc-lathe-a) and machining-centre part (fanuc-mill)") {
        const std::string& body = g.at("5");
        const auto split = body.find("Machining-centre part");
        REQUIRE(split != std::string::npos);
        const int lathe = check_tables(tally, "gcode §5 lathe", body.substr(0, split), "Code", 'G', {"fanuc-lathe-a"});
        const int mill = check_tables(tally, "gcode §5 mill", body.substr(split), "Code", 'G', {"fanuc-mill"});
        REQUIRE(lathe >= 29);
        REQUIRE(mill >= 8);
    }

    SECTION("gcode-tables.md §6: iso-legacy-mill") {
        const int n = check_tables(tally, "gcode §6", g.at("6"), "Code", 'G', {"iso-legacy-mill"});
        for (const char* code : {"G00", "G02", "G03", "G90", "G91"}) {   // "G02 / G03", "G90 / G91" rows
            INFO(code);
            REQUIRE(tally.per_dialect["iso-legacy-mill"].count(code) == 1);
        }
        REQUIRE(n >= 20);
    }

    SECTION("mcodes.md §1: adv400-mill and adv400-lathe") {
        const int n = check_tables(tally, "mcodes §1", m.at("1"), "Code", 'M', {"adv400-mill", "adv400-lathe"});
        REQUIRE(n >= 12);
    }

    SECTION("mcodes.md §2, §2.1, §2.2: the SPINNER M codes in spinner-lathe-a/b/c") {
        const int table = check_tables(tally, "mcodes §2", m.at("2"), "Code", 'M', spinner);
        const int extra = check_tables(tally, "mcodes §2.1", m.at("2.1"), "Code", 'M', spinner);
        const int c_axis = check_tables(tally, "mcodes §2.2", m.at("2.2"), "Code", 'M', spinner);
        for (const char* code : {"M203", "M204", "M301", "M302", "M454", "M455", "M472", "M473"}) {
            INFO(code);
            REQUIRE(tally.per_dialect["spinner-lathe-a"].count(code) == 1);
        }
        REQUIRE(table >= 82);
        REQUIRE(extra >= 28);
        REQUIRE(c_axis >= 10);
    }

    INFO(summary(tally));
    REQUIRE_FALSE(tally.per_table.empty());
}
