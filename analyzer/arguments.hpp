// What the analyzer knows about a program's G65/G66 arguments (issue 15): a local variable that is
// an argument is not a vacant read (K4001), and the guards a macro writes for missing arguments
// (IF [#1 EQ #0] THEN #3000=...) are its own checks when no caller is known (K4006). Pure.
#pragma once

#include <bitset>
#include <cstdint>
#include <functional>
#include <vector>

#include "ast/typed.hpp"

namespace kerf::analyzer {

using LocalSet = std::bitset<34>;   // #1..#33 by number (bit 0 unused)

// The locals a program's header documentation names as its arguments: a comment before its first
// word that reads "G65 P<number> A B C" (the Renishaw/Haas habit: O09994 "( G65 P9994 A B C )").
LocalSet documented_arguments(const ast::TypedFile& file, std::size_t program);

// The locals the G65/G66 calls of this file set when they call O`number` (in any of its programs);
// `called` says whether any such call exists.
LocalSet file_caller_arguments(const ast::TypedFile& file, std::int64_t number, bool& called);

// The locals a program reads before anything in it assigns them (text order): its inputs. Not
// empty: the program is a macro that expects arguments.
LocalSet argument_reads(const ast::TypedFile& file, std::size_t program);

// Whether a program reads a common variable (#100–#199, #500–#999) before anything in it assigns
// it: an input the operator or another program sets (versabuilt 01000.nc "#101 is our op cycle
// count and must be initialized to 1").
bool reads_common_inputs(const ast::TypedFile& file, std::size_t program);

// The locals a program tests for vacancy (`#2 EQ #0`, `#7 NE #0`): arguments it knows may be
// missing and checks (O09985 "IF [ #2 EQ #0 ] GOTO104 ( B CALL CHECK )").
LocalSet vacancy_tested(const ast::TypedFile& file, std::size_t program);

// The arguments program `program` of `file` may be called with, from its header, the calls of its
// file and `index_callers` (the letters callers elsewhere pass, as locals; may be empty); `known`
// says whether any caller or documentation was found.
struct ProgramArguments {
    LocalSet locals;             // documented, passed by a caller, or tested for vacancy
    bool caller_known = false;   // a caller in the file or the index
    bool documented = false;
};
ProgramArguments program_arguments(const ast::TypedFile& file, std::size_t program,
                                   const std::function<std::vector<int>(std::int64_t)>& index_callers);

}  // namespace kerf::analyzer
