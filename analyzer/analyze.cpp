#include "analyzer/analyze.hpp"

#include <iterator>
#include <thread>

#include <algorithm>
#include <map>
#include <unordered_set>

#include <fmt/format.h>

#include "analyzer/arguments.hpp"
#include "analyzer/static_walk.hpp"
#include "analyzer/suppress.hpp"
#include "dialects/alarms.hpp"
#include "interpreter/interpreter.hpp"

namespace kerf::analyzer {

namespace detail {

namespace {
bool active(const ActiveRules& rules, const Rule* r) { return r && std::find(rules.begin(), rules.end(), r) != rules.end(); }
}  // namespace

void map_diagnostics(const ast::SyntaxTree& tree, const std::vector<ast::Diagnostic>& diagnostics, const Registry& registry,
                     const ActiveRules& rules, const std::function<RuleTally*(const Rule&)>& tally_of, std::vector<Finding>& out) {
    for (const ast::Diagnostic& d : diagnostics) {
        const Rule* rule = registry.for_diagnostic(d.code);
        if (!active(rules, rule)) continue;
        Reporter reporter(*rule, out, tally_of(*rule));
        Finding& f = reporter.report(d.range, d.message, d.hint);
        f.notes.push_back("parser diagnostic " + d.code + " (docs/diagnostics.md)");
        if (rule->diagnostic_fix) f.fix = rule->diagnostic_fix(tree, d);
    }
}

ActiveRules active_rules(const Registry& registry, const CheckConfig& config) {
    ActiveRules rules;
    for (const Rule& r : registry.rules())
        if (config.enabled(r)) rules.push_back(&r);
    return rules;
}

const Registry& registry_of(const CheckOptions& options) { return options.registry ? *options.registry : builtin_rules(); }

void run_program_checks(const FileContext& ctx, const ActiveRules& rules, const std::function<RuleTally*(const Rule&)>& tally_of,
                        std::vector<Finding>& out) {
    for (const Rule* r : rules) {
        if (!r->program_check) continue;
        Reporter reporter(*r, out, tally_of(*r));
        for (std::size_t p = 0; p < ctx.typed.programs().size(); ++p) r->program_check->program(ctx, p, reporter);
    }
}

}  // namespace detail

namespace {

using detail::active;
using detail::active_rules;
using detail::map_diagnostics;
using detail::registry_of;

using detail::ActiveRules;
using detail::modal_code;
using detail::StaticRun;

// One tally per rule for one side of the check (the static rules and the parser's diagnostics on
// the calling thread, the dry run on its own): see RuleTally.
class Tallies {
public:
    Tallies(std::size_t limit, const std::vector<Suppression>& suppressions) : limit_(limit), suppressions_(suppressions) {}
    RuleTally* of(const Rule& rule) {
        RuleTally& t = tallies_[&rule];
        t.limit = limit_;
        t.suppressions = &suppressions_;
        return &t;
    }
    const std::map<const Rule*, RuleTally>& all() const { return tallies_; }

private:
    std::size_t limit_;
    const std::vector<Suppression>& suppressions_;
    std::map<const Rule*, RuleTally> tallies_;
};

std::function<RuleTally*(const Rule&)> tally_of(Tallies& tallies) {
    return [&tallies](const Rule& rule) { return tallies.of(rule); };
}

// Every static check sees every code block once, in text order, with the codes computed once.
// The program checks after them, unless the caller runs them (check_file: on the thread done first).
void run_static(const FileContext& ctx, const ActiveRules& rules, Tallies& tallies, std::vector<Finding>& out,
                const std::atomic<bool>* cancel = nullptr, bool program_checks = true) {
    std::vector<StaticRun> checks;
    for (const Rule* r : rules)
        if (r->make_static) checks.push_back({r, r->make_static(), Reporter(*r, out, tallies.of(*r))});
    detail::BlockStep step;
    const std::vector<ast::Program>& programs = ctx.typed.programs();
    for (std::size_t p = 0; p < programs.size() && !checks.empty(); ++p) {
        ModalState modal(ctx.dialect, ctx.setup.power_on);
        for (StaticRun& c : checks) c.check->begin_program(ctx, p, c.out);
        for (std::uint32_t b = programs[p].first_block; b < programs[p].end_block; ++b) {
            if (cancel && (b & 4095) == 0 && cancel->load(std::memory_order_relaxed)) return;
            step(ctx, checks, modal, p, b);
        }
        for (StaticRun& c : checks) c.check->end_program(ctx, p, c.out);
    }
    if (program_checks) detail::run_program_checks(ctx, rules, tally_of(tallies), out);
}

// The sink of the dry run: each event to every dynamic check, alarms to the rule that owns their
// number. Findings about other files (a subprogram loaded from the folder) are dropped: that file
// is checked on its own. State events (asked for by an observer) go to the observer only.
class FanOut : public interpreter::EventSink {
public:
    FanOut(const RunContext& run, const Registry& registry, const ActiveRules& rules, Tallies& tallies,
           std::vector<Finding>& out, const DryRunHooks& hooks, const CheckOptions& check)
        : run_(run), registry_(registry), rules_(rules), tallies_(tallies), out_(out), hooks_(hooks) {
        for (const Rule* r : rules)
            if (r->make_dynamic) checks_.push_back({r->make_dynamic(), Reporter(*r, out, tallies.of(*r))});
        own_guards_ = guards_own_inputs(check);
    }
    void on_event(const interpreter::Event& e) override {
        if (hooks_.observer) hooks_.observer->on_event(e);
        if (e.kind == interpreter::EventKind::state) return;
        const std::size_t before = out_.size();
        for (DynamicRun& c : checks_) c.check->event(run_, e, c.out);
        if (e.kind == interpreter::EventKind::alarm) report_alarm(e);
        if (e.source.file != run_.checked_file) out_.resize(before);
    }
    void finish() {
        for (DynamicRun& c : checks_) c.check->finish(run_, c.out);
    }

private:
    struct DynamicRun {
        std::unique_ptr<DynamicCheck> check;
        Reporter out;
    };
    void report_alarm(const interpreter::Event& e) {
        const Rule* rule = registry_.for_alarm(e.code);
        if (!active(rules_, rule)) return;
        if (own_guards_ && e.code >= alarms::user_alarm_first && e.code <= alarms::user_alarm_last &&
            e.source.file == run_.checked_file && own_guards_->first <= e.source.range.begin &&
            e.source.range.begin < own_guards_->second)
            return;   // the macro's own check of a missing argument: no caller gave it any
        const ast::SyntaxTree& tree = *run_.programs.file(e.source.file).whole_tree();
        Reporter reporter(*rule, out_, tallies_.of(*rule));
        Finding& f = reporter.report(trim_range(tree, e.source.range), e.text);
        f.notes.push_back("found by the dry run: the control stops here with an alarm");
    }
    // The bytes of the checked program when it is a macro run without a caller, or a program whose
    // inputs are common variables set elsewhere: a #3000 alarm it raises there is its guard for a
    // missing argument or input (IF [#1 EQ #0] THEN #3000=...; 01000.nc's dispatcher when #101 is
    // none of its cases), the program's own check, not a defect (issue 15). nullopt: the program
    // takes no arguments or inputs, or a caller is known.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> guards_own_inputs(const CheckOptions& check) const {
        const interpreter::LoadedFile& loaded = run_.programs.file(run_.checked_file);
        const ast::TypedFile& typed = *loaded.whole_typed();
        if (typed.programs().empty()) return std::nullopt;
        // The program's own tests first (its header, its reads: no walk at all for a program
        // without expressions), the callers after: finding them walks every block of the file,
        // which delayed the dry run of a 100 MB CAM program by 65 ms (bench/RESULTS.md).
        if (documented_arguments(typed, 0).none() && argument_reads(typed, 0).none() && !reads_common_inputs(typed, 0))
            return std::nullopt;
        if (program_arguments(typed, 0, check.caller_arguments).caller_known) return std::nullopt;
        const ast::Program& p = typed.programs()[0];
        const ast::SyntaxTree& tree = typed.tree();
        const std::uint32_t end = p.end_block < tree.block_count() ? tree.blocks[p.end_block].begin
                                                                   : static_cast<std::uint32_t>(tree.text.size());
        return std::pair{tree.blocks[p.first_block].begin, end};
    }
    const RunContext& run_;
    const Registry& registry_;
    const ActiveRules& rules_;
    Tallies& tallies_;
    std::vector<Finding>& out_;
    const DryRunHooks& hooks_;
    std::vector<DynamicRun> checks_;
    std::optional<std::pair<std::uint32_t, std::uint32_t>> own_guards_;
};

bool needs_run(const ActiveRules& rules) {
    return std::any_of(rules.begin(), rules.end(), [](const Rule* r) { return r->make_dynamic || !r->alarms.empty(); });
}

// False when cancelled.
bool run_dynamic(interpreter::ProgramSet& programs, std::uint32_t file, const dialects::Dialect& dialect,
                 const interpreter::Setup& setup, const Registry& registry, const ActiveRules& rules,
                 const CheckOptions& check, Tallies& tallies, std::vector<Finding>& out, const DryRunHooks& hooks = {}) {
    const std::optional<interpreter::ProgramRef> main = check.main ? check.main : programs.first_program(file);
    if (!main || (!needs_run(rules) && !hooks.observer)) return true;
    const RunContext run{programs, file, dialect, setup};
    FanOut sink(run, registry, rules, tallies, out, hooks, check);
    interpreter::RunOptions options = check.run;
    options.lenient = true;   // syntax defects are the syntax rules' findings; go on and check the rest
    options.time_limit = check.time_limit;
    options.emit_state = hooks.emit_state;
    options.after_block = hooks.after_block;
    options.resident = check.resident;
    options.cancel = hooks.cancel;
    if (interpreter::run(programs, *main, dialect, setup, sink, options).cancelled) return false;
    sink.finish();
    return true;
}

// At most `limit` findings of a rule in the file (the first ones in text order); the others,
// counted here and by the tallies, become one "and N more" finding after the last one shown.
void cap_per_rule(std::vector<Finding>& findings, std::size_t limit, const std::vector<const Tallies*>& tallies) {
    std::map<std::string, std::size_t> shown, more;
    std::map<std::string, ast::Range> last;
    std::erase_if(findings, [&](const Finding& f) {
        if (limit > 0 && ++shown[f.rule] > limit) {
            ++more[f.rule];
            return true;
        }
        last[f.rule] = f.range;
        return false;
    });
    std::map<std::string, const Rule*> rules;
    for (const Tallies* t : tallies)
        for (const auto& [rule, tally] : t->all()) {
            if (tally.dropped > 0) more[rule->id] += tally.dropped;
            rules[rule->id] = rule;
        }
    for (const auto& [id, count] : more) {
        if (count == 0 || !rules.count(id)) continue;
        Finding f;
        f.range = last.count(id) ? last[id] : ast::Range{};
        f.severity = Severity::info;
        f.rule = id;
        f.name = rules[id]->name;
        f.message = fmt::format("and {} more finding{} of {} in this file, not shown", count, count == 1 ? "" : "s", id);
        f.hint = fmt::format("at most {} findings per rule and file are shown (--max-findings-per-rule; 0 shows all)", limit);
        findings.push_back(std::move(f));
    }
}


// Suppressed findings out, configured severities in, one finding per rule and line (a static rule
// and the dry run may both see the same defect), sorted by position.
void finalize(std::vector<Finding>& findings, const std::vector<Suppression>& suppressions, const ast::LineIndex& lines,
              const Registry& registry, const CheckConfig& config) {
    std::erase_if(findings, [&](const Finding& f) { return suppressed(suppressions, f); });
    for (Finding& f : findings)
        if (const Rule* r = registry.find(f.rule)) f.severity = config.severity(*r);
    std::stable_sort(findings.begin(), findings.end(), [](const Finding& a, const Finding& b) {
        return a.range.begin != b.range.begin ? a.range.begin < b.range.begin : a.rule < b.rule;
    });
    // A static rule and the dry run may report the same defect on one line: keep the static one.
    const auto from_run = [](const Finding& f) { return !f.notes.empty() && f.notes.front().starts_with("found by the dry run"); };
    std::unordered_set<std::string> static_lines, seen;
    const auto line_key = [&](const Finding& f) { return f.rule + ":" + std::to_string(lines.utf8(f.range.begin).line); };
    // A static finding that explains the dry run's alarm on its line (K3003: the program is missing,
    // so the run stops with alarm 078) hides the alarm's finding: one defect, one finding.
    std::multimap<std::uint32_t, const Rule*> explanations;   // line → static rule that explains alarms there
    for (const Finding& f : findings) {
        if (from_run(f)) continue;
        static_lines.insert(line_key(f));
        if (const Rule* r = registry.find(f.rule); r && !r->explains.empty()) explanations.emplace(lines.utf8(f.range.begin).line, r);
    }
    const auto explained = [&](const Finding& f) {
        const Rule* alarm_rule = registry.find(f.rule);
        if (!alarm_rule || alarm_rule->alarms.empty()) return false;
        const auto [lo, hi] = explanations.equal_range(lines.utf8(f.range.begin).line);
        for (auto it = lo; it != hi; ++it)
            for (const auto& [first, last] : it->second->explains)
                for (const auto& [alarm_first, alarm_last] : alarm_rule->alarms)
                    if (first <= alarm_last && alarm_first <= last) return true;
        return false;
    };
    std::erase_if(findings, [&](const Finding& f) {
        if (from_run(f) && (static_lines.count(line_key(f)) || explained(f))) return true;
        return !seen.insert(f.rule + ":" + std::to_string(f.range.begin)).second;
    });
}

}  // namespace

ast::Range trim_range(const ast::SyntaxTree& tree, ast::Range range) {
    while (range.end > range.begin) {
        const char c = tree.text[range.end - 1];
        if (c != '\n' && c != '\r' && c != ' ' && c != '\t') break;
        --range.end;
    }
    return range;
}

std::vector<Finding> check_static(const interpreter::ProgramSet& programs, std::uint32_t file, const dialects::Dialect& dialect,
                                  const interpreter::Setup& setup, const CheckOptions& options,
                                  std::function<bool(std::int64_t)> program_exists, const std::atomic<bool>* cancel) {
    const Registry& registry = registry_of(options);
    const ActiveRules rules = active_rules(registry, options.config);
    const interpreter::LoadedFile& loaded = programs.file(file);
    const ast::SyntaxTree& tree = *loaded.whole_tree();
    const ast::TypedFile& typed = *loaded.whole_typed();
    if (!program_exists) {
        const interpreter::ProgramSet::Loader loader = programs.loader();
        program_exists = [&loaded, loader](std::int64_t n) { return loaded.find_program(n).has_value() || (loader && loader(n).has_value()); };
    }
    std::vector<Finding> out;
    // Uncapped here: finish_findings caps the phases' findings together (as check_file does).
    const std::vector<Suppression> suppressions = find_suppressions(tree);
    Tallies tallies(0, suppressions);
    FileContext ctx{typed, dialect, setup, std::move(program_exists), options.program_files};
    ctx.resident = options.resident;
    ctx.caller_arguments = options.caller_arguments;
    run_static(ctx, rules, tallies, out, cancel);
    map_diagnostics(tree, tree.diagnostics, registry, rules, tally_of(tallies), out);
    map_diagnostics(tree, typed.diagnostics(), registry, rules, tally_of(tallies), out);
    return out;
}

std::optional<std::vector<Finding>> check_dry_run(interpreter::ProgramSet& programs, std::uint32_t file,
                                                  const dialects::Dialect& dialect, const interpreter::Setup& setup,
                                                  const CheckOptions& options, const DryRunHooks& hooks) {
    const Registry& registry = registry_of(options);
    const std::vector<Suppression> suppressions = find_suppressions(*programs.file(file).whole_tree());
    Tallies tallies(0, suppressions);
    std::vector<Finding> out;
    if (!run_dynamic(programs, file, dialect, setup, registry, active_rules(registry, options.config), options, tallies, out, hooks))
        return std::nullopt;
    return out;
}

void finish_findings(std::vector<Finding>& findings, const ast::SyntaxTree& tree, const ast::LineIndex& lines,
                     const CheckOptions& options) {
    const Registry& registry = registry_of(options);
    const std::vector<Suppression> suppressions = find_suppressions(tree);
    finalize(findings, suppressions, lines, registry, options.config);
    // The rules of the findings, so that a cap says "and N more" for each (nothing was dropped earlier).
    Tallies seen(0, suppressions);
    for (const Finding& f : findings)
        if (const Rule* r = registry.find(f.rule)) seen.of(*r);
    cap_per_rule(findings, options.max_findings_per_rule, {&seen});
}

namespace {

// A program of another control (CheckOptions::foreign): one finding, nothing read as FANUC.
std::optional<std::vector<Finding>> foreign_control(const ast::SyntaxTree& tree, const ast::LineIndex& lines,
                                                    const Registry& registry, const ActiveRules& rules,
                                                    const CheckOptions& options) {
    const Rule* rule = registry.find("foreign-control");
    if (!options.foreign || !active(rules, rule)) return std::nullopt;
    const ForeignControl& f = *options.foreign;
    std::uint32_t at = 0;
    if (f.line > 0 && f.line <= lines.line_count()) at = lines.line_start(f.line - 1) + (f.column > 0 ? f.column - 1 : 0);
    at = std::min<std::uint32_t>(at, static_cast<std::uint32_t>(tree.text.size()));
    std::uint32_t end = at;
    while (end < tree.text.size() && tree.text[end] != '\n' && tree.text[end] != '\r') ++end;
    std::vector<Finding> out;
    Reporter reporter(*rule, out);
    Finding& finding = reporter.report({at, end},
                                       fmt::format("this looks like a {} program; kerf reads FANUC-family dialects", f.name),
                                       "check it with the tools of that control, or name a FANUC-family dialect (--dialect, "
                                       ".kerf.toml `dialect`) if it is one");
    if (!f.evidence.empty()) finding.notes.push_back(fmt::format("{}: {}", f.evidence, f.proves));
    finding.notes.push_back("kerf parse --explain-dialect lists all the evidence");
    return out;
}

}  // namespace

std::optional<std::vector<Finding>> check_foreign(const interpreter::ProgramSet& programs, std::uint32_t file,
                                                  const CheckOptions& options) {
    const Registry& registry = registry_of(options);
    const interpreter::LoadedFile& loaded = programs.file(file);
    auto foreign = foreign_control(*loaded.whole_tree(), *loaded.whole_lines(), registry, active_rules(registry, options.config), options);
    if (foreign) finalize(*foreign, find_suppressions(*loaded.whole_tree()), *loaded.whole_lines(), registry, options.config);
    return foreign;
}

std::vector<Finding> check_file(interpreter::ProgramSet& programs, std::uint32_t file, const dialects::Dialect& dialect,
                                const interpreter::Setup& setup, const CheckOptions& options) {
    const Registry& registry = registry_of(options);
    const ActiveRules rules = active_rules(registry, options.config);
    if (auto foreign = check_foreign(programs, file, options)) return *std::move(foreign);
    std::vector<Finding> out;
    // The analyzer reads files given whole (ProgramSet::add): the static rules walk every block.
    const interpreter::LoadedFile& loaded = programs.file(file);
    const ast::SyntaxTree& tree = *loaded.whole_tree();
    const ast::TypedFile& typed = *loaded.whole_typed();
    // A long file: the dry run on a second thread while the static rules walk the tree (both only
    // read it). Then only the dry run may add files to the set, so the static rules ask this file
    // and the loader (the folder) directly instead of ProgramSet::find_or_load.
    const bool parallel = options.dry_run && tree.text.size() >= options.parallel_from_bytes && needs_run(rules);
    std::vector<Finding> dynamic;
    const std::vector<Suppression> suppressions = find_suppressions(tree);
    Tallies static_tallies(options.max_findings_per_rule, suppressions);
    Tallies dynamic_tallies(options.max_findings_per_rule, suppressions);
    const auto dry_run = [&] {
        run_dynamic(programs, file, dialect, setup, registry, rules, options, dynamic_tallies, dynamic);
    };
    const interpreter::ProgramSet::Loader loader = programs.loader();
    FileContext ctx{typed, dialect, setup, [&](std::int64_t n) {
                        if (!parallel) return programs.find_or_load(n, file).has_value();
                        return loaded.find_program(n).has_value() || (loader && loader(n).has_value());
                    },
                    options.program_files};
    ctx.resident = options.resident;
    ctx.caller_arguments = options.caller_arguments;
    // The program checks (a CAM program's label table: 0.24 s of 100 MB, at the end of the static
    // walk, which ends last) go to whichever thread is done first (finalize sorts the findings).
    std::atomic<bool> program_checks_taken{false};
    Tallies program_tallies(options.max_findings_per_rule, suppressions);
    std::vector<Finding> program_findings;
    const auto program_checks = [&] {
        if (!program_checks_taken.exchange(true)) detail::run_program_checks(ctx, rules, tally_of(program_tallies), program_findings);
    };
    std::thread run_thread;
    if (parallel) run_thread = std::thread([&] {
        dry_run();
        program_checks();
    });
    run_static(ctx, rules, static_tallies, out, nullptr, !parallel);
    if (parallel) program_checks();
    map_diagnostics(tree, tree.diagnostics, registry, rules, tally_of(static_tallies), out);
    map_diagnostics(tree, typed.diagnostics(), registry, rules, tally_of(static_tallies), out);
    if (parallel) run_thread.join();
    else if (options.dry_run) dry_run();
    out.insert(out.end(), std::make_move_iterator(program_findings.begin()), std::make_move_iterator(program_findings.end()));
    out.insert(out.end(), std::make_move_iterator(dynamic.begin()), std::make_move_iterator(dynamic.end()));
    finalize(out, suppressions, *loaded.whole_lines(), registry, options.config);
    cap_per_rule(out, options.max_findings_per_rule, {&static_tallies, &dynamic_tallies, &program_tallies});
    return out;
}

std::vector<Finding> check_text(std::string name, std::string text, const dialects::Dialect& dialect,
                                const interpreter::Setup& setup, const CheckOptions& options) {
    interpreter::ProgramSet programs;
    const std::uint32_t file = programs.add(std::move(name), std::move(text), dialect);
    return check_file(programs, file, dialect, setup, options);
}

ModalState::ModalState(const dialects::Dialect& dialect, const std::vector<dialects::FunctionId>& power_on) {
    for (const dialects::CodeInfo& c : dialect.codes()) {
        if (!modal_code(c)) continue;
        const auto slot = std::find_if(slots_.begin(), slots_.end(), [&](const Slot& s) { return s.first == c.group; });
        const dialects::CodeInfo* active = c.power_on_default ? &c : nullptr;
        if (slot == slots_.end()) slots_.emplace_back(c.group, active);
        else if (active) slot->second = active;
    }
    for (const dialects::FunctionId function : power_on)
        for (const dialects::CodeInfo* c : dialect.codes_with_function(function))
            if (modal_code(*c)) set(*c);
}

bool ModalState::has_trait(std::uint32_t trait) const {
    return std::any_of(slots_.begin(), slots_.end(), [&](const Slot& s) { return s.second && s.second->has(trait); });
}

void ModalState::set(const dialects::CodeInfo& code) {
    for (Slot& s : slots_)
        if (s.first == code.group) {
            s.second = &code;
            return;
        }
    slots_.emplace_back(code.group, &code);   // a code of a group the dialect table did not list (user dialect)
}

namespace {
bool number_before(const LabelTable::Entry& a, const LabelTable::Entry& b) { return a.number() < b.number(); }
// The entries of one label, by the integer itself (not a key entry: a double may not hold it).
struct LabelOrder {
    bool operator()(const LabelTable::Entry& e, std::int64_t n) const { return e.number() < n; }
    bool operator()(std::int64_t n, const LabelTable::Entry& e) const { return n < e.number(); }
};
}  // namespace

LabelTable::LabelTable(std::vector<Entry> entries) : sorted_(std::move(entries)) {
    // Most programs number their blocks in ascending order: then there is nothing to sort. Stable,
    // so the blocks of one number stay in block order.
    if (std::is_sorted(sorted_.begin(), sorted_.end(), number_before)) return;
    const auto [lo, hi] = std::minmax_element(sorted_.begin(), sorted_.end(), number_before);
    const std::int64_t first = lo->number();
    const std::uint64_t span = static_cast<std::uint64_t>(hi->number() - first) + 1;
    if (span > 4 * sorted_.size() + 65536) {
        std::stable_sort(sorted_.begin(), sorted_.end(), number_before);
        return;
    }
    // CAM output whose N numbers wrap (a million blocks, N10 to N99990 over and over): a counting
    // sort over the few numbers, stable, in two passes, instead of a merge sort of the entries.
    std::vector<std::uint32_t> start(span + 1, 0);
    for (const Entry& e : sorted_) ++start[static_cast<std::size_t>(e.number() - first) + 1];
    for (std::size_t i = 1; i <= span; ++i) start[i] += start[i - 1];
    std::vector<Entry> out(sorted_.size());
    for (const Entry& e : sorted_) out[start[static_cast<std::size_t>(e.number() - first)]++] = e;
    sorted_ = std::move(out);
}

std::pair<std::vector<LabelTable::Entry>::const_iterator, std::vector<LabelTable::Entry>::const_iterator>
LabelTable::range(std::int64_t n) const {
    return std::equal_range(sorted_.begin(), sorted_.end(), n, LabelOrder{});
}

int LabelTable::count(std::int64_t n) const {
    const auto [lo, hi] = range(n);
    return static_cast<int>(hi - lo);
}

std::vector<std::uint32_t> LabelTable::blocks(std::int64_t n) const {
    std::vector<std::uint32_t> out;
    const auto [lo, hi] = range(n);
    for (auto it = lo; it != hi; ++it)
        if (it->value == static_cast<double>(n)) out.push_back(it->block);
    return out;
}

void LabelTable::splice(std::uint32_t first, std::uint32_t old_last, std::int64_t moved) {
    std::erase_if(sorted_, [&](const Entry& e) { return e.block >= first && e.block < old_last; });
    for (Entry& e : sorted_)
        if (e.block >= old_last) e.block = static_cast<std::uint32_t>(e.block + moved);
}

void LabelTable::replace(std::uint32_t first, std::uint32_t end, std::span<const Entry> now) {
    std::erase_if(sorted_, [&](const Entry& e) { return e.block >= first && e.block < end; });
    for (const Entry& e : now) {
        // After the entries of its number in earlier blocks, before those in later ones.
        const auto at = std::upper_bound(sorted_.begin(), sorted_.end(), e, [](const Entry& a, const Entry& b) {
            return a.number() != b.number() ? a.number() < b.number() : a.block < b.block;
        });
        sorted_.insert(at, e);
    }
}

bool JumpTargets::has(std::int64_t n) const { return std::binary_search(labels.begin(), labels.end(), n); }

std::shared_ptr<const JumpTargets> FileContext::shared_jump_targets() const {
    const std::lock_guard lock(*cache_mutex_);
    if (!targets_) {
        auto t = std::make_shared<JumpTargets>();
        t->labels = analyzer::jump_targets(tree(), t->computed);
        targets_ = std::move(t);
    }
    return targets_;
}

const JumpTargets& FileContext::jump_targets() const { return *shared_jump_targets(); }

std::optional<LabelTable::Entry> LabelTable::entry_of(const ast::TypedFile& typed, std::uint32_t block) {
    // The N value read once (sequence_label() reads it again to truncate it).
    const std::optional<double> value = typed.block(block).sequence_number();
    if (!value) return std::nullopt;
    const std::optional<std::int64_t> label = ast::truncated_integer(*value);
    if (!label) return std::nullopt;
    return Entry{*value, block};
}

void FileContext::adopt_jump_targets(std::shared_ptr<const JumpTargets> targets) const {
    const std::lock_guard lock(*cache_mutex_);
    targets_ = std::move(targets);
}

LabelTables FileContext::take_labels() const {
    const std::lock_guard lock(*cache_mutex_);
    return std::move(labels_);
}

void FileContext::adopt_labels(LabelTables labels) const {
    const std::lock_guard lock(*cache_mutex_);
    labels_ = std::move(labels);
}

// A std::map: the reference returned stays good while other programs' tables are added.
const LabelTable& FileContext::labels(std::size_t program) const {
    const std::lock_guard lock(*cache_mutex_);
    if (const auto it = labels_.find(program); it != labels_.end()) return it->second;
    std::vector<LabelTable::Entry> entries;
    const ast::Program& p = typed.programs()[program];
    // At most one entry per block: reserved once, not grown by copies (a CAM program numbers
    // every block: 5.9 million entries for 100 MB). Pages never written are never touched.
    entries.reserve(p.end_block - p.first_block);
    for (std::uint32_t b = p.first_block; b < p.end_block; ++b)
        if (const auto e = LabelTable::entry_of(typed, b)) entries.push_back(*e);
    return labels_.emplace(program, LabelTable(std::move(entries))).first->second;
}

Location locate(const ast::LineIndex& lines, ast::Range range) {
    const ast::Position b = lines.utf8(range.begin);
    const ast::Position e = lines.utf8(range.end);
    return {b.line + 1, b.column + 1, e.line + 1, e.column + 1};
}

bool BlockContext::modal_function(dialects::FunctionId function) const {
    for (const auto& [group, info] : modal)
        if (info && info->function == function) return true;
    return false;
}

}  // namespace kerf::analyzer
