// The analysis worker: `kerf check` on open documents, off the message thread. For each document
// version it runs the static rules (published at once), then the dry run with the dynamic rules
// (published when it finishes), and keeps what the dry run saw of each block for hover, inlay hints
// and code lens. A newer version of a document cancels the work on the older one (analyzer
// check_static / check_dry_run with a cancel flag); hovers and completions never wait for it.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "analyzer/finding.hpp"
#include "analyzer/incremental.hpp"
#include "interpreter/events.hpp"
#include "lsp/document.hpp"
#include "lsp/project_seam.hpp"

namespace kerf::lsp {

// The dry run's state after a block, the first time it ran.
struct BlockState {
    interpreter::Position position{};   // work coordinates (lathe X as diameter)
    double feed = 0;
    double spindle = 0;                 // S as the state event gives it (rpm, or the surface speed under G96)
    std::int32_t tool = 0;              // the tool
    std::int32_t tool_offset = 0;       // its offset number (lathe Tmmnn: nn)
    std::uint32_t modal = 0;            // index into DryRun::modal_texts
    std::uint32_t runs = 0;             // how many times the block ran
};

// What the events of one block added up to (a cycle block expands into many moves).
struct BlockMotion {
    std::uint32_t rapids = 0;
    std::uint32_t feeds = 0;            // linear, arc and thread moves
    double time_s = 0;
    double length_mm = 0;
};

struct ProgramRun {
    double time_s = 0;                  // events whose block is in this program
    double feed_mm = 0;
    double rapid_mm = 0;
    std::map<int, double> time_per_tool;
    std::map<int, double> length_per_tool;
};

// A value the dry run saw at a block the first time it ran: a variable the block names (its value
// after the block) or a word's expression (X[#1+2.]: the value the block used).
struct MacroValue {
    ast::Range range;             // the variable (#1, #[#2+1]) or the word's expression
    std::int64_t variable = -1;   // the variable's number; -1 for a word's expression
    bool vacant = false;
    double value = 0;
};

struct DryRun {
    std::vector<std::int32_t> state_of_block;   // per block: index into states, -1 when it never ran
    std::vector<BlockState> states;
    std::vector<std::string> modal_texts;        // "G00 G18 G40 ...": the active modal codes
    std::map<std::uint32_t, BlockMotion> motion; // blocks with more than one move
    std::map<std::uint32_t, ProgramRun> programs;   // program index → its share of the run
    ProgramRun total;                             // the whole run, calls included
    std::vector<std::pair<std::uint32_t, std::string>> alarms;   // block, text
    std::map<std::uint32_t, std::vector<MacroValue>> macro_values;   // blocks with macro expressions only
    const std::vector<MacroValue>* values(std::uint32_t block) const {
        const auto it = macro_values.find(block);
        return it == macro_values.end() ? nullptr : &it->second;
    }
    bool completed = false;                       // the run reached its end (not a step limit or alarm)
    const BlockState* state(std::uint32_t block) const {
        if (block >= state_of_block.size() || state_of_block[block] < 0) return nullptr;
        return &states[static_cast<std::size_t>(state_of_block[block])];
    }
};

struct Analysis {
    std::int64_t version = 0;
    std::vector<analyzer::Finding> findings;     // static and dynamic, as `kerf check` reports them
    std::shared_ptr<const DryRun> run;           // null when the dry run was off or is not done
};

class AnalysisWorker {
public:
    // Called on the worker thread: `final` is false for the static findings, true with the dry run's.
    using Publish = std::function<void(const Document& doc, const Analysis& analysis, bool final)>;
    AnalysisWorker(ProjectSeam& project, Publish publish);
    ~AnalysisWorker();

    void schedule(std::shared_ptr<const Document> document);
    void forget(const std::string& uri);
    // Drops the queued version of `uri` and stops the one being analysed, and returns once the
    // worker holds none of its versions (the store may then edit the document in place).
    void release(const std::string& uri);
    // The last finished analysis of `uri` (any version), or null.
    std::shared_ptr<const Analysis> latest(const std::string& uri) const;
    // Blocks until nothing is queued or running (tests, shutdown).
    void wait_idle();

private:
    void work();
    void analyse(const std::shared_ptr<const Document>& doc);
    bool superseded(const Document& doc) const;

    ProjectSeam& project_;
    Publish publish_;
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::string> order_;                                    // uris in arrival order
    std::map<std::string, std::shared_ptr<const Document>> pending_;   // the newest version per uri
    std::map<std::string, std::shared_ptr<const Analysis>> results_;
    // The static check of each document, kept between its versions (analyzer/incremental.hpp).
    struct Incremental {
        analyzer::IncrementalStatic check;    // share 0 of the static rules (and the program checks)
        analyzer::IncrementalStatic second;   // share 1, walked on a second thread
        std::uint64_t serial = 0;                       // Document::serial() of the version it knows
        std::shared_ptr<const FileSettings> settings;   // the settings it checked under (kept alive)
    };
    std::map<std::string, std::shared_ptr<Incremental>> incremental_;
    static std::optional<std::vector<analyzer::Finding>> check_static_shares(Incremental& incremental,
                                                                             const analyzer::IncrementalStatic::Input& input);
    std::string running_;                                              // the uri being analysed
    std::atomic<bool> cancel_{false};
    bool stop_ = false;
    bool busy_ = false;
    std::thread thread_;
};

}  // namespace kerf::lsp
