// Incremental static checking (issue 14: the language server checks a million-line program on every
// keystroke). The walk of the static rules over a file (check_static) is kept from one version of
// the file to the next. Every `checkpoint_blocks` blocks, and at every program's start, the walk
// keeps a copy of every check (Rule::clone_static) and of the modal state. After an edit it walks
// again from the last checkpoint before the edited blocks, and stops at the first later checkpoint
// where every check writes the same state (StaticCheck::state) and the modal state is the same as
// the last walk's there: from that point on the last walk's findings hold, moved with the text.
//
// It walks the whole file when it cannot know better: the first time; after an edit it was not told
// about; when an edit changed what checks read of other blocks (static_facts), the programs of the
// file, or `world` (the settings, the rules, the workspace the checks ask about programs); when a
// finding it would keep points into an edited line. The findings are check_static's, finished by
// finish_findings alike (tests/analyzer/test_incremental.cpp edits every example and corpus file).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "analyzer/analyze.hpp"
#include "analyzer/rule.hpp"
#include "ast/typed.hpp"

namespace kerf::analyzer {

// A hash of what static checks read beyond the block they check (rule.hpp, StaticCheck) in blocks
// [first_block, end_block): the O, P, Q and M words, lower-case words, the macro statements that jump or loop, empty
// and non-ASCII comments, a byte order mark, the blocks that start and end programs, listing
// ellipses (S0113). Two stretches with the same digest hold the same facts in the same order.
// N labels are apart (block_labels): they matter only where something jumps to them.
std::uint64_t static_facts(const ast::SyntaxTree& tree, std::uint32_t first_block, std::uint32_t end_block);
// The N labels of blocks [first_block, end_block) (BlockView::sequence_number, as labels count them).
std::vector<std::int64_t> block_labels(const ast::SyntaxTree& tree, std::uint32_t first_block, std::uint32_t end_block);

// One edit of the file as the document store made it: which blocks it replaced (ast::BlockSplice;
// old_end 0xFFFFFFFF for a text parsed again whole), whether the facts of the replaced blocks differ
// from those of the new ones (static_facts), and the labels of both (a jump target among them
// changes what the label rules say).
struct BlockEdit {
    ast::BlockSplice splice;
    bool facts_changed = true;
    std::vector<std::int64_t> labels;
};

class IncrementalStatic {
public:
    explicit IncrementalStatic(std::uint32_t checkpoint_blocks = 2048);
    ~IncrementalStatic();
    IncrementalStatic(const IncrementalStatic&) = delete;
    IncrementalStatic& operator=(const IncrementalStatic&) = delete;

    struct Input {
        const interpreter::ProgramSet& programs;
        std::uint32_t file = 0;
        const dialects::Dialect& dialect;
        const interpreter::Setup& setup;
        const CheckOptions& options;
        std::function<bool(std::int64_t)> program_exists;   // as check_static's
        // Changes whenever anything but the text may change what the checks say: the settings
        // (dialect, machine, [check] rules) or the programs of the workspace (K3003, K3010).
        std::uint64_t world = 0;
        // The edits since the last call, in order; nullopt: not known (the file is walked whole).
        std::optional<std::vector<BlockEdit>> edits;
        const std::atomic<bool>* cancel = nullptr;
        // This check's share of the static rules: those whose place among them is `shard` modulo
        // `shards` (the server walks two shares on two threads). Shard 0 also has the program
        // checks and the parser's diagnostics; the shares' findings together are check_static's.
        std::uint32_t shard = 0;
        std::uint32_t shards = 1;
    };

    // check_static(programs, file, ...) for the file as it is now; nullopt when `cancel` stopped
    // the walk (the edits are remembered: the next call walks what is still to walk).
    std::optional<std::vector<Finding>> check(const Input& input);

    // Blocks the last call walked, and whether it walked the file whole (tests, logs).
    std::uint64_t walked_blocks() const { return walked_; }
    bool walked_whole() const { return whole_; }

private:
    struct Walk;
    struct Snapshot;
    struct Point {
        std::uint32_t program = 0;
        std::uint32_t block = 0;
        bool before_begin = false;   // before begin_program(program); else before block `block`
        std::size_t finding = 0;     // findings_[finding, ...) were reported after this point
        std::shared_ptr<const Snapshot> snapshot;
    };
    void apply(const BlockEdit& edit);
    void relabel(const ast::TypedFile& typed);   // the label tables' entries of the changed blocks
    void forget();

    std::uint32_t every_;
    bool valid_ = false;
    std::uint64_t world_ = 0;
    std::vector<const Rule*> rules_;       // the checks of the points' snapshots, in order
    std::vector<ast::Program> programs_;   // the file's programs, block indices moved by the edits
    std::vector<Point> points_;            // in walk order
    std::vector<Finding> findings_;        // the static checks' findings, in walk order
    std::vector<std::size_t> poisoned_;    // findings_ that point into an edited line
    bool dirty_ = false;                   // blocks [dirty_lo_, dirty_hi_) changed since the last walk
    std::uint32_t dirty_lo_ = 0, dirty_hi_ = 0;
    LabelTables labels_;
    // The jump targets of the file (a fact: the same until a whole walk).
    std::shared_ptr<const JumpTargets> targets_;
    std::uint64_t walked_ = 0;
    bool whole_ = false;
};

}  // namespace kerf::analyzer
