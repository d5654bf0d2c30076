// What a word of a block means to the converter: how the interpreter reads its number (a length,
// read in least increments without a point unless the machine has calculator input; a dwell time
// in the dialect's P unit; a P/Q in least increments always; or the number itself) and, for the
// drilling cycles, which letter is the peck and which the repeat count in each dialect's table.
// Keyed by function id (dialects/functions.hpp) and the code's word list, never by dialect.
#pragma once

#include <cstdint>
#include <span>

#include "dialects/dialect.hpp"

namespace kerf::converter {

enum class WordUnit : std::uint8_t {
    raw,      // the number itself (F, S, T, counts, angles, G04 X seconds)
    length,   // mm (or inch): least increments without a point unless calculator input (dialects.md §2)
    dwell,    // a dwell in the dialect's P unit (ms or s, semantics.md §8.2)
    pq,       // least increments always (cycles.md §0): the machine's, not the dialect's
};

// The unit of a parameter word (Role::parameter) `letter` in a block with `codes`, as the
// interpreter reads it (interpreter/cycles/*.cpp ctx.mm / raw / pq, executor_*.cpp axis_value).
WordUnit parameter_unit(char letter, std::span<const dialects::CodeInfo* const> codes);

// A drilling cycle's peck word and repeat word in one dialect's entry: the peck is Q where the
// code takes Q, else K on a peck cycle (ADV400 G83 K, cycles.md §11.3); the repeat count is K
// where K is not the peck, else L (cycles.md §10, §11.1). 0 where there is none.
struct DrillLetters {
    char peck = 0;
    char repeat = 0;
};
DrillLetters drill_letters(const dialects::CodeInfo& code);
bool is_drilling_cycle(dialects::FunctionId function);
// Lathe live-tool cycles (cycles.md §10): their return level is the only one system A has.
bool is_lathe_drilling_cycle(dialects::FunctionId function);

}  // namespace kerf::converter
