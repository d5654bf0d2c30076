// Unit tests of the dialect loader and registry (dialects/SCHEMA.md, reference/dialects.md).
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "dialects/dialect.hpp"

using namespace kerf::dialects;

namespace {

const std::vector<std::string> kBuiltinIds = {
    "fanuc-lathe-a", "fanuc-lathe-b", "fanuc-lathe-c", "spinner-lathe-a", "spinner-lathe-b", "spinner-lathe-c",
    "fanuc-mill",    "adv400-mill",   "adv400-lathe",  "pcnc-mill",       "iso-legacy-mill", "haas-mill", "haas-lathe"};

const Dialect& builtin(const std::string& id) {
    const Dialect* d = builtin_registry().find(id);
    INFO("dialect " << id);
    REQUIRE(d != nullptr);
    return *d;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

// A small but complete base dialect; tests replace pieces of it to provoke errors.
std::string minimal_dialect(const std::string& id = "user-lathe", const std::string& semicolon = "end-of-block",
                            const std::string& code = "G00", const std::string& en_line = "en = \"Rapid\"") {
    return "id = \"" + id + "\"\n"                       // line 1
           "name = \"User lathe\"\n"                      // 2
           "machine = \"lathe\"\n"                        // 3
           "overlay = false\n"                            // 4
           "\n"                                           // 5
           "[lexical]\n"                                  // 6
           "semicolon = \"" + semicolon + "\"\n"          // 7
           "axes = [\"X\", \"Z\"]\n"                      // 8
           "\n"                                           // 9
           "[[g]]\n"                                      // 10
           "code = \"" + code + "\"\n"                    // 11
           "group = \"01\"\n"                             // 12
           "modal = true\n"                               // 13
           "default = true\n"                             // 14
           "function = \"rapid\"\n"                       // 15
           "words = [\"X\", \"Z\"]\n"                     // 16
           + en_line + "\n"                               // 17
           "ru = \"Ускоренное перемещение\"\n"            // 18
           "reference = \"user\"\n"                       // 19
           "\n"                                           // 20
           "[[m]]\n"                                      // 21
           "code = \"M30\"\n"                             // 22
           "function = \"program-end-rewind\"\n"          // 23
           "en = \"End of program\"\n"                    // 24
           "ru = \"Конец программы\"\n"                   // 25
           "reference = \"user\"\n";                      // 26
}

bool any_error_mentions(const std::vector<LoadError>& errors, const std::string& text) {
    for (const LoadError& e : errors)
        if (e.message.find(text) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("every built-in data file loads without errors") {
    const auto texts = builtin_dialect_texts();
    REQUIRE(texts.size() >= 9);   // 8 bases + the spinner overlay
    int overlays = 0;
    for (const auto& [stem, text] : texts) {
        INFO("data file " << stem);
        const LoadResult r = load_dialect_text(text, std::string(stem) + ".toml");
        for (const LoadError& e : r.errors) UNSCOPED_INFO("line " << e.line << ": " << e.message);
        REQUIRE(r.errors.empty());
        REQUIRE(r.file.has_value());
        const DialectFile& f = *r.file;
        CHECK(f.dialect.id == std::string(stem));
        CHECK(f.dialect.codes().empty() == f.dialect.foreign);   // a foreign control profile has no codes
        if (f.overlay) {
            ++overlays;
            CHECK(f.applies_to.size() == f.combined_ids.size());
        }
        for (const CodeInfo& c : f.dialect.codes()) {
            INFO(c.spelling);
            CHECK_FALSE(c.en.empty());
            CHECK_FALSE(c.ru.empty());
            CHECK_FALSE(c.function.empty());
        }
    }
    CHECK(overlays == 1);
}

TEST_CASE("the built-in registry has the 13 dialect ids") {
    const Registry& reg = builtin_registry();
    for (const std::string& id : kBuiltinIds) {
        INFO(id);
        REQUIRE(reg.find(id) != nullptr);
        CHECK(reg.find(id)->id == id);
    }
    const std::vector<std::string> ids = reg.ids();
    CHECK(ids.size() == kBuiltinIds.size());
    for (const std::string& id : kBuiltinIds) CHECK(contains(ids, id));
    CHECK(reg.find("spinner") == nullptr);   // the overlay itself is not a dialect
    CHECK(reg.find("nope") == nullptr);
    CHECK(builtin("spinner-lathe-b").overlays == std::vector<std::string>{"spinner"});
    CHECK(builtin("fanuc-lathe-a").machine == MachineKind::lathe);
    CHECK(builtin("fanuc-mill").machine == MachineKind::mill);
}

TEST_CASE("lexical switches follow reference/dialects.md") {
    SECTION("fanuc-lathe-a: U/W/H incremental, ';' ends the block") {
        const LexicalRules& lex = builtin("fanuc-lathe-a").lexical;
        CHECK(lex.incremental_axis_of('U') == 'X');
        CHECK(lex.incremental_axis_of('W') == 'Z');
        CHECK(lex.incremental_axis_of('H') == 'C');
        CHECK(lex.incremental_axis_of('X') == '\0');
        CHECK(lex.semicolon == SemicolonRole::end_of_block);
        CHECK(lex.is_diameter('X'));
        CHECK(lex.max_m_per_block == 1);
        CHECK_FALSE(lex.plain_direct_drawing);
    }
    SECTION("pcnc-mill: ';' starts a comment") {
        CHECK(builtin("pcnc-mill").lexical.semicolon == SemicolonRole::comment);
        CHECK(builtin("fanuc-mill").lexical.semicolon == SemicolonRole::end_of_block);
    }
    SECTION("adv400-*: '::' and ';;' line comments, M98 P_ L_") {
        for (const char* id : {"adv400-mill", "adv400-lathe"}) {
            INFO(id);
            const LexicalRules& lex = builtin(id).lexical;
            CHECK(contains(lex.line_comments, "::"));
            CHECK(contains(lex.line_comments, ";;"));
            CHECK(lex.subprogram_call == SubprogramCall::p_l);
            CHECK(lex.incremental_letters.empty());
        }
        CHECK(builtin("fanuc-lathe-a").lexical.line_comments.empty());
    }
    SECTION("spinner-lathe-a: direct drawing, three M codes, SPINNER codes") {
        const Dialect& spinner = builtin("spinner-lathe-a");
        const Dialect& fanuc = builtin("fanuc-lathe-a");
        CHECK(spinner.lexical.plain_direct_drawing);
        CHECK(spinner.lexical.max_m_per_block == 3);
        // Keys the overlay does not set come from the base.
        CHECK(spinner.lexical.incremental_axis_of('U') == 'X');
        CHECK(spinner.lexical.semicolon == SemicolonRole::end_of_block);
        REQUIRE(spinner.code("G38") != nullptr);
        REQUIRE(spinner.code("M329") != nullptr);
        CHECK(spinner.code("G71") != nullptr);   // base codes survive the overlay
        CHECK(fanuc.code("G38") == nullptr);
        CHECK(fanuc.code("M329") == nullptr);
        CHECK_FALSE(fanuc.lexical.plain_direct_drawing);
        CHECK(spinner.codes().size() > fanuc.codes().size());
    }
    SECTION("code functions are shared where the meaning is the same") {
        const CodeInfo* a32 = builtin("fanuc-lathe-a").code("G32");
        const CodeInfo* b33 = builtin("fanuc-lathe-b").code("G33");
        REQUIRE(a32 != nullptr);
        REQUIRE(b33 != nullptr);
        CHECK_FALSE(a32->function.empty());
        CHECK(b33->function == a32->function);
        CHECK(builtin("fanuc-lathe-b").code("G32") == nullptr);
        const CodeInfo* iso28 = builtin("iso-legacy-mill").code("G28");
        const CodeInfo* mill28 = builtin("fanuc-mill").code("G28");
        REQUIRE(iso28 != nullptr);
        REQUIRE(mill28 != nullptr);
        CHECK(iso28->function != mill28->function);
        CHECK(builtin("fanuc-mill").codes_with_function(mill28->function).size() >= 1);
    }
}

TEST_CASE("code spellings and keys") {
    CHECK(code_key(12.1) == CodeKey{121});
    CHECK(code_key(0.0) == CodeKey{0});
    CHECK(code_key(71.0) == CodeKey{710});
    CHECK(code_key(329.0) == CodeKey{3290});
    CHECK_FALSE(code_key(12.15).has_value());
    CHECK_FALSE(code_key(-1.0).has_value());

    using P = std::pair<char, CodeKey>;
    CHECK(parse_code_spelling("G12.1") == P{'G', 121});
    CHECK(parse_code_spelling("g1") == P{'G', 10});
    CHECK(parse_code_spelling("M003") == P{'M', 30});
    CHECK(parse_code_spelling("M3") == P{'M', 30});
    CHECK(parse_code_spelling("G00") == P{'G', 0});
    CHECK(parse_code_spelling("G113") == P{'G', 1130});
    for (const char* bad : {"", "G", "12", "1G", "GX", "G-1", "G 1", "G1.", "G1.23", "G1a", "G.5", "#1"}) {
        INFO("'" << bad << "'");
        CHECK_FALSE(parse_code_spelling(bad).has_value());
    }
    const Dialect& a = builtin("fanuc-lathe-a");
    REQUIRE(a.code("g71") != nullptr);
    CHECK(a.code("g71") == a.code("G71"));
    CHECK(a.code('G', 710) == a.code("G71"));
    CHECK(a.fast_code('G', 710) == a.code("G71"));
    CHECK(a.code("G12.1") == a.code("G112"));   // alias
    CHECK(a.code("G12.1") != nullptr);
    CHECK(a.code("not a code") == nullptr);
}

TEST_CASE("load errors carry a message and a line") {
    SECTION("the minimal text itself is valid") {
        const LoadResult r = load_dialect_text(minimal_dialect(), "user.toml");
        REQUIRE(r.errors.empty());
        REQUIRE(r.file.has_value());
        CHECK(r.file->dialect.code("G0") != nullptr);
        CHECK(r.file->dialect.code("M30") != nullptr);
    }
    SECTION("TOML syntax error") {
        const std::string text = "id = \"x\"\nname = \"y\"\nmachine = = \"lathe\"\n";
        const LoadResult r = load_dialect_text(text, "broken.toml");
        CHECK_FALSE(r.file.has_value());
        REQUIRE(r.errors.size() == 1);
        CHECK_FALSE(r.errors[0].message.empty());
        CHECK(r.errors[0].message.find("broken.toml") != std::string::npos);
        CHECK(r.errors[0].line == 3);
    }
    SECTION("missing en") {
        const LoadResult r = load_dialect_text(minimal_dialect("user-lathe", "end-of-block", "G00", ""), "no-en.toml");
        CHECK_FALSE(r.file.has_value());
        REQUIRE_FALSE(r.errors.empty());
        CHECK(any_error_mentions(r.errors, "'en'"));
        CHECK(r.errors[0].message.find("no-en.toml") != std::string::npos);
        // The error points at the [[g]] table that lacks the key (its header is line 10).
        CHECK(r.errors[0].line == 10);
    }
    SECTION("bad code spelling") {
        const LoadResult r = load_dialect_text(minimal_dialect("user-lathe", "end-of-block", "G7x"), "bad-code.toml");
        CHECK_FALSE(r.file.has_value());
        REQUIRE(r.errors.size() == 1);
        CHECK(any_error_mentions(r.errors, "G7x"));
        CHECK(r.errors[0].line == 11);
    }
    SECTION("an M spelling in a [[g]] table is an error") {
        const LoadResult r = load_dialect_text(minimal_dialect("user-lathe", "end-of-block", "M03"), "m-in-g.toml");
        REQUIRE_FALSE(r.errors.empty());
        CHECK(r.errors[0].line == 11);
    }
    SECTION("an unknown function id is an error at its value, with the nearest known id") {
        std::string text = minimal_dialect();
        const std::string good = "function = \"rapid\"";
        text.replace(text.find(good), good.size(), "function = \"rapdi\"");   // line 15
        const LoadResult r = load_dialect_text(text, "typo.toml");
        CHECK_FALSE(r.file.has_value());
        REQUIRE(r.errors.size() == 1);
        CHECK(any_error_mentions(r.errors, "unknown function id 'rapdi'"));
        CHECK(any_error_mentions(r.errors, "did you mean 'rapid'?"));
        CHECK(r.errors[0].line == 15);
        CHECK(r.errors[0].column == 12);   // the value, after `function = `
    }
    SECTION("unknown semicolon value") {
        const LoadResult r = load_dialect_text(minimal_dialect("user-lathe", "sometimes"), "semi.toml");
        CHECK_FALSE(r.file.has_value());
        REQUIRE(r.errors.size() == 1);
        CHECK(any_error_mentions(r.errors, "semicolon"));
        CHECK(any_error_mentions(r.errors, "sometimes"));
        CHECK(r.errors[0].line == 7);
    }
}

TEST_CASE("user dialect files through Registry::add_text") {
    SECTION("a user base dialect can be found") {
        Registry reg;
        const std::vector<LoadError> errors = reg.add_text(minimal_dialect("my-lathe"), "my-lathe.toml");
        REQUIRE(errors.empty());
        const Dialect* d = reg.find("my-lathe");
        REQUIRE(d != nullptr);
        CHECK(d->name == "User lathe");
        REQUIRE(d->code("G00") != nullptr);
        CHECK(d->code("G00")->power_on_default);
        CHECK(d->code("G01") == nullptr);
        CHECK(reg.ids() == std::vector<std::string>{"my-lathe"});
    }
    SECTION("a broken user file reports errors and adds nothing") {
        Registry reg;
        const std::vector<LoadError> errors = reg.add_text(minimal_dialect("bad", "sometimes"), "bad.toml");
        REQUIRE_FALSE(errors.empty());
        CHECK(reg.find("bad") == nullptr);
    }
    SECTION("a user overlay applies to the base it names") {
        Registry reg = builtin_registry();   // copy: the built-in registry stays untouched
        const std::string overlay =
            "id = \"probe\"\n"
            "name = \"Probe option\"\n"
            "overlay = true\n"
            "applies_to = [\"fanuc-mill\"]\n"
            "combined_ids = [\"fanuc-mill-probe\"]\n"
            "\n"
            "[lexical]\n"
            "max_m_per_block = 3\n"
            "\n"
            "[[g]]\n"
            "code = \"G31.1\"\n"
            "group = \"00\"\n"
            "modal = false\n"
            "function = \"skip-function\"\n"
            "words = [\"X\", \"Y\", \"Z\", \"F\"]\n"
            "en = \"Multi-step skip 1\"\n"
            "ru = \"Многоступенчатый пропуск 1\"\n"
            "reference = \"user\"\n";
        const std::vector<LoadError> errors = reg.add_text(overlay, "probe.toml");
        REQUIRE(errors.empty());
        const Dialect* combined = reg.find("fanuc-mill-probe");
        REQUIRE(combined != nullptr);
        REQUIRE(combined->code("G31.1") != nullptr);
        CHECK(combined->code("G31.1")->en == "Multi-step skip 1");
        CHECK(combined->code("G28") != nullptr);   // from the base
        CHECK(combined->lexical.max_m_per_block == 3);
        CHECK(combined->lexical.semicolon == SemicolonRole::end_of_block);   // not overridden
        CHECK(combined->overlays == std::vector<std::string>{"probe"});
        CHECK(combined->machine == MachineKind::mill);
        // The base is unchanged, in the copy and in the built-in registry.
        CHECK(reg.find("fanuc-mill")->code("G31.1") == nullptr);
        CHECK(builtin("fanuc-mill").code("G31.1") == nullptr);
        CHECK(builtin_registry().find("fanuc-mill-probe") == nullptr);
        CHECK(reg.find("probe") == nullptr);

        // The same overlay naming a dialect that does not exist is an error.
        Registry empty;
        const std::vector<LoadError> unknown = empty.add_text(overlay, "probe.toml");
        REQUIRE(unknown.size() == 1);
        CHECK(unknown[0].message.find("fanuc-mill") != std::string::npos);
        CHECK(empty.find("fanuc-mill-probe") == nullptr);
    }
    SECTION("apply_overlay combines a base with a loaded overlay file") {
        const LoadResult spinner = [] {
            for (const auto& [stem, text] : builtin_dialect_texts())
                if (stem == "spinner") return load_dialect_text(text, "spinner.toml");
            return LoadResult{};
        }();
        REQUIRE(spinner.file.has_value());
        REQUIRE(spinner.file->overlay);
        const Dialect combined = apply_overlay(builtin("fanuc-lathe-c"), *spinner.file, "my-spinner-c");
        CHECK(combined.id == "my-spinner-c");
        CHECK(combined.code("G38") != nullptr);
        CHECK(combined.lexical.max_m_per_block == 3);
        REQUIRE(combined.code("G71") != nullptr);
        CHECK(combined.code("G71")->function == builtin("fanuc-lathe-c").code("G71")->function);
    }
}

TEST_CASE("lexical.tool_word is mmnn or number; anything else is reported") {
    CHECK(builtin("fanuc-mill").lexical.tool_word == "number");      // T is a tool number, M06 changes
    CHECK(builtin("fanuc-lathe-a").lexical.tool_word == "mmnn");     // T0101: tool 1, offset 1
    std::string text = minimal_dialect();
    text.insert(text.find("axes = "), "tool_word = \"nnmm\"\n");
    Registry reg;
    const std::vector<LoadError> errors = reg.add_text(text, "user.toml");
    CHECK(any_error_mentions(errors, "lexical.tool_word: unknown value 'nnmm'"));
}
