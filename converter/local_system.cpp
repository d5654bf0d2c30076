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
                 fmt::format("{} (return to the R level) has no equivalent in {}: {}; left as it is{}", c.info->spelling,
                             to_.id, it->second, hazard(t.letter, c.key)));
}

void Converter::convert_local_system(std::uint32_t b, const ast::BlockView& view, const ast::CodeRef& c, const CodeMapping& m) {
    const Token& code = tree_.tokens[c.token];
    const bool differs = rf_.g52 != rt_.g52;
    if (!differs && m.action == CodeAction::local_system) {
        if (m.target->key != c.info->key) replace_token(code, respell(code, *m.target));
        return;
    }
    const BlockRun* run = run_ ? run_->block(b) : nullptr;
    if (!run) {
        report_token(code, ReportKind::unconverted,
                     fmt::format("the {} value depends on where the tool stands, and the dry run never reached this "
                                 "block: left as it is (semantics.md §2.4)",
                                 to_.id));
        return;
    }
    if (run->varies) {
        report_token(code, ReportKind::unconverted,
                     fmt::format("this G52 runs more than once from different points, so no one {} G52 says the same: "
                                 "left as it is (semantics.md §2.4)",
                                 to_.id));
        return;
    }
    const int digits = rt_.increment_digits;
    bool cancel = true;
    for (std::size_t a = 0; a < run->local_after.size(); ++a) cancel = cancel && std::fabs(run->local_after[a]) < 1e-9;
    // The axis words of the block and where they stand.
    std::vector<std::pair<std::uint32_t, std::size_t>> words;   // token, axis index
    for (const std::uint32_t ti : view.words_with_role(Role::axis_absolute)) {
        const auto axis = interpreter::axis_of_letter(tree_.tokens[ti].letter);
        if (axis) words.push_back({ti, static_cast<std::size_t>(*axis)});
    }
    const CodeInfo* cancel_code = codes_.target_code(fn::local_system_cancel);
    if (cancel && cancel_code && rt_.g52 == LocalSystem::current_point_g152) {
        // pcnc-mill: G152 cancels, and G52 X0 Y0 would not.
        replace_token(code, respell(code, *cancel_code));
        // "G52 X0 Y0" → "G152": the words after the code go with the blanks before them.
        const std::uint32_t code_index = token_index(code);
        bool contiguous = !words.empty();
        for (std::size_t k = 0; k < words.size(); ++k) contiguous = contiguous && words[k].first == code_index + 1 + k;
        if (contiguous) {
            const Token& last = tree_.tokens[words.back().first];
            edit(code.begin + code.length, last.begin + last.length, {});
        } else {
            for (const auto& [ti, axis] : words) remove_token(ti);
        }
        return;
    }
    const CodeInfo* g52 = m.target;
    if (m.action == CodeAction::local_cancel) {
        // G152 → G52 with zeros on the axes the shift had (a zero G52 cancels in both other readings).
        std::string text = respell(code, *g52);
        bool any = false;
        for (std::size_t a = 0; a < 3; ++a) {
            if (std::fabs(run->local_before[a]) < 1e-9 || !to_.lexical.is_axis(interpreter::kAxisLetters[a])) continue;
            text += fmt::format(" {}0", interpreter::kAxisLetters[a]);
            any = true;
        }
        if (!any) text += fmt::format(" {}0", to_.lexical.axes.empty() ? 'X' : to_.lexical.axes.front());
        replace_token(code, text);
        return;
    }
    if (g52->key != c.info->key) replace_token(code, respell(code, *g52));
    std::set<std::size_t> written;
    for (const auto& [ti, axis] : words) {
        const Token& t = tree_.tokens[ti];
        const double value = rt_.g52 == LocalSystem::vector_shift ? run->local_after[axis] : (cancel ? 0.0 : run->after[axis]);
        Rewrite& r = rewrite(ti);
        r.value = format_value(value, digits);
        r.value_fixed = true;
        written.insert(axis);
        (void)t;
    }
    // An axis whose shift changed without being written (an ADV400 zero G52 cancels them all).
    std::string extra;
    for (std::size_t a = 0; a < 3; ++a) {
        if (written.count(a) || std::fabs(run->local_after[a] - run->local_before[a]) < 1e-9) continue;
        const double value = rt_.g52 == LocalSystem::vector_shift ? run->local_after[a] : run->after[a];
        extra += fmt::format(" {}{}", interpreter::kAxisLetters[a], format_value(value, digits));
    }
    if (!extra.empty()) edit(code.begin + code.length, code.begin + code.length, extra);
    if (rt_.g52 == LocalSystem::current_point && !cancel) {
        bool zeros = true;
        for (const auto& [ti, axis] : words) zeros = zeros && std::fabs(run->after[axis]) < 0.5 * std::pow(10.0, -digits);
        if (zeros)
            report_token(code, ReportKind::unconverted,
                         fmt::format("the tool stands at the new origin, and a G52 of zeros cancels in {}: left as the "
                                     "values say (semantics.md §2.4)",
                                     to_.id));
    }
}

}  // namespace kerf::converter::detail
