// A rule: a stable id, a short name, a category, a default severity, its documentation and its
// check. Static checks see every block once in text order (with the text-order modal state);
// dynamic checks see the interpreter's events (design.md "analyzer = static rules on the AST +
// dynamic rules on the trace"). Parser diagnostics and interpreter alarms are turned into findings
// by the rules that list their codes, so a defect the grammar already found is not detected twice.
#pragma once

#include <functional>
#include <map>
#include <memory>
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

// What one rule reported in one file so far (bounded resources, ARCHITECTURE.md): one finding per
// position, suppressed ones not kept, and at most `limit` kept; the rest are only counted, so a
// rule firing on every word of a huge file, or on every turn of an endless loop, holds no memory.
struct RuleTally {
    std::size_t limit = 0;                                   // 0 = no cap
    const std::vector<Suppression>* suppressions = nullptr;  // the file's inline suppressions
    std::unordered_set<std::uint32_t> positions;             // range starts reported
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
    explicit LabelTable(std::vector<std::int64_t> numbers);
    int count(std::int64_t n) const;   // how many blocks carry N`n`

private:
    std::vector<std::int64_t> sorted_;
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

private:
    mutable std::map<std::size_t, LabelTable> labels_;
};

// The text-order modal state before a block: one slot per modal group (power-on defaults first),
// in a flat array because every rule walks it on every block. It is what a reader of the listing
// assumes; the dynamic rules see the state as it runs.
class ModalState {
public:
    using Slot = std::pair<std::string_view, const dialects::CodeInfo*>;   // group, active code (or none)
    explicit ModalState(const dialects::Dialect& dialect);
    void set(const dialects::CodeInfo& code);   // `code` becomes the active code of its group
    std::vector<Slot>::const_iterator begin() const { return slots_.begin(); }
    std::vector<Slot>::const_iterator end() const { return slots_.end(); }

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
};

class StaticCheck {
public:
    virtual ~StaticCheck() = default;
    virtual void begin_program(const FileContext&, std::size_t program, Reporter&) {}
    virtual void block(const BlockContext& b, Reporter& out) = 0;
    virtual void end_program(const FileContext&, std::size_t program, Reporter&) {}
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
    std::function<std::unique_ptr<DynamicCheck>()> make_dynamic;
};

}  // namespace kerf::analyzer
