// The one reference resolver: where a block points at another block or program, and what it
// points at. Every jump and call the reference names is here, found by function id, never by number:
//
//   GOTO n, IF [...] GOTO n        a label of the program itself (dialects.md §3.7)
//   G70–G73 P/Q (system A)         the first and last block of the profile (cycles.md §1–§5)
//   M98 Q                          with P a label of the called program, without P one of this
//                                  program ([FANUC]; the executor's call_subprogram)
//   M99 P                          a label of the caller (dialects.md §3.6)
//   M97 P                          [Haas] a label of this program run as a local subroutine
//   M98 P (packed or P/L form)     a program (dialects.md §3.6)
//   G65 P, G66 P                   a program called as a macro (dialects.md §3.7)
//
// The formatter's renumbering, the analyzer's reference rules and the language server's
// definition, references and rename all ask this module, so they can never disagree about what a
// word refers to. It reads one bound file; a program in another file is named by its number and
// found by the caller (the program index). Pure: no I/O.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ast/typed.hpp"

namespace kerf::references {

enum class Kind : std::uint8_t {
    goto_label,        // GOTO n / IF [...] GOTO n
    profile_label,     // G70–G73 P or Q
    call_label,        // M98 Q
    return_label,      // M99 P
    local_call_label,  // M97 P
    subprogram,        // M98 P
    macro,             // G65 P / G66 P
};
const char* to_string(Kind k);

// True for the kinds whose number is a sequence number (N), false for program numbers (O).
inline bool is_label(Kind k) { return k != Kind::subprogram && k != Kind::macro; }

struct Reference {
    Kind kind = Kind::goto_label;
    std::uint32_t block = 0;
    std::uint32_t program = 0;           // index into TypedFile::programs() of the block's program
    std::uint32_t token = 0;             // the P/Q word, or the statement token of a GOTO
    std::int32_t code_token = -1;        // the G/M word that makes it a reference (-1 for GOTO)
    char letter = 0;                     // 'P' or 'Q' of a word; 0 for GOTO
    ast::Range range;                    // where the number is written (the word's value, or the label)
    // The label or program number; nullopt when it is computed (GOTO #1, P#100) or not a plain
    // non-negative integer, so that no one follows it by guessing.
    std::optional<std::int64_t> value;
    // M98 P in the packed form (dialects.md §3.6): the repeat digits before the four of the program.
    bool packed = false;
    std::int64_t repeats = 0;            // the packed repeat count (0 when the form has none)
    // call_label with P: the called program's number (its labels are meant, not this program's).
    std::optional<std::int64_t> label_program;
};

// The references of block `block` (of program `program`), in token order.
std::vector<Reference> block_references(const ast::TypedFile& file, std::uint32_t program, std::uint32_t block);

// Every reference of the file, in text order.
std::vector<Reference> file_references(const ast::TypedFile& file);

// The program (TypedFile::programs() index) a block belongs to; nullopt for '%' lines and the
// tail, which belong to none.
std::optional<std::uint32_t> program_of_block(const ast::TypedFile& file, std::uint32_t block);

// The first program of the file with O number `number` (calls reach the first one).
std::optional<std::uint32_t> program_numbered(const ast::TypedFile& file, std::int64_t number);

// The block a jump to N`label` in `program` lands on: the first block of the program that carries
// it (the control searches from the program's start; dialects.md §2 "Sequence number").
std::optional<std::uint32_t> find_label(const ast::TypedFile& file, std::uint32_t program, std::int64_t label);
// The block a reference of this file jumps to in `program` (one of label_scope's programs): with
// the dialect's `label_search = "forward"` (Haas) a jump from a block of that same program lands on
// the first N`label` after the jumping block, wrapping to the program's top; else, and for labels of
// another program (M98 P Q, M99 P), on the first from the top (find_label).
std::optional<std::uint32_t> jump_target(const ast::TypedFile& file, std::uint32_t program, const Reference& r);
// The same for a label `label` jumped to from block `from` of `program` (the interpreter's search).
std::optional<std::uint32_t> find_label_from(const ast::TypedFile& file, std::uint32_t program, std::int64_t label,
                                             std::uint32_t from);
// Every block of `program` with N`label` (more than one: the first wins, the analyzer's K3002).
std::vector<std::uint32_t> label_blocks(const ast::TypedFile& file, std::uint32_t program, std::int64_t label);

// Which programs' labels a label reference may mean.
struct LabelScope {
    std::vector<std::uint32_t> programs;          // programs of this file
    std::optional<std::int64_t> other_program;    // M98 P Q: the called program when not in this file
    bool other_callers = false;                   // M99 P: a caller in another file may be meant too
};
LabelScope label_scope(const ast::TypedFile& file, const Reference& r);

// The programs of this file that call program `program` (M98 P, G65/G66 P with its number); for
// M99 P in the first program of the file, the program itself too (M99 in a main program returns
// to its own start or label: dialects.md §3.6).
std::vector<std::uint32_t> callers_of(const ast::TypedFile& file, std::uint32_t program);

// The text that replaces `r.range` when the block or program it names gets number `number`,
// keeping the reference's form: the repeat digits of a packed M98 P (P31234 → 1240: "31240"),
// the width of a number written with leading zeros (P0012 → 40: "0040"). nullopt when the form
// cannot hold the number (a packed M98 P takes four digits).
std::optional<std::string> respell(const ast::SyntaxTree& tree, const Reference& r, std::int64_t number);

}  // namespace kerf::references
