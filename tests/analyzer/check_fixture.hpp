// Shared by the analyzer tests: check a text with one dialect and its built-in machine, every rule
// on (off-by-default rules too), and print findings as "line:col severity ID".
#pragma once

#include <fmt/format.h>

#include <string>
#include <vector>

#include "analyzer/analyze.hpp"
#include "analyzer/output.hpp"
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

// A soft limit to add to the built-in machine (it has none): axis letter, min, max.
struct SoftLimit {
    char axis = 0;
    double min = 0, max = 0;
};

inline Checked check(const std::string& text, const std::string& dialect_id,
                     const analyzer::CheckOptions& options = all_rules_on(), SoftLimit limit = {}) {
    const dialects::Dialect* d = dialects::builtin_registry().find(dialect_id);
    REQUIRE(d);
    interpreter::Setup setup = interpreter::default_setup(*d);
    if (const auto axis = interpreter::axis_of_letter(limit.axis))
        setup.soft_limits[static_cast<std::size_t>(*axis)] = {limit.min, limit.max};
    interpreter::ProgramSet programs;
    const std::uint32_t file = programs.add("test.nc", text, *d);
    std::vector<analyzer::Finding> findings = analyzer::check_file(programs, file, *d, setup, options);
    const interpreter::LoadedFile& loaded = programs.file(file);
    Checked c;
    c.findings = findings;
    c.report = analyzer::make_report("test.nc", *loaded.whole_tree(), *loaded.whole_lines(), std::move(findings));
    return c;
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
