// The cheap scan behind the program index: the programs of a file (O number, byte range, first
// comment) without parsing it. It follows the grammar's and the binder's program split
// (grammar/parse.cpp block kinds, ast::ProgramSplitter) line by line with a few byte tests:
//
//   - blocks are the lines, cut further at ';' where the dialect's ';' ends a block (outside
//     comments); a UTF-8 BOM opens the file;
//   - a block whose first word, after blanks, a block delete (/ or /n) and leading comments, is an
//     O word (O1000, o1000, O 1000, O1000.) or the ISO form :1000 starts a program; the number is
//     its integer value (O60.5 and O#1 start a program without a number);
//   - a '%' block closes the open program; with an O word after the '%' on the same line
//     (%O0003(...)) it also starts that program; a '%' after code ends the file: the rest is the
//     tail the control does not read;
//   - blocks before the first O line form a program without number once one of them holds code;
//     programs without number are counted (program_index) but not indexed.
//
// tests/project/test_scan.cpp runs the scan and the parser on every reference example and corpus
// file and compares every program (number, index, byte range).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dialects/dialect.hpp"

namespace kerf::project {

// The lexical switches the scan needs (dialects::LexicalRules); the defaults are FANUC's.
struct ScanRules {
    bool semicolon_ends_block = true;     // false: ';' starts a comment (pcnc-mill)
    bool paren_comments = true;
    std::vector<std::string> line_comments;   // "::", ";;" (ADV400)
    bool decimal_comma = true;                // O1,5 reads as 1.5 (LexicalRules::decimal_comma_lenient)
    bool macro_b = true;                      // DPRNT[...]/BPRNT[...] text: its ';' ends no block
    static ScanRules of(const dialects::LexicalRules& lexical);
};

struct ScannedProgram {
    std::int64_t number = 0;
    std::uint32_t program_index = 0;   // index into the file's ast::TypedFile::programs()
    std::uint32_t begin = 0;           // byte range of the program: its first block ...
    std::uint32_t end = 0;             // ... to the block that ends it (or the end of the text)
    std::string comment;               // the first comment of the program (on its O line or the next lines), without ( )
};

// The numbered programs of `text`, in file order.
std::vector<ScannedProgram> scan_programs(std::string_view text, const ScanRules& rules = {});

}  // namespace kerf::project
