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
