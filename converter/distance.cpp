// Absolute and incremental (dialects.md §3.2, §4; gcode-tables.md §1.1): U/W/H in system A, G90/G91
// in B, C and the controls; the target mode written only where it changes; the power-on modes.
#include "converter/pass.hpp"

namespace kerf::converter::detail {

// The first code block of a program states the source's power-on modes the target lacks.
void Converter::write_power_on(const ast::BlockView& view, std::span<const Token> tokens, bool lower) {
    if (!power_on_pending_ || view.block().kind != ast::BlockKind::code) return;
    power_on_pending_ = false;
    for (const std::string& f : power_on_missing_)
        report(view.range(), ReportKind::unconverted, block_text(view),
               fmt::format("{} starts in {} mode and {} has no code for it (dialects.md §3.8)", from_.id, f, to_.id));
    for (const CodeInfo* code : power_on_codes_)
        if (!in_same_family(code->function)) insert_code(tokens, *code, lower);
}

// A block that sets a mode of the same family (G94 where G95 would go): it states it already.
bool Converter::in_same_family(FunctionId f) const {
    const std::initializer_list<FunctionId> families[] = {
        {fn::feed_per_minute, fn::feed_per_revolution}, {fn::metric_input, fn::inch_input},
        {fn::plane_xy, fn::plane_zx, fn::plane_yz},      {fn::return_initial_level, fn::return_r_level},
        {fn::css_off, fn::css_on},                         {fn::rapid, fn::linear, fn::circular_cw, fn::circular_ccw},
    };
    for (const auto& family : families) {
        if (std::find(family.begin(), family.end(), f) == family.end()) continue;
        for (const CodeInfo* c : infos_)
            if (c && std::find(family.begin(), family.end(), c->function) != family.end()) return true;
        if (f == fn::rapid || f == fn::linear)
            for (const CodeInfo* c : infos_)
                if (c && c->has(dialects::traits::motion_group)) return true;
    }
    return false;
}

// G10 L2 (work offsets) adds its axis words under G91; the lathe's G10 P (work shift, tool
// offsets) takes only its own U/W as increments (interpreter/executor_data_input.cpp).
bool Converter::data_follows_mode(const ast::BlockView& view) const {
    bool data_input = false;
    for (const CodeInfo* c : infos_)
        if (c && c->function == fn::programmable_data_input) data_input = true;
    if (!data_input) return false;
    const auto l = view.word('L');
    return l && tree_.tokens[*l].is_number() && tree_.number_value(tree_.tokens[*l]) == 2;
}

// Codes whose blocks read the same in G90 and G91: their words are no positions (a dwell, a
// feed or speed mode, a plane, units, a mode that only switches something on or off).
bool Converter::distance_free(FunctionId f) {
    static constexpr FunctionId kFree[] = {
        fn::dwell, fn::feed_per_minute, fn::feed_per_revolution, fn::css_on, fn::css_off, fn::plane_xy, fn::plane_zx,
        fn::plane_yz, fn::inch_input, fn::metric_input, fn::canned_cycle_cancel, fn::return_initial_level,
        fn::return_r_level, fn::modal_macro_call_cancel, fn::stroke_check_off, fn::tool_length_comp_cancel,
        fn::exact_stop_check, fn::exact_stop_mode, fn::continuous_cutting_mode};
    return std::find(std::begin(kFree), std::end(kFree), f) != std::end(kFree);
}

bool Converter::dependent(const ast::BlockView& view) const {
    for (const ast::CodeRef& c : g_) {
        if (!c.info || distance_free(c.info->function)) {
            if (!c.info) return true;
            continue;
        }
        // G50/G92 S alone is the spindle clamp: no position in it (semantics.md §4.1).
        if (c.info->function == fn::coordinate_system_setting && axes_.empty()) continue;
        return true;
    }
    for (const ast::CodeRef& c : m_) {
        if (!c.info) continue;
        const FunctionId f = c.info->function;
        if (f == fn::subprogram_call || f == fn::subprogram_return || f == fn::program_end || f == fn::program_end_rewind ||
            c.info->has(dialects::traits::takes_arguments) || c.info->has(dialects::traits::cycle))
            return true;
    }
    (void)view;
    return false;
}

// The source's mode of this block (its own G90/G91, the last wins, else the modal one), and the
// axis words with what they mean: which axis, incremental or not, written with a U/W/H letter.
std::optional<std::uint32_t> Converter::read_axis_meanings(const ast::BlockView& view, std::uint32_t first,
                                                          std::span<const Token> tokens) {
    std::optional<std::uint32_t> mode_token;
    for (const ast::CodeRef& c : g_) {
        if (!c.info) continue;
        if (c.info->function == fn::absolute_programming) src_incremental_ = false, mode_token = c.token;
        if (c.info->function == fn::incremental_programming) src_incremental_ = true, mode_token = c.token;
    }
    const bool data_mode = data_follows_mode(view);
    axes_.clear();
    for (std::uint32_t i = 0; i < tokens.size(); ++i) {
        const Token& t = tokens[i];
        if (t.kind != TokenKind::word || t.has(ast::token_flags::value_none)) continue;
        const Role r = t.role();
        const char inc_axis = incremental_axis(src_incremental_axis_, t.letter);
        if (r == Role::axis_incremental) {
            axes_.push_back({first + i, inc_axis, true, true});
        } else if (r == Role::axis_absolute || (r == Role::parameter && data_mode && (from_.lexical.is_axis(t.letter) || inc_axis))) {
            if (inc_axis) axes_.push_back({first + i, inc_axis, true, true});
            else axes_.push_back({first + i, t.letter, src_modes_ && src_incremental_, false});
        }
    }
    if (unconverted_motion() || repeats_construct(view)) axes_.clear();   // a construct: its words stay
    return mode_token;
}

// The target mode the block needs (nullopt: either reads the same), and whether its U/W/H become
// G91 X/Z/C (`to_mode_form`).
std::optional<bool> Converter::wanted_mode(const ast::BlockView& view, bool& to_mode_form) const {
    const bool src_effective = src_modes_ && src_incremental_;
    to_mode_form = false;
    if (axes_.empty()) return dependent(view) ? std::optional<bool>(src_effective) : std::nullopt;
    bool any_inc = false, all_inc = true, any_mode_form = false;
    for (const AxisMeaning& a : axes_) {
        any_inc = any_inc || a.incremental;
        all_inc = all_inc && a.incremental;
        any_mode_form = any_mode_form || (a.incremental && !a.letter_form);
    }
    const bool letters_must_go = (!src_modes_ && options_.incremental == IncrementalStyle::g91) || !letters_exist();
    if (!any_inc) return false;
    if (all_inc && (letters_must_go || any_mode_form)) {
        to_mode_form = letters_must_go;   // G91 X/Z (a source's own G91 words stay as they are)
        return true;
    }
    if (!all_inc) return false;   // mixed: the increments stay letters, the rest reads absolute
    return dependent(view) ? std::optional<bool>(src_effective) : std::nullopt;   // letters read alike in either mode
}

void Converter::convert_distance(std::uint32_t b, const ast::BlockView& view, std::uint32_t first, std::span<const Token> tokens,
                                 bool lower) {
    const std::optional<std::uint32_t> mode_token = read_axis_meanings(view, first, tokens);
    if (!tgt_modes_) {   // system A: no G90/G91, increments are letters
        for (const ast::CodeRef& c : g_)
            if (c.info && codes_(*c.info).action == CodeAction::distance_mode) remove_token(c.token);
        for (const AxisMeaning& a : axes_) write_axis(a, true);
        return;
    }
    if (flags_[b] & kProfile) {   // read in the cycle block's mode: its increments stay letters
        for (const AxisMeaning& a : axes_) write_axis(a, true);
        const bool src_effective = src_modes_ && src_incremental_;
        if (mode_token) map_mode_token(*mode_token, src_incremental_);
        // A profile block also runs in sequence: a G91 written for an earlier block must not make
        // its absolute words increments (fuzz_converter, regressions/converter/).
        else if (tgt_incremental_ != src_effective && (!axes_.empty() || dependent(view)))
            insert_mode(first, tokens, src_effective, lower);
        else return;
        tgt_incremental_ = src_effective;
        return;
    }
    bool to_mode_form = false;
    const std::optional<bool> want = wanted_mode(view, to_mode_form);
    for (const AxisMeaning& a : axes_) {
        if (to_mode_form && a.letter_form) rename_letter(a, a.axis);
        else write_axis(a, false);
    }
    if (!want) {
        if (mode_token) {
            map_mode_token(*mode_token, src_incremental_);
            tgt_incremental_ = src_incremental_;
        }
        return;
    }
    if (mode_token) map_mode_token(*mode_token, *want);
    else if (tgt_incremental_ != *want) insert_mode(first, tokens, *want, lower);
    tgt_incremental_ = *want;
}

bool Converter::letters_exist() const {
    for (const AxisMeaning& a : axes_)
        if (a.letter_form && !target_letter(a.axis)) return false;
    return true;
}

char Converter::target_letter(char axis) const {
    for (const auto& [letter, moved] : to_.lexical.incremental_letters)
        if (moved == axis) return letter;
    return 0;
}

// An axis word as the target writes it where its increments must be letters (system A, a
// profile, a mixed block): absolute words stay, increments take the target's letter.
void Converter::write_axis(const AxisMeaning& a, bool letters_only) {
    const Token& t = tree_.tokens[a.token];
    if (!a.incremental) return;
    if (a.letter_form && incremental_axis(tgt_incremental_axis_, t.letter) == a.axis) return;   // U stays U
    if (!a.letter_form && !letters_only) return;   // G91 X stays X under G91
    const char letter = target_letter(a.axis);
    if (!letter) {
        report_token(t, ReportKind::unconverted,
                     fmt::format("an incremental {} move here needs an incremental address, and {} has none for {} "
                                 "(dialects.md §3.2, §4)",
                                 a.axis, to_.id, a.axis));
        return;
    }
    rename_letter(a, letter);
}

void Converter::rename_letter(const AxisMeaning& a, char letter) {
    if (tree_.tokens[a.token].letter != letter) rewrite(a.token).letter = letter;
}

void Converter::map_mode_token(std::uint32_t token, bool incremental) {
    const Token& t = tree_.tokens[token];
    const CodeInfo* target = incremental ? tgt_inc_code_ : tgt_abs_code_;
    if (!target) return;
    const auto key = dialects::code_key(tree_.number_value(t));
    if (key && *key == target->key) return;
    replace_token(t, respell(t, *target));
}

void Converter::insert_mode(std::uint32_t first, std::span<const Token> tokens, bool incremental, bool lower) {
    const CodeInfo* target = incremental ? tgt_inc_code_ : tgt_abs_code_;
    if (!target) return;
    insert_code(tokens, *target, lower);
    (void)first;
}

void Converter::insert_code(std::span<const Token> tokens, const CodeInfo& code_info, bool lower) {
    const CodeInfo* target = &code_info;
    // Before the first word after N (and after a block delete).
    std::uint32_t at = 0;
    for (; at < tokens.size(); ++at) {
        const Token& t = tokens[at];
        if ((t.kind == TokenKind::word && t.role() != Role::sequence) || t.kind == TokenKind::statement) break;
    }
    if (at == tokens.size()) return;
    const Token& t = tokens[at];
    const bool compact = at > 0 && tree_.end(tokens[at - 1]) == t.begin &&
                         tokens[at - 1].kind == TokenKind::word;
    std::string code = target->spelling;
    if (lower) code[0] = static_cast<char>(std::tolower(code[0]));
    edit(t.begin, t.begin, compact ? code : code + " ");
}

// Axis words before any motion code: the source has no power-on motion mode and the target
// moves them at its own (G00): nothing says "do not move" there.
// An axis word of the source whose letter the target has no axis for (fanuc-mill's C into the
// three-axis pcnc-mill): the target reads the letter otherwise, or not at all, so the move is lost.
// Axis words one side has and the other has not: a move that would vanish, or a word the source
// ignores that the target would move by (fuzz_converter, regressions/converter/).
void Converter::report_lost_axes(std::span<const Token> tokens) {
    std::uint32_t parameters = 0;   // letters the block's codes take as their data
    for (const CodeInfo* c : infos_)
        if (c) parameters |= c->parameter_mask;
    for (const Token& t : tokens) {
        if (t.kind != TokenKind::word) continue;
        if (t.role() == Role::axis_absolute && !to_.lexical.is_axis(t.letter))
            report_token(t, ReportKind::unconverted,
                         fmt::format("{} is an axis of {}, and {} has no {} axis (its axes: {})", t.letter, from_.id, to_.id,
                                     t.letter, to_.lexical.axes));
        const bool data = t.letter >= 'A' && t.letter <= 'Z' && (parameters >> (t.letter - 'A') & 1u);
        if (t.role() == Role::parameter && !data && !from_.lexical.is_axis(t.letter) && to_.lexical.is_axis(t.letter))
            report_token(t, ReportKind::unconverted,
                         fmt::format("{} is no axis of {} (its axes: {}): the word moves nothing there, and {} would move "
                                     "its {} axis",
                                     t.letter, from_.id, from_.lexical.axes, to_.id, t.letter));
    }
}

void Converter::report_no_motion_mode(const ast::BlockView& view, bool group01, std::span<const Token> tokens, bool lower) {
    if (group01 || motion_ || seen_motion_ || !in_first_program_) return;
    bool axis = false;
    for (const Token& t : view.tokens()) axis = axis || (t.kind == TokenKind::word && is_axis_role(t.role()));
    if (!axis) return;
    if (power_on_motion_) {   // the source's power-on G00 the target does not start in
        insert_code(tokens, *power_on_motion_, lower);
        seen_motion_ = true;
        return;
    }
    if (source_moves_at_power_on_ || !target_moves_at_power_on_) return;
    for (const Token& t : view.tokens()) {
        if (t.kind != TokenKind::word || !is_axis_role(t.role())) continue;
        report(view.range(), ReportKind::unconverted, block_text(view),
               fmt::format("axis words before any motion code: {} has no power-on motion mode, {} moves them at its "
                           "own; write the motion code the program means",
                           from_.id, to_.id));
        return;
    }
}

}  // namespace kerf::converter::detail
