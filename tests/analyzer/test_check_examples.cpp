// issue 5, "what must be shown" 3: no rule fires on the reference examples unless a reviewed
// entry of tests/golden/check/examples-allowed.txt says why (the example is wrong, or is a
// fragment the rule must see as one). Each example is checked as `kerf check` checks it: its
// dialect detected from the text (the `(DIALECT: ...)` header decides), the dialect's built-in
// machine, the rules that are on by default.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "analyzer/analyze.hpp"
#include "analyzer/output.hpp"
#include "grammar/detect.hpp"
#include "interpreter/default_setup.hpp"
#include "tests/shared_files.hpp"

namespace fs = std::filesystem;
using namespace kerf;

namespace {

const fs::path kExamples = fs::path(KERF_SHARED_DIR) / "reference/examples";
const fs::path kAllowed = fs::path(KERF_SOURCE_DIR) / "tests/golden/check/examples-allowed.txt";

// "example rule" → the lines a finding of that rule may have, from the allowed list. A line is
// "<example> <rule> <line>[,<line>...] <reason>"; '#' starts a comment line.
struct Allowed {
    std::map<std::string, std::set<std::uint32_t>> lines;
    std::map<std::string, std::string> reasons;
};

Allowed read_allowed() {
    Allowed a;
    std::istringstream in(test::read_text(kAllowed));
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream words(line);
        std::string example, rule, numbers, reason;
        words >> example >> rule >> numbers;
        std::getline(words, reason);
        INFO(line);
        REQUIRE(reason.size() > 10);   // every entry says why
        const std::string key = example + " " + rule;
        std::istringstream list(numbers);
        for (std::string n; std::getline(list, n, ',');) a.lines[key].insert(static_cast<std::uint32_t>(std::stoul(n)));
        a.reasons[key] = reason;
    }
    return a;
}

// "example rule line" of every finding of `kerf check` on one example.
std::vector<std::string> findings_of(const fs::path& path) {
    const std::string text = test::read_text(path);
    const dialects::Dialect* d = dialects::builtin_registry().find(grammar::detect_dialect(text).dialect);
    REQUIRE(d);
    const interpreter::Setup setup = interpreter::default_setup(*d);
    interpreter::ProgramSet programs;
    const std::uint32_t file = programs.add(path.filename().string(), text, *d);
    const std::vector<analyzer::Finding> findings = analyzer::check_file(programs, file, *d, setup);
    std::vector<std::string> out;
    for (const analyzer::Finding& f : findings) {
        const analyzer::Location l = analyzer::locate(*programs.file(file).whole_lines(), f.range);
        out.push_back(fmt::format("{} {} {}", path.filename().string(), f.rule, l.line));
    }
    return out;
}

}  // namespace

TEST_CASE("kerf check on the reference examples: every finding is in the reviewed allowed list") {
    const std::vector<fs::path> files = test::shared_files_or_warn("reference examples test skipped");
    if (files.empty()) return;
    const Allowed allowed = read_allowed();
    std::set<std::string> used;
    std::size_t examples = 0;
    for (const fs::path& path : files) {
        if (path.parent_path() != kExamples) continue;
        ++examples;
        for (const std::string& finding : findings_of(path)) {
            std::istringstream words(finding);
            std::string example, rule;
            std::uint32_t line = 0;
            words >> example >> rule >> line;
            const std::string key = example + " " + rule;
            const auto it = allowed.lines.find(key);
            INFO(finding);
            CHECK((it != allowed.lines.end() && it->second.count(line) == 1));
            used.insert(key + " " + std::to_string(line));
        }
    }
    CHECK(examples == 88);
    // No stale entries: every allowed line is still a finding (an entry that no longer fires is
    // removed, so the list stays the list of what kerf says about the examples).
    for (const auto& [key, lines] : allowed.lines)
        for (const std::uint32_t line : lines) {
            INFO("allowed but not found: " << key << " " << line);
            CHECK(used.count(key + " " + std::to_string(line)) == 1);
        }
}
