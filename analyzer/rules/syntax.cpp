// Syntax rules: the grammar already finds these defects (docs/diagnostics.md); the rules give them
// stable ids, documentation and, where the intent is certain, a fix.
#include "analyzer/rules/common.hpp"
#include "ast/diagnostic_ids.hpp"

namespace kerf::analyzer::rules {

namespace {

using S = Severity;

// "MO6" → "M06": every O after the address letter is a zero (the diagnostic covers the word).
std::optional<Fix> letter_o_fix(const ast::SyntaxTree& tree, const ast::Diagnostic& d) {
    std::string text(tree.slice(d.range));
    for (std::size_t i = 1; i < text.size(); ++i)
        if (text[i] == 'O' || text[i] == 'o') text[i] = '0';
    return Fix{"replace the letter O by the digit 0", {{d.range, text}}};
}

// "0,25" → "0.25" (the diagnostic covers the number).
std::optional<Fix> decimal_comma_fix(const ast::SyntaxTree& tree, const ast::Diagnostic& d) {
    std::string text(tree.slice(d.range));
    for (char& c : text)
        if (c == ',') c = '.';
    return Fix{"write a decimal point", {{d.range, text}}};
}

// "(SYNC" → "(SYNC)": close the comment at the end of the line (trailing blanks stay outside).
std::optional<Fix> close_comment_fix(const ast::SyntaxTree& tree, const ast::Diagnostic& d) {
    std::uint32_t end = d.range.end;
    while (end > d.range.begin && (tree.text[end - 1] == ' ' || tree.text[end - 1] == '\t' || tree.text[end - 1] == '\r')) --end;
    return Fix{"close the comment", {{{end, end}, ")"}}};
}

}  // namespace

void add_syntax(Registry& r) {
    r.add(diagnostic_rule("K1001", "address-without-value", S::error, {ast::diagnostic_id::address_without_value},
        {"An address letter with no value after it.",
         "The control stops with a format alarm, or reads the next word's value for the wrong address.",
         "G01 X-11.Z-5. F0.2", "G01 X-11. Z-5. F0.2", "docs/diagnostics.md S0101; seed 001"}));
    r.add(diagnostic_rule("K1002", "malformed-number", S::error, {ast::diagnostic_id::malformed_number},
        {"A number with more than one decimal point.",
         "The control raises a format alarm; which digits were meant is a guess, so there is no automatic fix.",
         "G01 X-12.8. Z-3.", "G01 X-12.8 Z-3.", "docs/diagnostics.md S0102; seed 001"}));
    r.add(with_diagnostic_fix(diagnostic_rule("K1003", "letter-o-for-zero", S::error, {ast::diagnostic_id::letter_o_for_zero},
        {"The letter O typed where the digit zero is meant (MO6, HO1, GO).",
         "O starts a program number: the block is read as a new program or raises an alarm.",
         "MO6 T2", "M06 T2", "dialects.md §11.10; seed 004"}), letter_o_fix));
    r.add(diagnostic_rule("K1004", "placeholder-value", S::error, {ast::diagnostic_id::placeholder_value},
        {"A placeholder (? or _) left where a value belongs.",
         "A template was run without filling in its values; the control rejects the block.",
         "M165 P9810 X? Y? F50.", "M165 P9810 X10. Y20. F50.", "docs/diagnostics.md S0104; corpus O1000"}));
    r.add(with_diagnostic_fix(diagnostic_rule("K1005", "decimal-comma", S::warning, {ast::diagnostic_id::decimal_comma},
        {"A decimal comma (F0,25) instead of a decimal point.",
         "FANUC controls read only '.'; a comma is a format alarm or splits the number.",
         "G01 Z-1,3 F0,25", "G01 Z-1.3 F0.25", "dialects.md §2 Decimal comma"}), decimal_comma_fix));
    r.add(diagnostic_rule("K1006", "unknown-word", S::error, {ast::diagnostic_id::unknown_word},
        {"Letters that are neither an address word nor a macro keyword.",
         "The control raises a format alarm: prose must be inside a comment.",
         "UNLOAD TOOL", "(UNLOAD TOOL)", "docs/diagnostics.md S0106"}));
    r.add(diagnostic_rule("K1007", "value-without-address", S::error, {ast::diagnostic_id::value_without_address},
        {"A number without its address letter (the G of 'N10 21 G40' was lost).",
         "The control cannot tell what the number is for and stops.",
         "N10 21 G40", "N10 G21 G40", "docs/diagnostics.md S0107; corpus O0001.txt"}));
    r.add(diagnostic_rule("K1008", "misplaced-block-delete", S::error, {ast::diagnostic_id::misplaced_block_delete},
        {"Block delete '/' that is not at the start of the block.",
         "Only a leading '/' skips a block; elsewhere it is read as division or an alarm.",
         "G00 / X10.", "/ G00 X10.", "dialects.md §2 Block delete"}));
    r.add(diagnostic_rule("K1009", "stray-text", S::error, {ast::diagnostic_id::stray_text},
        {"Characters or prose outside a comment.", "The control stops with a format alarm.",
         "G01 X10. mm", "G01 X10. (mm)", "docs/diagnostics.md S0109; seed 000"}));
    r.add(diagnostic_rule("K1010", "unknown-comma-word", S::error, {ast::diagnostic_id::unknown_comma_word},
        {"A comma word (,A ,C ,R) the dialect does not have.", "The control raises an alarm on the unknown address.",
         "G01 X10. ,Q5", "G01 X10. ,C1.", "dialects.md §2 Comma-prefixed words"}));
    r.add(diagnostic_rule("K1011", "slash-comment", S::error, {ast::diagnostic_id::slash_comment},
        {"A '//' comment (Syntec and PC controls), not FANUC syntax.",
         "On a FANUC control '/' is block delete and the rest is read as words: an alarm or worse.",
         "G00 X0. // rapid home", "G00 X0. (rapid home)", "docs/diagnostics.md S0111; corpus O8000"}));
    r.add(diagnostic_rule("K1012", "zero-for-letter-o", S::warning, {ast::diagnostic_id::zero_for_letter_o},
        {"A program number written with the digit 0 for the letter O (00018).",
         "Read as O by kerf, but a control reads a number without address: an alarm.",
         "00018", "O0018", "dialects.md §2, §11.10"}));
    r.add(diagnostic_rule("K1013", "listing-ellipsis", S::error, {ast::diagnostic_id::listing_ellipsis},
        {"An ellipsis (...) of a printed listing: blocks are missing.",
         "The program is incomplete; the control rejects the dots.",
         "N10 G00 X0.\n...\nM30", "N10 G00 X0.\nN20 G01 Z-1. F0.1\nM30", "docs/diagnostics.md S0113; seed 001"}));
    r.add(with_diagnostic_fix(diagnostic_rule("K1014", "unclosed-comment", S::error, {ast::diagnostic_id::unclosed_comment},
        {"A comment not closed before the end of the line.",
         "The control reads to the next ')' or stops: the words of the next lines may be swallowed.",
         "G0 G28 B0 M37 (SYNC", "G0 G28 B0 M37 (SYNC)", "dialects.md §2 Comments; seed 001 §9.2"}), close_comment_fix));
    r.add(diagnostic_rule("K1015", "nested-comment", S::warning, {ast::diagnostic_id::nested_comment},
        {"A '(' inside a comment.", "FANUC does not nest comments: the first ')' ends it and the rest is read as words.",
         "(ROUGH (OD) PASS)", "(ROUGH - OD - PASS)", "dialects.md §2 Comments"}));
    r.add(diagnostic_rule("K1016", "unmatched-close-paren", S::error, {ast::diagnostic_id::unmatched_close_paren},
        {"A ')' without its '('.", "The text before it is read as words: a format alarm.",
         "F20 feed mm/min)", "F20 (feed mm/min)", "docs/diagnostics.md S0203; seed 000"}));
    r.add(diagnostic_rule("K1017", "packed-p-with-l", S::error, {ast::diagnostic_id::packed_p_with_l},
        {"M98 with a packed P (repeats and program) and an L as well.",
         "The repeat count is given twice; the control takes one of them, maybe not the one you meant.",
         "M98 P41001 L2", "M98 P1001 L4", "dialects.md §3.6"}));
    r.add(diagnostic_rule("K1018", "second-sequence-number", S::error, {ast::diagnostic_id::second_sequence_number},
        {"A second N word in one block.", "The control raises an alarm or takes a wrong label for GOTO and P/Q.",
         "N50 G384 N30", "N50 G384", "docs/diagnostics.md S0302; seed 001 §8.4"}));
    r.add(diagnostic_rule("K1019", "parser-limit", S::error, {ast::diagnostic_id::file_too_large, ast::diagnostic_id::nesting_too_deep, ast::diagnostic_id::grammar_stopped},
        {"Input beyond what can be read: a file over 4 GiB, brackets nested too deep, or an internal stop.",
         "The control itself limits brackets to 5 levels (alarm 118); the rest of the block is unchecked.",
         "#1=[[[[[[1]]]]]]", "#1=1", "docs/diagnostics.md S0001 S0114 S0199"}));
}

}  // namespace kerf::analyzer::rules
