#include "converter/codes.hpp"

#include <fmt/format.h>

#include <cctype>

#include "dialects/functions.hpp"

namespace kerf::converter {

namespace fn = dialects::functions;
using dialects::CodeInfo;
using dialects::FunctionId;

namespace {

// Ids several unrelated codes share: a code of one of them maps only to the same number.
bool is_catch_all(FunctionId f) {
    return f == fn::undocumented || f == fn::machine_builder_code;
}

// Function pairs that say the same thing with a difference in the words (functions.hpp notes).
struct Substitute {
    FunctionId from;
    FunctionId to;
    CodeAction action;
};
constexpr Substitute kSubstitutes[] = {
    {fn::coordinate_rotation, fn::coordinate_rotation_cw, CodeAction::rotation_sign},   // gcode-tables.md §8.10
    {fn::coordinate_rotation_cw, fn::coordinate_rotation, CodeAction::rotation_sign},
    {fn::local_system_shift, fn::local_system_current_point, CodeAction::local_system},   // semantics.md §2.4
    {fn::local_system_current_point, fn::local_system_shift, CodeAction::local_system},
    {fn::local_system_cancel, fn::local_system_shift, CodeAction::local_cancel},
    {fn::local_system_cancel, fn::local_system_current_point, CodeAction::local_cancel},
};

}  // namespace

CodeMap::CodeMap(const dialects::Dialect& from, const dialects::Dialect& to) : from_(from), to_(to) {
    by_index_.reserve(from.codes().size());
    for (const CodeInfo& c : from.codes()) by_index_.push_back(map(c));
}

const CodeMapping& CodeMap::operator()(const CodeInfo& source) const {
    return by_index_[static_cast<std::size_t>(&source - from_.codes().data())];
}

const CodeInfo* CodeMap::target_code(FunctionId function) const {
    const std::vector<const CodeInfo*> codes = to_.codes_with_function(function);
    return codes.empty() ? nullptr : codes.front();
}

CodeMapping CodeMap::map(const CodeInfo& source) const {
    const FunctionId f = source.function;
    const CodeInfo* same = to_.code(source.letter, source.key);
    // G90/G91 and G98/G99 (return level) are decided block by block (convert.cpp).
    if (f == fn::absolute_programming || f == fn::incremental_programming) {
        const CodeInfo* t = target_code(f);
        return {CodeAction::distance_mode, t};
    }
    if ((f == fn::return_initial_level || f == fn::return_r_level) && !target_code(fn::return_initial_level) &&
        !target_code(fn::return_r_level))
        return {CodeAction::return_level, nullptr};
    // G52 under two readings (the machine switch g52, semantics.md §2.4): convert.cpp decides.
    if (same && same->function == f && (f == fn::local_system_shift || f == fn::local_system_current_point))
        return {CodeAction::local_system, same};
    if (same && same->function == f) return {CodeAction::keep, same};
    if (is_catch_all(f)) return {CodeAction::none, nullptr};
    for (const CodeInfo* t : to_.codes_with_function(f))
        if (t->letter == source.letter) return {CodeAction::rename, t};
    for (const Substitute& s : kSubstitutes) {
        if (s.from != f) continue;
        for (const CodeInfo* t : to_.codes_with_function(s.to))
            if (t->letter == source.letter) return {s.action, t};
    }
    return {CodeAction::none, nullptr};
}

std::string respell_code(std::string_view source, const CodeInfo& target) {
    const char letter = !source.empty() && std::islower(static_cast<unsigned char>(source.front()))
                            ? static_cast<char>(std::tolower(static_cast<unsigned char>(target.letter)))
                            : target.letter;
    // The source's zero padding is kept ("G01" style: G90 → G77, G04 stays G04), a short spelling
    // stays short (G4, G152 → G52).
    std::size_t width = 0;   // integer digits of the source spelling
    for (std::size_t i = 1; i < source.size() && std::isdigit(static_cast<unsigned char>(source[i])); ++i) ++width;
    if (source.size() < 2 || source[1] != '0') width = 1;
    const int whole = target.key / 10, tenth = target.key % 10;
    std::string digits = fmt::format("{:0{}}", whole, std::max<std::size_t>(width, 1));
    if (tenth) digits += fmt::format(".{}", tenth);
    return letter + digits;
}

}  // namespace kerf::converter
