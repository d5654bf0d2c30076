#include "ast/display.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace kerf::ast {

namespace {

// The length of the valid UTF-8 sequence at `at`, or 0 when the byte there does not start one.
std::size_t utf8_sequence(std::string_view s, std::size_t at) {
    const unsigned char lead = static_cast<unsigned char>(s[at]);
    std::size_t n = 0;
    if (lead >= 0xC2 && lead <= 0xDF) n = 2;
    else if (lead >= 0xE0 && lead <= 0xEF) n = 3;
    else if (lead >= 0xF0 && lead <= 0xF4) n = 4;
    if (n == 0 || at + n > s.size()) return 0;
    for (std::size_t k = 1; k < n; ++k)
        if ((static_cast<unsigned char>(s[at + k]) & 0xC0) != 0x80) return 0;
    // Overlong and surrogate forms are not characters either.
    const unsigned char second = static_cast<unsigned char>(s[at + 1]);
    if ((lead == 0xE0 && second < 0xA0) || (lead == 0xED && second > 0x9F) || (lead == 0xF0 && second < 0x90) ||
        (lead == 0xF4 && second > 0x8F))
        return 0;
    return n;
}

// One character of `s` at `at`, as shown: appended to `out`; returns the bytes it took.
std::size_t append_shown(std::string& out, std::string_view s, std::size_t at, bool keep_newlines) {
    const unsigned char c = static_cast<unsigned char>(s[at]);
    if (c == '\t' || (keep_newlines && (c == '\n' || (c == '\r' && at + 1 < s.size() && s[at + 1] == '\n')))) {
        out += static_cast<char>(c);
        return 1;
    }
    if (c < 0x20 || c == 0x7F) {
        fmt::format_to(std::back_inserter(out), "\\x{:02x}", c);
        return 1;
    }
    if (c < 0x80) {
        out += static_cast<char>(c);
        return 1;
    }
    const std::size_t n = utf8_sequence(s, at);
    if (n == 0) {
        fmt::format_to(std::back_inserter(out), "\\x{:02x}", c);
        return 1;
    }
    if (n == 2 && c == 0xC2 && static_cast<unsigned char>(s[at + 1]) < 0xA0) {
        // U+0080..U+009F: the C1 controls (U+009B is CSI on a terminal).
        fmt::format_to(std::back_inserter(out), "\\u{:04x}", static_cast<unsigned char>(s[at + 1]));
        return 2;
    }
    out.append(s.substr(at, n));
    return n;
}

}  // namespace

std::string printable(std::string_view text, bool keep_newlines) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t at = 0; at < text.size();) at += append_shown(out, text, at, keep_newlines);
    return out;
}

bool is_valid_utf8(std::string_view text) {
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t n = static_cast<unsigned char>(text[at]) < 0x80 ? 1 : utf8_sequence(text, at);
        if (n == 0) return false;
        at += n;
    }
    return true;
}

std::string valid_utf8(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t at = 0; at < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[at]);
        const std::size_t n = c < 0x80 ? 1 : utf8_sequence(text, at);
        if (n == 0) {
            out += "\xEF\xBF\xBD";
            ++at;
            continue;
        }
        out.append(text.substr(at, n));
        at += n;
    }
    return out;
}

std::string shorten(std::string_view text, std::size_t max_chars) {
    std::size_t cut = 0;
    for (std::size_t chars = 0; cut < text.size() && chars < max_chars; ++chars) {
        ++cut;
        while (cut < text.size() && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) ++cut;
    }
    std::string out(text.substr(0, cut));
    if (cut < text.size()) out += "...";
    return out;
}

Excerpt excerpt(std::string_view line, std::uint32_t begin, std::uint32_t end, bool to_line_end, std::size_t width) {
    begin = std::min<std::uint32_t>(begin, static_cast<std::uint32_t>(line.size()));
    if (to_line_end) end = static_cast<std::uint32_t>(std::max<std::size_t>(line.size(), begin + 1));
    if (end <= begin) end = begin + 1;
    // The window: up to a third of it before the range, the rest after; whole characters.
    std::size_t from = begin > width / 3 ? begin - width / 3 : 0;
    while (from > 0 && (static_cast<unsigned char>(line[from]) & 0xC0) == 0x80) --from;
    const std::size_t to = std::min(line.size(), from + width);
    Excerpt e;
    std::size_t at = from;
    if (from > 0) {
        e.text = "...";
        e.caret = "   ";
    }
    std::size_t carets = 0;
    while (at < to) {
        const std::size_t shown_before = e.text.size();
        const bool tab = line[at] == '\t';
        const std::size_t n = append_shown(e.text, line, at, false);
        // Display width: one column per character shown (a multi-byte character is one).
        std::size_t columns = 0;
        for (std::size_t k = shown_before; k < e.text.size(); ++k)
            columns += (static_cast<unsigned char>(e.text[k]) & 0xC0) != 0x80;
        if (at < begin) e.caret += tab ? std::string("\t") : std::string(columns, ' ');
        else if (at < end) carets += tab ? 1 : columns;
        at += n;
    }
    if (to < line.size()) e.text += "...";
    e.caret += std::string(std::max<std::size_t>(carets, 1), '^');
    return e;
}

}  // namespace kerf::ast
