// The line diff the golden tests print when a golden and the output differ (tests/golden_ast_test.cpp,
// tests/interpreter/test_golden_trace.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace kerf::test {

inline std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        if (end == std::string::npos) {
            lines.push_back(text.substr(start));
            break;
        }
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

// A unified-style line diff (LCS; the goldens are small). Returns "" when equal.
inline std::string line_diff(const std::string& expected, const std::string& actual) {
    if (expected == actual) return {};
    const std::vector<std::string> a = split_lines(expected);
    const std::vector<std::string> b = split_lines(actual);
    const std::size_t n = a.size();
    const std::size_t m = b.size();
    std::vector<std::vector<std::uint32_t>> lcs(n + 1, std::vector<std::uint32_t>(m + 1, 0));
    for (std::size_t i = n; i-- > 0;)
        for (std::size_t j = m; j-- > 0;)
            lcs[i][j] = a[i] == b[j] ? lcs[i + 1][j + 1] + 1 : std::max(lcs[i + 1][j], lcs[i][j + 1]);
    struct Line {
        char tag;
        std::string text;
    };
    std::vector<Line> script;
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < n || j < m) {
        if (i < n && j < m && a[i] == b[j]) {
            script.push_back({' ', a[i]});
            ++i;
            ++j;
        } else if (i < n && (j == m || lcs[i + 1][j] >= lcs[i][j + 1])) {
            script.push_back({'-', a[i++]});
        } else {
            script.push_back({'+', b[j++]});
        }
    }
    // Print changed lines with two lines of context; at most 60 lines.
    std::ostringstream out;
    out << "--- expected\n+++ actual (kerf now)\n";
    if (a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin()))
        out << "(the texts differ only in the final line break)\n";
    std::vector<bool> show(script.size(), false);
    for (std::size_t k = 0; k < script.size(); ++k) {
        if (script[k].tag == ' ') continue;
        for (std::size_t c = (k >= 2 ? k - 2 : 0); c <= std::min(script.size() - 1, k + 2); ++c) show[c] = true;
    }
    int printed = 0;
    bool gap = false;
    for (std::size_t k = 0; k < script.size(); ++k) {
        if (!show[k]) {
            gap = true;
            continue;
        }
        if (gap) out << "@@\n";
        gap = false;
        if (++printed > 60) {
            out << "... (diff truncated)\n";
            break;
        }
        out << script[k].tag << script[k].text << "\n";
    }
    return out.str();
}

// The values of `key = "value"` / `key = true` lines of a golden case's .toml (the format and
// convert goldens), in order: a key may repeat (`report = ...`).
inline std::vector<std::string> golden_values(const std::string& toml, const std::string& key) {
    std::vector<std::string> out;
    const std::string prefix = key + " = ";
    for (const std::string& line : split_lines(toml)) {
        if (line.rfind(prefix, 0) != 0) continue;
        std::string v = line.substr(prefix.size());
        if (!v.empty() && v.front() == '"') v = v.substr(1, v.size() - 2);
        out.push_back(v);
    }
    return out;
}

inline std::string golden_value(const std::string& toml, const std::string& key, const std::string& fallback = "") {
    const std::vector<std::string> v = golden_values(toml, key);
    return v.empty() ? fallback : v.front();
}

}  // namespace kerf::test
