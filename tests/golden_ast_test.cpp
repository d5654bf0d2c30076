// Golden tests of the typed AST (ast::to_text) on the reference examples.
//
// Every tests/golden/ast/<example>.expected holds, after a first line "# dialect: <id>" (the dialect
// mapping of the examples, shared through tests/example_dialects.hpp), the exact
// text tree that `kerf parse <example> --dialect <id>` prints on stdout. The example itself is read
// from KERF_SHARED_DIR/reference/examples/<example>. Each golden was reviewed line by line against
// the reference (tests/golden/ast/REVIEW.md says what was checked and which examples are left out
// because kerf is still wrong on them).
//
// To re-generate the goldens after an intended change of the output, run the test with
// KERF_UPDATE_GOLDEN=1 in the environment, then review the `git diff` of tests/golden/ast.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ast/dump.hpp"
#include "ast/source.hpp"
#include "ast/typed.hpp"
#include "dialects/dialect.hpp"
#include "grammar/parse.hpp"
#include "tests/example_dialects.hpp"
#include "tests/golden_diff.hpp"

namespace fs = std::filesystem;

namespace {

using kerf::test::line_diff;
using kerf::test::split_lines;

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

struct Golden {
    std::string dialect;
    std::string text;   // everything after the first line
};

// Returns false (with the reason in `error`) when the first line is not "# dialect: <id>".
bool read_golden(const fs::path& path, Golden& golden, std::string& error) {
    const std::string all = read_text(path);
    const std::size_t eol = all.find('\n');
    const auto dialect = eol == std::string::npos ? std::nullopt : kerf::tests::parse_dialect_line(all.substr(0, eol));
    if (!dialect) {
        error = "the first line must be '# dialect: <id>'";
        return false;
    }
    golden.dialect = *dialect;
    golden.text = all.substr(eol + 1);
    return true;
}

// What `kerf parse FILE --dialect ID` prints on stdout, produced through the library.
std::string typed_text(std::string source, const kerf::dialects::Dialect& dialect) {
    kerf::ast::SyntaxTree tree = kerf::grammar::parse(std::move(source), dialect.lexical);
    const kerf::ast::TypedFile typed = kerf::ast::TypedFile::bind(tree, dialect);
    const kerf::ast::LineIndex lines(tree.text);
    return kerf::ast::to_text(typed, lines);
}

}  // namespace

TEST_CASE("typed AST of the reference examples matches the reviewed goldens", "[golden][ast]") {
#ifndef KERF_SHARED_DIR
    WARN("KERF_SHARED_DIR is not defined: the golden AST tests need ../shared/reference/examples; skipped");
    return;
#else
    const fs::path golden_dir = fs::path(KERF_SOURCE_DIR) / "tests" / "golden" / "ast";
    const fs::path examples = fs::path(KERF_SHARED_DIR) / "reference" / "examples";
    if (!fs::is_directory(examples)) {
        WARN("no reference examples at " << examples.string() << " (KERF_SHARED_DIR absent): golden AST tests skipped");
        return;
    }
    REQUIRE(fs::is_directory(golden_dir));

    std::vector<fs::path> goldens;
    for (const fs::directory_entry& e : fs::directory_iterator(golden_dir))
        if (e.is_regular_file() && e.path().extension() == ".expected") goldens.push_back(e.path());
    std::sort(goldens.begin(), goldens.end());

    const bool update = std::getenv("KERF_UPDATE_GOLDEN") != nullptr;
    std::size_t checked = 0;
    std::vector<std::string> failed;
    for (const fs::path& path : goldens) {
        const std::string name = path.stem().string();   // "<example>.nc"
        INFO("golden " << path.filename().string());
        Golden golden;
        std::string error;
        if (!read_golden(path, golden, error)) {
            FAIL_CHECK(path.filename().string() << ": " << error);
            failed.push_back(name);
            continue;
        }
        const kerf::dialects::Dialect* dialect = kerf::dialects::builtin_registry().find(golden.dialect);
        if (!dialect) {
            FAIL_CHECK(name << ": unknown dialect '" << golden.dialect << "' in the first line");
            failed.push_back(name);
            continue;
        }
        const fs::path example = examples / name;
        if (!fs::is_regular_file(example)) {
            FAIL_CHECK(name << ": the example " << example.string() << " does not exist");
            failed.push_back(name);
            continue;
        }
        const std::string actual = typed_text(read_text(example), *dialect);
        ++checked;
        if (update && actual != golden.text) {
            std::ofstream(path, std::ios::binary) << "# dialect: " << golden.dialect << "\n" << actual;
            WARN(name << ": golden rewritten (KERF_UPDATE_GOLDEN); review the diff before committing");
            continue;
        }
        const std::string diff = line_diff(golden.text, actual);
        if (!diff.empty()) {
            FAIL_CHECK(name << " (dialect " << golden.dialect << ") differs from its golden:\n" << diff);
            failed.push_back(name);
        }
    }

    INFO("golden files checked: " << checked << " of " << goldens.size());
    REQUIRE(checked >= 30);
    INFO("failed: " << failed.size());
    REQUIRE(failed.empty());
#endif
}

TEST_CASE("golden diff helper reports the first differing lines", "[golden]") {
    CHECK(line_diff("a\nb\n", "a\nb\n").empty());
    const std::string d = line_diff("a\nb\nc\n", "a\nB\nc\n");
    CHECK(d.find("-b\n") != std::string::npos);
    CHECK(d.find("+B\n") != std::string::npos);
    CHECK(!line_diff("a\n", "a").empty());
}
