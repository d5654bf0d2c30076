// The lossless syntax tree. Every byte of the text belongs to a token or is trivia (spaces, tabs,
// line breaks) between tokens; blocks are contiguous and cover the whole text, so printing the
// tokens and the trivia between them gives back the input byte for byte (ast/printer.hpp).
//
// Layout is flat and compact on purpose (bench/RESULTS.md): tokens, expression nodes and statements
// live in three arrays and refer to each other by index; numbers are exact decimals
// (mantissa / 10^scale), which is what a FANUC control reads and what the formatter must print back.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ast/diagnostic.hpp"
#include "ast/large_allocator.hpp"
#include "ast/source.hpp"

namespace kerf::ast {

enum class TokenKind : std::uint8_t {
    word,          // address letter + value: N10 G01 X[#1+2] O1000, or a letter without value
    comma_word,    // ,A45. ,C1 ,R2 (direct drawing)
    comment,       // ( ... ), or a line comment (";" in pcnc-mill, "::"/";;" in ADV400)
    block_delete,  // "/" or "/1" ... "/9" at the start of a block
    percent,       // "%" (tape start / end)
    eob,           // ";" end of block
    statement,     // macro statement (payload = index into statements)
    bom,           // UTF-8 byte order mark at the start of the file
    error,         // bytes that do not parse; a diagnostic covers them
};
const char* to_string(TokenKind k);

// What a token means once bound against the dialect (ast/typed.hpp). Set by bind().
enum class Role : std::uint8_t {
    none,
    sequence,          // N
    program,           // O (or ':')
    g_code,
    m_code,
    axis_absolute,     // X Z C ... (or any axis under G90 in B/C and mills: decided at run time)
    axis_incremental,  // U W H in system A
    parameter,         // every other address: F S T P Q R I J K D H L E A B ...
    direct_drawing,    // plain A / R read as angle / corner radius (SPINNER)
};
const char* to_string(Role r);

namespace token_flags {
inline constexpr std::uint8_t has_point = 1 << 0;      // the number had a decimal point
inline constexpr std::uint8_t lower_case = 1 << 1;     // the address letter was lower case
inline constexpr std::uint8_t decimal_comma = 1 << 2;  // F0,25: comma read as point
inline constexpr std::uint8_t value_expr = 1 << 3;     // payload = expression index
inline constexpr std::uint8_t value_none = 1 << 4;     // address without value
inline constexpr std::uint8_t value_big = 1 << 5;      // payload = index into big_numbers
inline constexpr std::uint8_t negative = 1 << 6;       // value written with '-' (keeps -0.)
inline constexpr std::uint8_t unclosed = 1 << 7;       // comment without ')'
}  // namespace token_flags

// A token is 12 bytes (the bulk of a tree: 2.4 tokens a line of CAM output, bench/RESULTS.md). Its
// length is kept in 8 bits; a token of kLongLength bytes or more (a long comment or macro expression)
// has its length in SyntaxTree::long_tokens: ask the tree (SyntaxTree::length, range, end).
// A number's payload holds mantissa * 16 + scale, so mantissas are 28-bit (bigger ones go to
// big_numbers, like any number that does not fit).
struct Token {
    static constexpr std::uint8_t kLongLength = 255;
    static constexpr std::int32_t kMaxMantissa = (1 << 27) - 1;

    std::uint32_t begin = 0;
    std::int32_t payload = 0;          // a number: mantissa * 16 + scale; else an index (see flags and kind)
    std::uint8_t short_length = 0;     // the length, or kLongLength (the tree has it)
    char letter = 0;                   // upper-case address letter of words and comma words; '/' level digit
    std::uint8_t flags = 0;
    TokenKind kind : 4 = TokenKind::error;
    Role role_bits : 4 = Role::none;

    bool has(std::uint8_t flag) const { return (flags & flag) != 0; }
    // Numbers (is_number()) only: the exact decimal mantissa / 10^scale.
    std::int32_t mantissa() const { return payload >> 4; }
    int scale() const { return payload & 0x0F; }
    void set_number(std::int32_t mantissa, int scale) { payload = static_cast<std::int32_t>(static_cast<std::uint32_t>(mantissa) << 4) | (scale & 0x0F); }
    Role role() const { return role_bits; }
    void set_role(Role r) { role_bits = r; }
    bool is_number() const { return (kind == TokenKind::word || kind == TokenKind::comma_word) && !(flags & (token_flags::value_expr | token_flags::value_none)); }
};
static_assert(sizeof(Token) == 12, "tokens are the bulk of the tree; keep them at 12 bytes");

// mantissa / 10^scale for |mantissa| < 2^53 and scale 0..15: the correctly rounded double, the one
// the decimal's spelling reads as (from_chars, strtod).
double exact_decimal(std::int64_t mantissa, int scale);

// The length of a token of Token::kLongLength bytes or more, by the token's begin.
struct LongToken {
    std::uint32_t begin = 0;
    std::uint32_t length = 0;
};

enum class BlockKind : std::uint8_t {
    code,          // words and/or statements
    blank,         // only trivia
    comment_only,  // only comments (and trivia)
    percent,       // a "%" line
    program_start, // starts with an O word (or ':')
    tail,          // text after the closing '%': the control ignores it; kept verbatim
};
const char* to_string(BlockKind k);

namespace block_flags {
inline constexpr std::uint8_t has_error = 1 << 0;    // a token of the block is an error
inline constexpr std::uint8_t has_eob = 1 << 1;      // ended by ';'
inline constexpr std::uint8_t deleted = 1 << 2;      // starts with block delete '/'
}  // namespace block_flags

// A block is [begin, next block's begin). Its tokens are tokens[first_token, next block's first_token).
struct Block {
    std::uint32_t begin = 0;
    std::uint32_t first_token = 0;
    BlockKind kind = BlockKind::code;
    std::uint8_t flags = 0;
    std::uint16_t reserved = 0;
    bool has(std::uint8_t flag) const { return (flags & flag) != 0; }
};
static_assert(sizeof(Block) == 12);

enum class ExprKind : std::uint8_t {
    number,     // a = mantissa (or big index), scale, flags as tokens
    variable,   // #a  (a = child: number or bracket)
    negate,     // -a
    plus,       // +a
    binary,     // a op b
    function,   // op = Function; a, b (b = -1 with one argument)
    bracket,    // [a]
};
enum class BinaryOp : std::uint8_t { add, sub, mul, div, or_, xor_, and_, mod, eq, ne, gt, lt, ge, le };
enum class Function : std::uint8_t { sin, cos, tan, asin, acos, atan, sqrt, abs, bin, bcd, round, fix, fup, ln, exp, pow, adp };
const char* to_string(BinaryOp op);
const char* to_string(Function f);

struct Expr {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    ExprKind kind = ExprKind::number;
    std::uint8_t op = 0;        // BinaryOp or Function
    std::uint8_t flags = 0;     // token_flags for numbers
    std::uint8_t scale = 0;
    std::int32_t a = -1;
    std::int32_t b = -1;
    Range range() const { return {begin, end}; }
    BinaryOp binary_op() const { return static_cast<BinaryOp>(op); }
    Function function() const { return static_cast<Function>(op); }
};

enum class StatementKind : std::uint8_t {
    assign,    // #target = value
    if_goto,   // IF [value] GOTO label
    if_then,   // IF [value] THEN then_statement
    goto_,     // GOTO label
    while_do,  // WHILE [value] DO label
    do_,       // DO label
    end,       // END label
    dprnt, bprnt, popen, pclos,   // text = what is between the brackets
    if_words,  // [Haas] IF [value] followed by the block's words: they run when value holds (lexical if_words)
};
const char* to_string(StatementKind k);

struct Statement {
    Range range;
    StatementKind kind = StatementKind::assign;
    std::int32_t target = -1;          // assign: the variable expression
    std::int32_t value = -1;           // assign: right side; IF/WHILE: condition
    std::int32_t label = -1;           // GOTO/DO/END/IF GOTO: label expression
    std::int32_t then_statement = -1;  // IF ... THEN: index of the nested statement
    Range text;                        // DPRNT/BPRNT: the bracket content
};

struct SyntaxTree {
    std::string text;
    LargeVector<Block> blocks;
    LargeVector<Token> tokens;
    std::vector<Expr> exprs;
    std::vector<Statement> statements;
    std::vector<double> big_numbers;   // numbers that do not fit mantissa/scale
    std::vector<LongToken> long_tokens;  // sorted by begin: the tokens too long for Token::short_length
    std::vector<Diagnostic> diagnostics;

    // Inline: the analyzer's rules, the binder and the formatter ask these for every block, several
    // times (out of line they were 5 % of a kerf check, bench/RESULTS.md).
    std::size_t block_count() const { return blocks.size(); }
    Range block_range(std::size_t i) const {
        const std::uint32_t end = i + 1 < blocks.size() ? blocks[i + 1].begin : static_cast<std::uint32_t>(text.size());
        return {blocks[i].begin, end};
    }
    std::span<const Token> block_tokens(std::size_t i) const {
        const std::uint32_t first = blocks[i].first_token;
        return std::span<const Token>(tokens.data() + first, block_token_end(i) - first);
    }
    std::uint32_t block_first_token(std::size_t i) const { return blocks[i].first_token; }
    std::uint32_t block_token_end(std::size_t i) const {
        return i + 1 < blocks.size() ? blocks[i + 1].first_token : static_cast<std::uint32_t>(tokens.size());
    }
    std::string_view slice(Range r) const { return std::string_view(text).substr(r.begin, r.size()); }
    std::uint32_t length(const Token& t) const { return t.short_length != Token::kLongLength ? t.short_length : long_length(t.begin); }
    std::uint32_t end(const Token& t) const { return t.begin + length(t); }
    Range range(const Token& t) const { return {t.begin, end(t)}; }
    // Sets a token's length (the builder, when it makes or widens a token); a long one is recorded
    // in long_tokens, which stays sorted.
    void set_length(Token& t, std::uint32_t length);
    std::string_view spelling(const Token& t) const { return slice(range(t)); }
    // The text of a word's value ("-12.5" of "X-12.5"), after the letter and any spaces.
    std::string_view value_spelling(const Token& t) const;
    Range value_range(const Token& t) const;   // where value_spelling is: "P1000" -> "1000"
    double number_value(const Token& t) const;   // words with a numeric value
    double number_value(const Expr& e) const;    // number nodes

private:
    std::uint32_t long_length(std::uint32_t begin) const;
};

}  // namespace kerf::ast
