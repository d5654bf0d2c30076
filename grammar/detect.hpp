// Dialect detection (reference/dialects.md §10): reads a file with permissive lexical rules and
// weighs the evidence each dialect of a registry declares in its `[detect]` table
// (dialects/SCHEMA.md), so a user's dialect file is detected like a built-in one. Always says why,
// so a wrong guess can be argued with and overridden.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dialects/dialect.hpp"

namespace kerf::grammar {

// One clue found in the file: which dialect's `[detect]` entry, where first, how often, the points.
struct Clue {
    std::string dialect;
    std::string what;     // "G50 S", "word U", "'::' comment", "#10000..#99999"
    std::string proves;   // the entry's `proves` text
    int line = 0;         // 1-based, of the first occurrence (0: a clue about the whole file)
    int column = 0;
    int count = 0;        // occurrences
    int points = 0;       // weight for the first, a quarter of it for each further one
};

struct Detection {
    std::string dialect;               // an id of the registry
    std::vector<std::string> reasons;  // the explanation, one line each (kerf parse --explain-dialect)
    int confidence = 0;                // the winning score (100: a header comment decided)
    bool evidence = true;              // false: nothing in the file pointed anywhere; `dialect` is the fallback
    std::vector<Clue> clues;           // every clue found, by dialect
    std::vector<std::pair<std::string, int>> scores;   // the candidates with a score, best first
    // A profile of another control (`foreign = true` in the registry) outweighed every dialect: its
    // id and name, and the first clue that proved it (line, column, what). `dialect` is still the
    // best dialect (or the fallback), for a caller that reads the file anyway.
    struct Foreign {
        std::string id, name;
        int score = 0;
        Clue first;
    };
    std::optional<Foreign> foreign;
};

struct DetectOptions {
    // For a file without evidence: the dialect to take and why ("7 of the 9 programs in its
    // folder"), chosen by the caller (the project layer knows the folder and .kerf.toml). Empty:
    // the registry's `[detect] default = true` dialect.
    std::string fallback;
    std::string fallback_reason;
};

// Reads at most the first 256 KiB (whole lines): enough evidence, and a long file costs no more.
Detection detect_dialect(std::string_view text, const dialects::Registry& registry, const DetectOptions& options = {});
// The built-in registry.
Detection detect_dialect(std::string_view text);

// The folder rule for a file without evidence: the dialect most of the other files' detections
// (those with evidence) chose, with "N of M programs in its folder"; nullopt when none had evidence.
std::optional<std::pair<std::string, std::string>> folder_majority(std::span<const Detection> others);

namespace detail {
// Where a `line` clue holds (dialects/SCHEMA.md [detect] lines): the offset of the first character
// that is not a blank of each line that starts with (`prefix`) or contains `pattern`, in text
// order, once per line. Lines end at '\n' or '\r'; leading spaces and tabs are not part of a line.
std::vector<std::uint32_t> line_clue_offsets(std::string_view text, std::string_view pattern, bool prefix);
}  // namespace detail

}  // namespace kerf::grammar
