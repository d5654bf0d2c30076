// The analyzer's bounds (issue 17, ARCHITECTURE.md "Bounded resources"): at most
// CheckOptions::max_findings_per_rule findings of a rule per file and one "and N more"; suppressed
// findings do not count; a dynamic rule in an endless loop reports each position once.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "analyzer/rule.hpp"
#include "tests/analyzer/check_fixture.hpp"

using namespace kerf;
using namespace kerf::test;

namespace {

std::size_t count_rule(const Checked& c, const std::string& rule, ast::Severity severity) {
    std::size_t n = 0;
    for (const analyzer::Finding& f : c.findings) n += f.rule == rule && f.severity == severity;
    return n;
}

const analyzer::Finding* and_more(const Checked& c, const std::string& rule) {
    for (const analyzer::Finding& f : c.findings)
        if (f.rule == rule && f.message.find(" more finding") != std::string::npos) return &f;
    return nullptr;
}

}  // namespace

TEST_CASE("analyzer bounds: at most the cap per rule and file, then 'and N more'") {
    std::string text = "O1000\n";
    for (int i = 0; i < 300; ++i) text += "G01 X1. X1. F100.\n";   // K1021 once a line
    text += "M30\n";
    analyzer::CheckOptions options;   // the defaults: cap 100
    const Checked capped = check(text, "fanuc-mill", options);
    CHECK(count_rule(capped, "K1021", ast::Severity::warning) == 100);
    const analyzer::Finding* more = and_more(capped, "K1021");
    REQUIRE(more);
    CHECK(more->severity == ast::Severity::info);
    CHECK(more->message == "and 200 more findings of K1021 in this file, not shown");
    CHECK(more->hint == "at most 100 findings per rule and file are shown (--max-findings-per-rule; 0 shows all)");
    // The first 100 in text order are the ones shown: lines 2 to 101.
    CHECK(capped.report.locations.front().line == 2);
    options.max_findings_per_rule = 0;
    const Checked all = check(text, "fanuc-mill", options);
    CHECK(count_rule(all, "K1021", ast::Severity::warning) == 300);
    CHECK_FALSE(and_more(all, "K1021"));
}

TEST_CASE("analyzer bounds: suppressed findings do not count against the cap") {
    std::string text = "O1000\n";
    for (int i = 0; i < 60; ++i) text += "G01 X1. X1. F100. (kerf: ignore K1021)\n";
    for (int i = 0; i < 150; ++i) text += "G01 X1. X1. F100.\n";
    text += "M30\n";
    const Checked c = check(text, "fanuc-mill", analyzer::CheckOptions{});
    CHECK(count_rule(c, "K1021", ast::Severity::warning) == 100);
    REQUIRE(and_more(c, "K1021"));
    CHECK(and_more(c, "K1021")->message == "and 50 more findings of K1021 in this file, not shown");
}

TEST_CASE("analyzer bounds: a dynamic rule in an endless loop reports its block once") {
    // No tool (K5008) on the feed move of a program that loops with GOTO until the step limit (an
    // M99 at its end would be a bar-feed loop, which the dry run runs once).
    const Checked c = check("O1000\nN1 G01 X1. F100.\nGOTO 1\n", "fanuc-mill", analyzer::CheckOptions{});
    CHECK(count_rule(c, "K5008", ast::Severity::warning) == 1);
    CHECK(count_rule(c, "K4004", ast::Severity::error) == 1);
}

TEST_CASE("analyzer bounds: a finding's message is cut, and the human excerpt is a window") {
    // "G01 X1. (" is 9 bytes, the comment's text 8,000, ") " 2: the second X1. starts at column 8,012.
    const std::string text = "O1000\nG01 X1. (" + std::string(8000, 'A') + ") X1. F100.\nM30\n";
    const Checked c = check(text, "fanuc-mill", analyzer::CheckOptions{});
    const std::string human = analyzer::format_human({c.report}, false);
    for (std::size_t at = 0, next; (next = human.find('\n', at)) != std::string::npos; at = next + 1)
        CHECK(next - at < 240);
    // The repeated X at column 8,012 is underlined where it is shown.
    CHECK(human.find("test.nc:2:8012: warning K1021") != std::string::npos);
}

TEST_CASE("analyzer bounds: past the cap a jump to a repeated label is counted without being built, suppressions kept") {
    // K3002 (ambiguous-label) counts its findings past the cap without formatting them
    // (Reporter::drop_if_full): the count of "and N more" must be what report() would count.
    std::string text = "O1000\nN5 G01 X1. F100.\nN5 G01 X2.\n";
    for (int i = 0; i < 130; ++i) text += "GOTO 5\n";
    for (int i = 0; i < 20; ++i) text += "GOTO 5 (kerf: ignore K3002)\n";
    for (int i = 0; i < 30; ++i) text += "GOTO 5\n";
    text += "M30\n";
    const Checked c = check(text, "fanuc-mill", analyzer::CheckOptions{});
    CHECK(count_rule(c, "K3002", ast::Severity::warning) == 100);
    REQUIRE(and_more(c, "K3002"));
    CHECK(and_more(c, "K3002")->message == "and 60 more findings of K3002 in this file, not shown");
}

TEST_CASE("analyzer bounds: the positions a rule reported count each once, in any order") {
    // Static rules report in text order (the sorted array), dynamic ones may come back (the set).
    analyzer::PositionSet set;
    const std::vector<std::uint32_t> order = {5, 9, 9, 12, 3, 5, 7, 3, 40, 12, 7, 41, 0, 0};
    const std::vector<bool> expected = {true, true, false, true, true, false, true, false, true, false, false, true, true, false};
    for (std::size_t i = 0; i < order.size(); ++i) {
        INFO("insert " << order[i] << " (#" << i << ")");
        CHECK(set.insert(order[i]) == expected[i]);
    }
}
