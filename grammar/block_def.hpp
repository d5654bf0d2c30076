// Block items: words, comma words, comments, macro statements, '%', block delete, end of block,
// and the error rules that turn the seeds' real defects into precise diagnostics
// (reference/dialects.md §2; diagnostic ids in docs/diagnostics.md).
#pragma once

#include <fmt/format.h>

#include <boost/spirit/home/x3.hpp>

#include "ast/diagnostic_ids.hpp"
#include "grammar/expression_def.hpp"

namespace kerf::grammar {
namespace block_detail {

using namespace expr_detail;
using ast::Severity;
using ast::StatementKind;
using ast::TokenKind;

inline bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
inline char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

template <typename It>
std::string_view view(It b, It e) {
    return std::string_view(&*b, static_cast<std::size_t>(e - b));
}

// Primitive parsers that read raw characters and write into the builder share this frame: they
// define `scan(builder, first, last)` and X3 sees an ordinary parser without attribute.
template <typename Derived>
struct builder_primitive : x3::parser<Derived> {
    using attribute_type = x3::unused_type;
    static bool const has_attribute = false;
    using It = const char*;
    template <typename Ctx, typename RCtx, typename Attr>
    bool parse(It& first, It const& last, Ctx const& ctx, RCtx&, Attr&) const {
        return static_cast<const Derived&>(*this).scan(builder_of(ctx), first, last);
    }
};

// One ASCII address letter; the attribute is the letter as written.
struct letter_parser : x3::parser<letter_parser> {
    using attribute_type = char;
    static bool const has_attribute = true;
    template <typename It, typename Ctx, typename RCtx, typename Attr>
    bool parse(It& first, It const& last, Ctx const&, RCtx&, Attr& attr) const {
        if (first == last || !is_letter(*first)) return false;
        if constexpr (!std::is_same_v<Attr, x3::unused_type>) attr = *first;
        ++first;
        return true;
    }
};
letter_parser const letter{};
number_parser const word_number{true, true};

// --- word values ---------------------------------------------------------------------------------

auto const set_number = [](auto& ctx) {
    Builder& b = builder_of(ctx);
    b.pending = PendingValue::number;
    b.pending_number = x3::_attr(ctx);
};
auto const set_expr = [](auto& ctx) { builder_of(ctx).pending = PendingValue::expr; };

// X-12.5 | X[#1+2] | X#5 | X-#5 | X-[#1] (dialects.md §2, FANUC macro B)
auto const word_value = word_number[set_number] |
                        (x3::omit[x3::raw[x3::lit('-') >> blanks >> (variable | bracket)][wrap_one<ast::ExprKind::negate>{}]] |
                         x3::omit[x3::raw[x3::lit('+') >> blanks >> (variable | bracket)][wrap_one<ast::ExprKind::plus>{}]] |
                         variable | bracket)[set_expr];

template <typename Ctx>
void fill_value(Builder& b, ast::Token& t, std::string_view written) {
    if (b.pending == PendingValue::number) {
        const NumberLit& n = b.pending_number;
        b.store_token_number(n, t);
        if (n.comma) {
            const bool lenient = b.rules.decimal_comma_lenient;
            std::string fixed(written);
            for (char& c : fixed) if (c == ',') c = '.';
            b.diagnose(n.begin, n.end, lenient ? Severity::warning : Severity::error, ast::diagnostic_id::decimal_comma,
                       fmt::format("decimal comma in '{}': FANUC controls read only '.' as the decimal point",
                                   written),
                       fmt::format("write '{}'", fixed));
        }
    } else {
        t.flags |= ast::token_flags::value_expr;
        t.payload = b.pop();
    }
    b.pending = PendingValue::none;
}

struct make_word_t {
    TokenKind kind;
    template <typename Ctx>
    void operator()(Ctx& ctx) const {
        Builder& b = builder_of(ctx);
        const auto where = x3::_attr(ctx);
        const char* begin = &*where.begin();
        const char* end = begin + where.size();
        const char* letter_at = kind == TokenKind::comma_word ? begin + 1 : begin;
        ast::Token& t = b.add_token(kind, begin, end);
        t.letter = upper(*letter_at);
        if (*letter_at != t.letter) t.flags |= ast::token_flags::lower_case;
        fill_value<Ctx>(b, t, std::string_view(begin, static_cast<std::size_t>(end - begin)));
        b.last_error_mergeable = false;
        if (kind == TokenKind::comma_word && !b.rules.is_comma_word(t.letter)) {
            b.diagnose(begin, end, Severity::error, ast::diagnostic_id::unknown_comma_word,
                       fmt::format("',{}' is not a comma word of this dialect (allowed: {})", t.letter,
                                   b.rules.comma_words.empty() ? std::string("none") : b.rules.comma_words),
                       "remove the comma, or choose the dialect that has this direct-drawing word");
        }
    }
};

// The hot path: a letter directly followed by a plain number of at most nine digits (X-12.345,
// G01, F1200.), which is nearly every word of a CAM program. It builds the token in place; anything
// else (spaces, expressions, decimal commas, long numbers, defects) goes to the general rules below
// (bench/RESULTS.md has the figures that made this worth it).
inline bool plain_word(Builder& b, const char*& first, const char* last) {
    const char* p = first;
    const char address = *p;
    if (!is_letter(address)) return false;
    ++p;
    bool negative = false;
    if (p != last && (*p == '-' || *p == '+')) {
        negative = *p == '-';
        ++p;
    }
    std::uint32_t mantissa = 0;
    const char* digits_begin = p;
    while (p != last && static_cast<unsigned>(*p - '0') < 10u) mantissa = mantissa * 10 + static_cast<unsigned>(*p++ - '0');
    int digits = static_cast<int>(p - digits_begin);
    int scale = 0;
    const bool point = p != last && *p == '.';
    if (point) {
        const char* fraction_begin = ++p;
        while (p != last && static_cast<unsigned>(*p - '0') < 10u) mantissa = mantissa * 10 + static_cast<unsigned>(*p++ - '0');
        scale = static_cast<int>(p - fraction_begin);
        digits += scale;
    }
    if (digits == 0 || digits > 9 || mantissa > static_cast<std::uint32_t>(ast::Token::kMaxMantissa)) return false;
    if (p != last && (*p == '.' || *p == ',')) return false;   // and F0,25 take the long way
    ast::Token& t = b.add_token(TokenKind::word, first, p);
    t.letter = upper(address);
    t.flags = static_cast<std::uint8_t>((address != t.letter ? ast::token_flags::lower_case : 0) |
                                        (point ? ast::token_flags::has_point : 0) |
                                        (negative ? ast::token_flags::negative : 0));
    t.set_number(negative ? -static_cast<std::int32_t>(mantissa) : static_cast<std::int32_t>(mantissa), scale);
    b.last_error_mergeable = false;
    first = p;
    return true;
}

// A number directly followed by another '.' (X-12.8.) is malformed: caught by malformed_number.
auto const word = transactional[x3::omit[x3::raw[letter >> blanks >> word_value >> !x3::lit('.')][make_word_t{TokenKind::word}]]];
auto const comma_word =
    transactional[x3::omit[x3::raw[x3::lit(',') >> letter >> blanks >> word_value >> !x3::lit('.')][make_word_t{TokenKind::comma_word}]]];

// ':1000' is the tape form of O1000 (dialects.md §2, [FANUC]).
auto const colon_program = transactional[x3::omit[x3::raw[x3::lit(':') >> word_number[set_number]][([](auto& ctx) {
    Builder& b = builder_of(ctx);
    const auto where = x3::_attr(ctx);
    const char* begin = &*where.begin();
    ast::Token& t = b.add_token(TokenKind::word, begin, begin + where.size());
    t.letter = 'O';
    fill_value<decltype(ctx)>(b, t, {});
    b.last_error_mergeable = false;
})]]];

// --- comments ------------------------------------------------------------------------------------

// ( ... ): no nesting on FANUC; a nested '(' is diagnosed and balanced so the rest of the line still
// reads; a missing ')' makes the comment run to the end of the line, with an error.
struct paren_comment_parser : builder_primitive<paren_comment_parser> {
    bool scan(Builder& b, It& first, It last) const {
        if (first == last || *first != '(' || !b.rules.paren_comments) return false;
        It p = first;
        ++p;
        int depth = 1;
        const char* nested_at = nullptr;
        while (p != last) {
            if (*p == '(') {
                if (!nested_at) nested_at = &*p;
                ++depth;
            } else if (*p == ')') {
                if (--depth == 0) break;
            }
            ++p;
        }
        const bool closed = p != last;
        if (closed) ++p;
        ast::Token& t = b.add_token(TokenKind::comment, &*first, &*first + (p - first));
        if (!closed) {
            t.flags |= ast::token_flags::unclosed;
            b.diagnose(&*first, &*first + (p - first), Severity::error, ast::diagnostic_id::unclosed_comment,
                       "comment is not closed: ')' is missing before the end of the line",
                       "add ')' where the comment ends; a comment cannot continue on the next line");
        }
        if (nested_at) {
            b.diagnose(nested_at, nested_at + 1, Severity::warning, ast::diagnostic_id::nested_comment,
                       "'(' inside a comment: FANUC comments cannot be nested and end at the first ')'",
                       "replace the inner parentheses, e.g. with '[' and ']' or '-'");
        }
        b.last_error_mergeable = false;
        first = p;
        return true;
    }
};
paren_comment_parser const paren_comment{};

// Comments to the end of the line: ';' where it is not the end of block (pcnc-mill), and the
// dialect's line-comment introducers ('::' and ';;' in ADV400, dialects.md §6, §11.5).
struct line_comment_parser : builder_primitive<line_comment_parser> {
    bool scan(Builder& b, It& first, It last) const {
        if (first == last) return false;
        const std::string_view rest = view(first, last);
        bool match = *first == ';' && b.rules.semicolon == dialects::SemicolonRole::comment;
        for (const std::string& intro : b.rules.line_comments)
            if (!intro.empty() && rest.substr(0, intro.size()) == intro) match = true;
        if (!match) return false;
        // The comment ends at the line end; trailing '\r' stays trivia.
        It end = last;
        while (end != first && *std::prev(end) == '\r') --end;
        b.add_token(TokenKind::comment, &*first, &*first + (end - first));
        b.last_error_mergeable = false;
        first = end;
        return true;
    }
};
line_comment_parser const line_comment{};

// --- macro statements ------------------------------------------------------------------------------

struct macro_enabled_parser : builder_primitive<macro_enabled_parser> {
    bool scan(Builder& b, It&, It) const { return b.rules.macro_b; }
};
macro_enabled_parser const macro_enabled{};

// [Haas] `IF [...] G65 P9725`: an IF whose action is the rest of the block (lexical if_words).
struct if_words_enabled_parser : builder_primitive<if_words_enabled_parser> {
    bool scan(Builder& b, It&, It) const { return b.rules.if_words; }
};
if_words_enabled_parser const if_words_enabled{};

// DPRNT[...] text: brackets nest (#100[53] is a format), the text ends at the matching ']'.
struct bracket_text_parser : builder_primitive<bracket_text_parser> {
    bool scan(Builder& b, It& first, It last) const {
        if (first == last || *first != '[') return false;
        It p = std::next(first);
        int depth = 1;
        while (p != last) {
            if (*p == '[') ++depth;
            else if (*p == ']' && --depth == 0) break;
            ++p;
        }
        if (p == last) return false;
        b.pending_text = {b.offset(&*first) + 1, b.offset(&*p)};
        first = std::next(p);
        return true;
    }
};
bracket_text_parser const bracket_text{};

struct make_statement_t {
    StatementKind kind;
    template <typename Ctx>
    void operator()(Ctx& ctx) const {
        Builder& b = builder_of(ctx);
        const auto where = x3::_attr(ctx);
        ast::Statement s;
        s.kind = kind;
        s.range = {b.offset(&*where.begin()), b.offset(&*where.begin() + where.size())};
        switch (kind) {
            case StatementKind::assign:
                s.value = b.pop();
                s.target = b.pop();
                break;
            case StatementKind::if_goto:
            case StatementKind::while_do:
                s.label = b.pop();
                s.value = b.pop();
                break;
            case StatementKind::if_words:
                s.value = b.pop();
                break;
            case StatementKind::if_then:
                s.then_statement = b.statement_stack.back();
                b.statement_stack.pop_back();
                s.value = b.pop();
                break;
            case StatementKind::goto_:
            case StatementKind::do_:
            case StatementKind::end:
                s.label = b.pop();
                break;
            case StatementKind::dprnt:
            case StatementKind::bprnt:
                s.text = b.pending_text;
                break;
            case StatementKind::popen:
            case StatementKind::pclos:
                break;
        }
        b.tree.statements.push_back(s);
        b.statement_stack.push_back(static_cast<std::int32_t>(b.tree.statements.size() - 1));
    }
};

inline auto kw(const char* lower) { return x3::no_case[x3::lit(lower)]; }

// A label or jump target: GOTO 10, GOTO #1, GOTO [#1+2], DO 1, END 1.
auto const label = unary;

auto const assign_stmt =
    x3::omit[x3::raw[variable >> blanks >> x3::lit('=') >> blanks >> expression][make_statement_t{StatementKind::assign}]];
auto const goto_stmt = x3::omit[x3::raw[kw("goto") >> blanks >> label][make_statement_t{StatementKind::goto_}]];
auto const if_stmt =
    transactional[x3::omit[x3::raw[kw("if") >> blanks >> bracket >> blanks >> kw("goto") >> blanks >> label][make_statement_t{StatementKind::if_goto}]]] |
    transactional[x3::omit[x3::raw[kw("if") >> blanks >> bracket >> blanks >> kw("then") >> blanks >> assign_stmt][make_statement_t{StatementKind::if_then}]]] |
    (if_words_enabled >> x3::omit[x3::raw[kw("if") >> blanks >> bracket][make_statement_t{StatementKind::if_words}]]);
auto const while_stmt =
    x3::omit[x3::raw[kw("while") >> blanks >> bracket >> blanks >> kw("do") >> blanks >> label][make_statement_t{StatementKind::while_do}]];
auto const do_stmt = x3::omit[x3::raw[kw("do") >> blanks >> label][make_statement_t{StatementKind::do_}]];
auto const end_stmt = x3::omit[x3::raw[kw("end") >> blanks >> label][make_statement_t{StatementKind::end}]];
auto const print_stmt = x3::omit[x3::raw[kw("dprnt") >> blanks >> bracket_text][make_statement_t{StatementKind::dprnt}]] |
                        x3::omit[x3::raw[kw("bprnt") >> blanks >> bracket_text][make_statement_t{StatementKind::bprnt}]];
auto const file_stmt = x3::omit[x3::raw[kw("popen")][make_statement_t{StatementKind::popen}]] | x3::omit[x3::raw[kw("pclos")][make_statement_t{StatementKind::pclos}]];

auto const make_statement_token = [](auto& ctx) {
    Builder& b = builder_of(ctx);
    const auto where = x3::_attr(ctx);
    const char* begin = &*where.begin();
    ast::Token& t = b.add_token(TokenKind::statement, begin, begin + where.size());
    t.payload = b.statement_stack.back();
    b.statement_stack.pop_back();
    b.last_error_mergeable = false;
};

auto const statement = transactional[macro_enabled >>
                                     x3::omit[x3::raw[transactional[assign_stmt] | transactional[if_stmt] | transactional[while_stmt] |
                                             transactional[goto_stmt] | transactional[do_stmt] | transactional[end_stmt] |
                                             print_stmt | file_stmt][make_statement_token]]];

// --- simple tokens -------------------------------------------------------------------------------

template <TokenKind Kind>
struct simple_token_t {
    template <typename Ctx>
    void operator()(Ctx& ctx) const {
        Builder& b = builder_of(ctx);
        const auto where = x3::_attr(ctx);
        ast::Token& t = b.add_token(Kind, &*where.begin(), &*where.begin() + where.size());
        if (Kind == TokenKind::block_delete && where.size() > 1) t.letter = *std::next(where.begin());
        b.last_error_mergeable = false;
    }
};

auto const percent = x3::omit[x3::raw[x3::lit('%')][simple_token_t<TokenKind::percent>{}]];
// '/' and '/1'…'/9' (dialects.md §2, [FANUC]); only at the start of a block (see block rule).
auto const block_delete = x3::omit[x3::raw[x3::lit('/') >> -x3::char_("1-9") >> !x3::lit('/')][simple_token_t<TokenKind::block_delete>{}]];


// --- error rules ---------------------------------------------------------------------------------

// Each takes the text of a defect and explains it; see docs/diagnostics.md.
struct error_rules_parser : builder_primitive<error_rules_parser> {
    bool scan(Builder& b, It& first, It last) const {
        if (first == last) return false;
        if (*first == ';' && b.rules.semicolon == dialects::SemicolonRole::end_of_block) return false;
        const char* const begin = &*first;
        const char* const end = begin + (last - first);
        const char* p = begin;
        auto finish = [&](const char* stop) {
            first += (stop - begin);
            return true;
        };
        // An expression nested past the grammar's limit: the rest of the line cannot be read.
        if (b.too_deep_at) {
            b.too_deep_at = nullptr;
            const char* r = end;
            while (r > p && *(r - 1) == '\r') --r;
            b.add_error(begin, r, ast::diagnostic_id::nesting_too_deep,
                        fmt::format("expression nested more than {} levels deep", Builder::kMaxExpressionDepth),
                        "FANUC allows 5 levels of brackets; split the expression with #variables", false);
            return finish(r);
        }
        if (is_letter(*p)) {
            const char L = upper(*p);
            const char* q = p + 1;
            // MO6, GO, GOO, HO1: the letter O typed for the digit zero (dialects.md §11.10, seed 004 OCR).
            if (q < end && (*q == 'O' || *q == 'o')) {
                const char* r = q;
                while (r < end && (*r == 'O' || *r == 'o' || is_digit(*r) || *r == '.')) ++r;
                if (r == end || !is_letter(*r)) {
                    std::string fixed(begin, r);
                    for (std::size_t i = 1; i < fixed.size(); ++i)
                        if (fixed[i] == 'O' || fixed[i] == 'o') fixed[i] = '0';
                    b.add_error(begin, r, ast::diagnostic_id::letter_o_for_zero,
                                fmt::format("letter O in '{}' where the digit zero is meant", view(begin, r)),
                                fmt::format("write '{}'", fixed), false);
                    return finish(r);
                }
            }
            // X?  Y?  B_: a placeholder left in the program (or a format line copied from a manual).
            if (q < end && (*q == '?' || *q == '_')) {
                const char* r = q;
                while (r < end && (*r == '?' || *r == '_')) ++r;
                b.add_error(begin, r, ast::diagnostic_id::placeholder_value,
                            fmt::format("placeholder '{}': the value of {} is missing", view(begin, r), L),
                            fmt::format("replace '{}' with the value of {}", view(q, r), L), false);
                return finish(r);
            }
            // .: a second decimal point.
            {
                const char* r = q;
                while (r < end && is_blank(*r)) ++r;
                NumberLit n;
                const char* s = r;
                if (scan_number(s, end, true, false, n) && s < end && *s == '.') {
                    if (n.point && s[-1] == '.' && s + 1 < end && s[1] == '.') {
                        // N10... : an ellipsis of a printed listing, not a number.
                        const char* e = s;
                        while (e < end && e[0] == '.') ++e;
                        b.add_error(begin, e, ast::diagnostic_id::listing_ellipsis,
                                    fmt::format("'{}' ends in an ellipsis: a listing's omission mark, not program text",
                                                view(begin, e)),
                                    "write the omitted blocks, or put the note in a comment", false);
                        return finish(e);
                    }
                    while (s < end && (*s == '.' || is_digit(*s))) ++s;
                    b.add_error(begin, s, ast::diagnostic_id::malformed_number,
                                fmt::format("malformed number in '{}': more than one decimal point", view(begin, s)),
                                "keep one decimal point, e.g. " + std::string(begin, n.end) + "", false);
                    return finish(s);
                }
            }
            // Three or more letters: neither a word nor a macro keyword (IF, GOTO, WHILE, ...). Two
            // letters (IZ-0.6) are more likely a word whose value was lost: let the next one read.
            const char* run = q;
            while (run < end && is_letter(*run)) ++run;
            if (run - begin >= 3) {
                const char* r = run;
                b.add_error(begin, r, ast::diagnostic_id::unknown_word,
                            fmt::format("'{}' is neither an address word nor a macro keyword", view(begin, r)),
                            b.rules.macro_b ? "put text in a comment '( ... )', or check the spelling of the keyword"
                                            : "put text in a comment; this dialect has no macro statements",
                            true);
                return finish(r);
            }
            // An address letter without value (X-11.Z). A bare N is a legal empty sequence number.
            ast::Token& t = b.add_token(TokenKind::word, begin, q);
            t.letter = L;
            if (*begin != L) t.flags |= ast::token_flags::lower_case;
            t.flags |= ast::token_flags::value_none;
            b.last_error_mergeable = false;
            if (L != 'N') {
                b.diagnose(begin, q, Severity::error, ast::diagnostic_id::address_without_value, fmt::format("address {} has no value", L),
                           fmt::format("write the value right after {} (e.g. {}0.) or remove the letter", L, L));
            }
            return finish(q);
        }
        // 00018 at the start of a block: a program number whose O was read as zero (dialects.md §2, §11.10).
        if (*p == '0' && b.tree.tokens.size() == b.block_first_token) {
            const char* s = p + 1;
            while (s < end && is_digit(*s)) ++s;
            const std::size_t digits = static_cast<std::size_t>(s - p - 1);
            if (digits >= 3 && digits <= 5 && (s == end || !(*s == '.' || is_digit(*s) || is_letter(*s)))) {
                ast::Token& t = b.add_token(TokenKind::word, begin, s);
                t.letter = 'O';
                std::int32_t number = 0;
                for (const char* d = p + 1; d < s; ++d) number = number * 10 + (*d - '0');
                t.set_number(number, 0);
                b.diagnose(begin, p + 1, Severity::warning, ast::diagnostic_id::zero_for_letter_o,
                           fmt::format("'{}' reads as program number O{}: the letter O was written as the digit 0",
                                       view(begin, s), view(p + 1, s)),
                           fmt::format("write 'O{}'", view(p + 1, s)));
                b.last_error_mergeable = false;
                return finish(s);
            }
        }
        // '...' standing for omitted blocks in a printed listing.
        if (*p == '.' && p + 2 < end && p[1] == '.' && p[2] == '.') {
            const char* e = p;
            while (e < end && *e == '.') ++e;
            b.add_error(begin, e, ast::diagnostic_id::listing_ellipsis, "'...' marks omitted blocks in a listing; it is not program text",
                        "write the omitted blocks, or put the note in a comment", false);
            return finish(e);
        }
        // 27 in 'N90 27 F100': a number without its address letter.
        {
            const char* s = p;
            NumberLit n;
            if (scan_number(s, end, true, false, n)) {
                while (s < end && (*s == '.' || is_digit(*s))) ++s;
                b.add_error(begin, s, ast::diagnostic_id::value_without_address,
                            fmt::format("value '{}' has no address letter", view(begin, s)),
                            "every value needs its address (X, Z, F, ...) in front; is a letter missing?", true);
                return finish(s);
            }
        }
        if (*p == '/' && p + 1 < end && p[1] == '/') {
            // '//' comments belong to Syntec and other PC controls; FANUC reads '/' as block delete.
            const char* r = end;
            while (r > p && *(r - 1) == '\r') --r;
            b.add_error(begin, r, ast::diagnostic_id::slash_comment, "'//' comment: FANUC controls have no '//' comments",
                        "write the comment in parentheses: ( ... )", false);
            return finish(r);
        }
        if (*p == '/' && !b.last_error_mergeable) {
            b.add_error(begin, p + 1, ast::diagnostic_id::misplaced_block_delete, "block delete '/' must be the first character of the block",
                        "move '/' to the start of the block, or remove it", false);
            return finish(p + 1);
        }
        if (*p == ')' && !b.last_error_mergeable) {
            b.add_error(begin, p + 1, ast::diagnostic_id::unmatched_close_paren, "')' without '(': the comment has no start",
                        "add '(' where the comment begins", false);
            return finish(p + 1);
        }
        // Anything else: one character, or a whole run of non-ASCII bytes (prose outside a comment).
        const char* r = p + 1;
        if (static_cast<unsigned char>(*p) >= 0x80)
            while (r < end && static_cast<unsigned char>(*r) >= 0x80) ++r;
        b.add_error(begin, r, ast::diagnostic_id::stray_text, fmt::format("unexpected '{}'", view(begin, r)),
                    b.rules.paren_comments ? "text must be inside a comment '( ... )'" : "remove it", true);
        return finish(r);
    }
};
error_rules_parser const error_rules{};

// Grammar objects are namespace-scope constants with internal linkage, defined in dependency order in
// the one translation unit that includes this header (grammar/parse.cpp): no inline variables, whose
// initialization order against ordinary ones is not guaranteed (a fuzzer found that the hard way).
// Items in the order they are tried; the error rules take whatever is left, so the item loop only
// stops at the end of the line or at ';' (end of block).
auto const item = paren_comment | word | line_comment | comma_word | statement | percent | error_rules;

// The item loop: blanks, then the plain-word fast path, then the X3 alternatives above. It stops at
// the end of the line or at ';' (end of block), which no item takes.
template <typename Item>
struct items_parser : x3::parser<items_parser<Item>> {
    using attribute_type = x3::unused_type;
    static bool const has_attribute = false;
    Item item;
    constexpr items_parser(Item i) : item(i) {}
    template <typename It, typename Ctx, typename RCtx, typename Attr>
    bool parse(It& first, It const& last, Ctx const& ctx, RCtx& rctx, Attr&) const {
        Builder& b = builder_of(ctx);
        while (true) {
            while (first != last && is_blank(*first)) ++first;
            if (first == last) return true;
            if (plain_word(b, first, last)) continue;
            if (!item.parse(first, last, ctx, rctx, x3::unused)) return true;
        }
    }
};
items_parser<decltype(item)> const items{item};

auto const block_body = blanks >> -(block_delete >> blanks) >> -(&x3::lit(':') >> colon_program >> blanks) >> items;

}  // namespace block_detail
}  // namespace kerf::grammar
