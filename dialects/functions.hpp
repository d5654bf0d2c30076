// Function ids the code refers to by name (the full vocabulary is in docs/functions.md).
// Code looks codes up by what they do, never by number, so that G32 (A) and G33 (B/C) are one thing.
#pragma once

#include <string_view>

namespace kerf::dialects::functions {

inline constexpr std::string_view rapid = "rapid";
inline constexpr std::string_view linear = "linear";
inline constexpr std::string_view dwell = "dwell";
inline constexpr std::string_view macro_call = "macro-call";
inline constexpr std::string_view modal_macro_call = "modal-macro-call";
inline constexpr std::string_view subprogram_call = "subprogram-call";
inline constexpr std::string_view subprogram_return = "subprogram-return";

}  // namespace kerf::dialects::functions
