#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "ast/source.hpp"

using kerf::ast::LineIndex;

TEST_CASE("line index: UTF-8 byte columns and UTF-16 code units") {
    // "(Ж𝄞)" : Ж is 2 bytes / 1 UTF-16 unit, 𝄞 is 4 bytes / 2 units.
    const std::string text = "G0\n(\xD0\x96\xF0\x9D\x84\x9E)X1\n";
    const LineIndex lines(text);
    CHECK(lines.line_count() == 3);
    const auto x = text.find('X');
    CHECK(lines.utf8(static_cast<std::uint32_t>(x)).line == 1);
    CHECK(lines.utf8(static_cast<std::uint32_t>(x)).column == 8);
    CHECK(lines.utf16(static_cast<std::uint32_t>(x)).column == 5);
    CHECK(lines.offset_of_utf16({1, 5}) == x);
    CHECK(lines.utf8(0).line == 0);
    CHECK(lines.utf8(static_cast<std::uint32_t>(text.size())).line == 2);
}

TEST_CASE("line index: invalid UTF-8 counts one unit per byte") {
    const std::string text = "(\xff\xfe)X";
    const LineIndex lines(text);
    CHECK(lines.utf16(4).column == 4);
}

TEST_CASE("line index: ASCII lines and lines with multi-byte characters agree with a slow walk") {
    const std::string text = "G0 X1\n(\xD0\x96)Y2\n\nZ3";
    const LineIndex lines(text);
    // Slow reference: count UTF-16 units from the line start.
    for (std::uint32_t off = 0; off <= text.size(); ++off) {
        const auto p8 = lines.utf8(off);
        const auto p16 = lines.utf16(off);
        CHECK(p8.line == p16.line);
        std::uint32_t units = 0;
        for (std::uint32_t i = lines.line_start(p8.line); i < off;) {
            const unsigned char c = static_cast<unsigned char>(text[i]);
            const int n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 1;
            units += n == 4 ? 2 : 1;
            i += static_cast<std::uint32_t>(n);
        }
        if (off < text.size() && (static_cast<unsigned char>(text[off]) & 0xC0) == 0x80) continue;   // inside a character
        CHECK(p16.column == units);
    }
    CHECK(lines.offset_of_utf16({0, 3}) == 3);
    CHECK(lines.offset_of_utf16({0, 99}) == 6);   // clamped to the line end (after '\n')
}

TEST_CASE("line index: an edit moves the lines after it and reads the edited ones again, as a new index would") {
    // Random edits of a text of '\n', '\r', "\r\n" line ends and multi-byte characters, each
    // compared position by position with an index built from the edited text.
    std::mt19937 rng(7);
    const char* pieces[] = {"\n", "\r", "\r\n", "G0 X1", "Ф", "𝄞", "", "ab\rcd\n", "\n\n"};
    std::string text = "O1\r\nG0 X1\rG1 Ф Y2\n\nM30\r\n";
    kerf::ast::LineIndex index(text);
    for (int i = 0; i < 2000; ++i) {
        const auto size = static_cast<std::uint32_t>(text.size());
        const std::uint32_t begin = size ? static_cast<std::uint32_t>(rng() % (size + 1)) : 0;
        const std::uint32_t end = std::min<std::uint32_t>(size, begin + static_cast<std::uint32_t>(rng() % 4));
        const std::string insert = pieces[rng() % std::size(pieces)];
        text.replace(begin, end - begin, insert);
        if (text.size() > 400) text.resize(200);   // keep it short (a cut is a whole new index)
        INFO("edit " << i << " [" << begin << "," << end << ") '" << insert << "'");
        if (text.size() == 200) index = kerf::ast::LineIndex(text);
        else index.edit(text, begin, end, static_cast<std::uint32_t>(begin + insert.size()));
        const kerf::ast::LineIndex fresh(text);
        REQUIRE(index.line_count() == fresh.line_count());
        for (std::uint32_t line = 0; line < fresh.line_count(); ++line) REQUIRE(index.line_start(line) == fresh.line_start(line));
        for (std::uint32_t at = 0; at <= text.size(); ++at) {
            const kerf::ast::Position a = index.utf16(at), b = fresh.utf16(at);
            REQUIRE((a.line == b.line && a.column == b.column));
            REQUIRE(index.offset_of_utf16(fresh.utf16(at)) == fresh.offset_of_utf16(fresh.utf16(at)));
        }
    }
}
