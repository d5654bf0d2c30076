#include "analyzer/registry.hpp"

#include <algorithm>
#include <stdexcept>

#include "analyzer/suppress.hpp"
#include "ast/display.hpp"

namespace kerf::analyzer {

namespace {

// The rule families; a new family is one line here and one file under rules/.
constexpr void (*kFamilies[])(Registry&) = {
    rules::add_syntax, rules::add_numbers, rules::add_dialect, rules::add_references,
    rules::add_macro,  rules::add_alarms,  rules::add_motion,  rules::add_safety,
};

Registry build() {
    Registry r;
    for (auto family : kFamilies) family(r);
    return r;
}

}  // namespace

void Registry::add(Rule rule) {
    if (find(rule.id) || find(rule.name)) throw std::logic_error("duplicate rule " + rule.id + " " + rule.name);
    const auto at = std::lower_bound(rules_.begin(), rules_.end(), rule.id,
                                     [](const Rule& a, const std::string& id) { return a.id < id; });
    rules_.insert(at, std::move(rule));
}

const Rule* Registry::find(std::string_view key) const {
    for (const Rule& r : rules_)
        if (r.id == key || r.name == key) return &r;
    return nullptr;
}

const Rule* Registry::for_diagnostic(std::string_view code) const {
    for (const Rule& r : rules_)
        if (std::find(r.diagnostics.begin(), r.diagnostics.end(), code) != r.diagnostics.end()) return &r;
    return nullptr;
}

// The rule with the narrowest matching range, so a catch-all range yields to a specific one.
const Rule* Registry::for_alarm(int number) const {
    const Rule* best = nullptr;
    int best_width = 0;
    for (const Rule& r : rules_)
        for (const auto& [first, last] : r.alarms)
            if (number >= first && number <= last && (!best || last - first < best_width)) {
                best = &r;
                best_width = last - first;
            }
    return best;
}

const Registry& builtin_rules() {
    static const Registry registry = build();
    return registry;
}

const char* to_string(Category c) {
    switch (c) {
        case Category::syntax: return "syntax";
        case Category::dialect: return "dialect";
        case Category::references: return "references";
        case Category::macro: return "macro";
        case Category::motion: return "motion";
    }
    return "?";
}

namespace {
// A message quotes the program; past this many characters the quote is not worth its memory.
constexpr std::size_t kMaxMessageChars = 400;
}  // namespace

bool Reporter::drop_if_full(ast::Range range) {
    if (!tally_ || tally_->limit == 0 || tally_->kept < tally_->limit) return false;
    const bool counted = !(tally_->suppressions && suppressed(*tally_->suppressions, range.begin, rule_->id, rule_->name)) &&
                         tally_->positions.insert(range.begin);
    if (counted) ++tally_->dropped;
    return true;
}

Finding& Reporter::report(ast::Range range, std::string message, std::string hint) {
    Finding f;
    f.range = range;
    f.severity = rule_->severity;
    f.rule = rule_->id;
    f.name = rule_->name;
    f.message = message.size() > kMaxMessageChars ? ast::shorten(message, kMaxMessageChars) : std::move(message);
    f.hint = hint.size() > kMaxMessageChars ? ast::shorten(hint, kMaxMessageChars) : std::move(hint);
    if (drop_if_full(range)) {   // past the cap: counted there, kept nowhere
        scratch_ = std::move(f);
        return scratch_;
    }
    if (tally_) {
        const bool kept = !(tally_->suppressions && suppressed(*tally_->suppressions, f)) && tally_->positions.insert(range.begin);
        if (!kept) {
            scratch_ = std::move(f);
            return scratch_;
        }
        ++tally_->kept;
    }
    out_->push_back(std::move(f));
    return out_->back();
}

}  // namespace kerf::analyzer
