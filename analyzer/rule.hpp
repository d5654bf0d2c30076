// A rule: a stable id, a short name, a category, a default severity, its documentation and its
// check. Static checks see every block once in text order (with the text-order modal state);
// program checks see a program whole, through the tables FileContext keeps of it (its labels);
// dynamic checks see the interpreter's events (design.md "analyzer = static rules on the AST +
// dynamic rules on the trace"). Parser diagnostics and interpreter alarms are turned into findings
// by the rules that list their codes, so a defect the grammar already found is not detected twice.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "analyzer/finding.hpp"
#include "ast/typed.hpp"
#include "interpreter/events.hpp"
#include "interpreter/program_set.hpp"
#include "interpreter/setup.hpp"
#include "references/references.hpp"

namespace kerf::analyzer {

enum class Category { syntax, dialect, references, macro, motion };
const char* to_string(Category c);

struct RuleDocs {
    std::string what;        // one sentence: what the rule finds
    std::string why;         // what happens on the machine
    std::string bad;         // a program fragment that fires
    std::string good;        // the fragment corrected
    std::string reference;   // the section of ../shared/reference (or the seed) it comes from
};

struct Rule;
struct Suppression;

// The positions a rule has reported, to count each once. Static rules report in text order: a
// position past every earlier one is appended to a sorted array (no hashing); one before the
// last (a dynamic rule in a loop, a rule that looks back) is looked up there, then in a set.
class PositionSet {
public:
    // True when `at` was not in the set (it is now).
    bool insert(std::uint32_t at) {
        if (ascending_.empty() || at > ascending_.back()) {
            ascending_.push_back(at);
            return true;
        }
        if (std::binary_search(ascending_.begin(), ascending_.end(), at)) return false;
        return others_.insert(at).second;
    }

private:
    std::vector<std::uint32_t> ascending_;
    std::unordered_set<std::uint32_t> others_;
};

// What one rule reported in one file so far (bounded resources, ARCHITECTURE.md): one finding per
// position, suppressed ones not kept, and at most `limit` kept; the rest are only counted, so a
// rule firing on every word of a huge file, or on every turn of an endless loop, holds no memory.
struct RuleTally {
    std::size_t limit = 0;                                   // 0 = no cap
    const std::vector<Suppression>* suppressions = nullptr;  // the file's inline suppressions
    PositionSet positions;                                   // range starts reported
    std::size_t kept = 0;
    std::size_t dropped = 0;                                 // distinct positions over the cap
};

// Collects the findings of one rule. Severity comes from the rule (or the configuration later).
class Reporter {
public:
    Reporter(const Rule& rule, std::vector<Finding>& out, RuleTally* tally = nullptr)
        : rule_(&rule), out_(&out), tally_(tally) {}
    // The new finding; with a tally, a finding it does not keep is a scratch one the caller may
    // still fill in (notes, fix) and that goes nowhere.
    Finding& report(ast::Range range, std::string message, std::string hint = {});
    // False for the scratch finding of a report the tally did not keep: a rule need not fill it in.
    bool kept(const Finding& f) const { return &f != &scratch_; }
    // When the tally's cap is reached: counts a finding at `range` as report() would (one more not
    // shown, unless suppressed or at a position already reported) without building it, and returns
    // true; the rule then skips formatting its message. A macro program whose jumps all land on a
    // repeated label reports 423,500 of them (bench/RESULTS.md). False while findings are kept.
    bool drop_if_full(ast::Range range);

private:
    const Rule* rule_;
    std::vector<Finding>* out_;
    RuleTally* tally_;
    Finding scratch_;
};

// The N numbers of one program, sorted (sequence numbers need not be unique: dialects.md §2; they
// matter only where something jumps to them). Built once per program for all rules that ask.
class LabelTable {
public:
    struct Entry {
        // Left unset on purpose: the sort writes a table of millions of entries once, and a
        // value-initialised one would be written twice (zeros first).
        Entry() {}   // NOLINT: no member initialisers
        Entry(double v, std::uint32_t b) : value(v), block(b) {}
        // The N value as an integer label (what count() compares): the value truncated, which
        // entry_of made sure fits (16 bytes an entry, not 24: a CAM program has millions).
        std::int64_t number() const { return static_cast<std::int64_t>(value); }
        double value;          // the N value as written (N10.5 is not label 10 for blocks())
        std::uint32_t block;
    };
    // `entries` in block order.
    explicit LabelTable(std::vector<Entry> entries);
    // The entry of block `block` of `typed`, when it carries a sequence number that is a label.
    static std::optional<Entry> entry_of(const ast::TypedFile& typed, std::uint32_t block);
    int count(std::int64_t n) const;   // how many blocks carry N`n`
    // The blocks whose N value is exactly `n`, in block order (references::label_blocks without the
    // walk over the program: AmbiguousLabel asks once per jump, and CAM output repeats N numbers).
    std::vector<std::uint32_t> blocks(std::int64_t n) const;
    // Every entry, by number, then block.
    std::span<const Entry> entries() const { return sorted_; }
    // An edit replaced blocks [first, old_last) and moved the later ones by `moved` (the language
    // server's incremental check keeps the table while no jump target changed): the replaced
    // blocks' entries go, the later ones move. replace() then puts in those of the new blocks.
    void splice(std::uint32_t first, std::uint32_t old_last, std::int64_t moved);
    // The entries of blocks [first, end) become `now` (in block order).
    void replace(std::uint32_t first, std::uint32_t end, std::span<const Entry> now);

private:
    std::pair<std::vector<Entry>::const_iterator, std::vector<Entry>::const_iterator> range(std::int64_t n) const;
    std::vector<Entry> sorted_;   // by number, then block
};
using LabelTables = std::map<std::size_t, LabelTable>;   // program index → its labels

// Every N number something in the file can jump to, sorted: the constant labels of macro statements
// and the numbers of P and Q words (calls, cycles, returns); `computed` when a GOTO's target is an
// expression (K3007; incremental checking: a label that is no target matters to no rule).
std::vector<std::int64_t> jump_targets(const ast::SyntaxTree& tree, bool& computed);
struct JumpTargets {
    std::vector<std::int64_t> labels;   // sorted
    bool computed = false;              // a GOTO's target is an expression: it may reach any label
    bool has(std::int64_t n) const;
};

// What a static check sees of the whole file.
struct FileContext {
    FileContext(const ast::TypedFile& t, const dialects::Dialect& d, const interpreter::Setup& s,
                std::function<bool(std::int64_t)> exists,
                std::function<std::vector<std::string>(std::int64_t)> files = {})
        : typed(t), dialect(d), setup(s), program_exists(std::move(exists)), program_files(std::move(files)) {}
    const ast::TypedFile& typed;
    const dialects::Dialect& dialect;
    const interpreter::Setup& setup;
    // True when program O`number` can be found (this file, then the loader: the program index).
    std::function<bool(std::int64_t)> program_exists;
    // The other files holding program O`number`, as a call reaches them (CheckOptions::program_files).
    std::function<std::vector<std::string>(std::int64_t)> program_files;
    // Programs the machine keeps resident (.kerf.toml [programs] resident): calls into them are not
    // findings (CheckOptions::resident). Empty: none.
    std::function<bool(std::int64_t)> resident;
    // The locals (#1 A ... #26 Z) callers elsewhere (the program index) pass to program O`number`
    // (CheckOptions::caller_arguments; analyzer/arguments.hpp adds the file's own calls and the
    // program's header documentation). Empty: none known.
    std::function<std::vector<int>(std::int64_t)> caller_arguments;
    const ast::SyntaxTree& tree() const { return typed.tree(); }
    // The labels of program `program` (typed.programs() index), computed on first use.
    const LabelTable& labels(std::size_t program) const;
    // The tables computed so far, and tables computed by an earlier walk of the same labels
    // (incremental checking carries them over edits that change no N number: incremental.hpp).
    LabelTables take_labels() const;
    void adopt_labels(LabelTables labels) const;
    // jump_targets(tree()), computed on first use; shared with incremental checking, which keeps it
    // while no edit changes a fact (a target is one: static_facts).
    const JumpTargets& jump_targets() const;
    std::shared_ptr<const JumpTargets> shared_jump_targets() const;
    void adopt_jump_targets(std::shared_ptr<const JumpTargets> targets) const;

private:
    // The caches are filled under a lock: a long file's program checks may run on the dry run's
    // thread while the static rules still walk the blocks (analyze.cpp check_file).
    mutable std::unique_ptr<std::mutex> cache_mutex_ = std::make_unique<std::mutex>();
    mutable LabelTables labels_;
    mutable std::shared_ptr<const JumpTargets> targets_;
};

// The text-order modal state before a block: one slot per modal group (power-on defaults first),
// in a flat array because every rule walks it on every block. It is what a reader of the listing
// assumes; the dynamic rules see the state as it runs.
class ModalState {
public:
    using Slot = std::pair<std::string_view, const dialects::CodeInfo*>;   // group, active code (or none)
    // The power-on state: the dialect table's defaults, then the machine's power-on switches
    // (interpreter Setup::power_on), as the dry run starts.
    explicit ModalState(const dialects::Dialect& dialect, const std::vector<dialects::FunctionId>& power_on = {});
    bool has_trait(std::uint32_t trait) const;   // an active code has it (dialects::traits::inch ...)
    void set(const dialects::CodeInfo& code);   // `code` becomes the active code of its group
    std::vector<Slot>::const_iterator begin() const { return slots_.begin(); }
    std::vector<Slot>::const_iterator end() const { return slots_.end(); }
    friend bool operator==(const ModalState&, const ModalState&) = default;

private:
    std::vector<Slot> slots_;
};

struct BlockContext {
    const FileContext& file;
    const ast::BlockView& view;
    std::span<const ast::CodeRef> g;   // the block's G codes
    std::span<const ast::CodeRef> m;   // the block's M codes
    const ModalState& modal;           // before this block
    std::size_t program = 0;           // index into typed.programs()
    const ast::SyntaxTree& tree() const { return file.typed.tree(); }
    // A G or M code of the block has `function`. Inline: every rule asks it of every block.
    bool has_function(dialects::FunctionId function) const {
        for (const ast::CodeRef& c : g)
            if (c.info && c.info->function == function) return true;
        for (const ast::CodeRef& c : m)
            if (c.info && c.info->function == function) return true;
        return false;
    }
    bool modal_function(dialects::FunctionId function) const; // active before the block
    const ast::Token& token(std::uint32_t i) const { return tree().tokens[i]; }
    // What several rules of every block ask, computed once per block on first use.
    const std::vector<references::Reference>& references() const {   // references::block_references
        if (!references_) references_ = references::block_references(file.typed, static_cast<std::uint32_t>(program), static_cast<std::uint32_t>(view.index()));
        return *references_;
    }
    const std::vector<std::uint32_t>& statements() const {   // ast::BlockView::statements
        if (!statements_) statements_ = view.statements();
        return *statements_;
    }
    mutable std::optional<std::vector<references::Reference>> references_{};
    mutable std::optional<std::vector<std::uint32_t>> statements_{};
};

// The state a static check carries from one block to the next, written as numbers. Incremental
// checking (analyzer/incremental.hpp, the language server) resumes a walk after an edit from a copy
// of the checks taken before it, and stops once every check writes the same state as the last walk
// wrote at the same place: from there on that walk's findings hold. A token index is written
// relative to the first token of the block where the state is taken, so that an edit before both
// leaves equal states equal (and one between them makes them differ, which only costs a longer walk).
class StateKey {
public:
    explicit StateKey(std::uint32_t first_token) : first_token_(first_token) {}
    void add(std::int64_t value) { values_.push_back(value); }
    void token(std::uint32_t index) { values_.push_back(static_cast<std::int64_t>(index) - first_token_); }
    void separate() { values_.push_back(INT64_MIN); }   // between the checks' parts
    const std::vector<std::int64_t>& values() const { return values_; }

private:
    std::int64_t first_token_;
    std::vector<std::int64_t> values_;
};

// A static check sees the blocks of each program in text order. Contract of incremental checking:
// what a check reports about a block depends on that block, the modal state, FileContext and the
// state the check carries (written by state()); what it reads of other blocks (in begin_program,
// end_program or through the tree: labels, jump targets, program numbers, comments, M codes) must
// be among the facts analyzer::static_facts digests (incremental.hpp), so that an edit that changes
// them is checked whole. tests/analyzer/test_incremental.cpp compares both ways on every example.
class StaticCheck {
public:
    virtual ~StaticCheck() = default;
    virtual void begin_program(const FileContext&, std::size_t program, Reporter&) {}
    virtual void block(const BlockContext& b, Reporter& out) = 0;
    virtual void end_program(const FileContext&, std::size_t program, Reporter&) {}
    // The state carried between blocks (none for a check without data members; static_rule<C> in
    // rules/common.hpp refuses to compile a check with members that does not write them).
    virtual void state(StateKey&) const {}
};

// A check of a whole program at once, from what FileContext keeps of it (its label table, the jump
// targets) rather than by walking its blocks: a finding that sums up the program (K3011 names every
// repeated N number). Incremental checking runs these again after every edit instead of walking the
// file whole, so one must cost no more than a pass over the program's labels.
class ProgramCheck {
public:
    virtual ~ProgramCheck() = default;
    virtual void program(const FileContext& file, std::size_t program, Reporter& out) const = 0;
};

// What a dynamic check sees: the run's files (events point into them) and the checked file.
struct RunContext {
    const interpreter::ProgramSet& programs;
    std::uint32_t checked_file = 0;
    const dialects::Dialect& dialect;
    const interpreter::Setup& setup;
};

class DynamicCheck {
public:
    virtual ~DynamicCheck() = default;
    virtual void event(const RunContext& run, const interpreter::Event& e, Reporter& out) = 0;
    virtual void finish(const RunContext&, Reporter&) {}
};

struct Rule {
    std::string id;     // K1001
    std::string name;   // address-without-value
    Category category = Category::syntax;
    Severity severity = Severity::warning;
    bool enabled = true;               // on unless configured (a few are opt-in)
    RuleDocs docs;
    std::vector<std::string> diagnostics;         // parser/binder codes reported as this rule ("S0101")
    std::vector<std::pair<int, int>> alarms;      // interpreter alarm numbers [first, last]
    // Alarms a finding of this static rule explains: the dry run's finding for such an alarm on the
    // same line is dropped (K3003 explains alarm 078 at its call: one missing program, one finding).
    std::vector<std::pair<int, int>> explains;
    bool has_fix = false;                         // documentation: the rule offers a fix
    // A fix for a mapped diagnostic (the letter O of "MO6" becomes 0), or nullopt.
    std::function<std::optional<Fix>(const ast::SyntaxTree&, const ast::Diagnostic&)> diagnostic_fix;
    std::function<std::unique_ptr<StaticCheck>()> make_static;
    // A copy of a check made by make_static, its state included (incremental checking's checkpoints).
    std::function<std::unique_ptr<StaticCheck>(const StaticCheck&)> clone_static;
    std::function<std::unique_ptr<DynamicCheck>()> make_dynamic;
    std::shared_ptr<const ProgramCheck> program_check;
};

}  // namespace kerf::analyzer
