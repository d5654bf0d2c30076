// The driver: splits the text into lines ("\n", "\r\n" or a lone "\r"), runs the X3 block grammar on each block, and lays the
// blocks end to end so that they cover every byte (the lossless invariant, ast/printer.hpp).
#include "grammar/parse.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <thread>

#include "ast/diagnostic_ids.hpp"
#include "ast/source.hpp"
#include "ast/display.hpp"
#include "grammar/block_def.hpp"

namespace kerf::grammar {

void Builder::add_error(const char* b, const char* e, const char* code, std::string message, std::string hint,
                        bool mergeable) {
    if (mergeable && last_error_mergeable && !tree.tokens.empty() && tree.tokens.size() > block_first_token) {
        ast::Token& last = tree.tokens.back();
        const char* gap = base + tree.end(last);
        bool only_blanks = gap <= b;
        for (const char* p = gap; only_blanks && p < b; ++p) only_blanks = block_detail::is_blank(*p);
        if (last.kind == ast::TokenKind::error && only_blanks && !tree.diagnostics.empty()) {
            tree.set_length(last, offset(e) - last.begin);
            tree.diagnostics.back().range.end = offset(e);
            if (merged_diagnostics.empty() || merged_diagnostics.back() != tree.diagnostics.size() - 1)
                merged_diagnostics.push_back(tree.diagnostics.size() - 1);
            return;
        }
    }
    add_token(ast::TokenKind::error, b, e);
    diagnose(b, e, ast::Severity::error, code, std::move(message), std::move(hint));
    last_error_mergeable = mergeable;
}

namespace {

using ast::BlockKind;
using ast::TokenKind;

bool only_blanks(const char* b, const char* e) {
    for (const char* p = b; p < e; ++p)
        if (!block_detail::is_blank(*p)) return false;
    return true;
}

// One pass over the block's tokens: its kind and its flags.
void classify(const ast::SyntaxTree& tree, ast::Block& block, std::size_t first, std::size_t last) {
    bool any = false;
    bool all_comments = true;
    bool leading = true;   // before the first word/statement (comments and '/' do not count)
    BlockKind kind = BlockKind::code;
    for (std::size_t i = first; i < last; ++i) {
        const ast::Token& t = tree.tokens[i];
        if (t.kind == TokenKind::error) block.flags |= ast::block_flags::has_error;
        if (t.kind == TokenKind::block_delete) block.flags |= ast::block_flags::deleted;
        if (t.kind == TokenKind::bom || t.kind == TokenKind::eob) continue;
        if (!any && t.kind == TokenKind::percent) kind = BlockKind::percent;
        any = true;
        if (t.kind != TokenKind::comment) all_comments = false;
        if (leading && t.kind != TokenKind::comment && t.kind != TokenKind::block_delete) {
            leading = false;
            if (kind != BlockKind::percent && t.kind == TokenKind::word && t.letter == 'O') kind = BlockKind::program_start;
        }
    }
    block.kind = !any ? BlockKind::blank : all_comments ? BlockKind::comment_only : kind;
}

// The block rule with the builder in its context. The driver makes it once: x3::with[...] holds
// its subject by value, and made per block it copied the whole grammar object (kilobytes) onto the
// stack for every line (bench/RESULTS.md, 2026-11-28 third session).
auto block_parser(Builder& builder) {
    namespace x3 = boost::spirit::x3;
    return x3::with<builder_tag>(std::ref(builder))[block_detail::block_body];
}

class Driver {
public:
    // `text` is the whole text the offsets count from; `tree` receives the blocks of the stretch
    // run() is given (tree.text is not read: it may hold the text or nothing).
    Driver(ast::SyntaxTree& tree, const dialects::LexicalRules& rules, std::string_view text)
        : tree_(tree), text_(text), builder_(tree, rules, text.data()), block_parser_(block_parser(builder_)) {}

    // Parses text[from, to): `from` starts a line and `to` ends one (or the text). The arrays are
    // reserved for `reserve_bytes` of text.
    grammar::ParseState run(grammar::ParseState state, std::size_t from, std::size_t to, std::size_t reserve_bytes) {
        const std::string_view text = text_;
        const char* const base = text.data();
        const char* const end = base + to;
        reserve(reserve_bytes);
        const char* pos = base + from;
        bool program_seen = state.program_seen;   // code since the opening '%'
        bool bom_pending = state.file_start && to - from >= 3 && std::memcmp(pos, "\xEF\xBB\xBF", 3) == 0;
        bool ended = false;
        // Lines end at "\n", "\r\n" or a lone "\r" (ast/source.hpp LineBreaks): a CR-only file is
        // read line by line like any other. The break itself is trivia of the block before it.
        ast::LineBreaks breaks(text);
        while (pos < end) {
            const ast::LineBreaks::Line line = breaks.line_from(static_cast<std::size_t>(pos - base));
            const char* line_end = base + line.end;
            const char* next_line = base + line.next;
            const char* p = pos;
            while (true) {
                const std::size_t block_index = tree_.blocks.size();
                start_block(p);
                if (bom_pending) {
                    builder_.add_token(TokenKind::bom, p, p + 3);
                    p += 3;
                    bom_pending = false;
                }
                p = parse_block(p, line_end);
                bool ended_by_eob = false;
                if (p < line_end && *p == ';') {
                    builder_.add_token(TokenKind::eob, p, p + 1);
                    ++p;
                    ended_by_eob = true;
                }
                const bool rest_blank = only_blanks(p, line_end);
                split_at_program_word(block_index, ended_by_eob);
                if (rest_blank) break;
                // Another block follows on the same line (G0 X0; G1 Z5;).
            }
            pos = next_line;
            prefault_ahead();
            const ast::Block& last = tree_.blocks.back();
            if (last.kind == BlockKind::percent) {
                if (program_seen) {
                    // Text after the closing '%' is not read by the control ([FANUC]).
                    if (pos < end) {
                        start_block(pos);
                        tree_.blocks.back().kind = BlockKind::tail;
                    }
                    ended = true;
                    break;
                }
                program_seen = false;
            } else if (last.kind == BlockKind::code || last.kind == BlockKind::program_start) {
                program_seen = true;
            }
        }
        if (tree_.blocks.empty()) start_block(base + from);   // an empty file is one blank block
        return {false, program_seen, ended};
    }

private:
    ast::SyntaxTree& tree_;
    std::string_view text_;
    Builder builder_;
    const decltype(block_parser(std::declval<Builder&>())) block_parser_;

    std::string_view slice(ast::Range r) const { return text_.substr(r.begin, r.size()); }

    void reserve(std::size_t size) {
        // Generous estimates: reserved capacity that is never written costs address space, not
        // memory (ast/large_allocator.hpp), and growing a 200 MB array would double the peak.
        tree_.blocks.reserve(size / 4 + 16);
        tree_.tokens.reserve(size / 2 + 16);   // a dense G1X1Y2 has 2-3 bytes per token
        // Macro B text: gen_program.py's macro kind has 0.24 expression nodes and 0.023 statements
        // per byte; grown by doubling, the 480 MB of nodes of its 100 MB program peaked at 1 GB
        // (old and new array during the last copy). Large reservations are mapped lazily by malloc.
        tree_.exprs.reserve(size / 2 + 16);
        tree_.statements.reserve(size / 16 + 16);
    }

    // Keeps the next stretch of the token and block arrays mapped before the parser writes there.
    void prefault_ahead() {
        constexpr std::size_t kTokenChunk = 65536;   // tokens (1 MiB)
        if (tree_.tokens.size() + kTokenChunk / 2 > tokens_prefaulted_ &&
            tokens_prefaulted_ + kTokenChunk <= tree_.tokens.capacity()) {
            ast::prefault(tree_.tokens.data() + tokens_prefaulted_, kTokenChunk * sizeof(ast::Token));
            tokens_prefaulted_ += kTokenChunk;
        }
        constexpr std::size_t kBlockChunk = 65536;
        if (tree_.blocks.size() + kBlockChunk / 2 > blocks_prefaulted_ &&
            blocks_prefaulted_ + kBlockChunk <= tree_.blocks.capacity()) {
            ast::prefault(tree_.blocks.data() + blocks_prefaulted_, kBlockChunk * sizeof(ast::Block));
            blocks_prefaulted_ += kBlockChunk;
        }
    }
    std::size_t tokens_prefaulted_ = 0;
    std::size_t blocks_prefaulted_ = 0;

    void start_block(const char* at) {
        ast::Block b;
        b.begin = builder_.offset(at);
        b.first_token = static_cast<std::uint32_t>(tree_.tokens.size());
        tree_.blocks.push_back(b);
        builder_.start_block(tree_.tokens.size());
        diagnostics_at_start_ = tree_.diagnostics.size();
    }

    const char* parse_block(const char* p, const char* line_end) {
        namespace x3 = boost::spirit::x3;
        const char* it = p;
        x3::parse(it, line_end, block_parser_);
        if (it < line_end && !(*it == ';' && builder_.rules.semicolon == dialects::SemicolonRole::end_of_block)) {
            // The item loop only stops at ';' or the line end; anything else is a grammar bug.
            builder_.add_error(it, line_end, ast::diagnostic_id::grammar_stopped, "internal: the grammar stopped here", "", false);
            it = line_end;
        }
        builder_.depth = 0;
        builder_.too_deep_at = nullptr;
        builder_.stack.clear();
        builder_.statement_stack.clear();
        builder_.functions.clear();
        builder_.operators.clear();
        return it;
    }

    // Merged runs of junk get their message once, quoting at most 80 characters of the run.
    void write_merged_messages() {
        for (const std::size_t i : builder_.merged_diagnostics) {
            ast::Diagnostic& d = tree_.diagnostics[i];
            const std::string_view text = slice(d.range);
            const std::string shown = ast::shorten(text, 80);   // on a UTF-8 character boundary
            if (text.back() == ')') {
                // Prose that ends in ')' is a comment that lost its '(' (seed 000, N040).
                d.code = ast::diagnostic_id::unmatched_close_paren;
                d.message = fmt::format("text '{}' ends with ')' but has no '(': a comment without its start", shown);
                d.hint = "add '(' where the comment begins";
            } else {
                d.message = fmt::format("unexpected text '{}'", shown);
            }
        }
        builder_.merged_diagnostics.clear();
    }

    // `M99O0810`: an O word after the block's first word starts the next program on the same line
    // ([FANUC] punched tapes and DNC files run programs together so): the block ends before it, and
    // the O word begins a program_start block of its own. Blocks stay contiguous (lossless).
    void split_at_program_word(std::size_t index, bool ended_by_eob) {
        write_merged_messages();
        const std::size_t end = tree_.tokens.size();
        std::uint32_t from = 0;   // the error diagnostics from here on belong to the block being finished
        for (std::size_t first = tree_.blocks[index].first_token;;) {
            const std::size_t split = program_word_after_first(first, end);
            if (!split) return finish_block(index, ended_by_eob, end, {from, ~0u});
            const std::uint32_t at = tree_.tokens[split].begin;
            finish_block(index, false, split, {from, at});
            ast::Block b;
            b.begin = at;
            b.first_token = static_cast<std::uint32_t>(split);
            tree_.blocks.push_back(b);
            index = tree_.blocks.size() - 1;
            first = split;
            from = at;
        }
    }

    // The O word with a number that follows plain words (`M99O0810`, `M30 O1234`: a letter other
    // than O and a number, nothing else but comments) in tokens [first, end); 0 when there is none
    // or anything else comes first (an error, a statement, an expression): then nothing is split,
    // which project/scan.cpp tells the same way from the bytes.
    std::size_t program_word_after_first(std::size_t first, std::size_t end) const {
        // Nearly every block has no O word after its first token: told from the letters alone,
        // before any token's text is read again (that reading was 5 % of a parse).
        bool o_word = false;
        for (std::size_t i = first + 1; i < end && !o_word; ++i) {
            const char letter = tree_.tokens[i].letter;
            o_word = letter == 'O' || letter == 'o';
        }
        if (!o_word) return 0;
        bool words_before = false;
        for (std::size_t i = first; i < end; ++i) {
            const ast::Token& t = tree_.tokens[i];
            if (t.kind == TokenKind::comment || t.kind == TokenKind::bom || (i == first && t.kind == TokenKind::block_delete)) continue;
            if (t.kind != TokenKind::word) return 0;
            if ((t.letter == 'O' || t.letter == 'o') && digits_follow(t)) return words_before ? i : 0;
            if (!is_plain_word(slice(tree_.range(t)))) return 0;
            words_before = true;
        }
        return 0;
    }

    // O0810, O 810: a digit after the letter (and blanks) — the test project/scan.cpp makes too.
    bool digits_follow(const ast::Token& t) const {
        const std::string_view s = slice(tree_.range(t));
        std::size_t i = 1;
        while (i < s.size() && block_detail::is_blank(s[i])) ++i;
        return i < s.size() && s[i] >= '0' && s[i] <= '9';
    }

    // The block's kind and flags from its tokens up to `end_token`; the error diagnostics of the
    // line that start in `errors` mark it.
    void finish_block(std::size_t index, bool ended_by_eob, std::size_t end_token, ast::Range errors) {
        ast::Block& b = tree_.blocks[index];
        classify(tree_, b, b.first_token, end_token);
        if (ended_by_eob) b.flags |= ast::block_flags::has_eob;
        for (std::size_t i = diagnostics_at_start_; i < tree_.diagnostics.size(); ++i) {
            const ast::Diagnostic& d = tree_.diagnostics[i];
            if (d.severity == ast::Severity::error && d.range.begin >= errors.begin && d.range.begin < errors.end)
                b.flags |= ast::block_flags::has_error;
        }
    }

    std::size_t diagnostics_at_start_ = 0;
};

}  // namespace

bool is_plain_word(std::string_view s) {
    if (s.empty() || !std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == 'O' || s[0] == 'o') return false;
    std::size_t i = 1;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    bool digits = false, point = false;
    for (; i < s.size(); ++i) {
        if (s[i] >= '0' && s[i] <= '9') digits = true;
        else if (s[i] == '.' && !point) point = true;
        else return false;
    }
    return digits;
}

namespace {

// Below this a second thread does not pay for itself (starting it, the second tree, the join).
constexpr std::size_t kTwoThreadsMin = std::size_t{8} << 20;

// Appends `second` (parsed from a later stretch of the same text: its ranges are already offsets
// into the whole text) to `tree`: its indices into tokens, expression nodes, statements and big
// numbers move by the counts `tree` has. The blocks and tokens go over a chunk at a time, the
// chunk's pages of `second` released behind the copy and those of `tree` mapped ahead of it, so
// that the two trees together hold little more than the one tree (bench/RESULTS.md: a two-thread
// parse that copied the whole second tree peaked at 5.6x the text instead of 4.1x).
template <typename Vector, typename Adjust>
void append_released(Vector& to, Vector& from, Adjust adjust) {
    using T = typename Vector::value_type;
    constexpr std::size_t kChunk = std::size_t{1} << 16;
    // Only a large array's pages go back early (a small one is not worth a system call).
    const bool large = from.capacity() * sizeof(T) >= ast::LargeAllocator<T>::kThreshold;
    for (std::size_t at = 0; at < from.size(); at += kChunk) {
        const std::size_t end = std::min(from.size(), at + kChunk);
        if (to.size() + (end - at) <= to.capacity()) ast::prefault(to.data() + to.size(), (end - at) * sizeof(T));
        // The chunk copied whole (a memmove), then its indices moved while it is in the cache: an
        // element at a time through push_back was most of the append (0.1 s for 100 MB).
        const std::size_t base = to.size();
        to.insert(to.end(), from.begin() + static_cast<std::ptrdiff_t>(at), from.begin() + static_cast<std::ptrdiff_t>(end));
        for (std::size_t i = base; i < to.size(); ++i) adjust(to[i]);
        if (large) ast::release(from.data() + at, (end - at) * sizeof(T));
    }
}

void append_tree(ast::SyntaxTree& tree, ast::SyntaxTree& second) {
    const auto tokens = static_cast<std::uint32_t>(tree.tokens.size());
    const auto exprs = static_cast<std::int32_t>(tree.exprs.size());
    const auto statements = static_cast<std::int32_t>(tree.statements.size());
    const auto big = static_cast<std::int32_t>(tree.big_numbers.size());
    // The tokens (most of the bytes of CAM output) go over on a second thread while this one moves
    // the rest: the arrays are apart, and the page faults of the copy are most of its time.
    std::thread token_mover([&] {
        append_released(tree.tokens, second.tokens, [&](ast::Token& t) {
            if (t.kind == TokenKind::statement) t.payload += statements;
            else if (t.has(ast::token_flags::value_expr)) t.payload += exprs;
            else if (t.has(ast::token_flags::value_big)) t.payload += big;
        });
    });
    append_released(tree.blocks, second.blocks, [&](ast::Block& b) { b.first_token += tokens; });
    const auto shift = [](std::int32_t& index, std::int32_t by) {
        if (index >= 0) index += by;
    };
    // Macro B text has as many expression nodes as tokens (gen_program.py's macro kind: 480 MB of
    // them in 100 MB): released as they go too.
    append_released(tree.exprs, second.exprs, [&](ast::Expr& e) {
        if (e.kind == ast::ExprKind::number) {
            if (e.flags & ast::token_flags::value_big) e.a += big;
        } else {
            shift(e.a, exprs);
            shift(e.b, exprs);
        }
    });
    append_released(tree.statements, second.statements, [&](ast::Statement& st) {
        shift(st.target, exprs);
        shift(st.value, exprs);
        shift(st.label, exprs);
        shift(st.then_statement, statements);
    });
    tree.big_numbers.insert(tree.big_numbers.end(), second.big_numbers.begin(), second.big_numbers.end());
    tree.long_tokens.insert(tree.long_tokens.end(), second.long_tokens.begin(), second.long_tokens.end());
    tree.diagnostics.insert(tree.diagnostics.end(), second.diagnostics.begin(), second.diagnostics.end());
    token_mover.join();
}

// The parse of a long text on two threads: the second half from the state a line in the middle
// of a program has (code seen, the tape not closed), checked against the state the first half
// really ends in; when they differ (a '%' line in the first half closed the tape, or no code came
// before the middle) the second half is parsed again after the first. The tree is the one the
// single-thread parse builds (tests/grammar/test_parse_threads.cpp).
void parse_on_two_threads(ast::SyntaxTree& tree, const dialects::LexicalRules& rules, std::size_t split) {
    const std::string_view text = tree.text;
    const ParseState assumed{false, true, false};
    ast::SyntaxTree second;
    ParseState second_end;
    std::thread worker([&] { second_end = Driver(second, rules, text).run(assumed, split, text.size(), text.size() - split); });
    const ParseState first_end = Driver(tree, rules, text).run({}, 0, split, text.size());
    worker.join();
    if (first_end.program_seen == assumed.program_seen && first_end.ended == assumed.ended) {
        append_tree(tree, second);
        return;
    }
    if (!first_end.ended) {
        Driver(tree, rules, text).run(first_end, split, text.size(), text.size());
        return;
    }
    // The tape closed in the first half: what follows is one tail block (see Driver::run).
    if (tree.blocks.back().kind != BlockKind::tail) {
        ast::Block tail;
        tail.begin = static_cast<std::uint32_t>(split);
        tail.first_token = static_cast<std::uint32_t>(tree.tokens.size());
        tail.kind = BlockKind::tail;
        tree.blocks.push_back(tail);
    }
}

}  // namespace

unsigned parse_threads() {
    // Asked once: hardware_concurrency() reads /sys on every call, which was 2 % of checking a
    // folder of small programs (each file asks, though only a text of 8 MiB or more uses it).
    static const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, 2u);
    return threads;
}

ast::SyntaxTree parse(std::string text, const dialects::LexicalRules& rules, unsigned threads) {
    ast::SyntaxTree tree;
    if (text.size() >= 0xFFFFFFF0u) {
        // Offsets are 32-bit; a 4 GiB NC program is not a program.
        tree.text = std::string();
        tree.blocks.push_back({});
        tree.diagnostics.push_back({{0, 0}, ast::Severity::error, ast::diagnostic_id::file_too_large,
                                    "file is too large (4 GiB or more)", "split the file"});
        return tree;
    }
    tree.text = std::move(text);
    const std::size_t size = tree.text.size();
    if (threads >= 2 && size >= kTwoThreadsMin) {
        const std::size_t split = ast::last_line_end_before(tree.text, size / 2);
        if (split != std::string_view::npos && split > 0 && split < size) {
            parse_on_two_threads(tree, rules, split);
            return tree;
        }
    }
    Driver(tree, rules, tree.text).run({}, 0, size, size);
    return tree;
}

ParseState parse_into(ast::SyntaxTree& tree, std::string_view text, const dialects::LexicalRules& rules,
                      ParseState start) {
    tree.text.assign(text);
    tree.blocks.clear();
    tree.tokens.clear();
    tree.exprs.clear();
    tree.statements.clear();
    tree.big_numbers.clear();
    tree.diagnostics.clear();
    if (text.size() >= 0xFFFFFFF0u) {
        tree.text.clear();
        tree.blocks.push_back({});
        tree.diagnostics.push_back({{0, 0}, ast::Severity::error, ast::diagnostic_id::file_too_large, "piece too large (4 GiB or more)", "split the file"});
        return {false, start.program_seen, true};
    }
    return Driver(tree, rules, tree.text).run(start, 0, tree.text.size(), tree.text.size());
}

}  // namespace kerf::grammar
