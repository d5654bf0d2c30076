#include "analyzer/config.hpp"

#include <fmt/format.h>

#include <toml++/toml.h>

#include <algorithm>
#include <tuple>

#include "analyzer/registry.hpp"

namespace kerf::analyzer {

namespace {

const std::optional<Severity>* lookup(const CheckConfig& c, const Rule& rule) {
    if (const auto it = c.rules.find(rule.id); it != c.rules.end()) return &it->second;
    if (const auto it = c.rules.find(rule.name); it != c.rules.end()) return &it->second;
    return nullptr;
}

void error(ConfigResult& r, const toml::source_region& at, std::string message) {
    r.errors.push_back({static_cast<int>(at.begin.line), static_cast<int>(at.begin.column), std::move(message)});
}

std::vector<std::string> strings(const toml::node* node, std::string_view key, ConfigResult& r) {
    std::vector<std::string> out;
    if (!node) return out;
    const toml::array* array = node->as_array();
    if (!array) {
        error(r, node->source(), fmt::format("check.{}: expected an array of glob strings, e.g. [\"**/*.nc\"]", key));
        return out;
    }
    for (const toml::node& item : *array) {
        if (const auto s = item.value<std::string>(); s && item.is_string()) out.push_back(*s);
        else error(r, item.source(), fmt::format("check.{}: a glob must be a string", key));
    }
    return out;
}

void read_rules(const toml::table& table, std::string_view where, ConfigResult& result) {
    for (const auto& [key, node] : table) {
        const std::string_view id = key.str();
        const std::optional<std::string> value = node.is_string() ? node.value<std::string>() : std::nullopt;
        if (!builtin_rules().find(id)) {
            error(result, key.source(), fmt::format("{}.{}: unknown rule (`kerf check --list-rules` lists the ids and names)", where, id));
            continue;
        }
        if (!value || (*value != "off" && !parse_severity(*value))) {
            error(result, node.source(), fmt::format("{}.{}: expected \"error\", \"warning\", \"info\", \"hint\" or \"off\"", where, id));
            continue;
        }
        result.config.rules[std::string(id)] = parse_severity(*value);
    }
}

const toml::table* table_at(const toml::node* node, std::string_view key, ConfigResult& r) {
    if (!node) return nullptr;
    if (const toml::table* t = node->as_table()) return t;
    error(r, node->source(), fmt::format("{}: expected a table ([{}])", key, key));
    return nullptr;
}

}  // namespace

std::optional<Severity> parse_severity(std::string_view text) {
    if (text == "error") return Severity::error;
    if (text == "warning") return Severity::warning;
    if (text == "info") return Severity::info;
    if (text == "hint") return Severity::hint;
    return std::nullopt;
}

bool CheckConfig::enabled(const Rule& rule) const {
    const std::optional<Severity>* s = lookup(*this, rule);
    return s ? s->has_value() : rule.enabled;
}

Severity CheckConfig::severity(const Rule& rule) const {
    const std::optional<Severity>* s = lookup(*this, rule);
    return s && s->has_value() ? **s : rule.severity;
}

namespace {

const std::string* first_match(const std::vector<std::string>& globs, std::string_view relative) {
    for (const std::string& g : globs)
        if (glob_match(g, relative)) return &g;
    return nullptr;
}

}  // namespace

const std::string* CheckConfig::included_by(std::string_view relative) const { return first_match(include, relative); }
const std::string* CheckConfig::excluded_by(std::string_view relative) const { return first_match(exclude, relative); }

bool CheckConfig::selects(std::string_view relative) const {
    return (include.empty() || included_by(relative)) && !excluded_by(relative);
}

bool glob_match(std::string_view p, std::string_view s) {
    if (p.empty()) return s.empty();
    if (p.starts_with("**")) {
        std::string_view rest = p.substr(2);
        if (rest.starts_with('/') && glob_match(rest.substr(1), s)) return true;   // "**/" matches nothing
        for (std::size_t i = 0; i <= s.size(); ++i)
            if (glob_match(rest, s.substr(i))) return true;
        return false;
    }
    if (p.front() == '*') {
        for (std::size_t i = 0; i <= s.size(); ++i) {
            if (glob_match(p.substr(1), s.substr(i))) return true;
            if (i < s.size() && s[i] == '/') break;
        }
        return false;
    }
    if (s.empty()) return false;
    if (p.front() == '?' ? s.front() == '/' : p.front() != s.front()) return false;
    return glob_match(p.substr(1), s.substr(1));
}

ConfigResult parse_check_config(std::string_view text) {
    ConfigResult result;
    toml::table root;
    try {
        root = toml::parse(text);
    } catch (const toml::parse_error& e) {
        error(result, e.source(), std::string(e.description()));
        return result;
    }
    if (const toml::table* check = table_at(root.get("check"), "check", result)) {
        for (const auto& [key, node] : *check)
            if (key.str() != "include" && key.str() != "exclude" && key.str() != "rules")
                error(result, key.source(), fmt::format("check.{}: unknown key; the keys of [check] are include, exclude and rules", key.str()));
        result.config.include = strings(check->get("include"), "include", result);
        result.config.exclude = strings(check->get("exclude"), "exclude", result);
        if (const toml::table* rules = table_at(check->get("rules"), "check.rules", result)) read_rules(*rules, "check.rules", result);
    }
    if (const toml::table* rules = table_at(root.get("rules"), "rules", result)) read_rules(*rules, "rules", result);
    // In the order of the file (a TOML table iterates by key).
    std::sort(result.errors.begin(), result.errors.end(), [](const ConfigError& a, const ConfigError& b) {
        return std::tie(a.line, a.column) < std::tie(b.line, b.column);
    });
    return result;
}

}  // namespace kerf::analyzer
