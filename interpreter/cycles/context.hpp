// The canned cycles (reference/cycles.md) as functions over a small interface the executor
// provides: where the tool is, the words of the cycle block, the profile blocks N P..N Q, the
// persistent cycle parameters, and moves emitted through the executor (so times, soft limits and
// machine positions stay those of ordinary blocks). Each family lives in its own file of this
// folder and is testable through a program run (tests/interpreter/test_cycles_*.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dialects/functions.hpp"
#include "interpreter/cycles/settings.hpp"
#include "interpreter/events.hpp"

namespace kerf::interpreter::cycles {

// One move of a finishing profile, in work coordinates as programmed (lathe X a diameter).
struct ProfileMove {
    EventKind kind = EventKind::linear;     // rapid, linear, arc_cw, arc_ccw
    Position end{};
    Position center{};                      // arcs
    double sweep = 0;                       // arcs: signed radians in the G18 frame (Z, X): > 0 CCW
    std::optional<double> feed;             // F of the block (effective in G70 only, cycles.md §1)
    bool x_word = false, z_word = false;    // the block names X/U, Z/W (G71 type I/II, §2)
    std::uint32_t block = 0;                // the profile block it comes from (its index in the file)
};

// What a group-01 single cycle (G90/G92/G94) keeps for the blocks that repeat it: a repeat block
// gives only the new X (or Z); the other end coordinate and R are those of the last cycle
// [FANUC] (cycles.md §8 "subsequent blocks containing only new X (or Z) repeat the cycle").
struct SingleCycleModal {
    Position end{};
    double r = 0;
};

// The modal data of a drilling cycle (cycles.md §10, §11; [FANUC] canned cycles): the levels and
// words a later block with only a new hole position reuses until G80 or a group-01 code cancels
// the cycle mode (Executor::cancel_cycle_by_motion_code resets `active`).
struct DrillModal {
    bool active = false;        // a drilling cycle ran since the last cancel
    Position start{};           // where the tool was when the cycle mode began: the initial level
    double r_level = 0;         // absolute, on the drilling axis (program units)
    double bottom = 0;          // absolute hole bottom
    bool has_bottom = false;
    double peck = 0;            // Q (K on ADV400 G83), mm along the axis; 0 = one feed
    double dwell_s = 0;         // P at the bottom
    double r_dwell_s = 0;       // ADV400 G84 Q: dwell at the R level after the exit (cycles.md §11.2)
    double shift = 0;           // G76 fine boring Q
    std::optional<int> clamp;   // lathe: the C-axis clamp M code, kept for the repeat blocks [inference]
};

// SPINNER G384 between its first block and G380 (cycles.md §15): the later blocks give only the
// hole position; H, R, F, S, D, M, T stay from the first block.
struct RigidTapModal {
    bool active = false;
    std::size_t axis = 2;          // Z (T2, T3) or X (T1)
    double toward = -1;            // sign of the feed into the hole along `axis`
    double r = 0, depth = 0;       // program units along the axis (X: diameter)
    double pitch = 0, rpm_in = 0, rpm_out = 0;
    std::optional<int> brake;      // M20 / M220
};

struct Profile {
    Position start{};                       // the cycle start point A
    std::vector<ProfileMove> moves;         // ns … nf in order; moves[0] is A → A′
    std::uint32_t q_block = 0;              // the block N Q (its index in the file)
};

// What the executor offers a cycle. Positions are work coordinates as programmed.
class Context {
public:
    virtual ~Context() = default;

    // The cycle block.
    virtual dialects::FunctionId function() const = 0;         // function id (docs/functions.md)
    virtual std::string spelling() const = 0;              // "G71", for messages
    virtual bool has(char letter) const = 0;
    virtual bool takes(char letter) const = 0;             // the code's word list names `letter` (dialect table)
    virtual std::optional<double> increment(char axis) const = 0;   // U/W/H written for X/Z/C (system A), mm/deg
    virtual std::optional<int> m_word() const = 0;         // the block's M code (G83 M20: the C-axis clamp, §10)
    virtual std::optional<double> raw(char letter) const = 0;   // the value as written (P100 = 100)
    virtual std::optional<double> mm(char letter) const = 0;    // a distance (no point: increments, §0)
    virtual std::optional<double> pq(char letter) const = 0;    // P/Q of G74–G76/G83/G87 (§0)
    virtual bool repeat() const = 0;                       // a modal cycle run again by a block without its code
    virtual bool names_axis(char axis) const = 0;          // the block moves `axis` (X or U for 'X', ...)
    virtual bool has_end_point() const = 0;                // X/U/Z/W (lathe), X/Y (mill) in the block
    virtual Position end_point() const = 0;                // the block's target (absolute/incremental)
    virtual bool incremental() const = 0;                  // G91 (B/C, mills)
    virtual bool return_to_r_level() const = 0;            // G99 of a return-level group (§10, §11)
    virtual double modal_feed() const = 0;                 // F in effect (the block's F included)

    // The machine.
    virtual Position position() const = 0;
    virtual bool diameter_x() const = 0;
    virtual double per_mm() const = 0;                     // program units per mm: 1, or 1/25.4 under G20
    virtual const Settings& settings() const = 0;
    virtual double dwell_seconds(double p) const = 0;      // a P dwell word: ms, or s (ADV400; semantics.md §8.2)
    virtual Parameters& parameters() = 0;                  // persistent across the run (§0)
    virtual SingleCycleModal& single_cycle() = 0;          // G90/G92/G94 values for repeat blocks
    virtual DrillModal& drill() = 0;                       // drilling cycle values for repeat blocks
    virtual RigidTapModal& rigid_tap() = 0;                // SPINNER G384 until G380
    virtual Position machine_offset() const = 0;           // machine = work (mm) + this, axis by axis

    // Profile N P .. N Q of the current program; nullopt after an alarm (not found, bad block).
    virtual std::optional<Profile> profile(double p, double q) = 0;

    // Motion: each returns false when the run stopped (soft limit alarm).
    virtual bool rapid(const Position& to) = 0;
    virtual bool feed(const Position& to, std::optional<double> feed = std::nullopt) = 0;
    virtual bool arc(bool cw, const Position& to, const Position& center, std::optional<double> feed = std::nullopt) = 0;
    virtual bool thread(const Position& to, double lead) = 0;
    // A finishing path (G70, cycles.md §1): offset by the tool nose radius compensation in force
    // before the cycle (semantics.md §5 "G70 does"), else run as written; false when the run stopped.
    virtual bool finishing_path(const std::vector<ProfileMove>& path) = 0;
    // A feed move at `mm_per_min` whatever G94/G95 (G98/G99) is in effect; the modal F and feed mode
    // stay (SPINNER cycles: F, S are cycle data, cycles.md §12–§16).
    virtual bool feed_at(const Position& to, double mm_per_min) = 0;
    virtual void tool(int code) = 0;                       // a T code the cycle executes (G238/G384/M329 A)
    virtual void dwell(double seconds) = 0;
    virtual void m_code(int number) = 0;                   // a clamp/unclamp M code issued by the cycle
    virtual void message(std::string text) = 0;
    virtual void alarm(int number, std::string text) = 0;
    // [Haas] M23 (true, the default) / M24: a thread cycle chamfers out of the thread (haas_lathe.cpp).
    virtual bool thread_chamfer() const { return true; }
    // An alarm a profile block causes (a move that breaks monotony): reported at that block.
    virtual void alarm_at(std::uint32_t block, int number, std::string text) = 0;
};

// Expands the cycle of the block; false when `ctx.function()` is no cycle this folder knows (the
// executor then keeps its placeholder message).
bool expand(Context& ctx);

// The pieces the Haas one-block forms share with the FANUC cycles (haas_lathe.cpp): the same
// expansion with the values read from one block instead of two.
// G71/G72 roughing over `profile` (lathe_profile.cpp): `facing` steps the depth along Z (G72);
// `q_block_may_return`: the Q block of a type II profile is exempt from the monotonic check (Haas,
// haas_lathe.cpp).
struct RoughCycle {
    bool facing = false;
    double depth = 0, retract = 0;
    bool q_block_may_return = false;
};
void rough_profile(Context& ctx, const Profile& profile, const RoughCycle& r);
// G73: the profile `divisions` times, shifted by the relief (radius X, Z) plus the allowance.
void repeat_pattern(Context& ctx, const Profile& profile, double relief_x, double relief_z, int divisions);
// G74/G75 (lathe_peck.cpp): pecks of `peck` along Z (face) or X, columns `shift` apart across,
// `retract` after each peck, `relief` away from the next column at the bottom.
struct PeckCycle {
    bool face = false;
    double peck = 0, shift = 0, retract = 0, relief = 0;
};
void peck_cycle(Context& ctx, const PeckCycle& p);
// G76 (lathe_thread.cpp): the passes of a multiple threading cycle to the block's end point.
enum class ThreadInfeed { machine, flank, alternating, radial };
struct ThreadCycle {
    double height = 0;           // k, radius
    double first = 0;            // Δd, radius
    double min_step = 0;         // Δdmin
    double allowance = 0;        // finishing allowance d
    int finishing_passes = 1;
    double angle = 60;           // tool angle, degrees
    double taper = 0;            // radius start − end (i)
    double chamfer = 0;          // pull-out length along Z
    bool constant_depth = false; // every pass Δd deep (Haas P3/P4) instead of Δd·√n
    ThreadInfeed infeed = ThreadInfeed::machine;
};
void thread_cycle(Context& ctx, const ThreadCycle& t, double lead);
// Profile N P .. N Q with its checks (empty profile: alarm 065); nullopt after an alarm.
std::optional<Profile> profile_of_block(Context& ctx);

// The families (one file each).
void lathe_profile(Context& ctx);   // G70–G73, cycles.md §1–§4 (lathe_profile.cpp)
void lathe_peck(Context& ctx);      // G74/G75, §5–§6 (lathe_peck.cpp)
void lathe_thread(Context& ctx);    // G76, G92 (lathe_thread.cpp)
void lathe_single(Context& ctx);    // G90/G94, §8 (lathe_single.cpp)
bool spinner(Context& ctx);         // SPINNER G38, G138, G238, G384/G380, M329, G100/G101, M432, §12–§17
                                    // (spinner.cpp); false when the function is none of them
bool drilling(Context& ctx);        // mill G73–G89, lathe G83–G89, ADV400 G81/G83/G84, §10–§11 (drilling.cpp);
                                    // false when the function is no drilling cycle
bool haas_lathe(Context& ctx);      // [Haas] one-block G71/G72/G73/G74/G75/G76 (haas_lathe.cpp); false for others

// The end point and R of a single cycle block: a repeat block takes the coordinate it omits and R
// from the last cycle (lathe_single.cpp).
struct SingleCycleBlock {
    Position end;
    double r;
};
SingleCycleBlock single_cycle_block(Context& ctx);

}  // namespace kerf::interpreter::cycles
