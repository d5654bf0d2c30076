// What the words of a block read as (words.hpp): integer lengths, dwell units, drilling letters,
// direct drawing, the G68 angle; the words a construct leaves as they are.
#include "converter/pass.hpp"

namespace kerf::converter::detail {

// G68 R: + = CCW (FANUC) ↔ + = CW (ADV400), gcode-tables.md §8.10: the angle changes sign.
void Converter::negate_rotation(const ast::BlockView& view) {
    const auto r = view.word('R');
    if (!r) return;
    const Token& t = tree_.tokens[*r];
    const auto d = t.is_number() ? parse_decimal(tree_.value_spelling(t)) : std::nullopt;
    if (!d) {
        report_token(t, ReportKind::unconverted, "a G68 angle written as an expression cannot change sign here");
        return;
    }
    rewrite(*r).value = d->point ? with_point(negated(*d)) : plain(negated(*d));
}

// A block whose motion code the target lacks is a construct left as it is, words and all.
bool Converter::unconverted_motion() const {
    for (const CodeInfo* c : infos_)
        if (c && moves(*c) && codes_(*c).action == CodeAction::none) return true;
    return false;
}

void Converter::convert_parameters(const ast::BlockView& view, std::uint32_t first, std::span<const Token> tokens) {
    if (unconverted_motion() || repeats_construct(view)) return;
    const CodeInfo* drill = nullptr;
    bool cycle = false;   // only a cycle's words can be missing from the target's code
    for (const CodeInfo* c : infos_) {
        if (c && is_drilling_cycle(c->function)) drill = c;
        cycle = cycle || (c && c->has(dialects::traits::cycle));
    }
    const CodeInfo* drill_target = drill ? mapped(*drill) : nullptr;
    // What a parameter reads as matters only where the two readings differ (most pairs: never).
    const bool units = lengths_differ_ || rf_.dwell_p_seconds != rt_.dwell_p_seconds;
    for (std::uint32_t i = 0; i < tokens.size(); ++i) {
        const Token& t = tokens[i];
        if (t.kind == TokenKind::comma_word) {
            convert_comma_word(t);
            if (t.letter != 'A') rewrite_reading(t, WordUnit::length);   // ,C ,R: lengths; ,A an angle
            continue;
        }
        if (t.kind != TokenKind::word || t.has(ast::token_flags::value_none)) continue;
        const Role r = t.role();
        if (r == Role::direct_drawing) {
            convert_plain_drawing(t);
            if (t.letter == 'R') rewrite_reading(t, WordUnit::length);   // executor_drawing.cpp: a corner radius
            continue;
        }
        if (is_axis_role(r)) {
            if (lengths_differ_) rewrite_reading(t, WordUnit::length);
            continue;
        }
        if (r != Role::parameter) continue;
        if (becomes_drawing(t)) continue;
        const std::size_t reports = out_.reports.size();
        if (drill && drill_target) rename_drill_letter(t, *drill, *drill_target);
        else if (cycle) check_taken(t);
        if (out_.reports.size() != reports || !units) continue;   // reported: left as written
        const WordUnit unit = parameter_unit(t.letter, infos_);
        if (unit == WordUnit::length) rewrite_reading(t, unit);
        if (unit == WordUnit::dwell) rewrite_dwell(t);
    }
    (void)view;
    (void)first;
}

const CodeInfo* Converter::mapped(const CodeInfo& c) const {
    const CodeMapping& m = codes_(c);
    return m.action == CodeAction::none || m.action == CodeAction::return_level ? nullptr : m.target ? m.target : &c;
}

// A word the target's code of the same function does not take (ADV400 G84 Q, the dwell at
// the R level): reported, left as it is.
void Converter::check_taken(const Token& t) {
    if (t.letter == 'F' || t.letter == 'S' || t.letter == 'T' || t.letter == 'M') return;
    const std::string letter(1, t.letter);
    for (const CodeInfo* c : infos_) {
        if (!c || !c->has(dialects::traits::cycle) || !c->takes_word(letter)) continue;
        const CodeInfo* target = mapped(*c);
        if (target && !target->words.empty() && !target->takes_word(letter))
            report_token(t, ReportKind::unconverted,
                         fmt::format("{} {} has no {} word ({} of {}): left as it is", to_.id, target->spelling,
                                     t.letter, t.letter, c->spelling));
    }
}

void Converter::rename_drill_letter(const Token& t, const CodeInfo& source, const CodeInfo& target) {
    const DrillLetters s = drill_letters(source), d = drill_letters(target);
    char to = 0;
    if (t.letter == s.peck && s.peck) to = d.peck;
    else if (t.letter == s.repeat && s.repeat) to = d.repeat;
    else {
        check_taken(t);
        return;
    }
    if (!to) {
        report_token(t, ReportKind::unconverted,
                     fmt::format("{} {} has no {} word: left as it is", to_.id, target.spelling,
                                 t.letter == s.peck ? "peck" : "repeat-count"));
        return;
    }
    if (to != t.letter) rewrite(token_index(t)).letter = to;
}

// dialects.md §2 "Numbers", §11.9: an integer length is least increments without calculator
// input; the target gets the value its machine reads the same (a point makes it mm in both).
void Converter::rewrite_reading(const Token& t, WordUnit) {
    if (!lengths_differ_ || !t.is_number() || t.has(ast::token_flags::has_point)) return;
    auto d = parse_decimal(tree_.value_spelling(t));
    if (!d) return;
    // The source's increment (interpreter/executor_words.cpp increment()): one more digit under
    // inch input, but for a rotary axis (degrees).
    const bool rotary = rf_.rotary.find(t.letter) != std::string::npos;
    if (!rf_.calculator_decimal) d = shifted(*d, -(rf_.increment_digits + (inch_ && !rotary ? 1 : 0)));
    Rewrite& r = rewrite(token_index(t));
    if (!r.value_fixed) r.value = with_point(*d);
}

// semantics.md §8.2: G04 P in ms (FANUC) or s (ADV400), and a drilling cycle's dwell P.
void Converter::rewrite_dwell(const Token& t) {
    if (rf_.dwell_p_seconds == rt_.dwell_p_seconds) return;
    const auto d = t.is_number() ? parse_decimal(tree_.value_spelling(t)) : std::nullopt;
    if (!d) {
        report_token(t, ReportKind::unconverted, "a dwell written as an expression cannot change unit here (semantics.md §8.2)");
        return;
    }
    const Decimal v = shifted(*d, rf_.dwell_p_seconds ? 3 : -3);
    rewrite(token_index(t)).value = plain(v);
    if (!rt_.dwell_p_seconds && plain(v).find('.') != std::string::npos)
        report_token(t, ReportKind::note,
                     fmt::format("{} ms has a fraction: a FANUC P takes whole milliseconds (semantics.md §8.2)", plain(v)));
}

// ,A ,C ,R direct drawing (dialects.md §2): only where the target has comma words.
void Converter::convert_comma_word(const Token& t) {
    if (to_.lexical.is_comma_word(t.letter)) return;
    report_token(t, ReportKind::unconverted, fmt::format("{} has no ,{} direct-drawing word (dialects.md §2)", to_.id, t.letter));
}

// SPINNER plain A/R in G01 blocks (dialects.md §11.4): the target's comma form.
void Converter::convert_plain_drawing(const Token& t) {
    if (to_.lexical.plain_direct_drawing) return;
    if (!to_.lexical.is_comma_word(t.letter)) {
        report_token(t, ReportKind::unconverted,
                     fmt::format("{} has no ,{} direct-drawing word (dialects.md §2, §11.4)", to_.id, t.letter));
        return;
    }
    edit(t.begin, t.begin, ",");
}

// A block with axis words and no group-01 code repeats the modal cycle (cycles.md §8, §10).
bool Converter::repeats_construct(const ast::BlockView& view) const {
    if (!motion_ || codes_(*motion_).action != CodeAction::none) return false;
    for (const CodeInfo* c : infos_)
        if (c && (c->has(dialects::traits::motion_group) || (c->has(dialects::traits::cycle) && c->modal))) return false;
    for (const Token& t : view.tokens())
        if (t.kind == TokenKind::word && is_axis_role(t.role())) return true;
    return false;
}

void Converter::report_repeat(std::uint32_t b, const ast::BlockView& view, bool group01) {
    if (group01 || !repeats_construct(view)) return;
    report(view.range(), ReportKind::unconverted, block_text(view),
           fmt::format("repeats {} of line {}, which has no equivalent in {}", motion_->spelling, line_of(motion_at_), to_.id));
    expandable_candidates_.insert(b);
}

// A plain A or R in a linear block means a direct-drawing angle or corner radius to a SPINNER
// target (dialects.md §11.4) and not to a source without that rule: reported, left as it is.
bool Converter::becomes_drawing(const Token& t) {
    if (!to_.lexical.plain_direct_drawing || from_.lexical.plain_direct_drawing || (t.letter != 'A' && t.letter != 'R')) return false;
    bool linear = motion_ && motion_->function == fn::linear;
    for (const CodeInfo* c : infos_) {
        if (!c || !c->has(dialects::traits::motion_group)) continue;
        linear = c->function == fn::linear;
    }
    if (!linear || (t.letter == 'A' && to_.lexical.is_axis('A'))) return false;
    report_token(t, ReportKind::unconverted,
                 fmt::format("a plain {} in a G01 block is a direct-drawing {} in {} (dialects.md §11.4) and not in {}: "
                             "left as it is",
                             t.letter, t.letter == 'A' ? "angle" : "corner radius", to_.id, from_.id));
    return true;
}

}  // namespace kerf::converter::detail
