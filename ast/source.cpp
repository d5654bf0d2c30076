#include "ast/source.hpp"

#include <algorithm>
#include <cstring>

namespace kerf::ast {

namespace {

bool all_ascii(std::string_view text) {
    std::uint64_t high = 0;
    std::size_t i = 0;
    for (; i + 8 <= text.size(); i += 8) {
        std::uint64_t word;
        std::memcpy(&word, text.data() + i, 8);
        high |= word;
    }
    for (; i < text.size(); ++i) high |= static_cast<unsigned char>(text[i]);
    return (high & 0x8080808080808080ull) == 0;
}

}  // namespace

LineBreaks::Line LineBreaks::line_from(std::size_t pos) {
    const std::size_t size = text_.size();
    if (pos >= size) return {size, size};
    if (!searched_ || (lf_ != std::string_view::npos && lf_ < pos)) {
        lf_ = text_.find('\n', pos);
        searched_ = true;
    }
    const std::size_t limit = lf_ == std::string_view::npos ? size : lf_;
    // The first '\r' before the '\n' ends the line unless it is the '\r' of "\r\n".
    if (const void* cr = std::memchr(text_.data() + pos, '\r', limit - pos)) {
        const std::size_t at = static_cast<std::size_t>(static_cast<const char*>(cr) - text_.data());
        if (at + 1 != lf_ && at + 1 < size) return {at, at + 1};
        if (at + 1 == size) return {at, size};
    }
    if (lf_ == std::string_view::npos) return {size, size};
    return {lf_, lf_ + 1};
}

std::size_t last_line_end_before(std::string_view text, std::size_t limit) {
    limit = std::min(limit, text.size());
    for (std::size_t i = limit; i > 0; --i) {
        const char c = text[i - 1];
        if (c == '\n') return i;
        // A lone '\r' ends a line; the '\r' of a "\r\n" whose '\n' lies at `limit` or beyond does not.
        if (c == '\r' && (i == text.size() || text[i] != '\n')) return i;
    }
    return std::string_view::npos;
}

std::size_t count_line_breaks(std::string_view text) {
    std::size_t n = 0;
    LineBreaks breaks(text);
    for (std::size_t pos = 0; pos < text.size();) {
        const LineBreaks::Line line = breaks.line_from(pos);
        if (line.end < text.size()) ++n;
        pos = line.next;
    }
    return n;
}

LineIndex::LineIndex(std::string_view text) : text_(text) {
    starts_.push_back(0);
    LineBreaks breaks(text);
    for (std::size_t pos = 0; pos < text.size();) {
        const LineBreaks::Line line = breaks.line_from(pos);
        if (line.end >= text.size()) break;
        pos = line.next;
        starts_.push_back(static_cast<std::uint32_t>(pos));
    }
    // Most NC lines are ASCII; for them a UTF-16 column needs no walk along the line. Most files
    // are ASCII throughout: one pass eight bytes at a time says so.
    ascii_.assign(starts_.size(), true);
    if (all_ascii(text)) return;
    for (std::size_t line = 0; line < starts_.size(); ++line) ascii_[line] = line_is_ascii(line);
}

bool LineIndex::line_is_ascii(std::size_t line) const {
    const std::size_t end = line + 1 < starts_.size() ? starts_[line + 1] : text_.size();
    return all_ascii(text_.substr(starts_[line], end - starts_[line]));
}

void LineIndex::edit(std::string_view text, std::uint32_t begin, std::uint32_t old_end, std::uint32_t new_end) {
    // A line starts at p when text[p - 1] ends a line ('\n', or a '\r' that text[p] does not
    // follow with '\n'): a start before `begin` reads only bytes before it and stays; one past
    // new_end reads only moved bytes, so it is an old start moved. The lines between are read again
    // from the start of the line that holds begin - 1.
    const std::int64_t delta = static_cast<std::int64_t>(new_end) - static_cast<std::int64_t>(old_end);
    const std::uint32_t first = begin == 0 ? 0 : line_of(begin - 1);
    std::vector<std::uint32_t> starts(starts_.begin(), starts_.begin() + first + 1);
    text_ = text;
    LineBreaks breaks(text);
    std::uint32_t resumed = 0;   // the first old start (moved) past the edited lines, 0 when none
    for (std::size_t pos = starts.back(); pos < text.size();) {
        const LineBreaks::Line line = breaks.line_from(pos);
        if (line.end >= text.size()) break;
        pos = line.next;
        starts.push_back(static_cast<std::uint32_t>(pos));
        if (pos > new_end) {
            resumed = static_cast<std::uint32_t>(pos);
            break;
        }
    }
    const std::size_t edited_end = starts.size();   // the lines [first, edited_end) were read again
    if (resumed) {
        const auto old_at = std::upper_bound(starts_.begin(), starts_.end(), static_cast<std::uint32_t>(resumed - delta));
        for (auto it = old_at; it != starts_.end(); ++it) starts.push_back(static_cast<std::uint32_t>(*it + delta));
    }
    // The flags: those of the lines before, read again for the edited lines, moved for the rest.
    std::vector<bool> ascii(ascii_.begin(), ascii_.begin() + first);
    const std::size_t moved_from = ascii_.size() - (starts.size() - edited_end);
    starts_ = std::move(starts);
    for (std::size_t line = first; line < edited_end; ++line) ascii.push_back(line_is_ascii(line));
    ascii.insert(ascii.end(), ascii_.begin() + static_cast<std::ptrdiff_t>(moved_from), ascii_.end());
    ascii_ = std::move(ascii);
}

std::uint32_t LineIndex::line_of(std::uint32_t offset) const {
    const auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
    return static_cast<std::uint32_t>(it - starts_.begin() - 1);
}

std::uint32_t LineIndex::line_near(std::uint32_t offset, std::uint32_t hint) const {
    const std::uint32_t count = line_count();
    for (std::uint32_t line = hint; line < count && line < hint + 4; ++line) {
        if (offset < starts_[line]) break;
        if (line + 1 == count || offset < starts_[line + 1]) return line;
    }
    return line_of(std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text_.size())));
}

Position LineIndex::utf8(std::uint32_t offset) const {
    offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text_.size()));
    const std::uint32_t line = line_of(offset);
    return {line, offset - starts_[line]};
}

namespace {
// Length in bytes of the UTF-8 sequence that starts with `lead`; invalid leads count as one byte
// (and one UTF-16 unit, the replacement character a client shows).
int utf8_length(unsigned char lead) {
    if (lead < 0x80) return 1;
    if ((lead >> 5) == 0x6) return 2;
    if ((lead >> 4) == 0xE) return 3;
    if ((lead >> 3) == 0x1E) return 4;
    return 1;
}
}  // namespace

Position LineIndex::utf16(std::uint32_t offset) const {
    offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text_.size()));
    const std::uint32_t line = line_of(offset);
    if (ascii_[line]) return {line, offset - starts_[line]};
    std::uint32_t units = 0;
    for (std::uint32_t i = starts_[line]; i < offset;) {
        const int n = utf8_length(static_cast<unsigned char>(text_[i]));
        units += n == 4 ? 2 : 1;
        i += static_cast<std::uint32_t>(n);
    }
    return {line, units};
}

std::uint32_t LineIndex::offset_of_utf16(Position p) const {
    if (p.line >= starts_.size()) return static_cast<std::uint32_t>(text_.size());
    const std::uint32_t line_end =
        p.line + 1 < starts_.size() ? starts_[p.line + 1] : static_cast<std::uint32_t>(text_.size());
    std::uint32_t i = starts_[p.line];
    if (ascii_[p.line]) return std::min(i + p.column, line_end);
    std::uint32_t units = 0;
    while (i < line_end && units < p.column) {
        const int n = utf8_length(static_cast<unsigned char>(text_[i]));
        units += n == 4 ? 2 : 1;
        i += static_cast<std::uint32_t>(n);
    }
    return std::min(i, line_end);
}

}  // namespace kerf::ast
