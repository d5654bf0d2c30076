// What the converter learns from a dry run of the source (interpreter/interpreter.hpp): for the
// blocks it asks about, where the tool stood before and after each execution, the local shift of
// G52 (semantics.md §2.4) before and after, and the events (for --expand). A conversion needs a
// run only for what text alone cannot say: the value of G52 in the other reading depends on where
// the tool is, and --expand writes the motion the interpreter computes.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "ast/typed.hpp"
#include "converter/convert.hpp"
#include "interpreter/events.hpp"

namespace kerf::converter {

// What the run says of one block, from its first execution.
struct BlockRun {
    std::uint32_t executions = 0;
    interpreter::Position before{};    // program position before the block (work coordinates, lathe X a diameter)
    interpreter::Position after{};
    interpreter::Position local_before{};   // the G52 shift L (program p is work p + L) before and after
    interpreter::Position local_after{};
    std::vector<interpreter::Event> events;   // the execution's events but `state` (kept when asked)
    bool varies = false;   // a later execution stood elsewhere, shifted otherwise or moved otherwise
};

// How a source block changes the local shift, for the run's bookkeeping (from its function ids).
enum class LocalEffect : std::uint8_t { none, set, cancel };

struct RunRequest {
    std::vector<std::uint32_t> blocks;              // block indices the caller asks about (ascending)
    std::map<std::uint32_t, LocalEffect> local;     // blocks that set or cancel the local shift
    bool keep_events = false;                       // record the events of the asked blocks
};

class SourceRun {
public:
    // Runs `file`'s first program in its dialect on `setup` (no file is read: `loader` brings
    // subprograms of other files). Blocks that never ran have no entry.
    static SourceRun run(const ast::TypedFile& file, const interpreter::Setup& setup, const Options& options,
                         const RunRequest& request);
    const BlockRun* block(std::uint32_t index) const;
    bool ran() const { return ran_; }

private:
    std::map<std::uint32_t, BlockRun> blocks_;
    bool ran_ = false;
};

}  // namespace kerf::converter
