// `base = "..."` inheritance (dialects/SCHEMA.md): fanuc-lathe-b and -c are written as their
// differences from fanuc-lathe-a. Their loaded tables must be those of the full files they replace
// (kept in tests/dialects/full/ for this comparison), code by code and field by field.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "dialects/dialect.hpp"
#include "tests/shared_files.hpp"

using namespace kerf::dialects;

namespace {

void check_same_code(const CodeInfo& a, const CodeInfo& b) {
    INFO(a.spelling);
    CHECK(a.letter == b.letter);
    CHECK(a.key == b.key);
    CHECK(a.spelling == b.spelling);
    CHECK(a.aliases == b.aliases);
    CHECK(a.group == b.group);
    CHECK(a.modal == b.modal);
    CHECK(a.power_on_default == b.power_on_default);
    CHECK(a.function == b.function);
    CHECK(a.words == b.words);
    CHECK(a.parameter_letters == b.parameter_letters);
    CHECK(a.required == b.required);
    CHECK(a.required_one_of == b.required_one_of);
    CHECK(a.availability == b.availability);
    CHECK(a.availability_note == b.availability_note);
    CHECK(a.en == b.en);
    CHECK(a.ru == b.ru);
    CHECK(a.reference == b.reference);
    CHECK(a.notes == b.notes);
    CHECK(a.traits == b.traits);
    CHECK(a.parameter_mask == b.parameter_mask);
}

void check_same_lexical(const LexicalRules& a, const LexicalRules& b) {
    CHECK(a.semicolon == b.semicolon);
    CHECK(a.paren_comments == b.paren_comments);
    CHECK(a.line_comments == b.line_comments);
    CHECK(a.incremental_letters == b.incremental_letters);
    CHECK(a.axes == b.axes);
    CHECK(a.diameter_letters == b.diameter_letters);
    CHECK(a.comma_words == b.comma_words);
    CHECK(a.plain_direct_drawing == b.plain_direct_drawing);
    CHECK(a.subprogram_call == b.subprogram_call);
    CHECK(a.decimal_comma_lenient == b.decimal_comma_lenient);
    CHECK(a.calculator_decimal == b.calculator_decimal);
    CHECK(a.tool_word == b.tool_word);
    CHECK(a.macro_b == b.macro_b);
    CHECK(a.max_m_per_block == b.max_m_per_block);
}

}  // namespace

TEST_CASE("fanuc-lathe-b and -c derived from -a load the tables of their full files") {
    for (const std::string id : {"fanuc-lathe-b", "fanuc-lathe-c", "spinner-lathe-b", "spinner-lathe-c"}) {
        INFO(id);
        const std::string stem = id.substr(id.find("lathe"));   // spinner-lathe-b: the full B + spinner
        const std::string full_text =
            kerf::test::read_text(std::filesystem::path(KERF_SOURCE_DIR) / "tests/dialects/full" / ("fanuc-" + stem + ".toml"));
        REQUIRE_FALSE(full_text.empty());
        const LoadResult full = load_dialect_text(full_text, "full.toml");
        REQUIRE(full.errors.empty());
        Dialect expected = full.file->dialect;
        if (id.starts_with("spinner")) {
            std::string_view spinner_text;
            for (const auto& [stem_of, text] : builtin_dialect_texts())
                if (stem_of == "spinner") spinner_text = text;
            const LoadResult spinner = load_dialect_text(spinner_text, "spinner.toml");
            REQUIRE(spinner.file.has_value());
            expected = apply_overlay(expected, *spinner.file, id);
        }
        const Dialect* derived = builtin_registry().find(id);
        REQUIRE(derived != nullptr);
        CHECK(derived->name == expected.name);
        CHECK(derived->reference == expected.reference);
        CHECK(derived->machine == expected.machine);
        check_same_lexical(derived->lexical, expected.lexical);
        REQUIRE(derived->codes().size() == expected.codes().size());
        for (const CodeInfo& c : expected.codes()) {
            const CodeInfo* d = derived->code(c.letter, c.key);
            INFO(c.spelling << " is missing in the derived dialect");
            REQUIRE(d != nullptr);
            check_same_code(*d, c);
        }
        CHECK(derived->groups().size() == expected.groups().size());
        // The chain of bases, nearest first: fanuc-lathe-b ← fanuc-lathe-a; spinner-lathe-b is the
        // overlay on fanuc-lathe-b, so its bases are fanuc-lathe-b, fanuc-lathe-a.
        const std::vector<std::string> bases =
            id.starts_with("spinner") ? std::vector<std::string>{"fanuc-" + stem, "fanuc-lathe-a"}
                                      : std::vector<std::string>{"fanuc-lathe-a"};
        CHECK(derived->bases == bases);
    }
}
