// Source positions: byte ranges into one file's text and the line index that turns them into
// line/column in UTF-8 bytes or UTF-16 code units (what LSP clients count).
#pragma once

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

class LineIndex {
public:
    explicit LineIndex(std::string_view text);
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
};

}  // namespace kerf::ast
