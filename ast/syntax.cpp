#include "ast/syntax.hpp"

#include <algorithm>
#include <cmath>

namespace kerf::ast {

const char* to_string(Severity s) {
    switch (s) {
        case Severity::error: return "error";
        case Severity::warning: return "warning";
        case Severity::info: return "info";
        case Severity::hint: return "hint";
    }
    return "?";
}

const char* to_string(TokenKind k) {
    switch (k) {
        case TokenKind::word: return "word";
        case TokenKind::comma_word: return "comma_word";
        case TokenKind::comment: return "comment";
        case TokenKind::block_delete: return "block_delete";
        case TokenKind::percent: return "percent";
        case TokenKind::eob: return "eob";
        case TokenKind::statement: return "statement";
        case TokenKind::bom: return "bom";
        case TokenKind::error: return "error";
    }
    return "?";
}

const char* to_string(Role r) {
    switch (r) {
        case Role::none: return "none";
        case Role::sequence: return "sequence";
        case Role::program: return "program";
        case Role::g_code: return "g_code";
        case Role::m_code: return "m_code";
        case Role::axis_absolute: return "axis";
        case Role::axis_incremental: return "axis_incremental";
        case Role::parameter: return "parameter";
        case Role::direct_drawing: return "direct_drawing";
    }
    return "?";
}

const char* to_string(BlockKind k) {
    switch (k) {
        case BlockKind::code: return "code";
        case BlockKind::blank: return "blank";
        case BlockKind::comment_only: return "comment";
        case BlockKind::percent: return "percent";
        case BlockKind::program_start: return "program_start";
        case BlockKind::tail: return "tail";
    }
    return "?";
}

const char* to_string(BinaryOp op) {
    static const char* const names[] = {"+", "-", "*", "/", "OR", "XOR", "AND", "MOD",
                                        "EQ", "NE", "GT", "LT", "GE", "LE"};
    return names[static_cast<int>(op)];
}

const char* to_string(Function f) {
    static const char* const names[] = {"SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "BIN",
                                        "BCD", "ROUND", "FIX", "FUP", "LN", "EXP", "POW", "ADP"};
    return names[static_cast<int>(f)];
}

const char* to_string(StatementKind k) {
    switch (k) {
        case StatementKind::assign: return "assign";
        case StatementKind::if_goto: return "if_goto";
        case StatementKind::if_then: return "if_then";
        case StatementKind::if_words: return "if_words";
        case StatementKind::goto_: return "goto";
        case StatementKind::while_do: return "while_do";
        case StatementKind::do_: return "do";
        case StatementKind::end: return "end";
        case StatementKind::dprnt: return "dprnt";
        case StatementKind::bprnt: return "bprnt";
        case StatementKind::popen: return "popen";
        case StatementKind::pclos: return "pclos";
    }
    return "?";
}

namespace {
// The first entry at or after `begin` (long_tokens is sorted by begin).
template <typename Vector>
auto long_entry(Vector& long_tokens, std::uint32_t begin) {
    return std::lower_bound(long_tokens.begin(), long_tokens.end(), begin, [](const LongToken& l, std::uint32_t b) { return l.begin < b; });
}
}  // namespace

std::uint32_t SyntaxTree::long_length(std::uint32_t begin) const {
    const auto it = long_entry(long_tokens, begin);
    return it != long_tokens.end() && it->begin == begin ? it->length : Token::kLongLength;
}

void SyntaxTree::set_length(Token& t, std::uint32_t length) {
    const auto it = long_entry(long_tokens, t.begin);
    const bool recorded = it != long_tokens.end() && it->begin == t.begin;
    if (length < Token::kLongLength) {
        if (recorded) long_tokens.erase(it);
        t.short_length = static_cast<std::uint8_t>(length);
        return;
    }
    t.short_length = Token::kLongLength;
    if (recorded) it->length = length;
    else long_tokens.insert(it, LongToken{t.begin, length});
}

std::string_view SyntaxTree::value_spelling(const Token& t) const {
    std::string_view s = spelling(t);
    const std::size_t skip = t.kind == TokenKind::comma_word ? 2 : 1;
    if (s.size() < skip) return {};
    s.remove_prefix(skip);
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    return s;
}

Range SyntaxTree::value_range(const Token& t) const {
    const std::uint32_t e = end(t);
    return {e - static_cast<std::uint32_t>(value_spelling(t).size()), e};
}

double exact_decimal(std::int64_t mantissa, int scale) {
    static constexpr double kPow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    // mantissa and 10^scale are exact doubles, so the quotient is correctly rounded.
    return static_cast<double>(mantissa) / kPow10[scale];
}

namespace {
double decimal_value(std::int32_t mantissa, int scale, std::uint8_t flags, const std::vector<double>& big) {
    if (flags & token_flags::value_big) return big[static_cast<std::size_t>(mantissa)];
    const double v = exact_decimal(mantissa, scale);
    return (flags & token_flags::negative) && v == 0.0 ? -0.0 : v;
}
}  // namespace

double SyntaxTree::number_value(const Token& t) const {
    if (!t.is_number()) return std::nan("");
    if (t.has(token_flags::value_big)) return big_numbers[static_cast<std::size_t>(t.payload)];
    return decimal_value(t.mantissa(), t.scale(), t.flags, big_numbers);
}

double SyntaxTree::number_value(const Expr& e) const {
    return decimal_value(e.a, e.scale, e.flags, big_numbers);
}

}  // namespace kerf::ast
