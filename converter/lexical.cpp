// What is read before meaning: comments and block ends (dialects/SCHEMA.md [lexical]), the
// DIALECT header, program numbers, the M98 forms (dialects.md §3.6), Custom Macro B.
#include "converter/pass.hpp"

namespace kerf::converter::detail {

Converter::CommentText Converter::target_comment(std::string_view text) const {
    CommentText r;
    if (text.empty()) return r;
    std::string_view body;
    std::string_view opener;
    CommentForm form = CommentForm::paren;
    if (text.front() != '(') {
        for (const std::string& l : from_.lexical.line_comments)
            if (text.substr(0, l.size()) == l && l.size() > opener.size()) opener = text.substr(0, l.size());
        if (opener.empty() && text.front() == ';') opener = text.substr(0, 1);
        form = opener == ";" && from_.lexical.semicolon == dialects::SemicolonRole::comment ? CommentForm::semicolon
                                                                                            : CommentForm::line;
        body = text.substr(opener.size());
    }
    if (accepts(form, opener)) return r;
    // A ( ) comment into a target without ( ), or no ( ) in the target for a line comment.
    if (form == CommentForm::paren || !to_.lexical.paren_comments) {
        r.impossible = true;
        return r;
    }
    std::string inner(body);
    r.parens_replaced = inner.find_first_of("()") != std::string::npos;
    std::replace(inner.begin(), inner.end(), '(', '[');
    std::replace(inner.begin(), inner.end(), ')', ']');
    // A line comment runs to the end of the line, blanks included; ( ) needs none of them.
    while (!inner.empty() && (inner.back() == ' ' || inner.back() == '\t')) inner.pop_back();
    std::string out = "(";
    out.append(inner);
    out += ')';
    r.text = std::move(out);
    return r;
}

void Converter::convert_comment(const Token& t) {
    const std::string_view text = spelling(t);
    if (!header_done_) rename_header(t, text);
    const CommentText c = target_comment(text);
    if (c.impossible) {
        report_token(t, ReportKind::unconverted, fmt::format("{} reads no comment of this form", to_.id));
        return;
    }
    if (!c.text) return;
    replace_token(t, *c.text);
    if (c.parens_replaced)
        report_token(t, ReportKind::note,
                     fmt::format("( ) inside the comment became [ ]: {} comments cannot nest (dialects.md §2)", to_.id));
}

bool Converter::accepts(CommentForm form, std::string_view opener) const {
    switch (form) {
    case CommentForm::paren: return to_.lexical.paren_comments;
    case CommentForm::semicolon: return to_.lexical.semicolon == dialects::SemicolonRole::comment;
    case CommentForm::line:
        return std::find(to_.lexical.line_comments.begin(), to_.lexical.line_comments.end(), opener) !=
               to_.lexical.line_comments.end();
    }
    return false;
}

// `(DIALECT: fanuc-lathe-a)` before the first word names the target (reference/README.md).
void Converter::rename_header(const Token& t, std::string_view text) {
    const std::size_t at = text.find("DIALECT:");
    if (at == std::string_view::npos) return;
    std::size_t begin = at + 8;
    while (begin < text.size() && text[begin] == ' ') ++begin;
    std::size_t end = begin;
    while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '-' || text[end] == '+'))
        ++end;
    if (end == begin || text.substr(begin, end - begin) == to_.id) return;
    edit(t.begin + static_cast<std::uint32_t>(begin), t.begin + static_cast<std::uint32_t>(end), to_.id);
}

// ';' ends a block in FANUC and starts a comment in pcnc-mill (dialects.md §8): where the target
// reads it as a comment, a ';' that ends a line goes, one followed by more blocks becomes a line break.
void Converter::convert_eob(const Token& t) {
    if (to_.lexical.semicolon != dialects::SemicolonRole::comment) return;
    const std::string_view text = tree_.text;
    std::uint32_t after = tree_.end(t);
    while (after < text.size() && (text[after] == ' ' || text[after] == '\t')) ++after;
    const bool line_end = after >= text.size() || text[after] == '\n' || text[after] == '\r';
    replace_token(t, line_end ? std::string() : line_ending_);
}

void Converter::check_program_number(const Token& t) {
    const int digits = to_.lexical.program_digits;
    if (digits <= 0 || !t.is_number()) return;
    const double v = tree_.number_value(t);
    // Only what the source holds and the target does not: a number too wide for both is the
    // program's own matter.
    const int source = from_.lexical.program_digits;
    if (source > 0 && v >= std::pow(10.0, source)) return;
    if (v >= std::pow(10.0, digits))
        report_token(t, ReportKind::unconverted,
                     fmt::format("{} program numbers have {} digits at most (dialects.md §2)", to_.id, digits));
}

void Converter::convert_call(const ast::BlockView& view) {
    bool calls = false;
    for (const ast::CodeRef& c : m_) calls = calls || (c.info && c.info->function == fn::subprogram_call);
    if (!calls) return;
    const auto call = view.subprogram_call();
    if (!call) return;
    const dialects::SubprogramCall form = to_.lexical.subprogram_call;
    const Token& p = tree_.tokens[call->p_token];
    const auto l = view.word('L');
    const int digits = to_.lexical.program_digits > 0 ? to_.lexical.program_digits : 4;
    const std::int64_t limit = static_cast<std::int64_t>(std::pow(10.0, digits));
    if (form == dialects::SubprogramCall::p_l) {
        if (!call->packed) return;
        replace_token(p, letter_part(p) + fmt::format("{}", call->program));
        // Compact blocks ("M98P41001") stay compact.
        const std::string gap = p.begin > 0 && (tree_.text[p.begin - 1] == ' ' || tree_.text[p.begin - 1] == '\t') ? " " : "";
        edit(tree_.end(p), tree_.end(p),
             fmt::format("{}{}{}", gap, p.has(ast::token_flags::lower_case) ? 'l' : 'L', call->repeats));
        return;
    }
    if (form == dialects::SubprogramCall::packed || (form == dialects::SubprogramCall::both && l && !call->packed && call->repeats > 1)) {
        if (call->packed || !l) {
            if (call->program >= limit)
                report_token(p, ReportKind::unconverted,
                             fmt::format("program {} does not fit the {} digits of {}'s M98 P", call->program, digits, to_.id));
            return;
        }
        if (call->program >= limit || call->repeats > 9999) {
            report_token(p, ReportKind::unconverted,
                         fmt::format("M98 P{} L{} does not fit {}'s packed M98 P (program of {} digits, repeats up to "
                                     "9999; dialects.md §3.6)",
                                     call->program, call->repeats, to_.id, digits));
            return;
        }
        if (form == dialects::SubprogramCall::both) return;   // both forms read: keep P L
        replace_token(p, letter_part(p) + fmt::format("{}{:0{}}", call->repeats > 1 ? fmt::format("{}", call->repeats) : "",
                                                        call->program, call->repeats > 1 ? digits : 1));
        remove_token(*l);
    }
}

// Custom Macro B (dialects.md §3.7) in a target without it.
void Converter::check_macro(const ast::BlockView& view, std::span<const Token> tokens) {
    if (to_.lexical.macro_b || !from_.lexical.macro_b) return;
    for (const Token& t : tokens) {
        if (t.kind == TokenKind::statement || (t.kind == TokenKind::word && t.has(ast::token_flags::value_expr))) {
            report(view.range(), ReportKind::unconverted, block_text(view),
                   fmt::format("{} has no Custom Macro B (#variables, expressions, IF/WHILE/GOTO)", to_.id));
            return;
        }
    }
}

}  // namespace kerf::converter::detail
