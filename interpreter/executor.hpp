// The executor behind interpreter::run: the machine state and the block loop. Internal to the
// interpreter library (the public contract is interpreter.hpp).
#pragma once

#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "interpreter/interpreter.hpp"
#include "interpreter/macro/evaluate.hpp"
#include "interpreter/macro/variables.hpp"
#include "motion/vec.hpp"

namespace kerf::interpreter {

// The values of one block's words after evaluation: letter → value (vacant macro values omitted).
struct BlockWords {
    struct Word {
        double value = 0;
        bool has_point = false;
        std::uint32_t token = 0;
    };
    std::map<char, Word> words;   // the last word of each letter (the analyzer reports duplicates)
    std::map<char, Word> incremental;   // U/W/H written for X/Z/C (system A), keyed by the axis
    const Word* get(char letter) const {
        const auto it = words.find(letter);
        return it == words.end() ? nullptr : &it->second;
    }
};

class Executor {
public:
    Executor(ProgramSet& programs, const dialects::Dialect& dialect, const Setup& setup, EventSink& sink,
             const RunOptions& options);
    RunResult run(ProgramRef main);

private:
    struct Frame {
        ProgramRef program;
        std::uint32_t block = 0;          // next block to execute (index into the file's blocks)
        std::int64_t repeats_left = 1;    // M98 repeats still to run, this one included
        bool macro = false;               // G65 call: has its own local variables
        struct Loop {
            std::uint32_t do_block;       // the WHILE/DO block
            int label;                    // m of DO m / END m
        };
        std::vector<Loop> loops;          // open WHILE/DO loops, innermost last (at most 3)
    };

    ProgramSet& programs_;
    const dialects::Dialect& dialect_;
    const Setup& setup_;
    EventSink& sink_;
    RunOptions options_;
    RunResult result_;

    std::deque<Frame> frames_;   // a deque: pushing a call keeps references to the caller valid
    macro::Variables variables_;

    // Modal state.
    std::map<std::string, const dialects::CodeInfo*> modal_;   // group → active code
    Position position_{};            // work coordinates as programmed (lathe X diameter)
    int work_system_ = 0;            // 0..5 = G54..G59
    Position work_shift_{};          // G10 P0 (lathe), subtracted (semantics.md §2.6)
    Position local_shift_{};         // G52
    Position setting_shift_{};       // G50/G92 correction
    double feed_ = 0;
    double spindle_rpm_ = 0;         // programmed S under G97
    double css_ = 0;                 // G96 S, m/min
    double max_rpm_ = 0;             // G50/G92 S clamp
    bool spindle_on_ = false;
    int tool_ = 0;
    int tool_offset_ = 0;
    int pending_tool_ = 0;           // mills: T selects, M06 changes
    bool stopped_ = false;

    // Block execution.
    void execute_block(Frame& frame);
    bool execute_statements(Frame& frame, const ast::BlockView& view);
    bool execute_statement(Frame& frame, const ast::BlockView& view, const ast::Statement& s);
    bool start_macro_call(Frame& frame, const ast::BlockView& view, const ast::MacroCall& call);
    std::optional<std::uint32_t> find_end(const Frame& frame, std::uint32_t from, int label) const;
    bool evaluate_words(const ast::BlockView& view, BlockWords& out);
    void apply_feed_speed_tool(const ast::BlockView& view, const BlockWords& words);
    void apply_modal_codes(const ast::BlockView& view);
    bool apply_coordinate_operations(const ast::BlockView& view, const BlockWords& words);
    void apply_local_system(const ast::BlockView& view, const BlockWords& words, bool current_point_code);
    void apply_motion(const ast::BlockView& view, const BlockWords& words);
    void apply_dwell(const ast::BlockView& view, const BlockWords& words);
    void apply_m_codes(Frame& frame, const ast::BlockView& view, const BlockWords& words);

    // Helpers.
    const LoadedFile& file_of(const Frame& f) const { return programs_.file(f.program.file); }
    const ast::Program& program_of(const Frame& f) const;
    SourceRef source(const Frame& f, const ast::BlockView& view) const;
    bool has_function(const ast::BlockView& view, std::string_view function) const;
    std::string_view modal_function(const std::string& group) const;
    double axis_value(const BlockWords::Word& w, char letter) const;
    Position target_position(const BlockWords& words, bool& moves) const;
    Position machine_offset() const;
    double current_rpm(double x_diameter) const;
    // An event of this block at the current position (start = end), before its details are set.
    Event event_at(EventKind kind, const Frame& f, const ast::BlockView& view) const;
    void emit(Event e);
    void alarm(const Frame& f, const ast::BlockView& view, int number, std::string text);
    void move(EventKind kind, const Position& to, const Frame& f, const ast::BlockView& view);
    void arc_move(bool cw, const Position& to, const BlockWords& words, const ast::BlockView& view);
    motion::Plane plane() const;
    std::optional<std::uint32_t> find_label(const Frame& f, double n) const;
    void pop_frame();
    void change_offsets(const std::function<void()>& change);
    Frame* current_frame() { return frames_.empty() ? nullptr : &frames_.back(); }
    const ast::BlockView* view_ = nullptr;
    const Frame* frame_ = nullptr;
};

}  // namespace kerf::interpreter
