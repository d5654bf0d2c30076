#include "analyzer/incremental.hpp"

#include <algorithm>
#include <string_view>

#include "analyzer/static_walk.hpp"
#include "ast/diagnostic_ids.hpp"

namespace kerf::analyzer {

namespace {

constexpr std::uint32_t kWholeText = 0xFFFFFFFFu;   // BlockSplice::old_end of a text parsed again whole

// FNV-1a over the facts, each part closed by a separator so that "N1" "0" and "N10" differ.
class Digest {
public:
    void add(std::string_view bytes) {
        for (const char c : bytes) mix(static_cast<unsigned char>(c));
        mix(0x100);
    }
    void add(std::uint64_t value) {
        for (int i = 0; i < 8; ++i) mix(value >> (8 * i) & 0xFF);
        mix(0x101);
    }
    std::uint64_t value() const { return h_; }

private:
    void mix(std::uint64_t byte) {
        h_ ^= byte;
        h_ *= 1099511628211ull;
    }
    std::uint64_t h_ = 1469598103934665603ull;
};

// Statements another block may depend on: jumps (K3001, K3002, K3007 targets) and loops.
bool jumps_or_loops(ast::StatementKind k) {
    using K = ast::StatementKind;
    return k == K::if_goto || k == K::if_then || k == K::goto_ || k == K::while_do || k == K::do_ || k == K::end;
}

// Comments K1016 and K1017 report (numbers.cpp walks every comment of a program at its start).
bool reported_comment(std::string_view s) {
    if (s.find_first_not_of("() \t") == std::string_view::npos) return true;
    return std::any_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) >= 0x80; });
}

}  // namespace

std::uint64_t static_facts(const ast::SyntaxTree& tree, std::uint32_t first_block, std::uint32_t end_block) {
    Digest d;
    end_block = std::min<std::uint32_t>(end_block, static_cast<std::uint32_t>(tree.block_count()));
    for (std::uint32_t b = first_block; b < end_block; ++b) {
        const ast::BlockKind kind = tree.blocks[b].kind;
        if (kind == ast::BlockKind::program_start || kind == ast::BlockKind::percent || kind == ast::BlockKind::tail)
            d.add(static_cast<std::uint64_t>(kind));
        for (const ast::Token& t : tree.block_tokens(b)) {
            switch (t.kind) {
                case ast::TokenKind::word:
                    // Lower-case words: K1026 counts and fixes them all at the file's first.
                    if (std::string_view("OPQMopqm").find(t.letter) != std::string_view::npos || t.has(ast::token_flags::lower_case))
                        d.add(tree.spelling(t));
                    break;
                case ast::TokenKind::statement:
                    if (jumps_or_loops(tree.statements[static_cast<std::size_t>(t.payload)].kind)) d.add(tree.spelling(t));
                    break;
                case ast::TokenKind::comment:
                    if (reported_comment(tree.spelling(t))) d.add(tree.spelling(t));
                    break;
                case ast::TokenKind::bom: d.add(std::string_view("bom")); break;
                default: break;
            }
        }
    }
    if (first_block < end_block) {   // K3006 does not fire on a listing fragment ("...", S0113)
        const std::uint32_t begin = tree.blocks[first_block].begin;
        const std::uint32_t end = end_block < tree.block_count() ? tree.blocks[end_block].begin : static_cast<std::uint32_t>(tree.text.size());
        for (const ast::Diagnostic& diag : tree.diagnostics)
            if (diag.code == ast::diagnostic_id::listing_ellipsis && diag.range.begin >= begin && diag.range.begin < end)
                d.add(std::string_view("..."));
    }
    return d.value();
}

std::vector<std::int64_t> block_labels(const ast::SyntaxTree& tree, std::uint32_t first_block, std::uint32_t end_block) {
    std::vector<std::int64_t> out;
    end_block = std::min<std::uint32_t>(end_block, static_cast<std::uint32_t>(tree.block_count()));
    for (std::uint32_t b = first_block; b < end_block; ++b)
        for (const ast::Token& t : tree.block_tokens(b))
            if (t.kind == ast::TokenKind::word && t.letter == 'N' && t.is_number()) {   // BlockView::sequence_number
                if (const auto label = ast::truncated_integer(tree.number_value(t))) out.push_back(*label);
                break;
            }
    return out;
}

// A copy of the walk's state at a point: the modal state and every check.
struct IncrementalStatic::Snapshot {
    ModalState modal;
    std::vector<std::unique_ptr<StaticCheck>> checks;   // in the order of the walk's checks
    std::vector<std::int64_t> key;                      // their state (StaticCheck::state)
};

// The checks at work on one walk and what they report.
struct IncrementalStatic::Walk {
    const FileContext& ctx;
    std::vector<detail::StaticRun> checks;
    std::vector<Finding> found;
    ModalState modal;
    detail::BlockStep step;
    std::uint64_t walked = 0;

    // Fresh checks (the file's start), or copies of those of `from`.
    Walk(const FileContext& context, const detail::ActiveRules& rules, const Snapshot* from)
        : ctx(context), modal(from ? from->modal : ModalState(context.dialect)) {
        checks.reserve(rules.size());
        for (std::size_t i = 0; i < rules.size(); ++i) {
            std::unique_ptr<StaticCheck> c = from ? rules[i]->clone_static(*from->checks[i]) : rules[i]->make_static();
            checks.push_back({rules[i], std::move(c), Reporter(*rules[i], found)});
        }
    }
    Walk(const Walk&) = delete;   // the reporters point at `found`

    std::vector<std::int64_t> key(std::uint32_t block) const {
        StateKey k(ctx.tree().blocks[block].first_token);
        for (const detail::StaticRun& c : checks) {
            c.check->state(k);
            k.separate();
        }
        return k.values();
    }
    std::shared_ptr<const Snapshot> snapshot(std::uint32_t block) const {
        auto s = std::make_shared<Snapshot>(Snapshot{modal, {}, key(block)});
        s->checks.reserve(checks.size());
        for (const detail::StaticRun& c : checks) s->checks.push_back(c.rule->clone_static(*c.check));
        return s;
    }
};

namespace {

// Where a point is in the walk: before begin_program of a program comes before its first block.
std::pair<std::uint32_t, int> order(std::uint32_t block, bool before_begin) { return {block, before_begin ? 0 : 1}; }

// The static rules the walk runs, in registry order.
detail::ActiveRules static_rules(const CheckOptions& options, std::uint32_t shard, std::uint32_t shards) {
    detail::ActiveRules out;
    std::uint32_t place = 0;
    for (const Rule* r : detail::active_rules(detail::registry_of(options), options.config))
        if (r->make_static && r->clone_static && place++ % std::max<std::uint32_t>(shards, 1) == shard) out.push_back(r);
    return out;
}

// The bytes of a range after `splice`, or false when the range lies in (or at the start of) the
// lines it replaced.
bool move_range(ast::Range& r, const ast::BlockSplice& splice) {
    if (r.end < splice.old_begin || (r.end == splice.old_begin && r.begin < r.end)) return true;
    if (r.begin < splice.old_end) return false;
    r.begin = static_cast<std::uint32_t>(r.begin + splice.shift);
    r.end = static_cast<std::uint32_t>(r.end + splice.shift);
    return true;
}

bool move_finding(Finding& f, const ast::BlockSplice& splice) {
    bool ok = move_range(f.range, splice);
    for (Related& r : f.related) ok = move_range(r.range, splice) && ok;
    if (f.fix)
        for (TextEdit& e : f.fix->edits) ok = move_range(e.range, splice) && ok;
    return ok;
}

bool same_programs(const std::vector<ast::Program>& a, const std::vector<ast::Program>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const ast::Program& x, const ast::Program& y) {
        return x.number == y.number && x.first_block == y.first_block && x.end_block == y.end_block;
    });
}

}  // namespace

IncrementalStatic::IncrementalStatic(std::uint32_t checkpoint_blocks) : every_(std::max<std::uint32_t>(checkpoint_blocks, 1)) {}
IncrementalStatic::~IncrementalStatic() = default;

void IncrementalStatic::forget() {
    valid_ = false;
    programs_.clear();
    points_.clear();
    findings_.clear();
    poisoned_.clear();
    dirty_ = false;
    labels_.clear();
    targets_.reset();
}

void IncrementalStatic::apply(const BlockEdit& edit) {
    if (!valid_) return;
    const ast::BlockSplice& s = edit.splice;
    const bool jump_target = std::any_of(edit.labels.begin(), edit.labels.end(), [&](std::int64_t n) { return targets_->has(n); });
    if (edit.facts_changed || jump_target || s.old_end == kWholeText) {
        forget();
        return;
    }
    const std::int64_t moved = static_cast<std::int64_t>(s.added) - static_cast<std::int64_t>(s.removed);
    const std::uint32_t old_last = s.first + s.removed;   // the first old block after the replaced ones
    const auto after = [&](std::uint32_t x) { return static_cast<std::uint32_t>(x + moved); };
    for (auto& [program, table] : labels_) table.splice(s.first, old_last, moved);
    // Points before the replaced blocks (or right before the first of them) keep their state; those
    // among them are gone; those after moved and hold the last walk's state, to compare with.
    std::erase_if(points_, [&](const Point& p) { return p.block > s.first && p.block < old_last; });
    for (Point& p : points_)
        if (p.block >= old_last && p.block > s.first) p.block = after(p.block);
    for (ast::Program& p : programs_) {
        if (p.first_block >= old_last && p.first_block > s.first) p.first_block = after(p.first_block);
        if (p.end_block >= old_last && p.end_block > s.first) p.end_block = after(p.end_block);
    }
    // What is left to walk: these new blocks and what was left before, moved.
    std::uint32_t lo = s.first, hi = s.first + s.added;
    if (dirty_) {
        const std::uint32_t old_lo = dirty_lo_ < s.first ? dirty_lo_ : (dirty_lo_ >= old_last ? after(dirty_lo_) : s.first);
        const std::uint32_t old_hi = dirty_hi_ <= s.first ? dirty_hi_ : (dirty_hi_ >= old_last ? after(dirty_hi_) : s.first + s.added);
        lo = std::min(lo, old_lo);
        hi = std::max(hi, old_hi);
    }
    dirty_ = true;
    dirty_lo_ = lo;
    dirty_hi_ = hi;
    for (std::size_t i = 0; i < findings_.size(); ++i)
        if (!move_finding(findings_[i], s)) poisoned_.push_back(i);
}

void IncrementalStatic::relabel(const ast::TypedFile& typed) {
    for (auto& [program, table] : labels_) {
        if (program >= programs_.size()) continue;
        const std::uint32_t lo = std::max(dirty_lo_, programs_[program].first_block);
        const std::uint32_t hi = std::min(dirty_hi_, programs_[program].end_block);
        if (lo >= hi) continue;
        std::vector<LabelTable::Entry> now;
        for (std::uint32_t b = lo; b < hi; ++b)
            if (const auto e = LabelTable::entry_of(typed, b)) now.push_back(*e);
        table.replace(lo, hi, now);
    }
}

std::optional<std::vector<Finding>> IncrementalStatic::check(const Input& in) {
    const interpreter::LoadedFile& loaded = in.programs.file(in.file);
    const ast::SyntaxTree& tree = *loaded.whole_tree();
    const ast::TypedFile& typed = *loaded.whole_typed();
    const detail::ActiveRules rules = static_rules(in.options, in.shard, in.shards);
    walked_ = 0;
    whole_ = false;

    if (!in.edits || in.world != world_ || rules != rules_) forget();
    if (valid_ && !targets_) {
        // The jump targets as the last whole walk saw them: those of this text unless an edit
        // changed a target, and such an edit changed a fact, which makes the walk whole anyway.
        auto t = std::make_shared<JumpTargets>();
        t->labels = jump_targets(tree, t->computed);
        targets_ = std::move(t);
    }
    if (valid_)
        for (const BlockEdit& e : *in.edits) apply(e);
    if (valid_ && !same_programs(programs_, typed.programs())) forget();
    if (valid_ && dirty_) relabel(typed);

    std::function<bool(std::int64_t)> exists = in.program_exists;
    if (!exists) {
        const interpreter::ProgramSet::Loader loader = in.programs.loader();
        exists = [&loaded, loader](std::int64_t n) { return loaded.find_program(n).has_value() || (loader && loader(n).has_value()); };
    }
    FileContext ctx{typed, in.dialect, in.setup, std::move(exists), in.options.program_files};
    ctx.resident = in.options.resident;
    ctx.caller_arguments = in.options.caller_arguments;
    ctx.adopt_labels(std::move(labels_));
    if (valid_) ctx.adopt_jump_targets(targets_);
    const std::vector<ast::Program>& programs = typed.programs();

    // Where the walk starts: the file's start, or the last point before what changed.
    std::size_t from = 0;
    if (valid_) {
        from = points_.size();
        for (std::size_t i = 0; i < points_.size() && points_[i].block <= dirty_lo_; ++i) from = i;
        if (from == points_.size()) forget();
    }
    const bool whole = !valid_;
    if (whole) {
        forget();
        ctx.adopt_labels({});
        ctx.adopt_jump_targets(nullptr);
    }
    if (whole || dirty_) {
        const Point start = whole ? Point{} : points_[from];
        Walk w(ctx, rules, whole ? nullptr : start.snapshot.get());
        std::vector<Point> walked;   // the new points after `start`
        std::size_t next_old = from + 1;
        std::optional<std::size_t> converged;
        std::uint32_t last_point = 0;
        const std::size_t base = whole ? 0 : start.finding;
        // At a place where the walk may keep a point: compare with the last walk's point there
        // (past the changed blocks); keep one at program starts, every `every_` blocks and where
        // the last walk had one.
        const auto at = [&](std::uint32_t program, std::uint32_t block, bool before_begin) {
            const auto here = order(block, before_begin);
            while (next_old < points_.size() && order(points_[next_old].block, points_[next_old].before_begin) < here) ++next_old;
            const bool old_here = !whole && next_old < points_.size() && order(points_[next_old].block, points_[next_old].before_begin) == here;
            if (old_here && block >= dirty_hi_) {
                const Snapshot& old = *points_[next_old].snapshot;
                if (old.modal == w.modal && old.key == w.key(block)) {
                    converged = next_old;
                    return true;
                }
            }
            if (old_here || before_begin || block == programs[program].first_block || block >= last_point + every_) {
                walked.push_back({program, block, before_begin, base + w.found.size(), w.snapshot(block)});
                last_point = block;
            }
            return false;
        };
        bool cancelled = false;
        const auto run = [&] {
            const std::uint32_t first_program = whole ? 0 : start.program;
            for (std::uint32_t p = first_program; p < programs.size(); ++p) {
                const ast::Program& program = programs[p];
                std::uint32_t b = program.first_block;
                const bool resume = !whole && p == start.program;
                if (resume) {
                    b = start.block;
                    last_point = start.block;
                }
                if (!resume || start.before_begin) {
                    if (!resume) {
                        w.modal = ModalState(ctx.dialect);   // each program starts from the power-on state
                        if (at(p, program.first_block, true)) return;
                    }
                    for (detail::StaticRun& c : w.checks) c.check->begin_program(ctx, p, c.out);
                }
                for (; b < program.end_block; ++b) {
                    const bool is_start = resume && !start.before_begin && b == start.block;
                    if (!is_start && at(p, b, false)) return;
                    if ((++w.walked & 4095) == 0 && in.cancel && in.cancel->load(std::memory_order_relaxed)) {
                        cancelled = true;
                        return;
                    }
                    w.step(ctx, w.checks, w.modal, p, b);
                }
                for (detail::StaticRun& c : w.checks) c.check->end_program(ctx, p, c.out);
            }
        };
        run();
        walked_ = w.walked;
        whole_ = whole;
        if (cancelled) {
            labels_ = ctx.take_labels();
            if (valid_) targets_ = ctx.shared_jump_targets();
            return std::nullopt;
        }
        // A kept finding that points into an edited line cannot be moved: walk the file whole.
        const std::size_t keep_end = converged ? points_[*converged].finding : findings_.size();
        if (!whole && std::any_of(poisoned_.begin(), poisoned_.end(), [&](std::size_t i) { return i < base || i >= keep_end; })) {
            forget();
            IncrementalStatic::Input again = in;
            again.edits = std::nullopt;
            return check(again);
        }
        std::vector<Point> points;
        std::vector<Finding> findings;
        if (!whole) {
            points.assign(std::make_move_iterator(points_.begin()), std::make_move_iterator(points_.begin() + static_cast<std::ptrdiff_t>(from + 1)));
            findings.assign(std::make_move_iterator(findings_.begin()), std::make_move_iterator(findings_.begin() + static_cast<std::ptrdiff_t>(base)));
        }
        points.insert(points.end(), std::make_move_iterator(walked.begin()), std::make_move_iterator(walked.end()));
        findings.insert(findings.end(), std::make_move_iterator(w.found.begin()), std::make_move_iterator(w.found.end()));
        if (converged) {
            const std::int64_t shift = static_cast<std::int64_t>(findings.size()) - static_cast<std::int64_t>(keep_end);
            for (std::size_t i = *converged; i < points_.size(); ++i) {
                points_[i].finding = static_cast<std::size_t>(static_cast<std::int64_t>(points_[i].finding) + shift);
                points.push_back(std::move(points_[i]));
            }
            findings.insert(findings.end(), std::make_move_iterator(findings_.begin() + static_cast<std::ptrdiff_t>(keep_end)),
                            std::make_move_iterator(findings_.end()));
        }
        points_ = std::move(points);
        findings_ = std::move(findings);
        poisoned_.clear();
        dirty_ = false;
        valid_ = true;
        world_ = in.world;
        rules_ = rules;
        programs_ = programs;
    }

    std::vector<Finding> out = findings_;
    if (in.shard == 0) {
        const detail::ActiveRules all = detail::active_rules(detail::registry_of(in.options), in.options.config);
        const auto no_tally = [](const Rule&) -> RuleTally* { return nullptr; };
        // The program checks sum up each program from its label table: again after every edit.
        detail::run_program_checks(ctx, all, no_tally, out);
        detail::map_diagnostics(tree, tree.diagnostics, detail::registry_of(in.options), all, no_tally, out);
        detail::map_diagnostics(tree, typed.diagnostics(), detail::registry_of(in.options), all, no_tally, out);
    }
    labels_ = ctx.take_labels();
    targets_ = ctx.shared_jump_targets();
    return out;
}

}  // namespace kerf::analyzer
