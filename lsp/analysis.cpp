#include "lsp/analysis.hpp"

#include <algorithm>
#include <charconv>
#include <exception>
#include <unordered_map>

#include "analyzer/analyze.hpp"
#include "analyzer/baseline.hpp"
#include "project/check.hpp"
#include "references/references.hpp"

namespace kerf::lsp {

namespace {

using interpreter::Event;
using interpreter::EventKind;

bool is_move(EventKind k) {
    return k == EventKind::rapid || k == EventKind::linear || k == EventKind::arc_cw || k == EventKind::arc_ccw ||
           k == EventKind::thread;
}

// What the dry run does, block by block, for the checked file (events of other files are
// subprograms loaded from the folder: they are checked when they are opened).
class Collector : public interpreter::EventSink {
public:
    Collector(const Document& doc, DryRun& run) : doc_(doc), run_(run) {
        run_.state_of_block.assign(doc.tree().block_count(), -1);
        for (const ast::Expr& e : doc.tree().exprs) {
            if (macro_blocks_.empty()) macro_blocks_.resize(doc.tree().block_count());
            macro_blocks_[doc.block_at(e.begin)] = true;
        }
    }
    bool has_macro() const { return !macro_blocks_.empty(); }

    // The values of a block's variables and expression words, the first time it ran (RunOptions::after_block).
    void after_block(const interpreter::SourceRef& where, interpreter::macro::Variables& variables, const interpreter::macro::Options& options) {
        if (where.file != 0) return;
        const std::uint32_t block = doc_.block_at(where.range.begin);
        if (block >= macro_blocks_.size() || !macro_blocks_[block] || run_.macro_values.count(block)) return;
        std::vector<MacroValue>& out = run_.macro_values[block];
        const ast::SyntaxTree& tree = doc_.tree();
        const auto add = [&](ast::Range range, std::int64_t variable, const interpreter::macro::Value& v) {
            out.push_back({range, variable, v.is_vacant(), v.or_zero()});
        };
        // The block's expression nodes: the tree keeps them in text order from block to block.
        const ast::Range r = tree.block_range(block);
        const auto first = std::partition_point(tree.exprs.begin(), tree.exprs.end(), [&](const ast::Expr& e) { return e.begin < r.begin; });
        const auto last = std::partition_point(first, tree.exprs.end(), [&](const ast::Expr& e) { return e.begin < r.end; });
        for (auto it = first; it != last; ++it) {
            if (it->kind != ast::ExprKind::variable) continue;
            const auto number = interpreter::macro::variable_number(tree, static_cast<std::int32_t>(it - tree.exprs.begin()), variables, options);
            if (!number.ok()) continue;
            if (const auto v = variables.read(number.number)) add(it->range(), number.number, *v);
        }
        for (const ast::Token& t : tree.block_tokens(block)) {
            if ((t.kind != ast::TokenKind::word && t.kind != ast::TokenKind::comma_word) || !t.has(ast::token_flags::value_expr)) continue;
            const interpreter::macro::Result v = interpreter::macro::evaluate(tree, static_cast<std::int32_t>(t.payload), variables, options);
            if (v.ok()) add(tree.exprs[t.payload].range(), -1, v.value);
        }
    }

    void on_event(const Event& e) override {
        const bool here = e.source.file == 0;
        const std::uint32_t block = here ? doc_.block_at(e.source.range.begin) : 0;
        if (e.kind == EventKind::state) {
            if (here) state(block, e);
            return;
        }
        if (e.kind == EventKind::alarm && here) run_.alarms.emplace_back(block, e.text);
        if (e.kind == EventKind::end) run_.completed = true;
        if (!is_move(e.kind) && e.kind != EventKind::dwell) return;
        add(run_.total, e);
        if (!here) return;
        if (const auto program = references::program_of_block(doc_.typed(), block)) add(run_.programs[*program], e);
        if (motion_.empty()) motion_.resize(run_.state_of_block.size());   // a flat table: nearly every block of a CAM program moves
        BlockMotion& m = motion_[block];
        if (e.kind == EventKind::rapid) ++m.rapids;
        else if (e.kind != EventKind::dwell) ++m.feeds;
        m.time_s += e.time_s;
        m.length_mm += e.length_mm;
    }

    void finish() {
        for (std::uint32_t block = 0; block < motion_.size(); ++block)
            if (motion_[block].rapids + motion_[block].feeds > 1) run_.motion.emplace(block, motion_[block]);
        motion_ = {};
    }

private:
    static void add(ProgramRun& p, const Event& e) {
        p.time_s += e.time_s;
        if (e.kind == EventKind::rapid) p.rapid_mm += e.length_mm;
        else p.feed_mm += e.length_mm;
        p.time_per_tool[e.tool] += e.time_s;
        p.length_per_tool[e.tool] += e.length_mm;
    }

    // The state event's text is "G00 G18 ... F<feed> S<speed> T<tool>" (interpreter/executor.cpp
    // emit_state); flow's structured state event replaces this parsing (NOTICES.md).
    void state(std::uint32_t block, const Event& e) {
        std::int32_t& slot = run_.state_of_block[block];
        if (slot >= 0) {
            ++run_.states[static_cast<std::size_t>(slot)].runs;
            return;
        }
        auto [it, added] = modal_ids_.emplace(e.text, static_cast<std::uint32_t>(run_.modal_texts.size()));
        if (added) run_.modal_texts.push_back(e.text);
        BlockState s;
        s.position = e.end;
        s.feed = e.feed;
        s.spindle = e.spindle_rpm;
        s.tool = e.tool;
        s.tool_offset = e.code;
        s.modal = it->second;
        s.runs = 1;
        slot = static_cast<std::int32_t>(run_.states.size());
        run_.states.push_back(s);
    }

    const Document& doc_;
    DryRun& run_;
    std::vector<bool> macro_blocks_;   // blocks with macro expressions (empty: none in the document)
    std::unordered_map<std::string, std::uint32_t> modal_ids_;
    std::vector<BlockMotion> motion_;   // per block of the document
};

// The findings a baseline accepts are not shown (kerf check --baseline): matched by rule and the
// text of their block, each entry once.
void apply_baseline(std::vector<analyzer::Finding>& findings, const Document& doc) {
    if (doc.settings().baseline.empty()) return;
    analyzer::BaselineFilter filter(doc.settings().baseline);
    std::erase_if(findings, [&](const analyzer::Finding& f) {
        return filter.accepts({doc.settings().baseline.front().file, f.rule, analyzer::block_text(doc.tree(), f.range.begin)});
    });
}

}  // namespace

AnalysisWorker::AnalysisWorker(ProjectSeam& project, Publish publish)
    : project_(project), publish_(std::move(publish)), thread_([this] { work(); }) {}

AnalysisWorker::~AnalysisWorker() {
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
        cancel_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

void AnalysisWorker::schedule(std::shared_ptr<const Document> document) {
    const std::string uri = document->uri();
    {
        const std::lock_guard lock(mutex_);
        if (!pending_.count(uri)) order_.push_back(uri);
        // The last analysis is of an older version, which no feature shows (Snapshot): its dry
        // run goes now, not when the new one is done (two of them for a long file: bench/RESULTS.md).
        if (const auto it = results_.find(uri); it != results_.end() && it->second->version != document->version()) results_.erase(it);
        pending_[uri] = std::move(document);
        if (running_ == uri) cancel_ = true;
    }
    changed_.notify_all();
}

void AnalysisWorker::forget(const std::string& uri) {
    const std::lock_guard lock(mutex_);
    pending_.erase(uri);
    std::erase(order_, uri);
    results_.erase(uri);
    incremental_.erase(uri);
    if (running_ == uri) cancel_ = true;
}

void AnalysisWorker::release(const std::string& uri) {
    std::unique_lock lock(mutex_);
    pending_.erase(uri);
    std::erase(order_, uri);
    if (running_ == uri) cancel_ = true;
    changed_.wait(lock, [&] { return running_ != uri; });
}

std::shared_ptr<const Analysis> AnalysisWorker::latest(const std::string& uri) const {
    const std::lock_guard lock(mutex_);
    const auto it = results_.find(uri);
    return it == results_.end() ? nullptr : it->second;
}

void AnalysisWorker::wait_idle() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return stop_ || (order_.empty() && !busy_); });
}

void AnalysisWorker::work() {
    while (true) {
        std::shared_ptr<const Document> doc;
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [&] { return stop_ || !order_.empty(); });
            if (stop_) return;
            const std::string uri = order_.front();
            order_.pop_front();
            doc = std::move(pending_[uri]);
            pending_.erase(uri);
            running_ = uri;
            cancel_ = false;
            busy_ = true;
        }
        analyse(doc);
        doc.reset();   // before the uri is free: release() then finds the version unshared
        {
            const std::lock_guard lock(mutex_);
            running_.clear();
            busy_ = false;
        }
        changed_.notify_all();
    }
}

bool AnalysisWorker::superseded(const Document&) const { return cancel_.load(); }

// The static rules in two shares on two threads (a whole walk of a million-line program after
// didOpen takes half the time); the findings of both, or nullopt when the walk was cancelled.
std::optional<std::vector<analyzer::Finding>> AnalysisWorker::check_static_shares(Incremental& incremental,
                                                                                  const analyzer::IncrementalStatic::Input& input) {
    analyzer::IncrementalStatic::Input other = input;
    other.shard = 1;
    std::optional<std::vector<analyzer::Finding>> second;
    std::exception_ptr failed;
    std::thread helper([&] {
        try {
            second = incremental.second.check(other);
        } catch (...) {
            failed = std::current_exception();
        }
    });
    std::optional<std::vector<analyzer::Finding>> first;
    try {
        first = incremental.check.check(input);
    } catch (...) {
        helper.join();
        throw;
    }
    helper.join();
    if (failed) std::rethrow_exception(failed);
    if (!first || !second) return std::nullopt;
    first->insert(first->end(), std::make_move_iterator(second->begin()), std::make_move_iterator(second->end()));
    return first;
}

void AnalysisWorker::analyse(const std::shared_ptr<const Document>& doc) {
    auto analysis = std::make_shared<Analysis>();
    analysis->version = doc->version();
    if (!doc->refused().empty() || !doc->settings().dialect) {
        publish_(*doc, *analysis, true);
        return;
    }
    const FileSettings& s = doc->settings();
    interpreter::ProgramSet programs;
    const std::uint32_t file = programs.add_parsed(doc->path().string(), doc, doc->typed(), doc->lines());
    programs.set_loader(project_.loader_for(doc->path()), s.dialect);
    // As kerf check takes them (project/check.hpp), with the dialect and machine this document uses.
    project::Resolved resolved = s.resolved;
    resolved.dialect = s.dialect;
    resolved.setup = &s.setup;
    analyzer::CheckOptions options = resolved.project ? project::project_check_options(resolved, programs, file, doc->path().string())
                                                      : analyzer::CheckOptions{};
    options.config = s.check;
    options.time_limit = s.time_limit;
    options.program_files = [this, path = doc->path()](std::int64_t n) { return project_.program_files(n, path); };
    const auto exists = [&](std::int64_t n) {
        return references::program_numbered(doc->typed(), n).has_value() || project_.find_program(n, doc->path(), false).has_value();
    };
    if (std::optional<std::vector<analyzer::Finding>> foreign = analyzer::check_foreign(programs, file, options)) {
        // Another control's program (K2009): that one finding, as kerf check says it; no dry run.
        analysis->findings = std::move(*foreign);
        apply_baseline(analysis->findings, *doc);
        publish_(*doc, *analysis, true);
        return;
    }
    std::shared_ptr<Incremental> incremental;
    {
        const std::lock_guard lock(mutex_);
        std::shared_ptr<Incremental>& slot = incremental_[doc->uri()];
        if (!slot) slot = std::make_shared<Incremental>();
        incremental = slot;
    }
    // The static findings: walked again only where the edits since the last analysis changed them.
    const bool same_settings = incremental->settings.get() == doc->settings_ptr().get();
    const analyzer::IncrementalStatic::Input input{programs, file, *s.dialect, s.setup, options, exists, project_.generation(),
                                                   same_settings ? doc->edits_since(incremental->serial) : std::nullopt, &cancel_, 0, 2};
    std::optional<std::vector<analyzer::Finding>> checked = check_static_shares(*incremental, input);
    incremental->serial = doc->serial();
    incremental->settings = doc->settings_ptr();
    if (!checked || superseded(*doc)) return;
    std::vector<analyzer::Finding> raw = std::move(*checked);
    {
        Analysis first;
        first.version = doc->version();
        first.findings = raw;
        analyzer::finish_findings(first.findings, doc->tree(), doc->lines(), options);
        apply_baseline(first.findings, *doc);
        publish_(*doc, first, false);
    }
    auto run = std::make_shared<DryRun>();
    Collector collector(*doc, *run);
    analyzer::DryRunHooks hooks;
    hooks.observer = &collector;
    hooks.emit_state = true;
    hooks.cancel = &cancel_;
    if (collector.has_macro())
        hooks.after_block = [&collector](const interpreter::SourceRef& block, interpreter::macro::Variables& variables,
                                         const interpreter::macro::Options& macro) { collector.after_block(block, variables, macro); };
    std::optional<std::vector<analyzer::Finding>> dynamic = analyzer::check_dry_run(programs, file, *s.dialect, s.setup, options, hooks);
    if (!dynamic || superseded(*doc)) return;
    collector.finish();
    raw.insert(raw.end(), std::make_move_iterator(dynamic->begin()), std::make_move_iterator(dynamic->end()));
    analyzer::finish_findings(raw, doc->tree(), doc->lines(), options);
    apply_baseline(raw, *doc);
    analysis->findings = std::move(raw);
    analysis->run = std::move(run);
    {
        const std::lock_guard lock(mutex_);
        if (cancel_) return;
        results_[doc->uri()] = analysis;
    }
    publish_(*doc, *analysis, true);
}

}  // namespace kerf::lsp
