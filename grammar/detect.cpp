#include "grammar/detect.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <map>

#include "ast/source.hpp"
#include "grammar/parse.hpp"

namespace kerf::grammar {

namespace detail {

std::vector<std::uint32_t> line_clue_offsets(std::string_view text, std::string_view pattern, bool prefix) {
    std::vector<std::uint32_t> out;
    constexpr std::string_view kBreaks = "\r\n";
    const auto blank = [](char c) { return c == ' ' || c == '\t'; };
    if (pattern.find_first_of(kBreaks) != std::string_view::npos) return out;   // no line holds a break
    const auto line_start = [&](std::size_t at) {
        const std::size_t before = at == 0 ? std::string_view::npos : text.find_last_of(kBreaks, at - 1);
        std::size_t begin = before == std::string_view::npos ? 0 : before + 1;
        while (begin < text.size() && blank(text[begin])) ++begin;
        return begin;
    };
    const auto line_end = [&](std::size_t at) {
        const std::size_t end = text.find_first_of(kBreaks, at);
        return end == std::string_view::npos ? text.size() : end;
    };
    if (pattern.empty()) {   // every line that is not blank
        for (std::size_t at = 0; at < text.size(); at = line_end(at) + 1) {
            std::size_t begin = at;
            while (begin < text.size() && blank(text[begin])) ++begin;
            if (begin < line_end(at)) out.push_back(static_cast<std::uint32_t>(begin));
        }
        return out;
    }
    // One search of the whole text per clue: a search per line and clue was most of weighing the
    // clues of a small file (bench/RESULTS.md, the folder of 10,000 programs).
    for (std::size_t from = 0;;) {
        const std::size_t hit = text.find(pattern, from);
        if (hit == std::string_view::npos) break;
        const std::size_t begin = line_start(hit);
        if (prefix ? hit == begin : hit >= begin) {
            out.push_back(static_cast<std::uint32_t>(begin));
            from = line_end(hit);   // a line counts once
        } else {
            // A prefix clue: the line's start came first in the search and did not match. A
            // contained one: the hit lay in the blanks before the line's first character.
            from = prefix ? line_end(hit) : hit + 1;
        }
    }
    return out;
}

}  // namespace detail

namespace {

using dialects::DetectClue;

// Lexical rules that read every dialect's text without losing words: ';' ends blocks, ADV400 line
// comments are comments, macros on, comma words on.
dialects::LexicalRules permissive_rules() {
    dialects::LexicalRules r;
    r.line_comments = {"::", ";;"};
    r.comma_words = "ACR";
    r.macro_b = true;
    r.if_words = true;   // Haas IF [...] G65: its words are evidence too
    return r;
}

struct Word {
    std::uint32_t block;
    std::uint32_t offset;
    bool number;
    double value;
    std::optional<dialects::CodeKey> key;   // dialects::code_key(value), once: every dialect's code clues compare it
};

// What a file says, read once from the permissive tree; every dialect's clues are weighed against it.
struct Facts {
    std::array<std::vector<Word>, 26> words;                            // by letter, in text order
    std::vector<std::uint32_t> block_begin;                              // per block
    // Per block: letter, value (NaN: no number); block b's words are [word_start[b], word_start[b + 1])
    // of one flat array (a vector per block was a third of a small file's detection in malloc/free).
    std::vector<std::pair<char, double>> block_words;
    std::vector<std::uint32_t> word_start;
    std::vector<std::pair<std::string_view, std::uint32_t>> comments;    // text, offset
    std::vector<std::pair<std::string, std::uint32_t>> header;           // comments before the first code, upper case
    std::vector<std::pair<double, std::uint32_t>> variables;             // #n with a plain number n
    std::vector<std::uint32_t> prose_after_semicolon;                    // offsets
    std::string_view text;                                                // the source, for the line clues
    // The G and M words with a code key, by key, then text order (index into words[letter]): every
    // dialect's code clues look their code up here (a scan of the words per clue and dialect was a
    // fifth of a small file's check).
    std::array<std::vector<std::pair<dialects::CodeKey, std::uint32_t>>, 2> codes;   // G, M
    const std::vector<std::pair<dialects::CodeKey, std::uint32_t>>* codes_of(char letter) const {
        return letter == 'G' ? &codes[0] : letter == 'M' ? &codes[1] : nullptr;
    }
};

bool letter_ok(char L) { return L >= 'A' && L <= 'Z'; }

std::string upper(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

Facts read_facts(const ast::SyntaxTree& tree, const ast::LineIndex& lines) {
    Facts f;
    bool in_header = true;
    f.word_start.reserve(tree.block_count() + 1);
    f.block_begin.resize(tree.block_count());
    for (std::size_t bi = 0; bi < tree.block_count(); ++bi) {
        const auto b = static_cast<std::uint32_t>(bi);
        f.block_begin[bi] = tree.blocks[bi].begin;
        f.word_start.push_back(static_cast<std::uint32_t>(f.block_words.size()));
        for (const ast::Token& t : tree.block_tokens(bi)) {
            if (t.kind == ast::TokenKind::comment) {
                f.comments.emplace_back(tree.spelling(t), t.begin);
                if (in_header) f.header.emplace_back(upper(tree.spelling(t)), t.begin);
            }
            // Text after ';' on the same line that does not read as a block: ';' starts a comment.
            if (t.kind == ast::TokenKind::error && bi > 0 && tree.blocks[bi - 1].has(ast::block_flags::has_eob) &&
                lines.utf8(tree.blocks[bi].begin).line == lines.utf8(tree.blocks[bi - 1].begin).line)
                f.prose_after_semicolon.push_back(t.begin);
            if (t.kind != ast::TokenKind::word || !letter_ok(t.letter)) continue;
            // The header ends at the first word that is not a program or sequence number.
            if (t.letter != 'O' && t.letter != 'N') in_header = false;
            const bool number = t.is_number();
            const double value = number ? tree.number_value(t) : std::numeric_limits<double>::quiet_NaN();
            f.words[static_cast<std::size_t>(t.letter - 'A')].push_back(
                {b, t.begin, number, value, number ? dialects::code_key(value) : std::nullopt});
            f.block_words.emplace_back(t.letter, value);
        }
    }
    f.text = tree.text;
    for (const ast::Expr& e : tree.exprs) {
        if (e.kind != ast::ExprKind::variable || e.a < 0) continue;
        const ast::Expr& n = tree.exprs[static_cast<std::size_t>(e.a)];
        if (n.kind == ast::ExprKind::number) f.variables.emplace_back(tree.number_value(n), e.begin);
    }
    f.word_start.push_back(static_cast<std::uint32_t>(f.block_words.size()));
    for (const char letter : {'G', 'M'}) {
        auto& keyed = f.codes[letter == 'G' ? 0 : 1];
        const std::vector<Word>& words = f.words[static_cast<std::size_t>(letter - 'A')];
        for (std::uint32_t i = 0; i < words.size(); ++i)
            if (words[i].number && words[i].key) keyed.emplace_back(*words[i].key, i);
        std::sort(keyed.begin(), keyed.end());
    }
    return f;
}

// The G65/G66 blocks of dialect `d` (its codes with traits::takes_arguments): their words are
// macro arguments (`W#23` is argument W, not an incremental Z), so they prove nothing.
std::vector<bool> macro_call_blocks(const Facts& f, const dialects::Dialect& d) {
    std::vector<bool> out(f.block_begin.size(), false);
    for (const Word& w : f.words['G' - 'A']) {
        if (!w.number) continue;
        const dialects::CodeInfo* info = w.key ? d.fast_code('G', *w.key) : nullptr;
        if (info && info->has(dialects::traits::takes_arguments)) out[w.block] = true;
    }
    return out;
}

bool block_has(const Facts& f, std::uint32_t block, char letter, std::optional<double> value = std::nullopt) {
    for (std::uint32_t i = f.word_start[block]; i < f.word_start[block + 1]; ++i)
        if (const auto& [L, v] = f.block_words[i]; L == letter && (!value || v == *value)) return true;
    return false;
}

bool block_has_any(const Facts& f, std::uint32_t block, std::string_view letters) {
    return std::any_of(letters.begin(), letters.end(), [&](char L) { return block_has(f, block, L); });
}

// The offsets where a clue holds (text order); one entry at offset ~0u for a clue about the whole file.
std::vector<std::uint32_t> occurrences(const DetectClue& c, const Facts& f, const std::vector<bool>& macro_calls) {
    std::vector<std::uint32_t> at;
    switch (c.kind) {
        case DetectClue::Kind::code: {
            const std::vector<Word>& words = f.words[static_cast<std::size_t>(c.letter - 'A')];
            const auto holds = [&](const Word& w) {
                bool ok = true;
                for (const auto& [L, v] : c.with) ok &= block_has(f, w.block, L, v);
                if (!c.with_any.empty()) ok &= block_has_any(f, w.block, c.with_any);
                if (!c.without.empty()) ok &= !block_has_any(f, w.block, c.without);
                if (ok) at.push_back(f.block_begin[w.block]);
            };
            if (const auto* keyed = f.codes_of(c.letter)) {
                const auto lo = std::lower_bound(keyed->begin(), keyed->end(), std::make_pair(c.key, std::uint32_t{0}));
                for (auto it = lo; it != keyed->end() && it->first == c.key; ++it) holds(words[it->second]);
                break;
            }
            for (const Word& w : words)
                if (w.number && w.key == std::optional<dialects::CodeKey>(c.key)) holds(w);
            break;
        }
        case DetectClue::Kind::word:
            for (const Word& w : f.words[static_cast<std::size_t>(c.letter - 'A')])
                if (!macro_calls[w.block]) at.push_back(w.offset);
            break;
        case DetectClue::Kind::absent_word: {
            bool present = false, given = false;
            for (const Word& w : f.words[static_cast<std::size_t>(c.letter - 'A')]) present |= !macro_calls[w.block];
            for (const char L : c.with_any)
                for (const Word& w : f.words[static_cast<std::size_t>(L - 'A')]) given |= !macro_calls[w.block];
            if (!present && given) at.push_back(~0u);
            break;
        }
        case DetectClue::Kind::comment:
            for (const auto& [text, offset] : f.comments)
                if (text.starts_with(c.text)) at.push_back(offset);
            break;
        case DetectClue::Kind::header: {
            const std::string wanted = upper(c.text);
            for (const auto& [text, offset] : f.header)
                if (text.find(wanted) != std::string::npos) at.push_back(offset);
            break;
        }
        case DetectClue::Kind::variable:
            for (const auto& [n, offset] : f.variables)
                if (n >= static_cast<double>(c.from) && n <= static_cast<double>(c.to)) at.push_back(offset);
            break;
        case DetectClue::Kind::lexical:
            at = f.prose_after_semicolon;   // the one observation the schema knows
            break;
        case DetectClue::Kind::line:
            at = detail::line_clue_offsets(f.text, c.text, c.line_prefix);
            break;
    }
    return at;
}

// A repeated clue counts, less: a quarter of its weight for each further occurrence.
int points(int weight, std::size_t count) { return count == 0 ? 0 : weight + static_cast<int>(count - 1) * (weight / 4); }

struct Score {
    const dialects::Dialect* dialect;
    int total = 0;
    int own = 0;   // the overlay's own clues (DetectRules::needs_own)
    std::vector<Clue> clues;
};

Score weigh(const dialects::Dialect& d, const Facts& f, const ast::LineIndex& lines) {
    Score s{&d, 0, 0, {}};
    // Only the word clues ask which blocks are macro calls: no table for a dialect without any.
    const bool word_clues = std::any_of(d.detect.clues.begin(), d.detect.clues.end(), [](const DetectClue& c) {
        return c.kind == DetectClue::Kind::word || c.kind == DetectClue::Kind::absent_word;
    });
    const std::vector<bool> macro_calls = word_clues ? macro_call_blocks(f, d) : std::vector<bool>{};
    for (const DetectClue& c : d.detect.clues) {
        const std::vector<std::uint32_t> at = occurrences(c, f, macro_calls);
        if (at.empty()) continue;
        Clue clue;
        clue.dialect = d.id;
        clue.what = c.spelling;
        clue.proves = c.proves;
        if (at.front() != ~0u) {
            const ast::Position p = lines.utf8(at.front());
            clue.line = static_cast<int>(p.line) + 1;
            clue.column = static_cast<int>(p.column) + 1;
        }
        clue.count = static_cast<int>(at.size());
        clue.points = points(c.weight, at.size());
        s.total += clue.points;
        if (c.own) s.own += clue.points;
        s.clues.push_back(std::move(clue));
    }
    return s;
}

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

// A header comment naming a dialect of the registry decides (the reference examples carry one:
// reference/README.md "Example files", `(DIALECT: <dialect id> [- machine options])`). Only the
// comment-only blocks before the first word count: a comment further down is about something else.
std::optional<Detection> header_dialect(const ast::SyntaxTree& tree, const ast::LineIndex& lines,
                                        const dialects::Registry& registry) {
    for (std::size_t bi = 0; bi < tree.block_count(); ++bi) {
        for (const ast::Token& t : tree.block_tokens(bi)) {
            if (t.kind == ast::TokenKind::word) return std::nullopt;
            if (t.kind != ast::TokenKind::comment) continue;
            const std::string_view id = id_after_tag(tree.spelling(t));
            if (id.empty() || !registry.find(id)) continue;
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

std::string clue_line(const Clue& c) {
    const std::string where = c.line ? fmt::format("{}:{} ", c.line, c.column) : std::string("the file: ");
    const std::string times = c.count > 1 ? fmt::format(" ×{}", c.count) : std::string();
    return fmt::format("    {}{}{} ({:+d}): {}", where, c.what, times, c.points, c.proves);
}

// The registry's dialect for files without evidence: the first with `[detect] default = true`, else the first.
std::string default_dialect(const dialects::Registry& registry) {
    const std::vector<std::string> ids = registry.ids();
    for (const std::string& id : ids)
        if (registry.find(id)->detect.fallback) return id;
    return ids.empty() ? std::string() : ids.front();
}

}  // namespace

Detection detect_dialect(std::string_view text, const dialects::Registry& registry, const DetectOptions& options) {
    // The evidence of a program is in its first lines (headers, first tool, first moves); reading
    // a 100 MB program to the end would cost a whole second parse. Whole lines only.
    constexpr std::size_t kEnough = std::size_t{256} << 10;
    if (text.size() > kEnough) {
        const std::size_t cut = ast::last_line_end_before(text, kEnough);
        text = text.substr(0, cut == std::string_view::npos ? kEnough : cut);
    }
    const ast::SyntaxTree tree = parse(std::string(text), permissive_rules());
    const ast::LineIndex lines(tree.text);
    if (std::optional<Detection> header = header_dialect(tree, lines, registry)) return *std::move(header);
    const Facts facts = read_facts(tree, lines);

    std::vector<Score> scores;
    for (const std::string& id : registry.ids()) {
        const dialects::Dialect& d = *registry.find(id);
        Score s = weigh(d, facts, lines);
        // An overlay's combination (spinner-lathe-a) scores its base's clues too; it is a candidate
        // only when the overlay's own clues point to it, else it would tie with its base.
        if (d.detect.needs_own && s.own <= 0) s.total = std::min(s.total, 0);
        scores.push_back(std::move(s));
    }
    Detection out;
    // Profiles of other controls: the best one counts when it outweighs every dialect (a Syntec
    // macro reads partly as FANUC, but its ':=' and '%@MACRO' weigh more).
    std::optional<Score> foreign;
    for (const dialects::Dialect& d : registry.foreign_controls()) {
        Score s = weigh(d, facts, lines);
        if (s.total > 0 && (!foreign || s.total > foreign->total)) foreign = std::move(s);
    }
    const Score* best = nullptr;
    for (const Score& s : scores)   // ties go to the dialect registered first
        if (s.total > 0 && (!best || s.total > best->total)) best = &s;
    std::vector<const Score*> ranked;
    for (const Score& s : scores)
        if (!s.clues.empty()) ranked.push_back(&s);
    std::stable_sort(ranked.begin(), ranked.end(), [](const Score* a, const Score* b) { return a->total > b->total; });
    for (const Score* s : ranked) {
        out.scores.emplace_back(s->dialect->id, s->total);
        out.clues.insert(out.clues.end(), s->clues.begin(), s->clues.end());
    }
    if (best) {
        out.dialect = best->dialect->id;
        out.confidence = best->total;
        std::string others;
        for (const auto& [id, score] : out.scores)
            if (id != out.dialect) others += fmt::format("{}{} {}", others.empty() ? "" : ", ", id, score);
        out.reasons.push_back(fmt::format("score {}{}", best->total, others.empty() ? "" : "; others: " + others));
    } else {
        out.evidence = false;
        const bool given = !options.fallback.empty() && registry.find(options.fallback);
        out.dialect = given ? options.fallback : default_dialect(registry);
        out.reasons.push_back(
            given ? fmt::format("no dialect evidence in the file; {} as {}", out.dialect, options.fallback_reason)
                  : fmt::format("no dialect evidence in the file; {}, the default for files without evidence "
                                "(`[detect] default = true`, dialects/SCHEMA.md): name the dialect in .kerf.toml, "
                                "a (DIALECT: id) header comment or --dialect",
                                out.dialect));
    }
    if (foreign && foreign->total > (best ? best->total : 0)) {
        Detection::Foreign f;
        f.id = foreign->dialect->id;
        f.name = foreign->dialect->name;
        f.score = foreign->total;
        // The earliest clue: where the file first shows what it is.
        const auto first = std::min_element(foreign->clues.begin(), foreign->clues.end(), [](const Clue& a, const Clue& b) {
            return std::pair(a.line, a.column) < std::pair(b.line, b.column);
        });
        if (first != foreign->clues.end()) f.first = *first;
        out.reasons.push_back(fmt::format("this looks like a {} program (score {}, more than any dialect): kerf reads "
                                          "FANUC-family dialects", f.name, f.score));
        out.reasons.push_back(fmt::format("  {} {}:", f.id, f.score));
        for (const Clue& c : foreign->clues) out.reasons.push_back(clue_line(c));
        out.foreign = std::move(f);
    }
    for (const Score* s : ranked) {
        out.reasons.push_back(fmt::format("  {} {}{}:", s->dialect->id, s->total,
                                          s->dialect->detect.needs_own && s->own <= 0 ? " (none of its own clues)" : ""));
        for (const Clue& c : s->clues) out.reasons.push_back(clue_line(c));
    }
    return out;
}

Detection detect_dialect(std::string_view text) { return detect_dialect(text, dialects::builtin_registry()); }

std::optional<std::pair<std::string, std::string>> folder_majority(std::span<const Detection> others) {
    std::map<std::string, std::pair<int, int>> votes;   // dialect → files, summed score
    int with_evidence = 0;
    for (const Detection& d : others) {
        if (!d.evidence) continue;
        ++with_evidence;
        auto& v = votes[d.dialect];
        ++v.first;
        v.second += d.confidence;
    }
    if (votes.empty()) return std::nullopt;
    const auto best = std::max_element(votes.begin(), votes.end(), [](const auto& a, const auto& b) {
        return a.second < b.second;   // more files, then the higher summed score
    });
    return std::pair{best->first, fmt::format("{} of the {} other programs with evidence in its folder",
                                              best->second.first, with_evidence)};
}

}  // namespace kerf::grammar
