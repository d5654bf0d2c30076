// The converter's pass (converter/convert.hpp, docs/convert.md), internal to converter/: the state of
// one conversion and its steps, a file per concern (pass.cpp the block loop and the codes,
// distance.cpp G90/G91 and U/W, parameters.cpp what words read, lexical.cpp comments, block ends
// and calls, local_system.cpp G52 and return levels, facts.cpp what is gathered before the pass,
// edits.cpp the edit list of a block, expand.cpp --expand).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "converter/codes.hpp"
#include "converter/convert.hpp"
#include "converter/dry_run.hpp"
#include "converter/expand.hpp"
#include "converter/numbers.hpp"
#include "converter/words.hpp"
#include "dialects/functions.hpp"

namespace kerf::converter::detail {

namespace fn = dialects::functions;
using ast::Role;
using ast::Token;
using ast::TokenKind;
using dialects::CodeInfo;
using dialects::FunctionId;

// One edit of the block being converted; sorted by place (insertions first) before it is kept.
struct Pending {
    std::uint32_t begin = 0, end = 0;
    std::uint32_t order = 0;
    std::string text;
};

inline bool is_axis_role(Role r) { return r == Role::axis_absolute || r == Role::axis_incremental; }

enum BlockFlag : std::uint8_t { kProfile = 1 };   // flags_: a block of a G70–G73 profile

class Converter {
public:
    Converter(const ast::TypedFile& file, const dialects::Dialect& to, const Options& options);
    Conversion run();

private:
    const ast::TypedFile& file_;
    const ast::SyntaxTree& tree_;
    const dialects::Dialect& from_;
    const dialects::Dialect& to_;
    Options options_;
    Reading rf_, rt_;
    CodeMap codes_;
    Conversion out_;
    std::string line_ending_;
    bool src_modes_ = false, tgt_modes_ = false;
    const CodeInfo* tgt_abs_code_ = nullptr;
    const CodeInfo* tgt_inc_code_ = nullptr;
    bool can_cycle_ = false;
    // Power-on modes the target lacks (dialects.md §3.8 and the tables' `default`): the source's
    // mode of each family where the two differ, written into each program's first code block.
    std::vector<const CodeInfo*> power_on_codes_;
    std::vector<std::string> power_on_missing_;
    bool source_moves_at_power_on_ = false;   // the source has a power-on motion mode (G00)
    bool target_moves_at_power_on_ = false;
    bool power_on_pending_ = false;
    bool in_first_program_ = true;
    const CodeInfo* power_on_motion_ = nullptr;   // the source's power-on G00 where the target has none
    bool src_power_incremental_ = false, tgt_power_incremental_ = false;
    bool lengths_differ_ = false;
    // The axis each letter moves incrementally (U → X), per dialect: lexical.incremental_axis_of
    // is a map lookup, and the pass asks for every word.
    std::array<char, 26> src_incremental_axis_{}, tgt_incremental_axis_{};
    char incremental_axis(const std::array<char, 26>& table, char letter) const {
        return letter >= 'A' && letter <= 'Z' ? table[static_cast<std::size_t>(letter - 'A')] : 0;
    }

    // Facts gathered before the pass.
    std::vector<std::uint8_t> flags_;                    // per block: BlockFlag
    std::unordered_map<std::uint32_t, std::string> return_level_;   // G99 token → why it cannot go ("" = it can)
    std::optional<SourceRun> run_;
    std::set<std::uint32_t> expandable_;                 // construct blocks --expand replaces
    bool header_done_ = false;

    // Text-order state, reset at each program start.
    bool src_incremental_ = false;
    bool tgt_incremental_ = false;
    const CodeInfo* motion_ = nullptr;                  // the source's modal group-01 code
    std::uint32_t motion_at_ = 0;   // where the modal group-01 code is written (its line when reported)
    bool feed_per_rev_ = false;
    bool inch_ = false;                                 // the source's G20 (inch input): its increments are 0.0001 in
    dialects::PlaneTrait plane_ = dialects::PlaneTrait::xy;
    bool compensating_ = false;
    bool transformed_ = false;

    // Per-block scratch, reused.
    struct Rewrite {
        std::uint32_t token = 0;
        char letter = 0;               // the address letter it gets (0: as written)
        std::optional<std::string> value;
        bool value_fixed = false;      // a computed value (G52): readings leave it alone
    };
    std::vector<Rewrite> rewrites_;
    std::vector<ast::CodeRef> g_, m_;
    std::vector<const CodeInfo*> infos_;
    std::vector<Pending> pending_;
    std::uint32_t order_ = 0;

    // 1-based line of an offset, for report texts: counted on from the last one asked (the pass
    // asks in text order), so a file with many reports costs one walk over its text.
    mutable std::uint32_t line_at_ = 0, line_ = 1;

    std::string_view spelling(const Token& t) const { return tree_.spelling(t); }

    void replace_token(const Token& t, std::string text) { edit(t.begin, tree_.end(t), std::move(text)); }

    enum class CommentForm { paren, semicolon, line };

    // A comment as the target reads it: its text unchanged, or in the target's comment form; nullopt
    // with a report when the target has no form for it.
    struct CommentText {
        std::optional<std::string> text;   // nullopt: as written
        bool parens_replaced = false;
        bool impossible = false;
    };

    std::set<std::uint32_t> expandable_candidates_;

    std::uint32_t token_index(const Token& t) const { return static_cast<std::uint32_t>(&t - tree_.tokens.data()); }

    struct AxisMeaning {
        std::uint32_t token;
        char axis;
        bool incremental;
        bool letter_form;   // written with an incremental letter (U/W/H)
    };
    std::vector<AxisMeaning> axes_;

    bool seen_motion_ = false;

    friend Conversion convert(const ast::TypedFile&, const dialects::Dialect&, const Options&);

    // pass: the pass: blocks in text order, codes by function id, the modal state it follows
    std::string hazard(char letter, std::optional<dialects::CodeKey> key) const;
    void reset_program_state(std::size_t b);
    void convert_block(std::size_t b);
    void convert_code_block(std::uint32_t b, const ast::BlockView& view, std::uint32_t first, std::span<const Token> tokens);
    void convert_code(std::uint32_t b, const ast::BlockView& view, const ast::CodeRef& c);
    static bool has_canned_cycles(const dialects::Dialect& d);
    static bool moves(const CodeInfo& c);
    std::string respell(const Token& t, const CodeInfo& target) const;
    void update_state(const ast::BlockView& view, bool group01);
    void report_syntax_errors();

    // edits: edits and reports of a block
    static bool power_on(const dialects::Dialect& d, FunctionId f);
    static std::string detect_line_ending(std::string_view text);
    std::uint32_t line_of(std::uint32_t offset) const;
    std::string block_text(const ast::BlockView& view) const;
    void edit(std::uint32_t begin, std::uint32_t end, std::string text);
    void remove_token(std::uint32_t index);
    void report(ast::Range range, ReportKind kind, std::string construct, std::string reason);
    void report_token(const Token& t, ReportKind kind, std::string reason);
    Rewrite& rewrite(std::uint32_t token);
    void flush_rewrites();
    std::string letter_part(const Token& t) const;
    void flush_block();

    // facts: what is gathered before the pass: profiles, return levels, the dry run, power-on modes
    void prepare();
    void mark_profiles(const ast::Program& p);
    bool needs_return_level_pass() const;
    void scan_return_levels(const ast::Program& p);
    void prepare_run();
    static Options without_expand(Options o);
    static FunctionId power_on_of(const dialects::Dialect& d, std::initializer_list<FunctionId> family, FunctionId none);
    void power_on_differences();

    // distance: G90/G91 and U/W/H (dialects.md §3.2, §4), power-on modes
    void write_power_on(const ast::BlockView& view, std::span<const Token> tokens, bool lower);
    bool in_same_family(FunctionId f) const;
    bool data_follows_mode(const ast::BlockView& view) const;
    static bool distance_free(FunctionId f);
    bool dependent(const ast::BlockView& view) const;
    std::optional<std::uint32_t> read_axis_meanings(const ast::BlockView& view, std::uint32_t first, std::span<const Token> tokens);
    std::optional<bool> wanted_mode(const ast::BlockView& view, bool& to_mode_form) const;
    void convert_distance(std::uint32_t b, const ast::BlockView& view, std::uint32_t first, std::span<const Token> tokens,
                          bool lower);
    bool letters_exist() const;
    char target_letter(char axis) const;
    void write_axis(const AxisMeaning& a, bool letters_only);
    void rename_letter(const AxisMeaning& a, char letter);
    void map_mode_token(std::uint32_t token, bool incremental);
    void insert_mode(std::uint32_t first, std::span<const Token> tokens, bool incremental, bool lower);
    void insert_code(std::span<const Token> tokens, const CodeInfo& code_info, bool lower);
    void report_no_motion_mode(const ast::BlockView& view, bool group01, std::span<const Token> tokens, bool lower);
    void report_lost_axes(std::span<const Token> tokens);

    // parameters: words: readings, dwell units, drilling letters, direct drawing, G68, constructs
    void negate_rotation(const ast::BlockView& view);
    bool unconverted_motion() const;
    bool becomes_drawing(const Token& t);
    void convert_parameters(const ast::BlockView& view, std::uint32_t first, std::span<const Token> tokens);
    const CodeInfo* mapped(const CodeInfo& c) const;
    void check_taken(const Token& t);
    void rename_drill_letter(const Token& t, const CodeInfo& source, const CodeInfo& target);
    void rewrite_reading(const Token& t, WordUnit);
    void rewrite_dwell(const Token& t);
    void convert_comma_word(const Token& t);
    void convert_plain_drawing(const Token& t);
    bool repeats_construct(const ast::BlockView& view) const;
    void report_repeat(std::uint32_t b, const ast::BlockView& view, bool group01);

    // lexical: comments, block ends, the DIALECT header, program numbers, M98, Macro B
    CommentText target_comment(std::string_view text) const;
    void convert_comment(const Token& t);
    bool accepts(CommentForm form, std::string_view opener) const;
    void rename_header(const Token& t, std::string_view text);
    void convert_eob(const Token& t);
    void check_program_number(const Token& t);
    void convert_call(const ast::BlockView& view);
    void check_macro(const ast::BlockView& view, std::span<const Token> tokens);

    // local_system: G52 (semantics.md §2.4), B/C return levels into A (cycles.md §10)
    void convert_return_level(const ast::CodeRef& c);
    void convert_local_system(std::uint32_t b, const ast::BlockView& view, const ast::CodeRef& c, const CodeMapping& m);
    std::vector<std::pair<std::uint32_t, std::size_t>> local_words(const ast::BlockView& view) const;
    void convert_work_select(std::uint32_t b, const ast::BlockView& view);
    bool axes_in(const ast::BlockView& view) const;
    const BlockRun* local_run(std::uint32_t b, const Token& code);
    void write_cancel_code(const Token& code, const CodeInfo& cancel_code,
                           const std::vector<std::pair<std::uint32_t, std::size_t>>& words);
    void write_zero_g52(const Token& code, const CodeInfo& g52, const BlockRun& run);
    void write_g52_values(const Token& code, const CodeInfo& g52, const ast::CodeRef& c,
                          const std::vector<std::pair<std::uint32_t, std::size_t>>& words, const BlockRun& run, bool cancel);

    // expand.cpp: --expand (a construct replaced by the motion the dry run computes)
    bool try_expand(std::uint32_t b, const ast::BlockView& view);
};

}  // namespace kerf::converter::detail
