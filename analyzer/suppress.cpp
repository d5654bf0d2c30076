#include "analyzer/suppress.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>

namespace kerf::analyzer {

namespace {

constexpr std::string_view kMarker = "kerf:";

bool is_separator(char c) { return c == ' ' || c == '\t' || c == ',' || c == ')' || c == ';'; }

// "kerf: ignore K1001, K1020)" → {"K1001", "K1020"}; nullopt when the comment is no suppression.
std::optional<std::vector<std::string>> parse(std::string_view comment) {
    const std::size_t at = comment.find(kMarker);
    if (at == std::string_view::npos) return std::nullopt;
    std::string_view rest = comment.substr(at + kMarker.size());
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    if (!rest.starts_with("ignore")) return std::nullopt;
    rest.remove_prefix(6);
    std::vector<std::string> ids;
    while (!rest.empty()) {
        while (!rest.empty() && is_separator(rest.front())) rest.remove_prefix(1);
        std::size_t n = 0;
        while (n < rest.size() && !is_separator(rest[n])) ++n;
        if (n > 0) ids.emplace_back(rest.substr(0, n));
        rest.remove_prefix(n);
    }
    return ids;
}

}  // namespace

std::vector<Suppression> find_suppressions(const ast::SyntaxTree& tree) {
    std::vector<Suppression> out;
    bool header = true;   // no code block yet
    for (std::size_t b = 0; b < tree.block_count(); ++b) {
        const ast::BlockKind kind = tree.blocks[b].kind;
        if (kind == ast::BlockKind::code) header = false;
        for (const ast::Token& t : tree.block_tokens(b)) {
            if (t.kind != ast::TokenKind::comment) continue;
            if (auto ids = parse(tree.spelling(t))) {
                const ast::Range all{0, UINT32_MAX};   // also findings at the very end of the text
                out.push_back({header ? all : tree.block_range(b), std::move(*ids)});
            }
        }
    }
    return out;
}

bool suppressed(const std::vector<Suppression>& suppressions, const Finding& f) {
    return std::any_of(suppressions.begin(), suppressions.end(), [&](const Suppression& s) {
        if (!s.block.contains(f.range.begin)) return false;
        return s.rules.empty() || std::find(s.rules.begin(), s.rules.end(), f.rule) != s.rules.end() ||
               std::find(s.rules.begin(), s.rules.end(), f.name) != s.rules.end();
    });
}

}  // namespace kerf::analyzer
