// Program text shown to a person (issue 17): what a file holds must not reach a terminal raw, and
// a message must not quote a megabyte.
// * `printable`: control bytes (C0 but TAB, DEL, C1) and bytes that are not UTF-8 become visible
//   escapes (\x1b, \u009b), so a file cannot move the cursor, change colours or hide text.
// * `excerpt`: a source line cut to a window around a column range, escaped, with the caret
//   underline that matches what is shown.
// * `shorten`: quoted text cut to a length, on a character boundary.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace kerf::ast {

// `keep_newlines`: LF (and the CR of CRLF) stay, for text of several lines.
std::string printable(std::string_view text, bool keep_newlines = false);

// `text` with every byte that does not belong to a valid UTF-8 sequence replaced by U+FFFD (JSON
// and SARIF must be UTF-8; a program's comment in CP1251 is not).
std::string valid_utf8(std::string_view text);
// True when every byte of `text` belongs to a valid UTF-8 sequence (valid_utf8 would not change it).
bool is_valid_utf8(std::string_view text);

// At most `max_chars` characters of `text`, cut on a UTF-8 boundary, "..." added when cut.
std::string shorten(std::string_view text, std::size_t max_chars);

struct Excerpt {
    std::string text;    // the shown part of the line, escaped; "..." where it was cut
    std::string caret;   // blanks (tabs where the line has tabs) then '^' under [begin, end)
};

// The line (without its break) around the byte columns [begin, end) (0-based; `end` past the line
// or not after `begin`: one caret at `begin`, or the rest of the line when `to_line_end`): at most
// about `width` characters, the range's start kept in view.
Excerpt excerpt(std::string_view line, std::uint32_t begin, std::uint32_t end, bool to_line_end, std::size_t width = 100);

}  // namespace kerf::ast
