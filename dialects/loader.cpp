// Reads one dialect data file (dialects/SCHEMA.md) into a Dialect. Every problem is reported with
// its key path and TOML position; nothing is silently defaulted except keys the schema marks optional.
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include <toml++/toml.h>

#include "dialects/alarms.hpp"
#include "dialects/dialect.hpp"
#include "dialects/toml_errors.hpp"

namespace kerf::dialects {
namespace {

class Reader : public TomlErrors {
public:
    using TomlErrors::TomlErrors;

    void check_keys(const toml::table& t, std::initializer_list<std::string_view> allowed, std::string_view where) {
        TomlErrors::check_keys(t, allowed, where, "dialects/SCHEMA.md");
    }

    std::string string(const toml::table& t, std::string_view key, std::string_view where, bool required) {
        const toml::node* n = t.get(key);
        if (!n) {
            if (required) error(&t, fmt::format("{}: missing key '{}'", where, key));
            return {};
        }
        if (const auto v = n->value<std::string>()) return *v;
        error(n, fmt::format("{}.{}: expected a string", where, key));
        return {};
    }

    bool boolean(const toml::table& t, std::string_view key, std::string_view where, bool fallback,
                 bool required = false) {
        const toml::node* n = t.get(key);
        if (!n) {
            if (required) error(&t, fmt::format("{}: missing key '{}'", where, key));
            return fallback;
        }
        if (const auto v = n->value<bool>()) return *v;
        error(n, fmt::format("{}.{}: expected true or false", where, key));
        return fallback;
    }

    std::vector<std::string> strings(const toml::table& t, std::string_view key, std::string_view where) {
        std::vector<std::string> out;
        const toml::node* n = t.get(key);
        if (!n) return out;
        const toml::array* a = n->as_array();
        if (!a) {
            error(n, fmt::format("{}.{}: expected an array of strings", where, key));
            return out;
        }
        for (const toml::node& item : *a) {
            if (const auto v = item.value<std::string>())
                out.push_back(*v);
            else
                error(&item, fmt::format("{}.{}: expected strings only", where, key));
        }
        return out;
    }

    std::string letters(const toml::table& t, std::string_view key, std::string_view where) {
        std::string out;
        for (const std::string& s : strings(t, key, where)) {
            if (s.size() != 1) {
                error(t.get(key), fmt::format("{}.{}: '{}' is not one letter", where, key, s));
                continue;
            }
            out += s[0];
        }
        return out;
    }

};

Availability parse_availability(Reader& r, const toml::table& t, std::string_view where) {
    const std::string s = r.string(t, "availability", where, false);
    if (s.empty() || s == "standard") return Availability::standard;
    if (s == "optional") return Availability::optional;
    if (s == "not-fitted") return Availability::not_fitted;
    if (s == "machine-specific") return Availability::machine_specific;
    if (s == "unlisted") return Availability::unlisted;
    r.error(t.get("availability"), fmt::format("{}.availability: unknown value '{}'", where, s));
    return Availability::standard;
}

// The `function` key: an id of the vocabulary (docs/functions.md), or a load error at the value.
FunctionId read_function(Reader& r, const toml::table& t, std::string_view where) {
    const std::string id = r.string(t, "function", where, true);
    if (id.empty()) return {};
    if (const std::optional<FunctionId> f = FunctionId::find(id)) return *f;
    const std::optional<std::string_view> near = closest_function_id(id);
    r.error(t.get("function"),
            fmt::format("{}.function: unknown function id '{}'{} (docs/functions.md lists the ids; a machine builder's "
                        "code kerf does not model is \"{}\")",
                        where, id, near ? fmt::format("; did you mean '{}'?", *near) : std::string(),
                        functions::machine_builder_code));
    return {};
}

// A [[g]]/[[m]] table, or with `partial` a [[patch]] table (only `code` required; letter 0: either).
std::optional<CodeInfo> read_code(Reader& r, const toml::table& t, char letter, const std::string& where,
                                  bool partial = false) {
    CodeInfo info;
    info.spelling = r.string(t, "code", where, true);
    const auto parsed = parse_code_spelling(info.spelling);
    if (!parsed || (parsed->first != 'G' && parsed->first != 'M') || (letter && parsed->first != letter)) {
        r.error(t.get("code"), fmt::format("{}.code: '{}' is not a {} code", where, info.spelling,
                                           letter ? std::string(1, letter) : std::string("G or M")));
        return std::nullopt;
    }
    letter = parsed->first;
    info.letter = letter;
    info.key = parsed->second;
    const std::string label = fmt::format("{} ({})", where, info.spelling);
    r.check_keys(t, {"code", "aliases", "group", "modal", "default", "function", "words", "parameter_words", "required", "required_one_of",
                     "availability", "availability_note", "en", "ru", "reference", "notes", "implied"},
                 label);
    info.aliases = r.strings(t, "aliases", label);
    for (const std::string& alias : info.aliases)
        if (!parse_code_spelling(alias)) r.error(t.get("aliases"), fmt::format("{}.aliases: bad code '{}'", label, alias));
    info.group = r.string(t, "group", label, letter == 'G' && !partial);
    info.modal = r.boolean(t, "modal", label, false, letter == 'G' && !partial);
    info.power_on_default = r.boolean(t, "default", label, false);
    if (!partial || t.contains("function")) info.function = read_function(r, t, label);
    info.words = r.strings(t, "words", label);
    for (const std::string& w : r.strings(t, "parameter_words", label)) {
        if (w.size() != 1) r.error(t.get("parameter_words"), fmt::format("{}.parameter_words: '{}' is not one letter", label, w));
        else info.parameter_letters += w;
    }
    info.required = r.strings(t, "required", label);
    if (const toml::node* n = t.get("required_one_of")) {
        if (const toml::array* outer = n->as_array()) {
            for (const toml::node& inner : *outer) {
                std::vector<std::string> alternatives;
                if (const toml::array* a = inner.as_array()) {
                    for (const toml::node& w : *a)
                        if (const auto v = w.value<std::string>()) alternatives.push_back(*v);
                } else {
                    r.error(&inner, fmt::format("{}.required_one_of: expected arrays of words", label));
                }
                if (!alternatives.empty()) info.required_one_of.push_back(std::move(alternatives));
            }
        } else {
            r.error(n, fmt::format("{}.required_one_of: expected an array of arrays", label));
        }
    }
    info.availability = parse_availability(r, t, label);
    info.availability_note = r.string(t, "availability_note", label, false);
    info.en = r.string(t, "en", label, !partial);
    info.ru = r.string(t, "ru", label, !partial);
    info.reference = r.string(t, "reference", label, !partial);
    info.notes = r.string(t, "notes", label, false);
    for (const std::string& w : r.strings(t, "implied", label)) {
        char* end = nullptr;
        const double v = w.size() > 1 ? std::strtod(w.c_str() + 1, &end) : 0;
        if (w.size() < 2 || w[0] < 'A' || w[0] > 'Z' || end != w.c_str() + w.size()) {
            r.error(t.get("implied"), fmt::format("{}.implied: '{}' is not a letter with a value (\"P1\")", label, w));
            continue;
        }
        info.implied.emplace_back(w[0], v);
    }
    return info;
}

// Reads [lexical]; `set` receives the keys present (overlays override only those).
LexicalRules read_lexical(Reader& r, const toml::table& t, LexicalRules rules, std::vector<std::string>& set) {
    const std::string where = "lexical";
    r.check_keys(t, {"semicolon", "paren_comments", "line_comments", "incremental_letters", "axes", "diameter_letters",
                     "comma_words", "plain_direct_drawing", "subprogram_call", "decimal_comma", "calculator_decimal",
                     "dwell_p_unit", "program_digits", "tool_word", "macro_b", "max_m_per_block", "label_search", "if_words"},
                 where);
    for (const auto& [key, node] : t) set.emplace_back(key.str());
    if (t.contains("semicolon")) {
        const std::string s = r.string(t, "semicolon", where, false);
        if (s == "end-of-block") rules.semicolon = SemicolonRole::end_of_block;
        else if (s == "comment") rules.semicolon = SemicolonRole::comment;
        else r.error(t.get("semicolon"), fmt::format("lexical.semicolon: unknown value '{}'", s));
    }
    rules.paren_comments = r.boolean(t, "paren_comments", where, rules.paren_comments);
    if (t.contains("line_comments")) rules.line_comments = r.strings(t, "line_comments", where);
    if (const toml::node* n = t.get("incremental_letters")) {
        rules.incremental_letters.clear();
        if (const toml::table* inc = n->as_table()) {
            for (const auto& [key, value] : *inc) {
                const auto axis = value.value<std::string>();
                if (key.str().size() != 1 || !axis || axis->size() != 1) {
                    r.error(&value, "lexical.incremental_letters: expected LETTER = \"AXIS\"");
                    continue;
                }
                rules.incremental_letters[key.str()[0]] = (*axis)[0];
            }
        } else {
            r.error(n, "lexical.incremental_letters: expected a table");
        }
    }
    if (t.contains("axes")) rules.axes = r.letters(t, "axes", where);
    if (t.contains("diameter_letters")) rules.diameter_letters = r.letters(t, "diameter_letters", where);
    if (t.contains("comma_words")) rules.comma_words = r.letters(t, "comma_words", where);
    rules.plain_direct_drawing = r.boolean(t, "plain_direct_drawing", where, rules.plain_direct_drawing);
    if (t.contains("subprogram_call")) {
        const std::string s = r.string(t, "subprogram_call", where, false);
        if (s == "packed") rules.subprogram_call = SubprogramCall::packed;
        else if (s == "p-l") rules.subprogram_call = SubprogramCall::p_l;
        else if (s == "both") rules.subprogram_call = SubprogramCall::both;
        else r.error(t.get("subprogram_call"), fmt::format("lexical.subprogram_call: unknown value '{}'", s));
    }
    if (t.contains("decimal_comma")) {
        const std::string s = r.string(t, "decimal_comma", where, false);
        if (s == "warn") rules.decimal_comma_lenient = true;
        else if (s == "reject") rules.decimal_comma_lenient = false;
        else r.error(t.get("decimal_comma"), fmt::format("lexical.decimal_comma: unknown value '{}'", s));
    }
    rules.calculator_decimal = r.boolean(t, "calculator_decimal", where, rules.calculator_decimal);
    if (t.contains("dwell_p_unit")) {
        const std::string s = r.string(t, "dwell_p_unit", where, false);
        if (s == "ms") rules.dwell_p_seconds = false;
        else if (s == "s") rules.dwell_p_seconds = true;
        else r.error(t.get("dwell_p_unit"), fmt::format("lexical.dwell_p_unit: unknown value '{}' (ms or s)", s));
    }
    if (const toml::node* n = t.get("program_digits")) {
        if (const auto v = n->value<std::int64_t>(); v && *v >= 0 && *v <= 9)
            rules.program_digits = static_cast<int>(*v);
        else
            r.error(n, "lexical.program_digits: expected an integer 0..9 (0: no fixed width)");
    }
    if (t.contains("tool_word")) {
        rules.tool_word = r.string(t, "tool_word", where, false);
        if (rules.tool_word != "mmnn" && rules.tool_word != "number")
            r.error(t.get("tool_word"), fmt::format("lexical.tool_word: unknown value '{}' (mmnn or number)", rules.tool_word));
    }
    rules.macro_b = r.boolean(t, "macro_b", where, rules.macro_b);
    rules.if_words = r.boolean(t, "if_words", where, rules.if_words);
    if (t.contains("label_search")) {
        const std::string s = r.string(t, "label_search", where, false);
        if (s == "from-top") rules.label_search = LabelSearch::from_top;
        else if (s == "forward") rules.label_search = LabelSearch::forward;
        else r.error(t.get("label_search"), fmt::format("lexical.label_search: unknown value '{}' (from-top or forward)", s));
    }
    if (const toml::node* n = t.get("max_m_per_block")) {
        if (const auto v = n->value<std::int64_t>(); v && *v >= 1 && *v <= 9)
            rules.max_m_per_block = static_cast<int>(*v);
        else
            r.error(n, "lexical.max_m_per_block: expected an integer 1..9");
    }
    return rules;
}

std::vector<CodeInfo> read_codes(Reader& r, const toml::table& root, char letter) {
    std::vector<CodeInfo> out;
    const char* key = letter == 'G' ? "g" : "m";
    const toml::node* n = root.get(key);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a) {
        r.error(n, fmt::format("'{}' must be an array of tables ([[{}]])", key, key));
        return out;
    }
    for (std::size_t i = 0; i < a->size(); ++i) {
        const toml::table* t = (*a)[i].as_table();
        if (!t) {
            r.error(&(*a)[i], fmt::format("{}[{}]: expected a table", key, i));
            continue;
        }
        if (auto info = read_code(r, *t, letter, fmt::format("{}[{}]", key, i))) out.push_back(std::move(*info));
    }
    return out;
}

// The array of tables under `key` (each item a table), or none; errors for anything else.
template <class F>
void each_table(Reader& r, const toml::table& t, std::string_view key, std::string_view where, F&& f) {
    const toml::node* n = t.get(key);
    if (!n) return;
    const toml::array* a = n->as_array();
    if (!a) {
        r.error(n, fmt::format("{}.{}: expected an array of tables", where, key));
        return;
    }
    for (std::size_t i = 0; i < a->size(); ++i) {
        if (const toml::table* item = (*a)[i].as_table())
            f(*item, fmt::format("{}.{}[{}]", where, key, i));
        else
            r.error(&(*a)[i], fmt::format("{}.{}[{}]: expected a table", where, key, i));
    }
}

// `remove = ["G32", ...]`: spellings with their positions.
void read_remove(Reader& r, const toml::table& root, DialectFile& file) {
    const toml::node* n = root.get("remove");
    if (!n) return;
    const toml::array* a = n->as_array();
    if (!a) {
        r.error(n, "remove: expected an array of code spellings");
        return;
    }
    for (const toml::node& item : *a) {
        const auto v = item.value<std::string>();
        if (!v || !parse_code_spelling(*v)) {
            r.error(&item, "remove: expected code spellings such as \"G50\"");
            continue;
        }
        file.remove.push_back({*v, {static_cast<int>(item.source().begin.line), static_cast<int>(item.source().begin.column)}});
    }
}

void read_patches(Reader& r, const toml::table& root, DialectFile& file) {
    each_table(r, root, "patch", "top level", [&](const toml::table& t, const std::string& where) {
        const auto info = read_code(r, t, 0, where, true);
        if (!info) return;
        CodePatch p;
        p.letter = info->letter;
        p.key = info->key;
        p.spelling = info->spelling;
        p.fields = *info;
        for (const auto& [key, node] : t)
            if (key.str() != "code") p.keys.emplace_back(key.str());
        p.line = static_cast<int>(t.source().begin.line);
        p.column = static_cast<int>(t.source().begin.column);
        file.patches.push_back(std::move(p));
    });
}

// One [detect] entry's weight and proves (both required).
bool read_weight(Reader& r, const toml::table& t, const std::string& where, DetectClue& c) {
    const toml::node* w = t.get("weight");
    const auto v = w ? w->value<std::int64_t>() : std::nullopt;
    if (!v || *v == 0 || *v < -50 || *v > 50) {
        r.error(w ? w : &t, fmt::format("{}.weight: expected an integer from -50 to 50, not 0", where));
        return false;
    }
    c.weight = static_cast<int>(*v);
    c.proves = r.string(t, "proves", where, true);
    c.line = static_cast<int>(t.source().begin.line);
    c.column = static_cast<int>(t.source().begin.column);
    return true;
}

std::string one_letter(Reader& r, const toml::table& t, std::string_view key, const std::string& where) {
    const std::string s = r.string(t, key, where, true);
    if (s.size() == 1 && s[0] >= 'A' && s[0] <= 'Z') return s;
    if (!s.empty()) r.error(t.get(key), fmt::format("{}.{}: '{}' is not one upper-case letter", where, key, s));
    return {};
}

// `with = ["S", "P0"]`: a letter, optionally with the value the word must have.
bool read_with(Reader& r, const toml::table& t, const std::string& where, DetectClue& c) {
    for (const std::string& w : r.strings(t, "with", where)) {
        if (w.empty() || w[0] < 'A' || w[0] > 'Z') {
            r.error(t.get("with"), fmt::format("{}.with: '{}' is not a letter with an optional value", where, w));
            return false;
        }
        std::optional<double> value;
        if (w.size() > 1) {
            char* end = nullptr;
            const double v = std::strtod(w.c_str() + 1, &end);
            if (end != w.c_str() + w.size()) {
                r.error(t.get("with"), fmt::format("{}.with: '{}' is not a letter with an optional value", where, w));
                return false;
            }
            value = v;
        }
        c.with.emplace_back(w[0], value);
    }
    return true;
}

std::string letters_text(std::string_view letters) {
    std::string out;
    for (const char L : letters) out += (out.empty() ? "" : "/") + std::string(1, L);
    return out;
}

void read_detect(Reader& r, const toml::table& root, DialectFile& file) {
    const toml::node* n = root.get("detect");
    if (!n) return;
    const toml::table* t = n->as_table();
    if (!t) {
        r.error(n, "detect: expected a table");
        return;
    }
    file.detect_set = true;
    DetectRules& rules = file.dialect.detect;
    r.check_keys(*t, {"default", "inherit", "codes", "words", "comments", "headers", "variables", "lexical", "lines"}, "detect");
    rules.fallback = r.boolean(*t, "default", "detect", false);
    file.detect_inherit = r.boolean(*t, "inherit", "detect", false);
    each_table(r, *t, "codes", "detect", [&](const toml::table& e, const std::string& where) {
        r.check_keys(e, {"code", "with", "with_any", "without", "weight", "proves"}, where);
        DetectClue c;
        c.kind = DetectClue::Kind::code;
        const std::string code = r.string(e, "code", where, true);
        const auto parsed = parse_code_spelling(code);
        if (!parsed || (parsed->first != 'G' && parsed->first != 'M')) {
            r.error(e.get("code"), fmt::format("{}.code: '{}' is not a G or M code", where, code));
            return;
        }
        c.letter = parsed->first;
        c.key = parsed->second;
        if (!read_with(r, e, where, c) || !read_weight(r, e, where, c)) return;
        c.with_any = r.letters(e, "with_any", where);
        c.without = r.letters(e, "without", where);
        c.spelling = code;
        for (const std::string& w : r.strings(e, "with", where)) c.spelling += " " + w;
        if (!c.with_any.empty()) c.spelling += " " + letters_text(c.with_any);
        if (!c.without.empty()) c.spelling += " without " + letters_text(c.without);
        rules.clues.push_back(std::move(c));
    });
    each_table(r, *t, "words", "detect", [&](const toml::table& e, const std::string& where) {
        r.check_keys(e, {"letter", "absent", "given", "weight", "proves"}, where);
        DetectClue c;
        const bool absent = e.contains("absent");
        if (absent == e.contains("letter")) {
            r.error(&e, fmt::format("{}: give either `letter` (the word is used) or `absent` (it never is)", where));
            return;
        }
        c.kind = absent ? DetectClue::Kind::absent_word : DetectClue::Kind::word;
        const std::string L = one_letter(r, e, absent ? "absent" : "letter", where);
        if (L.empty() || !read_weight(r, e, where, c)) return;
        c.letter = L[0];
        c.with_any = r.letters(e, "given", where);
        if (absent && c.with_any.empty()) {
            r.error(&e, fmt::format("{}: `absent` needs `given`, the letters the file must use (a file without "
                                    "words proves nothing)", where));
            return;
        }
        c.spelling = absent ? fmt::format("no {} word ({} used)", L, letters_text(c.with_any)) : "word " + L;
        rules.clues.push_back(std::move(c));
    });
    each_table(r, *t, "comments", "detect", [&](const toml::table& e, const std::string& where) {
        r.check_keys(e, {"prefix", "weight", "proves"}, where);
        DetectClue c;
        c.kind = DetectClue::Kind::comment;
        c.text = r.string(e, "prefix", where, true);
        if (c.text.empty() || !read_weight(r, e, where, c)) return;
        c.spelling = fmt::format("'{}' comment", c.text);
        rules.clues.push_back(std::move(c));
    });
    each_table(r, *t, "headers", "detect", [&](const toml::table& e, const std::string& where) {
        r.check_keys(e, {"contains", "weight", "proves"}, where);
        DetectClue c;
        c.kind = DetectClue::Kind::header;
        c.text = r.string(e, "contains", where, true);
        if (c.text.empty() || !read_weight(r, e, where, c)) return;
        c.spelling = fmt::format("header comment with \"{}\"", c.text);
        rules.clues.push_back(std::move(c));
    });
    each_table(r, *t, "variables", "detect", [&](const toml::table& e, const std::string& where) {
        r.check_keys(e, {"from", "to", "weight", "proves"}, where);
        DetectClue c;
        c.kind = DetectClue::Kind::variable;
        const auto from = e.get("from") ? e.get("from")->value<std::int64_t>() : std::nullopt;
        const auto to = e.get("to") ? e.get("to")->value<std::int64_t>() : std::nullopt;
        if (!from || !to || *from < 0 || *to < *from) {
            r.error(&e, fmt::format("{}: expected integers from <= to", where));
            return;
        }
        if (!read_weight(r, e, where, c)) return;
        c.from = *from;
        c.to = *to;
        c.spelling = fmt::format("#{}–#{}", *from, *to);
        rules.clues.push_back(std::move(c));
    });
    each_table(r, *t, "lexical", "detect", [&](const toml::table& e, const std::string& where) {
        r.check_keys(e, {"observe", "weight", "proves"}, where);
        DetectClue c;
        c.kind = DetectClue::Kind::lexical;
        c.text = r.string(e, "observe", where, true);
        if (c.text != "prose-after-semicolon") {
            r.error(e.get("observe"), fmt::format("{}.observe: unknown observation '{}' (prose-after-semicolon)", where, c.text));
            return;
        }
        if (!read_weight(r, e, where, c)) return;
        c.spelling = "text after ';' that reads as no block";
        rules.clues.push_back(std::move(c));
    });
    each_table(r, *t, "lines", "detect", [&](const toml::table& e, const std::string& where) {
        r.check_keys(e, {"starts_with", "contains", "weight", "proves"}, where);
        DetectClue c;
        c.kind = DetectClue::Kind::line;
        c.line_prefix = e.contains("starts_with");
        if (c.line_prefix == e.contains("contains")) {
            r.error(&e, fmt::format("{}: give either `starts_with` or `contains`", where));
            return;
        }
        c.text = r.string(e, c.line_prefix ? "starts_with" : "contains", where, true);
        if (c.text.empty() || !read_weight(r, e, where, c)) return;
        c.spelling = fmt::format("a line {} '{}'", c.line_prefix ? "starting with" : "with", c.text);
        rules.clues.push_back(std::move(c));
    });
}

// [[variables]]: ranges of macro variables the dialect defines (the Haas NGC #10000 ranges).
void read_variables(Reader& r, const toml::table& root, DialectFile& file) {
    file.variables_set = root.contains("variables");
    each_table(r, root, "variables", "top level", [&](const toml::table& e, const std::string& where) {
        r.check_keys(e, {"from", "to", "kind", "alias_of", "first_set", "stride", "axes", "read_only", "units", "en", "ru", "reference"}, where);
        VariableRange v;
        const auto integer = [&](std::string_view key) -> std::optional<std::int64_t> {
            const toml::node* n = e.get(key);
            return n ? n->value<std::int64_t>() : std::nullopt;
        };
        const auto from = integer("from"), to = integer("to");
        if (!from || !to || *from < 1 || *to < *from) {
            r.error(&e, fmt::format("{}: expected integers 1 <= from <= to", where));
            return;
        }
        v.from = *from;
        v.to = *to;
        const std::string kind = r.string(e, "kind", where, true);
        if (kind == "common") v.kind = VariableKind::common;
        else if (kind == "alias") v.kind = VariableKind::alias;
        else if (kind == "work-offsets") v.kind = VariableKind::work_offsets;
        else if (kind == "setting") v.kind = VariableKind::setting;
        else if (kind == "parameter") v.kind = VariableKind::parameter;
        else if (kind == "tool-in-spindle") v.kind = VariableKind::tool_in_spindle;
        else if (kind == "spindle-rpm") v.kind = VariableKind::spindle_rpm;
        else {
            r.error(e.get("kind"), fmt::format("{}.kind: unknown value '{}' (common, alias, work-offsets, setting, parameter, "
                                               "tool-in-spindle, spindle-rpm)", where, kind));
            return;
        }
        if (v.kind == VariableKind::alias) {
            const auto to_number = integer("alias_of");
            if (!to_number || *to_number < 1) {
                r.error(&e, fmt::format("{}: an alias needs `alias_of`, the variable #from stands for", where));
                return;
            }
            v.alias_of = *to_number;
        }
        if (const auto s = integer("first_set")) v.first_set = static_cast<int>(*s);
        if (const auto s = integer("stride")) v.stride = static_cast<int>(*s);
        if (v.stride < 1 || v.stride > 100) r.error(e.get("stride"), fmt::format("{}.stride: expected 1..100", where));
        if (e.contains("axes")) v.axes = r.letters(e, "axes", where);
        v.read_only = r.boolean(e, "read_only", where, false);
        v.units = r.boolean(e, "units", where, false);
        v.en = r.string(e, "en", where, true);
        v.ru = r.string(e, "ru", where, true);
        v.reference = r.string(e, "reference", where, true);
        file.dialect.variables.push_back(std::move(v));
    });
}

// The alarm names an [alarms] table may map: the control's alarms of dialects/alarms.hpp (kerf's
// own are no control's; the #3000 range is mapped by its first number).
std::vector<std::string_view> mappable_alarm_names() {
    std::vector<std::string_view> names;
    for (const alarms::AlarmDef& a : alarms::kAlarms)
        if (!alarms::is_kerf_own(a.number) && a.number != alarms::user_alarm_last) names.push_back(a.name);
    return names;
}

// One entry of [alarms]: `name = { number = 314, text = "...", reference = "..." }`.
void read_alarm(Reader& r, std::string_view name, const toml::node& node, AlarmTable& table) {
    const std::string where = fmt::format("alarms.{}", name);
    const int kerf = alarms::number_of(name);
    if (kerf == 0 || alarms::is_kerf_own(kerf) || kerf == alarms::user_alarm_last) {
        const std::vector<std::string_view> names = mappable_alarm_names();
        const std::optional<std::string_view> near = closest_name(name, names);
        const std::string why = kerf == 0 ? "is not the name of an alarm of dialects/alarms.hpp"
                                : kerf == alarms::user_alarm_last ? "is the end of the #3000 range, which user_alarm_first maps whole"
                                                                  : "is kerf's own alarm (a bound of the dry run), which no control shows";
        r.error(&node, fmt::format("{}: '{}' {}{} (docs/diagnostics.md lists the names)", where, name, why,
                                   near ? fmt::format("; did you mean '{}'?", *near) : std::string()));
        return;
    }
    const toml::table* t = node.as_table();
    if (!t) {
        r.error(&node, fmt::format("{}: expected a table {{ number = ..., text = \"...\", reference = \"...\" }}", where));
        return;
    }
    r.check_keys(*t, {"number", "text", "reference"}, where);
    ControlAlarm a;
    a.kerf = kerf;
    a.name = std::string(name);
    const toml::node* number = t->get("number");
    const auto value = number ? number->value<std::int64_t>() : std::nullopt;
    if (!value || *value < 1 || *value > 999999) {
        r.error(number ? number : t, fmt::format("{}.number: expected the control's alarm number, an integer 1..999999", where));
        return;
    }
    a.number = static_cast<int>(*value);
    // The #3000 range shows the program's own message; every other alarm needs the control's text.
    a.text = r.string(*t, "text", where, kerf != alarms::user_alarm_first);
    a.reference = r.string(*t, "reference", where, true);
    table.entries.push_back(std::move(a));
}

// [alarms]: `control = "Haas NGC"` and one entry per alarm the control numbers itself.
void read_alarms(Reader& r, const toml::table& root, DialectFile& file) {
    const toml::node* n = root.get("alarms");
    if (!n) return;
    const toml::table* t = n->as_table();
    if (!t) {
        r.error(n, "alarms: expected a table");
        return;
    }
    AlarmTable& table = file.dialect.alarms;
    for (const auto& [key, node] : *t) {
        if (key.str() == "control") table.control = r.string(*t, "control", "alarms", true);
        else read_alarm(r, key.str(), node, table);
    }
}

}  // namespace

LoadResult load_dialect_text(std::string_view toml_text, std::string_view source_name) {
    LoadResult result;
    Reader r(source_name);
    std::optional<toml::table> parsed = dialects::parse_toml(toml_text, source_name, result.errors);
    if (!parsed) return result;
    const toml::table& root = *parsed;
    DialectFile file;
    Dialect& d = file.dialect;
    r.check_keys(root, {"id", "name", "machine", "reference", "overlay", "applies_to", "combined_ids", "base", "remove",
                        "lexical", "g", "m", "patch", "detect", "variables", "foreign", "alarms"},
                 "top level");
    d.id = r.string(root, "id", "top level", true);
    d.name = r.string(root, "name", "top level", true);
    d.reference = r.string(root, "reference", "top level", false);
    file.overlay = r.boolean(root, "overlay", "top level", false);
    d.foreign = r.boolean(root, "foreign", "top level", false);
    if (d.foreign) {
        // A profile of another control: its name and the evidence, nothing to read a program with.
        for (const char* key : {"machine", "overlay", "base", "lexical", "g", "m", "patch", "variables", "alarms"})
            if (root.contains(key))
                r.error(root.get(key), fmt::format("{}: a foreign control profile (`foreign = true`) has only id, name, "
                                                   "reference and [detect]", key));
        read_detect(r, root, file);
        d.set_codes({});   // no codes: the (empty) lookup tables still exist for detection's code clues
        if (!file.detect_set) r.error(&root, "a foreign control profile needs the [detect] evidence that recognises it");
        result.errors = std::move(r.errors);
        if (result.errors.empty()) result.file = std::move(file);
        return result;
    }
    file.base = r.string(root, "base", "top level", false);
    if (const toml::node* b = root.get("base")) {
        file.base_line = static_cast<int>(b->source().begin.line);
        file.base_column = static_cast<int>(b->source().begin.column);
        if (file.overlay) r.error(b, "base: an overlay names its bases in applies_to");
    }
    const bool derived = !file.base.empty();
    if (!derived && (root.contains("remove") || root.contains("patch")))
        r.error(root.get(root.contains("remove") ? "remove" : "patch"), "remove and [[patch]] need a base dialect (`base = \"id\"`)");
    file.machine_set = root.contains("machine");
    const std::string machine = r.string(root, "machine", "top level", !file.overlay && !derived);
    if (machine == "mill") d.machine = MachineKind::mill;
    else if (machine == "lathe" || machine.empty()) d.machine = MachineKind::lathe;
    else r.error(root.get("machine"), fmt::format("machine: unknown value '{}' (lathe or mill)", machine));
    if (file.overlay) {
        file.applies_to = r.strings(root, "applies_to", "top level");
        file.combined_ids = r.strings(root, "combined_ids", "top level");
        if (file.applies_to.size() != file.combined_ids.size())
            r.error(root.get("combined_ids"), "combined_ids must have one id per entry of applies_to");
    }
    if (const toml::node* n = root.get("lexical")) {
        if (const toml::table* lex = n->as_table()) {
            if (file.overlay || derived)
                file.lexical_overrides = read_lexical(r, *lex, LexicalRules{}, file.lexical_keys_set);
            else
                d.lexical = read_lexical(r, *lex, LexicalRules{}, file.lexical_keys_set);
        } else {
            r.error(n, "lexical: expected a table");
        }
    } else if (!file.overlay && !derived) {
        r.error(&root, "missing [lexical] table");
    }
    read_remove(r, root, file);
    read_patches(r, root, file);
    read_detect(r, root, file);
    read_variables(r, root, file);
    read_alarms(r, root, file);
    std::vector<CodeInfo> codes = read_codes(r, root, 'G');
    std::vector<CodeInfo> ms = read_codes(r, root, 'M');
    codes.insert(codes.end(), std::make_move_iterator(ms.begin()), std::make_move_iterator(ms.end()));
    d.set_codes(std::move(codes));
    result.errors = std::move(r.errors);
    if (result.errors.empty()) result.file = std::move(file);
    return result;
}

namespace {

// The lexical keys a file sets override the base's, one by one.
void override_lexical(LexicalRules& lex, const DialectFile& file) {
    const LexicalRules& o = file.lexical_overrides;
    for (const std::string& key : file.lexical_keys_set) {
        if (key == "semicolon") lex.semicolon = o.semicolon;
        else if (key == "paren_comments") lex.paren_comments = o.paren_comments;
        else if (key == "line_comments") lex.line_comments = o.line_comments;
        else if (key == "incremental_letters") lex.incremental_letters = o.incremental_letters;
        else if (key == "axes") lex.axes = o.axes;
        else if (key == "diameter_letters") lex.diameter_letters = o.diameter_letters;
        else if (key == "comma_words") lex.comma_words = o.comma_words;
        else if (key == "plain_direct_drawing") lex.plain_direct_drawing = o.plain_direct_drawing;
        else if (key == "subprogram_call") lex.subprogram_call = o.subprogram_call;
        else if (key == "decimal_comma") lex.decimal_comma_lenient = o.decimal_comma_lenient;
        else if (key == "calculator_decimal") lex.calculator_decimal = o.calculator_decimal;
        else if (key == "dwell_p_unit") lex.dwell_p_seconds = o.dwell_p_seconds;
        else if (key == "program_digits") lex.program_digits = o.program_digits;
        else if (key == "tool_word") lex.tool_word = o.tool_word;
        else if (key == "macro_b") lex.macro_b = o.macro_b;
        else if (key == "max_m_per_block") lex.max_m_per_block = o.max_m_per_block;
        else if (key == "label_search") lex.label_search = o.label_search;
        else if (key == "if_words") lex.if_words = o.if_words;
    }
}

// The file's codes replace the base's entry of the same code in place, or come after the base's.
void merge_codes(std::vector<CodeInfo>& codes, const Dialect& changes) {
    for (const CodeInfo& info : changes.codes()) {
        const auto same = std::find_if(codes.begin(), codes.end(), [&](const CodeInfo& c) {
            return c.letter == info.letter && c.key == info.key;
        });
        if (same != codes.end()) *same = info;
        else codes.push_back(info);
    }
}

void apply_patch(CodeInfo& c, const CodePatch& p) {
    const CodeInfo& f = p.fields;
    for (const std::string& key : p.keys) {
        if (key == "aliases") c.aliases = f.aliases;
        else if (key == "group") c.group = f.group;
        else if (key == "modal") c.modal = f.modal;
        else if (key == "default") c.power_on_default = f.power_on_default;
        else if (key == "function") c.function = f.function;
        else if (key == "words") c.words = f.words;
        else if (key == "parameter_words") c.parameter_letters = f.parameter_letters;
        else if (key == "required") c.required = f.required;
        else if (key == "required_one_of") c.required_one_of = f.required_one_of;
        else if (key == "availability") c.availability = f.availability;
        else if (key == "availability_note") c.availability_note = f.availability_note;
        else if (key == "en") c.en = f.en;
        else if (key == "ru") c.ru = f.ru;
        else if (key == "reference") c.reference = f.reference;
        else if (key == "notes") c.notes = f.notes;
        else if (key == "implied") c.implied = f.implied;
    }
}

LoadError error_at(std::string_view source, int line, int column, std::string message) {
    return {fmt::format("{}: {}", source, message), line, column};
}

}  // namespace

Dialect apply_overlay(const Dialect& base, const DialectFile& overlay, std::string combined_id) {
    Dialect out = base;
    out.id = std::move(combined_id);
    out.name = fmt::format("{} + {}", base.name, overlay.dialect.name);
    out.overlays.push_back(overlay.dialect.id);
    out.bases.insert(out.bases.begin(), base.id);
    override_lexical(out.lexical, overlay);
    // Detection: the base's clues and the overlay's; a candidate only when the overlay's score.
    for (DetectClue& c : out.detect.clues) c.own = false;
    out.detect.clues.insert(out.detect.clues.end(), overlay.dialect.detect.clues.begin(),
                            overlay.dialect.detect.clues.end());
    out.detect.needs_own = true;
    out.detect.fallback = false;
    out.alarms.merge(overlay.dialect.alarms);
    std::vector<CodeInfo> codes(base.codes().begin(), base.codes().end());
    merge_codes(codes, overlay.dialect);
    out.set_codes(std::move(codes));
    return out;
}

Dialect derive_dialect(const Dialect& base, const DialectFile& file, std::string_view source_name,
                       std::vector<LoadError>& errors) {
    const Dialect& d = file.dialect;
    Dialect out = base;
    out.id = d.id;
    out.name = d.name;
    if (!d.reference.empty()) out.reference = d.reference;
    if (file.machine_set) out.machine = d.machine;
    out.bases.insert(out.bases.begin(), base.id);
    override_lexical(out.lexical, file);
    // The base's clues come first (check_detect's lines for them are the base file's).
    std::size_t inherited = out.detect.clues.size();
    if (file.detect_set) {
        if (!file.detect_inherit) out.detect.clues.clear();
        inherited = out.detect.clues.size();
        out.detect.clues.insert(out.detect.clues.end(), d.detect.clues.begin(), d.detect.clues.end());
        out.detect.fallback = d.detect.fallback;
        out.detect.needs_own = false;
    } else {
        out.detect.fallback = false;   // one default dialect: the base stays it
    }
    out.variables.insert(out.variables.end(), d.variables.begin(), d.variables.end());
    out.alarms.merge(d.alarms);
    std::vector<CodeInfo> codes(base.codes().begin(), base.codes().end());
    for (const auto& [spelling, at] : file.remove) {
        const auto parsed = parse_code_spelling(spelling);
        const auto it = std::find_if(codes.begin(), codes.end(), [&](const CodeInfo& c) {
            return parsed && c.letter == parsed->first && c.key == parsed->second;
        });
        if (it == codes.end())
            errors.push_back(error_at(source_name, at.first, at.second,
                                      fmt::format("remove: {} is not a code of the base dialect {}", spelling, base.id)));
        else
            codes.erase(it);
    }
    merge_codes(codes, d);
    for (const CodePatch& p : file.patches) {
        const auto it = std::find_if(codes.begin(), codes.end(),
                                     [&](const CodeInfo& c) { return c.letter == p.letter && c.key == p.key; });
        if (it == codes.end())
            errors.push_back(error_at(source_name, p.line, p.column,
                                      fmt::format("patch: {} is not a code of the base dialect {} (a new code is a "
                                                  "whole [[{}]] entry)",
                                                  p.spelling, base.id, p.letter == 'G' ? "g" : "m")));
        else
            apply_patch(*it, p);
    }
    out.set_codes(std::move(codes));
    // A base's evidence for a code this file removes proves nothing here; check_detect would report
    // it at a line of the base's file, not this one (fuzz_dialect_toml).
    const auto gone = [&out](const DetectClue& c) {
        return c.kind == DetectClue::Kind::code && c.weight > 0 && !out.code(c.letter, c.key);
    };
    out.detect.clues.erase(std::remove_if(out.detect.clues.begin(), out.detect.clues.begin() + static_cast<std::ptrdiff_t>(inherited), gone),
                           out.detect.clues.begin() + static_cast<std::ptrdiff_t>(inherited));
    return out;
}

std::vector<LoadError> check_detect(const Dialect& dialect, std::string_view source_name) {
    std::vector<LoadError> errors;
    for (const DetectClue& c : dialect.detect.clues) {
        if (c.kind != DetectClue::Kind::code || c.weight <= 0 || !c.own) continue;
        if (!dialect.code(c.letter, c.key))
            errors.push_back(error_at(source_name, c.line, c.column,
                                      fmt::format("detect: {} is not a code of {}: evidence for it cannot prove the "
                                                  "dialect (a negative weight may name any code)",
                                                  c.spelling.substr(0, c.spelling.find(' ')), dialect.id)));
    }
    return errors;
}

}  // namespace kerf::dialects
