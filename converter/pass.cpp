// The block loop: each block in text order, its codes mapped by function id (codes.hpp), the
// modal state the other steps read.
#include "converter/pass.hpp"

namespace kerf::converter::detail {

Converter::Converter(const ast::TypedFile& file, const dialects::Dialect& to, const Options& options)
    : file_(file), tree_(file.tree()), from_(file.dialect()), to_(to), options_(options),
      rf_(options.from.value_or(reading_of(from_))), rt_(options.to.value_or(reading_of(to))), codes_(from_, to) {
    src_modes_ = !from_.codes_with_function(fn::incremental_programming).empty();
    tgt_abs_code_ = codes_.target_code(fn::absolute_programming);
    tgt_inc_code_ = codes_.target_code(fn::incremental_programming);
    can_cycle_ = has_canned_cycles(to_);
    power_on_differences();
    tgt_modes_ = !to_.codes_with_function(fn::incremental_programming).empty();
    src_power_incremental_ = power_on(from_, fn::incremental_programming);
    tgt_power_incremental_ = power_on(to_, fn::incremental_programming);
    lengths_differ_ = rf_.calculator_decimal != rt_.calculator_decimal || rf_.increment_digits != rt_.increment_digits;
    line_ending_ = detect_line_ending(tree_.text);
    for (const auto& [letter, axis] : from_.lexical.incremental_letters)
        if (letter >= 'A' && letter <= 'Z') src_incremental_axis_[static_cast<std::size_t>(letter - 'A')] = axis;
    for (const auto& [letter, axis] : to_.lexical.incremental_letters)
        if (letter >= 'A' && letter <= 'Z') tgt_incremental_axis_[static_cast<std::size_t>(letter - 'A')] = axis;
}

Conversion Converter::run() {
    // A lathe program says nothing a mill dialect can say by meaning (axes, diameters, cycles).
    if (from_.machine != to_.machine) {
        const char* kinds[] = {"lathe", "mill"};
        report({0, 0}, ReportKind::unconverted, from_.id,
               fmt::format("a {} program: {} is a dialect for {}s; nothing was converted", kinds[static_cast<int>(from_.machine)],
                           to_.id, kinds[static_cast<int>(to_.machine)]));
        return std::move(out_);
    }
    prepare();
    for (std::size_t b = 0; b < tree_.block_count(); ++b) convert_block(b);
    report_syntax_errors();
    std::stable_sort(out_.reports.begin(), out_.reports.end(),
                     [](const Report& a, const Report& b) { return a.range.begin < b.range.begin; });
    return std::move(out_);
}

// "in fanuc-lathe-a, G99 is Feed per revolution": the danger of leaving a code as it is.
std::string Converter::hazard(char letter, std::optional<dialects::CodeKey> key) const {
    if (!key) return {};
    const CodeInfo* there = to_.code(letter, *key);
    if (!there) return {};
    return fmt::format(" (in {}, {} is {}: the output reads it so until you edit it)", to_.id, there->spelling, there->en);
}

// The power-on modes matter in the file's first program, the one a control starts: the others
// are subprograms and run in their caller's modes.
void Converter::reset_program_state(std::size_t b) {
    const auto& programs = file_.programs();
    in_first_program_ = programs.empty() || b < programs.front().end_block;
    power_on_pending_ = in_first_program_;
    src_incremental_ = src_power_incremental_;
    tgt_incremental_ = tgt_power_incremental_;
    motion_ = nullptr;
    feed_per_rev_ = power_on(from_, fn::feed_per_revolution);
    inch_ = power_on(from_, fn::inch_input);
    plane_ = from_.machine == dialects::MachineKind::lathe ? dialects::PlaneTrait::zx : dialects::PlaneTrait::xy;
    for (const CodeInfo& c : from_.codes())
        if (c.power_on_default && c.plane() != dialects::PlaneTrait::none) plane_ = c.plane();
    compensating_ = transformed_ = false;
    seen_motion_ = false;
}

void Converter::convert_block(std::size_t b) {
    const ast::Block& block = tree_.blocks[b];
    if (block.kind == ast::BlockKind::program_start || b == 0) reset_program_state(b);
    if (block.kind == ast::BlockKind::tail || block.kind == ast::BlockKind::blank || block.kind == ast::BlockKind::percent) return;
    const ast::BlockView view = file_.block(b);
    const auto tokens = view.tokens();
    const std::uint32_t first = view.first_token();
    for (std::uint32_t i = 0; i < tokens.size(); ++i) {
        const Token& t = tokens[i];
        if (t.kind == TokenKind::comment) convert_comment(t);
        else if (t.kind == TokenKind::eob) convert_eob(t);
        else if (t.kind == TokenKind::word && t.role() != Role::none) header_done_ = true;
        if (t.kind == TokenKind::word && t.role() == Role::program) check_program_number(t);
    }
    if (block.kind == ast::BlockKind::code || block.kind == ast::BlockKind::program_start) {
        header_done_ = true;
        if (expandable_.count(static_cast<std::uint32_t>(b)) && try_expand(static_cast<std::uint32_t>(b), view)) {
            flush_block();
            return;
        }
        convert_code_block(static_cast<std::uint32_t>(b), view, first, tokens);
    }
    flush_block();
}

void Converter::convert_code_block(std::uint32_t b, const ast::BlockView& view, std::uint32_t first, std::span<const Token> tokens) {
    view.collect_codes(g_, m_);
    infos_.clear();
    for (const ast::CodeRef& c : g_) infos_.push_back(c.info);
    for (const ast::CodeRef& c : m_) infos_.push_back(c.info);
    const bool lower = !tokens.empty() && tokens.front().has(ast::token_flags::lower_case);

    bool group01 = false;
    for (const ast::CodeRef& c : g_) {
        if (c.info && (c.info->has(dialects::traits::motion_group) || (c.info->has(dialects::traits::cycle) && c.info->modal)))
            group01 = true;
        convert_code(b, view, c);
    }
    for (const ast::CodeRef& c : m_) convert_code(b, view, c);
    write_power_on(view, tokens, lower);
    report_no_motion_mode(view, group01, tokens, lower);
    report_lost_axes(tokens);
    convert_distance(b, view, first, tokens, lower);
    // G20/G21 act before the block's words are read (semantics.md §1.2): the increments of G20 X100.
    for (const ast::CodeRef& c : g_) {
        if (c.info && c.info->function == fn::inch_input) inch_ = true;
        if (c.info && c.info->function == fn::metric_input) inch_ = false;
    }
    convert_parameters(view, first, tokens);
    convert_call(view);
    check_macro(view, tokens);
    report_repeat(b, view, group01);
    update_state(view, group01);
}

void Converter::convert_code(std::uint32_t b, const ast::BlockView& view, const ast::CodeRef& c) {
    const Token& t = tree_.tokens[c.token];
    if (!c.info) {
        // A code the source does not know reads alike where the target does not know it either
        // (a machine builder's M code): a note. Where the target has the number, it is a hazard.
        if (!c.key) {
            report_token(t, ReportKind::unconverted, "a computed code cannot be converted by meaning: left as it is");
        } else if (to_.code(t.letter, *c.key)) {
            report_token(t, ReportKind::unconverted,
                         fmt::format("not a code of {}: left as it is{}", from_.id, hazard(t.letter, c.key)));
        } else {
            report_token(t, ReportKind::note, fmt::format("a code of neither {} nor {}: left as it is", from_.id, to_.id));
        }
        return;
    }
    const CodeMapping& m = codes_(*c.info);
    if (c.info->work_coordinate() != 0 && rf_.g54_cancels_g52 != rt_.g54_cancels_g52) convert_work_select(b, view);
    switch (m.action) {
    case CodeAction::keep: return;
    case CodeAction::rename:
    case CodeAction::rotation_sign:
        if (m.target->key != c.info->key) replace_token(t, respell(t, *m.target));
        if (m.action == CodeAction::rotation_sign) negate_rotation(view);
        return;
    case CodeAction::local_system:
    case CodeAction::local_cancel: convert_local_system(b, view, c, m); return;
    case CodeAction::distance_mode: return;   // convert_distance
    case CodeAction::return_level: convert_return_level(c); return;
    case CodeAction::none: break;
    }
    if (c.info->function == fn::canned_cycle_cancel && !can_cycle_) {
        remove_token(c.token);
        report_token(t, ReportKind::note,
                     fmt::format("removed: {} has no canned cycles, so there is none to cancel", to_.id));
        return;
    }
    report_token(t, ReportKind::unconverted,
                 fmt::format("{} ({}) has no equivalent in {}: left as it is{}", spelling(t), c.info->function,
                             to_.id, hazard(t.letter, c.key)));
    if (moves(*c.info)) expandable_candidates_.insert(b);
}

bool Converter::has_canned_cycles(const dialects::Dialect& d) {
    return std::any_of(d.codes().begin(), d.codes().end(), [](const CodeInfo& c) { return is_drilling_cycle(c.function); });
}

bool Converter::moves(const CodeInfo& c) {
    return c.has(dialects::traits::cycle) || c.has(dialects::traits::motion_group) || c.function == fn::reference_return ||
           c.function == fn::reference_return_nth || c.function == fn::return_from_reference ||
           c.function == fn::dwell || c.has(dialects::traits::arc_approach) || c.function == fn::axis_homing;
}

std::string Converter::respell(const Token& t, const CodeInfo& target) const {
    const char letter = t.has(ast::token_flags::lower_case) ? static_cast<char>(std::tolower(t.letter)) : t.letter;
    std::string spelled(1, letter);
    spelled.append(tree_.value_spelling(t));
    return respell_code(spelled, target);
}

void Converter::update_state(const ast::BlockView& view, bool group01) {
    // A '/' block is skipped with the block-delete switch on, as the dry run (and --verify) runs it:
    // its motion code is not the mode of the blocks after it (`/G00 Z50.` then `X1.` moves in the
    // power-on mode, which the target must be told: fuzz_converter).
    const bool deleted = view.block().has(ast::block_flags::deleted);
    for (const ast::CodeRef& c : g_) {
        if (!c.info) continue;
        const CodeInfo& i = *c.info;
        // The modal motion: a group-01 code, or a drilling cycle of its own group (until G80 or
        // a group-01 code cancels it, cycles.md §10, §11).
        const bool modal_cycle = i.has(dialects::traits::cycle) && i.modal;
        if (!deleted && (i.has(dialects::traits::motion_group) || modal_cycle || i.function == fn::canned_cycle_cancel)) {
            motion_ = i.function == fn::canned_cycle_cancel ? nullptr : &i;
            seen_motion_ = true;
            motion_at_ = tree_.tokens[c.token].begin;
        }
        if (i.function == fn::feed_per_minute) feed_per_rev_ = false;
        if (i.function == fn::feed_per_revolution) feed_per_rev_ = true;
        if (i.plane() != dialects::PlaneTrait::none) plane_ = i.plane();
        if (i.has(dialects::traits::radius_comp)) compensating_ = i.has(dialects::traits::radius_comp_on);
        if (i.has(dialects::traits::program_transform) || i.has(dialects::traits::plane_transform) ||
            i.function == fn::coordinate_rotation || i.function == fn::coordinate_rotation_cw)
            transformed_ = true;
        if (i.function == fn::coordinate_rotation_cancel) transformed_ = false;
    }
    (void)view;
    (void)group01;
}

void Converter::report_syntax_errors() {
    for (const ast::Diagnostic& d : tree_.diagnostics) {
        if (d.severity != ast::Severity::error) continue;
        report(d.range, ReportKind::syntax_error, std::string(tree_.slice(d.range)),
               fmt::format("{} [{}]: left as it is", d.message, d.code));
    }
}

}  // namespace kerf::converter::detail
