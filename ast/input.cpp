#include "ast/input.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <thread>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "ast/source.hpp"

namespace kerf::ast {

namespace {

// The encoding and binary decisions look at the start of the file: enough to see a pattern,
// little enough to cost nothing.
constexpr std::size_t kHeadBytes = std::size_t{64} << 10;

std::string size_text(std::uint64_t bytes) {
    if (bytes >= (std::uint64_t{1} << 20)) return fmt::format("{:.1f} MiB", static_cast<double>(bytes) / (1 << 20));
    if (bytes >= (std::uint64_t{1} << 10)) return fmt::format("{:.1f} KiB", static_cast<double>(bytes) / (1 << 10));
    return fmt::format("{} bytes", bytes);
}

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

struct Detected {
    Encoding encoding = Encoding::utf8;
    bool bom = false;
    std::size_t bom_size = 0;
};

// Zero bytes by position modulo 4 in whole units of `head`.
struct ZeroPattern {
    std::array<std::size_t, 4> zeros{};
    std::size_t quads = 0;   // how many 4-byte groups were counted
    explicit ZeroPattern(std::string_view head) {
        quads = head.size() / 4;
        for (std::size_t i = 0; i < quads * 4; ++i)
            if (head[i] == '\0') ++zeros[i % 4];
    }
    // At least 70 % of the bytes at the positions in `high` are zero (ASCII text: the high bytes of
    // its units) and at most 10 % of those in `low` (the characters themselves are not NUL).
    bool matches(std::initializer_list<std::size_t> high, std::initializer_list<std::size_t> low) const {
        if (quads < 2) return false;
        std::size_t high_zeros = 0, low_zeros = 0;
        for (const std::size_t h : high) high_zeros += zeros[h];
        for (const std::size_t l : low) low_zeros += zeros[l];
        return high_zeros * 10 >= high.size() * quads * 7 && low_zeros * 10 <= low.size() * quads;
    }
};

Detected detect_encoding(std::string_view head) {
    if (starts_with(head, "\xEF\xBB\xBF")) return {Encoding::utf8, true, 0};   // the grammar keeps a UTF-8 BOM
    if (starts_with(head, std::string_view("\xFF\xFE\0\0", 4))) return {Encoding::utf32le, true, 4};
    if (starts_with(head, std::string_view("\0\0\xFE\xFF", 4))) return {Encoding::utf32be, true, 4};
    if (starts_with(head, "\xFF\xFE")) return {Encoding::utf16le, true, 2};
    if (starts_with(head, "\xFE\xFF")) return {Encoding::utf16be, true, 2};
    // Without a BOM: the zero bytes that ASCII characters have in these encodings.
    const ZeroPattern z(head);
    if (z.matches({1, 2, 3}, {0})) return {Encoding::utf32le, false, 0};
    if (z.matches({0, 1, 2}, {3})) return {Encoding::utf32be, false, 0};
    if (z.matches({1, 3}, {0, 2})) return {Encoding::utf16le, false, 0};
    if (z.matches({0, 2}, {1, 3})) return {Encoding::utf16be, false, 0};
    return {};
}

// Bytes that text does not have: NUL and the C0 controls other than TAB, LF, VT, FF, CR and ESC,
// and DEL. DC1–DC4 (tape reader control) and SUB (a DOS end of file) do appear in NC files,
// a few of them, so the decision is by share, not by presence.
// Written with & and | (no branch) so that a loop over the bytes vectorises: every file of a folder
// walk passes here.
unsigned binary_byte(unsigned char c) {
    return static_cast<unsigned>(c < 0x09) | (static_cast<unsigned>(c > 0x0D) & static_cast<unsigned>(c < 0x20) &
                                              static_cast<unsigned>(c != 0x1B)) |
           static_cast<unsigned>(c == 0x7F);
}

std::optional<InputProblem> binary_problem(std::string_view head) {
    std::size_t nul = 0, control = 0;
    for (const char ch : head) {
        const auto c = static_cast<unsigned char>(ch);
        nul += c == 0;
        control += binary_byte(c);
    }
    // A NUL with at least 1 % control bytes, or 10 % control bytes (compressed data has about 11 %,
    // executables far more NULs): not a program. A stray NUL in a text is read (the grammar
    // reports it where it is).
    const bool binary = (nul > 0 && control * 100 >= head.size()) || control * 10 >= head.size();
    if (!binary || head.empty()) return std::nullopt;
    return InputProblem{InputProblemKind::binary, Severity::error, 0,
                        fmt::format("binary data, not an NC program: {} of the first {} bytes are NUL or control "
                                    "bytes; nothing of it was read",
                                    control, head.size()),
                        "name program files only, or exclude this one in .kerf.toml [check] exclude"};
}

InputProblem too_large(std::uint64_t size, std::uint64_t limit) {
    return {InputProblemKind::too_large, Severity::error, 0,
            fmt::format("the file is {}, over the limit of {} per file; nothing of it was read", size_text(size),
                        size_text(limit)),
            "split the program, or raise the limit with --max-file-bytes or max_file_bytes in .kerf.toml [limits]"};
}

InputProblem line_too_long(std::uint64_t line, std::uint64_t length, std::uint64_t limit) {
    return {InputProblemKind::line_too_long, Severity::error, static_cast<std::uint32_t>(std::min<std::uint64_t>(line, UINT32_MAX)),
            fmt::format("line {} is {} long, over the limit of {} per line; nothing of the file was read", line,
                        size_text(length), size_text(limit)),
            "an NC block is a short line: is this a program? Raise the limit with --max-line-bytes or "
            "max_line_bytes in .kerf.toml [limits]"};
}

InputProblem empty_note(bool has_bytes) {
    return {InputProblemKind::empty, Severity::info, 0,
            has_bytes ? "the file holds only blanks and line breaks: no program" : "the file is empty: no program", ""};
}

bool is_blank_byte(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

// --- transcoding ----------------------------------------------------------------------------------

void append_utf8(std::string& out, char32_t c) {
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
}

constexpr char32_t kReplacement = 0xFFFD;

std::uint32_t unit_at(std::string_view bytes, std::size_t at, std::size_t size, bool little) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < size; ++i) {
        const std::uint32_t b = static_cast<unsigned char>(bytes[at + (little ? size - 1 - i : i)]);
        v = (v << 8) | b;
    }
    return v;
}

// UTF-16/32 → UTF-8; `bad` counts the units that were not characters (each became U+FFFD).
std::string transcode(std::string_view bytes, Encoding e, std::size_t& bad) {
    const bool little = e == Encoding::utf16le || e == Encoding::utf32le;
    const std::size_t unit = e == Encoding::utf16le || e == Encoding::utf16be ? 2 : 4;
    std::string out;
    out.reserve(bytes.size() / unit + 16);
    std::size_t i = 0;
    for (; i + unit <= bytes.size(); i += unit) {
        char32_t c = unit_at(bytes, i, unit, little);
        if (unit == 2 && c >= 0xD800 && c <= 0xDBFF) {
            const bool pair = i + 2 * unit <= bytes.size();
            const char32_t low = pair ? unit_at(bytes, i + unit, unit, little) : 0;
            if (pair && low >= 0xDC00 && low <= 0xDFFF) {
                c = 0x10000 + ((c - 0xD800) << 10) + (low - 0xDC00);
                i += unit;
            } else {
                c = kReplacement;
                ++bad;
            }
        } else if ((c >= 0xD800 && c <= 0xDFFF) || c > 0x10FFFF) {
            c = kReplacement;
            ++bad;
        }
        append_utf8(out, c);
    }
    if (i < bytes.size()) {   // a truncated last unit
        append_utf8(out, kReplacement);
        ++bad;
    }
    return out;
}

// UTF-8 → code points; an invalid byte becomes U+FFFD.
template <class Emit>
void each_code_point(std::string_view text, Emit emit) {
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char lead = static_cast<unsigned char>(text[i]);
        std::size_t n = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
        char32_t c = n == 1 ? lead : n == 2 ? (lead & 0x1F) : n == 3 ? (lead & 0x0F) : (lead & 0x07);
        bool ok = n > 0 && i + n <= text.size();
        for (std::size_t k = 1; ok && k < n; ++k) {
            const unsigned char b = static_cast<unsigned char>(text[i + k]);
            ok = (b & 0xC0) == 0x80;
            c = (c << 6) | (b & 0x3F);
        }
        if (!ok) {
            emit(kReplacement);
            ++i;
            continue;
        }
        emit(c);
        i += n;
    }
}

void append_unit(std::string& out, std::uint32_t v, std::size_t size, bool little) {
    for (std::size_t i = 0; i < size; ++i) {
        const std::size_t shift = 8 * (little ? i : size - 1 - i);
        out += static_cast<char>((v >> shift) & 0xFF);
    }
}

// Lines over the limit and blank-only content of UTF-8 text.
struct TextScan {
    std::uint64_t longest = 0, longest_line = 0;
    bool only_blank = true;
};

// The longest line of `text` (its bytes without the break) and its 1-based number; `lines`: how
// many lines were read.
struct LineScan {
    std::uint64_t longest = 0, longest_line = 0, lines = 0;
};

LineScan scan_lines(std::string_view text) {
    LineScan s;
    LineBreaks breaks(text);
    std::uint64_t line = 1;
    for (std::size_t pos = 0; pos < text.size(); ++line) {
        const LineBreaks::Line l = breaks.line_from(pos);
        // The line's bytes without its break: the '\r' of a "\r\n" is not counted (as the
        // mapped-file scanner counts; fuzz_input finding).
        const std::size_t end = l.end > pos && l.end < text.size() && text[l.end] == '\n' && text[l.end - 1] == '\r' ? l.end - 1 : l.end;
        if (end - pos > s.longest) {
            s.longest = end - pos;
            s.longest_line = line;
        }
        pos = l.next;
    }
    s.lines = line - 1;
    return s;
}

// From this size the lines are scanned in two halves on two threads (the other core is idle
// while a file is read: 40 ms of a 100 MB program, bench/RESULTS.md).
constexpr std::size_t kTwoHalvesFrom = std::size_t{8} << 20;

TextScan scan_text(std::string_view text) {
    LineScan lines;
    // Cut after a line break, so that no line (nor a "\r\n") is split between the halves.
    const std::size_t cut = text.size() >= kTwoHalvesFrom ? last_line_end_before(text, text.size() / 2) : std::string_view::npos;
    if (cut != std::string_view::npos && cut > 0) {
        LineScan second;
        std::thread worker([&] { second = scan_lines(text.substr(cut)); });
        lines = scan_lines(text.substr(0, cut));
        worker.join();
        if (second.longest > lines.longest) {   // the first longest line counts, as in one pass
            lines.longest = second.longest;
            lines.longest_line = lines.lines + second.longest_line;
        }
    } else {
        lines = scan_lines(text);
    }
    TextScan s;
    s.longest = lines.longest;
    s.longest_line = lines.longest_line;
    s.only_blank = std::all_of(text.begin(), text.end(), is_blank_byte);
    return s;
}

void add_text_problems(DecodedInput& out, const TextScan& s, std::size_t bytes, const InputLimits& limits) {
    if (limits.max_line_bytes > 0 && s.longest > limits.max_line_bytes)
        out.problems.push_back(line_too_long(s.longest_line, s.longest, limits.max_line_bytes));
    else if (s.only_blank)
        out.problems.push_back(empty_note(bytes > 0));
}

}  // namespace

const char* to_string(Encoding e) {
    switch (e) {
    case Encoding::utf8: return "UTF-8";
    case Encoding::utf16le: return "UTF-16LE";
    case Encoding::utf16be: return "UTF-16BE";
    case Encoding::utf32le: return "UTF-32LE";
    case Encoding::utf32be: return "UTF-32BE";
    }
    return "?";
}

bool DecodedInput::refused() const {
    return std::any_of(problems.begin(), problems.end(), [](const InputProblem& p) { return p.severity == Severity::error; });
}

std::optional<InputProblem> check_file_size(std::uint64_t size, const InputLimits& limits) {
    if (limits.max_file_bytes == 0 || size <= limits.max_file_bytes) return std::nullopt;
    return too_large(size, limits.max_file_bytes);
}

DecodedInput decode_input(std::string bytes, const InputLimits& limits) {
    DecodedInput out;
    if (auto problem = check_file_size(bytes.size(), limits)) {
        out.problems.push_back(std::move(*problem));
        return out;
    }
    const std::string_view head = std::string_view(bytes).substr(0, kHeadBytes);
    const Detected d = detect_encoding(head);
    out.encoding = d.encoding;
    out.bom = d.bom;
    if (d.encoding == Encoding::utf8) {
        if (auto binary = binary_problem(head)) {
            out.problems.push_back(std::move(*binary));
            return out;
        }
        add_text_problems(out, scan_text(bytes), bytes.size(), limits);
        if (!out.refused()) out.text = std::move(bytes);
        return out;
    }
    std::size_t bad = 0;
    std::string text = transcode(std::string_view(bytes).substr(d.bom_size), d.encoding, bad);
    // Sixteen-bit numbers below 256 look like UTF-16 text by their zeros: what they decode to is not.
    if (auto binary = binary_problem(std::string_view(text).substr(0, kHeadBytes))) {
        out.problems.push_back(std::move(*binary));
        return out;
    }
    out.problems.push_back({InputProblemKind::transcoded, Severity::info, 0,
                            fmt::format("read as {}{}; a rewrite (fmt --write, check --fix) keeps that encoding",
                                        to_string(d.encoding), d.bom ? " with a byte-order mark" : ""),
                            ""});
    if (bad > 0)
        out.problems.push_back({InputProblemKind::bad_encoding, Severity::warning, 0,
                                fmt::format("{} code unit(s) are not {} characters and read as U+FFFD", bad,
                                            to_string(d.encoding)),
                                "save the file again from an editor, in UTF-8 if the machine takes it"});
    add_text_problems(out, scan_text(text), bytes.size() - d.bom_size, limits);
    if (!out.refused()) out.text = std::move(text);
    return out;
}

namespace {

// Calls `at(i)` for every i in [from, text.size()) where text[i] is '\n' or '\r', in order. The
// dry run scans a whole file this way before its first block: one call of memchr per line (two,
// with the search for '\r') was 0.13 s of a 100 MB program on each of two cores
// (bench/RESULTS.md); sixteen bytes compared at a time, a line costs a few instructions.
template <typename At>
void for_each_break_byte(std::string_view text, std::size_t from, At at) {
    const char* data = text.data();
    const std::size_t n = text.size();
    std::size_t i = from;
#if defined(__SSE2__)
    const __m128i lf = _mm_set1_epi8('\n');
    const __m128i cr = _mm_set1_epi8('\r');
    for (; i + 16 <= n; i += 16) {
        const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(data + i));
        auto mask = static_cast<unsigned>(_mm_movemask_epi8(_mm_or_si128(_mm_cmpeq_epi8(v, lf), _mm_cmpeq_epi8(v, cr))));
        while (mask != 0) {
            at(i + static_cast<std::size_t>(__builtin_ctz(mask)));
            mask &= mask - 1;
        }
    }
#endif
    for (; i < n; ++i)
        if (data[i] == '\n' || data[i] == '\r') at(i);
}

}  // namespace

void InputScanner::feed(std::string_view piece) {
    if (head_.size() < kHeadBytes) head_.append(piece.substr(0, kHeadBytes - head_.size()));
    size_ += piece.size();
    std::size_t pos = 0;
    if (pending_cr_ && !piece.empty()) {
        pending_cr_ = false;
        if (piece.front() == '\n') pos = 1;   // the '\n' of a "\r\n" split between two pieces
    }
    const std::size_t n = piece.size();
    const auto line_part = [&](std::size_t end, std::size_t skip_cr) {
        line_length_ += end - pos - skip_cr;
        if (only_blank_) only_blank_ = std::all_of(piece.begin() + static_cast<std::ptrdiff_t>(pos),
                                                   piece.begin() + static_cast<std::ptrdiff_t>(end), is_blank_byte);
    };
    // A line ends at a '\n' or at a '\r' that no '\n' follows (LineBreaks, ast/source.hpp); its
    // bytes are counted without the break, and without the '\r' of a "\r\n" (as decode_input counts).
    for_each_break_byte(piece, pos, [&](std::size_t b) {
        const bool is_cr = piece[b] == '\r';
        if (is_cr && b + 1 < n && piece[b + 1] == '\n') return;   // the "\r" of "\r\n": the '\n' ends the line
        line_part(b, !is_cr && b > pos && piece[b - 1] == '\r' ? 1 : 0);
        if (line_length_ > longest_line_) {
            longest_line_ = line_length_;
            longest_at_ = line_;
        }
        ++line_;
        line_length_ = 0;
        pending_cr_ = is_cr && b + 1 == n;
        pos = b + 1;
    });
    if (pos < n) line_part(n, 0);   // the line goes on in the next piece
}

void InputScanner::append(const InputScanner& later) {
    if (head_.size() < kHeadBytes) head_.append(later.head_.substr(0, kHeadBytes - head_.size()));
    size_ += later.size_;
    const std::uint64_t lines_before = line_ - 1;   // this part ends at a line break: its lines are complete
    if (later.longest_line_ > longest_line_) {       // the first longest line counts, as in one pass
        longest_line_ = later.longest_line_;
        longest_at_ = lines_before + later.longest_at_;
    }
    line_ = lines_before + later.line_;
    line_length_ = later.line_length_;
    pending_cr_ = later.pending_cr_;
    only_blank_ = only_blank_ && later.only_blank_;
}

DecodedInput InputScanner::finish() {
    DecodedInput out;
    if (line_length_ > longest_line_) {
        longest_line_ = line_length_;
        longest_at_ = line_;
    }
    if (auto problem = check_file_size(size_, limits_)) {
        out.problems.push_back(std::move(*problem));
        return out;
    }
    const Detected d = detect_encoding(head_);
    out.encoding = d.encoding;
    out.bom = d.bom;
    if (d.encoding != Encoding::utf8) return out;   // the caller decodes the bytes
    if (auto binary = binary_problem(head_)) {
        out.problems.push_back(std::move(*binary));
        return out;
    }
    TextScan s;
    s.longest = longest_line_;
    s.longest_line = longest_at_;
    s.only_blank = only_blank_;
    add_text_problems(out, s, size_, limits_);
    return out;
}

std::string encode_output(std::string_view text, Encoding encoding, bool bom) {
    if (encoding == Encoding::utf8) return std::string(text);
    const bool little = encoding == Encoding::utf16le || encoding == Encoding::utf32le;
    const std::size_t unit = encoding == Encoding::utf16le || encoding == Encoding::utf16be ? 2 : 4;
    std::string out;
    out.reserve(text.size() * unit + 4);
    if (bom) append_unit(out, 0xFEFF, unit, little);
    each_code_point(text, [&](char32_t c) {
        if (unit == 4 || c < 0x10000) {
            append_unit(out, c, unit, little);
            return;
        }
        const char32_t v = c - 0x10000;
        append_unit(out, 0xD800 + (v >> 10), 2, little);
        append_unit(out, 0xDC00 + (v & 0x3FF), 2, little);
    });
    return out;
}

}  // namespace kerf::ast
