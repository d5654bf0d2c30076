// The executor behind interpreter::run: the block loop over the machine state. Internal to the
// interpreter library (the public contract is interpreter.hpp).
//
// Three things travel explicitly (issue 13):
//   - the block being run, as a BlockContext (frame, view, scan, words) handed to every step;
//   - the machine state, one value (MachineState, machine_state.hpp): the executor's live state_,
//     and the state a block is read with. Reading a block (its words, target, direct-drawing
//     corner, compensation element, G70–G73 profile) is done by const member functions that take
//     the MachineState and the position they read from: a look-ahead cannot change the run (the
//     compiler holds it to that), and what it finds wrong comes back as an Alarm value the running
//     block raises. The G70–G73 profile is read on a copy of the state whose point advances block
//     by block; the direct-drawing and compensation look-aheads read the live state as it is,
//     from the point the running block ends at (no copy: a per-block copy of the 2.5 KB state cost
//     10–12 % on a compensation-heavy program). The machine's memory (offset registers, G54.1
//     offsets, dialect and macro variables) is never copied: a reading only reads it;
//   - what a step did with the block, as an Outcome.
#pragma once

#include <array>
#include <bit>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "interpreter/block_scan.hpp"
#include "interpreter/compensation/radius_compensation.hpp"
#include "interpreter/cycles/context.hpp"
#include "interpreter/direct_drawing.hpp"
#include "interpreter/interpreter.hpp"
#include "interpreter/macro/evaluate.hpp"
#include "interpreter/machine_state.hpp"
#include "interpreter/macro/variables.hpp"
#include "interpreter/run_guard.hpp"
#include "interpreter/transforms.hpp"
#include "motion/arc.hpp"
#include "motion/polar.hpp"
#include "motion/vec.hpp"

namespace kerf::interpreter {

// The values of one block's words after evaluation: letter → value (vacant macro values omitted).
struct Word {
    double value = 0;
    bool has_point = false;
    bool data = false;          // data of a code in the block (G04 X): not a move, not modal F/S/T
    std::uint32_t token = 0;
};

// A map from the letters A–Z to words, in a fixed array (no allocation per block), iterated in
// letter order like the std::map it replaces.
class LetterMap {
public:
    using value_type = std::pair<char, Word>;
    class iterator {
    public:
        iterator(const LetterMap* map, int i) : map_(map), i_(i) { skip(); }
        const value_type& operator*() const { return current_; }
        const value_type* operator->() const { return &current_; }
        iterator& operator++() {
            ++i_;
            skip();
            return *this;
        }
        bool operator==(const iterator& o) const { return i_ == o.i_; }
        bool operator!=(const iterator& o) const { return i_ != o.i_; }

    private:
        void skip() {
            const std::uint32_t rest = i_ < 26 ? map_->mask_ >> i_ : 0u;
            i_ = rest ? i_ + std::countr_zero(rest) : 26;
            if (i_ < 26) current_ = {static_cast<char>('A' + i_), map_->words_[static_cast<std::size_t>(i_)]};
        }
        const LetterMap* map_;
        int i_;
        value_type current_{};
    };
    iterator begin() const { return {this, 0}; }
    iterator end() const { return {this, 26}; }
    iterator find(char c) const { return count(c) ? iterator(this, c - 'A') : end(); }
    std::size_t count(char c) const { return c >= 'A' && c <= 'Z' && (mask_ >> (c - 'A') & 1u) ? 1 : 0; }
    std::uint32_t mask() const { return mask_; }   // bit i: letter 'A' + i is present
    void clear() { mask_ = 0; }                     // the words stay as garbage, unreachable
    const Word& at(char c) const { return words_[static_cast<std::size_t>(c - 'A')]; }
    void set(char c, const Word& w) {
        words_[static_cast<std::size_t>(c - 'A')] = w;
        mask_ |= 1u << (c - 'A');
    }

private:
    std::array<Word, 26> words_{};
    std::uint32_t mask_ = 0;
};

struct BlockWords {
    using Word = interpreter::Word;
    LetterMap words;         // the last word of each letter (the analyzer reports duplicates)
    LetterMap incremental;   // U/W/H written for X/Z/C (system A), keyed by the axis
    const Word* get(char letter) const { return words.count(letter) ? &words.at(letter) : nullptr; }
    void clear() {
        words.clear();
        incremental.clear();
    }
};

class Executor;

// A program level of the run: a program and where the run is in it (a call pushes one).
struct Frame {
    ProgramRef program;
    std::uint32_t block = 0;          // next block to execute (index into the file's blocks)
    std::uint32_t start_block = 0;    // where a repeat starts again (M98 Q: the label)
    std::int64_t repeats_left = 1;    // M98 repeats still to run, this one included
    bool macro = false;               // G65/G66 call: has its own local variables
    bool modal_macro = false;         // called by G66: its moves do not call again
    struct Loop {
        std::uint32_t do_block;       // the WHILE/DO block
        int label;                    // m of DO m / END m
    };
    std::vector<Loop> loops;          // open WHILE/DO loops, innermost last (at most 3)
};

// One block as it runs (semantics.md §1.2), handed to each step explicitly: no member of the
// executor stands for "the block being run". A block read ahead (direct drawing, compensation, a
// G70–G73 profile) has a context of its own.
struct BlockContext {
    BlockContext(const Frame& f, const ast::BlockView& v, const BlockScan& s, const BlockWords& w,
                 std::optional<dialects::FunctionId> m = std::nullopt)
        : frame(f), view(v), scan(s), words(w), motion(m) {}
    const Frame& frame;          // the program level running it (gone after the block's M99 or M30, its last step)
    const ast::BlockView& view;
    const BlockScan& scan;       // its codes; scan.block is its index in the file, scan.source where it is
    const BlockWords& words;     // its evaluated words (empty until step 2 has evaluated them)
    // The motion it runs with when that is not the modal one of the state (a G12/G13 quarter arc
    // runs as G03/G02; a block read ahead is read with the motion it would run with).
    std::optional<dialects::FunctionId> motion;
    std::uint32_t index() const { return scan.block; }
    const SourceRef& source() const { return scan.source; }
    dialects::FunctionId motion_in(const MachineState& s) const { return motion.value_or(s.flags.motion); }
    // The same block with other words (G112 C without its C), or run as another motion with them
    // (a quarter arc with its centre words).
    BlockContext with(const BlockWords& other) const { return {frame, view, scan, other, motion}; }
    BlockContext running_as(const BlockWords& other, dialects::FunctionId m) const { return {frame, view, scan, other, m}; }
};

// Work coordinates (program units, lathe X diameter) → geometric mm (X radius).
motion::Vec3 geometric_mm(const Position& p, bool diameter_x, double scale);
// And back: X, Y, Z of `g` in program units into a copy of `like` (whose other axes are kept).
Position from_geometric(motion::Vec3 g, const Position& like, bool diameter_x, double scale);

// The system variables (#1000 and up) as the interpreter's state (executor_system.cpp), read from one
// machine state with the tool at `at` (the live state, or the one a block is read ahead with, at
// the point it is read from). Built with a block they are that block's, and its assignments write
// them into the run (#3000 raises its alarm at the block); otherwise (the executor's own behind
// RunOptions::after_block and DPRNT, a look-ahead's) every write is refused.
class ExecutorSystemVariables : public macro::SystemVariables {
public:
    ExecutorSystemVariables(const Executor& executor, const MachineState& state, const Position& at)
        : executor_(executor), state_(state), at_(at) {}
    ExecutorSystemVariables(Executor& executor, const BlockContext& block);
    std::optional<macro::Value> read(int number) override;
    macro::WriteResult write(int number, macro::Value value) override;
    bool read_only(int number) const override;
    bool modelled(int number) const override;

private:
    const Executor& executor_;
    const MachineState& state_;
    const Position& at_;
    Executor* writer_ = nullptr;          // with a block: the run its assignments write into
    const BlockContext* block_ = nullptr;
};

// What a step of a block did with it: the one answer of the handlers a block passes through
// (semantics.md §1.2: its statements, its frame codes, then apply_motion's chain of motion
// handlers: plane transforms, reference returns, cycles, the seed-004 specials, compensation,
// direct drawing, position offsets, the plain move). Each takes the block or leaves it to the next.
enum class Outcome : std::uint8_t {
    not_mine,   // not this handler's block (or part of it): the next step runs as usual
    done,       // taken; the tool did not move (a mode or frame set, a jump or call made, nothing to
                // move, a cycle block: G66 does not call after it)
    moved,      // taken; the tool moved (G66 calls its macro after such a block)
    stopped,    // an alarm (or a run bound) stopped the run
};
// What still answers bool says so in its name or its comment: predicates (has_function,
// compensating, full_circle ...), checks that raise their own alarm and answer false then
// (within_soft_limits, feed_commanded, evaluate_words, transform_switch_allowed), and the moves of
// a path that answer false once the run stopped (cycle_arc, run_comp_moves, the cycles::Context
// moves). Macro B conditions are a value or an error (std::optional<bool>, macro/evaluate.hpp).

// An alarm as a value: where, with the tool where, what. Reading a block (const functions over a
// MachineState) returns it; the live block that asked raises it (Executor::raise).
struct Alarm {
    SourceRef where;
    Position at{};   // where the reading stood (the event's start and end)
    int number = 0;
    std::string text;
};

// A value read, or the alarm that stopped the reading (`value` is then meaningless).
template <class T>
struct OrAlarm {
    T value{};
    std::optional<Alarm> alarm;
    bool ok() const { return !alarm; }
};

class Executor {
public:
    Executor(ProgramSet& programs, const dialects::Dialect& dialect, const Setup& setup, EventSink& sink,
             const RunOptions& options);
    Executor(const Executor&) = delete;
    Executor& operator=(const Executor&) = delete;
    RunResult run(ProgramRef main);

private:
    friend class ExecutorSystemVariables;

    ProgramSet& programs_;
    const dialects::Dialect& dialect_;
    const Setup& setup_;
    EventSink& sink_;
    RunOptions options_;
    RunResult result_;
    RunGuard guard_;   // step, move and time limits (run_guard.hpp)

    // The scan and words of the block being run, reused from block to block (no allocation, no 1 KB
    // zeroing per block): written by execute_block only, read through its BlockContext.
    BlockScan scan_buffer_;
    BlockWords words_buffer_;
    // Letter → axis index for the dialect's axis letters (axis_letters_: the mask of them).
    std::array<std::int8_t, 26> axis_of_{};
    std::uint32_t axis_letters_ = 0;
    bool any_soft_limit_ = false;   // the machine has a stored stroke limit on some axis
    std::uint32_t dialect_axes_ = 0;   // letters that are axes of the dialect (LexicalRules::is_axis)
    mutable std::uint32_t line_hint_ = 0;        // source(): the last line found, per file
    mutable std::uint32_t line_hint_file_ = ~0u;
    std::deque<Frame> frames_;   // a deque: pushing a call keeps references to the caller valid
    // The live machine state (machine_state.hpp: look-ahead reads blocks with a copy of it) and the
    // machine's memory (offset registers, G54.1 offsets, dialect variables, macro variables: never
    // copied; a block read ahead reads them through const functions only).
    MachineState state_{dialect_, setup_};
    MachineMemory memory_;
    ExecutorSystemVariables system_variables_{*this, state_, state_.position};   // read only: RunOptions::after_block, DPRNT
    macro::Variables variables_{system_variables_};
    const Position& active_work_offset(const MachineState& s) const;    // G54–G59 or G54.1 Pn
    // G54.1 Pn / G154 Pn / G10 L20 Pn: n from 1 to the machine's count, else alarm PS0030 (and nullopt).
    std::optional<int> additional_number(const BlockContext& ctx, std::optional<double> p);
    bool stopped_ = false;
    Outcome unless_stopped(Outcome o) const { return stopped_ ? Outcome::stopped : o; }   // `o`, or stopped

    // Block execution.
    void execute_block(Frame& frame);
    void scan_block(const Frame& frame, const ast::BlockView& view, BlockScan& out) const;
    bool refuse_unknown_g_code(const BlockContext& ctx);
    // Step 1: the block's macro statements and G65 call. not_mine: the rest of the block runs;
    // done: it ends here (a jump, a loop, a call, IF [..] with the words skipped).
    Outcome execute_statements(Frame& frame, const BlockContext& ctx);
    Outcome execute_statement(Frame& frame, const BlockContext& ctx, const ast::Statement& s);
    Outcome start_macro_call(const BlockContext& ctx, const ast::MacroCall& call);   // not_mine for G66
    std::optional<std::vector<std::pair<int, macro::Value>>> macro_arguments(const BlockContext& ctx, const ast::MacroCall& call);
    // The G65/G66 call made (a frame pushed): true; false after its alarm or a resident program skipped.
    bool push_macro_frame(const BlockContext& ctx, std::int64_t program, std::int64_t repeats,
                          const std::vector<std::pair<int, macro::Value>>& arguments, bool modal);
    std::optional<std::uint32_t> find_end(const Frame& frame, std::uint32_t from, int label) const;
    // The block's words evaluated with the machine state `s` and the tool at `at` (the live state and
    // position, or a block read ahead from where the running one ends); the alarm of the first
    // expression that fails (it stands at `at`).
    std::optional<Alarm> read_words(const MachineState& s, const Position& at, const BlockContext& ctx, BlockWords& out) const;
    bool evaluate_words(const BlockContext& ctx, BlockWords& out) {   // the live block's: its alarm raised
        std::optional<Alarm> failed = read_words(state_, state_.position, ctx, out);
        if (failed) raise(std::move(*failed));
        return !failed;
    }
    macro::Options macro_options(const MachineState& s, bool address) const;
    void remember_words(const BlockContext& ctx);
    void apply_feed_speed_tool(const BlockContext& ctx);
    void note_not_modelled(const BlockContext& ctx);
    void apply_tool_word(const BlockContext& ctx, int value);
    void apply_modal_codes(const BlockContext& ctx);
    void update_flags();
    // Step 5: not_mine, the block goes on to its motion; done, it only set a frame (G10, G50/G92 X Z, G52, G68).
    Outcome apply_coordinate_operations(const BlockContext& ctx);
    void apply_local_system(const BlockContext& ctx, bool current_point_code);
    void apply_data_input(const BlockContext& ctx);
    void apply_rotation(const BlockContext& ctx);
    Outcome apply_motion(const BlockContext& ctx);   // step 7: moved, done (no motion) or stopped
    void thread_move(const BlockContext& ctx, const Position& to);
    bool is_cycle(const dialects::CodeInfo& code) const;
    // What a code of the dialect is, as bits: code_class_of (block_scan.hpp). A block ORs its
    // codes' classes into scan.classes and skips whole families of checks with one test.
    static constexpr std::uint32_t kCycleCode = dialects::traits::cycle,
                                  kIncrementalCode = dialects::traits::incremental,
                                  kPerRevolutionCode = dialects::traits::per_revolution,
                                  kCssCode = dialects::traits::css, kInchCode = dialects::traits::inch,
                                  kPlaneXYCode = dialects::traits::plane_xy, kPlaneZXCode = dialects::traits::plane_zx,
                                  kPlaneYZCode = dialects::traits::plane_yz,   // the plane: two bits
                                  kOneShotCode = dialects::traits::one_shot,           // group 00 (G04, G10, G28, G53 ...)
                                  kMotionCode = dialects::traits::motion_group,        // group 01 (G00–G03, G32, modal cycles)
                                  kPositionOffsetCode = dialects::traits::position_offset,   // G45–G48
                                  kRadiusCompCode = dialects::traits::radius_comp,     // G40/G41/G42 (executor_compensation.cpp)
                                  kTransformCode = dialects::traits::plane_transform,  // G112/G113, G107 (polar.cpp)
                                  kLengthCompCode = dialects::traits::length_comp,     // G43/G44/G49 (executor_length.cpp)
                                  kCornerSlowdownCode = dialects::traits::corner_slowdown,   // seed 004 G28/G29 (executor_iso_specials.cpp)
                                  kApproachOffsetCode = dialects::traits::approach_offset,   // seed 004 G43 approach
                                  kArcApproachCode = dialects::traits::arc_approach,   // seed 004 G12/G13
                                  kProgramTransformCode = dialects::traits::program_transform;   // G15/G16, G50/G51, G50.1/G51.1 (executor_transforms.cpp)
    void note_drawing_outside_g01(const BlockContext& ctx);
    Outcome apply_reference_motion(const BlockContext& ctx);   // G27/G28/G29/G30/G53 (executor_reference.cpp)
    void apply_dwell(const BlockContext& ctx);
    // A P dwell word in seconds: ms, or s on ADV400 (semantics.md §8.2); G04 and the drilling cycles.
    double dwell_p_seconds(double p) const { return setup_.dwell_p_in_seconds ? p : p / 1000.0; }
    // The block's M codes of one phase (semantics.md §1.2): before its motion (step 3), or after it
    // (step 9: the codes with traits::after_motion, M05 M09 M00 M01 M02 M30 M98 M99).
    enum class MPhase { before_motion, after_motion };
    void apply_m_codes(Frame& frame, const BlockContext& ctx, MPhase phase);
    void call_subprogram(const BlockContext& ctx);
    // [local calls] [Haas] M97 P: a label of the running program as a subroutine (executor_local_call.cpp).
    void call_local_subprogram(const BlockContext& ctx);
    // A call to a program the run cannot find that the machine keeps resident (RunOptions::resident):
    // said in a message and skipped; false when the program is not resident (alarm 078 follows).
    bool skip_resident_call(const BlockContext& ctx, std::int64_t program, std::string_view how);
    // [dialect variables] (executor_dialect_variables.cpp): nullopt/undefined when the range says so.
    std::optional<macro::Value> read_dialect_variable(const MachineState& s, const Position& at,
                                                      const dialects::VariableRange& range, int number) const;
    macro::WriteResult write_dialect_variable(const dialects::VariableRange& range, int number, macro::Value value,
                                              macro::SystemVariables& system);
    void main_program_pass(Frame& frame, const BlockContext& ctx, const Word* p);   // M99 in the main program
    Outcome apply_block_words(Frame& frame, const BlockContext& ctx);   // steps 2-9
    void emit_state(const SourceRef& where);

    // Helpers.
    const LoadedFile& file_of(const Frame& f) const { return programs_.file(f.program.file); }
    bool reached(std::uint32_t file, std::uint32_t block) const;
    ast::Program program_of(const Frame& f) const;   // a copy: reading ahead may add programs
    SourceRef source(const Frame& f, const ast::BlockView& view) const;   // a block's place (the running one: ctx.source())
    bool has_function(const BlockContext& ctx, dialects::FunctionId function) const;
    bool modal_active(dialects::FunctionId function) const;
    // What the words of a block mean in the machine state `s`. These and the functions that read a
    // block ahead read the state they are given, never state_: a look-ahead gives its copy.
    double axis_value(const MachineState& s, const BlockWords::Word& w, char letter) const;   // program units (mm, inch, deg)
    double increment(const MachineState& s, char letter) const;   // least input increment of the letter, program units
    // The block's target from `from` (the tool, or the programmed point it measures from).
    Position target_position(const MachineState& s, const Position& from, const BlockWords& words, bool& moves) const;
    Position to_program(const MachineState& s, const Position& work) const;     // undo G51.1, G51, G68 (transforms.hpp)
    Position from_program(const MachineState& s, const Position& program) const;   // apply G68, G51, G51.1
    Position machine_offset(const MachineState& s) const;
    Position machine_position_of(const Position& work) const;   // work + the offsets in force, mm
    Position tool_offset(const MachineState& s) const;
    double current_rpm(const MachineState& s, double x_diameter) const;
    // An event of this block at the current position (start = end), before its details are set.
    Event event_at(EventKind kind, const BlockContext& ctx) const { return event_at(kind, ctx.source()); }
    Event event_at(EventKind kind, const SourceRef& where) const;
    // The event goes to the sink with its machine position and tool; rvalues are not copied.
    void emit(Event&& e) { emit(std::move(e), machine_position_of(e.end)); }
    // With its machine position already computed (move() has it: one offset sum per move, not two).
    void emit(Event&& e, const Position& machine_end);
    void emit(const Event& e) {
        Event copy = e;
        emit(std::move(copy));
    }
    int timed_tool_ = -1;                  // time_per_tool_s[timed_tool_] is *tool_time_ (map nodes stay)
    double* tool_time_ = nullptr;
    void alarm(const BlockContext& ctx, int number, std::string text) { alarm(ctx.source(), number, std::move(text)); }
    void alarm(const SourceRef& where, int number, std::string text);
    void raise(Alarm alarm);   // an alarm found reading (ahead): the event, and the run stops
    // A run bound reached (run_guard.hpp) while `where` runs, the tool at `at`: the alarm, and the
    // run stops.
    void limit_alarm(const SourceRef& where, const Position& at, LimitAlarm limit);
    // A cycle step that moved nothing counts against the move limit; false once the run stopped.
    bool count_idle_move(const BlockContext& ctx);
    // Stored stroke check of the box low..high (work coordinates); false after an OT alarm.
    bool within_soft_limits(const Position& low, const Position& high, const BlockContext& ctx);
    // The feed a move is timed with: the modal F and feed mode, a cycle's own (feed_at: mm/min
    // whatever G94/G95), or the reduced feed of a corner slow-down piece and its ramp.
    struct FeedRate {
        double value = 0;             // program units per minute, or per revolution
        bool per_revolution = false;
        double time_factor = 1.0;     // [seed 004 G28] a ramp's time over the step's
    };
    FeedRate modal_feed() const { return {state_.feed, state_.flags.per_revolution, 1.0}; }
    bool feed_commanded(bool moves, const BlockContext& ctx, double feed);   // else alarm 011
    void move(EventKind kind, const Position& to, const BlockContext& ctx) { move(kind, to, ctx, modal_feed()); }
    void move(EventKind kind, const Position& to, const BlockContext& ctx, const FeedRate& feed);
    // The move itself, never split (move() splits a slowed G01 first).
    void run_move(EventKind kind, const Position& to, const BlockContext& ctx, const FeedRate& feed);
    // Time of a feed move or thread (e.start/end/kind set): F per minute or per revolution, G96
    // rpm along the path (a line, or `arc` when not null), exact-stop acceleration.
    void time_feed_move(Event& e, double timed_length_mm, double accel_mm_s2, const motion::Arc* arc,
                        const FeedRate& feed) const;
    void arc_move(bool cw, const Position& to, const BlockContext& ctx);
    // The block a jump to N`n` lands on in the frame's program: the first from the top, or with the
    // dialect's label_search = forward the first after the frame's current block, wrapping to the top.
    std::optional<std::uint32_t> find_label(const Frame& f, double n) const;
    void pop_frame();
    void change_offsets(const std::function<void()>& change);
    std::string block_comment(const ast::BlockView& view) const;
    Frame* current_frame() { return frames_.empty() ? nullptr : &frames_.back(); }

    // System variables (executor_system.cpp).
    std::optional<macro::Value> read_system(const MachineState& s, const Position& at, int number) const;
    bool system_modelled(int number) const;
    macro::WriteResult write_system(const BlockContext& ctx, int number, macro::Value value);   // an assignment of block `ctx`
    bool system_read_only(int number) const;
    std::optional<std::pair<int, std::size_t>> additional_variable(int number) const;   // #7001.., #14001..

    // --- canned cycles (executor_cycles.cpp; the expansions are in interpreter/cycles/) ----------
    friend class CycleContext;
    // A group-01 code cancels a modal drilling cycle ([FANUC]; cycles.md §10 "until G80 or a
    // group-01 code"); any cancel ends the cycle mode (the next cycle takes a new initial level).
    void cancel_cycle_by_motion_code(const BlockContext& ctx);
    struct ProfileBlocks {
        std::uint32_t first, last;   // block indices of N P and N Q
    };
    // The cycle of the block (its code, or the modal one on a block with axis words) expanded into
    // moves (done; not_mine when the block has no cycle). `to` is the block's target point.
    Outcome apply_cycle(const BlockContext& ctx, bool has_axis_words, const Position& to);
    const dialects::CodeInfo* cycle_of_block(const BlockContext& ctx, bool has_axis_words) const;
    // Profile N P .. N Q of the cycle block `ctx` (its blocks into `blocks`); nullopt after an alarm.
    std::optional<cycles::Profile> cycle_profile(const BlockContext& ctx, std::string_view spelling, double p, double q,
                                                 std::optional<ProfileBlocks>& blocks);
    struct ProfileRead {
        cycles::Profile profile;
        ProfileBlocks blocks{};
    };
    // The profile read ahead with a copy of the machine state (each block from the running profile
    // point; the running block's state is not touched, cycles.md "Notation").
    OrAlarm<ProfileRead> read_profile(const BlockContext& ctx, std::string_view spelling, double p, double q) const;
    // One profile block into `profile`; `s` is the reading's state (its position the running point).
    std::optional<Alarm> read_profile_block(MachineState& s, const BlockContext& block, BlockWords& words,
                                            dialects::FunctionId& motion, cycles::Profile& profile, std::uint32_t last) const;
    std::optional<Alarm> read_profile_drawing(MachineState& s, const BlockContext& block, const Position& to,
                                              cycles::Profile& profile, std::uint32_t last) const;
    // An arc kerf computed, to `to` about `center`; false once the run stopped (as cycles::Context).
    bool cycle_arc(bool cw, const Position& to, const Position& center, const BlockContext& ctx);
    motion::ArcOptions computed_arc_options() const;   // arcs kerf computed: radius check ≥ 0.1 µm
    // --- direct drawing (executor_drawing.cpp; the resolver is direct_drawing.hpp) ---------------
    motion::P2 plane_point(const MachineState& s, const Position& p) const;
    Position plane_position(const MachineState& s, motion::P2 p, const Position& like) const;
    // The resolver's view of a block whose words are `words`, programmed from `start` to `to`.
    drawing::Block drawing_block(const MachineState& s, const Position& at, const BlockContext& ctx, bool linear,
                                 const Position& start, const Position& to) const;
    // A code block after the running one, read ahead: its scan and words live here.
    struct BlockAhead {
        ast::BlockView view;
        BlockScan scan;
        BlockWords words;
    };
    // The next code block after `ctx` (up to block `last` when given) as the resolver sees it,
    // programmed from `from` and read with `s` and the tool at `from`; nullopt when there is none.
    OrAlarm<std::optional<drawing::Block>> look_ahead(const MachineState& s, const BlockContext& ctx,
                                                      std::optional<std::uint32_t> last, const Position& from) const;
    // The moves of a direct-drawing block from the programmed point `start` (the tool at `tool`),
    // read with `s` from `at` (where its alarm stands). `last`: the end of a cycle profile the
    // look-ahead stays in.
    OrAlarm<drawing::Result> resolve_drawing(const MachineState& s, const Position& at, const BlockContext& ctx,
                                             const Position& start, const Position& tool, const Position& to,
                                             std::optional<std::uint32_t> last) const;
    // A G01 block with direct-drawing words, run: its line, chamfer or fillet (executor_drawing.cpp).
    Outcome draw_block(const BlockContext& ctx, const Position& start, const Position& to);
    // --- G45–G48 position offsets (executor_offsets.cpp, semantics.md §9.3) ----------------------
    std::optional<int> position_offset_factor(const BlockContext& ctx) const;   // ±1 / ±2 when the block has G45–G48
    double d_register() const;                             // the modal D's value, program units
    Outcome position_offset_move(const BlockContext& ctx, int factor, const Position& start, const Position& to);
    Outcome position_offset_arc(const BlockContext& ctx, bool cw, double change, const Position& start, const Position& to);
    static bool drawing_words(const BlockContext& ctx) { return ctx.scan.comma_words || ctx.scan.direct_drawing; }
    // --- cutter / nose radius compensation G40–G42 (executor_compensation.cpp, semantics.md §5,
    // §6). While the tool stands at an offset point, state_.position is the tool (centre, or the
    // imaginary tip on a lathe), state_.programmed the programmed point and state_.comp_path the point of the
    // programmed path (they differ past a direct-drawing corner).
    bool compensating() const { return state_.comp_side != 0 || state_.radius_comp.engaged(); }
    // The block's motion under compensation (or its G40–G42 without motion).
    Outcome compensate_motion(const BlockContext& ctx, const Position& to, bool moves);
    int comp_side_of_block(const MachineState& s, const BlockContext& ctx, int current) const;   // the side its G40–G42 set
    static bool full_circle(dialects::FunctionId motion, const BlockWords& words);
    double comp_radius(const MachineState& s, const BlockWords& words) const;  // mm: D register (mill), nose radius (lathe)
    motion::P2 tip_offset() const;                       // lathe: nose centre → imaginary tip
    struct CompPiece {
        compensation::Programmed programmed;
        Position end;                                    // the programmed end, work coordinates
    };
    // The block's programmed elements from `start` (a line, an arc, or the direct-drawing pieces),
    // read with `s` and the block's motion. `ahead` (a block read ahead): a direct-drawing block's
    // direction only.
    struct CompPieces {
        std::vector<CompPiece> pieces;
        Position programmed_end{};
        std::optional<Alarm> alarm;    // the block cannot run (an arc, a corner)
        bool zero_arc = false;         // an R arc whose end is its start: no motion, said by the block
    };
    CompPieces comp_pieces(const MachineState& s, const BlockContext& ctx, const Position& start, const Position& to,
                           bool ahead) const;
    bool block_pieces_run(CompPieces& read, const BlockContext& ctx);   // the live block's: its alarm raised, a 0° arc said
    // The next motion block's first element (look-ahead; up to two blocks without motion between),
    // read through const functions of the live state, each block with its own motion code or the
    // running block's motion; nullopt when none.
    OrAlarm<std::optional<compensation::Programmed>> comp_look_ahead(const BlockContext& ctx, const Position& from) const;
    std::optional<compensation::Step> comp_step(const compensation::Programmed& current,
                                                const std::optional<compensation::Programmed>& next, const BlockContext& ctx);
    // The step's tool moves; false once the run stopped.
    bool run_comp_moves(const compensation::Step& step, bool rapid, bool cancels, const Position& like, const BlockContext& ctx);
    // A G70 finishing path under G41/G42: each element offset with the next one as look-ahead;
    // false once the run stopped (cycles::Context::finishing_path).
    bool compensate_path(const std::vector<cycles::ProfileMove>& path, const BlockContext& ctx);
    void leave_offset_for_cycle();   // a cycle's own move under G41/G42: the offset is left (executor_cycles.cpp)
    // --- G43/G44/G49 tool length offsets (executor_length.cpp, semantics.md §7, §2.7) ----------
    // The H register's length (geometry + wear) on Z, +G43 / −G44; machine_offset() adds it. The
    // work coordinates stay: the machine position shifts (like a lathe T word).
    void take_up_length_offset_with_z(const BlockContext& ctx);   // if the block moves Z
    void take_up_length_offset(const BlockContext& ctx);
    void apply_length_offset(const BlockContext& ctx);
    bool axial_offset_is_length(const dialects::CodeInfo& code, const BlockWords& words) const;   // seed-004 G43/G44
    // --- iso-legacy-mill specials (executor_iso_specials.cpp, semantics.md §9.4, §9.5) ----------
    void apply_corner_slowdown(const BlockContext& ctx);
    // A G01 move split before its end into the full-feed and the reduced-feed piece; not_mine when
    // the move is not slowed (move() then runs it whole).
    Outcome slowed_move(const Position& to, const BlockContext& ctx, const FeedRate& feed);
    Outcome approach_offset_move(const BlockContext& ctx, const Position& to);
    // G43/G44 without H (a length offset otherwise): G43's approach, or what the seed leaves
    // open said; not_mine when the block then runs as usual.
    Outcome axial_offset_motion(const BlockContext& ctx, const Position& to, bool moves);
    // G12/G13 X Y: a quarter arc from the programmed point to X Y, run as a G03 (G41, G40) or G02
    // (G42) block with its centre words.
    Outcome arc_approach_move(const BlockContext& ctx, const Position& to);
    // The block's words with the centre words of that arc from `from`; `ccw` its direction.
    BlockWords arc_approach_words(const MachineState& s, const BlockContext& ctx, const Position& from, const Position& to,
                                  bool& ccw) const;
    // Arcs (executor_arc.cpp): the geometry of a G02/G03 block from `from`, and its event.
    motion::ArcResult arc_geometry(const MachineState& s, bool cw, const Position& from, const Position& to,
                                   const BlockWords& words) const;
    void emit_arc(const motion::Arc& arc, const Position& to, const BlockContext& ctx);
    // --- [transforms] G15/G16 polar coordinate command, G50/G51 scaling, G50.1/G51.1 mirror image
    // (executor_transforms.cpp; the geometry with G68 in transforms.hpp) -----------------------
    Outcome apply_program_transforms(const BlockContext& ctx);   // done: the block's words were centres, no motion
    void start_scaling(const BlockContext& ctx);
    double magnification(const Word& w) const;   // a P/I/J/K word: with a point the factor, else units
    void set_mirror(const BlockContext& ctx, bool on);
    void note_transform(const BlockContext& ctx, std::string text);   // a coordinate_change event
    // The plane's two axis words of a G16 block as radius and angle into `to` ([FANUC] rules there).
    void polar_target(const MachineState& s, const BlockWords& words, const Position& start, Position& to) const;
    // --- [polar] G112/G113 polar and G107 cylindrical interpolation (polar.cpp, cycles.md §18–§19) --
    struct PathSpan {             // the axes outside the plane: from → to over the part [u0, u1] of a block
        Position from, to;
        double u0 = 0, u1 = 1;
    };
    // The block under a mode (or starting/ending one); not_mine: the block runs as usual (no mode,
    // or G113 / G07.1 C0 just ended it).
    Outcome apply_plane_transform(const BlockContext& ctx);
    std::optional<std::string> improper_in_transform(const BlockContext& ctx) const;
    void start_polar(const std::string& spelling);
    Outcome start_polar_with_c(const BlockContext& ctx, const std::string& spelling);
    Outcome cylindrical_code(const BlockContext& ctx, const std::string& spelling);   // done (mode set or ended) or stopped
    Outcome transform_move(const BlockContext& ctx);
    motion::ArcResult transform_arc(const MachineState& s, bool cw, motion::P2 a, motion::P2 b, const BlockWords& words) const;
    void warn_rotary_speed(const BlockContext& ctx, const std::vector<motion::MappedPoint>& pieces, motion::P2 start);
    void transform_piece(EventKind kind, const Position& to, double length_mm, const BlockContext& ctx);
    void run_plane_path(EventKind kind, const std::function<motion::P2(double)>& path, const PathSpan& span,
                        const BlockContext& ctx);
    Alarm transform_arc_alarm(const MachineState& s, const BlockContext& ctx, const motion::ArcResult& geometry) const;
    static motion::P2 arc_point(const motion::Arc& arc, double u);
    // G41/G42 in the mode (polar_compensation.cpp): the element of the plane, the compensated block.
    // The element, or the arc's error (an alarm for the block that runs it).
    OrAlarm<motion::Element> transform_element(const MachineState& s, const BlockContext& ctx, const Position& start,
                                               const Position& to) const;
    Outcome transform_compensated(const BlockContext& ctx, const Position& to, bool moves);
    void run_transform_moves(const compensation::Step& step, EventKind kind, const Position& to, const BlockContext& ctx);
    bool transform_switch_allowed(const BlockContext& ctx, const std::string& spelling);   // false after alarm 145
    motion::P2 transform_point(const MachineState& s, const Position& p) const;
    double plane_mm(const MachineState& s, std::size_t axis, double value) const;      // program value → geometric mm (X radius)
    double program_value(const MachineState& s, std::size_t axis, double mm) const;    // and back
};

}  // namespace kerf::interpreter
