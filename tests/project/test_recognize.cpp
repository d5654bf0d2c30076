// Recognising programs by content (project/recognize.hpp): the corpus's 60 programs whatever their
// names, and none of the files a program folder holds beside them (manifests, READMEs, pictures,
// archives, configuration, scripts).
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "project/recognize.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using kerf::project::recognize_program;

namespace {

bool program(std::string_view name, std::string_view text) { return recognize_program(name, text).program; }

std::string head_of(const fs::path& file) {
    std::string text = kerf::test::read_text(file);
    if (text.size() > kerf::project::kRecognitionHead) text.resize(kerf::project::kRecognitionHead);
    return text;
}

}  // namespace

TEST_CASE("recognise: every corpus program, by its content where the name says nothing") {
    const fs::path corpus = fs::path(KERF_SHARED_DIR) / "corpus";
    if (!fs::is_directory(corpus)) {
        WARN("../shared is not there: recognition of the corpus not checked");
        return;
    }
    std::size_t programs = 0;
    for (const auto& e : fs::recursive_directory_iterator(corpus)) {
        if (!e.is_regular_file()) continue;
        const kerf::project::Recognition r = recognize_program(e.path().filename().string(), head_of(e.path()));
        INFO(e.path().string() << ": " << r.reason);
        if (e.path().filename() == "MANIFEST.md") {
            CHECK_FALSE(r.program);   // prose and tables, though it quotes G-code words
        } else {
            CHECK(r.program);
            ++programs;
        }
    }
    CHECK(programs == 60);
    // The files issue 12 names: no extension and a comment first, '%O0003(' first, '.src', Syntec '%@MACRO'.
    for (const char* name : {"lathe/MechatronicsCherepanovMA__CNCLearn__205", "lathe/MechatronicsCherepanovMA__CNCLearn__220",
                             "lathe/MechatronicsCherepanovMA__CNCLearn__240", "mill/mikemacfarland__Doosan-DNM-5700__O0003",
                             "macro/iSorp__macro-executor__test.src", "macro/Warcorer__macro-syil-22ma__O8000"}) {
        const kerf::project::Recognition r = recognize_program(fs::path(name).filename().string(), head_of(corpus / name));
        INFO(name << ": " << r.reason);
        CHECK(r.program);
        CHECK(r.reason.starts_with("content: "));
    }
}

TEST_CASE("recognise: the project's own documents and sources are not programs") {
    const fs::path root(KERF_SOURCE_DIR);
    for (const char* name : {"README.md", "ARCHITECTURE.md", "docs/rules.md", "docs/fmt.md", "Makefile", "CMakeLists.txt",
                             "dialects/data/fanuc-mill.toml", "machine/SCHEMA.md", "project/scan.cpp", "bench/gen_mill.py",
                             "docs/check-json.schema.json", "scripts/run-examples.sh"}) {
        const kerf::project::Recognition r = recognize_program(name, head_of(root / name));
        INFO(name << ": " << r.reason);
        CHECK_FALSE(r.program);
    }
    for (const char* name : {"examples/lathe-shaft.nc", "examples/mill-bolt-circle.nc", "examples/defects.nc"}) {
        INFO(name);
        CHECK(program(name, head_of(root / name)));
    }
}

TEST_CASE("recognise: binaries, pictures and archives by their bytes, whatever their names") {
    CHECK(recognize_program("O1000", "").reason == "empty file");
    CHECK(recognize_program("part.nc", std::string("\x89PNG\r\n\x1a\n", 8)).reason == "binary: PNG image");
    CHECK(recognize_program("x", "%PDF-1.7\n%...\n").reason == "binary: PDF document");   // starts with '%' as programs do
    CHECK(recognize_program("x.nc", std::string("PK\x03\x04", 4)).reason.starts_with("binary: ZIP"));
    CHECK(recognize_program("O1", std::string("O1\0\0", 4)).reason == "binary: a NUL byte at offset 2");
    CHECK(recognize_program("x", "\x01\x02\x03\x04 G01 X1.\n").reason.starts_with("binary: 4 control bytes"));
    // Text with a UTF-16 BOM is text: recognised on its characters.
    // Its length from the literal (30 bytes): a count written by hand read one byte past it (ASan).
    static constexpr char kUtf16[] = "\xFF\xFEO\0" "1\0" "0\0" "0\0" "0\0\n\0G\0" "0\0" "1\0 \0X\0" "1\0.\0\n\0";
    const std::string utf16(kUtf16, sizeof kUtf16 - 1);
    CHECK(program("o1000", utf16));
    // DNC control characters and the DOS end-of-file byte are allowed.
    CHECK(program("O1", "\x12%\nO0001\nG00 X0\nM30\n%\n\x14\x1a"));
}

TEST_CASE("recognise: NC extensions, content for everything else") {
    for (const char* ext : {".nc", ".NC", ".eia", ".gcode", ".prg", ".min", ".iso", ".ptp", ".tap", ".mpf"}) {
        INFO(ext);
        CHECK(recognize_program(std::string("part") + ext, "(ONLY A COMMENT)\n").reason == "extension " + std::string(ext == std::string(".NC") ? ".nc" : ext));
    }
    CHECK(program("O1000", "O1000\nG0X0\n"));
    CHECK(program("x", "%\nO0012 (PART)\n"));
    CHECK(program("x", "\xEF\xBB\xBF%\r\n:1000\r\n"));
    CHECK(program("x", "N10 G0 X0\n"));
    CHECK(program("205", "(ZAGLYSHKA FR0000-2223 2SHT)\n(VYLET 29MM)\nT0303(ROUSH R0.2)\nG54\nG97S2000M03\n"));
    CHECK(program("x.txt", "#100=0\nIF[#100 EQ 0] GOTO 99\nWHILE[#1 LE 3]DO1\nEND1\nN99 M30\n"));
    CHECK(program("x", "g01 z-18.5 f0.2\n"));
    CHECK_FALSE(program("x", "#!/bin/sh\necho\n"));
    CHECK_FALSE(program("x", "Once upon a time"));
    CHECK_FALSE(program("x", "(ONLY A COMMENT)\n(AND ANOTHER)\n"));
    CHECK_FALSE(program("notes.txt", "notes about the parts\nG01 X10 is a feed move\nthe second part is done\n"));
    CHECK_FALSE(program("README", "# Parts\n\nRun `G01 X10.` on the lathe.\n\n| part | program |\n|---|---|\n| A | O1000 |\n"));
    CHECK_FALSE(program("points.csv", "X,Y,Z\n1.0,2.0,3.0\n4.0,5.0,6.0\n"));
    CHECK_FALSE(program(".kerf.toml", "dialect = \"fanuc-mill\"\n[check]\nexclude = [\"old/**\"]\n"));
}

TEST_CASE("recognise: a program with CR-only line ends is recognised by its content, as the grammar reads it") {
    // Six NC blocks on six lines ended by a lone CR (ast/source.hpp LineBreaks), in a file whose
    // name says nothing: recognised by its content, line by line as with LF line ends.
    const std::string cr = "O1000\rG21 G90\rG0 X10. Y10.\rG1 Z-1. F100.\rX20.\rM30\r";
    CHECK(recognize_program("part", cr).reason == "content: 6 NC blocks in the first 6 lines");   // six lines, not one
    std::string lf = cr;
    for (char& c : lf)
        if (c == '\r') c = '\n';
    CHECK(recognize_program("part", lf).reason == "content: 6 NC blocks in the first 6 lines");
}
