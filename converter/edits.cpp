// The edits of one block (collected, sorted, appended in text order), the rewrites of a word
// (its letter and its value, one edit), the reports.
#include "converter/pass.hpp"

namespace kerf::converter::detail {

bool Converter::power_on(const dialects::Dialect& d, FunctionId f) {
    for (const CodeInfo* c : d.codes_with_function(f))
        if (c->power_on_default) return true;
    return false;
}

std::string Converter::detect_line_ending(std::string_view text) {
    const std::size_t n = text.find_first_of("\r\n");
    if (n == std::string_view::npos) return "\n";
    if (text[n] == '\r') return n + 1 < text.size() && text[n + 1] == '\n' ? "\r\n" : "\r";
    return "\n";
}

std::uint32_t Converter::line_of(std::uint32_t offset) const {
    if (offset < line_at_) line_at_ = 0, line_ = 1;
    line_ += static_cast<std::uint32_t>(std::count(tree_.text.begin() + line_at_, tree_.text.begin() + offset, '\n'));
    line_at_ = offset;
    return line_;
}

// A block's text for a report: without its line break.
std::string Converter::block_text(const ast::BlockView& view) const {
    std::string_view s = tree_.slice(view.range());
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return std::string(s);
}

void Converter::edit(std::uint32_t begin, std::uint32_t end, std::string text) {
    pending_.push_back({begin, end, order_++, std::move(text)});
}

// Removes a token with the blanks after it (before it when it is the last on its line), so that
// inserting "G91 " and removing it again give back the same bytes.
void Converter::remove_token(std::uint32_t index) {
    const Token& t = tree_.tokens[index];
    std::uint32_t begin = t.begin, end = tree_.end(t);
    const std::string_view text = tree_.text;
    std::uint32_t after = end;
    while (after < text.size() && (text[after] == ' ' || text[after] == '\t')) ++after;
    const bool last = after >= text.size() || text[after] == '\n' || text[after] == '\r' || text[after] == ';';
    if (!last) end = after;
    else
        while (begin > 0 && (text[begin - 1] == ' ' || text[begin - 1] == '\t')) --begin;
    // Not back into a removal before it ("G52 X0 Y0" losing both words).
    for (const Pending& p : pending_)
        if (p.end > begin && p.end <= t.begin) begin = p.end;
    edit(begin, end, {});
}

void Converter::report(ast::Range range, ReportKind kind, std::string construct, std::string reason) {
    out_.reports.push_back({range, kind, std::move(construct), std::move(reason)});
}

void Converter::report_token(const Token& t, ReportKind kind, std::string reason) {
    report(tree_.range(t), kind, std::string(spelling(t)), std::move(reason));
}

Converter::Rewrite& Converter::rewrite(std::uint32_t token) {
    for (Rewrite& r : rewrites_)
        if (r.token == token) return r;
    Rewrite r;
    r.token = token;
    rewrites_.push_back(std::move(r));
    return rewrites_.back();
}

// The address letter and the value of a word, each as the rewrite says or as written.
void Converter::flush_rewrites() {
    for (const Rewrite& r : rewrites_) {
        const Token& t = tree_.tokens[r.token];
        const char letter = r.letter && t.has(ast::token_flags::lower_case) ? static_cast<char>(std::tolower(r.letter)) : r.letter;
        if (!r.value) {
            if (letter && letter != spelling(t).front()) edit(t.begin, t.begin + 1, std::string(1, letter));
            continue;
        }
        std::string head = letter_part(t);
        if (letter) head[0] = letter;
        replace_token(t, head + *r.value);
    }
    rewrites_.clear();
}

std::string Converter::letter_part(const Token& t) const {
    const std::string_view s = spelling(t);
    return std::string(s.substr(0, s.size() - tree_.value_spelling(t).size()));
}

void Converter::flush_block() {
    flush_rewrites();
    std::sort(pending_.begin(), pending_.end(), [](const Pending& a, const Pending& b) {
        if (a.begin != b.begin) return a.begin < b.begin;
        const bool ai = a.begin == a.end, bi = b.begin == b.end;
        if (ai != bi) return ai;   // an insertion before a replacement at the same place
        return a.order < b.order;
    });
    std::uint32_t at = 0;
    for (const Pending& p : pending_) {
        if (p.begin < at) continue;   // overlapping: the first edit of a place wins
        out_.edits.replace({p.begin, p.end}, p.text);
        at = p.end;
    }
    pending_.clear();
}

}  // namespace kerf::converter::detail
