#include "formatter/format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "ast/source.hpp"

#include "formatter/renumber.hpp"

namespace kerf::formatter {

namespace {

using ast::Token;
using ast::TokenKind;
using ast::Role;

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == '\r'; }
// A blank within a line: the grammar's blanks (grammar/block_def.hpp) without the CR that may be a
// line break.
bool is_line_blank(char c) { return is_blank(c) && c != '\r'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// A piece of an output block: a token of the tree, or one the formatter adds.
struct Piece {
    std::uint32_t token = 0;
    int rank = 0;
};
constexpr std::uint32_t kNewNumber = std::numeric_limits<std::uint32_t>::max();   // an N word renumbering adds
constexpr std::uint32_t kNewEob = kNewNumber - 1;                                  // a ';' the style adds

// Canonical word order (issue 6): N, G codes, axis words, I/J/K/R, other addresses, comma words,
// F, S, T, M. Block delete stays first and ';' last; comments are not ranked (they keep their slot).
namespace rank {
constexpr int bom = 0, block_delete = 1, program = 2, sequence = 3, g_code = 4, axis = 5, arc = 6, other = 7,
              comma = 8, feed = 9, speed = 10, tool = 11, m_code = 12, eob = 14;
}

// Inside a rank, axis words go in the control's order and I/J/K/R alphabetically; others keep theirs.
int subrank(const Token& t, int rank_value) {
    const std::string_view order = rank_value == rank::axis ? "XYZUVWABC" : rank_value == rank::arc ? "IJKR" : "";
    const std::size_t at = order.find(t.letter);
    return at == std::string_view::npos ? static_cast<int>(order.size()) : static_cast<int>(at);
}

int rank_of(const Token& t);

// The sort key of a piece: its rank, then its subrank.
constexpr int key_of(int rank, int subrank = 0) { return rank * 16 + subrank; }
int order_key(const Token& t) {
    const int r = rank_of(t);
    return key_of(r, subrank(t, r));
}

int rank_of(const Token& t) {
    switch (t.kind) {
        case TokenKind::bom:
        case TokenKind::percent: return rank::bom;
        case TokenKind::block_delete: return rank::block_delete;
        case TokenKind::comma_word: return rank::comma;
        case TokenKind::eob: return rank::eob;
        case TokenKind::word: break;
        default: return rank::other;
    }
    switch (t.role()) {
        case Role::program: return rank::program;
        case Role::sequence: return rank::sequence;
        case Role::g_code: return rank::g_code;
        case Role::m_code: return rank::m_code;
        case Role::axis_absolute:
        case Role::axis_incremental: return rank::axis;
        case Role::direct_drawing: return rank::comma;   // plain A/R: the comma words' meaning (dialects.md §11.4)
        default: break;
    }
    switch (t.letter) {
        case 'I': case 'J': case 'K': case 'R': return rank::arc;
        case 'F': return rank::feed;
        case 'S': return rank::speed;
        case 'T': return rank::tool;
        default: return rank::other;
    }
}

// The line break at the end of a block: what follows its last token after blanks, when it is a
// line break ("\n", "\r\n" or a lone "\r": ast/source.hpp LineBreaks); empty when another block
// follows on the same line or the file ends.
std::string_view line_break_of(std::string_view trailing) {
    std::size_t at = 0;
    while (at < trailing.size() && is_line_blank(trailing[at])) ++at;
    trailing.remove_prefix(at);
    const bool lone_cr = !trailing.empty() && trailing.front() == '\r';
    return lone_cr || trailing.find('\n') != std::string_view::npos ? trailing : std::string_view{};
}

// "(  TEXT )" → "TEXT" with the style's blanks around it; other comments (line comments, unclosed
// ones) as written. The text between the blanks is never touched.
void append_comment(std::string& out, std::string_view spelling, bool unclosed, CommentInside inside) {
    if (inside == CommentInside::keep || unclosed || spelling.size() < 2 || spelling.front() != '(' ||
        spelling.back() != ')') {
        out += spelling;
        return;
    }
    std::string_view text = spelling.substr(1, spelling.size() - 2);
    while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
    while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
    const bool pad = inside == CommentInside::padded && !text.empty();
    out += pad ? "( " : "(";
    out += text;
    out += pad ? " )" : ")";
}

// The block writes #3000 (macro alarm) or #3006 (stop with message), whose message is the block's
// comment ([FANUC]; interpreter/executor_system.cpp): that comment is data, printed as written
// whatever comment_inside says (padded, `(TEXT)` became the message ' TEXT ': fuzz_formatter).
// A variable number computed at run time might be either.
bool writes_message(const ast::SyntaxTree& tree, std::span<const Token> tokens) {
    const auto message_variable = [&](std::int32_t target) {
        if (target < 0) return false;
        const ast::Expr& variable = tree.exprs[static_cast<std::size_t>(target)];
        if (variable.kind != ast::ExprKind::variable || variable.a < 0) return true;
        const ast::Expr& number = tree.exprs[static_cast<std::size_t>(variable.a)];
        if (number.kind != ast::ExprKind::number) return true;
        const double n = tree.number_value(number);
        return n == 3000 || n == 3006;
    };
    for (const Token& t : tokens) {
        if (t.kind != TokenKind::statement) continue;
        for (std::int32_t i = t.payload; i >= 0;) {
            const ast::Statement& st = tree.statements[static_cast<std::size_t>(i)];
            if (st.kind == ast::StatementKind::assign && message_variable(st.target)) return true;
            i = st.kind == ast::StatementKind::if_then ? st.then_statement : -1;
        }
    }
    return false;
}

// G/M code digits: "1" → "01" (two) or "001" → "1" (minimal); codes with a fraction keep it.
void append_code_number(std::string& out, std::string_view value, CodeDigits digits) {
    const std::size_t point = std::min(value.find('.'), value.size());
    std::string_view whole = value.substr(0, point);
    while (whole.size() > 1 && whole.front() == '0') whole.remove_prefix(1);
    // "M.0" has no digit before the point: two of them make "M00.0", as "M0.0" would become next time.
    if (digits == CodeDigits::two) out.append(whole.size() < 2 ? 2 - whole.size() : 0, '0');
    out += whole;
    out += value.substr(point);
}

bool plain_digits(std::string_view v, bool point_allowed) {
    if (v.empty()) return false;
    for (const char c : v)
        if (!is_digit(c) && !(point_allowed && c == '.')) return false;
    return true;
}

class Printer {
public:
    Printer(const ast::TypedFile& file, const Style& style, const FormatContext& context, const Renumbering& plan,
            std::string& out)
        : file_(file), tree_(file.tree()), style_(style), context_(context), plan_(plan), out_(out) {}

    void blocks(std::size_t first, std::size_t end) {
        for (std::size_t b = first; b < end; ++b) block(b);
    }

private:
    const ast::TypedFile& file_;
    const ast::SyntaxTree& tree_;
    const Style& style_;
    const FormatContext& context_;
    const Renumbering& plan_;
    std::string& out_;
    std::vector<Piece> pieces_;
    std::vector<std::uint32_t> slots_;   // reused by reorder()
    std::vector<Piece> words_;
    int blank_run_ = 0;
    bool line_start_ = true;
    std::uint32_t number_token_ = kNewNumber;   // the N word printed with new_number_
    std::int64_t new_number_ = 0;
    bool message_block_ = false;   // the block's comment is a message (writes_message)

    void block(std::size_t b) {
        const ast::Block& block = tree_.blocks[b];
        const ast::Range range = tree_.block_range(b);
        const auto tokens = tree_.block_tokens(b);
        const std::uint32_t content_begin = tokens.empty() ? range.end : tokens.front().begin;
        const std::uint32_t content_end = tokens.empty() ? range.end : tree_.end(tokens.back());
        const std::string_view trailing = tree_.slice({content_end, range.end});
        if (block.kind == ast::BlockKind::tail) {
            out_.append(tree_.text, range.begin, range.size());
            return;
        }
        // A block with a syntax error, or with an O word a reprint could make a program start
        // (renumber.hpp: renumbering refuses such a file, so no new N is lost here).
        if (block.has(ast::block_flags::has_error) || has_inner_program_word(tree_, tokens)) {
            blank_run_ = 0;
            out_.append(tree_.text, range.begin, content_end - range.begin);   // exactly as it was
            end_line(trailing);
            return;
        }
        if (block.kind == ast::BlockKind::blank) {
            // Its tokens can be a byte order mark (kept first) and a ';' (an empty block): a file of
            // nothing but a BOM printed as ';' (fuzz_formatter).
            bool eob = false;
            for (const Token& t : tokens) {
                if (t.kind == TokenKind::bom) out_ += tree_.spelling(t);
                eob = eob || t.kind == TokenKind::eob;
            }
            blank(tokens.empty() ? tree_.slice(range) : trailing, eob);
            return;
        }
        collect(b, block, b + 1 == tree_.block_count() || !line_break_of(trailing).empty() || only_dropped_blocks_follow(b));
        // A block of nothing but a removed N word goes, line and all; one left with only its ';'
        // is an empty block, which the grammar reads as a blank line: both are printed as they will
        // be when the output is formatted again.
        if (pieces_.empty()) {
            // After a block on its line, the line break is that block's: `G0 X1; N630;` with the N
            // removed is `G0 X1` and its line end (dropped, the next line joined it: fuzz_formatter).
            if (!line_start_) end_line(trailing);
            return;
        }
        if (pieces_.size() == 1 && (pieces_[0].token == kNewEob || is_kind(pieces_[0], TokenKind::eob))) {
            blank(trailing, true);
            return;
        }
        blank_run_ = 0;
        leading(tree_.slice({range.begin, content_begin}));
        message_block_ = writes_message(tree_, tokens);
        print_pieces();
        end_line(trailing);
    }

    // block_end = none prints nothing of an empty block (`;`), nor of a block of an N word that
    // renumbering removes (`N630;`): when only such blocks follow on the line, the block ends it
    // (`G28 U0;;;` → `G28 U0`, not `G28 U0;`, which the next pass changed).
    bool only_dropped_blocks_follow(std::size_t b) const {
        if (style_.block_end != BlockEnd::none) return false;
        for (std::size_t next = b + 1; next < tree_.block_count(); ++next) {
            const auto tokens = tree_.block_tokens(next);
            const auto planned = plan_.blocks.find(static_cast<std::uint32_t>(next));
            const bool number_removed = planned != plan_.blocks.end() && planned->second == Renumbering::kRemove;
            bool number_seen = false;
            for (const Token& t : tokens) {
                if (t.kind == TokenKind::eob) continue;
                if (number_removed && !number_seen && t.kind == TokenKind::word && t.role() == Role::sequence) {
                    number_seen = true;
                    continue;
                }
                return false;
            }
            const ast::Range range = tree_.block_range(next);
            const std::uint32_t content_end = tokens.empty() ? range.end : tree_.end(tokens.back());
            if (!line_break_of(tree_.slice({content_end, range.end})).empty()) return true;
        }
        return true;
    }

    // A blank line, or an empty block (`;` alone, `eob`), as one of a run of at most max_blank_lines.
    void blank(std::string_view text, bool eob) {
        const std::string_view brk = line_break_of(text);
        if (brk.empty() && !eob) {   // blanks at the end of the file without a line break
            if (style_.spacing == Spacing::keep) out_ += text;
            return;
        }
        // Only a line of its own is a blank line that blank_lines may drop: an empty block after a
        // block on its line (`G43 Z0.6 H5;;`) ends that line, and dropping its line break joined the
        // next line to it (`G43 Z0.6 H5 G00 Z0.2`: fuzz_formatter, --verify).
        if (line_start_) {
            ++blank_run_;
            if (style_.max_blank_lines >= 0 && blank_run_ > style_.max_blank_lines) return;
        }
        const std::size_t before = out_.size();
        if (eob && style_.block_end != BlockEnd::none) out_ += ';';
        else if (!eob && style_.spacing == Spacing::keep) out_.append(text.substr(0, text.size() - brk.size()));
        // A ';' that block_end = none drops leaves the line as it was: what follows it on the line
        // starts the line (`;(NOTE)` → `(NOTE)`, not ` (NOTE)`: fuzz_formatter, not idempotent).
        if (brk.empty()) line_start_ = line_start_ && out_.size() == before;
        else line_break(brk);
    }

    void leading(std::string_view text) {
        if (style_.spacing == Spacing::keep) out_ += text;
        else if (!line_start_ && style_.spacing == Spacing::spaced) out_ += ' ';
    }

    void end_line(std::string_view trailing) {
        const std::string_view brk = line_break_of(trailing);
        if (style_.spacing == Spacing::keep) out_.append(trailing.substr(0, trailing.size() - brk.size()));
        if (brk.empty()) {
            line_start_ = false;
            return;
        }
        line_break(brk);
    }

    void line_break(std::string_view original) {
        switch (style_.line_ending) {
            case LineEnding::keep: out_ += original; break;
            case LineEnding::lf: out_ += '\n'; break;
            case LineEnding::crlf: out_ += "\r\n"; break;
        }
        line_start_ = true;
    }

    // --- the pieces of a block ---------------------------------------------------------------------

    // `ends_line`: nothing follows the block on its line, so a ';' may go without joining blocks.
    void collect(std::size_t b, const ast::Block& block, bool ends_line) {
        pieces_.clear();
        number_token_ = kNewNumber;
        const auto planned = plan_.blocks.empty() ? plan_.blocks.end() : plan_.blocks.find(static_cast<std::uint32_t>(b));
        const bool renumbered = planned != plan_.blocks.end();
        bool number_seen = false;
        const std::uint32_t first = block.first_token;
        const std::uint32_t end = tree_.block_token_end(b);
        for (std::uint32_t i = first; i < end; ++i) {
            const Token& t = tree_.tokens[i];
            if (t.kind == TokenKind::eob && style_.block_end == BlockEnd::none && ends_line && i + 1 == end) continue;
            if (renumbered && !number_seen && t.kind == TokenKind::word && t.role() == Role::sequence) {
                number_seen = true;
                if (planned->second == Renumbering::kRemove) continue;
                number_token_ = i;
                new_number_ = planned->second;
            }
            pieces_.push_back({i, t.kind == TokenKind::comment ? -1 : order_key(t)});
        }
        if (renumbered && !number_seen && planned->second != Renumbering::kRemove) {
            new_number_ = planned->second;
            // The new N goes first, after a '%', a byte order mark or a block delete.
            const auto at = std::find_if(pieces_.begin(), pieces_.end(),
                                         [](const Piece& p) { return p.rank < 0 || p.rank >= key_of(rank::program); });
            pieces_.insert(at, Piece{kNewNumber, key_of(rank::sequence)});
        }
        if (wants_eob(block)) pieces_.push_back({kNewEob, key_of(rank::eob)});
        if (style_.word_order == WordOrder::canonical && reorderable(b)) reorder();
    }

    // block_end = semicolon adds ';' where the dialect ends blocks with it, unless the block ends in
    // a comment that runs to the end of the line (the ';' would become comment text).
    bool wants_eob(const ast::Block& block) const {
        if (style_.block_end != BlockEnd::semicolon || block.has(ast::block_flags::has_eob)) return false;
        if (file_.dialect().lexical.semicolon != dialects::SemicolonRole::end_of_block) return false;
        if (block.kind == ast::BlockKind::percent || pieces_.empty()) return false;
        const Piece& last = pieces_.back();
        if (last.token >= kNewEob) return true;
        const Token& t = tree_.tokens[last.token];
        if (t.kind == TokenKind::bom || t.kind == TokenKind::percent) return false;
        if (t.kind != TokenKind::comment) return true;
        const std::string_view s = tree_.spelling(t);
        return !t.has(ast::token_flags::unclosed) && !s.empty() && s.front() == '(';
    }

    // Word order matters in blocks with macro statements, and for G65/G66 arguments (argument
    // specification II counts repeated I J K in order; dialects.md §3.7). A '%' inside a block may
    // close the tape there (grammar/parse.cpp): what stands before it runs, what follows does not.
    bool reorderable(std::size_t b) const {
        if (axis_named_twice(b) || program_word_after_first(b)) return false;
        for (const Token& t : tree_.block_tokens(b)) {
            if (t.kind == TokenKind::statement || t.kind == TokenKind::error || t.kind == TokenKind::percent) return false;
            if (t.kind != TokenKind::word || t.role() != Role::g_code || !t.is_number()) continue;
            const auto key = dialects::code_key(tree_.number_value(t));
            const dialects::CodeInfo* info = key ? file_.dialect().fast_code('G', *key) : nullptr;
            if (info && info->has(dialects::traits::takes_arguments)) return false;
        }
        return true;
    }

    // `G0 O.1 Q1`: sorted first, the O word would start a program there (grammar/parse.cpp classify:
    // a block that begins with O is a program start), and the program before it would end a block
    // early (fuzz_formatter, --verify). An O word that is not the block's first word stays behind.
    bool program_word_after_first(std::size_t b) const {
        bool first = true;
        for (const Token& t : tree_.block_tokens(b)) {
            if (t.kind != TokenKind::word && t.kind != TokenKind::statement) continue;
            if (!first && t.kind == TokenKind::word && t.role() == Role::program) return true;
            first = false;
        }
        return false;
    }

    // `U107 X10.497`: one axis by two letters (absolute and incremental, system A); the last one
    // moves it (interpreter/executor_words.cpp), so the order is the meaning (fuzz_formatter).
    bool axis_named_twice(std::size_t b) const {
        std::uint32_t axes = 0;
        for (const Token& t : tree_.block_tokens(b)) {
            if (t.kind != TokenKind::word) continue;
            char axis = 0;
            if (t.role() == Role::axis_absolute) axis = t.letter;
            if (t.role() == Role::axis_incremental)
                for (const auto& [letter, moved] : file_.dialect().lexical.incremental_letters)
                    if (letter == t.letter) axis = moved;
            if (axis < 'A' || axis > 'Z') continue;
            const std::uint32_t bit = 1u << (axis - 'A');
            if (axes & bit) return true;
            axes |= bit;
        }
        return false;
    }

    // Comments keep their slots; the other pieces fill the remaining slots in rank order (stable:
    // two G codes of one group keep their order, the last wins; semantics.md §1.1).
    void reorder() {
        slots_.clear();
        words_.clear();
        for (std::uint32_t i = 0; i < pieces_.size(); ++i) {
            if (pieces_[i].rank < 0) continue;
            slots_.push_back(i);
            words_.push_back(pieces_[i]);
        }
        std::stable_sort(words_.begin(), words_.end(), [](const Piece& a, const Piece& b) { return a.rank < b.rank; });
        for (std::size_t k = 0; k < slots_.size(); ++k) pieces_[slots_[k]] = words_[k];
    }

    void print_pieces() {
        const Piece* previous = nullptr;
        for (const Piece& p : pieces_) {
            if (previous) separator(*previous, p);
            piece(p);
            previous = &p;
        }
    }

    bool is_kind(const Piece& p, TokenKind kind) const { return p.token < kNewEob && tree_.tokens[p.token].kind == kind; }

    void separator(const Piece& a, const Piece& b) {
        if (b.token == kNewEob || is_kind(b, TokenKind::eob)) return;
        // spacing = keep keeps the blanks after a byte order mark or a '/' too: a BOM line dropped by
        // blank_lines joins the next line with its leading blanks, which the next pass must keep
        // (fuzz_formatter, not idempotent).
        if (style_.spacing == Spacing::keep && a.token < kNewEob && b.token < kNewEob && b.token == a.token + 1) {
            const std::uint32_t gap = tree_.end(tree_.tokens[a.token]);
            out_.append(tree_.text, gap, tree_.tokens[b.token].begin - gap);
            return;
        }
        if (is_kind(a, TokenKind::bom) || is_kind(a, TokenKind::block_delete)) return;
        if (is_kind(b, TokenKind::comment) && !is_kind(a, TokenKind::comment) && style_.comment_gap != CommentGap::spacing) {
            if (style_.comment_gap == CommentGap::one) out_ += ' ';
            return;
        }
        // A macro statement keeps a blank on each side even in compact blocks: `N10IF[...]` would
        // read as an address I.
        if (style_.spacing != Spacing::compact || is_kind(a, TokenKind::statement) || is_kind(b, TokenKind::statement))
            out_ += ' ';
    }

    void piece(const Piece& p) {
        if (p.token == kNewNumber) {
            out_ += letter('N', 'N');
            fmt::format_to(std::back_inserter(out_), "{}", new_number_);
            return;
        }
        if (p.token == kNewEob) {
            out_ += ';';
            return;
        }
        const Token& t = tree_.tokens[p.token];
        switch (t.kind) {
            case TokenKind::word: word(t, p.token); break;
            case TokenKind::comma_word:
                out_ += ',';
                out_ += letter(t.letter, tree_.spelling(t)[1]);
                out_ += tree_.value_spelling(t);
                break;
            case TokenKind::comment:
                append_comment(out_, tree_.spelling(t), t.has(ast::token_flags::unclosed),
                               message_block_ ? CommentInside::keep : style_.comment_inside);
                break;
            case TokenKind::statement: statement(t, p.token); break;
            default: out_ += tree_.spelling(t);
        }
    }

    char letter(char upper, char written) const {
        if (written == ':') return ':';   // ISO program number ":1000"
        switch (style_.letter_case) {
            case LetterCase::keep: return written;
            case LetterCase::upper: return upper;
            case LetterCase::lower: return static_cast<char>(upper - 'A' + 'a');
        }
        return upper;
    }

    void word(const Token& t, std::uint32_t index) {
        out_ += letter(t.letter, tree_.spelling(t)[0]);
        if (index == number_token_) {
            fmt::format_to(std::back_inserter(out_), "{}", new_number_);
            return;
        }
        if (!plan_.words.empty()) {
            if (const auto it = plan_.words.find(index); it != plan_.words.end()) {
                fmt::format_to(std::back_inserter(out_), "{}", it->second);
                return;
            }
        }
        const std::string_view value = tree_.value_spelling(t);
        const bool number = t.is_number() && !t.has(ast::token_flags::negative);
        const Role role = t.role();
        if (number && style_.code_digits != CodeDigits::keep && (role == Role::g_code || role == Role::m_code) &&
            plain_digits(value, true)) {
            append_code_number(out_, value, style_.code_digits);
            return;
        }
        if (number && role == Role::program && style_.program_number == ProgramNumber::four_digits &&
            plain_digits(value, false) && value.size() < 4)
            out_.append(4 - value.size(), '0');
        out_ += value;
        if (adds_point(t)) out_ += '.';
    }

    // X10 → X10. only where the machine reads both as millimetres (FormatContext).
    bool adds_point(const Token& t) const {
        if (style_.decimal_point != DecimalPoint::add || !context_.calculator_decimal || !t.is_number()) return false;
        if (t.has(ast::token_flags::has_point) || t.has(ast::token_flags::decimal_comma) || t.has(ast::token_flags::value_big))
            return false;
        const Role role = t.role();
        return role == Role::axis_absolute || role == Role::axis_incremental || (role == Role::parameter && t.letter == 'F');
    }

    void statement(const Token& t, std::uint32_t index) {
        const std::string_view text = tree_.spelling(t);
        const auto it = plan_.statements.empty() ? plan_.statements.end() : plan_.statements.find(index);
        if (it == plan_.statements.end()) {
            out_ += text;
            return;
        }
        std::uint32_t at = t.begin;
        for (const LabelEdit& e : it->second) {
            out_.append(tree_.text, at, e.range.begin - at);
            fmt::format_to(std::back_inserter(out_), "{}", e.value);
            at = e.range.end;
        }
        out_.append(tree_.text, at, tree_.end(t) - at);
    }
};

// The first line break of the text, for lines the formatter adds ('%').
std::string_view added_line_break(const ast::SyntaxTree& tree, LineEnding ending) {
    if (ending == LineEnding::lf) return "\n";
    if (ending == LineEnding::crlf) return "\r\n";
    const std::string_view text = tree.text;
    const std::size_t end = ast::LineBreaks(text).line_from(0).end;
    if (end >= text.size()) return "\n";
    if (text[end] == '\r') return "\r";   // a CR-only file stays CR-only
    return end > 0 && text[end - 1] == '\r' ? "\r\n" : "\n";
}

bool ends_with_line_break(const std::string& out) { return !out.empty() && (out.back() == '\n' || out.back() == '\r'); }

// The text ends in blanks that no token holds, with no line break after them.
bool ends_in_loose_blanks(const ast::SyntaxTree& tree) {
    const std::string_view text = tree.text;
    std::size_t blanks = 0;
    while (blanks < text.size() && is_line_blank(text[text.size() - 1 - blanks])) ++blanks;
    if (blanks == 0) return false;
    if (tree.tokens.empty()) return true;
    const ast::Token& last = tree.tokens[tree.tokens.size() - 1];
    return tree.end(last) <= text.size() - blanks;
}

struct Framing {
    bool open = false;    // add a '%' line before the first block
    bool close = false;   // add a '%' line after the last
};

// percent = ensure: a '%' before the first code block and one after the last, unless there already
// is one; a file starting with a byte order mark keeps it first, so it gets no opening line.
Framing framing(const ast::SyntaxTree& tree, Percent percent) {
    if (percent != Percent::ensure) return {};
    std::optional<std::size_t> first_code, last_code;
    for (std::size_t b = 0; b < tree.block_count(); ++b) {
        const ast::BlockKind k = tree.blocks[b].kind;
        // An empty file is one code block without tokens (grammar/parse.cpp): nothing to frame.
        const bool empty = tree.block_first_token(b) == tree.block_token_end(b);
        if ((k == ast::BlockKind::code || k == ast::BlockKind::program_start) && !empty) {
            if (!first_code) first_code = b;
            last_code = b;
        }
    }
    if (!first_code) return {};
    Framing f{true, true};
    for (std::size_t b = 0; b < tree.block_count(); ++b) {
        if (tree.blocks[b].kind != ast::BlockKind::percent && tree.blocks[b].kind != ast::BlockKind::tail) continue;
        if (b < *first_code) f.open = false;
        if (b > *last_code) f.close = false;
    }
    const auto first = tree.block_tokens(0);
    if (!first.empty() && first.front().kind == TokenKind::bom) f.open = false;
    return f;
}

}  // namespace

FormatResult format(const ast::TypedFile& file, const Style& style, const FormatContext& context) {
    FormatResult result;
    auto plan = plan_renumbering(file, style);
    if (auto* problems = std::get_if<std::vector<ast::Diagnostic>>(&plan)) {
        result.diagnostics = std::move(*problems);
        return result;
    }
    const ast::SyntaxTree& tree = file.tree();
    const Framing frame = framing(tree, style.percent);
    const std::string_view brk = added_line_break(tree, style.line_ending);
    std::string out;
    out.reserve(tree.text.size() + tree.text.size() / 8);
    if (frame.open) (out += '%') += brk;
    Printer(file, style, context, std::get<Renumbering>(plan), out).blocks(0, tree.block_count());
    if (frame.close) {
        // Blanks at the end of the file without a line break (outside every token: a line comment's
        // text keeps its own) would become a line of blanks before the '%', one blank line more than
        // blank_lines allows the next time (fuzz_formatter).
        if (ends_in_loose_blanks(tree))
            while (!out.empty() && is_line_blank(out.back())) out.pop_back();
        if (!out.empty() && !ends_with_line_break(out)) out += brk;
        (out += '%') += brk;
    }
    result.text = std::move(out);
    return result;
}

TextEdit format_range(const ast::TypedFile& file, const ast::LineIndex& lines, std::uint32_t first_line,
                      std::uint32_t last_line, const Style& style, const FormatContext& context) {
    const ast::SyntaxTree& tree = file.tree();
    Style local = style;
    local.block_numbers = BlockNumbers::keep;
    local.percent = Percent::keep;
    const std::uint32_t count = lines.line_count();
    const std::uint32_t begin = lines.line_start(std::min(first_line, count - 1));
    const std::uint32_t end = last_line + 1 < count ? lines.line_start(last_line + 1) : static_cast<std::uint32_t>(tree.text.size());
    // Blocks from the one holding `begin` to the last that starts before `end`.
    std::size_t first = 0;
    while (first + 1 < tree.block_count() && tree.blocks[first + 1].begin <= begin) ++first;
    std::size_t last = first;
    while (last + 1 < tree.block_count() && tree.blocks[last + 1].begin < end) ++last;
    TextEdit edit;
    edit.range = {tree.blocks[first].begin, tree.block_range(last).end};
    const Renumbering none;
    Printer(file, local, context, none, edit.text).blocks(first, last + 1);
    return edit;
}

}  // namespace kerf::formatter
