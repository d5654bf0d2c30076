// Random edits of a program text as an editor makes them (typing, deleting across lines, pasting
// and deleting lines, typing '%' which changes how the rest of the file reads), drawn from a
// fixed-seed generator: the incremental re-parse and the incremental check are compared with
// whole ones after each (tests/lsp/test_reparse.cpp, test_incremental_check.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>

#include "lsp/reparse.hpp"

namespace kerf::test {

// A line boundary near `at` (0 or just after a '\n').
inline std::uint32_t line_start(const std::string& text, std::uint32_t at) {
    const std::size_t nl = at == 0 ? std::string::npos : text.rfind('\n', at - 1);
    return nl == std::string::npos ? 0 : static_cast<std::uint32_t>(nl + 1);
}

inline lsp::ByteEdit random_edit(const std::string& text, std::mt19937& rng, std::string& storage) {
    const auto pick = [&](std::uint32_t n) { return n == 0 ? 0u : static_cast<std::uint32_t>(rng() % (n + 1)); };
    const auto size = static_cast<std::uint32_t>(text.size());
    const std::uint32_t a = pick(size);
    static const char* kPieces[] = {"X", "1", " ", "\n", "(", ")", ";", "G71 P10 Q20", "N10 GOTO 10\n", "#1=#1+1", "%\n", "%",
                                    "O1234\n", "IF [#1 LT 2] GOTO 5\n", "M98 P41001\n", "\r\n", "12345678901234567890", "Ф"};
    switch (rng() % 6) {
        case 0: storage = kPieces[rng() % std::size(kPieces)]; return {a, a, storage};                     // typing
        case 1: return {a, std::min(size, a + pick(12)), ""};                                                // deleting
        case 2: {                                                                                            // pasting lines
            const std::uint32_t at = line_start(text, a);
            const std::uint32_t from = line_start(text, pick(size));
            storage = text.substr(from, std::min<std::size_t>(200, size - from));
            return {at, at, storage};
        }
        case 3: {                                                                                            // deleting lines
            const std::uint32_t at = line_start(text, a);
            return {at, std::min(size, at + pick(300)), ""};
        }
        case 4: storage = kPieces[rng() % std::size(kPieces)]; return {a, std::min(size, a + pick(4)), storage};   // replacing
        default: {                                                                                           // '%' on its own line
            const std::uint32_t at = line_start(text, a);
            storage = "%\n";
            return {at, at, storage};
        }
    }
}

}  // namespace kerf::test
