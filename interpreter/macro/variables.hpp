// Custom Macro B variable storage (FANUC 0i/16i/18i/30i operator manuals, "Custom macro" >
// "Variables", "Types of variables"):
//   #0          always vacant, cannot be assigned (write -> alarm 116)
//   #1-#33      local variables, one set per macro call level: level 0 is the main program, each
//               G65/G66 call opens a new level whose locals start vacant (apart from the
//               arguments the caller then writes), M99 returns to the caller's saved set
//               (push_level / pop_level); cleared to vacant at reset
//   #100-#199   common variables, cleared to vacant at power-off and, when bit 6 (CCV) of
//               parameter 6001 is 0 (the default), at reset
//   #500-#999   common variables kept at power-off and reset
//   #1000-      system variables: not stored here, delegated to a SystemVariables object that the
//               interpreter implements (#1000 interface signals, #2001 offsets, #3000 alarm,
//               #3006 stop with message, #4001 modal information, #5001 positions, ...)
// Every number that is neither #0, a local nor a common variable goes to SystemVariables (so a
// control with optional extra commons such as #200-#499 or #98000- can add them there). A number
// nobody knows is "illegal variable number" (alarm 115) for the evaluator.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "interpreter/macro/value.hpp"

namespace kerf::interpreter::macro {

// Variable number ranges (FANUC 0i/16i/18i/30i, "Types of variables").
namespace numbers {
inline constexpr int vacant = 0;                    // #0
inline constexpr int local_first = 1;               // #1-#33
inline constexpr int local_last = 33;
inline constexpr int common_cleared_first = 100;    // #100-#199, cleared at power-off/reset
inline constexpr int common_cleared_last = 199;
inline constexpr int common_kept_first = 500;       // #500-#999, retained
inline constexpr int common_kept_last = 999;
inline constexpr int system_first = 1000;           // #1000 and up: system variables

// Well-known system variables (what an interpreter implements; none is handled in this library).
inline constexpr int interface_inputs_first = 1000;    // #1000-#1035 interface signal inputs (read)
inline constexpr int interface_outputs_first = 1100;   // #1100-#1135 interface signal outputs (write)
inline constexpr int tool_offsets_first = 2001;        // #2001- tool compensation values
inline constexpr int alarm = 3000;                     // #3000=n(MESSAGE): macro alarm
inline constexpr int clock_ms = 3001;                  // #3001 clock 1 (ms)
inline constexpr int clock_hours = 3002;               // #3002 clock 2 (hours)
inline constexpr int single_block_control = 3003;      // #3003 single block / FIN wait control
inline constexpr int feed_hold_control = 3004;         // #3004 feed hold / override / exact stop control
inline constexpr int settings = 3005;                  // #3005 settings
inline constexpr int stop_with_message = 3006;         // #3006=1(MESSAGE): stop with message
inline constexpr int mirror_image = 3007;              // #3007 mirror image status (read)
inline constexpr int date = 3011;                      // #3011 year/month/day
inline constexpr int time = 3012;                      // #3012 hour/minute/second
inline constexpr int parts_total = 3901;               // #3901 parts machined
inline constexpr int parts_required = 3902;            // #3902 parts required
inline constexpr int modal_first = 4001;               // #4001-#4130 modal information (read)
inline constexpr int modal_last = 4130;
inline constexpr int position_first = 5001;            // #5001- positions, #5201- work offsets
inline constexpr int work_offsets_first = 5201;        // #5201-#5328 external, G54-G59 offsets
}  // namespace numbers

enum class WriteResult : std::uint8_t {
    ok,
    undefined,       // no variable has this number (alarm 115)
    read_only,       // the variable exists but cannot be assigned (alarm 116)
    invalid_value,   // the variable refuses this value (e.g. out of its range; alarm 119 here)
};

// The interpreter's side of the variable space. The default implementation knows nothing: every
// read is undefined, every write is undefined, nothing is read-only.
class SystemVariables {
public:
    virtual ~SystemVariables() = default;
    // The value of a variable that is not #0, local or common; nullopt when the number is undefined.
    virtual std::optional<Value> read(int number);
    virtual WriteResult write(int number, Value value);
    // Asked for every number before a write, commons included, so the interpreter can implement
    // the write protection of commons by parameters (FANUC 6031/6032 protect a range of
    // #500-#999) or make system variables read-only.
    virtual bool read_only(int number) const;
    // False for a number the control may have but this implementation does not model (a system
    // variable outside its tables): reading or writing it is kerf's limit (kerf_alarm::
    // unknown_variable), not alarm 115. The default models everything it knows: nothing exists.
    virtual bool modelled(int number) const;
};

class Variables {
public:
    // Without a SystemVariables object only #0, locals and commons exist.
    Variables();
    // `system` is not owned and must outlive this object (or be replaced with set_system).
    explicit Variables(SystemVariables& system);

    void set_system(SystemVariables& system) { system_ = &system; }
    SystemVariables& system() const { return *system_; }

    // nullopt: no variable has this number (the evaluator reports alarm 115).
    std::optional<Value> read(int number) const { return read(number, *system_); }
    // #0 and numbers the system hook protects are read-only (alarm 116).
    WriteResult write(int number, Value value) { return write(number, value, *system_); }
    bool read_only(int number) const { return read_only(number, *system_); }
    // The same with the numbers #1000 and up answered by `system` instead of the hook of this object
    // (the interpreter's system variables of one machine state, or of the block being run).
    std::optional<Value> read(int number, SystemVariables& system) const;
    WriteResult write(int number, Value value, SystemVariables& system);
    bool read_only(int number, const SystemVariables& system) const;

    // Macro call levels (FANUC: levels 0 to 4, G65/G66 calls nest 4 deep; the limit belongs to the
    // interpreter, which knows the control). A new level's #1-#33 are vacant.
    void push_level();
    // Back to the caller's locals (M99). False, and nothing changes, at level 0.
    bool pop_level();
    int level() const { return static_cast<int>(levels_.size()) - 1; }

    // RESET / M02 / M30 (FANUC): back to level 0 with all locals vacant; #100-#199 vacant unless
    // kept by `keep_commons_on_reset` (parameter 6001#6 CCV = 1); #500-#999 kept.
    void reset();
    // Power off and on: as reset, and #100-#199 always vacant.
    void power_cycle();
    bool keep_commons_on_reset = false;

private:
    using Locals = std::array<Value, numbers::local_last>;
    std::vector<Locals> levels_;
    std::array<Value, numbers::common_cleared_last - numbers::common_cleared_first + 1> cleared_{};
    std::array<Value, numbers::common_kept_last - numbers::common_kept_first + 1> kept_{};
    SystemVariables* system_;
    void clear_cleared_commons();
};

}  // namespace kerf::interpreter::macro
