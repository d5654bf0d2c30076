// ast/input.hpp (decoding the bytes of a file) and ast/display.hpp (text shown to people). The
// expected bytes are written by hand from the encodings' definitions (RFC 2781 UTF-16, RFC 3629
// UTF-8).
#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

#include "ast/display.hpp"
#include "ast/input.hpp"
#include "ast/source.hpp"

using namespace kerf::ast;

namespace {

// The lines of `text` as LineBreaks cuts them (without their breaks).
std::vector<std::string> scanner_lines(const std::string& text) {
    LineBreaks breaks(text);
    std::vector<std::string> lines;
    for (std::size_t pos = 0; pos < text.size();) {
        const LineBreaks::Line l = breaks.line_from(pos);
        lines.push_back(text.substr(pos, l.end - pos));
        pos = l.next;
    }
    return lines;
}

bool has(const DecodedInput& d, InputProblemKind kind) {
    for (const InputProblem& p : d.problems)
        if (p.kind == kind) return true;
    return false;
}

}  // namespace

TEST_CASE("input: UTF-8 passes through untouched, BOM and invalid bytes included") {
    const std::string text = "\xEF\xBB\xBFO1000\n(\xFF\xFE caf\xC3\xA9)\nM30\n";
    const DecodedInput d = decode_input(text);
    CHECK(d.text == text);
    CHECK(d.encoding == Encoding::utf8);
    CHECK(d.bom);
    CHECK(d.problems.empty());
    CHECK_FALSE(d.refused());
}

TEST_CASE("input: UTF-16 and UTF-32 with and without BOM are transcoded") {
    // "G0 Ж\n": G=47 0=30 space=20 Ж=U+0416 LF=0A; U+1D11E (𝄞) is the pair D834 DD1E.
    const std::string utf8 = "G0 \xD0\x96\n(\xF0\x9D\x84\x9E)\n";
    const std::string le = std::string("\xFF\xFE" "G\0" "0\0" " \0" "\x16\x04" "\n\0" "(\0" "\x34\xD8\x1E\xDD" ")\0" "\n\0", 22);
    const std::string be_no_bom = std::string("\0G" "\0" "0" "\0 " "\x04\x16" "\0\n" "\0(" "\xD8\x34\xDD\x1E" "\0)" "\0\n", 20);
    const std::string le32_no_bom = std::string("G\0\0\0" "0\0\0\0" " \0\0\0" "\x16\x04\0\0" "\n\0\0\0" "(\0\0\0"
                                                "\x1E\xD1\x01\0" ")\0\0\0" "\n\0\0\0", 36);
    const std::string be32 = std::string("\0\0\xFE\xFF" "\0\0\0G" "\0\0\0" "0" "\0\0\0 " "\0\0\x04\x16" "\0\0\0\n"
                                         "\0\0\0(" "\0\x01\xD1\x1E" "\0\0\0)" "\0\0\0\n", 40);
    for (const auto& [bytes, encoding, bom] :
         {std::tuple{le, Encoding::utf16le, true}, std::tuple{be_no_bom, Encoding::utf16be, false},
          std::tuple{le32_no_bom, Encoding::utf32le, false}, std::tuple{be32, Encoding::utf32be, true}}) {
        INFO(to_string(encoding));
        const DecodedInput d = decode_input(bytes);
        CHECK(d.text == utf8);
        CHECK(d.encoding == encoding);
        CHECK(d.bom == bom);
        CHECK(has(d, InputProblemKind::transcoded));
        CHECK_FALSE(d.refused());
        // And back: the writer's bytes are the input's.
        CHECK(encode_output(d.text, d.encoding, d.bom) == bytes);
    }
}

TEST_CASE("input: an unpaired surrogate reads as U+FFFD with a warning") {
    const std::string bytes("\xFF\xFEG\0\x00\xD8X\0", 8);   // G, a lone high surrogate D800, X
    const DecodedInput d = decode_input(bytes);
    CHECK(d.text == "G\xEF\xBF\xBDX");
    CHECK(has(d, InputProblemKind::bad_encoding));
    CHECK_FALSE(d.refused());
}

TEST_CASE("input: binary data is refused, a stray NUL or a few tape control codes are not") {
    std::string elf("\x7F" "ELF\x02\x01\x01", 7);
    for (int i = 0; i < 500; ++i) elf += std::string("\0\0\x01\x02G", 5);
    const DecodedInput bin = decode_input(elf);
    CHECK(bin.refused());
    CHECK(has(bin, InputProblemKind::binary));
    CHECK(bin.text.empty());
    REQUIRE(bin.problems.size() == 1);
    CHECK(bin.problems[0].message.find("binary data, not an NC program") == 0);
    // A program with DC2 ... DC4 (tape reader on/off) and one NUL: read.
    std::string tape = "\x12%\nO1000\n";
    for (int i = 0; i < 40; ++i) tape += "G01 X10. Y20. F100.\n";
    tape += std::string("(\0)\n%\x14", 6);
    const DecodedInput ok = decode_input(tape);
    CHECK_FALSE(ok.refused());
    CHECK(ok.text == tape);
}

TEST_CASE("input: size limits refuse a file or a line past them, with the limit in the message") {
    InputLimits limits;
    limits.max_file_bytes = 100;
    limits.max_line_bytes = 10;
    const DecodedInput big = decode_input(std::string(101, 'G'), limits);
    REQUIRE(big.refused());
    CHECK(big.problems[0].kind == InputProblemKind::too_large);
    CHECK(big.problems[0].message == "the file is 101 bytes, over the limit of 100 bytes per file; nothing of it was read");
    const DecodedInput line = decode_input("G0\nG1 X1. Y2. Z3.\nM30\n", limits);
    REQUIRE(line.refused());
    CHECK(line.problems[0].kind == InputProblemKind::line_too_long);
    CHECK(line.problems[0].line == 2);
    CHECK(line.problems[0].message.find("line 2 is 14 bytes long, over the limit of 10 bytes per line") == 0);
    CHECK(line.problems[0].hint.find("--max-line-bytes") != std::string::npos);
    CHECK_FALSE(decode_input("G0\nG1 X1.\nM30\n", limits).refused());
    // A line's length is its bytes without the break: the '\r' of "\r\n" is not counted.
    CHECK_FALSE(decode_input("G0\r\nG1 X1. Y2.\r\nM30\r\n", limits).refused());   // 10 bytes and a CR
    const DecodedInput crlf = decode_input("G0\r\nG1 X1. Y2.5\r\nM30\r\n", limits);
    REQUIRE(crlf.refused());
    CHECK(crlf.problems[0].message.find("line 2 is 11 bytes long, over the limit of 10 bytes per line") == 0);
    limits.max_line_bytes = 0;   // no limit
    CHECK_FALSE(decode_input("G0\nG1 X1. Y2. Z3.\nM30\n", limits).refused());
    CHECK(check_file_size(101, {100, 10}).has_value());
    CHECK_FALSE(check_file_size(100, {100, 10}).has_value());
}

TEST_CASE("input: a long text scanned in two halves finds the longest line and its number as one pass does") {
    // From 8 MiB the lines are scanned in two halves on two threads (ast/input.cpp): the number of
    // a line in the second half counts the first half's lines; of two equally long lines the first
    // is reported; a CRLF at the cut is not split.
    const std::string short_line = "G1 X1. Y2.\r\n";   // 10 bytes and a CRLF
    std::string text;
    std::uint64_t lines = 0;
    while (text.size() < (std::size_t{9} << 20)) text += short_line, ++lines;
    const auto refused_at = [](const std::string& t) {
        InputLimits limits;
        limits.max_line_bytes = 12;
        const DecodedInput d = decode_input(t, limits);
        return d.refused() ? d.problems[0].line : 0u;
    };
    CHECK(refused_at(text) == 0);
    // One long line near the end (the second half), one near the start (the first half).
    std::string late = text + "G1 X1. Y2. Z3.\r\n" + short_line;
    CHECK(refused_at(late) == lines + 1);
    std::string early = short_line + "G1 X1. Y2. Z3.\r\n" + text;
    CHECK(refused_at(early) == 2);
    // Two lines of the same length, one in each half: the first one.
    std::string both = short_line + "G1 X1. Y2. Z3.\r\n" + text + "G1 X1. Y2. Z4.\r\n";
    CHECK(refused_at(both) == 2);
    // A longer one in the second half wins over a shorter one in the first.
    std::string longer = short_line + "G1 X1. Y2. Z3.\r\n" + text + "G1 X1. Y2. Z3.5\r\n";
    CHECK(refused_at(longer) == lines + 3);
}

TEST_CASE("input: an empty or blank file gets a note") {
    const DecodedInput empty = decode_input("");
    REQUIRE(empty.problems.size() == 1);
    CHECK(empty.problems[0].kind == InputProblemKind::empty);
    CHECK(empty.problems[0].severity == Severity::info);
    CHECK(empty.problems[0].message == "the file is empty: no program");
    const DecodedInput blank = decode_input(" \r\n\t\n\r");
    REQUIRE(blank.problems.size() == 1);
    CHECK(blank.problems[0].message == "the file holds only blanks and line breaks: no program");
    CHECK_FALSE(blank.refused());
    CHECK(decode_input("%\n").problems.empty());
}

TEST_CASE("input: the scanner over pieces decides as decode_input does") {
    InputLimits limits;
    limits.max_line_bytes = 8;
    // A CRLF split between two pieces is one line break: lines "G0 X1." (6) and "G1" (2).
    for (const std::string& text : {std::string("G0 X1.\r\nG1\n"), std::string("G0 X1. Y2. Z3.\r\nG1\n"), std::string(""),
                                    std::string("\n\n"), std::string("G0\rG1 X1. Y2.\r")}) {
        INFO(text);
        for (std::size_t cut = 0; cut <= text.size(); ++cut) {
            InputScanner scanner(limits);
            scanner.feed(std::string_view(text).substr(0, cut));
            scanner.feed(std::string_view(text).substr(cut));
            const DecodedInput scanned = scanner.finish();
            const DecodedInput decoded = decode_input(text, limits);
            REQUIRE(scanned.problems.size() == decoded.problems.size());
            for (std::size_t i = 0; i < scanned.problems.size(); ++i) {
                CHECK(scanned.problems[i].kind == decoded.problems[i].kind);
                CHECK(scanned.problems[i].line == decoded.problems[i].line);
            }
        }
    }
}

TEST_CASE("input: the scanner finds the longest line as decode_input does, in every mix of breaks and pieces") {
    // Lines long and short (the scanner compares sixteen bytes at a time), CR, LF, CRLF and CR CR LF,
    // cut into two pieces anywhere: the longest line, its number and the blank-file note agree.
    std::mt19937 random(20261128);
    const std::vector<std::string> parts = {"G1 X1.", "G1 X12.345 Y-6.789 Z0.5 F1200.", " ", "\t", "\r", "\n", "\r\n", "\r\r\n",
                                            std::string(40, 'X'), std::string(17, ' ')};
    for (int round = 0; round < 400; ++round) {
        std::string text;
        const std::size_t count = random() % 24;
        for (std::size_t i = 0; i < count; ++i) text += parts[random() % parts.size()];
        InputLimits limits;
        limits.max_line_bytes = 1 + random() % 60;
        const DecodedInput decoded = decode_input(text, limits);
        const std::size_t cut = text.empty() ? 0 : random() % (text.size() + 1);
        InputScanner scanner(limits);
        scanner.feed(std::string_view(text).substr(0, cut));
        scanner.feed(std::string_view(text).substr(cut));
        const DecodedInput scanned = scanner.finish();
        INFO(printable(text) << " cut at " << cut << ", limit " << limits.max_line_bytes);
        REQUIRE(scanned.problems.size() == decoded.problems.size());
        for (std::size_t i = 0; i < scanned.problems.size(); ++i) {
            CHECK(scanned.problems[i].kind == decoded.problems[i].kind);
            CHECK(scanned.problems[i].line == decoded.problems[i].line);
            CHECK(scanned.problems[i].message == decoded.problems[i].message);
        }
    }
}

TEST_CASE("input: two scanners of a text cut at a line end, appended, decide as one") {
    InputLimits limits;
    limits.max_line_bytes = 8;
    // The longest line in the first part, in the second, tied across the cut, blank parts,
    // a lone CR before the cut, no break at the end.
    for (const std::string& text :
         {std::string("G0 X1. Y2. Z3.\r\nG1\nG2\n"), std::string("G1\nG2\r\nG0 X1. Y2. Z3.\nG3"),
          std::string("G0 X1. Y2. Z3.\nG0 X1. Y2. Z4.\n"), std::string(" \n\t\r\n \n"), std::string("\n\nG1 X123456789\n"),
          std::string("G0\rG1 X1. Y2.\rG2\r"), std::string("G0 X1.\nG1 X2. Y3. Z4."),
          std::string("G1\n \n\t\n")}) {
        INFO(text);
        const DecodedInput whole = decode_input(text, limits);
        for (std::size_t cut = 1; cut < text.size(); ++cut) {
            if (last_line_end_before(text, cut) != cut) continue;   // only cuts right after a line break
            INFO(cut);
            InputScanner first(limits), second(limits);
            first.feed(std::string_view(text).substr(0, cut));
            second.feed(std::string_view(text).substr(cut));
            first.append(second);
            const DecodedInput scanned = first.finish();
            REQUIRE(scanned.problems.size() == whole.problems.size());
            for (std::size_t i = 0; i < scanned.problems.size(); ++i) {
                CHECK(scanned.problems[i].kind == whole.problems[i].kind);
                CHECK(scanned.problems[i].line == whole.problems[i].line);
                CHECK(scanned.problems[i].message == whole.problems[i].message);
            }
        }
    }
}

TEST_CASE("line breaks: LF, CRLF and a lone CR each end a line") {
    const std::string text = "A\nB\r\nC\rD\r\rE";
    const std::vector<std::string> lines = scanner_lines(text);
    // "B\r" keeps the CR of its CRLF (trivia before the LF); "D\r\r" is D, then an empty line.
    CHECK(lines == std::vector<std::string>{"A", "B\r", "C", "D", "", "E"});
    CHECK(count_line_breaks(text) == 5);
    const LineIndex index(text);
    CHECK(index.line_count() == 6);
    CHECK(index.utf8(static_cast<std::uint32_t>(text.find('E'))).line == 5);
    // The last line end before a limit; a CRLF cut by the limit does not count.
    CHECK(last_line_end_before("AB\r\nCD", 3) == std::string::npos);
    CHECK(last_line_end_before("AB\r\nCD", 4) == 4);
    CHECK(last_line_end_before("AB\rCD", 4) == 3);
}

// The lines as the rule of LineBreaks says, one byte at a time: '\n' ends a line, so does a '\r'
// not followed by '\n' (the '\r' of "\r\n" stays in its line as trivia before the '\n').
namespace {

std::vector<std::string> naive_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::string line;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n' || (c == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) {
            lines.push_back(line);
            line.clear();
            continue;
        }
        line += c;
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

}  // namespace

TEST_CASE("line breaks: the scanner cuts every mix of CR, LF and CRLF as a byte-by-byte reading does") {
    // Texts without any '\r', with '\r' only at the end, with '\r' here and there, CRLF and
    // CR CR LF: every mix must cut as the rule says.
    std::mt19937 random(20261128);
    const std::string alphabet = "G1\r\n\n X";
    for (int round = 0; round < 2000; ++round) {
        std::string text;
        const std::size_t length = random() % 40;
        for (std::size_t i = 0; i < length; ++i) text += alphabet[random() % alphabet.size()];
        const std::vector<std::string> lines = scanner_lines(text);
        INFO(printable(text));
        CHECK(lines == naive_lines(text));
    }
}

TEST_CASE("line breaks: long texts with a few CRs far apart cut as a byte-by-byte reading does") {
    // Long texts of short lines with a few lone CRs and CRLFs tens of kilobytes apart, and lines
    // longer than 64 KiB ended by a lone CR: the searches for '\r' and '\n' go far ahead.
    std::mt19937 random(7);
    for (int round = 0; round < 20; ++round) {
        std::string text;
        while (text.size() < 300000) {
            const unsigned pick = random() % 5000;
            if (pick == 0) text += "G1 X1\r";
            else if (pick == 1) text += "G1 X1\r\n";
            else if (pick == 2) text += std::string(70000 + random() % 1000, 'X') + "\r";
            else text += "G1 X1\n";
        }
        const std::vector<std::string> lines = scanner_lines(text);
        CHECK(lines == naive_lines(text));
    }
}

TEST_CASE("display: control bytes and invalid UTF-8 are escaped, characters kept") {
    CHECK(printable("G0 (\x1b[2J) \x07\x7f") == "G0 (\\x1b[2J) \\x07\\x7f");
    CHECK(printable("(\xD0\x96 \xC2\x9B" "1m \xFF)") == "(\xD0\x96 \\u009b1m \\xff)");
    CHECK(printable("a\tb\nc\r\n") == "a\tb\\x0ac\\x0d\\x0a");
    CHECK(printable("a\nb\r\n", true) == "a\nb\r\n");
    CHECK(valid_utf8("ok \xD0\x96 \xFF\xC0\xAF") == "ok \xD0\x96 \xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");
    CHECK(shorten("abcdef", 3) == "abc...");
    CHECK(shorten("\xD0\x96\xD0\x96\xD0\x96", 2) == "\xD0\x96\xD0\x96...");
    CHECK(shorten("abc", 3) == "abc");
}

TEST_CASE("display: an excerpt is a window around the range, its caret under what is shown") {
    const Excerpt short_line = excerpt("G01 X1. X1.", 8, 11, false);
    CHECK(short_line.text == "G01 X1. X1.");
    CHECK(short_line.caret == "        ^^^");
    const Excerpt tabs = excerpt("\tG01\tX\x1b", 5, 7, false);
    CHECK(tabs.text == "\tG01\tX\\x1b");
    CHECK(tabs.caret == "\t   \t^^^^^");
    // A 10,000-character line: about 100 columns around column 5,000, cut on both sides.
    std::string line;
    for (int i = 0; i < 2500; ++i) line += "X1. ";
    const Excerpt long_line = excerpt(line, 5000, 5003, false);
    CHECK(long_line.text.size() < 110);
    CHECK(long_line.text.substr(0, 3) == "...");
    CHECK(long_line.text.substr(long_line.text.size() - 3) == "...");
    const std::size_t caret = long_line.caret.find('^');
    CHECK(long_line.text.substr(caret, 3) == "X1.");
    CHECK(long_line.caret.substr(caret) == "^^^");
    // To the line's end, and a range at the end of the line.
    CHECK(excerpt("G01 X1.", 4, 0, true).caret == "    ^^^");
    CHECK(excerpt("G01", 3, 3, false).caret == "   ^");
}
