// The stable ids of the diagnostics kerf's layers produce (docs/diagnostics.md): the grammar and the
// binder (S…), macro evaluation (M…, the FANUC alarm number after "M0"), the formatter's
// renumbering (F…). Code names them through these constants; tests/test_ids.cpp checks that this
// list, docs/diagnostics.md and the analyzer's rules (which S ids each rule reports) agree.
#pragma once

#include <string_view>

namespace kerf::ast::diagnostic_id {

// Grammar and binder (grammar/block_def.hpp, grammar/parse.cpp, ast/typed.cpp).
inline constexpr const char* file_too_large = "S0001";
inline constexpr const char* address_without_value = "S0101";
inline constexpr const char* malformed_number = "S0102";
inline constexpr const char* letter_o_for_zero = "S0103";
inline constexpr const char* placeholder_value = "S0104";
inline constexpr const char* decimal_comma = "S0105";
inline constexpr const char* unknown_word = "S0106";
inline constexpr const char* value_without_address = "S0107";
inline constexpr const char* misplaced_block_delete = "S0108";
inline constexpr const char* stray_text = "S0109";
inline constexpr const char* unknown_comma_word = "S0110";
inline constexpr const char* slash_comment = "S0111";
inline constexpr const char* zero_for_letter_o = "S0112";
inline constexpr const char* listing_ellipsis = "S0113";
inline constexpr const char* nesting_too_deep = "S0114";
inline constexpr const char* grammar_stopped = "S0199";
inline constexpr const char* unclosed_comment = "S0201";
inline constexpr const char* nested_comment = "S0202";
inline constexpr const char* unmatched_close_paren = "S0203";
inline constexpr const char* packed_p_with_l = "S0301";
inline constexpr const char* second_sequence_number = "S0302";
// Macro evaluation (interpreter/macro/evaluate.hpp; reported as interpreter alarms).
inline constexpr const char* macro_overflow = "M0111";
inline constexpr const char* macro_division_by_zero = "M0112";
inline constexpr const char* macro_format = "M0114";
inline constexpr const char* macro_variable_number = "M0115";
inline constexpr const char* macro_write_protected = "M0116";
inline constexpr const char* macro_bracket_nesting = "M0118";
inline constexpr const char* macro_argument = "M0119";
inline constexpr const char* macro_bad_tree = "M0901";
// Formatter (formatter/renumber.cpp).
inline constexpr const char* renumber_refused = "F0001";

// Every id above, in the order of docs/diagnostics.md.
inline constexpr std::string_view kAll[] = {
    file_too_large, address_without_value, malformed_number, letter_o_for_zero, placeholder_value, decimal_comma,
    unknown_word, value_without_address, misplaced_block_delete, stray_text, unknown_comma_word, slash_comment,
    zero_for_letter_o, listing_ellipsis, nesting_too_deep, grammar_stopped, unclosed_comment, nested_comment,
    unmatched_close_paren, packed_p_with_l, second_sequence_number, macro_overflow, macro_division_by_zero,
    macro_format, macro_variable_number, macro_write_protected, macro_bracket_nesting, macro_argument,
    macro_bad_tree, renumber_refused,
};

}  // namespace kerf::ast::diagnostic_id
