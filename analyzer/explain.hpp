// `kerf explain` as data: what a check rule, a diagnostic id or a G/M code of a dialect is. The CLI
// prints `format_explanation`; the language server's hover renders the same structures. Pure: the
// caller passes the registries (project::Workspace has the file's).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "analyzer/registry.hpp"
#include "analyzer/rule.hpp"
#include "dialects/dialect.hpp"

namespace kerf::analyzer {

enum class Language { en, ru };

// One G or M code as one or more dialects read it (the same reading in each of `dialects`).
struct CodeExplanation {
    std::vector<std::string> dialects;   // ids, registry order; the first is the one the fields come from
    std::string spelling;                // "G71"
    std::vector<std::string> aliases;    // "G112" for G12.1
    std::string title;                   // the code's description in the requested language
    char letter = 'G';
    std::string group;                   // G codes: "00", "01", ...; empty for M codes
    bool one_shot = false;               // group 00
    bool power_on_default = false;
    dialects::FunctionId function;
    std::string_view function_meaning;   // the vocabulary's meaning of the function (docs/functions.md)
    std::vector<std::string> words, required;
    std::vector<std::vector<std::string>> required_one_of;
    dialects::Availability availability = dialects::Availability::standard;
    std::string availability_note;
    std::string notes;
    std::string reference;
};

CodeExplanation explain_code(const dialects::Dialect& dialect, const dialects::CodeInfo& code, Language lang);

struct ExplainRequest {
    std::string query;     // "G71", "m3", "K1002", "address-without-value", "S0101"
    std::string dialect;   // empty: every dialect of the registry that has the code
    Language lang = Language::en;
};

struct Explanation {
    enum class Kind {
        rule,              // `rule` is set (a rule id or name, or an S/M/F id: the rule reporting it)
        code,              // `codes`: one entry per distinct reading
        no_such_rule,      // a K id (or S/M/F id) kerf does not have
        no_such_code,      // a code no dialect (or not the given dialect) has
        unknown_dialect,
        not_understood,    // neither a code nor a rule
    };
    Kind kind = Kind::not_understood;
    const Rule* rule = nullptr;
    std::string diagnostic;                 // the S/M/F id asked for, when `rule` reports it
    std::vector<CodeExplanation> codes;
    std::string message;                    // the other kinds: what to tell the user, with what to do
};

Explanation explain(const ExplainRequest& request, const dialects::Registry& dialects, const Registry& rules);

// The CLI's text (`kerf explain`), in the request's language for codes (rules are documented in English).
std::string format_explanation(const Explanation& e, Language lang);
std::string format_code(const CodeExplanation& c, Language lang);

const char* availability_text(dialects::Availability a);

}  // namespace kerf::analyzer
