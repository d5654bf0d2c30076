#include "grammar/detect.hpp"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <optional>
#include <map>

#include "ast/source.hpp"
#include "dialects/dialect.hpp"
#include "grammar/parse.hpp"

namespace kerf::grammar {
namespace {

// Lexical rules that read every dialect's text without losing words: ';' ends blocks, ADV400 line
// comments are comments, macros on, comma words on.
dialects::LexicalRules permissive_rules() {
    dialects::LexicalRules r;
    r.line_comments = {"::", ";;"};
    r.comma_words = "ACR";
    r.macro_b = true;
    return r;
}

struct Evidence {
    std::map<std::string, int> score;
    std::vector<std::string> reasons;
    std::map<std::string, int> seen;   // one reason per kind of evidence

    void add(const std::string& what, std::uint32_t offset, const ast::LineIndex& lines,
             std::initializer_list<std::pair<const char*, int>> weights) {
        if (seen[what]++ > 0) {
            for (const auto& [d, w] : weights) score[d] += w / 4;   // repeated evidence counts, less
            return;
        }
        const ast::Position p = lines.utf8(offset);
        std::string suggests;
        for (const auto& [d, w] : weights) {
            score[d] += w;
            if (w > 0) suggests += (suggests.empty() ? "" : ", ") + std::string(d);
        }
        reasons.push_back(fmt::format("{} at {}:{} suggests {}", what, p.line + 1, p.column + 1, suggests));
    }
};

// "(DIALECT: spinner-lathe-a - live tools)" → "spinner-lathe-a": the id after the tag, up to the
// first character that cannot be part of an id.
std::string_view id_after_tag(std::string_view comment) {
    constexpr std::string_view tag = "DIALECT:";
    if (comment.starts_with('(')) comment.remove_prefix(1);
    while (!comment.empty() && comment.front() == ' ') comment.remove_prefix(1);
    if (comment.size() < tag.size()) return {};
    for (std::size_t i = 0; i < tag.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(comment[i])) != tag[i]) return {};
    comment.remove_prefix(tag.size());
    while (!comment.empty() && comment.front() == ' ') comment.remove_prefix(1);
    std::size_t n = 0;
    while (n < comment.size() && (std::isalnum(static_cast<unsigned char>(comment[n])) || comment[n] == '-')) ++n;
    return comment.substr(0, n);
}

// A header comment naming a known dialect id decides (the reference examples carry one:
// reference/README.md "Example files", `(DIALECT: <dialect id> [- machine options])`). Only the
// comment-only blocks before the first word count: a comment further down is about something else.
std::optional<Detection> header_dialect(const ast::SyntaxTree& tree, const ast::LineIndex& lines) {
    for (std::size_t bi = 0; bi < tree.block_count(); ++bi) {
        for (const ast::Token& t : tree.block_tokens(bi)) {
            if (t.kind == ast::TokenKind::word) return std::nullopt;
            if (t.kind != ast::TokenKind::comment) continue;
            const std::string_view id = id_after_tag(tree.spelling(t));
            if (id.empty() || !dialects::builtin_registry().find(id)) continue;
            const ast::Position p = lines.utf8(t.begin);
            Detection d;
            d.dialect = std::string(id);
            d.confidence = 100;
            d.reasons.push_back(fmt::format("header comment at {}:{} names the dialect {} (decisive)", p.line + 1,
                                            p.column + 1, id));
            return d;
        }
    }
    return std::nullopt;
}

}  // namespace

Detection detect_dialect(std::string_view text) {
    // The evidence of a program is in its first lines (headers, first tool, first moves); reading
    // a 100 MB program to the end would cost a whole second parse. Whole lines only.
    constexpr std::size_t kEnough = std::size_t{256} << 10;
    if (text.size() > kEnough) {
        const std::size_t cut = ast::last_line_end_before(text, kEnough);
        text = text.substr(0, cut == std::string_view::npos ? kEnough : cut);
    }
    const ast::SyntaxTree tree = parse(std::string(text), permissive_rules());
    const ast::LineIndex lines(tree.text);
    if (std::optional<Detection> header = header_dialect(tree, lines)) return *std::move(header);
    Evidence ev;
    bool has_y = false;
    for (std::size_t bi = 0; bi < tree.block_count(); ++bi) {
        const auto tokens = tree.block_tokens(bi);
        auto has_letter = [&](char L) {
            for (const ast::Token& t : tokens)
                if (t.kind == ast::TokenKind::word && t.letter == L) return true;
            return false;
        };
        auto code_in_block = [&](char L, int whole, int tenth = 0) {
            for (const ast::Token& t : tokens) {
                if (t.kind != ast::TokenKind::word || t.letter != L || !t.is_number()) continue;
                const double v = tree.number_value(t);
                if (static_cast<int>(v * 10 + 0.5) == whole * 10 + tenth) return true;
            }
            return false;
        };
        for (const ast::Token& t : tokens) {
            if (t.kind == ast::TokenKind::comment) {
                const std::string_view s = tree.spelling(t);
                if (s.starts_with("::") || s.starts_with(";;"))
                    ev.add("'" + std::string(s.substr(0, 2)) + "' comment", t.begin, lines,
                           {{"adv400-mill", 6}, {"adv400-lathe", 6}});
            }
            // Text after ';' on the same line that does not read as a block: ';' starts a comment.
            if (t.kind == ast::TokenKind::error && bi > 0 && tree.blocks[bi - 1].has(ast::block_flags::has_eob) &&
                lines.utf8(tree.blocks[bi].begin).line == lines.utf8(tree.blocks[bi - 1].begin).line)
                ev.add("text after ';' (a comment)", t.begin, lines, {{"pcnc-mill", 6}});
            if (t.kind != ast::TokenKind::word) continue;
            switch (t.letter) {
                case 'U': case 'W':
                    ev.add(fmt::format("incremental word {}", t.letter), t.begin, lines, {{"fanuc-lathe-a", 3}});
                    break;
                case 'Y':
                    has_y = true;
                    ev.add("Y axis word", t.begin, lines, {{"fanuc-mill", 2}, {"adv400-mill", 1}, {"pcnc-mill", 1}});
                    break;
                case 'B':
                    ev.add("B axis word", t.begin, lines, {{"spinner-lathe-a", 1}});
                    break;
                default: break;
            }
        }
        const std::uint32_t at = tree.blocks[bi].begin;
        if (code_in_block('G', 50) && has_letter('S')) ev.add("G50 S (spindle clamp)", at, lines, {{"fanuc-lathe-a", 4}});
        if (code_in_block('G', 96)) ev.add("G96 (constant surface speed)", at, lines, {{"fanuc-lathe-a", 2}, {"fanuc-lathe-b", 1}});
        if (code_in_block('G', 99) && has_letter('F')) ev.add("G99 F (feed per revolution)", at, lines, {{"fanuc-lathe-a", 3}});
        for (int g : {70, 71, 72, 73, 74, 75, 76})
            if (code_in_block('G', g) && has_letter('P') && has_letter('Q'))
                ev.add(fmt::format("G{} P Q (multiple repetitive cycle)", g), at, lines, {{"fanuc-lathe-a", 4}});
        if (code_in_block('G', 91)) ev.add("G91", at, lines, {{"fanuc-lathe-b", 1}, {"fanuc-mill", 1}});
        for (int g : {77, 78, 79})
            if (code_in_block('G', g) && has_letter('Z')) ev.add(fmt::format("G{} X Z (system B single cycle; no such code in A)", g), at, lines, {{"fanuc-lathe-b", 8}});
        for (int g : {38, 138, 238, 380, 384, 100, 101})
            if (code_in_block('G', g)) ev.add(fmt::format("G{} (SPINNER cycle)", g), at, lines, {{"spinner-lathe-a", 8}});
        for (int m : {329, 432})
            if (code_in_block('M', m)) ev.add(fmt::format("M{} (SPINNER cycle)", m), at, lines, {{"spinner-lathe-a", 8}});
        if (code_in_block('G', 10) && code_in_block('P', 0) && (has_letter('Z') || has_letter('W')))
            ev.add("G10 P0 Z/W (work shift)", at, lines, {{"spinner-lathe-a", 4}});
        if (code_in_block('M', 98) && has_letter('L')) ev.add("M98 P L", at, lines, {{"adv400-mill", 3}, {"adv400-lathe", 3}});
        if (code_in_block('G', 92, 1)) ev.add("G92.1", at, lines, {{"adv400-mill", 5}});
        if (code_in_block('G', 50, 1)) ev.add("G50.1 (ADV400 coordinate cancel)", at, lines, {{"adv400-lathe", 2}});
        if (code_in_block('G', 25) || code_in_block('G', 26)) ev.add("G25/G26", at, lines, {{"adv400-mill", 2}, {"adv400-lathe", 2}});
        if (code_in_block('G', 152)) ev.add("G152", at, lines, {{"pcnc-mill", 8}});
        if (code_in_block('G', 30) && has_letter('P')) ev.add("G30 P", at, lines, {{"pcnc-mill", 3}});
        for (int g : {45, 46, 47, 48})
            if (code_in_block('G', g) && has_letter('D')) ev.add(fmt::format("G{} D (one-block offset)", g), at, lines, {{"iso-legacy-mill", 6}});
        if (code_in_block('G', 28) && has_letter('K') && has_letter('F'))
            ev.add("G28 K F (corner slow-down)", at, lines, {{"iso-legacy-mill", 8}});
        if (code_in_block('G', 43) && has_letter('H')) ev.add("G43 H", at, lines, {{"fanuc-mill", 3}});
        if (code_in_block('M', 6)) ev.add("M06 (tool change)", at, lines, {{"fanuc-mill", 3}});
        if (code_in_block('G', 17)) ev.add("G17", at, lines, {{"fanuc-mill", 1}});
    }
    // ADV400 evidence splits by axes; the SPINNER overlay needs its base.
    auto& s = ev.score;
    if (has_y) s["adv400-lathe"] -= 3; else s["adv400-mill"] -= 3;
    if (s["spinner-lathe-a"] > 0) s["spinner-lathe-a"] += s["fanuc-lathe-a"];
    Detection d;
    d.dialect = has_y ? "fanuc-mill" : "fanuc-lathe-a";
    int best = 0;
    for (const auto& [id, score] : s) {
        if (score > best) {
            best = score;
            d.dialect = id;
        }
    }
    d.confidence = best;
    d.reasons = std::move(ev.reasons);
    if (best == 0)
        d.reasons.push_back(fmt::format("no dialect evidence; {} because {}", d.dialect,
                                        has_y ? "the program has Y words" : "the program has no Y words"));
    return d;
}

}  // namespace kerf::grammar
