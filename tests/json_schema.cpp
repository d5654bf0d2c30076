#include "tests/json_schema.hpp"

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
#include <regex>
#include <string_view>

#include "tests/shared_files.hpp"

namespace kerf::test {

namespace json = boost::json;

namespace {

using Errors = std::vector<std::string>;

bool is_annotation(std::string_view key) {
    static constexpr std::string_view kAnnotations[] = {"$schema", "$id",     "title",   "description",
                                                        "default", "format", "$comment", "examples"};
    return std::find(std::begin(kAnnotations), std::end(kAnnotations), key) != std::end(kAnnotations);
}

// JSON Schema's type names; "integer" is a number without a fraction (1.0 counts).
bool has_type(const json::value& v, std::string_view type) {
    if (type == "object") return v.is_object();
    if (type == "array") return v.is_array();
    if (type == "string") return v.is_string();
    if (type == "boolean") return v.is_bool();
    if (type == "null") return v.is_null();
    if (type == "number") return v.is_number();
    if (type == "integer") return v.is_int64() || v.is_uint64() || (v.is_double() && v.as_double() == static_cast<double>(static_cast<long long>(v.as_double())));
    return false;
}

double number_of(const json::value& v) { return v.to_number<double>(); }

// JSON pointer escaping of one reference token (RFC 6901).
std::string pointer_token(std::string_view key) {
    std::string out;
    for (const char c : key) {
        if (c == '~') out += "~0";
        else if (c == '/') out += "~1";
        else out += c;
    }
    return out;
}

class Checker {
public:
    explicit Checker(const json::value& root) : root_(root) {}

    void check(const json::value& schema, const json::value& doc, const std::string& at, Errors& errors) const {
        if (schema.is_bool()) {
            if (!schema.as_bool()) errors.push_back(at + ": no value is allowed here");
            return;
        }
        if (!schema.is_object()) {
            errors.push_back(at + ": (schema) a schema must be an object or a boolean");
            return;
        }
        for (const auto& [key, value] : schema.as_object()) keyword(schema.as_object(), key, value, doc, at, errors);
    }

private:
    using Keyword = void (Checker::*)(const json::object&, const json::value&, const json::value&, const std::string&,
                                      Errors&) const;

    void keyword(const json::object& schema, std::string_view key, const json::value& arg, const json::value& doc,
                 const std::string& at, Errors& errors) const {
        static const std::map<std::string_view, Keyword> kKeywords = {
            {"type", &Checker::type},           {"required", &Checker::required},
            {"properties", &Checker::properties}, {"additionalProperties", &Checker::additional},
            {"items", &Checker::items},         {"enum", &Checker::enumeration},
            {"const", &Checker::constant},      {"minimum", &Checker::minimum},
            {"maximum", &Checker::maximum},     {"minItems", &Checker::min_items},
            {"uniqueItems", &Checker::unique},  {"pattern", &Checker::pattern},
            {"$ref", &Checker::ref},            {"oneOf", &Checker::one_of},
            {"anyOf", &Checker::any_of},        {"allOf", &Checker::all_of},
            {"definitions", &Checker::nothing},
        };
        if (is_annotation(key)) return;
        const auto it = kKeywords.find(key);
        if (it == kKeywords.end()) {
            errors.push_back(fmt::format("{}: (schema) unsupported keyword '{}'", at, key));
            return;
        }
        (this->*it->second)(schema, arg, doc, at, errors);
    }

    void nothing(const json::object&, const json::value&, const json::value&, const std::string&, Errors&) const {}

    void type(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
              Errors& errors) const {
        if (arg.is_string()) {
            if (!has_type(doc, arg.as_string())) errors.push_back(fmt::format("{}: not of type {}", at, json::serialize(arg)));
            return;
        }
        for (const json::value& t : arg.as_array())
            if (has_type(doc, t.as_string())) return;
        errors.push_back(fmt::format("{}: not of any type of {}", at, json::serialize(arg)));
    }

    void required(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
                  Errors& errors) const {
        if (!doc.is_object()) return;
        for (const json::value& name : arg.as_array())
            if (!doc.as_object().contains(name.as_string()))
                errors.push_back(fmt::format("{}: required property '{}' missing", at, std::string_view(name.as_string())));
    }

    void properties(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
                    Errors& errors) const {
        if (!doc.is_object()) return;
        for (const auto& [name, value] : doc.as_object())
            if (const json::value* sub = arg.as_object().if_contains(name))
                check(*sub, value, at + "/" + pointer_token(name), errors);
    }

    // Applies to the members that `properties` does not name (draft-07 without patternProperties).
    void additional(const json::object& schema, const json::value& arg, const json::value& doc, const std::string& at,
                    Errors& errors) const {
        if (!doc.is_object()) return;
        const json::value* named = schema.if_contains("properties");
        for (const auto& [name, value] : doc.as_object()) {
            if (named && named->as_object().contains(name)) continue;
            if (arg.is_bool() && !arg.as_bool())
                errors.push_back(fmt::format("{}: property '{}' is not allowed", at, std::string_view(name)));
            else check(arg, value, at + "/" + pointer_token(name), errors);
        }
    }

    void items(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
               Errors& errors) const {
        if (!doc.is_array()) return;
        const json::array& a = doc.as_array();
        for (std::size_t i = 0; i < a.size(); ++i) check(arg, a[i], fmt::format("{}/{}", at, i), errors);
    }

    void enumeration(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
                     Errors& errors) const {
        const json::array& values = arg.as_array();
        if (std::find(values.begin(), values.end(), doc) == values.end())
            errors.push_back(fmt::format("{}: {} is not one of {}", at, json::serialize(doc), json::serialize(arg)));
    }

    void constant(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
                  Errors& errors) const {
        if (doc != arg) errors.push_back(fmt::format("{}: {} is not {}", at, json::serialize(doc), json::serialize(arg)));
    }

    void minimum(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
                 Errors& errors) const {
        if (doc.is_number() && number_of(doc) < number_of(arg))
            errors.push_back(fmt::format("{}: {} is less than {}", at, json::serialize(doc), json::serialize(arg)));
    }

    void maximum(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
                 Errors& errors) const {
        if (doc.is_number() && number_of(doc) > number_of(arg))
            errors.push_back(fmt::format("{}: {} is more than {}", at, json::serialize(doc), json::serialize(arg)));
    }

    void min_items(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
                   Errors& errors) const {
        if (doc.is_array() && doc.as_array().size() < arg.to_number<std::size_t>())
            errors.push_back(fmt::format("{}: fewer than {} items", at, json::serialize(arg)));
    }

    void unique(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
                Errors& errors) const {
        if (!arg.as_bool() || !doc.is_array()) return;
        const json::array& a = doc.as_array();
        for (std::size_t i = 0; i < a.size(); ++i)
            if (std::find(a.begin() + static_cast<std::ptrdiff_t>(i) + 1, a.end(), a[i]) != a.end())
                errors.push_back(fmt::format("{}/{}: item repeated later", at, i));
    }

    void pattern(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
                 Errors& errors) const {
        if (!doc.is_string()) return;
        const std::regex re(std::string(arg.as_string()), std::regex::ECMAScript);
        if (!std::regex_search(std::string(doc.as_string()), re))
            errors.push_back(fmt::format("{}: {} does not match {}", at, json::serialize(doc), json::serialize(arg)));
    }

    void ref(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
             Errors& errors) const {
        constexpr std::string_view prefix = "#/definitions/";
        const std::string_view target = arg.as_string();
        const json::value* definitions = root_.as_object().if_contains("definitions");
        const json::value* sub = target.starts_with(prefix) && definitions
                                     ? definitions->as_object().if_contains(target.substr(prefix.size()))
                                     : nullptr;
        if (!sub) {
            errors.push_back(fmt::format("{}: (schema) cannot resolve $ref '{}'", at, target));
            return;
        }
        check(*sub, doc, at, errors);
    }

    std::size_t passing(const json::value& arg, const json::value& doc, const std::string& at) const {
        std::size_t n = 0;
        for (const json::value& sub : arg.as_array()) {
            Errors e;
            check(sub, doc, at, e);
            n += e.empty();
        }
        return n;
    }

    void one_of(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
                Errors& errors) const {
        const std::size_t n = passing(arg, doc, at);
        if (n != 1) errors.push_back(fmt::format("{}: matches {} of the oneOf schemas, not exactly one", at, n));
    }

    void any_of(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
                Errors& errors) const {
        if (passing(arg, doc, at) == 0) errors.push_back(at + ": matches none of the anyOf schemas");
    }

    void all_of(const json::object&, const json::value& arg, const json::value& doc, const std::string& at,
                Errors& errors) const {
        for (const json::value& sub : arg.as_array()) check(sub, doc, at, errors);
    }

    const json::value& root_;
};

}  // namespace

std::vector<std::string> JsonSchema::validate(const json::value& doc) const {
    Errors errors;
    Checker(root_).check(root_, doc, "", errors);
    return errors;
}

JsonSchema load_schema(const std::string& path) {
    const std::string text = read_text(path);
    REQUIRE(!text.empty());
    boost::system::error_code ec;
    json::value v = json::parse(text, ec);
    INFO(path << ": " << ec.message());
    REQUIRE(!ec);
    return JsonSchema(std::move(v));
}

}  // namespace kerf::test
