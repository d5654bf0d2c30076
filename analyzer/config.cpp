#include "analyzer/config.hpp"

#include <fmt/format.h>

#include <toml++/toml.h>

#include "analyzer/registry.hpp"

namespace kerf::analyzer {

namespace {

const std::optional<Severity>* lookup(const CheckConfig& c, const Rule& rule) {
    if (const auto it = c.rules.find(rule.id); it != c.rules.end()) return &it->second;
    if (const auto it = c.rules.find(rule.name); it != c.rules.end()) return &it->second;
    return nullptr;
}

std::string where(std::string_view source, const toml::source_region& r) {
    return fmt::format("{}:{}:{}", source, r.begin.line, r.begin.column);
}

std::vector<std::string> strings(const toml::node* node, std::string_view source, std::string_view key,
                                 std::vector<std::string>& errors) {
    std::vector<std::string> out;
    if (!node) return out;
    const toml::array* array = node->as_array();
    if (!array) {
        errors.push_back(fmt::format("{}: check.{} must be an array of glob strings", where(source, node->source()), key));
        return out;
    }
    for (const toml::node& item : *array) {
        if (const auto s = item.value<std::string>()) out.push_back(*s);
        else errors.push_back(fmt::format("{}: check.{}: a glob must be a string", where(source, item.source()), key));
    }
    return out;
}

void read_rules(const toml::table& table, std::string_view source, ConfigResult& result) {
    for (const auto& [key, node] : table) {
        const std::string_view id = key.str();
        const std::optional<std::string> value = node.value<std::string>();
        if (!builtin_rules().find(id)) {
            result.errors.push_back(fmt::format("{}: unknown rule '{}' (kerf check --list-rules lists them)",
                                                where(source, key.source()), id));
            continue;
        }
        if (!value || (*value != "off" && !parse_severity(*value))) {
            result.errors.push_back(fmt::format("{}: rule '{}': use \"error\", \"warning\", \"info\", \"hint\" or \"off\"",
                                                where(source, node.source()), id));
            continue;
        }
        result.config.rules[std::string(id)] = parse_severity(*value);
    }
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

bool CheckConfig::selects(std::string_view relative) const {
    bool in = include.empty();
    for (const std::string& g : include) in = in || glob_match(g, relative);
    if (!in) return false;
    for (const std::string& g : exclude)
        if (glob_match(g, relative)) return false;
    return true;
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

ConfigResult parse_check_config(std::string_view text, std::string_view source) {
    ConfigResult result;
    toml::table root;
    try {
        root = toml::parse(text, source);
    } catch (const toml::parse_error& e) {
        result.errors.push_back(fmt::format("{}: {}", where(source, e.source()), e.description()));
        return result;
    }
    if (const toml::table* check = root["check"].as_table()) {
        result.config.include = strings(check->get("include"), source, "include", result.errors);
        result.config.exclude = strings(check->get("exclude"), source, "exclude", result.errors);
        if (const toml::table* rules = (*check)["rules"].as_table()) read_rules(*rules, source, result);
    }
    if (const toml::table* rules = root["rules"].as_table()) read_rules(*rules, source, result);
    return result;
}

}  // namespace kerf::analyzer
