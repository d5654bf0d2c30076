// Shared by the analyzer tests: check a text with one dialect and its built-in machine, every rule
// on (off-by-default rules too), and print findings as "line:col severity ID".
#pragma once

#include <fmt/format.h>

#include <string>
#include <vector>

#include "analyzer/analyze.hpp"
#include "analyzer/output.hpp"
#include "grammar/detect.hpp"
#include "interpreter/default_setup.hpp"

namespace kerf::test {

inline analyzer::CheckOptions all_rules_on() {
    analyzer::CheckOptions o;
    for (const analyzer::Rule& r : analyzer::builtin_rules().rules())
        o.config.rules[r.id] = r.severity;
    return o;
}

struct Checked {
    std::vector<analyzer::Finding> findings;
    analyzer::FileReport report;
};

// A soft limit to add to the built-in machine (it has none): axis letter, min, max; and what a
// machine file would say: that it was given (its limits count), its M codes.
struct SoftLimit {
    char axis = 0;
    double min = 0, max = 0;
    bool machine_given = false;
    std::vector<int> m_codes;
};

inline Checked check(const std::string& text, const std::string& dialect_id,
                     const analyzer::CheckOptions& options = all_rules_on(), SoftLimit limit = {}) {
    const dialects::Dialect* d = dialects::builtin_registry().find(dialect_id);
    REQUIRE(d);
    interpreter::Setup setup = interpreter::default_setup(*d);
    if (const auto axis = interpreter::axis_of_letter(limit.axis))
        setup.soft_limits[static_cast<std::size_t>(*axis)] = {limit.min, limit.max};
    setup.machine_given = limit.machine_given;
    setup.m_codes = limit.m_codes;
    interpreter::ProgramSet programs;
    const std::uint32_t file = programs.add("test.nc", text, *d);
    std::vector<analyzer::Finding> findings = analyzer::check_file(programs, file, *d, setup, options);
    const interpreter::LoadedFile& loaded = programs.file(file);
    Checked c;
    c.findings = findings;
    c.report = analyzer::make_report("test.nc", *loaded.whole_tree(), *loaded.whole_lines(), std::move(findings));
    return c;
}

// What the project layer hands the check when detection finds another control's program
// (project/check.cpp); nullopt when it does not.
inline std::optional<analyzer::ForeignControl> foreign_control(const std::string& text) {
    const grammar::Detection d = grammar::detect_dialect(text);
    if (!d.foreign) return std::nullopt;
    return analyzer::ForeignControl{d.foreign->id, d.foreign->name, static_cast<std::uint32_t>(d.foreign->first.line),
                                    static_cast<std::uint32_t>(d.foreign->first.column), d.foreign->first.what,
                                    d.foreign->first.proves};
}

// "line:col severity ID" of the findings of `rule` (all rules when empty).
inline std::vector<std::string> summary(const Checked& c, const std::string& rule = {}) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < c.report.findings.size(); ++i) {
        const analyzer::Finding& f = c.report.findings[i];
        if (!rule.empty() && f.rule != rule) continue;
        out.push_back(fmt::format("{}:{} {} {}", c.report.locations[i].line, c.report.locations[i].column,
                                  ast::to_string(f.severity), f.rule));
    }
    return out;
}

}  // namespace kerf::test
