#include "project/recognize.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>

#include "ast/source.hpp"

namespace kerf::project {

namespace {

// ASCII classes without the C locale's function calls (the recognition reads every byte of a head).
bool is_alpha(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

constexpr std::size_t kMaxLines = 200;
constexpr std::size_t kEnoughBlocks = 32;

struct Magic {
    std::string_view bytes;
    std::string_view what;
};

// File formats a program folder holds beside the programs (pictures, documents, archives, builds).
// PDF starts with '%', as many programs do: its magic is checked before anything else.
constexpr std::array<Magic, 14> kMagic = {{
    {"\x89PNG", "PNG image"},
    {"\xFF\xD8\xFF", "JPEG image"},
    {"GIF87a", "GIF image"},
    {"GIF89a", "GIF image"},
    {"%PDF-", "PDF document"},
    {"PK\x03\x04", "ZIP archive (or an Office document)"},
    {"\x1F\x8B", "gzip archive"},
    {"\x7F" "ELF", "ELF executable"},
    {"MZ", "Windows executable"},
    {"\xD0\xCF\x11\xE0", "Office document"},
    {"Rar!", "RAR archive"},
    {"7z\xBC\xAF", "7-Zip archive"},
    {"SQLite format 3", "SQLite database"},
    {"{\\rtf", "RTF document"},
}};

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string_view extension_of(std::string_view name) {
    const std::size_t slash = name.find_last_of("/\\");
    if (slash != std::string_view::npos) name.remove_prefix(slash + 1);
    const std::size_t dot = name.rfind('.');
    return dot == std::string_view::npos || dot == 0 ? std::string_view{} : name.substr(dot);
}

// Text of a UTF-16 or UTF-32 file with a BOM, narrowed to one byte per character (enough to read
// the words; the reader decodes it properly). nullopt for anything else.
std::optional<std::string> narrow_wide_text(std::string_view head) {
    std::size_t unit = 0, low = 0;
    if (head.starts_with(std::string_view("\xFF\xFE\x00\x00", 4))) unit = 4, low = 0;
    else if (head.starts_with(std::string_view("\x00\x00\xFE\xFF", 4))) unit = 4, low = 3;
    else if (head.starts_with("\xFF\xFE")) unit = 2, low = 0;
    else if (head.starts_with("\xFE\xFF")) unit = 2, low = 1;
    if (unit == 0) return std::nullopt;
    std::string out;
    for (std::size_t i = unit; i + unit <= head.size(); i += unit) {
        bool ascii = true;
        for (std::size_t b = 0; b < unit; ++b)
            if (b != low && head[i + b] != 0) ascii = false;
        out.push_back(ascii ? head[i + low] : '?');
    }
    return out;
}

bool allowed_control(unsigned char c) {
    // Tab, line feed, vertical tab, form feed, carriage return; DC1–DC4 (tape and DNC control);
    // the DOS end-of-file byte after the last block.
    return c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r' || (c >= 0x11 && c <= 0x14) || c == 0x1A;
}

std::optional<std::string> binary_reason(std::string_view head) {
    for (const Magic& m : kMagic)
        if (head.starts_with(m.bytes)) return std::string(m.what);
    if (const std::size_t nul = head.find('\0'); nul != std::string_view::npos)
        return fmt::format("a NUL byte at offset {}", nul);
    std::size_t control = 0;
    for (const char ch : head) {
        const auto c = static_cast<unsigned char>(ch);
        if ((c < 0x20 && !allowed_control(c)) || c == 0x7F) ++control;
    }
    if (control * 50 > head.size()) return fmt::format("{} control bytes in the first {}", control, head.size());
    return std::nullopt;
}

// Macro B and FANUC words of two letters or more that an NC block may hold (dialects.md §3.7).
constexpr std::array<std::string_view, 44> kKeywords = {
    "IF",  "THEN", "GOTO", "WHILE", "DO",   "END",   "ELSE",  "ENDIF", "EQ",    "NE",    "GT",
    "LT",  "GE",   "LE",   "AND",   "OR",   "XOR",   "MOD",   "SIN",   "COS",   "TAN",   "ASIN",
    "ACOS", "ATAN", "ATN", "SQRT",  "SQR",  "ABS",   "BIN",   "BCD",   "ROUND", "RND",   "FIX",
    "FUP", "LN",   "EXP",  "POW",   "ADP",  "PRM",   "DPRNT", "BPRNT", "POPEN", "PCLOS", "SETVN"};

bool keyword(std::string_view run) { return std::find(kKeywords.begin(), kKeywords.end(), run) != kKeywords.end(); }

// The line without its comments, upper case, into `out`: (...) up to ')' or the end, and //, /*,
// ::, ; to the end (';' ends the block in FANUC; what follows on the line is another block or a
// comment).
void strip_comments(std::string_view line, std::string& out) {
    out.clear();
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        const char next = i + 1 < line.size() ? line[i + 1] : '\0';
        if (c == '(') {
            const std::size_t close = line.find(')', i);
            if (close == std::string_view::npos) break;
            i = close;
            out.push_back(' ');
            continue;
        }
        if (c == ';' || (c == '/' && (next == '/' || next == '*')) || (c == ':' && next == ':')) break;
        out.push_back(upper(c));
    }
}

enum class LineKind { blank, nc, prose, other };

bool nc_char(char c) {
    return is_alpha(c) || is_digit(c) || c == ' ' || c == '\t' || c == '\r' || c == '.' || c == '-' ||
           c == '+' || c == '#' || c == '[' || c == ']' || c == '=' || c == '*' || c == '/' || c == ',' || c == ':' ||
           c == '<' || c == '>' || c == '%';
}

bool markdown(std::string_view line) {
    while (!line.empty() && line.front() == ' ') line.remove_prefix(1);
    return line.starts_with("| ") || line.starts_with("|-") || line.starts_with("# ") || line.starts_with("## ") ||
           line.starts_with("- ") || line.starts_with("* ") || line.starts_with("> ") || line.starts_with("```");
}

// `line` is a buffer reused from line to line (no allocation per line).
LineKind classify(std::string_view raw, std::string& line) {
    if (markdown(raw)) return LineKind::prose;
    strip_comments(raw, line);
    bool foreign = false, address = false, statement = false, odd = false;
    // The ISO program number :1000 (dialects.md §2) has no letter.
    const std::size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line[first] == ':' && first + 1 < line.size() &&
        is_digit(line[first + 1]))
        statement = true;
    int words = 0;
    for (std::size_t i = 0; i < line.size();) {
        const char c = line[i];
        if (!nc_char(c)) foreign = true;
        if (c == '#' && i + 1 < line.size() && is_digit(line[i + 1])) {
            std::size_t j = i + 1;
            while (j < line.size() && is_digit(line[j])) ++j;
            while (j < line.size() && line[j] == ' ') ++j;
            if (j < line.size() && (line[j] == '=' || (line[j] == ':' && j + 1 < line.size() && line[j + 1] == '=')))
                statement = true;
            i = j;
            continue;
        }
        if (!is_alpha(c)) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < line.size() && is_alpha(line[j])) ++j;
        const std::string_view run(line.data() + i, j - i);
        if (run.size() == 1) {
            std::size_t k = j;
            while (k < line.size() && line[k] == ' ') ++k;
            if (k < line.size() && (is_digit(line[k]) || line[k] == '.' || line[k] == '-' ||
                                    line[k] == '+' || line[k] == '#' || line[k] == '['))
                address = true;
        } else if (keyword(run)) {
            statement = statement || run == "GOTO" || run == "IF" || run == "WHILE" || run == "END" || run == "DPRNT";
        } else if (run.size() >= 3) {
            ++words;
        } else {
            odd = true;
        }
        i = j;
    }
    if (words >= 2) return LineKind::prose;
    if (!foreign && !odd && words == 0 && (address || statement)) return LineKind::nc;
    bool blank = std::all_of(line.begin(), line.end(), [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '%'; });
    return blank ? LineKind::blank : LineKind::other;
}

Recognition by_content(std::string_view text) {
    // Whole lines only: a head cut inside a line would judge half a word.
    if (text.size() >= kRecognitionHead)
        if (const std::size_t cut = ast::last_line_end_before(text, text.size()); cut != std::string_view::npos)
            text = text.substr(0, cut);
    std::size_t nc = 0, prose = 0, lines = 0;
    std::string buffer;
    // Lines as the grammar reads them ("\n", "\r\n", a lone "\r": a CR-only program is recognised).
    ast::LineBreaks breaks(text);
    std::size_t pos = 0;
    // Stop early on a plain program: kEnoughBlocks NC blocks and no prose decide it.
    while (pos < text.size() && lines < kMaxLines && !(nc >= kEnoughBlocks && prose == 0)) {
        const ast::LineBreaks::Line l = breaks.line_from(pos);
        const std::string_view line = text.substr(pos, l.end - pos);
        pos = l.next;
        switch (classify(line, buffer)) {
            case LineKind::nc: ++nc, ++lines; break;
            case LineKind::prose: ++prose, ++lines; break;
            case LineKind::other: ++lines; break;
            case LineKind::blank: break;
        }
    }
    if (nc == 0) return {false, fmt::format("not a program: no NC block in the first {} lines", lines)};
    if (prose > nc) return {false, fmt::format("not a program: {} lines of prose against {} NC blocks", prose, nc)};
    return {true, fmt::format("content: {} NC blocks in the first {} lines", nc, lines)};   // at least; see kEnoughBlocks
}

}  // namespace

Recognition recognize_program(std::string_view name, std::string_view head) {
    if (head.empty()) return {false, "empty file"};
    std::optional<std::string> narrowed = narrow_wide_text(head);
    const std::string_view text = narrowed ? std::string_view(*narrowed) : head;
    if (!narrowed)
        if (const std::optional<std::string> binary = binary_reason(head)) return {false, "binary: " + *binary};
    const std::string ext = lower(extension_of(name));
    if (!ext.empty() && std::find(std::begin(kProgramExtensions), std::end(kProgramExtensions), ext) != std::end(kProgramExtensions))
        return {true, "extension " + ext};
    return by_content(text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text);
}

}  // namespace kerf::project
