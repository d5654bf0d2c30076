// The dialect tables: codes, modal groups, words, descriptions and lexical switches.
// Built from the TOML files in dialects/data (see dialects/SCHEMA.md). No I/O here:
// the loader takes text; the CLI reads files.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dialects/functions.hpp"

namespace kerf::dialects {

// G12.1 → 121, G00 → 0, M329 → 3290: one decimal digit is all FANUC codes use.
using CodeKey = std::int32_t;
std::optional<CodeKey> code_key(double number);
// "G12.1" / "M03" / "g1" → letter and key; nullopt if not a code spelling.
std::optional<std::pair<char, CodeKey>> parse_code_spelling(std::string_view spelling);

enum class Availability { standard, optional, not_fitted, machine_specific, unlisted };
enum class SemicolonRole { end_of_block, comment };
enum class SubprogramCall { packed, p_l, both };
enum class MachineKind { lathe, mill };
// Where a jump to N`n` lands when several blocks carry N`n` (GOTO, M97 P, M99 P, M98 Q): the first
// from the program's top, or the first after the jump, wrapping to the top (`[lexical] label_search`).
enum class LabelSearch { from_top, forward };

struct CodeInfo {
    char letter = 'G';
    CodeKey key = 0;
    std::string spelling;                  // as in the reference: "G00", "G12.1", "M003"
    std::vector<std::string> aliases;      // other spellings of this entry ("G113")
    std::string group;                     // "00" one-shot, "" none
    bool modal = false;
    bool power_on_default = false;
    FunctionId function;                   // shared semantic id (docs/functions.md)
    std::vector<std::string> words;        // "X", ",A", ...
    std::string parameter_letters;         // letters that are data, not axis moves, in this code's block (G04 X, G71 U)
    std::vector<std::string> required;
    std::vector<std::vector<std::string>> required_one_of;
    Availability availability = Availability::standard;
    std::string availability_note;
    std::string en;
    std::string ru;
    std::string reference;
    std::string notes;
    // `implied = ["P1"]`: words the code stands for, read as if the block had them (Haas G110 is
    // G154 P1); a word the block writes itself wins.
    std::vector<std::pair<char, double>> implied;

    // Derived from the fields above when the dialect is indexed (Dialect::reindex), so hot loops
    // compare bits, not strings: the function's traits plus the group's (traits::one_shot for a G
    // code of group 00, traits::motion_group for group 01).
    std::uint32_t traits = 0;
    std::uint32_t parameter_mask = 0;   // parameter_letters as bits (A = bit 0)
    std::uint8_t group_index = 0;       // index of `group` in Dialect::groups() (0: no group, "")

    bool has(std::uint32_t trait) const { return (traits & trait) != 0; }
    PlaneTrait plane() const { return plane_of(traits); }
    int position_offset() const { return function.def().position_offset; }   // G45–G48: ±1, ±2 D
    int work_coordinate() const { return function.def().work_coordinate; }   // G54–G59: 1–6
    bool takes_word(std::string_view word) const;
};

struct LexicalRules {
    SemicolonRole semicolon = SemicolonRole::end_of_block;
    bool paren_comments = true;
    std::vector<std::string> line_comments;          // "::", ";;"
    std::map<char, char> incremental_letters;        // U → X
    std::string axes;                                // "XZCBY"
    std::string diameter_letters;                    // "XU"
    std::string comma_words;                         // "ACR"
    bool plain_direct_drawing = false;
    SubprogramCall subprogram_call = SubprogramCall::packed;
    bool decimal_comma_lenient = true;               // "warn": read F0,25 as 0.25 (with a diagnostic)
    bool calculator_decimal = false;
    // Default of the machine switch dwell_p_unit: G04 P (and a drilling cycle's dwell P) in
    // milliseconds (FANUC) or seconds (ADV400), semantics.md §8.2.
    bool dwell_p_seconds = false;
    // Digits of a program number (O word, the program part of a packed M98 P): FANUC 4
    // (dialects.md §2, §3.6); 0 = no fixed width (the seed does not say).
    int program_digits = 4;
    std::string tool_word = "mmnn";
    bool macro_b = true;
    int max_m_per_block = 1;
    LabelSearch label_search = LabelSearch::from_top;
    bool if_words = false;   // [Haas] IF [...] may be followed by the block's words (IF [#1 NE 1.] G65 P9725)

    bool is_axis(char letter) const { return axes.find(letter) != std::string::npos; }
    bool is_diameter(char letter) const { return diameter_letters.find(letter) != std::string::npos; }
    bool is_comma_word(char letter) const { return comma_words.find(letter) != std::string::npos; }
    // The absolute axis an incremental letter moves, or 0.
    char incremental_axis_of(char letter) const;
};

// One clue of dialect detection (dialects/SCHEMA.md `[detect]`; grammar/detect.cpp weighs them).
struct DetectClue {
    enum class Kind : std::uint8_t { code, word, absent_word, comment, header, variable, lexical, line };
    Kind kind = Kind::code;
    char letter = 0;                 // code: 'G' / 'M'; word, absent_word: the address letter
    CodeKey key = 0;                 // code
    std::string spelling;            // what the explanation quotes: "G50 S", "word U", "'::' comment"
    std::vector<std::pair<char, std::optional<double>>> with;   // code: words the block must have ("P0": P = 0)
    std::string with_any;            // code: one of these letters too; absent_word: the file has one of them
    std::string without;             // code: none of these letters in the block
    std::string text;                // comment: the prefix; header: the text; lexical: the observation;
                                     // line: what a source line starts with or contains
    bool line_prefix = false;        // line: `starts_with` (else `contains`)
    std::int64_t from = 0, to = 0;   // variable: #from .. #to
    int weight = 0;                  // points for the first occurrence (negative: evidence against)
    std::string proves;              // what the clue proves, for the explanation
    bool own = true;                 // false: a base's clue in an overlay's combination
    int line = 0, column = 0;        // in the data file, for errors found once the dialect is complete
};

// A range of macro variables the dialect gives a meaning beyond FANUC Custom Macro B's
// (`[[variables]]`, dialects/SCHEMA.md): the Haas NGC #10000 ranges. The interpreter asks the
// dialect before its built-in system variables.
enum class VariableKind : std::uint8_t {
    common,         // general-purpose, kept for the run (vacant at power-on)
    alias,          // the same variable as #(alias_of + n − from)
    work_offsets,   // additional work offsets (G154 P / G54.1 P): `stride` variables per offset, axis order
    setting,        // a control setting (#20000 + n): read as stored, else vacant
    parameter,      // a control parameter (#30000 + n): read as stored, else vacant
    tool_in_spindle,   // the tool in the spindle (Haas #3026)
    spindle_rpm,       // the commanded spindle speed (Haas #3027)
};
struct VariableRange {
    std::int64_t from = 0, to = 0;
    VariableKind kind = VariableKind::common;
    std::int64_t alias_of = 0;   // alias: the variable #from stands for
    int first_set = 1;           // work_offsets: the offset number of #from (G154 P1)
    int stride = 20;             // work_offsets: variables from one offset to the next
    std::string axes;            // work_offsets: the axis of each variable of an offset ("XYZABC"); empty: the machine's order
    bool read_only = false;
    bool units = false;          // reading it tells a program its unit (Haas #20009, Setting 9 inch/mm)
    std::string en, ru, reference;
};

// `[alarms]` (dialects/SCHEMA.md): the number and text a control shows for one of kerf's alarms.
// kerf's number (dialects/alarms.hpp, FANUC's numbering) stays the alarm's identity: the
// analyzer's rules, `--verify` and the trace's `code` use it; the control's number is what the
// user reads (the trace's `control_alarm`, the messages of kerf run and kerf check).
struct ControlAlarm {
    int kerf = 0;             // the constant's number (alarms::program_not_found = 78)
    std::string name;         // the constant's name, as the file writes it ("program_not_found")
    int number = 0;           // the control's number; for user_alarm_first, the number #3000 = 0 shows
    std::string text;         // the control's text; empty for the #3000 range (the program's own message)
    std::string reference;    // the public document the number and text come from
};

struct AlarmTable {
    std::string control;                 // who numbers them ("Haas NGC"), said with the number
    std::vector<ControlAlarm> entries;   // at most one per kerf number

    struct Shown {
        int number = 0;                      // what the control shows
        const ControlAlarm* entry = nullptr;
    };
    // The control's number for kerf's alarm `kerf`, or nullopt: the control shows kerf's (FANUC's)
    // number. #3000 = n (kerf's 3000 + n) maps through a user_alarm_first entry to its number + n,
    // unless an entry names 3000 + n itself (SPINNER's 3011).
    std::optional<Shown> shown(int kerf) const;
    // How a message names the alarm: "Haas NGC alarm 314 SUBPROGRAM NOT FOUND" when the table maps
    // it, else FANUC's "alarm 078" (three digits below 1000, as FANUC writes them).
    std::string name_of(int kerf) const;
    // The alarm's text as the user reads it: kerf's explanation as it is when the table does not map
    // the alarm (with "(Haas NGC numbers this alarm its own way; kerf gives FANUC's)" and the FANUC
    // number named as FANUC's when the table names a control), else "Haas NGC alarm 314 SUBPROGRAM NOT FOUND: program O9810 not found (FANUC alarm
    // 078)" — the control's number and text, then kerf's explanation with the FANUC number it quotes
    // named as FANUC's.
    std::string message(int kerf, std::string_view kerf_text) const;
    // Entries of `other` replace this table's entry of the same alarm or are added (`base`
    // inheritance and overlays); its control name, when it has one, replaces this one.
    void merge(const AlarmTable& other);
};

struct DetectRules {
    std::vector<DetectClue> clues;
    bool needs_own = false;   // an overlay's combination: a candidate only when its own clues score
    bool fallback = false;    // `default = true`: the dialect of files without evidence
};

class Dialect {
public:
    std::string id;
    std::string name;
    MachineKind machine = MachineKind::lathe;
    std::string reference;
    std::vector<std::string> overlays;   // ids of the overlays applied, in order
    std::vector<std::string> bases;      // `base` inheritance: the dialect this one derives from, its base, ...
    DetectRules detect;                  // [detect]: the evidence that proves this dialect
    LexicalRules lexical;
    std::vector<VariableRange> variables;   // [[variables]]: ranges beyond FANUC Macro B's
    AlarmTable alarms;                      // [alarms]: the control's own alarm numbers, if not FANUC's
    // A profile of another control (`foreign = true`): only its [detect] evidence, no tables. When
    // it wins detection, kerf says so instead of reading the file as FANUC (issue 15).
    bool foreign = false;

    // The dialect's meaning of variable #`number`, or nullptr (FANUC's built-in ranges apply).
    const VariableRange* variable_range(std::int64_t number) const;

    const CodeInfo* code(char letter, CodeKey key) const;
    const CodeInfo* code(std::string_view spelling) const;   // "G71", "m3", "G12.1"
    std::span<const CodeInfo> codes() const { return codes_; }
    // All codes with a function id (several in C for renamed codes is impossible; at most one per dialect
    // is usual, but the API returns all).
    std::vector<const CodeInfo*> codes_with_function(FunctionId function) const;

    // The modal groups of the codes, sorted, "" first: CodeInfo::group_index indexes it, so the
    // modal state can be a flat array (one slot per group) in the order of the group names.
    std::span<const std::string> groups() const { return groups_; }
    std::optional<std::uint8_t> group_index(std::string_view group) const;   // "01" → its index

    // O(1) lookup used by the binder on every G and M word.
    const CodeInfo* fast_code(char letter, CodeKey key) const;

    void add_or_replace(CodeInfo info);
    void set_codes(std::vector<CodeInfo> codes);

private:
    static constexpr CodeKey kFastCodes = 10000;   // G/M keys below 1000.0
    std::vector<CodeInfo> codes_;
    std::vector<std::string> groups_;
    std::map<std::pair<char, CodeKey>, std::size_t> index_;
    std::vector<std::int32_t> g_fast_;
    std::vector<std::int32_t> m_fast_;
    void reindex();
};

struct LoadError {
    std::string message;   // what is wrong, with the TOML key path
    int line = 0;          // 1-based line in the TOML text, 0 if unknown
    int column = 0;
};

// `[[patch]]` in a derived dialect: single fields of an inherited code.
struct CodePatch {
    char letter = 'G';
    CodeKey key = 0;
    std::string spelling;
    CodeInfo fields;                 // the values of the keys below
    std::vector<std::string> keys;   // the keys the patch sets ("reference", "notes", ...)
    int line = 0, column = 0;
};

// A parsed data file: a whole dialect, a dialect derived from another (`base`), or an overlay.
struct DialectFile {
    Dialect dialect;
    bool overlay = false;
    std::vector<std::string> applies_to;
    std::vector<std::string> combined_ids;
    // Lexical keys present in an overlay or derived file (only these override the base).
    std::vector<std::string> lexical_keys_set;
    LexicalRules lexical_overrides;
    // `base = "id"`: the dialect is its base's tables with `remove`, the file's codes and `patch`.
    std::string base;
    bool machine_set = false;                                    // `machine` given (else the base's)
    std::vector<std::pair<std::string, std::pair<int, int>>> remove;   // spelling, line/column
    std::vector<CodePatch> patches;
    bool detect_set = false;       // a [detect] table (else a derived dialect takes its base's)
    bool detect_inherit = false;   // [detect] inherit = true: the base's clues and these
    bool variables_set = false;    // [[variables]] given (a derived dialect appends them to its base's)
    int base_line = 0, base_column = 0;
};

struct LoadResult {
    std::optional<DialectFile> file;
    std::vector<LoadError> errors;
};

// Parses one dialect data file. `source_name` is used in error messages only.
LoadResult load_dialect_text(std::string_view toml_text, std::string_view source_name);

// Base + overlay → combined dialect (spinner-lathe-a = fanuc-lathe-a + spinner).
Dialect apply_overlay(const Dialect& base, const DialectFile& overlay, std::string combined_id);

// Base + derived file → the derived dialect (fanuc-lathe-b = fanuc-lathe-a with B's differences);
// errors for a `remove` or `[[patch]]` code the base does not have. `source_name` is for messages.
Dialect derive_dialect(const Dialect& base, const DialectFile& file, std::string_view source_name,
                       std::vector<LoadError>& errors);

// A complete dialect's [detect] clues checked against its tables: a code clue with a positive
// weight must name a code of the dialect (evidence for a code it lacks proves nothing).
std::vector<LoadError> check_detect(const Dialect& dialect, std::string_view source_name);


class Registry {
public:
    const Dialect* find(std::string_view id) const;
    std::vector<std::string> ids() const;
    void add(Dialect dialect);
    // Adds a user file: a base dialect, or an overlay combined with every base it applies to.
    std::vector<LoadError> add_text(std::string_view toml_text, std::string_view source_name);
    std::vector<LoadError> add_file(DialectFile file, std::string_view source_name);
    std::span<const DialectFile> overlay_files() const { return overlays_; }
    // The profiles of other controls (`foreign = true` files), which detection weighs beside the
    // dialects but which are no dialect to read a file in.
    std::span<const Dialect> foreign_controls() const { return foreign_; }
    const Dialect* find_foreign(std::string_view id) const;

private:
    std::vector<LoadError> add_derived(DialectFile file, std::string_view source_name);
    std::deque<Dialect> dialects_;   // a deque keeps pointers stable as dialects are added
    std::vector<Dialect> foreign_;
    std::vector<DialectFile> overlays_;
};

// The dialects compiled into the binary (dialects/data/*.toml), with overlays combined.
const Registry& builtin_registry();

// docs/functions.md's two tables (G-code and M-code functions: id, meaning, the codes of each
// dialect of `registry` with that function, traits), from the vocabulary in functions.hpp;
// `kerf dialects --functions` prints them and tests/dialects/test_functions.cpp keeps the file equal.
std::string function_tables_markdown(const Registry& registry);

// The built-in data file texts by file stem ("fanuc-lathe-a", "spinner"), for `kerf dialects --dump`.
std::span<const std::pair<std::string_view, std::string_view>> builtin_dialect_texts();

}  // namespace kerf::dialects
