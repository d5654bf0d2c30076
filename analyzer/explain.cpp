#include "analyzer/explain.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "analyzer/output.hpp"

namespace kerf::analyzer {

namespace {

std::string upper(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

// "K1002", "S0101", "M0115", "F0001": a letter and four digits.
bool looks_like_id(std::string_view q, std::string_view letters) {
    return q.size() == 5 && letters.find(q[0]) != std::string_view::npos &&
           std::all_of(q.begin() + 1, q.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
}

// "G71", "M3", "G12.1": a G or M and a number.
bool looks_like_code(std::string_view q) {
    if (q.size() < 2 || (q[0] != 'G' && q[0] != 'M')) return false;
    return std::all_of(q.begin() + 1, q.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.'; });
}

// Two dialects read a code alike when what explain shows of it is the same.
bool same_reading(const CodeExplanation& a, const CodeExplanation& b) {
    return a.spelling == b.spelling && a.aliases == b.aliases && a.title == b.title && a.group == b.group &&
           a.power_on_default == b.power_on_default && a.function == b.function && a.words == b.words &&
           a.required == b.required && a.required_one_of == b.required_one_of && a.availability == b.availability &&
           a.availability_note == b.availability_note && a.notes == b.notes && a.reference == b.reference;
}

Explanation code_in_dialects(const ExplainRequest& r, const std::string& code, const dialects::Registry& registry) {
    Explanation e;
    std::vector<std::string> ids = registry.ids();
    if (!r.dialect.empty()) {
        if (!registry.find(r.dialect)) {
            e.kind = Explanation::Kind::unknown_dialect;
            e.message = fmt::format("unknown dialect '{}'; `kerf dialects` lists them", r.dialect);
            return e;
        }
        ids = {r.dialect};
    }
    for (const std::string& id : ids) {
        const dialects::Dialect& d = *registry.find(id);
        const dialects::CodeInfo* info = d.code(code);
        if (!info) continue;
        CodeExplanation c = explain_code(d, *info, r.lang);
        const auto same = std::find_if(e.codes.begin(), e.codes.end(), [&](const CodeExplanation& x) { return same_reading(x, c); });
        if (same != e.codes.end()) same->dialects.push_back(id);
        else e.codes.push_back(std::move(c));
    }
    if (!e.codes.empty()) {
        e.kind = Explanation::Kind::code;
        return e;
    }
    e.kind = Explanation::Kind::no_such_code;
    e.message = r.dialect.empty()
                    ? fmt::format("{} is not a code of any dialect (`kerf dialects` lists them; a control raises alarm 010 "
                                  "for a code it does not have)", code)
                    : fmt::format("{} is not a code of {} (alarm 010 on the control)", code, r.dialect);
    return e;
}

void add_block(std::string& out, const char* label, const std::vector<std::string>& items, const char* sep) {
    if (items.empty()) return;
    std::string joined;
    for (const std::string& s : items) joined += (joined.empty() ? "" : sep) + s;
    out += fmt::format("  {}: {}\n", label, joined);
}

}  // namespace

const char* availability_text(dialects::Availability a) {
    switch (a) {
        case dialects::Availability::standard: return "standard";
        case dialects::Availability::optional: return "optional";
        case dialects::Availability::not_fitted: return "not fitted";
        case dialects::Availability::machine_specific: return "machine-specific";
        case dialects::Availability::unlisted: return "not in the seed table";
    }
    return "?";
}

CodeExplanation explain_code(const dialects::Dialect& dialect, const dialects::CodeInfo& code, Language lang) {
    CodeExplanation c;
    c.dialects = {dialect.id};
    c.spelling = code.spelling;
    c.aliases = code.aliases;
    c.title = lang == Language::ru ? code.ru : code.en;
    c.letter = code.letter;
    if (code.letter == 'G') c.group = code.group;
    c.one_shot = code.letter == 'G' && code.group == "00";
    c.power_on_default = code.power_on_default;
    c.function = code.function;
    c.function_meaning = code.function.def().meaning;
    c.words = code.words;
    c.required = code.required;
    c.required_one_of = code.required_one_of;
    c.availability = code.availability;
    c.availability_note = code.availability_note;
    c.notes = code.notes;
    c.reference = code.reference;
    return c;
}

Explanation explain(const ExplainRequest& request, const dialects::Registry& dialects, const Registry& rules) {
    Explanation e;
    const std::string q = upper(request.query);
    if (const Rule* rule = rules.find(request.query); rule || (rule = rules.find(q))) {   // K1001 or its name
        e.kind = Explanation::Kind::rule;
        e.rule = rule;
        return e;
    }
    if (looks_like_id(q, "K")) {
        e.kind = Explanation::Kind::no_such_rule;
        e.message = fmt::format("{} is not a rule of kerf check (`kerf check --list-rules` lists them, docs/rules.md "
                                "documents them)", q);
        return e;
    }
    if (looks_like_id(q, "SF") || (looks_like_id(q, "M") && q[1] == '0')) {   // M0115: a diagnostic, M115 a code
        if (const Rule* rule = rules.for_diagnostic(q)) {
            e.kind = Explanation::Kind::rule;
            e.rule = rule;
            e.diagnostic = q;
            return e;
        }
        if (q[0] != 'M') {
            e.kind = Explanation::Kind::no_such_rule;
            e.message = fmt::format("{} is not a diagnostic of kerf (docs/diagnostics.md lists them)", q);
            return e;
        }
    }
    if (looks_like_code(q)) return code_in_dialects(request, q, dialects);
    e.kind = Explanation::Kind::not_understood;
    e.message = fmt::format("'{}' is neither a G/M code (G71, M98, G12.1) nor a rule (K1001, address-without-value)",
                            request.query);
    return e;
}

std::string format_code(const CodeExplanation& c, Language lang) {
    const bool ru = lang == Language::ru;
    std::string out = fmt::format("{} — {}\n", c.spelling, c.title);
    add_block(out, ru ? "также" : "also written", c.aliases, ", ");
    add_block(out, c.dialects.size() > 1 ? (ru ? "диалекты" : "dialects") : (ru ? "диалект" : "dialect"), c.dialects, ", ");
    if (c.letter == 'G') {
        out += fmt::format("  {}: {}{}\n", ru ? "группа" : "group", c.group,
                           c.one_shot ? (ru ? " (однократный)" : " (one-shot)") : (ru ? " (модальный)" : " (modal)"));
        if (c.power_on_default) out += ru ? "  активен при включении и сбросе\n" : "  active at power-on and reset\n";
    }
    out += fmt::format("  {}: {}\n", ru ? "функция" : "function", c.function);
    add_block(out, ru ? "адреса" : "words", c.words, " ");
    add_block(out, ru ? "обязательные" : "required", c.required, " ");
    for (const std::vector<std::string>& alternatives : c.required_one_of)
        add_block(out, ru ? "одно из" : "one of", alternatives, " ");
    out += fmt::format("  {}: {}{}\n", ru ? "наличие" : "availability", availability_text(c.availability),
                       c.availability_note.empty() ? "" : " — " + c.availability_note);
    if (!c.notes.empty()) out += fmt::format("  {}: {}\n", ru ? "примечания" : "notes", c.notes);
    out += fmt::format("  {}: {}\n", ru ? "источник" : "reference", c.reference);
    return out;
}

std::string format_explanation(const Explanation& e, Language lang) {
    switch (e.kind) {
        case Explanation::Kind::rule:
            return (e.diagnostic.empty() ? std::string() : fmt::format("{} is reported by kerf check as {}\n", e.diagnostic, e.rule->id)) +
                   format_rule_docs(*e.rule);
        case Explanation::Kind::code: {
            std::string out;
            for (const CodeExplanation& c : e.codes) out += (out.empty() ? "" : "\n") + format_code(c, lang);
            return out;
        }
        default: return "kerf: " + e.message + "\n";
    }
}

}  // namespace kerf::analyzer
