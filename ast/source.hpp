// Source positions: byte ranges into one file's text and the line index that turns them into
// line/column in UTF-8 bytes or UTF-16 code units (what LSP clients count).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace kerf::ast {

// [begin, end) in bytes from the start of the file.
struct Range {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    std::uint32_t size() const { return end - begin; }
    bool contains(std::uint32_t offset) const { return offset >= begin && offset < end; }
    friend bool operator==(Range, Range) = default;
};

// 0-based line; column in the unit asked for.
struct Position {
    std::uint32_t line = 0;
    std::uint32_t column = 0;
};

// Line breaks are "\n", "\r\n" and a lone "\r" (old Mac editors and some DNC senders write CR
// only). The grammar, the line index, the streamed reader, the formatter and the input decoder all
// cut lines here, so every command sees the same lines (issue 17).
//
// The scanner walks the lines of a text front to back in linear total time: a '\n' search that
// found nothing is not repeated, so a file without any '\n' costs one pass, not one per line.
class LineBreaks {
public:
    struct Line {
        std::size_t end;    // where the line's break begins ('\n' or the lone '\r'); text.size() if none
        std::size_t next;   // where the next line starts (after the break); text.size() at the end
    };
    explicit LineBreaks(std::string_view text) : text_(text) {}
    // The line that starts at `pos`; calls must come with non-decreasing `pos`.
    Line line_from(std::size_t pos);

private:
    std::string_view text_;
    std::size_t lf_ = 0;        // the first '\n' at or after the last search, or npos
    bool searched_ = false;
};

// The offset just after the last line break that lies wholly inside [0, limit) of `text` (a "\r\n"
// split by `limit` does not count), or npos when there is none.
std::size_t last_line_end_before(std::string_view text, std::size_t limit);

// The number of line breaks in `text`.
std::size_t count_line_breaks(std::string_view text);

class LineIndex {
public:
    explicit LineIndex(std::string_view text);
    // The index of `text`, an edit of the indexed text whose bytes [begin, old_end) became
    // [begin, new_end): only the edited lines are read again, the lines after them move (the
    // language server's edits of a million-line document).
    void edit(std::string_view text, std::uint32_t begin, std::uint32_t old_end, std::uint32_t new_end);
    Position utf8(std::uint32_t offset) const;     // column in bytes
    Position utf16(std::uint32_t offset) const;    // column in UTF-16 code units
    std::uint32_t offset_of_utf16(Position p) const;
    std::uint32_t line_count() const { return static_cast<std::uint32_t>(starts_.size()); }
    std::uint32_t line_start(std::uint32_t line) const { return starts_[line]; }
    // The 0-based line of `offset`, trying `hint` and the lines just after it first: O(1) for a
    // reader that moves forward through the text (the interpreter), a binary search otherwise.
    std::uint32_t line_near(std::uint32_t offset, std::uint32_t hint) const;

private:
    std::string_view text_;
    std::vector<std::uint32_t> starts_;
    std::vector<bool> ascii_;   // per line: no byte >= 0x80, so UTF-16 columns are byte columns
    std::uint32_t line_of(std::uint32_t offset) const;
    bool line_is_ascii(std::size_t line) const;
};

}  // namespace kerf::ast
