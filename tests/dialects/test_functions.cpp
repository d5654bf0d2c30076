// The function vocabulary (dialects/functions.hpp): sorted and unique (the compile-time lookup
// needs it), equal to docs/functions.md, used by every built-in code, and spelt only in
// functions.hpp (code names ids through the typed constants).
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "dialects/dialect.hpp"
#include "tests/shared_files.hpp"

using namespace kerf::dialects;
namespace fn = kerf::dialects::functions;

TEST_CASE("the vocabulary is sorted, unique and found by name") {
    const auto all = FunctionId::all();
    REQUIRE(all.size() >= 238);
    for (std::size_t i = 1; i < all.size(); ++i) {
        INFO(all[i - 1].id << " < " << all[i].id);
        CHECK(all[i - 1].id < all[i].id);
    }
    for (const FunctionDef& d : all) {
        INFO(d.id);
        const auto f = FunctionId::find(d.id);
        REQUIRE(f.has_value());
        CHECK(f->name() == d.id);
        CHECK((d.letter == 'G' || d.letter == 'M'));
        CHECK_FALSE(d.meaning.empty());
    }
    CHECK_FALSE(FunctionId::find("linaer").has_value());
    CHECK_FALSE(FunctionId::find("").has_value());
    CHECK(FunctionId{}.empty());
    CHECK(fn::linear.name() == "linear");
    CHECK(fn::css_on.name() == "constant-surface-speed");
    CHECK(closest_function_id("rough-turnig-cycle") == std::optional<std::string_view>("rough-turning-cycle"));
    CHECK_FALSE(closest_function_id("tool-change-please-now").has_value());   // too far from any id to guess
}

// The traits that replaced string heuristics: each checked on the codes the reference names.
TEST_CASE("per-code traits come from the function and the group") {
    const Dialect& a = *builtin_registry().find("fanuc-lathe-a");
    const Dialect& c = *builtin_registry().find("fanuc-lathe-c");
    const Dialect& mill = *builtin_registry().find("fanuc-mill");
    const Dialect& spinner = *builtin_registry().find("spinner-lathe-a");
    // P/Q labels: G70–G73 in A, G72–G75 in C (cycles.md §1–§4; gcode-tables.md §1).
    for (const char* code : {"G70", "G71", "G72", "G73"}) CHECK(a.code(code)->has(traits::profile_cycle));
    for (const char* code : {"G72", "G73", "G74", "G75"}) CHECK(c.code(code)->has(traits::profile_cycle));
    CHECK_FALSE(a.code("G74")->has(traits::profile_cycle));   // face peck: P/Q are depths
    CHECK_FALSE(c.code("G70")->has(traits::profile_cycle));   // C G70 is inch input
    // Cycles: the "-cycle" ids and the SPINNER ones whose ids do not say so (cycles.md §15, §17).
    CHECK(a.code("G76")->has(traits::cycle));
    CHECK(spinner.code("G384")->has(traits::cycle));
    CHECK(spinner.code("G380")->has(traits::cycle));
    CHECK(spinner.code("G100")->has(traits::cycle));
    CHECK(spinner.code("M329")->has(traits::cycle));
    CHECK_FALSE(mill.code("G80")->has(traits::cycle));   // canned-cycle-cancel
    // Group traits: G04 one-shot (group 00), G01 the motion group, M codes neither.
    CHECK(a.code("G04")->has(traits::one_shot));
    CHECK(a.code("G01")->has(traits::motion_group));
    CHECK(a.code("G01")->has(traits::linear));
    CHECK_FALSE(a.code("M03")->has(traits::one_shot | traits::motion_group));
    // Planes, offsets, work systems.
    CHECK(mill.code("G17")->plane() == PlaneTrait::xy);
    CHECK(mill.code("G18")->plane() == PlaneTrait::zx);
    CHECK(mill.code("G19")->plane() == PlaneTrait::yz);
    CHECK(mill.code("G01")->plane() == PlaneTrait::none);
    CHECK(mill.code("G45")->position_offset() == 1);    // semantics.md §9.3: +D
    CHECK(mill.code("G46")->position_offset() == -1);
    CHECK(mill.code("G47")->position_offset() == 2);
    CHECK(mill.code("G48")->position_offset() == -2);
    CHECK(mill.code("G54")->work_coordinate() == 1);
    CHECK(mill.code("G59")->work_coordinate() == 6);
    CHECK(mill.code("G54.1")->work_coordinate() == 0);
    CHECK(mill.code("G65")->has(traits::takes_arguments));
    CHECK(mill.code("M98")->has(traits::calls_subprogram));
    // Threading: G32 (A), G33 (C), the thread cycles, and G34 variable lead.
    for (const char* code : {"G32", "G92", "G76", "G34"}) CHECK(a.code(code)->has(traits::threading));
    CHECK(c.code("G33")->has(traits::threading));
    CHECK_FALSE(c.code("G92")->has(traits::threading));   // C G92 is coordinate setting
}

TEST_CASE("modal groups are indexed: one slot per group, in the order of the group names") {
    const Dialect& a = *builtin_registry().find("fanuc-lathe-a");
    const auto groups = a.groups();
    REQUIRE_FALSE(groups.empty());
    CHECK(groups[0].empty());
    CHECK(std::is_sorted(groups.begin(), groups.end()));
    for (const CodeInfo& c : a.codes()) {
        INFO(c.spelling);
        REQUIRE(c.group_index < groups.size());
        CHECK(groups[c.group_index] == c.group);
    }
    CHECK(a.code("G00")->group_index == a.code("G01")->group_index);
    CHECK(a.code("G00")->group_index != a.code("G96")->group_index);
}

TEST_CASE("every id of the vocabulary is in docs/functions.md, with the codes the dialects give it") {
    const std::string doc = kerf::test::read_text(std::filesystem::path(KERF_SOURCE_DIR) / "docs/functions.md");
    const std::size_t at = doc.find("## G-code functions");
    REQUIRE(at != std::string::npos);
    const std::string expected = function_tables_markdown(builtin_registry());
    // On a difference: `kerf dialects --functions` prints the tables to paste from that heading on.
    INFO("regenerate with: kerf dialects --functions");
    CHECK(doc.substr(at) == expected);
}

TEST_CASE("every built-in code names an id of the vocabulary; every G/M id is listed under its letter") {
    std::set<std::string_view> used;
    for (const std::string& id : builtin_registry().ids())
        for (const CodeInfo& c : builtin_registry().find(id)->codes()) {
            INFO(id << " " << c.spelling);
            CHECK_FALSE(c.function.empty());
            CHECK(c.function.def().letter == c.letter);
            used.insert(c.function.name());
        }
    // Ids no built-in dialect uses are for user dialect files; name them here when one is added.
    std::set<std::string_view> unused;
    for (const FunctionDef& d : FunctionId::all())
        if (!used.count(d.id)) unused.insert(d.id);
    // local-subprogram-call and machine-builder-code were unused until the Haas dialects (issue 15).
    CHECK(unused.empty());
}

// Code names function ids through dialects/functions.hpp's typed constants: a string literal that is
// an id elsewhere in the source would bypass the compile-time check (issue 13 counted 35 of them).
// "rapid", "linear" and "dwell" are also event kinds and machine switch values, so they are allowed.
TEST_CASE("no function-id string literals outside dialects/functions.hpp") {
    namespace fs = std::filesystem;
    const fs::path root(KERF_SOURCE_DIR);
    std::set<std::string, std::less<>> ids;
    for (const FunctionDef& d : FunctionId::all()) ids.emplace(d.id);
    for (const char* generic : {"rapid", "linear", "dwell"}) ids.erase(generic);
    const std::regex literal("\"([a-z0-9]+(?:-[a-z0-9]+)*)\"");
    std::vector<std::string> found;
    for (const auto& top : fs::directory_iterator(root)) {
        const std::string name = top.path().filename().string();
        if (!top.is_directory() || name.starts_with('.') || name.starts_with("build") || name == "tests") continue;
        for (const auto& e : fs::recursive_directory_iterator(top.path())) {
            const std::string ext = e.path().extension().string();
            if (!e.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
            if (e.path() == root / "dialects" / "functions.hpp") continue;
            const std::string text = kerf::test::read_text(e.path());
            for (auto it = std::sregex_iterator(text.begin(), text.end(), literal); it != std::sregex_iterator(); ++it)
                if (ids.count((*it)[1].str()))
                    found.push_back(fs::relative(e.path(), root).string() + ": \"" + (*it)[1].str() + "\"");
        }
    }
    for (const std::string& f : found) UNSCOPED_INFO(f);
    CHECK(found.empty());
}
