#include "converter/dry_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "interpreter/interpreter.hpp"

namespace kerf::converter {

namespace {

using interpreter::Event;
using interpreter::EventKind;
using interpreter::Position;

bool same_position(const Position& a, const Position& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::fabs(a[i] - b[i]) > 1e-9) return false;
    return true;
}

bool same_events(const std::vector<Event>& a, const std::vector<Event>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].kind != b[i].kind || !same_position(a[i].end, b[i].end)) return false;
    return true;
}

// Where a run starts: reference point 1 of a homed machine in the G54 system (interpreter/setup.hpp
// start_at_reference; the executor's power-on position), so that a G52 in the first block knows it.
Position start_position(const interpreter::Setup& s) {
    Position p{};
    const Position machine = s.start_at_reference ? s.reference_points[0] : Position{};
    for (std::size_t a = 0; a < p.size(); ++a) {
        const double offset = s.work_offsets[0][a] + s.external_offset[a] - s.work_shift[a];
        p[a] = machine[a] - offset;
    }
    return p;
}

// Follows the run block by block: a block's events arrive before its `state` event, which says
// which block it was and where the tool stands after it.
class FactSink : public interpreter::EventSink {
public:
    FactSink(const ast::TypedFile& file, std::uint32_t file_index, const RunRequest& request,
             std::map<std::uint32_t, BlockRun>& blocks, Position start)
        : file_(file), file_index_(file_index), request_(request), blocks_(blocks), position_(start) {}

    void on_event(const Event& e) override {
        if (e.kind != EventKind::state) {
            if (request_.keep_events) pending_.push_back(e);
            return;
        }
        const Position before = position_;
        const Position local_before = local_;
        position_ = e.end;
        std::vector<Event> events = std::move(pending_);
        pending_.clear();
        if (e.source.file != file_index_) return;
        const std::optional<std::uint32_t> index = block_at(e.source.range.begin);
        if (!index) return;
        track_local(*index, before);
        if (!std::binary_search(request_.blocks.begin(), request_.blocks.end(), *index)) return;
        BlockRun& b = blocks_[*index];
        if (b.executions++ == 0) {
            b.before = before;
            b.after = position_;
            b.local_before = local_before;
            b.local_after = local_;
            b.events = std::move(events);
            return;
        }
        if (!same_position(b.before, before) || !same_position(b.after, position_) || !same_position(b.local_after, local_) ||
            !same_events(b.events, events))
            b.varies = true;
    }

private:
    const ast::TypedFile& file_;
    std::uint32_t file_index_;
    const RunRequest& request_;
    std::map<std::uint32_t, BlockRun>& blocks_;
    Position position_;
    Position local_{};
    std::vector<Event> pending_;

    std::optional<std::uint32_t> block_at(std::uint32_t begin) const {
        const auto& blocks = file_.tree().blocks;
        std::size_t lo = 0, hi = blocks.size();
        while (lo < hi) {   // the last block whose begin is <= begin
            const std::size_t mid = (lo + hi) / 2;
            if (blocks[mid].begin <= begin) lo = mid + 1;
            else hi = mid;
        }
        if (lo == 0) return std::nullopt;
        return static_cast<std::uint32_t>(lo - 1);
    }

    // G52 keeps the tool still, so the shift changes by what the program position moved:
    // p + L is the work position before and after (semantics.md §2.4).
    void track_local(std::uint32_t index, const Position& before) {
        const auto it = request_.local.find(index);
        if (it == request_.local.end()) return;
        if (it->second == LocalEffect::cancel) {
            local_ = {};
            return;
        }
        for (std::size_t a = 0; a < local_.size(); ++a) local_[a] += before[a] - position_[a];
    }
};

}  // namespace

SourceRun SourceRun::run(const ast::TypedFile& file, const interpreter::Setup& setup, const Options& options,
                         const RunRequest& request) {
    SourceRun result;
    interpreter::ProgramSet programs;
    const ast::LineIndex lines(file.tree().text);
    // The file is used in place: it outlives the run.
    const std::uint32_t index = programs.add_parsed(options.name, std::shared_ptr<const void>(), file, lines);
    if (options.loader) programs.set_loader(options.loader, &file.dialect());
    const std::optional<interpreter::ProgramRef> main = programs.first_program(index);
    if (!main) return result;
    interpreter::RunOptions run;
    run.emit_state = true;
    run.lenient = true;   // a file with syntax errors is converted around them; run it as far as it goes
    run.time_limit = std::chrono::milliseconds(options.time_limit_ms);
    FactSink sink(file, index, request, result.blocks_, start_position(setup));
    interpreter::run(programs, *main, file.dialect(), setup, sink, run);
    result.ran_ = true;
    return result;
}

const BlockRun* SourceRun::block(std::uint32_t index) const {
    const auto it = blocks_.find(index);
    return it == blocks_.end() ? nullptr : &it->second;
}

}  // namespace kerf::converter
