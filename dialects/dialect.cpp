#include "dialects/dialect.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "dialects/alarms.hpp"

namespace kerf::dialects {

std::optional<CodeKey> code_key(double number) {
    if (!(number >= 0.0) || number > 99999.0) return std::nullopt;
    const double tenths = number * 10.0;
    const double rounded = std::round(tenths);
    // FANUC decimal codes have exactly one decimal digit (G12.1, G92.1).
    if (std::fabs(tenths - rounded) > 1e-6) return std::nullopt;
    return static_cast<CodeKey>(rounded);
}

std::optional<std::pair<char, CodeKey>> parse_code_spelling(std::string_view spelling) {
    if (spelling.size() < 2) return std::nullopt;
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(spelling[0])));
    if (letter < 'A' || letter > 'Z') return std::nullopt;
    long whole = 0;
    std::size_t i = 1;
    if (!std::isdigit(static_cast<unsigned char>(spelling[i]))) return std::nullopt;
    for (; i < spelling.size() && std::isdigit(static_cast<unsigned char>(spelling[i])); ++i) {
        whole = whole * 10 + (spelling[i] - '0');
        if (whole > 99999) return std::nullopt;
    }
    int tenth = 0;
    if (i < spelling.size()) {
        if (spelling[i] != '.' || i + 2 != spelling.size() ||
            !std::isdigit(static_cast<unsigned char>(spelling[i + 1])))
            return std::nullopt;
        tenth = spelling[i + 1] - '0';
    }
    return std::pair<char, CodeKey>{letter, static_cast<CodeKey>(whole * 10 + tenth)};
}

bool CodeInfo::takes_word(std::string_view word) const {
    return std::find(words.begin(), words.end(), word) != words.end();
}

char LexicalRules::incremental_axis_of(char letter) const {
    const auto it = incremental_letters.find(letter);
    return it == incremental_letters.end() ? '\0' : it->second;
}

const CodeInfo* Dialect::code(char letter, CodeKey key) const {
    const auto it = index_.find({letter, key});
    return it == index_.end() ? nullptr : &codes_[it->second];
}

const CodeInfo* Dialect::code(std::string_view spelling) const {
    const auto parsed = parse_code_spelling(spelling);
    return parsed ? code(parsed->first, parsed->second) : nullptr;
}

const VariableRange* Dialect::variable_range(std::int64_t number) const {
    for (const VariableRange& v : variables)
        if (number >= v.from && number <= v.to) return &v;
    return nullptr;
}

std::optional<AlarmTable::Shown> AlarmTable::shown(int kerf) const {
    const ControlAlarm* range = nullptr;
    for (const ControlAlarm& a : entries) {
        if (a.kerf == kerf) return Shown{a.number, &a};
        if (a.kerf == alarms::user_alarm_first) range = &a;
    }
    if (range && kerf >= alarms::user_alarm_first && kerf <= alarms::user_alarm_last)
        return Shown{range->number + (kerf - alarms::user_alarm_first), range};
    return std::nullopt;
}

namespace {
// kerf's texts quote the FANUC number they stand for ("program O9810 not found (alarm 078)"); under
// a control with numbers of its own that number is named as FANUC's, so it is not read as the
// control's.
std::string qualify_fanuc_number(std::string_view text, int kerf) {
    if (kerf >= 1000) return std::string(text);   // #3000 = n: the text is the program's message
    const std::string quoted = fmt::format("alarm {:03}", kerf);
    std::string out;
    std::size_t from = 0;
    for (std::size_t at = text.find(quoted); at != std::string_view::npos; at = text.find(quoted, from)) {
        out.append(text.substr(from, at - from));
        if (!out.ends_with("FANUC ") && !out.ends_with("FANUC] ")) out += "FANUC ";
        out += quoted;
        from = at + quoted.size();
    }
    out.append(text.substr(from));
    return out;
}
}  // namespace

std::string AlarmTable::name_of(int kerf) const {
    const std::optional<Shown> s = shown(kerf);
    if (!s) return kerf < 1000 ? fmt::format("alarm {:03}", kerf) : fmt::format("alarm {}", kerf);
    const std::string who = control.empty() ? std::string("control") : control;
    if (s->entry->text.empty()) return fmt::format("{} alarm {}", who, s->number);
    return fmt::format("{} alarm {} {}", who, s->number, s->entry->text);
}

std::string AlarmTable::message(int kerf, std::string_view kerf_text) const {
    if (!shown(kerf)) {
        // A control with numbers of its own that the table does not give (Haas: none could be
        // sourced, docs/haas.md): the number said is FANUC's, and the message says so.
        if (control.empty() || kerf >= 1000) return std::string(kerf_text);
        return fmt::format("{} ({} numbers this alarm its own way; kerf gives FANUC's)", qualify_fanuc_number(kerf_text, kerf), control);
    }
    return fmt::format("{}: {}", name_of(kerf), qualify_fanuc_number(kerf_text, kerf));
}

void AlarmTable::merge(const AlarmTable& other) {
    if (!other.control.empty()) control = other.control;
    for (const ControlAlarm& a : other.entries) {
        const auto same = std::find_if(entries.begin(), entries.end(), [&](const ControlAlarm& e) { return e.kerf == a.kerf; });
        if (same != entries.end()) *same = a;
        else entries.push_back(a);
    }
}

std::vector<const CodeInfo*> Dialect::codes_with_function(FunctionId function) const {
    std::vector<const CodeInfo*> out;
    for (const CodeInfo& info : codes_)
        if (info.function == function) out.push_back(&info);
    return out;
}

void Dialect::add_or_replace(CodeInfo info) {
    const auto it = index_.find({info.letter, info.key});
    if (it != index_.end()) {
        codes_[it->second] = std::move(info);
    } else {
        codes_.push_back(std::move(info));
    }
    reindex();
}

void Dialect::set_codes(std::vector<CodeInfo> codes) {
    codes_ = std::move(codes);
    reindex();
}

namespace {
// The code's traits: its function's, and its group's for G codes (group 00 one-shot, group 01 the
// motion group; reference/gcode-tables.md "group" columns).
std::uint32_t code_traits(const CodeInfo& info) {
    std::uint32_t t = info.function.def().traits;
    if (info.letter == 'G' && info.group == "00") t |= traits::one_shot;
    if (info.letter == 'G' && info.group == "01") t |= traits::motion_group;
    return t;
}
}  // namespace

void Dialect::reindex() {
    index_.clear();
    g_fast_.assign(kFastCodes, -1);
    m_fast_.assign(kFastCodes, -1);
    groups_.assign(1, std::string());
    for (const CodeInfo& info : codes_) groups_.push_back(info.group);
    std::sort(groups_.begin(), groups_.end());
    groups_.erase(std::unique(groups_.begin(), groups_.end()), groups_.end());
    for (std::size_t i = 0; i < codes_.size(); ++i) {
        CodeInfo& info = codes_[i];
        info.traits = code_traits(info);
        info.group_index = static_cast<std::uint8_t>(
            std::lower_bound(groups_.begin(), groups_.end(), info.group) - groups_.begin());
        info.parameter_mask = 0;
        for (const char L : info.parameter_letters)
            if (L >= 'A' && L <= 'Z') info.parameter_mask |= std::uint32_t{1} << (L - 'A');
        index_[{info.letter, info.key}] = i;
        for (const std::string& alias : info.aliases)
            if (const auto parsed = parse_code_spelling(alias)) index_[*parsed] = i;
    }
    for (const auto& [letter_key, i] : index_) {
        auto& fast = letter_key.first == 'G' ? g_fast_ : m_fast_;
        if ((letter_key.first == 'G' || letter_key.first == 'M') && letter_key.second >= 0 &&
            letter_key.second < kFastCodes)
            fast[static_cast<std::size_t>(letter_key.second)] = static_cast<std::int32_t>(i);
    }
}

std::optional<std::uint8_t> Dialect::group_index(std::string_view group) const {
    const auto it = std::lower_bound(groups_.begin(), groups_.end(), group);
    if (it == groups_.end() || *it != group) return std::nullopt;
    return static_cast<std::uint8_t>(it - groups_.begin());
}

const CodeInfo* Dialect::fast_code(char letter, CodeKey key) const {
    if (key >= 0 && key < kFastCodes && (letter == 'G' || letter == 'M')) {
        const std::int32_t i = (letter == 'G' ? g_fast_ : m_fast_)[static_cast<std::size_t>(key)];
        return i < 0 ? nullptr : &codes_[static_cast<std::size_t>(i)];
    }
    return code(letter, key);
}

}  // namespace kerf::dialects
