// Error collection shared by the TOML loaders (dialects/loader.cpp, machine/loader.cpp): every
// problem with its key path and TOML position; unknown keys are errors, because a misspelt key must
// not silently keep a default.
#pragma once

#include <fmt/format.h>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "dialects/dialect.hpp"

namespace kerf::dialects {

class TomlErrors {
public:
    explicit TomlErrors(std::string_view source) : source_(source) {}
    std::vector<LoadError> errors;

    void error(const toml::node* node, std::string message) {
        LoadError e;
        e.message = fmt::format("{}: {}", source_, message);
        if (node) {
            e.line = static_cast<int>(node->source().begin.line);
            e.column = static_cast<int>(node->source().begin.column);
        }
        errors.push_back(std::move(e));
    }

    // `schema` names the document that lists the keys ("dialects/SCHEMA.md").
    void check_keys(const toml::table& t, std::initializer_list<std::string_view> allowed, std::string_view where,
                    std::string_view schema) {
        for (const auto& [key, node] : t) {
            bool known = false;
            for (const std::string_view a : allowed) known |= key.str() == a;
            if (!known) error(&node, fmt::format("{}: unknown key '{}' (see {})", where, key.str(), schema));
        }
    }

protected:
    std::string_view source_;
};

// Parses TOML text; a syntax error becomes one LoadError with its position and nullopt.
inline std::optional<toml::table> parse_toml(std::string_view text, std::string_view source_name,
                                             std::vector<LoadError>& errors) {
    try {
        return toml::parse(text, source_name);
    } catch (const toml::parse_error& e) {
        LoadError err;
        err.message = fmt::format("{}: {}", source_name, e.description());
        err.line = static_cast<int>(e.source().begin.line);
        err.column = static_cast<int>(e.source().begin.column);
        errors.push_back(std::move(err));
        return std::nullopt;
    }
}

}  // namespace kerf::dialects
