#include <catch2/catch.hpp>

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
