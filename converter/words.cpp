#include "converter/words.hpp"

#include <algorithm>
#include <string_view>

#include "dialects/functions.hpp"

namespace kerf::converter {

namespace fn = dialects::functions;
using dialects::FunctionId;

namespace {

// The parameter letters a code of each function reads as lengths, P/Q increments and dwell times
// (the interpreter's reading: cycles.md and the files named).
struct Units {
    FunctionId function;
    std::string_view length;
    std::string_view pq;
    std::string_view dwell;
};

constexpr Units kUnits[] = {
    {fn::circular_cw, "IJKR", "", ""},                           // executor_arc.cpp
    {fn::circular_ccw, "IJKR", "", ""},
    {fn::rough_turning_cycle, "UWR", "", ""},                    // lathe_profile.cpp: U/W depth and allowance, R retract
    {fn::rough_facing_cycle, "UWR", "", ""},
    {fn::pattern_repeating_cycle, "UW", "", ""},                 // R: the number of divisions
    {fn::face_peck_drilling_cycle, "R", "PQ", ""},               // lathe_peck.cpp
    {fn::grooving_cycle, "R", "PQ", ""},
    {fn::multiple_threading_cycle, "R", "Q", ""},                // lathe_thread.cpp: P packed (1st) / pq (2nd)
    {fn::turning_cycle, "R", "", ""},                            // lathe_single.cpp: taper
    {fn::thread_cutting_cycle, "R", "", ""},
    {fn::facing_cycle, "R", "", ""},
    {fn::thread_cutting, "EK", "", ""},                          // executor_motion.cpp: E lead, K lead change
    {fn::variable_lead_thread_cutting, "EK", "", ""},
    {fn::programmable_data_input, "XYZUVWABCR", "", ""},         // executor_data_input.cpp
    {fn::dwell, "", "", "P"},                                    // executor_motion.cpp apply_dwell (X/U: seconds)
    {fn::workpiece_transfer_cycle, "BQ", "", ""},                // cycles/spinner.cpp
    {fn::tailstock_clamping_cycle_1, "BQJ", "", ""},
    {fn::tailstock_clamping_cycle_2, "BQJXZK", "", ""},
    {fn::live_tool_rigid_tapping, "HRXZ", "", ""},
    {fn::spindle_rigid_tapping_cycle, "HRXZ", "", ""},
};

constexpr FunctionId kDrilling[] = {
    fn::drilling_cycle,         fn::drilling_dwell_cycle,       fn::peck_drilling_cycle,   fn::high_speed_peck_drilling_cycle,
    fn::tapping_cycle,          fn::left_hand_tapping_cycle,    fn::boring_cycle,          fn::boring_dwell_cycle,
    fn::boring_spindle_stop_cycle, fn::boring_manual_retract_cycle, fn::back_boring_cycle, fn::fine_boring_cycle,
    fn::face_drilling_cycle,    fn::face_tapping_cycle,         fn::face_boring_cycle,     fn::side_drilling_cycle,
    fn::side_tapping_cycle,     fn::side_boring_cycle,
};

constexpr FunctionId kLatheDrilling[] = {fn::face_drilling_cycle, fn::face_tapping_cycle, fn::face_boring_cycle,
                                         fn::side_drilling_cycle, fn::side_tapping_cycle, fn::side_boring_cycle};

bool has(std::string_view letters, char letter) { return letters.find(letter) != std::string_view::npos; }

// cycles/drilling.cpp: R the R level; Q the peck (lathe: P/Q increments; mill: mm) or a fine/back
// boring shift; K the peck where the code takes no Q; P the dwell at the bottom; a tapping cycle's
// Q (ADV400 G84) the dwell at the R level.
WordUnit drilling_unit(char letter, const dialects::CodeInfo& code) {
    const FunctionId f = code.function;
    const bool lathe = is_lathe_drilling_cycle(f);
    switch (letter) {
    case 'R': return WordUnit::length;
    case 'P': return WordUnit::dwell;
    case 'Q':
        if (f == fn::tapping_cycle) return WordUnit::dwell;
        return lathe ? WordUnit::pq : WordUnit::length;
    case 'K': return drill_letters(code).peck == 'K' ? WordUnit::length : WordUnit::raw;
    default: return WordUnit::raw;
    }
}

}  // namespace

bool is_drilling_cycle(FunctionId function) {
    return std::find(std::begin(kDrilling), std::end(kDrilling), function) != std::end(kDrilling);
}

bool is_lathe_drilling_cycle(FunctionId function) {
    return std::find(std::begin(kLatheDrilling), std::end(kLatheDrilling), function) != std::end(kLatheDrilling);
}

DrillLetters drill_letters(const dialects::CodeInfo& code) {
    DrillLetters d;
    const bool q = code.takes_word("Q"), k = code.takes_word("K"), l = code.takes_word("L");
    const bool pecks = code.has(dialects::traits::peck) || code.function == fn::peck_drilling_cycle ||
                       code.function == fn::face_drilling_cycle || code.function == fn::side_drilling_cycle;
    if (pecks) d.peck = q ? 'Q' : (k ? 'K' : 0);
    if (k && d.peck != 'K') d.repeat = 'K';
    else if (l) d.repeat = 'L';
    return d;
}

WordUnit parameter_unit(char letter, std::span<const dialects::CodeInfo* const> codes) {
    for (const dialects::CodeInfo* code : codes) {
        if (!code) continue;
        if (is_drilling_cycle(code->function)) {
            const WordUnit u = drilling_unit(letter, *code);
            if (u != WordUnit::raw) return u;
            continue;
        }
        for (const Units& u : kUnits) {
            if (u.function != code->function) continue;
            if (has(u.length, letter)) return WordUnit::length;
            if (has(u.pq, letter)) return WordUnit::pq;
            if (has(u.dwell, letter)) return WordUnit::dwell;
        }
    }
    return WordUnit::raw;
}

}  // namespace kerf::converter
