// Reads one dialect data file (dialects/SCHEMA.md) into a Dialect. Every problem is reported with
// its key path and TOML position; nothing is silently defaulted except keys the schema marks optional.
#include <fmt/format.h>

#include <algorithm>

#include <toml++/toml.h>

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

std::optional<CodeInfo> read_code(Reader& r, const toml::table& t, char letter, std::size_t index) {
    const std::string where = fmt::format("{}[{}]", letter == 'G' ? "g" : "m", index);
    CodeInfo info;
    info.letter = letter;
    info.spelling = r.string(t, "code", where, true);
    const auto parsed = parse_code_spelling(info.spelling);
    if (!parsed || parsed->first != letter) {
        r.error(t.get("code"), fmt::format("{}.code: '{}' is not a {} code", where, info.spelling, letter));
        return std::nullopt;
    }
    info.key = parsed->second;
    const std::string label = fmt::format("{} ({})", where, info.spelling);
    r.check_keys(t, {"code", "aliases", "group", "modal", "default", "function", "words", "parameter_words", "required", "required_one_of",
                     "availability", "availability_note", "en", "ru", "reference", "notes"},
                 label);
    info.aliases = r.strings(t, "aliases", label);
    for (const std::string& alias : info.aliases)
        if (!parse_code_spelling(alias)) r.error(t.get("aliases"), fmt::format("{}.aliases: bad code '{}'", label, alias));
    info.group = r.string(t, "group", label, letter == 'G');
    info.modal = r.boolean(t, "modal", label, false, letter == 'G');
    info.power_on_default = r.boolean(t, "default", label, false);
    info.function = read_function(r, t, label);
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
    info.en = r.string(t, "en", label, true);
    info.ru = r.string(t, "ru", label, true);
    info.reference = r.string(t, "reference", label, true);
    info.notes = r.string(t, "notes", label, false);
    return info;
}

// Reads [lexical]; `set` receives the keys present (overlays override only those).
LexicalRules read_lexical(Reader& r, const toml::table& t, LexicalRules rules, std::vector<std::string>& set) {
    const std::string where = "lexical";
    r.check_keys(t, {"semicolon", "paren_comments", "line_comments", "incremental_letters", "axes", "diameter_letters",
                     "comma_words", "plain_direct_drawing", "subprogram_call", "decimal_comma", "calculator_decimal",
                     "tool_word", "macro_b", "max_m_per_block"},
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
    if (t.contains("tool_word")) {
        rules.tool_word = r.string(t, "tool_word", where, false);
        if (rules.tool_word != "mmnn" && rules.tool_word != "number")
            r.error(t.get("tool_word"), fmt::format("lexical.tool_word: unknown value '{}' (mmnn or number)", rules.tool_word));
    }
    rules.macro_b = r.boolean(t, "macro_b", where, rules.macro_b);
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
        if (auto info = read_code(r, *t, letter, i)) out.push_back(std::move(*info));
    }
    return out;
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
    r.check_keys(root, {"id", "name", "machine", "reference", "overlay", "applies_to", "combined_ids", "lexical", "g", "m"},
                 "top level");
    d.id = r.string(root, "id", "top level", true);
    d.name = r.string(root, "name", "top level", true);
    d.reference = r.string(root, "reference", "top level", false);
    file.overlay = r.boolean(root, "overlay", "top level", false);
    const std::string machine = r.string(root, "machine", "top level", !file.overlay);
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
            if (file.overlay)
                file.lexical_overrides = read_lexical(r, *lex, LexicalRules{}, file.lexical_keys_set);
            else
                d.lexical = read_lexical(r, *lex, LexicalRules{}, file.lexical_keys_set);
        } else {
            r.error(n, "lexical: expected a table");
        }
    } else if (!file.overlay) {
        r.error(&root, "missing [lexical] table");
    }
    std::vector<CodeInfo> codes = read_codes(r, root, 'G');
    std::vector<CodeInfo> ms = read_codes(r, root, 'M');
    codes.insert(codes.end(), std::make_move_iterator(ms.begin()), std::make_move_iterator(ms.end()));
    d.set_codes(std::move(codes));
    result.errors = std::move(r.errors);
    if (result.errors.empty()) result.file = std::move(file);
    return result;
}

Dialect apply_overlay(const Dialect& base, const DialectFile& overlay, std::string combined_id) {
    Dialect out = base;
    out.id = std::move(combined_id);
    out.name = fmt::format("{} + {}", base.name, overlay.dialect.name);
    out.overlays.push_back(overlay.dialect.id);
    std::vector<std::string> unused;
    LexicalRules& lex = out.lexical;
    const LexicalRules& o = overlay.lexical_overrides;
    for (const std::string& key : overlay.lexical_keys_set) {
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
        else if (key == "tool_word") lex.tool_word = o.tool_word;
        else if (key == "macro_b") lex.macro_b = o.macro_b;
        else if (key == "max_m_per_block") lex.max_m_per_block = o.max_m_per_block;
    }
    std::vector<CodeInfo> codes(base.codes().begin(), base.codes().end());
    for (const CodeInfo& info : overlay.dialect.codes()) {
        const auto same = std::find_if(codes.begin(), codes.end(), [&](const CodeInfo& c) {
            return c.letter == info.letter && c.key == info.key;
        });
        if (same != codes.end()) *same = info;
        else codes.push_back(info);
    }
    out.set_codes(std::move(codes));
    return out;
}

}  // namespace kerf::dialects
