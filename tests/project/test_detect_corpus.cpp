// Dialect detection on the real programs of ../shared/corpus (issue 12 "Dialect detection"): every
// file whose MANIFEST row names its machine is detected as that machine's dialect, through the
// project layer as `kerf check` resolves it (header, [detect] evidence of the registry, folder rule).
//
// Expected dialects, from corpus/MANIFEST.md: the `dialect` column where it is fanuc-lathe-a or
// fanuc-mill (the collector's reading of each program, checked against the notable column: G50/U/W/
// G70–G76 lathes, G43/M06/G81 mills); and the macro-b rows whose notes name the machine: the Renishaw
// Inspection Plus / MRZP macros "for Haas NGC" (machining centres: G31 probing in X/Y/Z), the Haas
// VF-3 job, the Haas vice-centre macro (mills), and the Fusion lathe finishing program 2001.nc.
// Rows marked `other` (Fagor, Syntec, LinuxCNC, P-code source) and macros whose notes name no
// machine (Brother dispatcher, thread-grinder punch-out, versabuilt vise macros) are not pinned.
//
// Issue 15: the programs written for Haas controls whose text shows it are haas-mill / haas-lathe
// (the MANIFEST's dialect column predates the Haas dialects and says "Haas programs are counted as
// Fanuc-family"): the four enier290188 lathe jobs (one-block G71 with D, G76 with K/D, G75 with I),
// the Renishaw macros "for Haas NGC" (G103, G154, #10000+ variables), the p2g vice-centre macro
// (M97, G103), the Versabuilt vise macro for Haas NGC. Haas programs without Haas-only codes (the
// enier290188 mill jobs and o20013, the aaronrzt VF-3 job) stay FANUC: nothing in them says Haas.
// The programs of other controls are pinned to their foreign profile (dialects/data/foreign-*.toml).
#include <catch2/catch.hpp>

#include <filesystem>
#include <map>
#include <regex>
#include <string>

#include "project/workspace.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf;

namespace {

const std::map<std::string, std::string>& named_macros() {
    static const std::map<std::string, std::string> m = {
        {"macro/jpaullee__renishaw_macros__O09023_RENISHAW_Storm.nc", "haas-mill"},
        {"macro/jpaullee__renishaw_macros__O09724_RENISHAW_Storm.nc", "haas-mill"},
        {"macro/jpaullee__renishaw_macros__O09811_RENISHAW_Storm.nc", "haas-mill"},
        {"macro/jpaullee__renishaw_macros__O09812_RENISHAW_Storm.nc", "haas-mill"},
        {"macro/jpaullee__renishaw_macros__O09985(_SINGLE_AXIS_MRZP_).nc", "haas-mill"},
        {"macro/jpaullee__renishaw_macros__O09994(_B_AXIS_TILT_AND_C_AXIS_ROT_AXIS_MRZP_).nc", "haas-mill"},
        {"macro/aaronrzt__SistemasTecnologias4.0__VF3.txt", "fanuc-mill"},
        {"macro/0x5ac__p2g__vicecenter.nc", "haas-mill"},
        {"macro/aaronrzt__SistemasTecnologias4.0__2001.nc", "fanuc-lathe-a"},
        {"macro/versabuilt__Gcode__nitro-haas-ngc-9002.nc", "haas-mill"},
        {"macro/versabuilt__Gcode__r2c-focas-9002.nc", "fanuc-mill"},
    };
    return m;
}

// The MANIFEST's Haas lathe rows ("Haas lathe: single-block G71 (D word) ..."), read as haas-lathe.
const std::map<std::string, std::string>& haas_lathes() {
    static const std::map<std::string, std::string> m = {
        {"lathe/enier290188__cnc__lathe_hp_2.nc", "haas-lathe"},
        {"lathe/enier290188__cnc__round_head_plug.nc", "haas-lathe"},
        {"lathe/enier290188__cnc__valve.nc", "haas-lathe"},
        {"lathe/enier290188__cnc__weld_pin.nc", "haas-lathe"},
    };
    return m;
}

}  // namespace

TEST_CASE("every corpus file whose MANIFEST row names its machine is detected as that dialect") {
    const fs::path corpus = fs::path(KERF_SHARED_DIR) / "corpus";
    if (!fs::exists(corpus / "MANIFEST.md")) {
        WARN("../shared/corpus is absent: skipped");
        return;
    }
    const std::string manifest = test::read_text(corpus / "MANIFEST.md");
    const std::regex row(R"(^\| `([^`]+)` \|[^|]*\|[^|]*\|[^|]*\|[^|]*\| ([a-z0-9-]+) \|)", std::regex::multiline);
    std::map<std::string, std::string> expected;
    for (auto it = std::sregex_iterator(manifest.begin(), manifest.end(), row); it != std::sregex_iterator(); ++it) {
        const std::string dialect = (*it)[2].str();
        if (dialect == "fanuc-lathe-a" || dialect == "fanuc-mill") expected[(*it)[1].str()] = dialect;
    }
    for (const auto& [file, dialect] : named_macros()) expected[file] = dialect;
    for (const auto& [file, dialect] : haas_lathes()) expected[file] = dialect;
    // 22 lathe files, 14 Fanuc mill files, 2 Fanuc cam-large files (MANIFEST.md), 11 named macros.
    CHECK(expected.size() == 49);

    project::Workspace ws;
    int right = 0;
    for (const auto& [file, dialect] : expected) {
        const fs::path path = corpus / file;
        const project::ReadResult read = ws.read(path);
        REQUIRE(read.text);
        const project::Resolved r = ws.resolve(path, *read.text);
        std::string why = r.choice.why;
        for (const std::string& line : r.choice.evidence) why += "\n" + line;
        INFO(file << ": " << why);
        CHECK(r.choice.id == dialect);
        right += r.choice.id == dialect;
    }
    CHECK(right == static_cast<int>(expected.size()));
}

// The folder rule (dialects/SCHEMA.md [detect]): a program without evidence (a macro of statements
// only) takes the dialect most of the other programs of its folder were detected as, and says so;
// alone in a folder it takes the registry's default (fanuc-mill) and says that.
TEST_CASE("a file without evidence takes its folder's dialect") {
    const fs::path dir = test::fresh_folder("detect-folder");
    const std::string lathe = "O1\nG50 S2000\nG96 S200 M3\nG0 X50. Z2.\nG1 U-2. W-3. F0.2\nM30\n";
    test::write_text(dir / "O0001.nc", lathe);
    test::write_text(dir / "O0002.nc", lathe);
    test::write_text(dir / "O0003.nc", "O3\nG0 G90 G17 X0 Y0\nG43 H1 Z50.\nM06\nM30\n");   // a mill
    const fs::path macro = test::write_text(dir / "O9000.nc", "O9000\n#1=#2+1\n#100=#1\nM99\n");
    const fs::path alone = test::write_text(dir / "alone" / "O9001.nc", "O9001\n#1=#2+1\nM99\n");
    project::Workspace ws;
    const project::Resolved r = ws.resolve(macro, test::read_text(macro));
    const project::Resolved a = ws.resolve(alone, test::read_text(alone));
    fs::remove_all(dir);
    CHECK(r.choice.id == "fanuc-lathe-a");
    CHECK(r.choice.no_evidence);
    REQUIRE_FALSE(r.choice.evidence.empty());
    CHECK(r.choice.evidence.front().find("2 of the 3 other programs with evidence in its folder") != std::string::npos);
    CHECK(a.choice.id == "fanuc-mill");
    CHECK(a.choice.no_evidence);
}

// Issue 15: the programs of other controls are recognised by their profile's evidence, which
// outweighs every dialect's; the project layer hands that to `kerf check` (one K2009 finding).
TEST_CASE("the corpus programs of other controls are detected as such") {
    const fs::path corpus = fs::path(KERF_SHARED_DIR) / "corpus";
    if (!fs::exists(corpus / "MANIFEST.md")) {
        WARN("../shared/corpus is absent: skipped");
        return;
    }
    const std::map<std::string, std::string> foreign = {
        {"macro/Warcorer__macro-syil-22ma__O8000", "foreign-syntec"},
        {"mill/nwpablodeveloper__cifo-cnc__224.nc", "foreign-fagor"},
        {"macro/iSorp__macro-executor__test.src", "foreign-macro-executor"},
        {"cam-large/Epictetzu__GCodePosts__NozzleStepdownADOC_OP1.nc", "foreign-grbl"},
    };
    project::Workspace ws;
    for (const auto& [file, id] : foreign) {
        const fs::path path = corpus / file;
        const project::ReadResult read = ws.read(path);
        REQUIRE(read.text);
        const project::Resolved r = ws.resolve(path, *read.text);
        INFO(file);
        REQUIRE(r.choice.foreign);
        CHECK(r.choice.foreign->id == id);
        CHECK(r.choice.foreign->first.line > 0);
    }
    // A FANUC program is not foreign (the LinuxCNC-flavoured tiger.nc writes only FANUC-compatible words).
    const fs::path tiger = corpus / "cam-large/CauldronDevelopmentLLC__CAMotics__tiger.nc";
    const project::ReadResult read = ws.read(tiger);
    REQUIRE(read.text);
    CHECK_FALSE(ws.resolve(tiger, *read.text).choice.foreign);
}

// Issue 15: the evidence that tells Haas from FANUC is explained clue by clue.
TEST_CASE("detection says why a program is Haas") {
    const fs::path corpus = fs::path(KERF_SHARED_DIR) / "corpus";
    if (!fs::exists(corpus / "MANIFEST.md")) {
        WARN("../shared/corpus is absent: skipped");
        return;
    }
    project::Workspace ws;
    const fs::path path = corpus / "macro/versabuilt__Gcode__nitro-haas-ngc-9002.nc";
    const project::ReadResult read = ws.read(path);
    REQUIRE(read.text);
    const project::Resolved r = ws.resolve(path, *read.text);
    std::string why;
    for (const std::string& line : r.choice.evidence) why += line + "\n";
    INFO(why);
    CHECK(r.choice.id == "haas-mill");
    CHECK(why.find("G103 limits block look-ahead: a Haas code") != std::string::npos);
    CHECK(why.find("Haas NGC numbers of the general-purpose variables") != std::string::npos);
    CHECK(why.find("the header names a Haas machine or control") != std::string::npos);
}
