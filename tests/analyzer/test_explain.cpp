// analyzer::explain: `kerf explain` as data (the CLI prints it, the server's hover renders it).
#include <catch2/catch.hpp>

#include "analyzer/explain.hpp"
#include "analyzer/registry.hpp"

using namespace kerf;
using analyzer::Explanation;

namespace {

Explanation explain(std::string query, std::string dialect = {}, analyzer::Language lang = analyzer::Language::en) {
    return analyzer::explain({std::move(query), std::move(dialect), lang}, dialects::builtin_registry(),
                             analyzer::builtin_rules());
}

}  // namespace

TEST_CASE("a rule by id or name, and a diagnostic id through the rule that reports it") {
    const Explanation by_id = explain("K1002");
    REQUIRE(by_id.kind == Explanation::Kind::rule);
    CHECK(by_id.rule->name == "malformed-number");
    CHECK(explain("malformed-number").rule == by_id.rule);
    CHECK(explain("k1002").rule == by_id.rule);   // as typed in a hurry
    const Explanation s = explain("S0103");
    REQUIRE(s.kind == Explanation::Kind::rule);
    CHECK(s.rule->id == "K1003");   // docs/diagnostics.md: S0103 is reported as K1003 letter-o-for-zero
    CHECK(s.diagnostic == "S0103");
}

TEST_CASE("K9999 is a rule that does not exist, not a code of some dialect (issue 12)") {
    const Explanation e = explain("K9999");
    CHECK(e.kind == Explanation::Kind::no_such_rule);
    CHECK(e.message.find("not a rule") != std::string::npos);
    CHECK(e.message.find("fanuc") == std::string::npos);
    CHECK(explain("S0999").kind == Explanation::Kind::no_such_rule);
}

TEST_CASE("a code without a dialect: every dialect that has it, one entry per reading") {
    // G81 is the drilling cycle of the mill dialects (gcode-tables.md §2, §3, §4); no FANUC lathe
    // system has it (gcode-tables.md §1).
    const Explanation e = explain("G81");
    REQUIRE(e.kind == Explanation::Kind::code);
    std::vector<std::string> all;
    for (const analyzer::CodeExplanation& c : e.codes) {
        CHECK(c.spelling == "G81");
        all.insert(all.end(), c.dialects.begin(), c.dialects.end());
    }
    CHECK(std::find(all.begin(), all.end(), "fanuc-mill") != all.end());
    CHECK(std::find(all.begin(), all.end(), "fanuc-lathe-a") == all.end());
    // Each dialect is listed once, and two entries differ in what they show.
    std::sort(all.begin(), all.end());
    CHECK(std::adjacent_find(all.begin(), all.end()) == all.end());
}

TEST_CASE("G71 reads differently in systems A and C: two entries") {
    // gcode-tables.md §1: G71 is the rough turning cycle in A and B, metric input in C (A/B: G21).
    const Explanation e = explain("G71");
    REQUIRE(e.kind == Explanation::Kind::code);
    const auto of = [&](const std::string& id) -> const analyzer::CodeExplanation* {
        for (const analyzer::CodeExplanation& c : e.codes)
            if (std::find(c.dialects.begin(), c.dialects.end(), id) != c.dialects.end()) return &c;
        return nullptr;
    };
    REQUIRE(of("fanuc-lathe-a"));
    REQUIRE(of("fanuc-lathe-c"));
    CHECK(of("fanuc-lathe-a") != of("fanuc-lathe-c"));
    CHECK(of("fanuc-lathe-a")->function.name() == "rough-turning-cycle");
    CHECK(of("fanuc-lathe-c")->function.name() == "metric-input");
    CHECK(of("fanuc-lathe-a")->group == "00");
    CHECK(of("fanuc-lathe-a")->one_shot);
}

TEST_CASE("a code in one dialect, in Russian; unknown codes and dialects") {
    const Explanation ru = explain("G71", "fanuc-lathe-a", analyzer::Language::ru);
    REQUIRE(ru.kind == Explanation::Kind::code);
    REQUIRE(ru.codes.size() == 1);
    CHECK(ru.codes[0].dialects == std::vector<std::string>{"fanuc-lathe-a"});
    CHECK(ru.codes[0].title == dialects::builtin_registry().find("fanuc-lathe-a")->code("G71")->ru);
    CHECK(analyzer::format_explanation(ru, analyzer::Language::ru).find("группа: 00") != std::string::npos);
    CHECK(explain("G999").kind == Explanation::Kind::no_such_code);
    CHECK(explain("G999", "fanuc-mill").message.find("fanuc-mill") != std::string::npos);
    CHECK(explain("G71", "nope").kind == Explanation::Kind::unknown_dialect);
    CHECK(explain("hello").kind == Explanation::Kind::not_understood);
}
