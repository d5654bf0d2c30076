// Diagnostic ids and alarm numbers agree between the code (ast/diagnostic_ids.hpp,
// dialects/alarms.hpp), docs/diagnostics.md and the analyzer's rules: every id is documented and
// reported by exactly one rule; every alarm the dry run raises is documented with the rule that
// reports it (the narrowest alarm range, as `kerf check` picks it).
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <string>

#include "analyzer/registry.hpp"
#include "ast/diagnostic_ids.hpp"
#include "dialects/alarms.hpp"
#include "interpreter/events.hpp"
#include "interpreter/macro/evaluate.hpp"
#include "tests/shared_files.hpp"

using namespace kerf;

namespace {

std::string diagnostics_doc() {
    return test::read_text(std::filesystem::path(KERF_SOURCE_DIR) / "docs/diagnostics.md");
}

// The first cells of the table rows whose first cell matches `id` ("| S0101 | ...").
std::vector<std::string> first_cells(const std::string& doc, const std::string& id) {
    std::vector<std::string> out;
    const std::regex row("^\\| (" + id + ") \\|", std::regex::multiline);
    for (auto it = std::sregex_iterator(doc.begin(), doc.end(), row); it != std::sregex_iterator(); ++it)
        out.push_back((*it)[1].str());
    return out;
}

// docs/diagnostics.md's alarm table, as the code says it must be.
std::string alarm_table() {
    std::string out = "| alarm | name (`dialects/alarms.hpp`) | what | kerf check |\n|---|---|---|---|\n";
    for (const alarms::AlarmDef& a : alarms::kAlarms) {
        const analyzer::Rule* rule = analyzer::builtin_rules().for_alarm(a.number);
        out += fmt::format("| {:03} | `{}` | {} | {} |\n", a.number, a.name, a.what,
                           rule ? fmt::format("{} {}", rule->id, rule->name) : std::string("(none)"));
    }
    return out;
}

}  // namespace

TEST_CASE("every diagnostic id is in docs/diagnostics.md once, and the document has no other") {
    const std::string doc = diagnostics_doc();
    std::vector<std::string> documented = first_cells(doc, "[SMF][0-9]{4}");
    std::multiset<std::string> counted(documented.begin(), documented.end());
    std::set<std::string> code;
    for (const std::string_view id : ast::diagnostic_id::kAll) {
        INFO(id);
        CHECK(code.insert(std::string(id)).second);   // no id twice in the code
        CHECK(counted.count(std::string(id)) == 1);
    }
    for (const std::string& id : documented) {
        INFO(id << " is documented but not in ast/diagnostic_ids.hpp");
        CHECK(code.count(id) == 1);
    }
}

TEST_CASE("every S id is reported by exactly one rule, and rules report only known ids") {
    std::map<std::string, std::vector<std::string>> rules_of;
    for (const analyzer::Rule& r : analyzer::builtin_rules().rules())
        for (const std::string& d : r.diagnostics) rules_of[d].push_back(r.id);
    for (const std::string_view id : ast::diagnostic_id::kAll) {
        if (!id.starts_with('S')) continue;
        INFO(id);
        CHECK(rules_of[std::string(id)].size() == 1);
    }
    for (const auto& [id, rules] : rules_of) {
        INFO(id << " is reported by " << rules.front());
        CHECK(std::find(std::begin(ast::diagnostic_id::kAll), std::end(ast::diagnostic_id::kAll), id) !=
              std::end(ast::diagnostic_id::kAll));
    }
}

TEST_CASE("the macro error ids are the FANUC alarm numbers the dry run raises") {
    namespace codes = interpreter::macro::codes;
    CHECK(std::string_view(codes::overflow) == ast::diagnostic_id::macro_overflow);
    CHECK(std::string_view(codes::bad_tree) == ast::diagnostic_id::macro_bad_tree);
    for (const std::string_view id : ast::diagnostic_id::kAll) {
        if (!id.starts_with("M01")) continue;
        const int number = std::stoi(std::string(id.substr(1)));
        INFO(id);
        CHECK(std::any_of(std::begin(alarms::kAlarms), std::end(alarms::kAlarms),
                          [&](const alarms::AlarmDef& a) { return a.number == number; }));
    }
    // kerf's own numbers stay outside the controls' ranges, and the interpreter's names are these.
    CHECK(interpreter::kerf_alarm::step_limit == alarms::step_limit);
    CHECK(interpreter::kerf_alarm::move_limit == alarms::move_limit);
    CHECK(interpreter::kerf_alarm::time_limit == alarms::time_limit);
    CHECK(interpreter::kerf_alarm::unknown_variable == alarms::unknown_variable);
    CHECK(interpreter::kerf_warning::not_modelled == alarms::not_modelled);
    CHECK(interpreter::kerf_warning::program_repeats == alarms::program_repeats);
}

TEST_CASE("alarm numbers are unique and sorted; docs/diagnostics.md lists each with its rule") {
    for (std::size_t i = 1; i < std::size(alarms::kAlarms); ++i) {
        INFO(alarms::kAlarms[i].name);
        CHECK(alarms::kAlarms[i - 1].number < alarms::kAlarms[i].number);
    }
    const std::string doc = diagnostics_doc();
    const std::string table = alarm_table();
    INFO("expected in docs/diagnostics.md:\n" << table);
    CHECK(doc.find(table) != std::string::npos);
}

// The alarm numbers written as literals where the dry run raises an alarm (`alarm(frame, view, 78,
// ...)`, `make_alarm(..., 62, ...)`, the arc kernel's `error(ArcErrorCode::..., 20, ...)`) are all
// named in dialects/alarms.hpp (and so documented). Numbers raised through a named constant are
// checked by the cases above.
TEST_CASE("every alarm number the interpreter and the motion kernel raise as a literal is in dialects/alarms.hpp") {
    const std::regex call(R"(\b(?:make_)?alarm\(([^";{}]*?)(?:"|fmt::))");
    const std::regex arc(R"(error\(ArcErrorCode::\w+, (\d+))");
    const std::regex number(R"((?:^|[^\w.])(\d{2,5})(?![\w.]))");
    std::set<int> raised;
    for (const char* folder : {"interpreter", "motion"}) {
        for (const auto& e : std::filesystem::recursive_directory_iterator(std::filesystem::path(KERF_SOURCE_DIR) / folder)) {
            if (e.path().extension() != ".cpp" && e.path().extension() != ".hpp") continue;
            const std::string text = test::read_text(e.path());
            for (auto it = std::sregex_iterator(text.begin(), text.end(), call); it != std::sregex_iterator(); ++it) {
                const std::string args = (*it)[1].str();
                for (auto n = std::sregex_iterator(args.begin(), args.end(), number); n != std::sregex_iterator(); ++n)
                    raised.insert(std::stoi((*n)[1].str()));
            }
            for (auto it = std::sregex_iterator(text.begin(), text.end(), arc); it != std::sregex_iterator(); ++it)
                raised.insert(std::stoi((*it)[1].str()));
        }
    }
    // The scan finds the alarms written as literals today (078 in executor_motion.cpp, 020 in motion/arc.cpp,
    // 3012 in cycles/spinner.cpp): a scan that finds nothing would check nothing.
    CHECK(raised.count(78) == 1);
    CHECK(raised.count(20) == 1);
    CHECK(raised.count(3012) == 1);
    for (const int n : raised) {
        INFO("alarm " << n << " is raised but not named in dialects/alarms.hpp");
        CHECK(std::any_of(std::begin(alarms::kAlarms), std::end(alarms::kAlarms),
                          [&](const alarms::AlarmDef& a) { return a.number == n; }));
    }
}
