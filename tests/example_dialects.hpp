// Which dialect each reference example is run under, for every test that reads the examples
// (tests/golden_ast_test.cpp, tests/interpreter/test_golden_trace.cpp).
//
// The mapping is kept in one place: the first line "# dialect: <id>" of the example's typed-AST
// golden, tests/golden/ast/<example>.expected. That id is the dialect named in the example's
// `(DIALECT: …)` header line, reviewed with the golden (tests/golden/ast/REVIEW.md).
#pragma once

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

namespace kerf::tests {

// "# dialect: spinner-lathe-a" → "spinner-lathe-a"; nullopt when the line has another form.
inline std::optional<std::string> parse_dialect_line(std::string_view line) {
    constexpr std::string_view prefix = "# dialect: ";
    if (line.substr(0, prefix.size()) != prefix) return std::nullopt;
    std::string id(line.substr(prefix.size()));
    while (!id.empty() && (id.back() == ' ' || id.back() == '\r')) id.pop_back();
    if (id.empty()) return std::nullopt;
    return id;
}

// The dialect of a reference example ("001_O0001_facing.nc"), read from its AST golden under
// `source_dir` (the repository root); nullopt when the example has no AST golden.
inline std::optional<std::string> example_dialect(const std::filesystem::path& source_dir, std::string_view example) {
    const std::filesystem::path golden =
        source_dir / "tests" / "golden" / "ast" / (std::string(example) + ".expected");
    std::ifstream in(golden, std::ios::binary);
    std::string first;
    if (!in || !std::getline(in, first)) return std::nullopt;
    return parse_dialect_line(first);
}

}  // namespace kerf::tests
