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
    // Every suppression holds the marker: search the text for it (memchr speed, as the language
    // server finishes its findings on every keystroke of a million-line file) and look at the
    // comment around each one.
    std::vector<Suppression> out;
    const std::string_view text = tree.text;
    std::size_t first_code = tree.block_count();   // the blocks before it are the header
    for (std::size_t b = 0; b < tree.block_count(); ++b)
        if (tree.blocks[b].kind == ast::BlockKind::code) {
            first_code = b;
            break;
        }
    for (std::size_t at = text.find(kMarker); at != std::string_view::npos; at = text.find(kMarker, at + 1)) {
        const auto block = std::upper_bound(tree.blocks.begin(), tree.blocks.end(), at,
                                            [](std::size_t offset, const ast::Block& b) { return offset < b.begin; });
        if (block == tree.blocks.begin()) continue;
        const auto b = static_cast<std::size_t>(block - tree.blocks.begin() - 1);
        for (const ast::Token& t : tree.block_tokens(b)) {
            if (t.kind != ast::TokenKind::comment || !tree.range(t).contains(static_cast<std::uint32_t>(at))) continue;
            // The first marker of the comment decides (parse), once.
            if (tree.spelling(t).find(kMarker) != at - t.begin) break;
            if (auto ids = parse(tree.spelling(t))) {
                const ast::Range all{0, UINT32_MAX};   // also findings at the very end of the text
                out.push_back({b < first_code ? all : tree.block_range(b), std::move(*ids)});
            }
            break;
        }
    }
    return out;
}

bool suppressed(const std::vector<Suppression>& suppressions, std::uint32_t at, std::string_view rule, std::string_view name) {
    return std::any_of(suppressions.begin(), suppressions.end(), [&](const Suppression& s) {
        if (!s.block.contains(at)) return false;
        return s.rules.empty() || std::find(s.rules.begin(), s.rules.end(), rule) != s.rules.end() ||
               std::find(s.rules.begin(), s.rules.end(), name) != s.rules.end();
    });
}

bool suppressed(const std::vector<Suppression>& suppressions, const Finding& f) {
    return suppressed(suppressions, f.range.begin, f.rule, f.name);
}

}  // namespace kerf::analyzer
