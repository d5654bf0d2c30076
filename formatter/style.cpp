#include "formatter/style.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <tuple>
#include <charconv>
#include <toml++/toml.h>

namespace kerf::formatter {

namespace {

// An enum option: its value names in enum order ("keep|upper|lower" → LetterCase::keep ...).
template <typename E>
std::optional<std::string> set_enum(E& field, std::string_view names, std::string_view value) {
    int index = 0;
    for (std::size_t at = 0; at <= names.size(); ++index) {
        const std::size_t bar = std::min(names.find('|', at), names.size());
        if (names.substr(at, bar - at) == value) {
            field = static_cast<E>(index);
            return std::nullopt;
        }
        at = bar + 1;
    }
    return fmt::format("'{}' is not one of {}", value, names);
}

std::optional<std::string> set_int(int& field, std::string_view value, int min, int max) {
    int v = 0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (ec != std::errc{} || end != value.data() + value.size() || v < min || v > max)
        return fmt::format("'{}' is not a whole number from {} to {}", value, min, max);
    field = v;
    return std::nullopt;
}

using Setter = std::optional<std::string> (*)(Style&, std::string_view names, std::string_view value);

struct Option {
    OptionInfo info;
    Setter set;
};

template <auto Field>
Option enum_option(std::string_view key, std::string_view names, std::string_view text) {
    return {{key, names, text}, [](Style& s, std::string_view n, std::string_view v) { return set_enum(s.*Field, n, v); }};
}

// The table behind options(), set_option() and docs/fmt.md (keep them in step).
const std::array<Option, 15> kOptions = {{
    enum_option<&Style::letter_case>("letter_case", "keep|upper|lower",
                     "case of address letters (comments, macro statements and expression text are kept)"),
    enum_option<&Style::spacing>("spacing", "keep|spaced|compact",
                     "blanks between the words of a block: as written, one, or none"),
    enum_option<&Style::word_order>("word_order", "keep|canonical",
                     "canonical: N, G codes, axes, I/J/K/R, other addresses, comma words, F, S, T, M; comments keep "
                     "their places; blocks with macro statements or G65/G66 calls keep their order"),
    enum_option<&Style::code_digits>("code_digits", "keep|two|minimal", "G/M code numbers: G01 M03 (two) or G1 M3 (minimal)"),
    enum_option<&Style::decimal_point>("decimal_point", "keep|add",
                     "add: a trailing point on axis and F values (X10 → X10.) only on a machine with "
                     "calculator-type decimal input, where both mean millimetres"),
    enum_option<&Style::block_end>("block_end", "keep|semicolon|none",
                     "';' at the end of every block, or none at line ends (dialects where ';' ends blocks)"),
    enum_option<&Style::line_ending>("line_ending", "keep|lf|crlf", "line breaks"),
    enum_option<&Style::percent>("percent", "keep|ensure", "ensure: a '%' line before and after the program"),
    enum_option<&Style::program_number>("program_number", "keep|four_digits", "O numbers: O1 → O0001"),
    Option{{"blank_lines", "integer", "at most this many blank lines in a row; -1 keeps them all"},
           [](Style& s, std::string_view, std::string_view v) { return set_int(s.max_blank_lines, v, -1, 1000); }},
    enum_option<&Style::comment_inside>("comment_inside", "keep|tight|padded",
                     "blanks inside parentheses: (TEXT) or ( TEXT ); the text between is kept byte for byte"),
    enum_option<&Style::comment_gap>("comment_gap", "spacing|one|none",
                     "blanks before a comment after a word: as the spacing option, one, or none"),
    enum_option<&Style::block_numbers>("block_numbers", "keep|remove|renumber|referenced",
                     "N words: keep; remove those nothing refers to; renumber all code blocks; number only the "
                     "blocks something refers to (references in G70-G73 P/Q, M98 Q, M99 P, GOTO follow)"),
    Option{{"number_start", "integer", "first N of each program when renumbering"},
           [](Style& s, std::string_view, std::string_view v) { return set_int(s.number_start, v, 0, 99999); }},
    Option{{"number_step", "integer", "step between N numbers when renumbering"},
           [](Style& s, std::string_view, std::string_view v) { return set_int(s.number_step, v, 1, 99999); }},
}};

const Option* find_option(std::string_view key) {
    for (const Option& o : kOptions)
        if (o.info.key == key) return &o;
    return nullptr;
}

std::array<OptionInfo, kOptions.size()> make_infos() {
    std::array<OptionInfo, kOptions.size()> infos;
    for (std::size_t i = 0; i < kOptions.size(); ++i) infos[i] = kOptions[i].info;
    return infos;
}

// A TOML value as the spelling set_option takes: strings as they are, integers in decimal.
std::optional<std::string> spelling_of(const toml::node& node) {
    if (const auto s = node.value<std::string>(); s && node.is_string()) return *s;
    if (node.is_integer()) return std::to_string(node.as_integer()->get());
    return std::nullopt;
}

std::string option_keys() {
    std::string keys;
    for (const Option& o : kOptions) keys += (keys.empty() ? "" : ", ") + std::string(o.info.key);
    return keys;
}

}  // namespace

std::span<const OptionInfo> options() {
    static const auto infos = make_infos();
    return infos;
}

std::optional<std::string> set_option(Style& style, std::string_view key, std::string_view value) {
    const Option* o = find_option(key);
    if (!o) return fmt::format("unknown option '{}'", key);
    return o->set(style, o->info.values, value);
}

StyleResult style_from_toml(std::string_view toml_text, std::string_view source_name, const Style& base) {
    StyleResult r{base, {}};
    toml::table root;
    try {
        root = toml::parse(toml_text, source_name);
    } catch (const toml::parse_error& e) {
        r.errors.push_back({fmt::format("{}: {}", source_name, e.description()), static_cast<int>(e.source().begin.line),
                            static_cast<int>(e.source().begin.column)});
        return r;
    }
    const toml::table* table = root["format"].as_table();
    if (!table) return r;
    for (const auto& [key, node] : *table) {
        const int line = static_cast<int>(node.source().begin.line);
        const int column = static_cast<int>(node.source().begin.column);
        const Option* o = find_option(key.str());
        const std::optional<std::string> value = spelling_of(node);
        std::optional<std::string> error;
        if (!o) error = fmt::format("unknown key; the keys of [format] are {}", option_keys());
        else if (!value) error = fmt::format("expected {}", o->info.values == "integer" ? "an integer" : "a string");
        else error = o->set(r.style, o->info.values, *value);
        if (error) r.errors.push_back({fmt::format("{}: format.{}: {}", source_name, key.str(), *error), line, column});
    }
    // In the order of the file (a TOML table iterates by key).
    std::sort(r.errors.begin(), r.errors.end(),
              [](const StyleError& a, const StyleError& b) { return std::tie(a.line, a.column) < std::tie(b.line, b.column); });
    return r;
}

}  // namespace kerf::formatter
