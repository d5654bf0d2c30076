// G52 between its two readings (semantics.md §2.4), from the dry run; B/C G98/G99 return levels into
// system A (cycles.md §10).
#include "converter/pass.hpp"

namespace kerf::converter::detail {

// B/C G98/G99 (return level) into system A.
void Converter::convert_return_level(const ast::CodeRef& c) {
    const Token& t = tree_.tokens[c.token];
    if (c.info->function == fn::return_initial_level) {
        remove_token(c.token);
        report_token(t, ReportKind::note,
                     fmt::format("removed: {} always returns to the initial level (cycles.md §10)", to_.id));
        return;
    }
    const auto it = return_level_.find(c.token);
    if (it == return_level_.end() || it->second.empty()) {
        remove_token(c.token);
        report_token(t, ReportKind::note,
                     fmt::format("removed: no drilling cycle under it has an R point off the initial level, so {}'s "
                                 "return to the initial level is the same motion (cycles.md §10)",
                                 to_.id));
        return;
    }
    report_token(t, ReportKind::unconverted,
                 fmt::format("{} (return to the R level) has no equivalent in {}: {}; left as it is{}", spelling(t),
                             to_.id, it->second, hazard(t.letter, c.key)));
}

// The axis words of a G52 block and the axis each moves.
std::vector<std::pair<std::uint32_t, std::size_t>> Converter::local_words(const ast::BlockView& view) const {
    std::vector<std::pair<std::uint32_t, std::size_t>> words;
    for (const std::uint32_t ti : view.words_with_role(Role::axis_absolute))
        if (const auto axis = interpreter::axis_of_letter(tree_.tokens[ti].letter)) words.push_back({ti, static_cast<std::size_t>(*axis)});
    return words;
}

// What the dry run says of the block, when it says one thing: a G52's value in the other reading
// depends on where the tool stands (semantics.md §2.4).
const BlockRun* Converter::local_run(std::uint32_t b, const Token& code) {
    const BlockRun* run = run_ ? run_->block(b) : nullptr;
    if (!run) {
        report_token(code, ReportKind::unconverted,
                     fmt::format("the {} value depends on where the tool stands, and the dry run never reached this "
                                 "block: left as it is (semantics.md §2.4)",
                                 to_.id));
        return nullptr;
    }
    if (run->varies) {
        report_token(code, ReportKind::unconverted,
                     fmt::format("this G52 runs more than once from different points, so no one {} G52 says the same: "
                                 "left as it is (semantics.md §2.4)",
                                 to_.id));
        return nullptr;
    }
    return run;
}

void Converter::convert_local_system(std::uint32_t b, const ast::BlockView& view, const ast::CodeRef& c, const CodeMapping& m) {
    const Token& code = tree_.tokens[c.token];
    if (rf_.g52 == rt_.g52 && m.action == CodeAction::local_system) {
        if (m.target->key != c.info->key) replace_token(code, respell(code, *m.target));
        return;
    }
    const BlockRun* run = local_run(b, code);
    if (!run) return;
    bool cancel = true;
    for (std::size_t a = 0; a < run->local_after.size(); ++a) cancel = cancel && std::fabs(run->local_after[a]) < 1e-9;
    const auto words = local_words(view);
    const CodeInfo* cancel_code = codes_.target_code(fn::local_system_cancel);
    if (cancel && cancel_code && rt_.g52 == LocalSystem::current_point_g152) write_cancel_code(code, *cancel_code, words);
    else if (m.action == CodeAction::local_cancel) write_zero_g52(code, *m.target, *run);
    else write_g52_values(code, *m.target, c, words, *run, cancel);
}

// pcnc-mill: G152 cancels, and G52 X0 Y0 would not. "G52 X0 Y0" → "G152": the words after the
// code go with the blanks before them.
void Converter::write_cancel_code(const Token& code, const CodeInfo& cancel_code,
                                  const std::vector<std::pair<std::uint32_t, std::size_t>>& words) {
    replace_token(code, respell(code, cancel_code));
    const std::uint32_t code_index = token_index(code);
    bool contiguous = !words.empty();
    for (std::size_t k = 0; k < words.size(); ++k) contiguous = contiguous && words[k].first == code_index + 1 + k;
    if (contiguous) {
        const Token& last = tree_.tokens[words.back().first];
        edit(tree_.end(code), tree_.end(last), {});
        return;
    }
    for (const auto& [ti, axis] : words) remove_token(ti);
}

// G152 → G52 with zeros on the axes the shift had: a zero G52 cancels in both other readings.
void Converter::write_zero_g52(const Token& code, const CodeInfo& g52, const BlockRun& run) {
    std::string text = respell(code, g52);
    bool any = false;
    for (std::size_t a = 0; a < 3; ++a) {
        if (std::fabs(run.local_before[a]) < 1e-9 || !to_.lexical.is_axis(interpreter::kAxisLetters[a])) continue;
        text += fmt::format(" {}0", interpreter::kAxisLetters[a]);
        any = true;
    }
    if (!any) text += fmt::format(" {}0", to_.lexical.axes.empty() ? 'X' : to_.lexical.axes.front());
    replace_token(code, text);
}

// The values in the target's reading: the vector of the shift (FANUC), or where the tool stands in
// the new system (the current-point readings).
void Converter::write_g52_values(const Token& code, const CodeInfo& g52, const ast::CodeRef& c,
                                 const std::vector<std::pair<std::uint32_t, std::size_t>>& words, const BlockRun& run, bool cancel) {
    const int digits = rt_.increment_digits;
    const bool vector = rt_.g52 == LocalSystem::vector_shift;
    if (g52.key != c.info->key) replace_token(code, respell(code, g52));
    std::set<std::size_t> written;
    for (const auto& [ti, axis] : words) {
        Rewrite& r = rewrite(ti);
        r.value = format_value(vector ? run.local_after[axis] : (cancel ? 0.0 : run.after[axis]), digits);
        r.value_fixed = true;
        written.insert(axis);
    }
    // An axis whose shift changed without being written (an ADV400 zero G52 cancels them all).
    std::string extra;
    for (std::size_t a = 0; a < 3; ++a) {
        if (written.count(a) || std::fabs(run.local_after[a] - run.local_before[a]) < 1e-9) continue;
        extra += fmt::format(" {}{}", interpreter::kAxisLetters[a], format_value(vector ? run.local_after[a] : run.after[a], digits));
    }
    if (!extra.empty()) edit(tree_.end(code), tree_.end(code), extra);
    if (rt_.g52 != LocalSystem::current_point || cancel) return;
    bool zeros = true;
    for (const auto& [ti, axis] : words) zeros = zeros && std::fabs(run.after[axis]) < 0.5 * std::pow(10.0, -digits);
    if (zeros)
        report_token(code, ReportKind::unconverted,
                     fmt::format("the tool stands at the new origin, and a G52 of zeros cancels in {}: left as the "
                                 "values say (semantics.md §2.4)",
                                 to_.id));
}

// G54–G59 with a local system in force: pcnc-mill's selection cancels it, FANUC's and ADV400's keep
// it (semantics.md §2.4). Into a reading that keeps it, a zero G52 goes on a line before the block;
// into one that cancels it, a G52 after the block puts it back (the current point takes where the
// tool stands in it), unless the block also moves: then it moves in the shifted system in one
// reading and not the other, which one block cannot say (reported).
void Converter::convert_work_select(std::uint32_t b, const ast::BlockView& view) {
    const BlockRun* run = run_ ? run_->block(b) : nullptr;
    if (!run) return;   // never ran: no local system to worry about there
    std::string axes;
    for (std::size_t a = 0; a < 3; ++a)
        if (std::fabs(run->local_before[a]) > 1e-9 && to_.lexical.is_axis(interpreter::kAxisLetters[a])) axes += interpreter::kAxisLetters[a];
    if (axes.empty()) return;
    const CodeInfo* g52 = codes_.target_code(to_.codes_with_function(fn::local_system_shift).empty() ? fn::local_system_current_point
                                                                                                     : fn::local_system_shift);
    if (!g52) return;
    const ast::Range range = view.range();
    if (rf_.g54_cancels_g52) {
        std::string line = g52->spelling;
        for (const char a : axes) line += fmt::format(" {}0", a);
        edit(range.begin, range.begin, line + line_ending_);
        report(range, ReportKind::note,
               block_text(view), fmt::format("{} selecting a work system cancels the local system, {} not: a zero {} "
                                             "before it (semantics.md §2.4)", from_.id, to_.id, g52->spelling));
        return;
    }
    if (!axes_in(view)) {
        std::string line = line_ending_ + g52->spelling;
        for (const char a : axes) {
            const auto i = static_cast<std::size_t>(a - 'X');
            line += fmt::format(" {}{}", a, format_value(run->after[i], rt_.increment_digits));
        }
        std::uint32_t end = range.end;
        while (end > range.begin && (tree_.text[end - 1] == '\n' || tree_.text[end - 1] == '\r')) --end;
        edit(end, end, line);
        report(range, ReportKind::note, block_text(view),
               fmt::format("{} keeps the local system over a work-system selection, {} cancels it: a {} after the "
                           "block puts it back (semantics.md §2.4)",
                           from_.id, to_.id, g52->spelling));
        return;
    }
    report(range, ReportKind::unconverted, block_text(view),
           fmt::format("this block selects a work system and moves with a local system in force: {} keeps it, {} "
                       "cancels it first (semantics.md §2.4); left as it is",
                       from_.id, to_.id));
}

bool Converter::axes_in(const ast::BlockView& view) const {
    for (const Token& t : view.tokens())
        if (t.kind == TokenKind::word && is_axis_role(t.role())) return true;
    return false;
}

}  // namespace kerf::converter::detail
