#include "project/scan.hpp"

#include <cctype>
#include <cmath>
#include <cstring>
#include <optional>

#include "ast/source.hpp"
#include "grammar/parse.hpp"

namespace kerf::project {

namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
bool digit(char c) { return c >= '0' && c <= '9'; }

enum class Kind { blank, comment_only, code, program_start, percent };

// What the scan needs of one block (grammar/parse.cpp classify()).
struct Block {
    Kind kind = Kind::blank;
    std::size_t end = 0;                  // where the next block of the line starts (after ';')
    bool has_o = false;                   // an O word starts the program (after '%' too)
    std::optional<std::int64_t> number;   // its integer value
    std::string_view comment;             // the first comment's text, without ( )
};

class BlockReader {
public:
    BlockReader(std::string_view text, const ScanRules& rules) : text_(text), rules_(rules) {}

    // The block from `p` to the end of its line `le` (or to its ';'); `after_bom`: the file's
    // BOM came first (a token of the block for the grammar).
    Block read(std::size_t p, std::size_t le, bool after_bom = false) const {
        Block b;
        p = skip_blanks(p, le);
        if (plain_code(p, le)) {   // most blocks: a word first, no comment, no ';'
            b.kind = Kind::code;
            b.end = le;
            return b;
        }
        if (p < le && text_[p] == '/') {   // block delete, /n
            ++p;
            while (p < le && digit(text_[p])) ++p;
            b.kind = Kind::code;
            p = skip_blanks(p, le);
        }
        if (p < le && text_[p] == ':' && p + 1 < le && digit(text_[p + 1]) && !line_comment_at(p)) {
            read_number(p + 1, le, b);   // ISO program number :1000
            b.kind = Kind::program_start;
        }
        bool leading = b.kind != Kind::program_start;
        bool any = b.kind != Kind::blank;
        bool plain_prefix = b.kind != Kind::program_start;   // only plain words (and comments, '/') so far
        std::size_t plain_words = 0;
        bool all_comments = b.kind == Kind::blank;
        while (p < le) {
            const char c = text_[p];
            if (blank(c)) {
                ++p;
                continue;
            }
            if (rules_.paren_comments && c == '(') {
                p = comment_end(p, le, b);
                any = true;
                continue;
            }
            if (line_comment_at(p)) {
                if (b.comment.empty()) b.comment = trim(text_.substr(p, le - p));
                any = true;
                p = le;
                break;
            }
            if (c == ';' && rules_.semicolon_ends_block) break;
            // A word, a statement, '%' or an error: the first one decides the block's kind.
            if (!any && c == '%') {
                plain_prefix = false;
                b.kind = Kind::percent;
                leading = false;
                any = true;
                all_comments = false;
                p = percent_program(p + 1, le, b);
                if (b.has_o) p = skip_item(p, le);
                continue;
            }
            // An O word after plain words starts the next program on the same line (`M99O0810`):
            // the block ends before it (grammar/parse.cpp program_word_after_first).
            if ((c == 'O' || c == 'o') && plain_prefix && plain_words > 0 && digit_after(p + 1, le)) break;
            if (leading) {
                leading = false;
                if ((c == 'O' || c == 'o') && !o_is_error(p, le)) {
                    b.kind = Kind::program_start;
                    b.has_o = true;
                    read_number(p + 1, le, b);
                } else if (!any && !after_bom && zero_for_o(p, le, b)) {
                    b.kind = Kind::program_start;
                }
            }
            any = true;
            all_comments = false;
            const std::size_t item = p;
            p = skip_item(p, le);
            if (grammar::is_plain_word(text_.substr(item, p - item))) ++plain_words;
            else plain_prefix = false;
        }
        if (b.kind == Kind::blank && any) b.kind = all_comments ? Kind::comment_only : Kind::code;
        b.end = p < le && text_[p] == ';' ? p + 1 : p < le ? p : le;
        return b;
    }

private:
    std::string_view text_;
    const ScanRules& rules_;

    // A block that starts with a letter other than O (N10, G01, X1., IF, #1=...) and holds no
    // comment and no ';' before the line end is code to the line end: one memchr each, no loop.
    bool plain_code(std::size_t p, std::size_t le) const {
        if (p >= le) return false;
        const char c = text_[p];
        const bool word = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '#';
        if (!word || c == 'O' || c == 'o') return false;
        const char* begin = text_.data() + p;
        const std::size_t n = le - p;
        if (std::memchr(begin, ';', n) || (rules_.paren_comments && std::memchr(begin, '(', n))) return false;
        if (std::memchr(begin + 1, 'O', n - 1) || std::memchr(begin + 1, 'o', n - 1)) return false;   // M99O0810
        for (const std::string& intro : rules_.line_comments)
            if (!intro.empty() && std::memchr(begin, intro.front(), n)) return false;
        return true;
    }

    bool digit_after(std::size_t p, std::size_t le) const {
        p = skip_blanks(p, le);
        return p < le && digit(text_[p]);
    }

    std::size_t skip_blanks(std::size_t p, std::size_t le) const {
        while (p < le && blank(text_[p])) ++p;
        return p;
    }

    static std::string_view trim(std::string_view s) {
        while (!s.empty() && (blank(s.front()) || s.front() == '(')) s.remove_prefix(1);
        while (!s.empty() && (blank(s.back()) || s.back() == ')')) s.remove_suffix(1);
        return s;
    }

    bool line_comment_at(std::size_t p) const {
        const std::string_view rest = text_.substr(p);
        if (!rules_.semicolon_ends_block && rest.starts_with(';')) return true;
        for (const std::string& intro : rules_.line_comments)
            if (!intro.empty() && rest.starts_with(intro)) return true;
        return false;
    }

    // ( ... ) with nesting counted as the grammar counts it; an unclosed comment runs to the line end.
    std::size_t comment_end(std::size_t p, std::size_t le, Block& b) const {
        const std::size_t begin = p;
        int depth = 0;
        for (; p < le; ++p) {
            if (text_[p] == '(') ++depth;
            else if (text_[p] == ')' && --depth == 0) {
                ++p;
                break;
            }
        }
        if (b.comment.empty()) b.comment = trim(text_.substr(begin, p - begin));
        return p;
    }

    // DPRNT[...] / BPRNT[...] at p: the position after its matching ']' on the line (the grammar
    // reads the text between as it is, ';' and '(' included), or p.
    std::size_t print_text_end(std::size_t p, std::size_t le) const {
        if (!rules_.macro_b || le - p < 6) return p;
        for (const char* kw : {"DPRNT", "BPRNT"}) {
            std::size_t i = 0;
            while (i < 5 && std::toupper(static_cast<unsigned char>(text_[p + i])) == kw[i]) ++i;
            if (i < 5) continue;
            std::size_t q = skip_blanks(p + 5, le);
            if (q >= le || text_[q] != '[') return p;
            int depth = 0;
            for (; q < le; ++q) {
                if (text_[q] == '[') ++depth;
                else if (text_[q] == ']' && --depth == 0) return q + 1;
            }
            return p;
        }
        return p;
    }

    // Past one item: up to the next blank, comment, ';', or letter after a value.
    std::size_t skip_item(std::size_t p, std::size_t le) const {
        if (const std::size_t printed = print_text_end(p, le); printed != p) return printed;
        if (p < le) ++p;
        while (p < le) {
            const char c = text_[p];
            if (blank(c) || c == '(' || c == ';' || line_comment_at(p)) break;
            // A letter after a value starts the next item (O6DPRNT[...], G0X1).
            if (std::isalpha(static_cast<unsigned char>(c)) && !std::isalpha(static_cast<unsigned char>(text_[p - 1]))) break;
            ++p;
        }
        return p;
    }

    // The O word after '%' on the same line (%O0003(...)): blanks, comments and more '%' may come
    // between (ast::ProgramSplitter skips the same tokens).
    std::size_t percent_program(std::size_t p, std::size_t le, Block& b) const {
        while (p < le) {
            if (blank(text_[p]) || text_[p] == '%') {
                ++p;
            } else if (rules_.paren_comments && text_[p] == '(') {
                p = comment_end(p, le, b);
            } else {
                break;
            }
        }
        if (p < le && (text_[p] == 'O' || text_[p] == 'o') && !o_is_error(p, le)) {
            b.has_o = true;
            read_number(p + 1, le, b);
        }
        return p;
    }

    // An O that the grammar reads as an error, not as a word (grammar/block_def.hpp): OO12 (letter O
    // for zero, S0103), O? (placeholder, S0104), O1.2. (two points, S0102), ORIGIN (three letters or
    // more, S0106). Such a block is code, not the start of a program.
    bool o_is_error(std::size_t p, std::size_t le) const {
        const std::size_t q = p + 1;
        if (q >= le) return false;
        const char next = text_[q];
        if (next == 'O' || next == 'o') {
            std::size_t r = q;
            while (r < le && (text_[r] == 'O' || text_[r] == 'o' || digit(text_[r]) || text_[r] == '.')) ++r;
            if (r == le || !std::isalpha(static_cast<unsigned char>(text_[r]))) return true;
        }
        if (next == '?' || next == '_') return true;
        std::size_t s = skip_blanks(q, le);
        if (s < le && (text_[s] == '-' || text_[s] == '+')) ++s;
        bool digits = false;
        for (; s < le && digit(text_[s]); ++s) digits = true;
        if (s < le && text_[s] == '.')
            for (++s; s < le && digit(text_[s]); ++s) digits = true;
        if (digits && s < le && text_[s] == '.') return true;
        std::size_t run = q;
        while (run < le && std::isalpha(static_cast<unsigned char>(text_[run]))) ++run;
        return run - p >= 3;
    }

    // 00018 as the first item of a block: a program number whose O was written as the digit 0
    // (grammar/block_def.hpp, S0112): 0 and three to five digits, then no point, digit or letter.
    bool zero_for_o(std::size_t p, std::size_t le, Block& b) const {
        if (text_[p] != '0') return false;
        std::size_t s = p + 1;
        while (s < le && digit(text_[s])) ++s;
        const std::size_t digits = s - p - 1;
        if (digits < 3 || digits > 5) return false;
        if (s < le && (text_[s] == '.' || std::isalpha(static_cast<unsigned char>(text_[s])))) return false;
        std::int64_t n = 0;
        for (std::size_t d = p + 1; d < s; ++d) n = n * 10 + (text_[d] - '0');
        b.number = n;
        return true;
    }

    // The value of an O word as ast::integer_value reads it: blanks, a sign, digits, a point and
    // decimals; an integer or nothing.
    void read_number(std::size_t p, std::size_t le, Block& b) const {
        p = skip_blanks(p, le);
        bool negative = false;
        if (p < le && (text_[p] == '-' || text_[p] == '+')) negative = text_[p++] == '-';
        double value = 0;
        bool digits = false;
        for (; p < le && digit(text_[p]); ++p, digits = true) value = value * 10 + (text_[p] - '0');
        const bool comma = rules_.decimal_comma && digits && p + 1 < le && text_[p] == ',' && digit(text_[p + 1]);
        if (p < le && (text_[p] == '.' || comma)) {
            for (++p; p < le && digit(text_[p]); ++p, digits = true)
                if (text_[p] != '0') return;   // O60.5: a program without number
        }
        if (!digits || value > 9.0e15) return;
        b.number = static_cast<std::int64_t>(negative ? -value : value);
    }
};

// ast::ProgramSplitter, fed with byte offsets instead of block indices.
class Splitter {
public:
    explicit Splitter(std::vector<ScannedProgram>& out) : out_(out) {}

    void feed(const Block& b, std::size_t begin) {
        switch (b.kind) {
            case Kind::program_start: start(b, begin); break;
            case Kind::percent:
                close(begin);
                if (b.has_o) start(b, begin);
                break;
            case Kind::code:
                open_here(begin);
                has_code_ = true;
                want_comment_ = false;
                break;
            case Kind::blank:
            case Kind::comment_only:
                open_here(begin);
                if (want_comment_ && current_.comment.empty() && !b.comment.empty()) current_.comment = b.comment;
                break;
        }
    }
    void close(std::size_t end) {
        if (open_ && (has_code_ || number_)) {
            if (number_) {
                current_.number = *number_;
                current_.program_index = count_;
                current_.end = static_cast<std::uint32_t>(end);
                out_.push_back(std::move(current_));
            }
            ++count_;
        }
        open_ = false;
        has_code_ = false;
        number_.reset();
        want_comment_ = false;
    }

private:
    void start(const Block& b, std::size_t begin) {
        close(begin);
        current_ = ScannedProgram{};
        current_.begin = static_cast<std::uint32_t>(begin);
        current_.comment = std::string(b.comment);
        number_ = b.number;
        open_ = true;
        has_code_ = true;
        want_comment_ = true;
    }
    void open_here(std::size_t begin) {
        if (open_) return;
        current_ = ScannedProgram{};
        current_.begin = static_cast<std::uint32_t>(begin);
        number_.reset();
        open_ = true;
    }

    std::vector<ScannedProgram>& out_;
    ScannedProgram current_;
    std::optional<std::int64_t> number_;
    std::uint32_t count_ = 0;
    bool open_ = false;
    bool has_code_ = false;
    bool want_comment_ = false;
};

}  // namespace

ScanRules ScanRules::of(const dialects::LexicalRules& lexical) {
    ScanRules r;
    r.semicolon_ends_block = lexical.semicolon == dialects::SemicolonRole::end_of_block;
    r.paren_comments = lexical.paren_comments;
    r.line_comments = lexical.line_comments;
    r.decimal_comma = lexical.decimal_comma_lenient;
    r.macro_b = lexical.macro_b;
    return r;
}

std::vector<ScannedProgram> scan_programs(std::string_view text, const ScanRules& rules) {
    std::vector<ScannedProgram> out;
    Splitter splitter(out);
    const BlockReader reader(text, rules);
    const bool bom = text.starts_with("\xEF\xBB\xBF");
    bool program_seen = false;   // code since the opening '%' (grammar::ParseState)
    std::size_t pos = 0;
    // Lines end where the grammar ends them: "\n", "\r\n" or a lone "\r" (ast/source.hpp).
    ast::LineBreaks breaks(text);
    while (pos < text.size()) {
        const ast::LineBreaks::Line line = breaks.line_from(pos);
        const std::size_t le = line.end;
        const std::size_t next = line.next;
        std::size_t p = pos;
        Kind last = Kind::blank;
        while (true) {
            const std::size_t begin = p;
            const Block b = begin == 0 && bom ? reader.read(3, le, true) : reader.read(p, le);
            splitter.feed(b, begin);
            last = b.kind;
            p = b.end;
            std::size_t q = p;
            while (q < le && blank(text[q])) ++q;
            if (q >= le) break;   // the rest of the line is blank: it belongs to this block
        }
        pos = next;
        if (last == Kind::percent) {
            if (program_seen) {
                splitter.close(pos);   // the tail after the closing '%' is not read
                return out;
            }
            program_seen = false;
        } else if (last == Kind::code || last == Kind::program_start) {
            program_seen = true;
        }
    }
    splitter.close(text.size());
    return out;
}

}  // namespace kerf::project
